/* qhull_print.h — Qhull's output formats (qhull_print.c; Voronoi: qhull_voronoi.c). */
#ifndef LH_CLI_QHULL_PRINT_H
#define LH_CLI_QHULL_PRINT_H

#include "qhull.h"

/* d coordinates as Qhull prints them: "%6.16g " each. */
void lh_cli_qcoords(FILE *f, const double *x, int d);
/* qvoronoi's o, p, Fv, Fi, Fo. Returns 0 when out of memory (message printed). */
int lh_cli_qprint_voronoi(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

/* qdelaunay's lifted coordinate, |p|^2 scaled to [0, max |coordinate|] as Qhull's
 * Qbb does: (|p|^2 - low) * factor. */
typedef struct lh_cli_qlift {
    double low, factor;
} lh_cli_qlift;
lh_cli_qlift lh_cli_qlift_scale(const lh_cli_qmodel *mo);
double lh_cli_qlifted(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i);
/* qconvex's facet t: its outward unit normal n and offset (n.x + off = 0). */
void lh_cli_qfacet_plane(const lh_cli_qmodel *mo, size_t t, double *n, double *off);
/* Facet t's unit normal: qconvex's outward one; qdelaunay's lifted one (lifted
 * coordinate scaled by s), pointing down for a lower facet (up with Qu); the lifted
 * dimension at most LH_ORIENT_MAX_DIM (qhull_select.c). */
void lh_cli_qfacet_normal(const lh_cli_qmodel *mo, const lh_cli_qopts *o, lh_cli_qlift s,
                          size_t t, double *n);
/* The same for the lifted facet through the d+1 sites v, pointing up when `up`. */
void lh_cli_qlifted_normal(const lh_cli_qmodel *mo, lh_cli_qlift s, const lh_index *v, int up,
                           double *n);
/* Whether site i is a vertex of a printed facet; how many are. */
int lh_cli_qis_vertex(const lh_cli_qmodel *mo, size_t i);
size_t lh_cli_qvertex_count(const lh_cli_qmodel *mo);
/* The printed facets' total area and (qconvex) enclosed volume, as FA reports them;
 * 0 when out of memory. */
int lh_cli_qtotals(const lh_cli_qmodel *mo, double *area, double *volume);
/* FS, Fa, Fs (qhull_measure.c). Returns 0 when out of memory. */
int lh_cli_qprint_measure(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

/* FI, Fm, FQ, Fc, FP, m, FM (qhull_extra.c); G (qhull_geom.c). Return 0 when out
 * of memory. */
int lh_cli_qprint_geomview(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo);
/* f and FF (qhull_fields.c). */
void lh_cli_qprint_fields(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo);
int lh_cli_qprint_extra(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

#endif
