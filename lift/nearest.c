/*
 * nearest.c — lh_tri_nearest: the nearest site by greedy descent along Delaunay
 * edges. If site v is not nearest to q, the segment from v to q leaves v's Voronoi
 * region through a facet shared with a Delaunay neighbour w, and |q - w| < |q - v|
 * (e.g. Bose & Morin, "Online routing in triangulations", SIAM J. Comput. 33(4),
 * 2004, for 2D; the argument holds in any dimension), so descent ends at a nearest
 * site. Sites exactly as near form the vertex set of one Delaunay cell, whose
 * triangulation connects them: a walk over the ties finds the smallest index.
 * Every comparison is exact (lh_distance_compare).
 */
#include "dt.h"
#include "lh_alloc.h"

#include <string.h>

/* An open-addressing set of non-negative indices (simplices or sites), growing. */
typedef struct idset {
    const lh_allocator *a;
    lh_index *slot; /* -1 empty */
    size_t cap, size;
} idset;

static int set_grow(idset *s)
{
    size_t cap = s->cap ? 2 * s->cap : 64;
    lh_index *slot = lh__alloc(s->a, cap * sizeof *slot);
    if (!slot) return 0;
    memset(slot, 0xff, cap * sizeof *slot);
    for (size_t i = 0; i < s->cap; i++) {
        if (s->slot[i] < 0) continue;
        size_t h = ((lh__uindex)s->slot[i] * 2654435761u) & (cap - 1);
        while (slot[h] >= 0) h = (h + 1) & (cap - 1);
        slot[h] = s->slot[i];
    }
    lh__free(s->a, s->slot);
    s->slot = slot;
    s->cap = cap;
    return 1;
}

/* 1 if x was added, 0 if present, -1 out of memory. */
static int set_add(idset *s, lh_index x)
{
    if (2 * (s->size + 1) > s->cap && !set_grow(s)) return -1;
    size_t h = ((lh__uindex)x * 2654435761u) & (s->cap - 1);
    while (s->slot[h] >= 0) {
        if (s->slot[h] == x) return 0;
        h = (h + 1) & (s->cap - 1);
    }
    s->slot[h] = x;
    s->size++;
    return 1;
}

static void set_clear(idset *s)
{
    if (s->slot) memset(s->slot, 0xff, s->cap * sizeof *s->slot);
    s->size = 0;
}

/* A stack of indices, growing. */
typedef struct idstack {
    const lh_allocator *a;
    lh_index *v;
    size_t size, cap;
} idstack;

static int push(idstack *st, lh_index x)
{
    if (st->size == st->cap) {
        size_t cap = st->cap ? 2 * st->cap : 64;
        lh_index *v = lh__alloc(st->a, cap * sizeof *v);
        if (!v) return 0;
        if (st->size) memcpy(v, st->v, st->size * sizeof *v);
        lh__free(st->a, st->v);
        st->v = v;
        st->cap = cap;
    }
    st->v[st->size++] = x;
    return 1;
}

typedef struct walk {
    lh_tri *t;
    const double *q;
    idset seen;   /* simplices of the star being enumerated */
    idstack todo; /* simplices to visit */
} walk;

/* The Delaunay neighbours of vertex v: every vertex of the simplices around v (found
 * by crossing the facets that contain v). Sets *best to the first neighbour with
 * sign(|q - w| - |q - v|) == want (want -1: strictly nearer; 0: exactly as near and
 * not yet in `ties`), or leaves it at -1. Returns 0 when out of memory. */
static int scan_star(walk *w, lh_index v, int want, idset *ties, lh_index *best)
{
    lh_tri *t = w->t;
    const int nv = t->frame.k + 1, d = t->d;
    const double *pv = t->xyz + (size_t)v * d;
    set_clear(&w->seen);
    w->todo.size = 0;
    *best = -1;
    if (set_add(&w->seen, t->vsimp[v]) < 0 || !push(&w->todo, t->vsimp[v])) return 0;
    while (w->todo.size && *best < 0) {
        lh_index s = w->todo.v[--w->todo.size];
        const lh_index *sv = t->simp + (size_t)s * nv, *sn = t->nbr + (size_t)s * nv;
        for (int j = 0; j < nv && *best < 0; j++) {
            if (sv[j] == v) continue;
            int c = lh_distance_compare(t->pred, d, w->q, t->xyz + (size_t)sv[j] * d, pv);
            if (c == want && (want < 0 || set_add(ties, sv[j]) == 1)) *best = sv[j];
            if (sn[j] < 0) continue;
            int added = set_add(&w->seen, sn[j]);
            if (added < 0 || (added && !push(&w->todo, sn[j]))) return 0;
        }
    }
    return 1;
}

/* Descent to a nearest site, then the smallest index among the exact ties. */
static lh_status descend(walk *w, lh_index v, lh_index *site)
{
    idset ties = {w->seen.a, NULL, 0, 0};
    idstack open = {w->seen.a, NULL, 0, 0};
    lh_status st = LH_ERR_NOMEM;
    for (lh_index next = v;; v = next) {
        if (!scan_star(w, v, -1, &ties, &next)) goto done;
        if (next < 0) break;
    }
    *site = v;
    if (set_add(&ties, v) < 0 || !push(&open, v)) goto done;
    while (open.size) {
        lh_index u = open.v[--open.size], tie;
        do {
            if (!scan_star(w, u, 0, &ties, &tie)) goto done;
            if (tie >= 0 && !push(&open, tie)) goto done;
            if (tie >= 0 && tie < *site) *site = tie;
        } while (tie >= 0);
    }
    st = LH_OK;
done:
    lh__free(w->seen.a, ties.slot);
    lh__free(w->seen.a, open.v);
    return st;
}

lh_status lh_tri_nearest(lh_tri *t, const double *q, lh_index hint, lh_index *site)
{
    if (!t || !q || !site || t->furthest) return LH_ERR_INVALID_ARGUMENT;
    lh_location loc;
    lh_status st = lh_tri_locate(t, q, hint, &loc);
    if (st != LH_OK) return st;
    const int nv = t->frame.k + 1;
    lh_index v = loc.simplex >= 0    ? t->simp[(size_t)loc.simplex * nv]
                : loc.hull_facet >= 0 ? t->hull[(size_t)loc.hull_facet * (nv - 1)]
                                      : t->simp[0]; /* any start: the descent finds it */
    walk w = {t, q, {&t->alloc, NULL, 0, 0}, {&t->alloc, NULL, 0, 0}};
    st = descend(&w, v, site);
    lh__free(&t->alloc, w.seen.slot);
    lh__free(&t->alloc, w.todo.v);
    return st;
}
