/*
 * faces.c — the extreme points of a hull the engine built. The engine's hull is a
 * triangulation of the boundary in which a site on a flat face can be a vertex
 * without being a corner (hull.c). A point of the boundary is a corner exactly when
 * it is a corner of every face that holds it; so:
 *   1. adjacent facets whose planes coincide (the vertex of one across their common
 *      ridge lies on the other's plane: orient_d = 0, exact and unperturbed) are
 *      joined by union-find into the hull's faces, each a (d-1)-polytope — a face of
 *      a convex polytope is connected through its ridges;
 *   2. with no such pair every facet is a face and every vertex a corner;
 *   3. else the vertices of each face of two or more facets are projected along a
 *      coordinate axis the face's plane is not parallel to (dropping a coordinate:
 *      exact, and one to one on that plane, so corners map to corners), and their
 *      corners found in R^(d-1) by the same method, down to R^1 (the two ends).
 * The same faces give the edges of a hull of sites in convex position
 * (lh__hull_edges, for the cells of the Delaunay complex): every edge lies in a
 * facet, and the edges of a face are edges of the hull; a simplex face's are its
 * pairs of vertices, a polygon's are found by orientations, a larger face's in
 * R^(d-1) again.
 */
#include "engine.h"

#include <string.h>

/* The vertex of cell b that cell a lacks (they share a side). */
static lh_index opposite(const lh__tds *t, lh_index a, lh_index b)
{
    const int nv = t->nv;
    for (int k = 0; k < nv; k++)
        if (t->nbr[(size_t)b * nv + k] == a) return t->vert[(size_t)b * nv + k];
    return LH__INF; /* not reached: the neighbour relation is symmetric */
}

/* Joins each pair of adjacent infinite cells whose facets are coplanar; returns
 * whether any pair was. */
static int join_coplanar(lh__eng *e, lh_index *parent)
{
    const int nv = e->nv, d = e->d;
    const double *p[LH__ENGINE_MAX_DIM + 1];
    int any = 0;
    for (lh_index c = 0; c < e->tds.top; c++) {
        parent[c] = c;
        if (lh__tds_dead(&e->tds, c) || lh__eng_finite(e, c)) continue;
        const lh_index *v = e->tds.vert + (size_t)c * nv;
        for (int k = 1; k < nv; k++) { /* the sides through LH__INF: other facets */
            lh_index nb = e->tds.nbr[(size_t)c * nv + k];
            if (nb > c) continue; /* each pair once, when nb's parent is set */
            for (int j = 1; j < nv; j++) p[j - 1] = lh__eng_input(e, (size_t)v[j]);
            p[d] = lh__eng_input(e, (size_t)opposite(&e->tds, c, nb));
            if (lh_orient(e->pred, d, p) == 0) {
                parent[lh__uf_find(parent, c)] = lh__uf_find(parent, nb);
                any = 1;
            }
        }
    }
    return any;
}

static lh_status corners(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                         uint8_t *ext);

/* The first coordinate whose removal leaves the facet v[1..d] of an infinite cell
 * a (d-1)-simplex of nonzero volume (one exists: the facet is not flat). */
static int drop_axis(lh__eng *e, const lh_index *v)
{
    const int d = e->d;
    double q[LH__ENGINE_MAX_DIM][LH__ENGINE_MAX_DIM];
    const double *p[LH__ENGINE_MAX_DIM];
    for (int j = 0; j < d; j++) {
        for (int k = 0; k < d; k++) {
            const double *x = lh__eng_input(e, (size_t)v[k + 1]);
            for (int c = 0, w = 0; c < d; c++)
                if (c != j) q[k][w++] = x[c];
            p[k] = q[k];
        }
        if (lh_orient(e->pred, d - 1, p) != 0) return j;
    }
    return 0;
}

/* A face of the hull: its vertices list[0..m-1] (caller's site indices, distinct)
 * and their coordinates in R^(d-1) after dropping axis `drop` (m (d-1) doubles). */
typedef struct face {
    lh_index *list;
    double *x;
    size_t m;
} face;

/* Gathers face f, whose infinite cells are cell[0..count-1]; seen[] (n entries,
 * never f + 1 yet) marks what is gathered. */
static lh_status gather(lh__eng *e, const lh_index *cell, size_t count, lh_index f, lh_index *seen,
                        face *out)
{
    const int nv = e->nv, d = e->d;
    const int drop = drop_axis(e, e->tds.vert + (size_t)cell[0] * nv);
    out->m = 0;
    out->list = lh__alloc(&e->alloc, (count * (size_t)d + 1) * sizeof *out->list);
    out->x = lh__alloc(&e->alloc, (count * (size_t)d * (size_t)(d - 1) + 1) * sizeof *out->x);
    if (!out->list || !out->x) return LH_ERR_NOMEM;
    for (size_t i = 0; i < count; i++)
        for (int k = 1; k < nv; k++) {
            lh_index v = e->tds.vert[(size_t)cell[i] * nv + k];
            if (seen[v] == f + 1) continue;
            seen[v] = f + 1;
            const double *p = lh__eng_input(e, (size_t)v);
            for (int c = 0, w = 0; c < d; c++)
                if (c != drop) out->x[out->m * (size_t)(d - 1) + (size_t)w++] = p[c];
            out->list[out->m++] = v;
        }
    return LH_OK;
}

