/* qhull_print.h — Qhull's output formats (qhull_print.c; Voronoi: qhull_voronoi.c). */
#ifndef LH_CLI_QHULL_PRINT_H
#define LH_CLI_QHULL_PRINT_H

#include "qhull.h"

/* d coordinates as Qhull prints them: "%6.16g " each. */
void lh_cli_qcoords(FILE *f, const double *x, int d);
/* qvoronoi's o, p, Fv, Fi, Fo. Returns 0 when out of memory (message printed). */
int lh_cli_qprint_voronoi(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

/* The sites that are vertices of a printed facet. */
size_t lh_cli_qvertex_count(const lh_cli_qmodel *mo);
/* The printed facets' total area and (qconvex) enclosed volume, as FA reports them;
 * 0 when out of memory. */
int lh_cli_qtotals(const lh_cli_qmodel *mo, double *area, double *volume);
/* FS, Fa, Fs (qhull_measure.c). Returns 0 when out of memory. */
int lh_cli_qprint_measure(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt);

#endif
