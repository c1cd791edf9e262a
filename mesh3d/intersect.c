/*
 * intersect.c — lh_plc_intersections: the pairs of facets that meet other than in what
 * they share (TetGen's -d; docs/meshing3d.md, "Self-intersections").
 *
 * 1. Every facet is triangulated in its plane (facets.h), with no new point.
 * 2. Points of equal coordinates are one point: each gets the smallest index among
 *    its equals, so that triangles sharing a corner are recognised by index.
 * 3. Candidate pairs from a uniform grid over the triangles' bounding boxes, cells
 *    as large as the mean box's largest side: an entry (cell, triangle) for each
 *    cell a box overlaps, radix-sorted by cell, so only occupied cells cost memory
 *    (a surface fills few of its grid's cells). A pair is tested in one cell only,
 *    the first cell (lowest coordinates) both boxes overlap, so no pair is tested
 *    twice and no table of tested pairs is kept.
 * 4. Each pair of triangles of different facets whose boxes overlap is tested exactly
 *    (intersect.h): they intersect when they meet other than in the corners they
 *    share. Triangles of one facet are never compared.
 * 5. The facet pairs of intersecting triangles are sorted and made unique.
 */
#include "facets.h"
#include "intersect.h"
#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_sort.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* The state of one call: triangles, their boxes, the grid, the pairs found. */
typedef struct isect {
    const lh_plc *g;
    const lh_allocator *al;
    lh_pred *pred;
    lh__facet_tris ft;
    lh_index *rep;          /* g->n: the smallest index of a point of equal coordinates */
    double *box;            /* 6 per triangle: min x y z, max x y z                     */
    size_t *clo;            /* 3 per triangle: the cell of its box's min corner          */
    double lo[3], h;        /* the grid's origin and cell size                         */
    size_t dim[3];          /* cells along each axis                                   */
    size_t nent;            /* entries: (cell, triangle) for each cell a box overlaps   */
    uint64_t *key;          /* nent cell numbers, sorted                                */
    lh_index *item;         /* nent triangles, in the order of key                      */
    lh_index *pairs;        /* 2 per facet pair found (with repeats until step 5)      */
    size_t npairs, pairs_cap;
} isect;

static void isect_free(isect *s)
{
    lh__facet_tris_free(s->al, &s->ft);
    lh__free(s->al, s->rep);
    lh__free(s->al, s->box);
    lh__free(s->al, s->clo);
    lh__free(s->al, s->key);
    lh__free(s->al, s->item);
    lh__free(s->al, s->pairs);
    lh_pred_free(s->pred);
}

static void *alloc_n(const lh_allocator *al, size_t n, size_t size)
{
    return n > SIZE_MAX / size ? NULL : lh__alloc(al, n ? n * size : 1);
}

/* ---- step 2: equal points --------------------------------------------------------- */

static int cmp_point(const void *ctx, lh_index a, lh_index b)
{
    const double *xyz = ctx, *p = xyz + 3 * (size_t)a, *q = xyz + 3 * (size_t)b;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

static lh_status merge_equal_points(isect *s)
{
    const size_t n = s->g->n;
    lh_index *tmp = alloc_n(s->al, n, sizeof(lh_index));
    s->rep = alloc_n(s->al, n, sizeof(lh_index));
    if (!tmp || !s->rep) {
        lh__free(s->al, tmp);
        return LH_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++) s->rep[i] = (lh_index)i;
    lh__sort_idx(s->rep, tmp, n, cmp_point, s->g->xyz); /* stable: equals by index */
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && !cmp_point(s->g->xyz, s->rep[i], s->rep[j]); j++) {}
        for (size_t k = i; k < j; k++) tmp[s->rep[k]] = s->rep[i];
    }
    lh__free(s->al, s->rep);
    s->rep = tmp;
    for (size_t t = 0; t < 3 * s->ft.count; t++) s->ft.tri[t] = s->rep[s->ft.tri[t]];
    return LH_OK;
}

/* ---- step 3: the grid ------------------------------------------------------------- */

