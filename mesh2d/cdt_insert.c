/*
 * cdt_insert.c — segment insertion into the 2D constrained Delaunay triangulation
 * (m2.h). The walk from a collects the triangles the segment crosses and the
 * vertices left and right of it; the two pseudo-polygons are retriangulated by
 * Anglada's recursion (M. V. Anglada 1997, "An improved incremental algorithm for
 * constructing restricted Delaunay triangulations", Computers & Graphics 21(2)):
 * on base edge pq choose the polygon vertex c whose circle pqc holds no other; the
 * triangle pqc splits the polygon in two. Every decision is an exact orient_2 or
 * incircle; a vertex exactly on the segment splits it there (Shewchuk & Brown 2015
 * §3). Cocircular ties keep the earlier vertex, so the result is deterministic.
 */
#include <math.h>

#include "m2.h"

lh_index lh__m2_find_edge(const lh__m2 *m, lh_index a, lh_index b, int *pos)
{
    lh__m2_fan f;
    for (lh_index t = lh__m2_fan_first(m, &f, a); t >= 0; t = lh__m2_fan_next(m, &f)) {
        const int i = lh__m2_vpos(m, t, a);
        if (m->v[3 * (size_t)t + (i + 1) % 3] == b) {
            *pos = (i + 2) % 3;
            return t;
        }
    }
    return -1;
}

/* The first triangle of the fan around a with an edge on subsegment s. */
static lh_index subseg_in_fan(const lh__m2 *m, lh_index a, lh_index s, int *pos)
{
    lh__m2_fan f;
    for (lh_index t = lh__m2_fan_first(m, &f, a); t >= 0; t = lh__m2_fan_next(m, &f))
        for (int k = 0; k < 3; k++)
            if (m->sg[3 * (size_t)t + k] == s) {
                *pos = k;
                return t;
            }
    return -1;
}

/* The fan from vt[a] is one of the components of a's neighbourhood: where a hole
 * touches the outer ring, or a ring touches itself, the domain is pinched at a and
 * the subsegment may lie in another component (its edge either way round), or in
 * none of both ends' fans when both are such pinch vertices: then every triangle is
 * searched. Both triangles beside a subsegment name it (m2.h). */
lh_index lh__m2_find_subseg(const lh__m2 *m, lh_index s, int *pos)
{
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    lh_index t = lh__m2_find_edge(m, a, b, pos);
    if (t < 0) t = lh__m2_find_edge(m, b, a, pos);
    if (t < 0) t = subseg_in_fan(m, a, s, pos);
    if (t < 0) t = subseg_in_fan(m, b, s, pos);
    for (size_t u = 0; t < 0 && u < m->nt; u++)
        for (int k = 0; k < 3 && t < 0; k++)
            if (m->v[3 * u] >= 0 && m->sg[3 * u + k] == s) t = (lh_index)u, *pos = k;
    return t;
}

/* Marks edge t:pos (and its twin) as subsegment s. */
static void mark_edge(lh__m2 *m, lh_index t, int pos, lh_index s)
{
    m->sg[3 * (size_t)t + pos] = s;
    const lh_index n = m->nb[3 * (size_t)t + pos];
    if (n >= 0) m->sg[3 * (size_t)n + lh__m2_npos(m, n, t)] = s;
}

/* Edge a->u or u->a exists: make it (part of) input segment parent. */
static lh_status claim_edge(lh__m2 *m, lh_index t, int pos, lh_index a, lh_index u,
                            lh_index parent)
{
    const lh_index s = m->sg[3 * (size_t)t + pos];
    if (s >= 0) { /* overlapping input segments share the edge */
        m->smul[s]++;
        return m->cover && parent >= 0 && m->sp[s] < -1 ? lh__cover_claim(m, s, parent) : LH_OK;
    }
    lh_index id;
    lh_status st = lh__m2_add_subseg(m, a, u, parent, &id);
    if (st == LH_OK) mark_edge(m, t, pos, id);
    return st;
}

/* Triangulates the pseudo-polygon p, q, V[0..k-1] (counterclockwise) into c; the
 * triangle on pq gets subsegment s on that edge. Ranges wait on m's scratch stack. */
