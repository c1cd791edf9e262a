/*
 * measure.c — lengths, areas and volumes of simplices (Qhull's FA, Fa, FS):
 * lh_simplex_measures, lh_tri_measures, lh_hull_measures.
 *
 * The k-measure of a simplex p_0..p_k in R^d is sqrt(det G) / k!, G the Gram matrix
 * of the edges p_i - p_0; by the Cauchy-Binet formula det G is the sum of the
 * squares of the k x k minors of the edge matrix over every k of the d columns, and
 * each such minor is a minor of the homogeneous matrix [1, p_i] (its column of ones
 * and the k columns), computed exactly and rounded once (lh__minor_value). For
 * k = d that is one determinant: two roundings in all. A total of full-dimensional
 * volumes, and the volume a hull's facets enclose (coned from one of its vertices),
 * are exact sums of exact determinants rounded once (lh__detsum_value).
 */
#include "dt.h"
#include "lh_exact.h"

#include <math.h>

static double factorial(int k)
{
    double f = 1;
    for (int i = 2; i <= k; i++) f *= i;
    return f;
}

/* The k-measure of the simplex pts[0..k] in R^d (lh__minor_value on every choice of
 * k columns; the squares summed after scaling by the largest exponent, so nothing
 * overflows before the final ldexp). */
static double simplex_measure(lh_pred *ctx, int d, int k, const double *const *pts)
{
    int rows[LH_DELAUNAY_MAX_DIM + 1], cols[LH_DELAUNAY_MAX_DIM + 1];
    double v[70]; /* C(8, 4), the most column choices */
    int e[70], count = 0, emax = INT32_MIN;
    for (int i = 0; i <= k; i++) rows[i] = i;
    cols[0] = 0;
    for (int i = 1; i <= k; i++) cols[i] = i; /* columns 1..k, then the next choices */
    for (;;) {
        v[count] = lh__minor_value(ctx, pts, d, k + 1, rows, cols, &e[count]);
        if (v[count] != 0 && e[count] > emax) emax = e[count];
        count++;
        int i = k;
        while (i >= 1 && cols[i] == d - k + i) i--;
        if (i < 1) break;
        cols[i]++;
        for (int j = i + 1; j <= k; j++) cols[j] = cols[j - 1] + 1;
    }
    if (emax == INT32_MIN) return 0;
    double sum = 0;
    for (int i = 0; i < count; i++) {
        double x = v[i] != 0 ? ldexp(v[i], e[i] - emax) : 0;
        sum += x * x;
    }
    return ldexp(sqrt(sum) / factorial(k), emax); /* divided first: no overflow on the way */
}

/* Neumaier's compensated sum (Neumaier 1974, "Rundungsfehleranalyse einiger
 * Verfahren zur Summation endlicher Summen"): the error of the running sum is kept
 * in *c and added at the end. */
static void neumaier_add(double *s, double *c, double x)
{
    double t = *s + x;
    if (isinf(t)) { /* past DBL_MAX: the total is +inf; a correction would be inf - inf */
        *s = t;
        *c = 0;
        return;
    }
    *c += fabs(*s) >= fabs(x) ? (*s - t) + x : (x - t) + *s;
    *s = t;
}

/* The lowest set bit's exponent among the coordinates of the listed sites (the
 * common scale lh__detsum needs); 0 when every one is 0. */
static int sites_scale(int d, const double *xyz, size_t count, const lh_index *idx)
{
    int scale = 0, any = 0;
    for (size_t i = 0; i < count; i++)
        for (int j = 0; j < d; j++) {
            double x = xyz[(size_t)idx[i] * d + j];
            if (x == 0) continue;
            int e = lh__dbl_low_exp(x);
            if (!any || e < scale) scale = e;
            any = 1;
        }
    return scale;
}

static int valid(int d, int k, const double *xyz, size_t n, size_t m, const lh_index *simp)
{
    if (d < 1 || d > LH_DELAUNAY_MAX_DIM || k < 1 || k > d || (m && (!xyz || !simp))) return 0;
    for (size_t i = 0; i < m * (size_t)(k + 1); i++)
        if (simp[i] < 0 || (size_t)simp[i] >= n) return 0;
    return 1;
}

