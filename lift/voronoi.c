/*
 * voronoi.c — the Voronoi diagram as the dual of the triangulation (Voronoi 1908;
 * Delaunay 1934): vertex s is the circumcentre of simplex s, built once per handle.
 * The centres are constructions in floating point; the combinatorics (which
 * centres bound which region) is the exact triangulation's.
 */
#include "dt.h"
#include "geom.h"
#include "lh_alloc.h"

lh_status lh_tri_circumcenter_exp(const lh_tri *t, size_t s, double *c, int *e)
{
    if (!t || !c || !e || s >= t->count) return LH_ERR_INVALID_ARGUMENT;
    const int d = t->d, k = t->frame.k;
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (int j = 0; j <= k; j++) p[j] = t->xyz + (size_t)t->simp[s * (size_t)(k + 1) + j] * d;
    lh__circumcenter_exp(d, k, p, c, e);
    return LH_OK;
}

lh_status lh_tri_circumcenters(lh_tri *t, const double **centers)
{
    if (!t || !centers) return LH_ERR_INVALID_ARGUMENT;
    if (!t->centers) {
        const int d = t->d, k = t->frame.k;
        double *c = lh__alloc(&t->alloc, (t->count ? t->count : 1) * (size_t)d * sizeof *c);
        if (!c) return LH_ERR_NOMEM;
        for (size_t s = 0; s < t->count; s++) {
            const double *p[LH_DELAUNAY_MAX_DIM + 1];
            for (int j = 0; j <= k; j++) p[j] = t->xyz + (size_t)t->simp[s * (size_t)(k + 1) + j] * d;
            lh__circumcenter(d, k, p, c + s * (size_t)d);
        }
        t->centers = c;
    }
    *centers = t->centers;
    return LH_OK;
}