static lh_status retriangulate(lh__m2 *m, lh__m2_cavity *c, lh_index p, lh_index q,
                               const lh_index *V, size_t k, lh_index s)
{
    typedef struct { lh_index p, q; size_t lo, hi; } range;
    range work[64], *w = work;
    size_t top = 0, cap = 64;
    lh_status st = LH_OK;
    range *heap = NULL;
    work[top++] = (range){p, q, 0, k};
    int first = 1;
    while (top && st == LH_OK) {
        const range r = w[--top];
        if (r.lo == r.hi) continue;
        size_t i = r.lo;
        for (size_t j = r.lo + 1; j < r.hi; j++)
            if (lh__m2_incircle(m, r.p, r.q, V[i], lh__m2_pt(m, V[j])) < 0) i = j;
        const lh_index sg[3] = {-1, -1, first ? s : -1};
        first = 0;
        st = lh__m2_cavity_push_tri(m, c, r.p, r.q, V[i], sg);
        if (top + 2 > cap) { /* deeper than 64 ranges: move to the heap */
            range *h = lh__alloc(&m->al, 2 * cap * sizeof *h);
            if (!h) { st = LH_ERR_NOMEM; break; }
            for (size_t j = 0; j < top; j++) h[j] = w[j];
            lh__free(&m->al, heap);
            w = heap = h;
            cap *= 2;
        }
        w[top++] = (range){V[i], r.q, r.lo, i};
        w[top++] = (range){r.p, V[i], i + 1, r.hi};
    }
    lh__free(&m->al, heap);
    return st;
}

/* The triangle at a whose wedge holds the direction to b: *u is a vertex of it on
 * the ray a->b (then *pos names edge a-u), or -1 when the ray enters the interior. */
static lh_index start_wedge(lh__m2 *m, lh_index a, lh_index b, lh_index *u, int *pos)
{
    lh__m2_fan f;
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    for (lh_index t = lh__m2_fan_first(m, &f, a); t >= 0; t = lh__m2_fan_next(m, &f)) {
        const int i = lh__m2_vpos(m, t, a);
        const lh_index x = m->v[3 * (size_t)t + (i + 1) % 3], y = m->v[3 * (size_t)t + (i + 2) % 3];
        const int ox = lh__m2_orient(m, a, x, b), oy = lh__m2_orient(m, a, y, b);
        if (ox == 0 && lh__m2_same_way(pa, lh__m2_pt(m, x), pa, pb)) {
            *u = x, *pos = (i + 2) % 3;
            return t;
        }
        if (oy == 0 && lh__m2_same_way(pa, lh__m2_pt(m, y), pa, pb)) {
            *u = y, *pos = (i + 1) % 3;
            return t;
        }
        if (ox > 0 && oy < 0) {
            *u = -1, *pos = i;
            return t;
        }
    }
    return -1;
}

static lh_status crossing(lh__m2 *m, lh_index s, lh_index parent, lh__m2_problem *pb)
{
    pb->kind = LH__M2_CROSSING;
    pb->sub = s;
    pb->seg[0] = parent;
    pb->seg[1] = m->sp[s];
    return LH_ERR_DEGENERATE;
}

static lh_status chain_push(lh__m2 *m, lh__m2_cavity *c, int side, lh_index v)
{
    if (!lh__m2_grow(m, (void **)&c->chain[side], c->chain_count[side], &c->chain_cap[side],
                     c->chain_count[side] + 1, sizeof(lh_index)))
        return LH_ERR_NOMEM;
    c->chain[side][c->chain_count[side]++] = v;
    return LH_OK;
}

/* The position in triangle n of its vertex that is neither x nor y. */
static int other_pos(const lh__m2 *m, lh_index n, lh_index x, lh_index y)
{
    const lh_index *v = m->v + 3 * (size_t)n;
    return v[0] != x && v[0] != y ? 0 : v[1] != x && v[1] != y ? 1 : 2;
}

/* Walks from a towards b through the interior, from triangle t whose edge opposite
 * a the segment crosses: c->dead gets the crossed triangles, c->chain[0] the
 * vertices left of a->b and c->chain[1] those right of it, in the order met; *end
 * is where the segment stops: b, or a vertex exactly on it (then strictly between). */
