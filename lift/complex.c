/*
 * complex.c — lh_tri_complex: the Delaunay complex from the triangulation. Two
 * neighbouring simplices have the same circumsphere exactly when the vertex of one
 * opposite their common facet lies on the other's circumsphere (insphere = 0, exact
 * and unperturbed); union-find over such facets gives the cells, each a convex
 * polytope inscribed in its sphere.
 */
#include "dt.h"
#include "lh_sort.h"

#include <string.h>

static lh_index find(lh_index *parent, lh_index x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* The vertex of simplex n that simplex s lacks (they share a facet). */
static lh_index opposite(const lh_tri *t, size_t s, lh_index n)
{
    const int nv = t->frame.k + 1;
    for (int j = 0; j < nv; j++) {
        lh_index x = t->simp[(size_t)n * nv + j], shared = 0;
        for (int i = 0; i < nv; i++) shared |= t->simp[s * nv + i] == x;
        if (!shared) return x;
    }
    return -1;
}

/* cell[s]: the cell of simplex s, numbered in order of first simplex; returns the
 * number of cells, or 0 when memory runs out. */
static size_t group_simplices(lh_tri *t, lh_index *cell)
{
    const int nv = t->frame.k + 1;
    lh_index *parent = lh__alloc(&t->alloc, (t->count + 1) * sizeof *parent);
    if (!parent) return 0;
    for (size_t s = 0; s < t->count; s++) parent[s] = (lh_index)s;
    const double *p[LH_DELAUNAY_MAX_DIM + 2];
    for (size_t s = 0; s < t->count; s++)
        for (int k = 0; k < nv; k++) {
            lh_index n = t->nbr[s * nv + k];
            if (n < (lh_index)s) continue; /* each facet once; -1 across the hull */
            for (int j = 0; j < nv; j++) p[j] = t->xyz + (size_t)t->simp[s * nv + j] * t->d;
            p[nv] = t->xyz + (size_t)opposite(t, s, n) * t->d;
            if (lh__frame_insphere(t->pred, &t->frame, p) == 0) parent[find(parent, n)] = find(parent, (lh_index)s);
        }
    size_t nc = 0;
    for (size_t s = 0; s < t->count; s++) cell[s] = -1;
    for (size_t s = 0; s < t->count; s++) {
        lh_index r = find(parent, (lh_index)s);
        if (cell[r] < 0) cell[r] = (lh_index)nc++;
        cell[s] = cell[r];
    }
    lh__free(&t->alloc, parent);
    return nc;
}

/* off[c]..off[c+1]: the distinct vertices of cell c, increasing. */
static lh_status cell_vertices(lh_tri *t, const lh_index *cell, size_t nc, lh_index *off,
                               lh_index **out)
{
    const int nv = t->frame.k + 1;
    lh_index *by = lh__alloc(&t->alloc, (t->count + 1) * sizeof *by);
    lh_index *mark = lh__alloc(&t->alloc, (t->n + 1) * sizeof *mark);
    lh_index *vert = lh__alloc(&t->alloc, (t->count * nv + 1) * sizeof *vert);
    if (!by || !mark || !vert) {
        lh__free(&t->alloc, by);
        lh__free(&t->alloc, mark);
        lh__free(&t->alloc, vert);
        return LH_ERR_NOMEM;
    }
    memset(off, 0, (nc + 1) * sizeof *off); /* counting sort of simplices by cell */
    for (size_t s = 0; s < t->count; s++) off[cell[s] + 1]++;
    for (size_t c = 0; c < nc; c++) off[c + 1] += off[c];
    for (size_t s = 0; s < t->count; s++) by[off[cell[s]]++] = (lh_index)s;
    for (size_t i = 0; i < t->n; i++) mark[i] = -1;
    size_t o = 0;
    for (size_t i = 0, c = 0; c < nc; c++) {
        off[c] = (lh_index)o;
        for (; i < t->count && (size_t)cell[by[i]] == c; i++)
            for (int k = 0; k < nv; k++) {
                lh_index v = t->simp[(size_t)by[i] * nv + k];
                if (mark[v] != (lh_index)c) {
                    mark[v] = (lh_index)c;
                    vert[o++] = v;
                }
            }
        for (size_t a = (size_t)off[c] + 1; a < o; a++) /* a cell has few vertices */
            for (size_t b = a; b > (size_t)off[c] && vert[b] < vert[b - 1]; b--) {
                lh_index x = vert[b];
                vert[b] = vert[b - 1];
                vert[b - 1] = x;
            }
    }
    off[nc] = (lh_index)o;
    lh__free(&t->alloc, by);
    lh__free(&t->alloc, mark);
    *out = vert;
    return LH_OK;
}

typedef struct cells_ctx {
    const lh_index *off, *vert;
} cells_ctx;

static int cell_cmp(const void *vctx, lh_index a, lh_index b)
{
    const cells_ctx *c = vctx;
    lh_index la = c->off[a + 1] - c->off[a], lb = c->off[b + 1] - c->off[b];
    for (lh_index k = 0; k < la && k < lb; k++) {
        lh_index x = c->vert[c->off[a] + k], y = c->vert[c->off[b] + k];
        if (x != y) return x < y ? -1 : 1;
    }
    return (la > lb) - (la < lb);
}

/* Stores the cells in lexicographic order in the handle. */
static lh_status store_sorted(lh_tri *t, size_t nc, const lh_index *off, const lh_index *vert)
{
    lh_index *order = lh__alloc(&t->alloc, (nc + 1) * sizeof *order);
    lh_index *tmp = lh__alloc(&t->alloc, (nc + 1) * sizeof *tmp);
    lh_index *noff = lh__alloc(&t->alloc, (nc + 1) * sizeof *noff);
    lh_index *nvert = lh__alloc(&t->alloc, ((size_t)off[nc] + 1) * sizeof *nvert);
    lh_status st = order && tmp && noff && nvert ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        for (size_t c = 0; c < nc; c++) order[c] = (lh_index)c;
        cells_ctx cc = {off, vert};
        lh__sort_idx(order, tmp, nc, cell_cmp, &cc);
        noff[0] = 0;
        for (size_t c = 0; c < nc; c++) {
            lh_index a = off[order[c]], b = off[order[c] + 1];
            memcpy(nvert + noff[c], vert + a, (size_t)(b - a) * sizeof *nvert);
            noff[c + 1] = noff[c] + (b - a);
        }
        t->cell_off = noff;
        t->cell_vert = nvert;
        t->ncells = nc;
        noff = nvert = NULL;
    }
    lh__free(&t->alloc, order);
    lh__free(&t->alloc, tmp);
    lh__free(&t->alloc, noff);
    lh__free(&t->alloc, nvert);
    return st;
}