static lh_status boxes(isect *s, double ext[3], double *mean)
{
    const size_t tc = s->ft.count;
    s->box = alloc_n(s->al, 6 * tc, sizeof(double));
    if (!s->box) return LH_ERR_NOMEM;
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY}, sum = 0;
    s->lo[0] = s->lo[1] = s->lo[2] = INFINITY;
    for (size_t t = 0; t < tc; t++) {
        double *b = s->box + 6 * t, big = 0;
        for (int k = 0; k < 3; k++) {
            b[k] = INFINITY, b[k + 3] = -INFINITY;
            for (int c = 0; c < 3; c++) {
                const double x = s->g->xyz[3 * (size_t)s->ft.tri[3 * t + c] + k];
                b[k] = x < b[k] ? x : b[k];
                b[k + 3] = x > b[k + 3] ? x : b[k + 3];
            }
            s->lo[k] = b[k] < s->lo[k] ? b[k] : s->lo[k];
            hi[k] = b[k + 3] > hi[k] ? b[k + 3] : hi[k];
            big = b[k + 3] - b[k] > big ? b[k + 3] - b[k] : big;
        }
        sum += big;
    }
    for (int k = 0; k < 3; k++) ext[k] = hi[k] - s->lo[k];
    *mean = sum / (double)tc;
    return LH_OK;
}

/* The cell of coordinate x along axis k (clamped into the grid). */
static size_t cell_of(const isect *s, int k, double x)
{
    if (s->dim[k] == 1) return 0;
    const double c = (x - s->lo[k]) / s->h;
    return c >= (double)(s->dim[k] - 1) ? s->dim[k] - 1 : (size_t)c;
}

/* Cells of side h (at least 1/2^20 of the extent along each axis). */
static void grid_size(isect *s, const double ext[3], double h)
{
    const double most = 1048576;
    for (int k = 0; k < 3; k++)
        if (ext[k] / h >= most) h = ext[k] / (most - 1);
    s->h = h;
    for (int k = 0; k < 3; k++) {
        const int ok = isfinite(ext[k]) && isfinite(h); /* else beyond the doubles' range */
        s->dim[k] = ok ? (size_t)floor(ext[k] / h) + 1 : 1;
    }
}

/* The cell range of triangle t's box: lo[k] .. hi[k] along each axis. */
static void cell_range(const isect *s, size_t t, size_t lo[3], size_t hi[3])
{
    const double *b = s->box + 6 * t;
    for (int k = 0; k < 3; k++) lo[k] = cell_of(s, k, b[k]), hi[k] = cell_of(s, k, b[k + 3]);
}

static uint64_t cell_key(const isect *s, size_t x, size_t y, size_t z)
{
    return ((uint64_t)x * s->dim[1] + y) * s->dim[2] + z;
}

/* Counts (fill 0; stopping past limit) or lists (fill 1) each triangle in every cell
 * its box overlaps; records the first of them in clo. */
