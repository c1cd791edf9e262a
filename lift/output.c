/*
 * output.c — the triangulation as the caller sees it: finite simplices in canonical
 * form (vertices increasing but for one exchange that keeps orient_d > 0; simplices
 * in lexicographic order), neighbours, outward hull facets, an incident simplex per
 * site. Canonical form makes the output a function of the site set alone.
 */
#include "dt.h"

#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define PREFETCH(p) __builtin_prefetch(p)
#else
#define PREFETCH(p) ((void)(p))
#endif
enum { AHEAD = 16 }; /* iterations between a prefetch and the use */

/* Simplex row o := finite cell row v in canonical order (lh__canonical_ranks). */
static inline void canonical_row(const lh_index *v, int nv, lh_index *o)
{
    int rank[LH__ENGINE_MAX_DIM + 1];
    lh__canonical_ranks(v, nv, rank);
    for (int k = 0; k < nv; k++) o[rank[k]] = v[k];
}

/* Neighbour row sn of the simplex made from cell (cv, cn): the cell's neighbour
 * across vertex j is the simplex's across vertex rank[j]. */
static inline void neighbour_row(const lh_index *cv, const lh_index *cn, int nv,
                                 const lh_index *out_of_cell, lh_index *sn)
{
    int rank[LH__ENGINE_MAX_DIM + 1];
    lh__canonical_ranks(cv, nv, rank);
    for (int j = 0; j < nv; j++) sn[rank[j]] = out_of_cell[cn[j]];
}

/* mark[c]: the smallest vertex of finite cell c, -1 for the others. */
static void mark_min_vertex(lh__eng *b, lh_index *mark)
{
    const int nv = b->nv;
    for (lh_index c = 0; c < b->tds.top; c++) {
        const lh_index *v = b->tds.vert + (size_t)c * nv;
        lh_index m = v[0];
        for (int k = 1; k < nv; k++)
            if (v[k] < m) m = v[k];
        mark[c] = m; /* LH__INF and LH__DEAD are negative */
    }
}

/* Finite simplices, canonical and sorted, in t->simp: a counting sort of the cells
 * on their smallest vertex (mark[]) gives cell[s], the cell behind simplex s; the
 * canonical tuples are gathered in that order and each bucket is sorted. The
 * random accesses are prefetched AHEAD iterations early. */
static lh_status place_simplices(lh__eng *b, lh_tri *t, lh_index *cell, const lh_index *mark)
{
    const int nv = b->nv;
    const lh_index top = b->tds.top;
    size_t *start = lh__alloc(&t->alloc, (t->n + 2) * sizeof *start);
    if (!start) return LH_ERR_NOMEM;
    memset(start, 0, (t->n + 2) * sizeof *start);
    for (lh_index c = 0; c < top; c++) {
        if (c + AHEAD < top && mark[c + AHEAD] >= 0) PREFETCH(start + mark[c + AHEAD] + 2);
        if (mark[c] >= 0) start[(size_t)mark[c] + 2]++;
    }
    for (size_t k = 2; k < t->n + 2; k++) start[k] += start[k - 1];
    for (lh_index c = 0; c < top; c++) {
        if (c + AHEAD < top && mark[c + AHEAD] >= 0) PREFETCH(start + mark[c + AHEAD] + 1);
        if (mark[c] >= 0) cell[start[(size_t)mark[c] + 1]++] = c;
    }
    for (size_t s = 0; s < t->count; s++) {
        if (s + AHEAD < t->count) PREFETCH(b->tds.vert + (size_t)cell[s + AHEAD] * nv);
        const lh_index *v = b->tds.vert + (size_t)cell[s] * nv;
        lh_index *o = t->simp + s * nv;
#define ROW(m) canonical_row(v, m, o)
        LH__WITH_CONSTANT_M(nv, ROW);
#undef ROW
    }
    /* Placing advanced start[v+1] to bucket v's end: bucket k is start[k]..start[k+1]. */
    int ok = lh__sort_buckets(&t->alloc, t->simp, cell, start, t->n, nv);
    lh__free(&t->alloc, start);
    return ok ? LH_OK : LH_ERR_NOMEM;
}

/* Neighbour k of simplex s: across the facet opposite its k-th vertex, the cell's
 * vertex j of canonical rank k (lh__canonical_ranks: the simplex is not read back).
 * Cells are visited in store order; the neighbours' out_of_cell entries are
 * prefetched 2*AHEAD cells early (the free list scatters them), the simplex's
 * neighbour row AHEAD early. */