static void face_free(lh__eng *e, face *fc)
{
    lh__free(&e->alloc, fc->list);
    lh__free(&e->alloc, fc->x);
}

/* What is done with each face of the hull: its infinite cells cell[0..count-1],
 * its number f (distinct per face, below tds.top), seen[] for gather. */
typedef lh_status (*visit_fn)(lh__eng *e, const lh_index *cell, size_t count, lh_index f,
                              lh_index *seen, void *ctx);

/* Clears ext[] (ctx) of the vertices of a face of two or more facets that are not
 * its corners. */
static lh_status face_corners(lh__eng *e, const lh_index *cell, size_t count, lh_index f,
                              lh_index *seen, void *ctx)
{
    uint8_t *ext = ctx;
    if (count < 2) return LH_OK; /* a simplex: its vertices are its corners */
    face fc;
    lh_status st = gather(e, cell, count, f, seen, &fc);
    uint8_t *sub = st == LH_OK ? lh__alloc(&e->alloc, fc.m + 1) : NULL;
    if (st == LH_OK && !sub) st = LH_ERR_NOMEM;
    if (st == LH_OK) st = corners(&e->alloc, e->pred, e->d - 1, fc.m, fc.x, sub);
    for (size_t i = 0; st == LH_OK && i < fc.m; i++)
        if (!sub[i]) ext[fc.list[i]] = 0;
    lh__free(&e->alloc, sub);
    face_free(e, &fc);
    return st;
}

/* The infinite cells grouped by face (counting sort on the root), then visit on
 * each face. */
static lh_status faces(lh__eng *e, lh_index *parent, visit_fn visit, void *ctx)
{
    const size_t top = (size_t)e->tds.top;
    lh_index *off = lh__alloc(&e->alloc, (top + 1) * sizeof *off);
    lh_index *by = lh__alloc(&e->alloc, (top + 1) * sizeof *by);
    lh_index *seen = lh__alloc(&e->alloc, (e->n + 1) * sizeof *seen);
    lh_status st = off && by && seen ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        memset(off, 0, (top + 1) * sizeof *off);
        memset(seen, 0, (e->n + 1) * sizeof *seen);
        for (size_t c = 0; c < top; c++)
            if (!lh__tds_dead(&e->tds, (lh_index)c) && !lh__eng_finite(e, (lh_index)c))
                off[lh__uf_find(parent, (lh_index)c) + 1]++;
        for (size_t r = 0; r < top; r++) off[r + 1] += off[r];
        for (size_t c = 0; c < top; c++)
            if (!lh__tds_dead(&e->tds, (lh_index)c) && !lh__eng_finite(e, (lh_index)c))
                by[off[lh__uf_find(parent, (lh_index)c)]++] = (lh_index)c;
        for (size_t r = top; r > 0; r--) off[r] = off[r - 1]; /* back to the starts */
        off[0] = 0;
        for (size_t r = 0; st == LH_OK && r < top; r++)
            if (off[r + 1] > off[r])
                st = visit(e, by + off[r], (size_t)(off[r + 1] - off[r]), (lh_index)r, seen, ctx);
    }
    lh__free(&e->alloc, off);
    lh__free(&e->alloc, by);
    lh__free(&e->alloc, seen);
    return st;
}

lh_status lh__eng_hull_corners(lh__eng *e, uint8_t *ext, int *flat)
{
    const int nv = e->nv;
    memset(ext, 0, e->n);
    for (lh_index c = 0; c < e->tds.top; c++)
        if (!lh__tds_dead(&e->tds, c) && !lh__eng_finite(e, c))
            for (int k = 1; k < nv; k++) ext[e->tds.vert[(size_t)c * nv + k]] = 1;
    lh_index *parent = lh__alloc(&e->alloc, ((size_t)e->tds.top + 1) * sizeof *parent);
    if (!parent) return LH_ERR_NOMEM;
    *flat = join_coplanar(e, parent);
    lh_status st = *flat ? faces(e, parent, face_corners, ext) : LH_OK;
    lh__free(&e->alloc, parent);
    return st;
}

/* ext[i] = whether site i of the n (spanning R^d) is a corner of their hull; of
 * duplicates, only the one the others merge into can be. */
