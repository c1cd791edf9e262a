/*
 * complex.c — lh_tri_complex: the Delaunay complex from the triangulation. Two
 * neighbouring simplices have the same circumsphere exactly when the vertex of one
 * opposite their common facet lies on the other's circumsphere (insphere = 0, exact
 * and unperturbed); union-find over such facets gives the cells, each a convex
 * polytope inscribed in its sphere. Its edges: a simplex cell's pairs of vertices,
 * a larger cell's found from its faces (lh__hull_edges: its vertices, on a sphere,
 * are in convex position), in the coordinates J of the frame (one to one there).
 */
#include "dt.h"
#include "lh_sort.h"

#include <string.h>

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
            if (lh__frame_insphere(t->pred, &t->frame, p) == 0)
                parent[lh__uf_find(parent, n)] = lh__uf_find(parent, (lh_index)s);
        }
    size_t nc = 0;
    for (size_t s = 0; s < t->count; s++) cell[s] = -1;
    for (size_t s = 0; s < t->count; s++) {
        lh_index r = lh__uf_find(parent, (lh_index)s);
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

/* Stores the cells in lexicographic order in the handle, and each simplex's place
 * in that order (cell[s] numbers them in order of first simplex). */
static lh_status store_sorted(lh_tri *t, size_t nc, const lh_index *off, const lh_index *vert,
                              const lh_index *cell)
{
    lh_index *order = lh__alloc(&t->alloc, (nc + 1) * sizeof *order);
    lh_index *tmp = lh__alloc(&t->alloc, (nc + 1) * sizeof *tmp);
    lh_index *noff = lh__alloc(&t->alloc, (nc + 1) * sizeof *noff);
    lh_index *nvert = lh__alloc(&t->alloc, ((size_t)off[nc] + 1) * sizeof *nvert);
    lh_index *scell = lh__alloc(&t->alloc, (t->count + 1) * sizeof *scell);
    lh_status st = order && tmp && noff && nvert && scell ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        for (size_t c = 0; c < nc; c++) order[c] = (lh_index)c;
        cells_ctx cc = {off, vert};
        lh__sort_idx(order, tmp, nc, cell_cmp, &cc);
        noff[0] = 0;
        for (size_t c = 0; c < nc; c++) {
            lh_index a = off[order[c]], b = off[order[c] + 1];
            memcpy(nvert + noff[c], vert + a, (size_t)(b - a) * sizeof *nvert);
            noff[c + 1] = noff[c] + (b - a);
            tmp[order[c]] = (lh_index)c; /* the inverse permutation */
        }
        for (size_t s = 0; s < t->count; s++) scell[s] = tmp[cell[s]];
        t->cell_off = noff;
        t->cell_vert = nvert;
        t->simp_cell = scell;
        t->ncells = nc;
        noff = nvert = scell = NULL;
    }
    lh__free(&t->alloc, order);
    lh__free(&t->alloc, tmp);
    lh__free(&t->alloc, noff);
    lh__free(&t->alloc, nvert);
    lh__free(&t->alloc, scell);
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
    if (st == LH_OK) st = store_sorted(t, nc, off, vert, cell);
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

lh_status lh_tri_complex_cells(lh_tri *t, const lh_index **cell)
{
    if (!t || !cell) return LH_ERR_INVALID_ARGUMENT;
    size_t count;
    const lh_index *off, *vert;
    lh_status st = lh_tri_complex(t, &count, &off, &vert);
    *cell = st == LH_OK ? t->simp_cell : NULL;
    return st;
}

/* Growing list of pairs for lh__hull_edges. */
typedef struct pairs {
    lh_tri *t;
    const lh_index *map; /* a cell's local index -> site */
    lh_index *v;
    size_t count, cap;
    int nomem;
} pairs;

static void add_pair(void *ctx, lh_index a, lh_index b)
{
    pairs *p = ctx;
    if (p->count == p->cap && !p->nomem) {
        size_t cap = p->cap ? 2 * p->cap : 64;
        lh_index *v = lh__alloc(&p->t->alloc, 2 * cap * sizeof *v);
        if (v) {
            if (p->count) memcpy(v, p->v, 2 * p->count * sizeof *v);
            lh__free(&p->t->alloc, p->v);
            p->v = v;
            p->cap = cap;
        } else {
            p->nomem = 1;
        }
    }
    if (p->count == p->cap) return;
    a = p->map ? p->map[a] : a;
    b = p->map ? p->map[b] : b;
    p->v[2 * p->count] = a < b ? a : b;
    p->v[2 * p->count + 1] = a < b ? b : a;
    p->count++;
}

/* Sorts p's pairs and keeps each once. */
static lh_status sort_pairs(lh_tri *t, pairs *p)
{
    lh_index *sorted = lh__alloc(&t->alloc, (2 * p->count + 2) * sizeof *sorted);
    lh_index *order = lh__alloc(&t->alloc, (p->count + 1) * sizeof *order);
    lh_status st = sorted && order && lh__sort_tuples(&t->alloc, p->v, 2, p->count, t->n, sorted, order)
                       ? LH_OK : LH_ERR_NOMEM;
    size_t w = 0;
    for (size_t i = 0; st == LH_OK && i < p->count; i++)
        if (!w || sorted[2 * i] != sorted[2 * w - 2] || sorted[2 * i + 1] != sorted[2 * w - 1]) {
            sorted[2 * w] = sorted[2 * i];
            sorted[2 * w + 1] = sorted[2 * i + 1];
            w++;
        }
    lh__free(&t->alloc, order);
    lh__free(&t->alloc, p->v);
    p->v = st == LH_OK ? sorted : NULL;
    p->count = st == LH_OK ? w : 0;
    if (st != LH_OK) lh__free(&t->alloc, sorted);
    return st;
}

/* The edges of the cells that are not simplices, sorted, once each. */
static lh_status big_cell_edges(lh_tri *t, pairs *p)
{
    const int k = t->frame.k;
    size_t most = 0;
    for (size_t c = 0; c < t->ncells; c++)
        if ((size_t)(t->cell_off[c + 1] - t->cell_off[c]) > most) most = (size_t)(t->cell_off[c + 1] - t->cell_off[c]);
    double *x = lh__alloc(&t->alloc, (most * (size_t)k + 1) * sizeof *x);
    if (!x) return LH_ERR_NOMEM;
    lh_status st = LH_OK;
    for (size_t c = 0; c < t->ncells && st == LH_OK && !p->nomem; c++) {
        const lh_index *v = t->cell_vert + t->cell_off[c];
        const size_t m = (size_t)(t->cell_off[c + 1] - t->cell_off[c]);
        if (m == (size_t)k + 1) continue;
        p->map = v;
        for (size_t i = 0; i < m; i++)
            for (int j = 0; j < k; j++) x[i * k + j] = t->xyz[(size_t)v[i] * t->d + (k == t->d ? j : t->frame.J[j])];
        st = lh__hull_edges(&t->alloc, t->pred, k, m, x, add_pair, p);
    }
    lh__free(&t->alloc, x);
    p->map = NULL;
    if (st == LH_OK && p->nomem) st = LH_ERR_NOMEM;
    return st == LH_OK ? sort_pairs(t, p) : st;
}

static int has_pair(const pairs *p, lh_index a, lh_index b)
{
    size_t lo = 0, hi = p->count;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const lh_index *q = p->v + 2 * mid;
        if (q[0] < a || (q[0] == a && q[1] < b)) lo = mid + 1;
        else hi = mid;
    }
    return lo < p->count && p->v[2 * lo] == a && p->v[2 * lo + 1] == b;
}

