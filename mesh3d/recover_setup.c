/*
 * recover_setup.c — the constraints: facet triangles on representative points (exact
 * duplicates merged), checked and without repeats, grouped into one patch per facet;
 * and the segments: the PLC's free segments and the facets' polygon edges, each once,
 * with their output number.
 */
#include "recover.h"

#include "facets.h"
#include "lh_sort.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

int lh__t3_collinear(lh_pred *pred, const double *p, const double *q, const double *r)
{
    for (int k = 0; k < 3; k++) {
        int i = k, j = (k + 1) % 3;
        double a[2] = {p[i], p[j]}, b[2] = {q[i], q[j]}, d[2] = {r[i], r[j]};
        const double *pts[3] = {a, b, d};
        if (lh_orient(pred, 2, pts) != 0) return 0;
    }
    return 1;
}

static size_t facet_line(const t3_ctx *c, lh_index f)
{
    return c->g->facet_line ? c->g->facet_line[f] : 0;
}

/* The triangles' corners sorted, for comparing triangles as sets. */
static void sorted3(const lh_index *t, lh_index s[3])
{
    s[0] = t[0], s[1] = t[1], s[2] = t[2];
    lh__t3_sort3(s);
}

/* Triangles on representatives; zero area is an error naming the facet. */
static lh_status take_triangles(t3_ctx *c, const lh__facet_tris *ft)
{
    size_t m = ft->count;
    c->tri = lh__alloc(&c->al, (3 * m + 1) * sizeof(lh_index));
    c->tri_facet = lh__alloc(&c->al, (m + 1) * sizeof(lh_index));
    if (!c->tri || !c->tri_facet) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t k = 0; k < m; k++) {
        lh_index v[3];
        for (int j = 0; j < 3; j++) v[j] = c->dup[ft->tri[3 * k + j]];
        lh_index f = ft->facet[k];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
            lh__t3_collinear(c->pred, c->xyz + 3 * v[0], c->xyz + 3 * v[1], c->xyz + 3 * v[2]))
            return lh__t3_say(c, LH_ERR_DEGENERATE, facet_line(c, f),
                              "facet %ld has a zero-area part (points %ld %ld %ld)",
                              (long)f + c->g->first_index, (long)ft->tri[3 * k] + c->g->first_index,
                              (long)ft->tri[3 * k + 1] + c->g->first_index,
                              (long)ft->tri[3 * k + 2] + c->g->first_index);
        memcpy(c->tri + 3 * k, v, sizeof v);
        c->tri_facet[k] = f;
    }
    c->tri_count = m;
    return LH_OK;
}

