/*
 * hull.c — lh_convex_hull: the engine as a placing triangulation (no finite cell
 * ever conflicts, engine.h); its infinite cells are the convex hull. A site inside
 * the current hull or on its boundary is not inserted, but a site on the boundary of
 * the final hull can still be a vertex when it was inserted before the sites that put
 * it there; its facets are then coplanar with their neighbours. So the hull's corners
 * are found exactly (faces.c), and when some facets were coplanar the hull is built
 * again from the corners alone, in lexicographic order of their coordinates: every
 * vertex a corner, and each flat face's triangulation a function of the point set
 * (the engine's output is a function of its input sequence and seed, the default
 * one here), whatever the input order or opt->seed.
 */
#include "engine.h"

#include "lh_sort.h"

#include <string.h>

struct lh_hull {
    lh_allocator alloc;
    int d;
    size_t n;
    size_t count;
    lh_index *facets; /* d per facet, outward, canonical */
    size_t nvert;
    lh_index *vertices; /* increasing site indices */
    lh_index *dup;     /* n */
    size_t ndup;
};

void lh_hull_free(lh_hull *h)
{
    if (!h) return;
    lh_allocator a = h->alloc;
    lh__free(&a, h->facets);
    lh__free(&a, h->vertices);
    lh__free(&a, h->dup);
    lh__free(&a, h);
}

const lh_allocator *lh__hull_allocator(const lh_hull *h) { return &h->alloc; }

/* The corners (ext[i] set), increasing. */
static lh_status collect_vertices(lh_hull *h, const uint8_t *ext)
{
    h->nvert = 0;
    for (size_t i = 0; i < h->n; i++) h->nvert += ext[i];
    h->vertices = lh__alloc(&h->alloc, (h->nvert + 1) * sizeof *h->vertices);
    if (!h->vertices) return LH_ERR_NOMEM;
    for (size_t i = 0, k = 0; i < h->n; i++)
        if (ext[i]) h->vertices[k++] = (lh_index)i;
    return LH_OK;
}

/* h->facets: the hull of the corners h->vertices, inserted in lexicographic order of
 * their coordinates with the default seed, in the caller's site numbering. */
static lh_status corner_facets(lh_hull *h, const double *xyz)
{
    const int d = h->d;
    const size_t m = h->nvert;
    lh_index *order = lh__alloc(&h->alloc, (m + 1) * sizeof *order);
    lh_index *tmp = lh__alloc(&h->alloc, (m + 1) * sizeof *tmp);
    double *x = lh__alloc(&h->alloc, (m * (size_t)d + 1) * sizeof *x);
    lh_index *raw = NULL, *sorted = NULL, *pos = NULL;
    size_t count = 0;
    lh_status st = order && tmp && x ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        memcpy(order, h->vertices, m * sizeof *order);
        lh__lex lex = {xyz, d};
        lh__sort_idx(order, tmp, m, lh__lex_cmp, &lex);
        for (size_t i = 0; i < m; i++) memcpy(x + i * d, xyz + (size_t)order[i] * d, (size_t)d * sizeof *x);
        lh__eng e;
        st = lh__eng_init(&e, &h->alloc, d, m, x, tmp, NULL); /* tmp: the (no) duplicates */
        int affdim = -1;
        if (st == LH_OK) st = lh__eng_build(&e, lh__hull_cells_hint(m), &affdim);
        if (st == LH_OK) st = lh__eng_hull_facets(&e, 0, &raw, &count);
        lh__eng_release(&e);
    }
    if (st == LH_OK) {
        sorted = lh__alloc(&h->alloc, (count * (size_t)d + 1) * sizeof *sorted);
        pos = lh__alloc(&h->alloc, (count + 1) * sizeof *pos);
        if (!sorted || !pos) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        for (size_t f = 0; f < count; f++) {
            for (int k = 0; k < d; k++) raw[f * d + k] = order[raw[f * d + k]];
            lh__canonical(raw + f * d, d);
        }
        if (!lh__sort_tuples(&h->alloc, raw, d, count, h->n, sorted, pos)) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        lh__free(&h->alloc, h->facets);
        h->facets = sorted;
        h->count = count;
        sorted = NULL;
    }
    lh__free(&h->alloc, order);
    lh__free(&h->alloc, tmp);
    lh__free(&h->alloc, x);
    lh__free(&h->alloc, raw);
    lh__free(&h->alloc, sorted);
    lh__free(&h->alloc, pos);
    return st;
}

lh_status lh_convex_hull(int d, size_t n, const double *xyz, const lh_options *opt,
                         lh_hull **out)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    *out = NULL;
    lh_status st = lh__eng_check_args(d, 2, LH__ENGINE_MAX_DIM, n, xyz, opt);
    if (st != LH_OK) return st;
    lh_allocator a;
    lh__allocator_init(&a, opt ? opt->alloc : NULL);
    lh_hull *h = lh__alloc(&a, sizeof *h);
    if (!h) return LH_ERR_NOMEM;
    memset(h, 0, sizeof *h);
    h->alloc = a;
    h->d = d;
    h->n = n;
    h->dup = lh__alloc(&a, (n + 1) * sizeof *h->dup);
    uint8_t *ext = lh__alloc(&a, n + 1); /* the corners */
    if (!h->dup || !ext) {
        lh__free(&a, ext);
        lh_hull_free(h);
        return LH_ERR_NOMEM;
    }
    lh__eng e;
    st = lh__eng_init(&e, &a, d, n, xyz, h->dup, opt);
    int affdim = -1, flat = 0;
    if (st == LH_OK) st = lh__eng_build(&e, lh__hull_cells_hint(n), &affdim);
    if (st == LH_OK) st = lh__eng_hull_corners(&e, ext, &flat);
    if (st == LH_OK && !flat) st = lh__eng_hull_facets(&e, 0, &h->facets, &h->count);
    h->ndup = e.ndup;
    lh__eng_release(&e);
    if (st == LH_OK) st = collect_vertices(h, ext);
    if (st == LH_OK && flat) st = corner_facets(h, xyz);
    lh__free(&a, ext);
    if (st != LH_OK) {
        lh_hull_free(h);
        return st;
    }
    *out = h;
    return LH_OK;
}

int lh_hull_dim(const lh_hull *h) { return h ? h->d : 0; }
size_t lh_hull_facet_count(const lh_hull *h) { return h ? h->count : 0; }
const lh_index *lh_hull_facets(const lh_hull *h) { return h ? h->facets : NULL; }
size_t lh_hull_vertex_count(const lh_hull *h) { return h ? h->nvert : 0; }
const lh_index *lh_hull_vertices(const lh_hull *h) { return h ? h->vertices : NULL; }
const lh_index *lh_hull_duplicate_of(const lh_hull *h) { return h ? h->dup : NULL; }
