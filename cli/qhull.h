/*
 * qhull.h — `lifthull qdelaunay | qvoronoi | qconvex OPTIONS`: Qhull's programs'
 * options and text formats (qhull.org, "qdelaunay", "qvoronoi", "qconvex" manual
 * pages; Qhull 2020.2), computed exactly by lifthull. Every facet is a simplex
 * (Qhull's Qt is always on), so a script changes only the program name.
 */
#ifndef LH_CLI_QHULL_H
#define LH_CLI_QHULL_H

#include "lifthull.h"

#include <stdio.h>

typedef enum { LH_QPROG_DELAUNAY, LH_QPROG_VORONOI, LH_QPROG_CONVEX, LH_QPROG_HALF } lh_cli_qprog;

enum { LH_QOUT_MAX = 32 };

/* G's suboptions (qhull_geom.c): Gi, Go, Gn, Ga, Gr, Gh, Gv, Gt, Gc. */
enum { LH_QG_INNER = 1, LH_QG_OUTER = 2, LH_QG_NOPLANES = 4, LH_QG_POINTS = 8, LH_QG_RIDGES = 16,
       LH_QG_INTERSECT = 32, LH_QG_SPHERES = 64, LH_QG_TRANSPARENT = 128,
       LH_QG_CENTRUMS = 256 };

typedef struct lh_cli_qopts {
    lh_cli_qprog prog;
    const char *name;         /* "qdelaunay", "qvoronoi", "qconvex", "qhalf"   */
    char out[LH_QOUT_MAX][4]; /* output options in the order given ("i", "Fn") */
    int nout;
    int furthest;             /* Qu                                            */
    int areas;                /* FA or FS: totals in the summary 's'           */
    int cdd;                  /* FD: cdd's format for n, Fi, Fo, p (qhalf: Fd, in) */
    int show_options;         /* FO: the options on standard error             */
    int stats;                /* Ts: statistics on standard error              */
    double interior[LH_DELAUNAY_MAX_DIM]; /* qhalf's Hn,n,...                  */
    int ninterior;
    int summary_default;      /* no output asked: 's' on standard output       */
    int verify;               /* Tv: the exact check of the result             */
    struct lh_cli_qpd {       /* Pdk:n (ge: normal[k] >= n), PDk:n (<= n)      */
        int k, ge;
        double at;
    } pd[LH_QOUT_MAX];
    int npd;
    size_t largest;           /* PAn: the n largest facets are the good ones   */
    int good, good_nbrs;      /* Pg: print good facets; PG: their neighbours   */
    int geom;                 /* G's suboptions, LH_QG_* bits                  */
    int geom_drop;            /* GDn: the coordinate a 4-d picture drops; -1   */
    struct lh_cli_qgood {     /* QGn (visible from point n; QG-n: not visible), */
        int on, not;          /* QVn (with vertex n; QV-n: without)             */
        size_t n;
    } gpoint, gvertex;
    const char *input;        /* TI file, NULL: standard input                 */
    const char *output;       /* TO file, NULL: standard output                */
    char command[256];        /* "lifthull qdelaunay OPTIONS", for summaries    */
    char words[4096];         /* the option words (input and output point here) */
} lh_cli_qopts;

/* Parses Qhull-style options (words that may also come several to an argument, as
 * "i Qt"). Returns 0; 1 when --help was printed; -1 after printing a usage error. */
int lh_cli_qparse(lh_cli_qopts *o, lh_cli_qprog prog, int argc, char **argv);

/*
 * What every format prints from: the facets (Delaunay simplices, or hull facets) and
 * across each side either another facet (>= 0) or, for Delaunay, one of the "other"
 * facets of the lifted hull, -(j+1): the upper hull's (the furthest-site simplices
 * of the hull's vertices) — or with Qu the lower hull's — as Qhull numbers its upper
 * Delaunay facets with negative ids.
 */