static lh_status walk(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b, lh_index t,
                      lh_index parent, lh_index *end, lh__m2_problem *pb)
{
    const int i = lh__m2_vpos(m, t, a);
    lh_index right = m->v[3 * (size_t)t + (i + 1) % 3], left = m->v[3 * (size_t)t + (i + 2) % 3];
    int pos = i;
    lh__m2_cavity_clear(c);
    c->chain_count[0] = c->chain_count[1] = 0;
    lh_status st;
    if ((st = chain_push(m, c, 0, left)) != LH_OK || (st = chain_push(m, c, 1, right)) != LH_OK)
        return st;
    for (;;) {
        const lh_index s = m->sg[3 * (size_t)t + pos];
        if (s >= 0) return crossing(m, s, parent, pb);
        if ((st = lh__m2_cavity_push_dead(m, c, t)) != LH_OK) return st;
        const lh_index n = m->nb[3 * (size_t)t + pos];
        if (n < 0) return LH_ERR_INTERNAL; /* b is in the hull: the walk cannot leave it */
        const lh_index v = m->v[3 * (size_t)n + lh__m2_npos(m, n, t)];
        const int o = v == b ? 0 : lh__m2_orient(m, a, b, v);
        if (o == 0) {
            *end = v;
            return lh__m2_cavity_push_dead(m, c, n);
        }
        if (o > 0) { /* v is left: the next crossed edge joins right and v */
            pos = other_pos(m, n, right, v);
            left = v;
        } else {
            pos = other_pos(m, n, left, v);
            right = v;
        }
        if ((st = chain_push(m, c, o > 0 ? 0 : 1, v)) != LH_OK) return st;
        t = n;
    }
}

/* Replaces the crossed triangles by the two sides' triangulations, the segment
 * a-end between them. */
static lh_status fill(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index end, lh_index parent)
{
    lh_index s;
    lh_status st = lh__m2_add_subseg(m, a, end, parent, &s);
    if (st != LH_OK) return st;
    lh_index *L = c->chain[0];
    const size_t nl = c->chain_count[0];
    for (size_t i = 0; i < nl / 2; i++) { /* left side: a, end, then the chain backwards */
        const lh_index x = L[i];
        L[i] = L[nl - 1 - i];
        L[nl - 1 - i] = x;
    }
    if ((st = retriangulate(m, c, a, end, L, nl, s)) != LH_OK ||
        (st = retriangulate(m, c, end, a, c->chain[1], c->chain_count[1], s)) != LH_OK)
        return st;
    return lh__m2_cavity_apply(m, c);
}

/* Puts a vertex at the crossing of a-b with subsegment s (the intersection of the two
 * lines, rounded once: it lies within an ulp or so of both), splitting s there
 * (m2_insert.c). *x is the new vertex, or -1 when rounding put it where it cannot go
 * (on an endpoint, or outside the two triangles beside s). */
static lh_status split_crossing(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b, lh_index s,
                                lh_index *x)
{
    const lh_index e = m->sv[2 * (size_t)s], f = m->sv[2 * (size_t)s + 1];
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b), *pe = lh__m2_pt(m, e), *pf = lh__m2_pt(m, f);
    const double bx = pb[0] - pa[0], by = pb[1] - pa[1], fx = pf[0] - pe[0], fy = pf[1] - pe[1];
    const double t = ((pe[0] - pa[0]) * fy - (pe[1] - pa[1]) * fx) / (bx * fy - by * fx);
    const double p[2] = {pa[0] + t * bx, pa[1] + t * by};
    const double u = fabs(fx) > fabs(fy) ? (p[0] - pe[0]) / fx : (p[1] - pe[1]) / fy; /* along s */
    lh__m2_ins r = {0};
    lh_status st = lh__m2_insert_point(m, c, p, -1, s, &r);
    lh__free(&m->al, r.enc);
    *x = st == LH_OK && r.result == LH__M2_INSERTED ? r.vertex : -1;
    if (*x < 0) return st;
    const lh_index parent = m->sp[s];
    m->pmark[*x] = parent >= 0 && m->seg_marker ? m->seg_marker[parent] : 0;
    for (int j = 0; j < m->attr_count; j++) {
        const size_t na = (size_t)m->attr_count;
        m->attr[(size_t)*x * na + j] = (1 - u) * m->attr[(size_t)e * na + j] + u * m->attr[(size_t)f * na + j];
    }
    m->crossings++;
    return LH_OK;
}

/* Whether x lies ahead of a towards b and nearer b than a (rounded arithmetic: a
 * choice among vertices an exact test already put on the segment's line). */
static int ahead_towards(const double *pa, const double *pb, const double *px)
{
    const double dx = pb[0] - pa[0], dy = pb[1] - pa[1], ex = pb[0] - px[0], ey = pb[1] - px[1];
    return (px[0] - pa[0]) * dx + (px[1] - pa[1]) * dy > 0 && ex * ex + ey * ey < dx * dx + dy * dy;
}

/* With split_crossings an input segment's chain of subsegments bends at each rounded
 * crossing vertex, so an input segment overlapping it (a duplicate, or collinear and
 * sharing a stretch) no longer runs along it: inserted straight, it crossed the chain
 * beside each bend and made a second chain, an ulp or so from the first along their
 * whole length, whose slivers refinement split without end (gigabytes for a
 * four-vertex input). So an overlap follows the chain: from a, a subsegment of an
 * input segment on parent's line (exact orient_2 of the input endpoints) to a vertex
 * w nearer b than a and ahead of a is claimed like an edge along the segment (w = b,
 * or w before b). Returns the triangle holding that edge (*pos, *w), or -1. */
