/*
 * output.c — the triangulation as the caller sees it: finite simplices in canonical
 * form (vertices increasing but for one exchange that keeps orient_d > 0; simplices
 * in lexicographic order), neighbours, outward hull facets, an incident simplex per
 * site. Canonical form makes the output a function of the site set alone.
 */
#include "dt.h"
#include "lh_sort.h"

#include <string.h>

/* Sorts v[0..m-1] increasing; returns the permutation's parity (1 = odd) and, in
 * from[p], the original position of the value now at p. */
static int sort_with_parity(int32_t *v, int *from, int m)
{
    int parity = 0;
    for (int i = 0; i < m; i++) from[i] = i;
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            int32_t x = v[j];
            v[j] = v[j - 1];
            v[j - 1] = x;
            int f = from[j];
            from[j] = from[j - 1];
            from[j - 1] = f;
            parity ^= 1;
        }
    return parity;
}

/* Canonical order of an oriented tuple: increasing, then the last two exchanged if
 * the sort was an odd permutation (so the orientation is kept). */
static void canonical(int32_t *v, int *from, int m)
{
    if (sort_with_parity(v, from, m)) {
        int32_t x = v[m - 1];
        v[m - 1] = v[m - 2];
        v[m - 2] = x;
        int f = from[m - 1];
        from[m - 1] = from[m - 2];
        from[m - 2] = f;
    }
}

