/*
 * fuzz_query.c — libFuzzer target: queries on the Delaunay triangulation of small
 * fuzzer-chosen integer sites (d = 2..4; coarse grids, so degenerate, or int8 values),
 * at fuzzer-chosen query points on a half-integer grid (so on vertices, edges and
 * facets, and outside the hull, often). For each query:
 *   - lh_tri_locate: inside, the simplex contains q exactly (orient_d >= 0 with q in
 *     place of each vertex) and no simplex of smaller index does; outside (-1), no
 *     simplex contains q, hull_facet names a hull facet, distance > 0; the same answer
 *     from another hint;
 *   - lh_tri_nearest: a site that is no merged duplicate, as near as every site
 *     (lh_distance_compare), strictly nearer than every site of smaller index;
 *   - lh_tri_interpolate of two affine functions, all queries in one call: LINEAR and,
 *     for d <= 3, NATURAL reproduce them within 1e-9 relative inside the hull and give
 *     NaN outside (relative to the largest |value| at a site plus the sum of
 *     the absolute terms at q); NEAREST gives exactly the value at lh_tri_nearest's site.
 * Anything else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXD 4
#define MAXN 16
#define MAXQ 16

static double affine(int c, int d, const double *q)
{
    double v = c ? -7.0 : 3.0;
    for (int j = 0; j < d; j++) v += (c ? (j % 2 ? 0.25 : -1.5) : (double)(j + 2)) * q[j];
    return v;
}

static double affine_scale(int c, int d, const double *q)
{
    double v = c ? 7.0 : 3.0;
    for (int j = 0; j < d; j++) v += fabs((c ? (j % 2 ? 0.25 : -1.5) : (double)(j + 2)) * q[j]);
    return v;
}

static int contains(lh_pred *p, int d, const double *x, const lh_index *v, const double *q)
{
    for (int k = 0; k <= d; k++) {
        const double *pts[MAXD + 1];
        for (int j = 0; j <= d; j++) pts[j] = j == k ? q : x + (size_t)v[j] * d;
        if (lh_orient(p, d, pts) < 0) return 0;
    }
    return 1;
}

static void check_value(double got, double want, double scale, int inside)
{
    if (inside ? !(fabs(got - want) <= 1e-9 * scale) : !isnan(got)) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const int maxn[MAXD + 1] = {0, 0, 16, 12, 10};
    if (size < 3) return 0;
    int d = 2 + data[0] % 3, flags = data[1];
    size_t n = 1 + (size_t)(data[2] % maxn[d]);
    if (n > (size - 3) / (size_t)d) n = (size - 3) / (size_t)d;
    double x[MAXN * MAXD], q[MAXQ * MAXD];
    for (size_t i = 0; i < n * (size_t)d; i++) {
        int8_t v = (int8_t)data[3 + i];
        x[i] = (flags & 1) ? (double)v : (double)(v % 4);
    }
    const uint8_t *rest = data + 3 + n * (size_t)d;
    size_t left = size - 3 - n * (size_t)d, m = left / (size_t)d;
    if (m > MAXQ) m = MAXQ;
    for (size_t i = 0; i < m * (size_t)d; i++) {
        int8_t v = (int8_t)rest[i];
        q[i] = ((flags & 1) ? (double)v : (double)(v % 10)) / 2.0;
    }
    lh_tri *t = NULL;
    if (lh_delaunay(d, n, x, NULL, &t) != LH_OK || m == 0) {
        lh_tri_free(t);
        return 0;
    }
    lh_pred *p;
    if (lh_pred_create(NULL, &p) != LH_OK) abort();
    size_t count = lh_tri_count(t), hulls = lh_tri_hull_count(t);
    const lh_index *simp = lh_tri_simplices(t), *dup = lh_tri_duplicate_of(t);
    double values[MAXN * 2], lin[MAXQ * 2], nat[MAXQ * 2], near[MAXQ * 2];
    double vmax[2] = {0, 0}; /* the largest value at a site: the scale of the rounding */
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 2; c++) {
            values[i * 2 + c] = affine(c, d, x + i * d);
            if (fabs(values[i * 2 + c]) > vmax[c]) vmax[c] = fabs(values[i * 2 + c]);
        }
    if (lh_tri_interpolate(t, LH_INTERP_LINEAR, m, q, 2, values, lin) != LH_OK ||
        lh_tri_interpolate(t, LH_INTERP_NEAREST, m, q, 2, values, near) != LH_OK ||
        (d <= 3 && lh_tri_interpolate(t, LH_INTERP_NATURAL, m, q, 2, values, nat) != LH_OK))
        abort();
    for (size_t i = 0; i < m; i++) {
        const double *qi = q + i * d;
        lh_location loc, loc2;
        if (lh_tri_locate(t, qi, -1, &loc) != LH_OK) abort();
        lh_index hint = (lh_index)((flags >> 1) % count);
        if (lh_tri_locate(t, qi, hint, &loc2) != LH_OK || loc2.simplex != loc.simplex) abort();
        lh_index first = -1;
        for (size_t s = 0; s < count && first < 0; s++)
            if (contains(p, d, x, simp + s * (d + 1), qi)) first = (lh_index)s;
        if (loc.simplex != first) abort(); /* not the smallest simplex containing q */
        int inside = first >= 0;
        if (!inside && (loc.hull_facet < 0 || (size_t)loc.hull_facet >= hulls || !(loc.distance > 0))) abort();
        lh_index site = -1;
        if (lh_tri_nearest(t, qi, hint, &site) != LH_OK || site < 0 || (size_t)site >= n || dup[site] != site)
            abort();
        for (size_t j = 0; j < n; j++) {
            int c = lh_distance_compare(p, d, qi, x + (size_t)site * d, x + j * d);
            if (c > 0 || (c == 0 && (lh_index)j < site && dup[j] == (lh_index)j)) abort();
        }
        for (int c = 0; c < 2; c++) {
            double want = affine(c, d, qi), scale = affine_scale(c, d, qi) + vmax[c];
            check_value(lin[i * 2 + c], want, scale, inside);
            if (d <= 3) check_value(nat[i * 2 + c], want, scale, inside);
            if (near[i * 2 + c] != values[(size_t)site * 2 + c]) abort();
        }
    }
    lh_pred_free(p);
    lh_tri_free(t);
    return 0;
}