static lh_status corners(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                         uint8_t *ext)
{
    if (d == 1) {
        size_t lo = 0, hi = 0;
        for (size_t i = 0; i < n; i++) {
            ext[i] = 0;
            lo = xyz[i] < xyz[lo] ? i : lo;
            hi = xyz[i] > xyz[hi] ? i : hi;
        }
        if (n) ext[lo] = ext[hi] = 1;
        return LH_OK;
    }
    lh_index *dup = lh__alloc(a, (n + 1) * sizeof *dup);
    if (!dup) return LH_ERR_NOMEM;
    lh__eng e;
    lh__eng_init_shared(&e, a, d, n, xyz, dup, pred);
    int affdim = -1, flat = 0;
    lh_status st = lh__eng_build(&e, lh__hull_cells_hint(n), &affdim);
    if (st == LH_OK) st = lh__eng_hull_corners(&e, ext, &flat);
    lh__eng_release(&e);
    lh__free(a, dup);
    return st;
}

/* Where lh__hull_edges's pairs go: up the chain of faces, each level's index mapped
 * through its face's vertex list, to the caller's callback at the top. */
typedef struct edge_sink {
    const struct edge_sink *up; /* NULL at the top */
    const lh_index *map;        /* this level's index -> the level above's */
    lh__edge_fn fn;
    void *user;
} edge_sink;

static void emit(const edge_sink *s, lh_index a, lh_index b)
{
    for (; s->up; s = s->up) {
        a = s->map[a];
        b = s->map[b];
    }
    s->fn(s->user, a < b ? a : b, a < b ? b : a);
}

static lh_status edges_of(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                          const edge_sink *s);

/* The sides of a convex polygon (n sites in convex position in R^2): the pairs with
 * every other site strictly on one side, by n^3 orientations; 0 when n is too large
 * for that to beat building the hull. */
enum { SMALL_POLYGON = 12 };
static int polygon_edges(lh_pred *pred, size_t n, const double *x, const edge_sink *s)
{
    if (n > SMALL_POLYGON) return 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            int lo = 1, hi = -1;
            for (size_t k = 0; k < n; k++) {
                if (k == i || k == j) continue;
                const double *p[3] = {x + 2 * i, x + 2 * j, x + 2 * k};
                int o = lh_orient(pred, 2, p);
                lo = o < lo ? o : lo;
                hi = o > hi ? o : hi;
            }
            if (lo == hi && lo != 0) emit(s, (lh_index)i, (lh_index)j);
        }
    return 1;
}

/* The edges of a face: a simplex's pairs of vertices, else those of the face as a
 * polytope in R^(d-1) (every edge of a face is an edge of the hull). */
static lh_status face_edges(lh__eng *e, const lh_index *cell, size_t count, lh_index f,
                            lh_index *seen, void *ctx)
{
    const int nv = e->nv;
    if (count == 1) {
        const lh_index *v = e->tds.vert + (size_t)cell[0] * nv;
        for (int i = 1; i < nv; i++)
            for (int j = i + 1; j < nv; j++) emit(ctx, v[i], v[j]);
        return LH_OK;
    }
    face fc;
    lh_status st = gather(e, cell, count, f, seen, &fc);
    edge_sink sub = {ctx, fc.list, NULL, NULL};
    if (st == LH_OK && !(e->d == 3 && polygon_edges(e->pred, fc.m, fc.x, &sub)))
        st = edges_of(&e->alloc, e->pred, e->d - 1, fc.m, fc.x, &sub);
    face_free(e, &fc);
    return st;
}

/* Every edge of the hull of the n sites (in convex position, spanning R^d), once
 * or more: in R^1 the two ends; d+1 sites: every pair; else the edges of its faces
 * (every edge lies in a facet). */
static lh_status edges_of(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                          const edge_sink *s)
{
    if (d == 1) {
        size_t lo = 0, hi = 0;
        for (size_t i = 0; i < n; i++) {
            lo = xyz[i] < xyz[lo] ? i : lo;
            hi = xyz[i] > xyz[hi] ? i : hi;
        }
        emit(s, (lh_index)lo, (lh_index)hi);
        return LH_OK;
    }
    if (n == (size_t)d + 1) {
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n; j++) emit(s, (lh_index)i, (lh_index)j);
        return LH_OK;
    }
    if (d == 2 && polygon_edges(pred, n, xyz, s)) return LH_OK;
    lh_index *dup = lh__alloc(a, (n + 1) * sizeof *dup);
    if (!dup) return LH_ERR_NOMEM;
    lh__eng e;
    lh__eng_init_shared(&e, a, d, n, xyz, dup, pred);
    int affdim = -1;
    lh_status st = lh__eng_build(&e, lh__hull_cells_hint(n), &affdim);
    lh_index *parent = st == LH_OK ? lh__alloc(a, ((size_t)e.tds.top + 1) * sizeof *parent) : NULL;
    if (st == LH_OK && !parent) st = LH_ERR_NOMEM;
    if (st == LH_OK) {
        join_coplanar(&e, parent);
        st = faces(&e, parent, face_edges, (void *)s);
    }
    lh__free(a, parent);
    lh__eng_release(&e);
    lh__free(a, dup);
    return st;
}

lh_status lh__hull_edges(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                         lh__edge_fn fn, void *user)
{
    edge_sink top = {NULL, NULL, fn, user};
    return edges_of(a, pred, d, n, xyz, &top);
}
