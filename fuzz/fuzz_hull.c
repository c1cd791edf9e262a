/*
 * fuzz_hull.c — libFuzzer target: lh_convex_hull on small fuzzer-chosen point sets of
 * small integers (so coplanar, collinear and duplicate sites are common), d = 2..6.
 * Byte 0 picks d, byte 1 the grid (coarse 0..2 or 0..4, or int8 values, or quarters)
 * and the seed; the rest are coordinates. Whatever comes back must be right, exactly:
 *   - LH_OK exactly when the distinct sites span R^d (lh_coords_affine_dim), else
 *     LH_ERR_DEGENERATE with *out NULL;
 *   - lh_hull_duplicate_of maps each site to its first equal site;
 *   - every facet: d distinct site indices, none a merged duplicate, in canonical order
 *     (increasing, the last two possibly exchanged), facets strictly increasing;
 *   - orient_d(facet, p) <= 0 for every site p (no site strictly outside), and < 0 for
 *     some site (no facet flat: its vertices affinely independent);
 *   - every ridge (d-1 vertices of a facet) lies in exactly two facets;
 *   - lh_hull_vertices is exactly the increasing list of sites used by the facets,
 *     and each is a corner: outside the hull of the other sites (or needed for them
 *     to span R^d) — so, with the above, the vertices are exactly the corners;
 *   - a second run with another lh_options.seed gives the same output
 *     (fuzz/findings/hull_seed.md);
 *   - when no d+1 distinct sites lie on a hyperplane, the facets are exactly
 *     lh_delaunay's hull facets (lh_tri_hull_facets).
 * Anything else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "lifthull.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXD 6
#define MAXN 48

static int same_site(int d, const double *a, const double *b)
{
    for (int j = 0; j < d; j++)
        if (a[j] != b[j]) return 0;
    return 1;
}

static int cmp_rows(const lh_index *a, const lh_index *b, int w)
{
    for (int k = 0; k < w; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

static int ridge_w; /* qsort has no user pointer; set before each sort */
static int cmp_ridge(const void *a, const void *b) { return cmp_rows(a, b, ridge_w); }

static void sort_small(lh_index *v, int w)
{
    for (int a = 1; a < w; a++)
        for (int b = a; b > 0 && v[b] < v[b - 1]; b--) {
            lh_index t = v[b];
            v[b] = v[b - 1];
            v[b - 1] = t;
        }
}

/* 1 when no d+1 of the distinct sites rep[0..m-1] are affinely dependent; stops
 * (returning 0, "unknown") after `budget` orientation tests. */
static int general_position(lh_pred *p, int d, const double *x, const lh_index *rep, int m, long budget)
{
    int idx[MAXD + 1];
    if (m < d + 1) return 0;
    for (int k = 0; k <= d; k++) idx[k] = k;
    for (;;) {
        const double *pts[MAXD + 1];
        for (int k = 0; k <= d; k++) pts[k] = x + (size_t)rep[idx[k]] * d;
        if (--budget < 0 || lh_orient(p, d, pts) == 0) return 0;
        int k = d;
        while (k >= 0 && idx[k] == m - d - 1 + k) k--;
        if (k < 0) return 1;
        idx[k]++;
        for (int j = k + 1; j <= d; j++) idx[j] = idx[j - 1] + 1;
    }
}

static int same_hull(const lh_hull *a, const lh_hull *b, int d, size_t n)
{
    size_t m = lh_hull_facet_count(a), v = lh_hull_vertex_count(a);
    return m == lh_hull_facet_count(b) && v == lh_hull_vertex_count(b) &&
           !memcmp(lh_hull_facets(a), lh_hull_facets(b), m * (size_t)d * sizeof(lh_index)) &&
           !memcmp(lh_hull_vertices(a), lh_hull_vertices(b), v * sizeof(lh_index)) &&
           !memcmp(lh_hull_duplicate_of(a), lh_hull_duplicate_of(b), n * sizeof(lh_index));
}

/* Whether site v is a corner: outside the hull of the sites other than v and its
 * duplicates, or needed for them to span R^d. */
static int is_corner(lh_pred *p, int d, size_t n, const double *x, size_t v)
{
    double y[MAXN * MAXD];
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (!same_site(d, x + i * d, x + v * d)) memcpy(y + m++ * d, x + i * d, (size_t)d * sizeof *y);
    lh_hull *h = NULL;
    if (lh_convex_hull(d, m, y, NULL, &h) != LH_OK) return 1;
    int corner = 0;
    const lh_index *f = lh_hull_facets(h);
    for (size_t i = 0; i < lh_hull_facet_count(h) && !corner; i++) {
        const double *pts[MAXD + 1];
        for (int k = 0; k < d; k++) pts[k] = y + (size_t)f[i * d + k] * d;
        pts[d] = x + v * d;
        corner = lh_orient(p, d, pts) > 0;
    }
    lh_hull_free(h);
    return corner;
}