static int tuple_less(const int32_t *x, const int32_t *y, int m)
{
    for (int k = 0; k < m; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

typedef struct tuple_ctx {
    const int32_t *v;
    int m;
} tuple_ctx;

static int tuple_cmp(const void *vctx, int32_t a, int32_t b)
{
    const tuple_ctx *c = vctx;
    const int32_t *x = c->v + (size_t)a * c->m, *y = c->v + (size_t)b * c->m;
    for (int k = 0; k < c->m; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

static int is_finite(const lh__dt *b, int32_t c)
{
    const int32_t *v = b->tds.vert + (size_t)c * b->nv;
    for (int k = 0; k < b->nv; k++)
        if (v[k] == LH__INF) return 0;
    return 1;
}

/* Sorts count canonical tuples (m int32 each) lexicographically into out, with
 * order[i] the input position of out's tuple i: a counting sort on the first entry
 * (a site index below n) gathers the tuples bucket by bucket; each bucket, now
 * contiguous, is sorted on the rest — insertion sort for the usual small buckets,
 * merge sort for large ones (a vertex of huge degree). Returns 0 on no memory. */
static int sort_tuples(const lh_allocator *a, const int32_t *v, int m, size_t count,
                       size_t n, int32_t *out, int32_t *order)
{
    size_t *start = lh__alloc(a, (n + 2) * sizeof *start);
    int32_t *tmp = lh__alloc(a, (count + 1) * sizeof *tmp);
    if (!start || !tmp) {
        lh__free(a, start);
        lh__free(a, tmp);
        return 0;
    }
    memset(start, 0, (n + 2) * sizeof *start);
    for (size_t i = 0; i < count; i++) start[(size_t)v[i * m] + 2]++;
    for (size_t k = 2; k < n + 2; k++) start[k] += start[k - 1];
    for (size_t i = 0; i < count; i++) order[start[(size_t)v[i * m] + 1]++] = (int32_t)i;
    for (size_t i = 0; i < count; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
    tuple_ctx c = {v, m};
    for (size_t k = 0; k < n; k++) {
        size_t lo = start[k], hi = start[k + 1];
        if (hi - lo > 32) { /* rare: sort indices, then regather this bucket */
            lh__sort_idx(order + lo, tmp, hi - lo, tuple_cmp, &c);
            for (size_t i = lo; i < hi; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
            continue;
        }
        for (size_t i = lo + 1; i < hi; i++) {
            int32_t key[LH_DELAUNAY_MAX_DIM + 1], o = order[i];
            memcpy(key, out + i * m, (size_t)m * sizeof *key);
            size_t j = i;
            for (; j > lo && tuple_less(key, out + (j - 1) * m, m); j--) {
                memcpy(out + j * m, out + (j - 1) * m, (size_t)m * sizeof *out);
                order[j] = order[j - 1];
            }
            memcpy(out + j * m, key, (size_t)m * sizeof *key);
            order[j] = o;
        }
    }
    lh__free(a, start);
    lh__free(a, tmp);
    return 1;
}

/* Finite simplices (canonical, sorted) with their neighbours. */
static lh_status extract_simplices(lh__dt *b, int32_t *out_of_cell)
{
    lh_tri *t = b->t;
    const int nv = b->nv;
    size_t count = 0;
    for (int32_t c = 0; c < b->tds.top; c++)
        if (!lh__tds_dead(&b->tds, c) && is_finite(b, c)) count++;
    t->count = count;
    /* raw: canonical tuples in cell order; from: where each came from in its cell. */
    int32_t *raw = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *raw);
    uint8_t *from = lh__alloc(&t->alloc, count * nv + 1);
    int32_t *cell_of = lh__alloc(&t->alloc, (count + 1) * sizeof *cell_of);
    int32_t *order = lh__alloc(&t->alloc, (count + 1) * sizeof *order);
    lh_status st = raw && from && cell_of && order ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        size_t s = 0;
        for (int32_t c = 0; c < b->tds.top; c++) {
            if (lh__tds_dead(&b->tds, c) || !is_finite(b, c)) continue;
            int f[LH_DELAUNAY_MAX_DIM + 1];
            memcpy(raw + s * nv, b->tds.vert + (size_t)c * nv, (size_t)nv * sizeof(int32_t));
            canonical(raw + s * nv, f, nv);
            for (int k = 0; k < nv; k++) from[s * nv + k] = (uint8_t)f[k];
            cell_of[s++] = c;
        }
        t->simp = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *t->simp);
        if (!t->simp || !sort_tuples(&t->alloc, raw, nv, count, t->n, t->simp, order)) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        lh__free(&t->alloc, raw);
        raw = NULL;
        t->nbr = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *t->nbr);
        if (!t->nbr) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        for (size_t s = 0; s < count; s++) out_of_cell[cell_of[order[s]]] = (int32_t)s;
        for (size_t s = 0; s < count; s++) {
            int32_t o = order[s], c = cell_of[o];
            for (int k = 0; k < nv; k++) {
                int32_t n = b->tds.nbr[(size_t)c * nv + from[(size_t)o * nv + k]];
                t->nbr[s * nv + k] = out_of_cell[n];
            }
        }
    }
    lh__free(&t->alloc, raw);
    lh__free(&t->alloc, from);
    lh__free(&t->alloc, cell_of);
    lh__free(&t->alloc, order);
    return st;
}

/* Hull facets from the infinite cells, oriented outward, canonical and sorted. */
static lh_status extract_hull(lh__dt *b)
{
    lh_tri *t = b->t;
    const int nv = b->nv, d = b->d;
    size_t h = (size_t)b->tds.live - t->count;
    t->hull_count = h;
    t->hull = lh__alloc(&t->alloc, (h * d + 1) * sizeof *t->hull);
    if (!t->hull) return LH_ERR_NOMEM;
    size_t f = 0;
    for (int32_t c = 0; c < b->tds.top; c++) {
        if (lh__tds_dead(&b->tds, c) || is_finite(b, c)) continue;
        const int32_t *v = b->tds.vert + (size_t)c * nv;
        int32_t *o = t->hull + f * d, m = 0, inf = 0;
        for (int k = 0; k < nv; k++) {
            if (v[k] == LH__INF)
                inf = k;
            else
                o[m++] = v[k];
        }
        /* Moving the outside point from position inf to the end takes d - inf
         * exchanges; compensate an odd number with one more. */
        if ((d - inf) & 1) {
            int32_t x = o[0];
            o[0] = o[1];
            o[1] = x;
        }
        int from[LH_DELAUNAY_MAX_DIM];
        canonical(o, from, d);
        f++;
    }
    int32_t *order = lh__alloc(&t->alloc, (h + 1) * sizeof *order);
    int32_t *copy = lh__alloc(&t->alloc, (h * d + 1) * sizeof *copy);
    lh_status st = LH_ERR_NOMEM;
    if (order && copy) {
        memcpy(copy, t->hull, h * d * sizeof *copy);
        if (sort_tuples(&t->alloc, copy, d, h, t->n, t->hull, order)) st = LH_OK;
    }
    lh__free(&t->alloc, order);
    lh__free(&t->alloc, copy);
    return st;
}

lh_status lh__dt_extract(lh__dt *b)
{
    lh_tri *t = b->t;
    int32_t *out_of_cell = lh__alloc(&t->alloc, ((size_t)b->tds.top + 1) * sizeof *out_of_cell);
    if (!out_of_cell) return LH_ERR_NOMEM;
    for (int32_t c = 0; c < b->tds.top; c++) out_of_cell[c] = -1;
    lh_status st = extract_simplices(b, out_of_cell);
    if (st == LH_OK) st = extract_hull(b);
    if (st == LH_OK) {
        t->vsimp = lh__alloc(&t->alloc, (t->n + 1) * sizeof *t->vsimp);
        if (!t->vsimp) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        for (size_t i = 0; i < t->n; i++) {
            int32_t c = t->dup[i] == (int32_t)i ? b->v2c[i] : -1;
            if (c >= 0 && !is_finite(b, c)) { /* step to the finite cell across its facet */
                const int32_t *v = b->tds.vert + (size_t)c * b->nv;
                for (int k = 0; k < b->nv; k++)
                    if (v[k] == LH__INF) c = b->tds.nbr[(size_t)c * b->nv + k];
            }
            t->vsimp[i] = c >= 0 ? out_of_cell[c] : -1;
        }
    }
    lh__free(&t->alloc, out_of_cell);
    return st;
}

int lh_tri_dim(const lh_tri *t) { return t ? t->d : 0; }
size_t lh_tri_site_count(const lh_tri *t) { return t ? t->n : 0; }
size_t lh_tri_count(const lh_tri *t) { return t ? t->count : 0; }
const int32_t *lh_tri_simplices(const lh_tri *t) { return t ? t->simp : NULL; }
const int32_t *lh_tri_neighbors(const lh_tri *t) { return t ? t->nbr : NULL; }
size_t lh_tri_hull_count(const lh_tri *t) { return t ? t->hull_count : 0; }
const int32_t *lh_tri_hull_facets(const lh_tri *t) { return t ? t->hull : NULL; }
const int32_t *lh_tri_vertex_simplex(const lh_tri *t) { return t ? t->vsimp : NULL; }
const int32_t *lh_tri_duplicate_of(const lh_tri *t) { return t ? t->dup : NULL; }
size_t lh_tri_duplicate_count(const lh_tri *t) { return t ? t->ndup : 0; }
