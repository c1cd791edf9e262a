/*
 * recover_split.c — segments' chains and their splitting: where a subsegment is split
 * (recover.h), the round's queue of split points, and committing them to the mesh.
 */
#include "recover.h"

#include "lh_sort.h"

#include <math.h>
#include <string.h>

static const double *pt(const t3_ctx *c, lh_index i)
{
    return c->xyz + 3 * (size_t)i;
}

size_t lh__t3_chain(const t3_ctx *c, lh_index s, lh_index *buf, size_t cap)
{
    size_t len = 0;
    const t3_seg *sg = c->seg + s;
#define PUT(v)                         \
    do {                               \
        if (len < cap) buf[len] = (v); \
        len++;                         \
    } while (0)
    PUT(sg->a);
    for (lh_index i = c->node_first[s]; i < c->node_first[s + 1]; i++) PUT(c->node[i].p);
    PUT(sg->b);
#undef PUT
    return len;
}

lh_status lh__t3_each_subsegment(t3_ctx *c, t3_subsegment_fn f, void *arg)
{
    for (size_t s = 0; s < c->seg_count; s++) {
        size_t cl = (size_t)(c->node_first[s + 1] - c->node_first[s]) + 2;
        lh_status st = lh__t3_room(c, &c->vbuf, &c->vcap, cl);
        if (st != LH_OK) return st;
        lh__t3_chain(c, (lh_index)s, c->vbuf, c->vcap);
        for (size_t i = 0; i + 1 < cl; i++) {
            lh_index p = c->vbuf[i], q = c->vbuf[i + 1];
            if ((st = f(c, p < q ? p : q, p < q ? q : p, (lh_index)s, i, arg)) != LH_OK) return st;
        }
    }
    return LH_OK;
}

/* The parameter of chain point i of segment s (0 at a, 1 at b). */
static double chain_t(const t3_ctx *c, lh_index s, size_t i)
{
    size_t k = (size_t)(c->node_first[s + 1] - c->node_first[s]);
    if (i == 0) return 0;
    if (i > k) return 1;
    return c->node[c->node_first[s] + (lh_index)i - 1].t;
}

/* Exact: v lies strictly between p and q on their line. */
static int on_open_segment(const t3_ctx *c, lh_index v, lh_index p, lh_index q)
{
    const double *a = pt(c, p), *b = pt(c, q), *x = pt(c, v);
    if (!lh__t3_collinear(c->pred, a, b, x)) return 0;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? a[k] < x[k] && x[k] < b[k] : b[k] < x[k] && x[k] < a[k];
    return 0;
}

/* Half the differences q - p (no overflow at any finite p, q) scaled so that the
 * largest is 1 (no square over- or underflows): into u; returns the factor. */
static double half_diff_unit(const double *p, const double *q, double u[3])
{
    double m = 0;
    for (int k = 0; k < 3; k++) u[k] = q[k] / 2 - p[k] / 2, m = fmax(m, fabs(u[k]));
    for (int k = 0; k < 3; k++) u[k] = m > 0 ? u[k] / m : 0;
    return m;
}

/* The parameter of point v's projection on segment s (for ordering its chain). */
static double seg_param(const t3_ctx *c, lh_index s, lh_index v)
{
    double u[3], w[3];
    double mu = half_diff_unit(pt(c, c->seg[s].a), pt(c, c->seg[s].b), u);
    double mw = half_diff_unit(pt(c, c->seg[s].a), pt(c, v), w);
    double num = 0, den = 0;
    for (int k = 0; k < 3; k++) num += w[k] * u[k], den += u[k] * u[k];
    return mu > 0 ? num / den * (mw / mu) : 0;
}

lh_status lh__t3_queue(t3_ctx *c, lh_index s, double t, lh_index p, const double x[3])
{
    if (c->new_count == c->new_cap) {
        size_t cap = c->new_cap ? 2 * c->new_cap : 64;
        double *nx = lh__alloc(&c->al, 3 * cap * sizeof(double));
        t3_node *nn = lh__alloc(&c->al, cap * sizeof(t3_node));
        if (!nx || !nn) {
            lh__free(&c->al, nx);
            lh__free(&c->al, nn);
            return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        }
        if (c->new_count) {
            memcpy(nx, c->new_xyz, 3 * c->new_count * sizeof(double));
            memcpy(nn, c->new_node, c->new_count * sizeof(t3_node));
        }
        lh__free(&c->al, c->new_xyz);
        lh__free(&c->al, c->new_node);
        c->new_xyz = nx, c->new_node = nn, c->new_cap = cap;
    }
    t3_node nd = {s, p, t};
    c->new_node[c->new_count] = nd;
    if (x) memcpy(c->new_xyz + 3 * c->new_count, x, 3 * sizeof(double));
    c->new_count++;
    return LH_OK;
}

