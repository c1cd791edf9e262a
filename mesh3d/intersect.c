/*
 * intersect.c — lh_plc_intersections: the pairs of facets that meet other than in what
 * they share (TetGen's -d; docs/meshing3d.md, "Self-intersections").
 *
 * 1. Every facet is triangulated in its plane (facets.h), with no new point.
 * 2. Points of equal coordinates are one point: each gets the smallest index among
 *    its equals, so that triangles sharing a corner are recognised by index.
 * 2b. Identical triangles (the same three corners) form a group, represented by its
 *    first: members of a group all overlap one another, and meet a triangle exactly
 *    when their representative does, so only representatives are compared (10^6
 *    copies of one triangle cost one test, not 5 10^11).
 * 3. Candidate pairs from a uniform grid over the triangles' bounding boxes, cells
 *    as large as the mean box's largest side: an entry (cell, triangle) for each
 *    cell a box overlaps, radix-sorted by cell, so only occupied cells cost memory
 *    (a surface fills few of its grid's cells). A pair is tested in one cell only,
 *    the first cell (lowest coordinates) both boxes overlap, so no pair is tested
 *    twice and no table of tested pairs is kept.
 * 4. Each pair of triangles of different facets whose boxes overlap is tested exactly
 *    (intersect.h): they intersect when they meet other than in the corners they
 *    share. Triangles of one facet are never compared.
 * 5. The facet pairs of intersecting triangles are sorted and made unique. When every
 *    facet is one triangle (surface formats), facet pairs are triangle pairs, all
 *    distinct: they are counted from the groups' sizes and only the first `cap` are
 *    listed, facet by facet, so copies cost time in what is written only.
 */
#include "facets.h"
#include "intersect.h"
#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_sort.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The state of one call: triangles, their boxes, the grid, the pairs found. */
typedef struct isect {
    const lh_plc *g;
    const lh_allocator *al;
    lh_pred *pred;
    lh__facet_tris ft;
    lh_index *rep;    /* g->n: the smallest index of a point of equal coordinates */
    double *box;      /* 6 per triangle: min x y z, max x y z                     */
    size_t *clo;      /* 3 per triangle: the cell of its box's min corner          */
    double lo[3], h;  /* the grid's origin and cell size                         */
    size_t dim[3];    /* cells along each axis                                   */
    size_t nent;      /* entries: (cell, triangle) for each cell a box overlaps   */
    uint64_t *key;    /* nent cell numbers, sorted                                */
    lh_index *item;   /* nent triangles, in the order of key                      */
    size_t ng;        /* groups of identical triangles                           */
    lh_index *gid;    /* per triangle: its group                                 */
    lh_index *gmem;   /* the triangles by group, ascending within one            */
    lh_index *gfirst; /* ng + 1 offsets into gmem; a group's first: its
                               representative                                       */
    lh_index *pairs;  /* 2 per pair found: groups (step 4), then facets (step 5) */
    size_t npairs, pairs_cap;
    lh_index *ring;   /* 3 per polygon edge (slits too): its representative points,
                         smaller first, and its facet; sorted                       */
    size_t nring;
} isect;

static void isect_free(isect *s)
{
    lh__facet_tris_free(s->al, &s->ft);
    lh__free(s->al, s->rep);
    lh__free(s->al, s->box);
    lh__free(s->al, s->clo);
    lh__free(s->al, s->key);
    lh__free(s->al, s->item);
    lh__free(s->al, s->gid);
    lh__free(s->al, s->gmem);
    lh__free(s->al, s->gfirst);
    lh__free(s->al, s->pairs);
    lh__free(s->al, s->ring);
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
        for (j = i + 1; j < n && !cmp_point(s->g->xyz, s->rep[i], s->rep[j]); j++) {
        }
        for (size_t k = i; k < j; k++) tmp[s->rep[k]] = s->rep[i];
    }
    lh__free(s->al, s->rep);
    s->rep = tmp;
    for (size_t t = 0; t < 3 * s->ft.count; t++) s->ft.tri[t] = s->rep[s->ft.tri[t]];
    return LH_OK;
}