static void grid_pass(isect *s, int fill, size_t limit)
{
    size_t e = 0;
    for (size_t t = 0; t < s->ft.count; t++) {
        size_t *lo = s->clo + 3 * t, hi[3];
        cell_range(s, t, lo, hi);
        if (!fill) {
            e += (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
            if (e > limit) break;
            continue;
        }
        for (size_t x = lo[0]; x <= hi[0]; x++)
            for (size_t y = lo[1]; y <= hi[1]; y++)
                for (size_t z = lo[2]; z <= hi[2]; z++) {
                    s->key[e] = cell_key(s, x, y, z);
                    s->item[e++] = (lh_index)t;
                }
    }
    s->nent = e;
}

/* LSD radix sort of the entries by key, 11 bits a pass, through the scratch arrays
 * k2, i2 (nent each), which it frees. */
static void radix_sort(isect *s, uint64_t *k2, lh_index *i2)
{
    const uint64_t top = cell_key(s, s->dim[0] - 1, s->dim[1] - 1, s->dim[2] - 1);
    for (int shift = 0; shift < 64 && (top >> shift); shift += 11) {
        size_t count[2049] = {0};
        for (size_t e = 0; e < s->nent; e++) count[((s->key[e] >> shift) & 2047) + 1]++;
        for (int d = 0; d < 2048; d++) count[d + 1] += count[d];
        for (size_t e = 0; e < s->nent; e++) {
            const size_t at = count[(s->key[e] >> shift) & 2047]++;
            k2[at] = s->key[e], i2[at] = s->item[e];
        }
        uint64_t *kt = s->key;
        lh_index *it = s->item;
        s->key = k2, s->item = i2, k2 = kt, i2 = it;
    }
    lh__free(s->al, k2);
    lh__free(s->al, i2);
}

static lh_status grid_build(isect *s)
{
    double ext[3], mean;
    lh_status st = boxes(s, ext, &mean);
    if (st != LH_OK) return st;
    s->clo = alloc_n(s->al, 3 * s->ft.count, sizeof(size_t));
    if (!s->clo) return LH_ERR_NOMEM;
    /* a few boxes far larger than the mean would overlap too many cells: coarser */
    const size_t limit = 8 * s->ft.count + 1024;
    for (double h = mean > 0 ? mean : 1;; h *= 2) {
        grid_size(s, ext, h);
        grid_pass(s, 0, limit);
        if (s->nent <= limit) break;
    }
    s->key = alloc_n(s->al, s->nent, sizeof(uint64_t));
    s->item = alloc_n(s->al, s->nent, sizeof(lh_index));
    uint64_t *k2 = alloc_n(s->al, s->nent, sizeof(uint64_t));
    lh_index *i2 = alloc_n(s->al, s->nent, sizeof(lh_index));
    if (!s->key || !s->item || !k2 || !i2) {
        lh__free(s->al, k2), lh__free(s->al, i2);
        return LH_ERR_NOMEM;
    }
    grid_pass(s, 1, 0);
    radix_sort(s, k2, i2);
    return LH_OK;
}

/* ---- step 4: the exact tests ------------------------------------------------------ */

static int boxes_overlap(const double *a, const double *b)
{
    for (int k = 0; k < 3; k++)
        if (a[k] > b[k + 3] || b[k] > a[k + 3]) return 0;
    return 1;
}

/* Cell (x, y, z) is the first that both t's and u's boxes overlap. */
static int first_common_cell(const isect *s, size_t t, size_t u, const size_t cell[3])
{
    const size_t *lt = s->clo + 3 * t, *lu = s->clo + 3 * u;
    for (int k = 0; k < 3; k++)
        if (cell[k] != (lt[k] > lu[k] ? lt[k] : lu[k])) return 0;
    return 1;
}

/* Triangles t and u (of different facets) meet other than in the corners they
 * share: their corners reordered, the shared ones first and in the same order. */
static int triangles_meet(const isect *s, size_t t, size_t u)
{
    const lh_index *vt = s->ft.tri + 3 * t, *vu = s->ft.tri + 3 * u;
    int ia[3], ib[3], na = 0, shared = 0, used[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (vt[i] == vu[j] && !used[j]) {
                ia[shared] = i, ib[shared] = j, used[j] = 1, shared++;
                break;
            }
    na = shared;
    for (int i = 0; i < 3; i++) {
        int seen = 0;
        for (int k = 0; k < shared; k++) seen |= ia[k] == i;
        if (!seen) ia[na++] = i;
    }
    for (int j = 0, nb = shared; j < 3; j++)
        if (!used[j]) ib[nb++] = j;
    const double *a[3], *b[3];
    for (int i = 0; i < 3; i++) {
        a[i] = s->g->xyz + 3 * (size_t)vt[ia[i]];
        b[i] = s->g->xyz + 3 * (size_t)vu[ib[i]];
    }
    return lh__tri_tri_meet(s->pred, a, b, shared);
}

static lh_status add_pair(isect *s, lh_index f, lh_index h)
{
    if (s->npairs == s->pairs_cap) {
        const size_t cap = s->pairs_cap ? 2 * s->pairs_cap : 256;
        lh_index *p = alloc_n(s->al, 2 * cap, sizeof(lh_index));
        if (!p) return LH_ERR_NOMEM;
        if (s->npairs) memcpy(p, s->pairs, 2 * s->npairs * sizeof(lh_index));
        lh__free(s->al, s->pairs);
        s->pairs = p, s->pairs_cap = cap;
    }
    s->pairs[2 * s->npairs] = f < h ? f : h;
    s->pairs[2 * s->npairs + 1] = f < h ? h : f;
    s->npairs++;
    return LH_OK;
}

/* The pairs of the cell whose entries are e0 .. e1-1, tested here. */
static lh_status scan_cell(isect *s, size_t e0, size_t e1)
{
    const uint64_t key = s->key[e0];
    const size_t cell[3] = {(size_t)(key / s->dim[2] / s->dim[1]), (size_t)(key / s->dim[2] % s->dim[1]),
                            (size_t)(key % s->dim[2])};
    for (size_t i = e0; i < e1; i++) {
        const size_t t = (size_t)s->item[i];
        for (size_t j = i + 1; j < e1; j++) {
            const size_t u = (size_t)s->item[j];
            const lh_index f = s->ft.facet[t], h = s->ft.facet[u];
            if (f == h || !boxes_overlap(s->box + 6 * t, s->box + 6 * u) ||
                !first_common_cell(s, t, u, cell) || !triangles_meet(s, t, u))
                continue;
            lh_status st = add_pair(s, f, h);
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

static lh_status scan(isect *s)
{
    for (size_t e0 = 0, e1; e0 < s->nent; e0 = e1) {
        for (e1 = e0 + 1; e1 < s->nent && s->key[e1] == s->key[e0]; e1++) {}
        lh_status st = scan_cell(s, e0, e1);
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

/* ---- step 5: unique pairs --------------------------------------------------------- */

static lh_status unique_pairs(isect *s, size_t *count)
{
    const size_t n = s->npairs;
    lh_index *idx = alloc_n(s->al, n, sizeof(lh_index)), *tmp = alloc_n(s->al, n, sizeof(lh_index));
    lh_index *out = alloc_n(s->al, 2 * n, sizeof(lh_index));
    if (!idx || !tmp || !out) {
        lh__free(s->al, idx), lh__free(s->al, tmp), lh__free(s->al, out);
        return LH_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++) idx[i] = (lh_index)i;
    const lh__rows rows = {s->pairs, 2, 2};
    lh__sort_idx(idx, tmp, n, lh__rows_cmp, &rows);
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        const lh_index *p = s->pairs + 2 * (size_t)idx[i];
        if (m && out[2 * m - 2] == p[0] && out[2 * m - 1] == p[1]) continue;
        out[2 * m] = p[0], out[2 * m + 1] = p[1], m++;
    }
    lh__free(s->al, idx), lh__free(s->al, tmp), lh__free(s->al, s->pairs);
    s->pairs = out, s->npairs = m;
    *count = m;
    return LH_OK;
}

lh_status lh_plc_intersections(const lh_plc *g, const lh_allocator *alloc, size_t cap,
                               lh_index *pairs, size_t *count, lh_error *err)
{
    lh__error_clear(err);
    if (count) *count = 0;
    lh_allocator al;
    if (!g || !count || (cap && !pairs) || !lh__allocator_init(&al, alloc))
        return lh__error_done(err, LH_ERR_INVALID_ARGUMENT);
    isect s;
    memset(&s, 0, sizeof s);
    s.g = g, s.al = &al;
    lh_status st = lh__facets_triangulate(g, &al, &s.ft, err);
    if (st == LH_OK) st = lh_pred_create(&al, &s.pred);
    if (st == LH_OK) st = merge_equal_points(&s);
    if (st == LH_OK && s.ft.count > 1) {
        st = grid_build(&s);
        if (st == LH_OK) st = scan(&s);
        if (st == LH_OK) st = unique_pairs(&s, count);
    }
    if (st == LH_OK) {
        const size_t w = *count < cap ? *count : cap;
        if (w) memcpy(pairs, s.pairs, 2 * w * sizeof(lh_index));
    }
    isect_free(&s);
    return lh__error_done(err, st);
}