/* A mesh vertex exactly on the open subsegment p q next to p, or -1. */
static lh_index vertex_on(const t3_ctx *c, lh_index p, lh_index q)
{
    const lh_index *s = c->tv;
    lh_index best = -1;
    for (lh_index i = c->star_first[p]; i < c->star_first[p + 1]; i++)
        for (int j = 0; j < 4; j++) {
            lh_index v = s[4 * (size_t)c->star[i] + j];
            if (v == p || v == q || !on_open_segment(c, v, p, q)) continue;
            if (best < 0 || on_open_segment(c, v, p, best)) best = v;
        }
    return best;
}

/* The split parameter of subsegment (tp, tq) of s: Shewchuk's concentric shells
 * around an input vertex at one end only, else the midpoint. */
static double split_param(const t3_ctx *c, lh_index s, lh_index p, lh_index q, double tp, double tq)
{
    int ip = (size_t)p < c->n_input, iq = (size_t)q < c->n_input;
    if (ip == iq) return 0.5 * (tp + tq);
    double u[3], half = half_diff_unit(pt(c, c->seg[s].a), pt(c, c->seg[s].b), u);
    /* the subsegment's length over 2^e, e chosen so that no step over- or
       underflows; a power-of-two distance d from the vertex in [ell/3, 2 ell/3] */
    int e;
    frexp(half, &e);
    double ell = fabs(tq - tp) * ldexp(half, 1 - e) * sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double d = exp2(floor(log2(2.0 * ell / 3.0)));
    double frac = ell > 0 ? d / ell : 0.5;
    return ip ? tp + (tq - tp) * frac : tq - (tq - tp) * frac;
}

lh_status lh__t3_split(t3_ctx *c, lh_index s, size_t i)
{
    lh_index p = i == 0 ? c->seg[s].a : c->node[c->node_first[s] + (lh_index)i - 1].p;
    size_t k = (size_t)(c->node_first[s + 1] - c->node_first[s]);
    lh_index q = i + 1 > k ? c->seg[s].b : c->node[c->node_first[s] + (lh_index)i].p;
    lh_index v = vertex_on(c, p, q);
    if (v >= 0) return lh__t3_queue(c, s, seg_param(c, s, v), v, NULL);
    double tp = chain_t(c, s, i), tq = chain_t(c, s, i + 1);
    double t = split_param(c, s, p, q, tp, tq);
    const double *a = pt(c, c->seg[s].a), *b = pt(c, c->seg[s].b);
    double x[3];
    for (int j = 0; j < 3; j++) { /* a + t (b - a): exact where a and b agree */
        double dj = b[j] - a[j];
        x[j] = isfinite(dj) ? a[j] + t * dj : (1 - t) * a[j] + t * b[j];
    }
    int same_p = 1, same_q = 1, outside = 0;
    for (int j = 0; j < 3; j++) {
        double u = pt(c, p)[j], w = pt(c, q)[j];
        outside |= x[j] < fmin(u, w) || x[j] > fmax(u, w);
        same_p &= x[j] == u;
        same_q &= x[j] == w;
    }
    long base = c->g->first_index; /* as the input numbers its points */
    if (outside || same_p || same_q)
        return lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                          "segment %ld %ld cannot be split further: no point of doubles "
                          "lies between its points %ld and %ld",
                          (long)c->seg[s].a + base, (long)c->seg[s].b + base, (long)p + base,
                          (long)q + base);
    return lh__t3_queue(c, s, t, -1, x);
}

static int cmp_node(const void *ctx, lh_index i, lh_index j)
{
    const t3_node *x = (const t3_node *)ctx + i, *y = (const t3_node *)ctx + j;
    if (x->seg != y->seg) return x->seg < y->seg ? -1 : 1;
    if (x->t != y->t) return x->t < y->t ? -1 : 1;
    return x->p < y->p ? -1 : x->p > y->p;
}

