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
 */
#include "engine.h"

#include <string.h>

static lh_index find(lh_index *parent, lh_index x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

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
                parent[find(parent, c)] = find(parent, nb);
                any = 1;
            }
        }
    }
    return any;
}

static lh_status corners(const lh_allocator *a, int d, size_t n, const double *xyz, uint8_t *ext);

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

/* Clears ext[] of the vertices of face f's cells cell[0..count-1] that are not its
 * corners; seen[] (n entries, never f + 1 yet) marks what is gathered. */
static lh_status face_corners(lh__eng *e, const lh_index *cell, size_t count, lh_index f,
                              lh_index *seen, uint8_t *ext)
{
    const int nv = e->nv, d = e->d;
    const int drop = drop_axis(e, e->tds.vert + (size_t)cell[0] * nv);
    lh_index *list = lh__alloc(&e->alloc, (count * (size_t)d + 1) * sizeof *list);
    double *x = lh__alloc(&e->alloc, (count * (size_t)d * (size_t)(d - 1) + 1) * sizeof *x);
    uint8_t *sub = lh__alloc(&e->alloc, count * (size_t)d + 1);
    lh_status st = list && x && sub ? LH_OK : LH_ERR_NOMEM;
    size_t m = 0;
    for (size_t i = 0; st == LH_OK && i < count; i++)
        for (int k = 1; k < nv; k++) {
            lh_index v = e->tds.vert[(size_t)cell[i] * nv + k];
            if (seen[v] == f + 1) continue;
            seen[v] = f + 1;
            const double *p = lh__eng_input(e, (size_t)v);
            for (int c = 0, w = 0; c < d; c++)
                if (c != drop) x[m * (size_t)(d - 1) + (size_t)w++] = p[c];
            list[m++] = v;
        }
    if (st == LH_OK) st = corners(&e->alloc, d - 1, m, x, sub);
    for (size_t i = 0; st == LH_OK && i < m; i++)
        if (!sub[i]) ext[list[i]] = 0;
    lh__free(&e->alloc, list);
    lh__free(&e->alloc, x);
    lh__free(&e->alloc, sub);
    return st;
}

/* The infinite cells grouped by face (counting sort on the root), then
 * face_corners on each face of two or more. */
static lh_status faces(lh__eng *e, lh_index *parent, uint8_t *ext)
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
                off[find(parent, (lh_index)c) + 1]++;
        for (size_t r = 0; r < top; r++) off[r + 1] += off[r];
        for (size_t c = 0; c < top; c++)
            if (!lh__tds_dead(&e->tds, (lh_index)c) && !lh__eng_finite(e, (lh_index)c))
                by[off[find(parent, (lh_index)c)]++] = (lh_index)c;
        for (size_t r = top; r > 0; r--) off[r] = off[r - 1]; /* back to the starts */
        off[0] = 0;
        for (size_t r = 0; st == LH_OK && r < top; r++)
            if (off[r + 1] - off[r] > 1)
                st = face_corners(e, by + off[r], (size_t)(off[r + 1] - off[r]), (lh_index)r, seen, ext);
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
    lh_status st = *flat ? faces(e, parent, ext) : LH_OK;
    lh__free(&e->alloc, parent);
    return st;
}

/* ext[i] = whether site i of the n (spanning R^d) is a corner of their hull; of
 * duplicates, only the one the others merge into can be. */
static lh_status corners(const lh_allocator *a, int d, size_t n, const double *xyz, uint8_t *ext)
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
    lh_status st = lh__eng_init(&e, a, d, n, xyz, dup, NULL);
    int affdim = -1, flat = 0;
    if (st == LH_OK) st = lh__eng_build(&e, (lh_index)(4 * n + 256), &affdim);
    if (st == LH_OK) st = lh__eng_hull_corners(&e, ext, &flat);
    lh__eng_release(&e);
    lh__free(a, dup);
    return st;
}