static void set_neighbours(lh__eng *b, lh_tri *t, const lh_index *out_of_cell)
{
    const int nv = b->nv;
    const lh_index top = b->tds.top;
    for (lh_index c = 0; c < top; c++) {
        if (c + 2 * AHEAD < top && out_of_cell[c + 2 * AHEAD] >= 0)
            for (int j = 0; j < nv; j++) /* free-list reuse scatters neighbours */
                PREFETCH(out_of_cell + b->tds.nbr[(size_t)(c + 2 * AHEAD) * nv + j]);
        if (c + AHEAD < top && out_of_cell[c + AHEAD] >= 0) PREFETCH(t->nbr + (size_t)out_of_cell[c + AHEAD] * nv);
        lh_index s = out_of_cell[c];
        if (s < 0) continue;
        const lh_index *cv = b->tds.vert + (size_t)c * nv, *cn = b->tds.nbr + (size_t)c * nv;
        lh_index *sn = t->nbr + (size_t)s * nv;
#define ROW(m) neighbour_row(cv, cn, m, out_of_cell, sn)
        LH__WITH_CONSTANT_M(nv, ROW);
#undef ROW
    }
}

static lh_status extract_simplices(lh__eng *b, lh_tri *t, lh_index *out_of_cell)
{
    const int nv = b->nv;
    mark_min_vertex(b, out_of_cell);
    size_t count = 0;
    for (lh_index c = 0; c < b->tds.top; c++) count += out_of_cell[c] >= 0;
    t->count = count;
    lh_index *cell = lh__alloc(&t->alloc, (count + 1) * sizeof *cell);
    t->simp = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *t->simp);
    lh_status st = cell && t->simp ? place_simplices(b, t, cell, out_of_cell) : LH_ERR_NOMEM;
    if (st == LH_OK) {
        t->nbr = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *t->nbr);
        if (!t->nbr) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        for (lh_index c = 0; c < b->tds.top; c++) out_of_cell[c] = -1;
        for (size_t s = 0; s < count; s++) {
            if (s + AHEAD < count) PREFETCH(out_of_cell + cell[s + AHEAD]);
            out_of_cell[cell[s]] = (lh_index)s;
        }
        set_neighbours(b, t, out_of_cell);
    }
    lh__free(&t->alloc, cell);
    return st;
}

lh_status lh__dt_extract(lh__eng *b, lh_tri *t)
{
    /* The stamps are no longer needed: their words become the cell -> simplex map. */
    lh_index *out_of_cell = lh__tds_finish(&b->tds);
    lh_status st = out_of_cell ? extract_simplices(b, t, out_of_cell) : LH_ERR_NOMEM;
    if (st == LH_OK) st = lh__eng_hull_facets(b, &t->hull, &t->hull_count);
    if (st == LH_OK) {
        t->vsimp = lh__alloc(&t->alloc, (t->n + 1) * sizeof *t->vsimp);
        if (!t->vsimp) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) { /* from the output itself: right even for sites that stopped
                        * being vertices (furthest-site) */
        for (size_t i = 0; i < t->n; i++) t->vsimp[i] = -1;
        const int nv = b->nv;
        for (size_t c = t->count; c-- > 0;) {
            if (c >= AHEAD)
                for (int k = 0; k < nv; k++) PREFETCH(t->vsimp + t->simp[(c - AHEAD) * nv + k]);
            for (int k = 0; k < nv; k++) t->vsimp[t->simp[c * nv + k]] = (lh_index)c;
        }
    }
    lh__free(&b->tds.alloc, out_of_cell);
    return st;
}

int lh_tri_dim(const lh_tri *t) { return t ? t->d : 0; }
int lh_tri_simplex_dim(const lh_tri *t) { return t ? t->frame.k : 0; }
size_t lh_tri_site_count(const lh_tri *t) { return t ? t->n : 0; }
size_t lh_tri_count(const lh_tri *t) { return t ? t->count : 0; }
const lh_index *lh_tri_simplices(const lh_tri *t) { return t ? t->simp : NULL; }
const lh_index *lh_tri_neighbors(const lh_tri *t) { return t ? t->nbr : NULL; }
size_t lh_tri_hull_count(const lh_tri *t) { return t ? t->hull_count : 0; }
const lh_index *lh_tri_hull_facets(const lh_tri *t) { return t ? t->hull : NULL; }
const lh_index *lh_tri_vertex_simplex(const lh_tri *t) { return t ? t->vsimp : NULL; }
const lh_index *lh_tri_duplicate_of(const lh_tri *t) { return t ? t->dup : NULL; }
size_t lh_tri_duplicate_count(const lh_tri *t) { return t ? t->ndup : 0; }

void lh_tri_pred_counters(const lh_tri *t, lh_pred_counters *out)
{
    lh_pred_counters_get(t ? t->pred : NULL, out);
}