typedef struct lh_cli_qmodel {
    int d;                 /* coordinates per site                           */
    size_t n;
    const double *xyz;
    int nv;                /* vertices per facet: d + 1, or d for a hull     */
    size_t m;              /* facets                                         */
    const lh_index *vert;  /* nv per facet                                   */
    lh_index *nbr;         /* nv per facet, opposite each vertex             */
    lh_index *own_vert;    /* vert when the model owns it (hull facets)      */
    size_t m_other;        /* the other facets                               */
    size_t m_upper;        /* the first m_upper of them: upper (Qu: lower) and
                              vertical facets; then those the filters dropped */
    lh_index *other;       /* nv per other facet, in site numbering (-1: the
                              empty slot of a vertical facet's d vertices)    */
    lh_index *inc_off;     /* n + 1: site i's facets are inc[inc_off[i]..]   */
    lh_index *inc;         /* main facets, then other ones as -(j+1)         */
    const lh_index *dup;   /* the site each one was merged into              */
    lh_index *own_dup;     /* dup when the model owns it (QGn)               */
    lh_index excluded;     /* QGn's point n, left out of the hull; -1: none  */
    size_t built_n;        /* the sites the hull was built on: all, or (QGn) */
    const double *built_xyz; /* all but `excluded`, in order (lh_hull_measures) */
    double *own_xyz;       /* built_xyz when the model owns it               */
    size_t ndup;
    double seconds;        /* the computation's time                          */
    lh_tri *tri, *tri_other;
    lh_hull *hull;
    lh_pred *pred;         /* for the exact hyperplanes of qconvex n, Fi, Fo    */
    char *good;            /* qvoronoi's filters: the simplices kept (NULL: all) */
    size_t ngood;          /* how many facets are good (PG prints their neighbours) */
    const struct lh_cli_qmodel *all; /* qvoronoi with filters: this model before
                              them (good set), for the Voronoi formats; NULL  */
} lh_cli_qmodel;

/* Builds the model for the options' program; 0 after printing the problem. */
int lh_cli_qmodel_build(lh_cli_qmodel *mo, const lh_cli_qopts *o, int d, size_t n,
                        const double *xyz, const char *name);
void lh_cli_qmodel_free(lh_cli_qmodel *mo);
/* (Re)builds mo->inc_off and mo->inc from the facets (qhull_model.c). */
lh_status lh_cli_qmodel_incidence(lh_cli_qmodel *mo);
/* Qhull's print filters (Pdk, PDk, PAn, Pg, PG, QGn, QVn; qhull_select.c): the
 * facets they drop join the other facets (negative ids), as Qhull's unprinted ones.
 * `all`, when not NULL, is a second build of the same model: it keeps every facet
 * and gets the kept ones as its good set (qvoronoi's Voronoi formats). Returns 1;
 * 0 when out of memory, -1 for a coordinate outside the facets' normals (both after
 * printing the problem). */
int lh_cli_qselect(lh_cli_qmodel *mo, const lh_cli_qopts *o, lh_cli_qmodel *all);
/* Whether options select good facets (QGn QVn Pdk PDk PAn PG): then, as in Qhull,
 * the summary counts them apart and Fx, FN name only the printed facets' vertices. */
int lh_cli_qselecting(const lh_cli_qopts *o);

/* Whether the outputs asked for suit n sites in d dimensions (m, FM: 2-d and 3-d
 * hulls, 2-d Delaunay; G: pictures of 2 to 4 coordinates, qvoronoi 2-d; qdelaunay's
 * f and FF: up to 7-d; QGn, QVn: a point n); 0 after printing the problem
 * (qhull_extra.c). */
int lh_cli_qcheck_outputs(const lh_cli_qopts *o, int d, size_t n);

/* Ts: the computation's statistics (qhull_stats.c). */
void lh_cli_qstats(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo);

/* Prints output option `opt` (one of those lh_cli_qparse accepts for o->prog).
 * Returns 0 when out of memory. */
int lh_cli_qprint(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

#endif