/* Every edge ij (i < j) of the triangulation that is an edge of the complex — of
 * the cell of a simplex holding it (an edge of one cell holding ij is one of every
 * cell holding it: they meet in a face holding ij) — site by site, j increasing. */
static lh_status complex_edges(lh_tri *t, const pairs *big, pairs *out)
{
    const int nv = t->frame.k + 1;
    lh_index *off = lh__alloc(&t->alloc, (t->n + 1) * sizeof *off);
    lh_index *inc = lh__alloc(&t->alloc, (t->count * nv + 1) * sizeof *inc);
    lh_index *mark = lh__alloc(&t->alloc, (t->n + 1) * sizeof *mark);
    lh_index *nb = lh__alloc(&t->alloc, (t->n + 1) * sizeof *nb);
    lh_index *via = lh__alloc(&t->alloc, (t->n + 1) * sizeof *via);
    lh_status st = off && inc && mark && nb && via ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        memset(off, 0, (t->n + 1) * sizeof *off); /* site -> simplices, by counting */
        for (size_t i = 0; i < t->count * nv; i++) off[t->simp[i] + 1]++;
        for (size_t i = 0; i < t->n; i++) off[i + 1] += off[i];
        for (size_t i = 0; i < t->count * nv; i++) inc[off[t->simp[i]]++] = (lh_index)(i / nv);
        for (size_t i = t->n; i > 0; i--) off[i] = off[i - 1];
        off[0] = 0;
        for (size_t i = 0; i < t->n; i++) mark[i] = -1;
    }
    for (size_t i = 0; st == LH_OK && i < t->n; i++) {
        size_t cnt = 0;
        for (lh_index q = off[i]; q < off[i + 1]; q++)
            for (int k = 0; k < nv; k++) {
                lh_index j = t->simp[(size_t)inc[q] * nv + k];
                if (j <= (lh_index)i || mark[j] == (lh_index)i) continue;
                mark[j] = (lh_index)i;
                size_t w = cnt++; /* insertion by j: a site has few neighbours */
                for (; w > 0 && nb[w - 1] > j; w--) {
                    nb[w] = nb[w - 1];
                    via[w] = via[w - 1];
                }
                nb[w] = j;
                via[w] = inc[q];
            }
        for (size_t c = 0; c < cnt && !out->nomem; c++) {
            lh_index cell = t->simp_cell[via[c]];
            if (t->cell_off[cell + 1] - t->cell_off[cell] == nv || has_pair(big, (lh_index)i, nb[c]))
                add_pair(out, (lh_index)i, nb[c]);
        }
        if (out->nomem) st = LH_ERR_NOMEM;
    }
    lh__free(&t->alloc, off);
    lh__free(&t->alloc, inc);
    lh__free(&t->alloc, mark);
    lh__free(&t->alloc, nb);
    lh__free(&t->alloc, via);
    return st;
}

lh_status lh_tri_complex_edges(lh_tri *t, size_t *count, const lh_index **edges)
{
    if (!t || !count || !edges) return LH_ERR_INVALID_ARGUMENT;
    if (!t->edges) {
        size_t nc;
        const lh_index *off, *vert;
        lh_status st = lh_tri_complex(t, &nc, &off, &vert);
        pairs big = {t, NULL, NULL, 0, 0, 0}, all = {t, NULL, NULL, 0, 0, 0};
        if (st == LH_OK) st = big_cell_edges(t, &big);
        if (st == LH_OK) st = complex_edges(t, &big, &all);
        lh__free(&t->alloc, big.v);
        if (st != LH_OK) {
            lh__free(&t->alloc, all.v);
            return st;
        }
        t->edges = all.v;
        t->nedges = all.count;
        if (!t->edges) t->edges = lh__alloc(&t->alloc, 2 * sizeof *t->edges); /* none: still built */
        if (!t->edges) return LH_ERR_NOMEM;
    }
    *count = t->nedges;
    *edges = t->edges;
    return LH_OK;
}
