/*
 * hull.c — lh_convex_hull: the engine as a placing triangulation (no finite cell
 * ever conflicts, engine.h); its infinite cells are the convex hull. A site inside
 * the current hull or on its boundary is not inserted. A site on the boundary of the
 * final hull can still be a vertex when it was inserted before the sites that put it
 * there; its facets are then coplanar with their neighbours, never flat.
 */
#include "engine.h"

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

/* The sites that appear in a facet, increasing. */
static lh_status collect_vertices(lh_hull *h)
{
    uint8_t *used = lh__alloc(&h->alloc, h->n + 1);
    if (!used) return LH_ERR_NOMEM;
    memset(used, 0, h->n + 1);
    for (size_t i = 0; i < h->count * (size_t)h->d; i++) used[h->facets[i]] = 1;
    h->nvert = 0;
    for (size_t i = 0; i < h->n; i++) h->nvert += used[i];
    h->vertices = lh__alloc(&h->alloc, (h->nvert + 1) * sizeof *h->vertices);
    if (h->vertices) {
        size_t k = 0;
        for (size_t i = 0; i < h->n; i++)
            if (used[i]) h->vertices[k++] = (lh_index)i;
    }
    lh__free(&h->alloc, used);
    return h->vertices ? LH_OK : LH_ERR_NOMEM;
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
    if (!h->dup) {
        lh_hull_free(h);
        return LH_ERR_NOMEM;
    }
    lh__eng e;
    st = lh__eng_init(&e, &a, d, n, xyz, h->dup, opt);
    int affdim = -1;
    if (st == LH_OK) st = lh__eng_build(&e, (lh_index)(n < 1000000 ? 4 * n + 256 : 4000000), &affdim);
    if (st == LH_OK) st = lh__eng_hull_facets(&e, 0, &h->facets, &h->count);
    h->ndup = e.ndup;
    lh__eng_release(&e);
    if (st == LH_OK) st = collect_vertices(h);
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
