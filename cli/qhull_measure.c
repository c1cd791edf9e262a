/*
 * qhull_measure.c — Qhull's FA (totals in the summary), FS, Fa and Fs, from
 * lh_hull_measures / lh_tri_measures. As in Qhull, a Delaunay "facet area" is the
 * volume of its simplex (the lower facet's projection), and qdelaunay's "volume"
 * is 0. Volumes are exact sums rounded once; areas a few ulps each.
 */
#include "qhull.h"
#include "qhull_print.h"

#include <stdlib.h>

/* The totals over every facet of the hull (or lower facet), whatever the print
 * filters select, as Qhull's; 0 when out of memory. */
int lh_cli_qtotals(const lh_cli_qmodel *mo, double *area, double *volume)
{
    lh_status st;
    if (mo->hull) {
        st = lh_hull_measures(mo->hull, mo->built_xyz, mo->built_n, NULL, area, volume);
    } else {
        st = lh_tri_measures(mo->tri, NULL, area);
        *volume = 0;
    }
    return st == LH_OK;
}

static int print_FS(FILE *f, const lh_cli_qmodel *mo)
{
    double area, volume;
    if (!lh_cli_qtotals(mo, &area, &volume)) return 0;
    fprintf(f, "0\n2 ");
    lh_cli_qcoords(f, (const double[]){area, volume}, 2);
    fputc('\n', f);
    return 1;
}

static int print_Fa(FILE *f, const lh_cli_qmodel *mo)
{
    double *each = malloc((mo->m ? mo->m : 1) * sizeof *each);
    if (!each || lh_simplex_measures(mo->d, mo->nv - 1, mo->xyz, mo->n, mo->m, mo->vert, each,
                                     NULL) != LH_OK) {
        free(each);
        return 0;
    }
    fprintf(f, "%zu\n", mo->m);
    for (size_t t = 0; t < mo->m; t++) {
        lh_cli_qcoords(f, each + t, 1);
        fputc('\n', f);
    }
    free(each);
    return 1;
}

/* Fs: ten integers, then two reals. Lifthull's facets are exact simplices: no
 * coplanar, nonsimplicial or deleted ones, and every site exactly inside or on every
 * facet (outer and inner offsets 0); qdelaunay's merged duplicates are its coplanar
 * points, as Qhull counts them. */
static void print_Fs(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    size_t vertices = lh_cli_qvertex_count(mo);
    int convex = o->prog == LH_QPROG_CONVEX;
    fprintf(f, "10 %d %zu %zu %zu %zu %zu %zu 0 0 0\n", mo->d + !convex, mo->n, vertices,
            mo->m + mo->m_other, vertices, mo->m, convex ? (size_t)0 : mo->ndup);
    fprintf(f, "2 %6.16g %6.16g\n", 0.0, 0.0);
}

int lh_cli_qprint_measure(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt)
{
    if (opt[1] == 'S') return print_FS(f, mo);
    if (opt[1] == 'a') return print_Fa(f, mo);
    print_Fs(f, o, mo);
    return 1;
}
