/* qhull_print.h — Qhull's output formats (qhull_print.c; Voronoi: qhull_voronoi.c). */
#ifndef LH_CLI_QHULL_PRINT_H
#define LH_CLI_QHULL_PRINT_H

#include "qhull.h"

/* d coordinates as Qhull prints them: "%6.16g " each. */
void lh_cli_qcoords(FILE *f, const double *x, int d);
/* m 2^e as "%W.Pg" would print it had doubles the range: beyond DBL_MAX (offsets of
 * facets, circumcentres of sites near DBL_MAX) and below DBL_MIN (where a double
 * keeps fewer digits: circumcentres of subnormal sites) in long double, or from
 * logarithms where long double is no wider (about 13 correct digits then). Never inf
 * or nan for a finite m. */
void lh_cli_qscaled(FILE *f, int width, int prec, double m, int e);
/* The d coordinates m 2^e as lh_cli_qcoords prints them. */
void lh_cli_qcoords_scaled(FILE *f, const double *m, int e, int d);
/* qvoronoi's o, p (FD: cdd's format), Fv, Fi, Fo, FN, G. Returns 0 when out of memory. */
int lh_cli_qprint_voronoi(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

/* qdelaunay's lifted coordinate, |p|^2 scaled to [0, max |coordinate|] as Qhull's
 * Qbb does: (|p|^2 - low) * factor. Computed on the sites scaled by 2^-exp (the
 * exponent of their largest coordinate; low and factor are those of the scaled
 * sites, the result scaled back): the same bits as in double where nothing
 * overflows, and finite (at most max |coordinate|) where |p|^2 passes DBL_MAX. */
typedef struct lh_cli_qlift {
    double low, factor;
    int exp;
} lh_cli_qlift;
lh_cli_qlift lh_cli_qlift_scale(const lh_cli_qmodel *mo);
double lh_cli_qlifted(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i);
/* The same as m with lifted = m 2^s.exp: all its digits where lifted is subnormal. */
double lh_cli_qlifted_scaled(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i);
/* qconvex's facet t: its outward unit normal n and offset off 2^e (n.x + off 2^e = 0;
 * lh_hyperplane_exp: finite even where the offset passes DBL_MAX). */
void lh_cli_qfacet_plane(const lh_cli_qmodel *mo, size_t t, double *n, double *off, int *e);
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