/* Drops repeated triangles (the same three points), keeping the first. */
static lh_status drop_repeats(t3_ctx *c)
{
    size_t m = c->tri_count;
    lh_index *idx = lh__alloc(&c->al, (5 * m + 1) * sizeof(lh_index));
    unsigned char *drop = lh__alloc(&c->al, m + 1);
    if (!idx || !drop) {
        lh__free(&c->al, idx);
        lh__free(&c->al, drop);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    lh_index *key = idx + 2 * m; /* each triangle's corners sorted */
    for (size_t k = 0; k < m; k++)
        idx[k] = (lh_index)k, drop[k] = 0, sorted3(c->tri + 3 * k, key + 3 * k);
    const lh__rows rows = {key, 3, 3};
    lh__sort_idx(idx, idx + m, m, lh__rows_cmp, &rows);
    for (size_t k = 1; k < m; k++)
        if (lh__rows_cmp(&rows, idx[k - 1], idx[k]) == 0) drop[idx[k]] = 1;
    size_t w = 0;
    for (size_t k = 0; k < m; k++) {
        if (drop[k]) continue;
        memmove(c->tri + 3 * w, c->tri + 3 * k, 3 * sizeof(lh_index));
        c->tri_facet[w++] = c->tri_facet[k];
    }
    c->tri_count = w;
    lh__free(&c->al, idx);
    lh__free(&c->al, drop);
    return LH_OK;
}

/* An edge as found: endpoints a < b; kind 0 a free segment, 1 a facet ring edge;
 * seq its order of appearance within its kind. */
typedef struct edge_rec {
    lh_index a, b, kind, seq, marker, facet;
} edge_rec;

static int cmp_rec(const void *ctx, lh_index i, lh_index j)
{
    const edge_rec *x = (const edge_rec *)ctx + i, *y = (const edge_rec *)ctx + j;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
    return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static void rec_put(edge_rec *r, size_t *k, lh_index a, lh_index b, lh_index kind, lh_index seq,
                    lh_index marker, lh_index facet)
{
    if (a == b) return;
    edge_rec e = {a < b ? a : b, a < b ? b : a, kind, seq, marker, facet};
    r[(*k)++] = e;
}

static size_t ring_edge_count(const lh_plc *g)
{
    size_t cnt = 0;
    for (size_t p = 0; p < g->polygon_count; p++) {
        size_t k = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
        cnt += k >= 3 ? k : k == 2;
    }
    return cnt;
}

/* Every edge record: free segments, then facet ring edges (a triangulation's
 * diagonals are no constraint: a facet is recovered as a whole, recover_faces.c). */
static size_t collect_edges(const t3_ctx *c, edge_rec *r)
{
    const lh_plc *g = c->g;
    size_t k = 0;
    for (size_t s = 0; s < g->segment_count; s++)
        rec_put(r, &k, c->dup[g->segments[2 * s]], c->dup[g->segments[2 * s + 1]], 0, (lh_index)s,
                g->segment_marker ? g->segment_marker[s] : 0, -1);
    lh_index seq = 0;
    for (size_t f = 0; f < g->facet_count; f++) {
        lh_index mk = g->facet_marker ? g->facet_marker[f] : 0;
        for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
            const lh_index *v = g->polygon_vertices + g->polygon_first[p];
            size_t len = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
            for (size_t i = 0; len >= 2 && i < (len == 2 ? 1 : len); i++)
                rec_put(r, &k, c->dup[v[i]], c->dup[v[(i + 1) % len]], 1, seq++, mk, (lh_index)f);
        }
    }
    return k;
}

static int lex_less(const double *p, const double *q)
{
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k];
    return 0;
}

/* Segments from the sorted records: one per endpoint pair, the first record's kind
 * deciding; seg_key in the records' (endpoint) order. */
static lh_status make_segments(t3_ctx *c, const edge_rec *r, const lh_index *idx, size_t m)
{
    c->seg = lh__alloc(&c->al, (m + 1) * sizeof(t3_seg));
    c->seg_key = lh__alloc(&c->al, (3 * m + 1) * sizeof(lh_index));
    if (!c->seg || !c->seg_key) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t s = 0;
    for (size_t i = 0; i < m; i++) {
        const edge_rec *e = r + idx[i];
        if (i == 0 || e->a != r[idx[i - 1]].a || e->b != r[idx[i - 1]].b) {
            /* a before b in coordinates: a split point depends on the points only */
            int swap = lex_less(c->xyz + 3 * e->b, c->xyz + 3 * e->a);
            t3_seg sg = {swap ? e->b : e->a, swap ? e->a : e->b, 0, e->marker};
            c->seg_key[3 * s] = e->a, c->seg_key[3 * s + 1] = e->b;
            c->seg_key[3 * s + 2] = (lh_index)s;
            c->seg[s++] = sg;
        }
    }
    c->seg_count = s;
    return LH_OK;
}

/* Dense output numbers for the PLC segments: free ones first, then ring edges, each
 * in its first appearance's order. */
