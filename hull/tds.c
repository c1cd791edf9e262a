/*
 * tds.c — the cell store (tds.h): capacity, the free list, the scratch of one
 * insertion. The insertion itself is hull/insert_impl.h.
 */
#include "tds.h"

#include "lh_alloc.h"

#include <string.h>


static int ridge_room(lh__tds *t);

static void *grow(const lh_allocator *a, void *old, size_t old_bytes, size_t new_bytes)
{
    void *p = lh__alloc(a, new_bytes);
    if (!p) return NULL;
    if (old_bytes) memcpy(p, old, old_bytes);
    lh__free(a, old);
    return p;
}

static lh_status set_capacity(lh__tds *t, lh_index cap)
{
    size_t nv = (size_t)t->nv, old = (size_t)t->cap;
    lh_index *v = grow(&t->alloc, t->vert, old * nv * sizeof *v, (size_t)cap * nv * sizeof *v);
    if (!v) return LH_ERR_NOMEM;
    t->vert = v;
    lh_index *n = grow(&t->alloc, t->nbr, old * nv * sizeof *n, (size_t)cap * nv * sizeof *n);
    if (!n) return LH_ERR_NOMEM;
    t->nbr = n;
    uint32_t *s = grow(&t->alloc, t->stamp, old * sizeof *s, (size_t)cap * sizeof *s);
    if (!s) return LH_ERR_NOMEM;
    memset(s + old, 0, ((size_t)cap - old) * sizeof *s);
    t->stamp = s;
    t->cap = cap;
    return LH_OK;
}

lh_status lh__tds_init(lh__tds *t, const lh_allocator *alloc, int nv, lh_index cap_hint)
{
    memset(t, 0, sizeof *t);
    if (!lh__allocator_init(&t->alloc, alloc)) return LH_ERR_INVALID_ARGUMENT;
    t->nv = nv;
    t->vbits = LH__TDS_VBITS_MAX;
    t->free_head = -1;
    return set_capacity(t, cap_hint > 16 ? cap_hint : 16);
}

void lh__tds_free_scratch(lh__tds *t)
{
    lh__free(&t->alloc, t->cells);
    lh__free(&t->alloc, t->bound);
    lh__free(&t->alloc, t->fresh);
    lh__free(&t->alloc, t->ridge);
    lh__free(&t->alloc, t->sorted);
    lh__free(&t->alloc, t->spos);
    lh__free(&t->alloc, t->vloc);
    lh__free(&t->alloc, t->edge);
    t->cells = t->bound = t->fresh = t->sorted = NULL;
    t->ridge = NULL;
    t->spos = NULL;
    t->vloc = NULL;
    t->edge = NULL;
    t->cells_cap = t->bound_cap = t->fresh_cap = t->ridge_cap = t->sorted_cap = 0;
}

void lh__tds_release(lh__tds *t)
{
    lh__tds_free_scratch(t);
    lh__free(&t->alloc, t->vert);
    lh__free(&t->alloc, t->nbr);
    lh__free(&t->alloc, t->stamp);
    memset(t, 0, sizeof *t);
}

/* Capacity for `extra` cells above top, growing by half (less overshoot than
 * doubling) or more. */
static lh_status grow_above_top(lh__tds *t, size_t extra)
{
    size_t want = (size_t)t->cap + (size_t)t->cap / 2 + 1024;
    if (want < (size_t)t->top + extra) want = (size_t)t->top + extra;
    size_t most = SIZE_MAX / ((size_t)t->nv * sizeof *t->vert); /* bytes must not overflow */
    if (most > LH_INDEX_MAX) most = LH_INDEX_MAX;
    if (want > most) want = most;
    if (want < (size_t)t->top + extra) return LH_ERR_TOO_LARGE;
    return set_capacity(t, (lh_index)want);
}

lh_status lh__tds_reserve(lh__tds *t, size_t extra)
{
    size_t have = (size_t)(t->cap - t->top), freed = (size_t)(t->top - t->live);
    if (have + freed >= extra) return LH_OK;
    return t->frozen ? LH_ERR_NOMEM : grow_above_top(t, extra);
}

lh_index *lh__tds_finish(lh__tds *t)
{
    uint32_t *s = t->stamp;
    t->stamp = NULL;
    lh__tds_free_scratch(t);
#if LH_INDEX_BITS == 64
    lh__free(&t->alloc, s); /* a stamp is narrower than an index */
    return lh__alloc(&t->alloc, ((size_t)t->cap + 1) * sizeof(lh_index));
#else
    return (lh_index *)s;
#endif
}

int lh__tds_mirror(const lh__tds *t, lh_index c, lh_index other)
{
    const lh_index *n = t->nbr + (size_t)c * t->nv;
    for (int k = 0; k < t->nv; k++)
        if (n[k] == other) return k;
    return -1;
}

static int index_of(const lh_index *v, int nv, lh_index x)
{
    for (int k = 0; k < nv; k++)
        if (v[k] == x) return k;
    return -1;
}