/* Exact total of the full-dimensional simplices' volumes (|det| / d!), rounded. */
static lh_status exact_total(const lh_allocator *al, lh_pred *ctx, int d, const double *xyz, size_t m,
                             const lh_index *simp, double *total)
{
    lh__detsum *sum = NULL;
    lh_status st = lh__detsum_create(al, d, sites_scale(d, xyz, m * (size_t)(d + 1), simp), &sum);
    if (st != LH_OK) return st;
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (size_t s = 0; s < m; s++) {
        for (int i = 0; i <= d; i++) p[i] = xyz + (size_t)simp[s * (d + 1) + i] * d;
        lh__detsum_add(ctx, sum, p, lh_orient(ctx, d, p) < 0);
    }
    int e;
    double v = lh__detsum_value(sum, &e);
    *total = ldexp(v / factorial(d), e);
    lh__detsum_free(sum);
    return LH_OK;
}

/* lh_simplex_measures with its allocations through al (NULL: malloc): a handle's
 * measures use the handle's hooks. */
static lh_status measures(const lh_allocator *al, int d, int k, const double *xyz, size_t n, size_t m,
                          const lh_index *simplices, double *each, double *total)
{
    if (!valid(d, k, xyz, n, m, simplices)) return LH_ERR_INVALID_ARGUMENT;
    lh_pred *ctx;
    lh_status st = lh_pred_create(al, &ctx);
    if (st != LH_OK) return st;
    double s = 0, c = 0;
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (size_t t = 0; t < m && (each || (total && k < d)); t++) {
        for (int i = 0; i <= k; i++) p[i] = xyz + (size_t)simplices[t * (k + 1) + i] * d;
        double x = simplex_measure(ctx, d, k, p);
        if (each) each[t] = x;
        neumaier_add(&s, &c, x);
    }
    if (total && k < d) *total = s + c;
    else if (total) st = exact_total(al, ctx, d, xyz, m, simplices, total);
    lh_pred_free(ctx);
    return st;
}

lh_status lh_simplex_measures(int d, int k, const double *xyz, size_t n, size_t m,
                              const lh_index *simplices, double *each, double *total)
{
    return measures(NULL, d, k, xyz, n, m, simplices, each, total);
}

lh_status lh_tri_measures(const lh_tri *t, double *each, double *total)
{
    if (!t) return LH_ERR_INVALID_ARGUMENT;
    return measures(&t->alloc, t->d, t->frame.k, t->xyz, t->n, t->count, t->simp, each, total);
}

/* The volume the outward facets enclose: the cone from a vertex o over every facet,
 * sum det(f, o) = -d! volume (orient_d(f, o) <= 0 for o inside), exactly. */
static lh_status enclosed_volume(const lh_allocator *al, lh_pred *ctx, int d, const double *xyz, size_t m,
                                 const lh_index *facets, double *volume)
{
    *volume = 0;
    if (m == 0) return LH_OK;
    lh__detsum *sum = NULL;
    lh_status st = lh__detsum_create(al, d, sites_scale(d, xyz, m * (size_t)d, facets), &sum);
    if (st != LH_OK) return st;
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    p[d] = xyz + (size_t)facets[0] * d;
    for (size_t f = 0; f < m; f++) {
        for (int i = 0; i < d; i++) p[i] = xyz + (size_t)facets[f * d + i] * d;
        lh__detsum_add(ctx, sum, p, 1);
    }
    int e;
    double v = lh__detsum_value(sum, &e);
    *volume = ldexp(v / factorial(d), e);
    lh__detsum_free(sum);
    return LH_OK;
}

lh_status lh_hull_measures(const lh_hull *h, const double *xyz, size_t n, double *each,
                           double *area, double *volume)
{
    if (!h) return LH_ERR_INVALID_ARGUMENT;
    const int d = lh_hull_dim(h);
    const size_t m = lh_hull_facet_count(h);
    const lh_index *f = lh_hull_facets(h);
    const lh_allocator *al = lh__hull_allocator(h);
    lh_status st = LH_OK;
    if (each || area) st = measures(al, d, d - 1, xyz, n, m, f, each, area);
    else if (!valid(d, d - 1, xyz, n, m, f)) st = LH_ERR_INVALID_ARGUMENT;
    if (st != LH_OK || !volume) return st;
    lh_pred *ctx;
    st = lh_pred_create(al, &ctx);
    if (st != LH_OK) return st;
    st = enclosed_volume(al, ctx, d, xyz, m, f, volume);
    lh_pred_free(ctx);
    return st;
}