lh_status lh__t3_xyz_room(t3_ctx *c, size_t m)
{
    if (c->n + m <= c->n_cap) return LH_OK;
    size_t cap = 2 * (c->n + m);
    double *x = lh__alloc(&c->al, 3 * cap * sizeof(double));
    if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memcpy(x, c->xyz, 3 * c->n * sizeof(double));
    lh__free(&c->al, c->xyz);
    c->xyz = x, c->n_cap = cap;
    return LH_OK;
}

lh_status lh__t3_node_room(t3_ctx *c, t3_node **nodes, size_t count, size_t *cap, size_t m)
{
    return lh__t3_grow(c, (void **)nodes, cap, count, count + m, sizeof(t3_node));
}

/* Sorts nodes[0..*count) by (seg, t), drops repeats of (seg, point) and, for
 * segments (ends), nodes at a segment's end; rebuilds first[0..groups]. */
static lh_status sort_nodes(t3_ctx *c, t3_node **nodes, size_t *count, size_t *cap, lh_index *first,
                            size_t groups, int ends)
{
    size_t m = *count;
    lh_index *idx = lh__alloc(&c->al, (2 * m + 1) * sizeof(lh_index));
    t3_node *out = lh__alloc(&c->al, (m + 1) * sizeof(t3_node));
    if (!idx || !out) {
        lh__free(&c->al, idx);
        lh__free(&c->al, out);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    for (size_t i = 0; i < m; i++) idx[i] = (lh_index)i;
    lh__sort_idx(idx, idx + m, m, cmp_node, *nodes);
    size_t w = 0;
    for (size_t i = 0; i < m; i++) {
        t3_node nd = (*nodes)[idx[i]];
        if (ends && (nd.p == c->seg[nd.seg].a || nd.p == c->seg[nd.seg].b)) continue;
        /* a repeat has the same parameter (patch points: all 0), so it sorts next */
        if (w == 0 || out[w - 1].seg != nd.seg || out[w - 1].p != nd.p) out[w++] = nd;
    }
    lh__free(&c->al, *nodes);
    lh__free(&c->al, idx);
    *nodes = out, *count = w, *cap = m + 1;
    for (size_t s = 0; s <= groups; s++) first[s] = 0;
    for (size_t i = 0; i < w; i++) first[out[i].seg + 1]++;
    for (size_t s = 0; s < groups; s++) first[s + 1] += first[s];
    return LH_OK;
}

lh_status lh__t3_chains_sort(t3_ctx *c)
{
    lh_status st =
        sort_nodes(c, &c->node, &c->node_count, &c->node_cap, c->node_first, c->seg_count, 1);
    if (st != LH_OK) return st;
    return sort_nodes(c, &c->pnode, &c->pnode_count, &c->pnode_cap, c->pnode_first, c->patch_count,
                      0);
}

static int cmp_xyz(const void *ctx, lh_index a, lh_index b)
{
    const double *x = (const double *)ctx + 3 * (size_t)a, *y = (const double *)ctx + 3 * (size_t)b;
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

void lh__t3_queue_firsts(t3_ctx *c, lh_index *first, lh_index *idx)
{
    size_t k = 0;
    for (size_t i = 0; i < c->new_count; i++) {
        first[i] = (lh_index)i;
        if (c->new_node[i].p < 0) idx[k++] = (lh_index)i; /* the others have no coordinates */
    }
    lh__sort_idx(idx, idx + c->new_count, k, cmp_xyz, c->new_xyz); /* stable: first stays first */
    for (size_t j = 1; j < k; j++)
        if (cmp_xyz(c->new_xyz, idx[j - 1], idx[j]) == 0) first[idx[j]] = first[idx[j - 1]];
}

/* The queued new points, equal ones once, into x (in queue order of first
 * appearance), each node pointing at its point's index; *fresh of them. */
static lh_status number_fresh(t3_ctx *c, double *x, size_t *fresh)
{
    size_t m = c->new_count;
    lh_index *idx = lh__alloc(&c->al, (2 * m + 1) * sizeof(lh_index));
    lh_index *first = lh__alloc(&c->al, (m + 1) * sizeof(lh_index));
    if (!idx || !first) {
        lh__free(&c->al, idx);
        lh__free(&c->al, first);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    lh__t3_queue_firsts(c, first, idx);
    size_t f = 0;
    for (size_t i = 0; i < m; i++) {
        if (c->new_node[i].p >= 0) continue;
        if (first[i] == (lh_index)i) {
            memcpy(x + 3 * f, c->new_xyz + 3 * i, 3 * sizeof(double));
            c->new_node[i].p = (lh_index)(c->n + f++);
        } else {
            c->new_node[i].p = c->new_node[first[i]].p;
        }
    }
    *fresh = f;
    lh__free(&c->al, idx);
    lh__free(&c->al, first);
    return LH_OK;
}

int lh__t3_seg_changed(const t3_ctx *c, size_t s, uint32_t r)
{
    if (c->changed[c->seg[s].a] > r || c->changed[c->seg[s].b] > r) return 1;
    for (lh_index i = c->node_first[s]; i < c->node_first[s + 1]; i++)
        if (c->changed[c->node[i].p] > r) return 1;
    return 0;
}

/* What this round's insertions changed: the new points and every point beside one
 * (their stars), and the points put on chains (their chains changed). */
lh_status lh__t3_mark_changed(t3_ctx *c, size_t first_new, const t3_node *nodes, size_t m)
{
    if (c->changed_cap < c->n) {
        size_t cap = 2 * c->n;
        uint32_t *x = lh__alloc(&c->al, cap * sizeof(uint32_t));
        if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        memset(x, 0, cap * sizeof(uint32_t));
        if (c->changed_cap) memcpy(x, c->changed, c->changed_cap * sizeof(uint32_t));
        lh__free(&c->al, c->changed);
        c->changed = x, c->changed_cap = cap;
    }
    const uint32_t r = (uint32_t)c->rounds;
    const lh_index *s = c->tv;
    for (size_t p = first_new; p < c->n; p++) {
        if (c->dup[p] != (lh_index)p) continue;
        for (lh_index i = c->star_first[p]; i < c->star_first[p + 1]; i++)
            for (int j = 0; j < 4; j++) c->changed[s[4 * (size_t)c->star[i] + j]] = r;
    }
    for (size_t i = 0; i < m; i++) c->changed[nodes[i].p] = r;
    return LH_OK;
}

lh_status lh__t3_commit(t3_ctx *c)
{
    size_t m = c->new_count, fresh = 0;
    lh_status st = lh__t3_xyz_room(c, m);
    if (st == LH_OK) st = lh__t3_node_room(c, &c->node, c->node_count, &c->node_cap, m);
    if (st == LH_OK) st = lh__t3_node_room(c, &c->pnode, c->pnode_count, &c->pnode_cap, m);
    if (st != LH_OK) return st;
    double *x = c->xyz + 3 * c->n;
    st = number_fresh(c, x, &fresh);
    if (st != LH_OK) return st;
    st = lh_tri_insert(c->dt, fresh, x); /* in canonical order: the output's comes from it */
    if (st != LH_OK)
        return lh__t3_say(c, st, 0, "inserting Steiner points: %s", lh_status_message(st));
    c->dup = lh_tri_duplicate_of(c->dt);
    size_t added = 0; /* new distinct points */
    for (size_t i = 0; i < fresh; i++) added += c->dup[c->n + i] == (lh_index)(c->n + i);
    c->steiner += added;
    size_t first_new = c->n;
    c->n += fresh;
    size_t before = c->node_count + c->pnode_count;
    for (size_t i = 0; i < m; i++) {
        t3_node nd = c->new_node[i];
        nd.p = c->dup[nd.p];
        if (nd.seg >= 0) {
            c->node[c->node_count++] = nd;
        } else if (nd.seg != T3_INTERIOR) {
            nd.seg = -1 - nd.seg;
            c->pnode[c->pnode_count++] = nd;
        }
    }
    for (size_t i = 0; i < m; i++) c->new_node[i].p = c->dup[c->new_node[i].p];
    st = lh__t3_chains_sort(c);
    if (st == LH_OK && c->node_count + c->pnode_count == before && added == 0)
        return lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                          "boundary recovery made no progress: every split point fell on a "
                          "point already there");
    if (st == LH_OK) st = lh__t3_mesh_load(c);
    if (st == LH_OK) st = lh__t3_stars(c);
    if (st == LH_OK) st = lh__t3_mark_changed(c, first_new, c->new_node, m);
    c->new_count = 0;
    return st;
}
