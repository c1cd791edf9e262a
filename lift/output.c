/*
 * output.c — the triangulation as the caller sees it: finite simplices in canonical
 * form (vertices increasing but for one exchange that keeps orient_d > 0; simplices
 * in lexicographic order), neighbours, outward hull facets, an incident simplex per
 * site. Canonical form makes the output a function of the site set alone.
 */
#include "dt.h"

#include <string.h>

/* Finite simplices (canonical, sorted) with their neighbours. */
static lh_status extract_simplices(lh__eng *b, lh_tri *t, int32_t *out_of_cell)
{
    const int nv = b->nv;
    size_t count = 0;
    for (int32_t c = 0; c < b->tds.top; c++)
        if (!lh__tds_dead(&b->tds, c) && lh__eng_finite(b, c)) count++;
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
            if (lh__tds_dead(&b->tds, c) || !lh__eng_finite(b, c)) continue;
            int f[LH__ENGINE_MAX_DIM + 1];
            memcpy(raw + s * nv, b->tds.vert + (size_t)c * nv, (size_t)nv * sizeof(int32_t));
            lh__canonical(raw + s * nv, f, nv);
            for (int k = 0; k < nv; k++) from[s * nv + k] = (uint8_t)f[k];
            cell_of[s++] = c;
        }
        t->simp = lh__alloc(&t->alloc, (count * nv + 1) * sizeof *t->simp);
        if (!t->simp || !lh__sort_tuples(&t->alloc, raw, nv, count, t->n, t->simp, order)) st = LH_ERR_NOMEM;
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

lh_status lh__dt_extract(lh__eng *b, lh_tri *t)
{
    int32_t *out_of_cell = lh__alloc(&t->alloc, ((size_t)b->tds.top + 1) * sizeof *out_of_cell);
    if (!out_of_cell) return LH_ERR_NOMEM;
    for (int32_t c = 0; c < b->tds.top; c++) out_of_cell[c] = -1;
    lh_status st = extract_simplices(b, t, out_of_cell);
    if (st == LH_OK) st = lh__eng_hull_facets(b, &t->hull, &t->hull_count);
    if (st == LH_OK) {
        t->vsimp = lh__alloc(&t->alloc, (t->n + 1) * sizeof *t->vsimp);
        if (!t->vsimp) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) { /* from the output itself: right even for sites that stopped
                        * being vertices (furthest-site) */
        for (size_t i = 0; i < t->n; i++) t->vsimp[i] = -1;
        const int nv = t->d + 1;
        for (size_t c = t->count; c-- > 0;)
            for (int k = 0; k < nv; k++) t->vsimp[t->simp[c * nv + k]] = (int32_t)c;
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