static int cmp_ring(const void *x, const void *y)
{
    const lh_index *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* Step 2a: every facet's polygon edges (ring edges and slits), on representatives. */
static lh_status ring_edges(isect *s)
{
    const lh_plc *g = s->g;
    size_t m = g->facet_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    s->ring = alloc_n(s->al, 3 * m + 3, sizeof(lh_index));
    if (!s->ring) return LH_ERR_NOMEM;
    for (size_t f = 0; f < g->facet_count; f++)
        for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
            const lh_index *v = g->polygon_vertices + g->polygon_first[p];
            size_t len = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
            for (size_t i = 0; len >= 2 && i < (len == 2 ? 1 : len); i++) {
                lh_index a = s->rep[v[i]], b = s->rep[v[(i + 1) % len]];
                lh_index *r = s->ring + 3 * s->nring++;
                r[0] = a < b ? a : b, r[1] = a < b ? b : a, r[2] = (lh_index)f;
            }
        }
    /* cmp_ring's order: by the second point, then the first (stable); rows are made in
       facet order, which stable passes keep among equal pairs */
    const size_t row = 3 * sizeof(lh_index);
    lh_status st = lh__sort_by_index(s->al, s->ring, s->nring, row, sizeof(lh_index), s->g->n);
    return st == LH_OK ? lh__sort_by_index(s->al, s->ring, s->nring, row, 0, s->g->n) : st;
}

/* Whether p q (representatives) is a polygon edge of facet f. */
static int is_ring_edge(const isect *s, lh_index p, lh_index q, lh_index f)
{
    lh_index key[3] = {p < q ? p : q, p < q ? q : p, f};
    return bsearch(key, s->ring, s->nring, 3 * sizeof(lh_index), cmp_ring) != NULL;
}

/* Step 2b: groups of triangles with the same corners (sorted triples compared). */
static lh_status group_identical(isect *s)
{
    const size_t tc = s->ft.count;
    lh_index *key = alloc_n(s->al, 3 * tc, sizeof(lh_index)),
             *tmp = alloc_n(s->al, tc, sizeof(lh_index));
    s->gid = alloc_n(s->al, tc, sizeof(lh_index));
    s->gmem = alloc_n(s->al, tc, sizeof(lh_index));
    s->gfirst = alloc_n(s->al, tc + 1, sizeof(lh_index));
    lh_status st = key && tmp && s->gid && s->gmem && s->gfirst ? LH_OK : LH_ERR_NOMEM;
    for (size_t t = 0; t < tc && st == LH_OK; t++) {
        lh_index *k = key + 3 * t, x;
        memcpy(k, s->ft.tri + 3 * t, 3 * sizeof(lh_index));
        if (k[0] > k[1]) x = k[0], k[0] = k[1], k[1] = x;
        if (k[1] > k[2]) x = k[1], k[1] = k[2], k[2] = x;
        if (k[0] > k[1]) x = k[0], k[0] = k[1], k[1] = x;
        s->gmem[t] = (lh_index)t;
    }
    if (st == LH_OK) {
        const lh__rows rows = {key, 3, 3};
        lh__sort_idx(s->gmem, tmp, tc, lh__rows_cmp, &rows); /* stable: ascending in a group */
        s->ng = 0;
        for (size_t i = 0; i < tc; i++) {
            if (!i || lh__rows_cmp(&rows, s->gmem[i - 1], s->gmem[i]))
                s->gfirst[s->ng++] = (lh_index)i;
            s->gid[s->gmem[i]] = (lh_index)(s->ng - 1);
        }
        s->gfirst[s->ng] = (lh_index)tc;
    }
    lh__free(s->al, key), lh__free(s->al, tmp);
    return st;
}

static size_t group_size(const isect *s, lh_index g)
{
    return (size_t)(s->gfirst[g + 1] - s->gfirst[g]);
}

