/* qhalf.h — `lifthull qhalf`: the halfspaces (read by qhalf_read.c), their intersection
 * (qhalf.c) and Qhull's outputs for it (qhalf_print.c). */
#ifndef LH_CLI_QHALF_H
#define LH_CLI_QHALF_H

#include "qhull.h"

typedef struct lh_cli_halfspaces {
    int d;          /* dimension of the space: d + 1 coefficients per halfspace */
    size_t n;
    double *h;      /* n * (d + 1): a_i, then b_i (a_i.x + b_i <= 0)            */
    size_t *line;   /* n: the input line of each halfspace's first coefficient  */
    double c[LH_DELAUNAY_MAX_DIM]; /* the interior point                        */
    int has_c;      /* from the input's first point                             */
    char comment[160]; /* the input's first comment line (Qhull's FQ), or ""     */
} lh_cli_halfspaces;

/* The intersection's vertices are groups of dual hull facets on one hyperplane. */
typedef struct lh_cli_hresult {
    lh_hull *hull;       /* of the dual points                                    */
    double *dual;        /* n * d: a_i / -(a_i.c + b_i)                           */
    lh_index *nbr;       /* d per hull facet: the facet across each side, or -1    */
    size_t groups;
    lh_index *group_of;  /* per hull facet: its group                             */
    lh_index *facets;    /* per group: how many hull facets it merges             */
    lh_index *first;     /* per group: its first hull facet                       */
    double *point;       /* groups * d: the intersection points, point * 2^exp    */
    int *exp;            /* per group (0 unless a coordinate passes DBL_MAX)       */
    lh_index *off, *idx; /* group g's halfspaces: idx[off[g]..off[g+1]), increasing */
    lh_pred *pred;
    double seconds;      /* the dual hull's computation                           */
} lh_cli_hresult;

/* Reads the halfspaces (qhalf_read.c) of file (NULL or "-": standard input), in Qhull's
 * format or, with cdd, cdd's; *name is the name the messages use. 1 read, 0 after
 * printing the error (FILE:LINE: problem). hs starts zeroed; the caller frees hs->h and
 * hs->line in every case. */
int lh_cli_qhalf_read(const char *file, int cdd, lh_cli_halfspaces *hs, const char **name);
/* Prints output `opt` (one lh_cli_qparse accepts for qhalf; not o, G, m, FM, f, FF,
 * which print the dual hull through qconvex's printers). Returns 0 when out of
 * memory (message printed). */
int lh_cli_qhalf_print(FILE *f, const lh_cli_qopts *o, const lh_cli_halfspaces *hs,
                       const lh_cli_hresult *r, const char *opt);
/* The Chebyshev centre of the halfspaces (the centre of the largest ball inside
 * them) in x, from a floating-point linear program (qhalf_lp.c); 1 when it found
 * one with a positive radius, 0 otherwise (also when out of memory). The caller
 * checks x exactly. */
int lh_cli_qhalf_centre(const lh_cli_halfspaces *hs, double *x);
/* Tv: every dual point inside or on every facet of the dual hull (exact); 1 when
 * so, 0 after printing the first violation. */
int lh_cli_qhalf_verify(const lh_cli_qopts *o, const lh_cli_halfspaces *hs, const lh_cli_hresult *r);

#endif