static lh_index along_chain(const lh__m2 *m, lh_index a, lh_index b, lh_index parent, lh_index *w,
                            int *pos)
{
    if (!m->split_crossings || !m->in_seg || parent < 0) return -1;
    const lh_index *P = m->in_seg + 2 * (size_t)parent;
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    lh__m2_fan f;
    for (lh_index t = lh__m2_fan_first(m, &f, a); t >= 0; t = lh__m2_fan_next(m, &f)) {
        const int i = lh__m2_vpos(m, t, a);
        for (int j = 1; j <= 2; j++) { /* edge a-x is opposite position k */
            const int k = (i + 3 - j) % 3;
            const lh_index e = m->sg[3 * (size_t)t + k], x = m->v[3 * (size_t)t + (i + j) % 3];
            if (e < 0 || m->sp[e] < 0) continue;
            const lh_index *Q = m->in_seg + 2 * (size_t)m->sp[e];
            if (lh__m2_orient(m, P[0], P[1], Q[0]) || lh__m2_orient(m, P[0], P[1], Q[1])) continue;
            if (x != b && !ahead_towards(pa, pb, lh__m2_pt(m, x))) continue;
            *w = x, *pos = k;
            return t;
        }
    }
    return -1;
}

/* With split_crossings, the rest a-b of input segment `parent` after a bend at a
 * rounded crossing vertex a no longer runs exactly through the input vertices on the
 * segment: the walk then meets subsegment s beside such a vertex e, and the crossing
 * of a-b with s, rounded, lands on e or where it cannot go — an error "crosses" for
 * segments that only touch (fuzz/README.md, finding 9). The input segment passes
 * exactly through e (orient_2 of its input endpoints, exact), so the chain goes to e:
 * returns the endpoint of s that lies on the input segment ahead of a (nearer b, and
 * not b), or -1. */
static lh_index vertex_on_parent_ahead(const lh__m2 *m, lh_index a, lh_index b, lh_index parent,
                                       lh_index s)
{
    if (!m->in_seg || parent < 0) return -1;
    const lh_index *P = m->in_seg + 2 * (size_t)parent;
    for (int j = 0; j < 2; j++) {
        const lh_index e = m->sv[2 * (size_t)s + j];
        if (e == a || e == b || e == P[0] || e == P[1] || lh__m2_orient(m, P[0], P[1], e)) continue;
        if (ahead_towards(lh__m2_pt(m, a), lh__m2_pt(m, b), lh__m2_pt(m, e))) return e;
    }
    return -1;
}

lh_status lh__m2_insert_segment(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b,
                                lh_index parent, lh__m2_problem *pb)
{
    while (a != b) {
        lh_index u, end;
        int pos;
        lh_index t = along_chain(m, a, b, parent, &u, &pos);
        if (t >= 0) {
            lh_status st = claim_edge(m, t, pos, a, u, parent);
            if (st != LH_OK) return st;
            a = u;
            continue;
        }
        t = start_wedge(m, a, b, &u, &pos);
        if (t < 0) return LH_ERR_INTERNAL;
        lh_status st;
        if (u >= 0) { /* an edge along the segment: a vertex on it, or b itself */
            if ((st = claim_edge(m, t, pos, a, u, parent)) != LH_OK) return st;
            a = u;
            continue;
        }
        st = walk(m, c, a, b, t, parent, &end, pb);
        if (st == LH_ERR_DEGENERATE && m->split_crossings && pb->kind == LH__M2_CROSSING) {
            /* the first crossing from a: a-x crosses nothing, x-b is what is left;
               x is the vertex of the crossed subsegment that the input segment runs
               through exactly, if any, else a new vertex at the crossing */
            lh_index x = vertex_on_parent_ahead(m, a, b, parent, pb->sub);
            if (x < 0 && (st = split_crossing(m, c, a, b, pb->sub, &x)) != LH_OK) return st;
            if (x < 0) return LH_ERR_DEGENERATE; /* pb still names the two segments */
            pb->kind = 0;
            if ((st = lh__m2_insert_segment(m, c, a, x, parent, pb)) != LH_OK) return st;
            a = x;
            continue;
        }
        if (st != LH_OK || (st = fill(m, c, a, end, parent)) != LH_OK) return st;
        a = end;
    }
    return LH_OK;
}