static lh_status number_segments(t3_ctx *c, const edge_rec *r, const lh_index *idx, size_t m)
{
    lh_index *first = lh__alloc(&c->al, (c->seg_count + 1) * sizeof(lh_index));
    lh_index *order = lh__alloc(&c->al, (2 * c->seg_count + 1) * sizeof(lh_index));
    edge_rec *key = lh__alloc(&c->al, (c->seg_count + 1) * sizeof(edge_rec));
    lh_status st = LH_OK;
    if (!first || !order || !key) st = lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t s = 0, k = 0;
    for (size_t i = 0; st == LH_OK && i < m; i++) {
        const edge_rec *e = r + idx[i];
        if (i > 0 && e->a == r[idx[i - 1]].a && e->b == r[idx[i - 1]].b) continue;
        {
            key[k] = *e;
            key[k].a = key[k].b = 0; /* order by (kind, seq) only */
            first[k] = (lh_index)s;
            order[k] = (lh_index)k;
            k++;
        }
        s++;
    }
    if (st == LH_OK) {
        lh__sort_idx(order, order + c->seg_count, k, cmp_rec, key);
        for (size_t j = 0; j < k; j++) c->seg[first[order[j]]].parent = (lh_index)j;
    }
    lh__free(&c->al, first);
    lh__free(&c->al, order);
    lh__free(&c->al, key);
    return st;
}