static lh_status build_complex(lh_tri *t)
{
    lh_index *cell = lh__alloc(&t->alloc, (t->count + 1) * sizeof *cell), *off = NULL, *vert = NULL;
    lh_status st = cell ? LH_OK : LH_ERR_NOMEM;
    size_t nc = 0;
    if (st == LH_OK && t->count) {
        nc = group_simplices(t, cell);
        if (!nc) st = LH_ERR_NOMEM;
    }
    if (st == LH_OK) {
        off = lh__alloc(&t->alloc, (nc + 2) * sizeof *off);
        st = off ? cell_vertices(t, cell, nc, off, &vert) : LH_ERR_NOMEM;
    }
    if (st == LH_OK) st = store_sorted(t, nc, off, vert);
    lh__free(&t->alloc, cell);
    lh__free(&t->alloc, off);
    lh__free(&t->alloc, vert);
    return st;
}

lh_status lh_tri_complex(lh_tri *t, size_t *count, const lh_index **offsets,
                         const lh_index **vertices)
{
    if (!t || !count || !offsets || !vertices) return LH_ERR_INVALID_ARGUMENT;
    if (!t->cell_off) {
        lh_status st = build_complex(t);
        if (st != LH_OK) return st;
    }
    *count = t->ncells;
    *offsets = t->cell_off;
    *vertices = t->cell_vert;
    return LH_OK;
}