static int is_representative(const isect *s, size_t t)
{
    return s->gmem[s->gfirst[s->gid[t]]] == (lh_index)t;
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

/* Counts (fill 0; stopping past limit) or lists (fill 1) each representative in
 * every cell its box overlaps; records the first of them in clo. */
static void grid_pass(isect *s, int fill, size_t limit)
{
    size_t e = 0;
    for (size_t t = 0; t < s->ft.count; t++) {
        if (!is_representative(s, t)) continue;
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
    /* A shared edge inside either facet (no polygon edge of it): that facet meets the
       other along a line inside it, which a PLC does not allow. */
    if (shared == 2 && (!is_ring_edge(s, vt[ia[0]], vt[ia[1]], s->ft.facet[t]) ||
                        !is_ring_edge(s, vt[ia[0]], vt[ia[1]], s->ft.facet[u])))
        return 1;
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

/* The pairs of the cell whose entries are e0 .. e1-1 tested here; the groups of
 * those that meet recorded. Representatives of one facet are compared when a group
 * has other members (their facets may differ). */
static lh_status scan_cell(isect *s, size_t e0, size_t e1)
{
    const uint64_t key = s->key[e0];
    const size_t cell[3] = {(size_t)(key / s->dim[2] / s->dim[1]),
                            (size_t)(key / s->dim[2] % s->dim[1]), (size_t)(key % s->dim[2])};
    for (size_t i = e0; i < e1; i++) {
        const size_t t = (size_t)s->item[i];
        for (size_t j = i + 1; j < e1; j++) {
            const size_t u = (size_t)s->item[j];
            const int alone = group_size(s, s->gid[t]) == 1 && group_size(s, s->gid[u]) == 1;
            if ((alone && s->ft.facet[t] == s->ft.facet[u]) ||
                !boxes_overlap(s->box + 6 * t, s->box + 6 * u) ||
                !first_common_cell(s, t, u, cell) || !triangles_meet(s, t, u))
                continue;
            lh_status st = add_pair(s, s->gid[t], s->gid[u]);
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

static lh_status scan(isect *s)
{
    for (size_t e0 = 0, e1; e0 < s->nent; e0 = e1) {
        for (e1 = e0 + 1; e1 < s->nent && s->key[e1] == s->key[e0]; e1++) {
        }
        lh_status st = scan_cell(s, e0, e1);
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

/* Sorts s->pairs and drops repeats; *count their number. */
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

/* ---- step 5: facet pairs ------------------------------------------------------ */

/* Facet pairs of the members of groups a and b (a == b: of one group), facets
 * differing. */
static lh_status add_member_pairs(isect *s, lh_index a, lh_index b)
{
    for (lh_index i = s->gfirst[a]; i < s->gfirst[a + 1]; i++)
        for (lh_index j = a == b ? i + 1 : s->gfirst[b]; j < s->gfirst[b + 1]; j++) {
            const lh_index f = s->ft.facet[s->gmem[i]], h = s->ft.facet[s->gmem[j]];
            lh_status st = f == h ? LH_OK : add_pair(s, f, h);
            if (st != LH_OK) return st;
        }
    return LH_OK;
}

/* The general case: the group pairs expanded to facet pairs, sorted, unique. */
static lh_status facet_pairs(isect *s, size_t *count)
{
    lh_index *gp = s->pairs;
    const size_t ngp = s->npairs;
    s->pairs = NULL, s->npairs = s->pairs_cap = 0;
    lh_status st = LH_OK;
    for (size_t g = 0; g < s->ng && st == LH_OK; g++)
        if (group_size(s, (lh_index)g) > 1) st = add_member_pairs(s, (lh_index)g, (lh_index)g);
    for (size_t i = 0; i < ngp && st == LH_OK; i++)
        st = add_member_pairs(s, gp[2 * i], gp[2 * i + 1]);
    lh__free(s->al, gp);
    return st == LH_OK ? unique_pairs(s, count) : st;
}

static int cmp_value(const void *ctx, lh_index a, lh_index b)
{
    (void)ctx;
    return (a > b) - (a < b);
}

/* Every facet one triangle (triangle t is facet t): the pairs are the members of
 * each group among themselves and of each meeting group pair, all distinct, so
 * counted from the sizes; the first cap written facet by facet, each facet's
 * partners (greater than it) sorted. adj: the meeting groups of each group (CSR). */
static lh_status triangle_pairs(isect *s, const lh_index *adj_first, const lh_index *adj,
                                size_t cap, lh_index *out, size_t *count)
{
    size_t n = 0, w = 0;
    for (size_t g = 0; g < s->ng; g++)
        n += group_size(s, (lh_index)g) * (group_size(s, (lh_index)g) - 1) / 2;
    for (size_t i = 0; i < s->npairs; i++)
        n += group_size(s, s->pairs[2 * i]) * group_size(s, s->pairs[2 * i + 1]);
    *count = n;
    lh_index *buf = alloc_n(s->al, s->ft.count, sizeof(lh_index)),
             *tmp = alloc_n(s->al, s->ft.count, sizeof(lh_index));
    if (!buf || !tmp) {
        lh__free(s->al, buf), lh__free(s->al, tmp);
        return LH_ERR_NOMEM;
    }
    for (size_t f = 0; f < s->ft.count && w < cap && w < n; f++) {
        const lh_index g = s->gid[f];
        size_t m = 0;
        for (lh_index a = adj_first[g] - 1; a < adj_first[g + 1]; a++) { /* -1: g itself */
            const lh_index h = a < adj_first[g] ? g : adj[a];
            for (lh_index i = s->gfirst[h]; i < s->gfirst[h + 1]; i++)
                if ((size_t)s->gmem[i] > f) buf[m++] = s->gmem[i];
        }
        lh__sort_idx(buf, tmp, m, cmp_value, NULL);
        for (size_t i = 0; i < m && w < cap; i++, w++)
            out[2 * w] = (lh_index)f, out[2 * w + 1] = buf[i];
    }
    lh__free(s->al, buf), lh__free(s->al, tmp);
    return LH_OK;
}

/* The meeting group pairs as adjacency lists, then triangle_pairs. */
static lh_status triangle_pairs_adj(isect *s, size_t cap, lh_index *out, size_t *count)
{
    lh_index *first = alloc_n(s->al, s->ng + 1, sizeof(lh_index));
    lh_index *adj = alloc_n(s->al, 2 * s->npairs, sizeof(lh_index));
    lh_status st = first && adj ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        memset(first, 0, (s->ng + 1) * sizeof(lh_index));
        for (size_t i = 0; i < 2 * s->npairs; i++) first[s->pairs[i] + 1]++;
        for (size_t g = 0; g < s->ng; g++) first[g + 1] += first[g];
        for (size_t i = 0; i < 2 * s->npairs; i++) adj[first[s->pairs[i]]++] = s->pairs[i ^ 1];
        memmove(first + 1, first, s->ng * sizeof(lh_index)); /* back to the starts */
        first[0] = 0;
        st = triangle_pairs(s, first, adj, cap, out, count);
    }
    lh__free(s->al, first), lh__free(s->al, adj);
    return st;
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
    if (st == LH_OK) st = ring_edges(&s);
    if (st == LH_OK && s.ft.count > 1) {
        const int one_each = s.ft.count == g->facet_count; /* every facet one triangle */
        st = group_identical(&s);
        if (st == LH_OK) st = grid_build(&s);
        if (st == LH_OK) st = scan(&s);
        if (st == LH_OK && one_each) st = triangle_pairs_adj(&s, cap, pairs, count);
        if (st == LH_OK && !one_each) st = facet_pairs(&s, count);
        const size_t w = *count < cap ? *count : cap;
        if (st == LH_OK && !one_each && w) memcpy(pairs, s.pairs, 2 * w * sizeof(lh_index));
    }
    if (st != LH_OK) *count = 0;
    isect_free(&s);
    return lh__error_done(err, st);
}