lh_index lh__t3_seg_of(const t3_ctx *c, lh_index p, lh_index q)
{
    lh_index a = p < q ? p : q, b = p < q ? q : p;
    size_t lo = 0, hi = c->seg_count;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        const lh_index *k = c->seg_key + 3 * mid;
        if (k[0] == a && k[1] == b) return k[2];
        if (k[0] < a || (k[0] == a && k[1] < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

/* The triangles' indices grouped by facet, in triangle order within a facet. */
static lh_status by_facet(t3_ctx *c, lh_index **order_out)
{
    size_t nf = c->g->facet_count;
    lh_index *first = lh__alloc(&c->al, (nf + 2) * sizeof(lh_index));
    lh_index *order = lh__alloc(&c->al, (c->tri_count + 1) * sizeof(lh_index));
    if (!first || !order) {
        lh__free(&c->al, first);
        lh__free(&c->al, order);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    memset(first, 0, (nf + 2) * sizeof(lh_index));
    for (size_t k = 0; k < c->tri_count; k++) first[c->tri_facet[k] + 1]++;
    for (size_t f = 0; f < nf; f++) first[f + 1] += first[f];
    for (size_t k = 0; k < c->tri_count; k++) order[first[c->tri_facet[k]]++] = (lh_index)k;
    lh__free(&c->al, first);
    *order_out = order;
    return LH_OK;
}

/* The axis a patch's projection drops, as +-(1 + axis), signed as the normal of the
 * patch's triangle t along it: the facet's own projection axis ax when it was
 * projected (facets.h: the one lh_tetmesh_check projects it along too, where its
 * triangles keep their area even when it is not planar), else (ax = -1, a facet of
 * one triangle) the dominant coordinate of t's normal. */
static signed char drop_axis(const t3_ctx *c, const lh_index *t, int ax)
{
    const double *a = c->xyz + 3 * (size_t)t[0], *b = c->xyz + 3 * (size_t)t[1],
                 *d = c->xyz + 3 * (size_t)t[2];
    if (ax >= 0) /* the sign exactly: t has area in that projection */
        return (signed char)(lh__orient2_along(c->pred, ax, a, b, d) < 0 ? -(ax + 1) : ax + 1);
    double u[3], v[3], nrm[3];
    for (int k = 0; k < 3; k++) /* halved and scaled: no overflow at any scale */
        u[k] = ldexp(b[k] / 2 - a[k] / 2, -c->unit_exp),
        v[k] = ldexp(d[k] / 2 - a[k] / 2, -c->unit_exp);
    nrm[0] = u[1] * v[2] - u[2] * v[1];
    nrm[1] = u[2] * v[0] - u[0] * v[2];
    nrm[2] = u[0] * v[1] - u[1] * v[0];
    ax = fabs(nrm[0]) >= fabs(nrm[1]) && fabs(nrm[0]) >= fabs(nrm[2]) ? 0
         : fabs(nrm[1]) >= fabs(nrm[2])                               ? 1
                                                                      : 2;
    return (signed char)(nrm[ax] < 0 ? -(ax + 1) : ax + 1);
}

/* Patches: each facet's triangles together. */
static lh_status make_patches(t3_ctx *c, const lh_index *order, const signed char *facet_axis)
{
    size_t m = c->tri_count;
    c->patch_first = lh__alloc(&c->al, (m + 2) * sizeof(lh_index));
    c->patch_tri = lh__alloc(&c->al, (m + 1) * sizeof(lh_index));
    c->patch_facet = lh__alloc(&c->al, (m + 1) * sizeof(lh_index));
    c->patch_axis = lh__alloc(&c->al, m + 1);
    if (!c->patch_first || !c->patch_tri || !c->patch_facet || !c->patch_axis)
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t p = 0;
    for (size_t i = 0; i < m; i++) {
        lh_index k = order[i], f = c->tri_facet[k];
        if (i == 0 || c->tri_facet[order[i - 1]] != f) {
            c->patch_first[p] = (lh_index)i;
            c->patch_facet[p] = f;
            c->patch_axis[p] = drop_axis(c, c->tri + 3 * (size_t)k, facet_axis[f]);
            p++;
        }
        c->patch_tri[i] = k;
    }
    c->patch_first[p] = (lh_index)m;
    c->patch_count = p;
    c->pnode_first = lh__alloc(&c->al, (p + 1) * sizeof(lh_index));
    if (!c->pnode_first) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memset(c->pnode_first, 0, (p + 1) * sizeof(lh_index));
    return LH_OK;
}

static lh_status make_edges(t3_ctx *c)
{
    size_t cap = c->g->segment_count + ring_edge_count(c->g) + 1;
    edge_rec *r = lh__alloc(&c->al, cap * sizeof(edge_rec));
    lh_index *idx = lh__alloc(&c->al, 2 * cap * sizeof(lh_index));
    lh_status st = r && idx ? LH_OK : lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t m = 0;
    if (st == LH_OK) {
        m = collect_edges(c, r);
        /* cmp_rec's order: by b, then a (stable); records are made in (kind, seq)
           order, which stable passes keep among equal pairs */
        st = lh__sort_by_index(&c->al, r, m, sizeof *r, offsetof(edge_rec, b), c->g->n);
        if (st == LH_OK)
            st = lh__sort_by_index(&c->al, r, m, sizeof *r, offsetof(edge_rec, a), c->g->n);
        if (st != LH_OK) st = lh__t3_say(c, st, 0, "out of memory");
        for (size_t i = 0; i < m; i++) idx[i] = (lh_index)i;
        if (st == LH_OK) st = make_segments(c, r, idx, m);
    }
    if (st == LH_OK) st = number_segments(c, r, idx, m);
    lh__free(&c->al, r);
    lh__free(&c->al, idx);
    if (st != LH_OK) return st;
    c->tri_seg = lh__alloc(&c->al, (3 * c->tri_count + 1) * sizeof(lh_index));
    if (!c->tri_seg) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t k = 0; k < c->tri_count; k++)
        for (int j = 0; j < 3; j++)
            c->tri_seg[3 * k + j] =
                lh__t3_seg_of(c, c->tri[3 * k + j], c->tri[3 * k + (j + 1) % 3]);
    return LH_OK;
}

lh_status lh__t3_constraints(t3_ctx *c, const lh__facet_tris *ft)
{
    lh_status st = take_triangles(c, ft);
    if (st == LH_OK) st = drop_repeats(c);
    lh_index *order = NULL;
    if (st == LH_OK) st = by_facet(c, &order);
    if (st == LH_OK) st = make_edges(c);
    if (st == LH_OK) st = make_patches(c, order, ft->axis);
    lh__free(&c->al, order);
    return st;
}