static void check_hull(lh_pred *p, int d, size_t n, const double *x, const lh_hull *h)
{
    size_t m = lh_hull_facet_count(h);
    const lh_index *f = lh_hull_facets(h), *dup = lh_hull_duplicate_of(h);
    if (lh_hull_dim(h) != d || m < (size_t)d + 1 || !f || !dup) abort();
    for (size_t i = 0; i < n; i++) { /* the first equal site */
        size_t j = 0;
        while (!same_site(d, x + j * d, x + i * d)) j++;
        if (dup[i] != (lh_index)j) abort();
    }
    uint8_t used[MAXN] = {0};
    for (size_t i = 0; i < m; i++) {
        const lh_index *v = f + i * d;
        lh_index s[MAXD];
        for (int k = 0; k < d; k++) {
            if (v[k] < 0 || (size_t)v[k] >= n || dup[v[k]] != v[k]) abort();
            used[v[k]] = 1;
            s[k] = v[k];
        }
        sort_small(s, d);
        for (int k = 1; k < d; k++)
            if (s[k] == s[k - 1]) abort();
        /* canonical: sorted, or sorted with the last two exchanged */
        int swapped = v[d - 2] == s[d - 1] && v[d - 1] == s[d - 2];
        if (memcmp(v, s, (size_t)(d - 2) * sizeof *v) || (!swapped && memcmp(v, s, (size_t)d * sizeof *v)))
            abort();
        if (i && cmp_rows(f + (i - 1) * d, v, d) >= 0) abort();
        const double *pts[MAXD + 1];
        for (int k = 0; k < d; k++) pts[k] = x + (size_t)v[k] * d;
        int inner = 0;
        for (size_t q = 0; q < n; q++) {
            pts[d] = x + q * d;
            int o = lh_orient(p, d, pts);
            if (o > 0) abort(); /* a site strictly outside facet i */
            inner |= o < 0;
        }
        if (!inner) abort(); /* facet i flat */
    }
    /* ridges: each (d-1)-subset of a facet, sorted, then counted in runs */
    int w = d - 1;
    size_t r = m * (size_t)d;
    lh_index *ridge = malloc(r * (size_t)w * sizeof *ridge);
    if (!ridge) abort();
    for (size_t i = 0; i < m; i++)
        for (int skip = 0; skip < d; skip++) {
            lh_index *o = ridge + (i * d + skip) * w;
            for (int k = 0, q = 0; k < d; k++)
                if (k != skip) o[q++] = f[i * d + k];
            sort_small(o, w);
        }
    ridge_w = w;
    qsort(ridge, r, (size_t)w * sizeof *ridge, cmp_ridge);
    for (size_t a = 0; a < r;) {
        size_t b = a + 1;
        while (b < r && !cmp_rows(ridge + a * w, ridge + b * w, w)) b++;
        if (b - a != 2) abort(); /* a ridge in one facet only, or in three or more */
        a = b;
    }
    free(ridge);
    size_t nv = lh_hull_vertex_count(h), k = 0;
    const lh_index *vert = lh_hull_vertices(h);
    for (size_t i = 0; i < n; i++)
        if (used[i] && (k >= nv || vert[k++] != (lh_index)i)) abort();
    if (k != nv) abort(); /* a listed vertex no facet uses */
    for (size_t i = 0; i < nv; i++)
        if (!is_corner(p, d, n, x, (size_t)vert[i])) abort(); /* a vertex not a corner */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    int d = 2 + data[0] % 5, flags = data[1];
    size_t n = (size - 2) / (size_t)d;
    if (n > MAXN) n = MAXN;
    double x[MAXN * MAXD];
    for (size_t i = 0; i < n * (size_t)d; i++) {
        int8_t v = (int8_t)data[2 + i];
        switch (flags & 3) {
        case 0: x[i] = (double)(v % 3); break; /* 3^d grid: heavily degenerate */
        case 1: x[i] = (double)(v % 5); break;
        case 2: x[i] = v; break;
        default: x[i] = v / 4.0; break;
        }
    }
    lh_options o;
    lh_options_default(&o);
    lh_hull *h = NULL;
    lh_status st = lh_convex_hull(d, n, x, &o, &h);
    int dim = -2;
    if (lh_coords_affine_dim(d, n, x, NULL, &dim) != LH_OK) abort();
    if (st != (dim == d ? LH_OK : LH_ERR_DEGENERATE) || (st != LH_OK) != (h == NULL)) abort();
    if (st != LH_OK) return 0;
    lh_pred *p;
    if (lh_pred_create(NULL, &p) != LH_OK) abort();
    check_hull(p, d, n, x, h);
    lh_hull *h2 = NULL;
    o.seed = 0x9e3779b97f4a7c15u * (uint64_t)(flags + 1);
    if (lh_convex_hull(d, n, x, &o, &h2) != LH_OK) abort();
    check_hull(p, d, n, x, h2);
    if (!same_hull(h, h2, d, n)) abort(); /* the hull does not depend on the seed */
    lh_hull_free(h2);
    lh_index rep[MAXN];
    int m = 0;
    const lh_index *dup = lh_hull_duplicate_of(h);
    for (size_t i = 0; i < n; i++)
        if (dup[i] == (lh_index)i) rep[m++] = (lh_index)i;
    if (general_position(p, d, x, rep, m, 20000)) {
        lh_tri *t = NULL;
        lh_options_default(&o);
        if (lh_delaunay(d, n, x, &o, &t) != LH_OK) abort();
        size_t c = lh_tri_hull_count(t);
        if (c != lh_hull_facet_count(h) ||
            memcmp(lh_tri_hull_facets(t), lh_hull_facets(h), c * (size_t)d * sizeof(lh_index)))
            abort(); /* in general position the hull is the Delaunay triangulation's */
        lh_tri_free(t);
    }
    lh_pred_free(p);
    lh_hull_free(h);
    return 0;
}