void lh__tds_link_all(lh__tds *t, const lh_index *list, int count)
{
    int nv = t->nv;
    for (int a = 0; a < count; a++) {
        const lh_index *va = t->vert + (size_t)list[a] * nv;
        for (int b = 0; b < count; b++) {
            if (a == b) continue;
            const lh_index *vb = t->vert + (size_t)list[b] * nv;
            int missing = -1, shared = 0;
            for (int k = 0; k < nv; k++) {
                if (index_of(vb, nv, va[k]) >= 0)
                    shared++;
                else
                    missing = k;
            }
            if (shared == nv - 1) t->nbr[(size_t)list[a] * nv + missing] = list[b];
        }
    }
}

int lh__tds_push_slow(lh__tds *t, lh_index **arr, size_t *cap, size_t *len, lh_index x)
{
    if (t->frozen) return 0;
    size_t nc = *cap ? *cap * 2 : 64;
    lh_index *p = grow(&t->alloc, *arr, *cap * sizeof *p, nc * sizeof *p);
    if (!p) return 0;
    *arr = p;
    *cap = nc;
    (*arr)[(*len)++] = x;
    return 1;
}

void lh__tds_reset_rounds(lh__tds *t)
{
    memset(t->stamp, 0, (size_t)t->cap * sizeof *t->stamp);
    if (t->ridge) memset(t->ridge, 0, t->ridge_cap * sizeof *t->ridge);
    t->round = 0;
}

void lh__tds_next_round(lh__tds *t)
{
    if (t->round >= LH__TDS_MAX_ROUND) lh__tds_reset_rounds(t);
    t->round++;
}

lh_status lh__tds_reserve_top(lh__tds *t, size_t extra)
{
    return (size_t)(t->cap - t->top) >= extra ? LH_OK : grow_above_top(t, extra);
}

lh_status lh__tds_scratch(lh__tds *t, size_t facets)
{
    lh_index **arr[3] = {&t->cells, &t->bound, &t->fresh};
    size_t *cap[3] = {&t->cells_cap, &t->bound_cap, &t->fresh_cap};
    for (int i = 0; i < 3; i++) {
        if (*cap[i] >= 4 * facets) continue;
        lh_index *p = grow(&t->alloc, *arr[i], 0, 4 * facets * sizeof *p);
        if (!p) return LH_ERR_NOMEM;
        *arr[i] = p;
        *cap[i] = 4 * facets;
    }
    t->nbound = facets;
    int ok = ridge_room(t);
    t->nbound = 0;
    return ok ? LH_OK : LH_ERR_NOMEM;
}

/* The numbering of a cavity's boundary vertices (cone_local in 3D,
 * insert_link_twins.h; number_ridges from 3D on, insert_link_numbered.h) and the
 * 3D edge table, once the vertex bound is known: allocated zero, kept until the
 * store is finished. */
static int number_room(lh__tds *t)
{
    if (t->nv < 4 || !t->vlimit || t->vloc) return 1;
    if (t->frozen) return 0;
    uint8_t *loc = lh__alloc(&t->alloc, t->vlimit);
    uint32_t *edge = t->nv == 4 ? lh__alloc(&t->alloc, LH__EDGE_SLOTS * sizeof *edge) : NULL;
    if (!loc || (t->nv == 4 && !edge)) {
        lh__free(&t->alloc, loc);
        lh__free(&t->alloc, edge);
        return 0;
    }
    memset(loc, 0, t->vlimit);
    if (edge) memset(edge, 0, LH__EDGE_SLOTS * sizeof *edge);
    t->vloc = loc;
    t->edge = edge;
    return 1;
}

/* Room for the ridges of nbound new cells (lh__ridge_slots), their sorted vertex
 * lists, and the boundary numbering (number_room). */
static int ridge_room(lh__tds *t)
{
    const size_t m = (size_t)t->nv - 1, nb = t->nbound;
    if (!number_room(t)) return 0;
    if (t->frozen && (t->sorted_cap < nb || t->ridge_cap < lh__ridge_slots(nb * m))) return 0;
    if (t->sorted_cap < nb) {
        size_t cap = 2 * nb;
        lh_index *s = grow(&t->alloc, t->sorted, 0, cap * LH__SORTED_ROOM(m) * sizeof *s);
        if (!s) return 0;
        t->sorted = s;
        int8_t *p = grow(&t->alloc, t->spos, 0, cap * m * sizeof *p);
        if (!p) return 0;
        t->spos = p;
        t->sorted_cap = cap;
    }
    size_t want = lh__ridge_slots(nb * m);
    if (t->ridge_cap >= want) return 1;
    lh__ridge *r = grow(&t->alloc, t->ridge, 0, want * sizeof *r);
    if (!r) return 0;
    memset(r, 0, want * sizeof *r);
    t->ridge = r;
    t->ridge_cap = want;
    return 1;
}

lh_status lh__tds_room(lh__tds *t)
{
    if (t->nbound >= (size_t)LH__MAX_NEW_CELLS) return LH_ERR_TOO_LARGE;
    if (t->fresh_cap < t->nbound) {
        if (t->frozen) return LH_ERR_NOMEM;
        lh_index *p = grow(&t->alloc, t->fresh, 0, t->nbound * 2 * sizeof *p);
        if (!p) return LH_ERR_NOMEM;
        t->fresh = p;
        t->fresh_cap = t->nbound * 2;
    }
    if (!ridge_room(t)) return LH_ERR_NOMEM;
    return lh__tds_reserve(t, t->nbound);
}
