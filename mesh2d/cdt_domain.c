/*
 * cdt_domain.c — which triangles of the constrained Delaunay triangulation are the
 * domain, and their regions. Triangle's rule (Shewchuk 1996, "Triangle: engineering
 * a 2D quality mesh generator", §3): a flood from every hull edge that is not a
 * segment, and from the triangle holding each hole seed, across edges that are not
 * subsegments, removes what it reaches (-c: no flood from the hull). Or the even-odd
 * rule for polygon rings: crossing a subsegment lain along by an odd number of input
 * segments changes sides; the triangles on the odd side stay. Regions flood the same
 * way from their seeds, later seeds overriding earlier ones, as in Triangle.
 * With an existing mesh to refine (lh_pslg.cover), its triangles are the domain
 * (cdt_cover.c) and only the holes' floods carve. Afterwards every boundary edge is a
 * subsegment (hull edges kept by -c become
 * subsegments of no input segment), which is what refinement relies on.
 */
#include <string.h>

#include "refine.h"

/* Floods from the triangles on the stack across non-subsegment edges, marking them
 * with epoch e. */
static lh_status flood(lh__m2 *m, lh__m2_cavity *c, uint32_t e)
{
    while (c->stack_count) {
        const size_t t = (size_t)c->stack[--c->stack_count];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k];
            if (n < 0 || m->sg[3 * t + k] >= 0 || m->mark[n] == e) continue;
            m->mark[n] = e;
            lh_status st = lh__m2_stack_push(m, c, n);
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

static lh_status seed(lh__m2 *m, lh__m2_cavity *c, lh_index t, uint32_t e)
{
    if (m->mark[t] == e) return LH_OK;
    m->mark[t] = e;
    return lh__m2_stack_push(m, c, t);
}

/* The live triangle holding p (closed), or -1 outside the mesh. */
static lh_index find(lh__m2 *m, const double *p)
{
    lh_index blocked;
    return lh__m2_locate(m, -1, p, 0, &blocked);
}

/* The subsegment ending at vertex a, found in the fan of triangles around a from
 * triangle t (which has a as a vertex): of an input segment, the least segment number;
 * else (boundary edges of a mesh to refine) the least subsegment id; -1 when none.
 * The fan is a's neighbourhood: O(degree of a), and the same answer for every t. */
static lh_index subseg_at_vertex(const lh__m2 *m, lh_index t, lh_index a)
{
    lh_index best = -1;
    lh__m2_fan f = {a, t, t, 0};
    for (lh_index u = t; u >= 0; u = lh__m2_fan_next(m, &f)) {
        const int i = lh__m2_vpos(m, u, a);
        for (int j = 1; j < 3; j++) { /* the two edges of u at a */
            const lh_index s = m->sg[3 * (size_t)u + (i + j) % 3];
            if (s < 0) continue;
            const int input = m->sp[s] >= 0, best_input = best >= 0 && m->sp[best] >= 0;
            if (best < 0 || (input && !best_input) ||
                (input == best_input && (input ? m->sp[s] < m->sp[best] : s < best)))
                best = s;
        }
    }
    return best;
}

lh_index lh__m2_subseg_at(lh__m2 *m, const double *p)
{
    const lh_index t = find(m, p);
    if (t < 0) return -1;
    const lh_index *v = m->v + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
        const double *q = lh__m2_pt(m, v[k]);
        if (q[0] == p[0] && q[1] == p[1]) return subseg_at_vertex(m, t, v[k]);
    }
    for (int k = 0; k < 3; k++) /* p in the closed triangle t: on edge k when collinear */
        if (m->sg[3 * (size_t)t + k] >= 0 && lh__m2_orient_pt(m, v[(k + 1) % 3], v[(k + 2) % 3], p) == 0)
            return m->sg[3 * (size_t)t + k];
    return -1;
}

/* Marks with epoch e what Triangle's rule removes; *ignored counts useless seeds. */
static lh_status infect(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, int convex_hull,
                        uint32_t e, size_t *ignored)
{
    c->stack_count = 0;
    lh_status st;
    for (size_t t = 0; t < m->nt && !convex_hull; t++) {
        if (m->v[3 * t] < 0) continue;
        for (int k = 0; k < 3; k++)
            if (m->nb[3 * t + k] < 0 && m->sg[3 * t + k] < 0 &&
                (st = seed(m, c, (lh_index)t, e)) != LH_OK)
                return st;
    }
    if ((st = flood(m, c, e)) != LH_OK) return st;
    for (size_t h = 0; h < g->hole_count; h++) {
        const lh_index t = find(m, g->holes + 2 * h);
        if (t < 0 || m->mark[t] == e) {
            ++*ignored;
            continue;
        }
        if ((st = seed(m, c, t, e)) != LH_OK || (st = flood(m, c, e)) != LH_OK) return st;
    }
    return LH_OK;
}

/* Marks with epoch e the triangles on the even side (outside) by a parity flood. */
static lh_status even_odd(lh__m2 *m, lh__m2_cavity *c, uint32_t e)
{
    /* two epochs: e for "outside", e + 1 for "inside"; a triangle is marked once */
    const uint32_t in = lh__m2_new_epoch(m);
    c->stack_count = 0;
    lh_status st;
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0 || m->mark[t] == e || m->mark[t] == in) continue;
        int k = 0;
        while (k < 3 && m->nb[3 * t + k] >= 0) k++;
        if (k == 3) continue;
        const lh_index s = m->sg[3 * t + k];
        m->mark[t] = s >= 0 && (m->smul[s] & 1) ? in : e;
        if ((st = lh__m2_stack_push(m, c, (lh_index)t)) != LH_OK) return st;
        while (c->stack_count) {
            const size_t u = (size_t)c->stack[--c->stack_count];
            for (int j = 0; j < 3; j++) {
                const lh_index n = m->nb[3 * u + j], sj = m->sg[3 * u + j];
                if (n < 0 || m->mark[n] == e || m->mark[n] == in) continue;
                const int flip = sj >= 0 && (m->smul[sj] & 1);
                m->mark[n] = (m->mark[u] == in) != flip ? in : e;
                if ((st = lh__m2_stack_push(m, c, n)) != LH_OK) return st;
            }
        }
    }
    return LH_OK;
}

/* Removes the triangles marked e; the survivors' links to them become -1. */
static void carve(lh__m2 *m, uint32_t e)
{
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0 || m->mark[t] == e) continue;
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k];
            if (n >= 0 && m->mark[n] == e) m->nb[3 * t + k] = -1;
        }
    }
    const size_t live = m->live;
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0 && m->mark[t] == e) lh__m2_kill_tri(m, (lh_index)t);
    if (m->live == live) return; /* nothing removed: every vt still names a live triangle */
    for (size_t p = 0; p < m->np; p++) m->vt[p] = -1;
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0)
            for (int k = 0; k < 3; k++) m->vt[m->v[3 * t + k]] = (lh_index)t;
}

/* Every boundary edge left without a subsegment (a hull edge kept by -c) gets one. */
static lh_status seal(lh__m2 *m)
{
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0) continue;
        for (int k = 0; k < 3; k++) {
            if (m->nb[3 * t + k] >= 0 || m->sg[3 * t + k] >= 0) continue;
            lh_index s;
            lh_status st = lh__m2_add_subseg(m, m->v[3 * t + (k + 1) % 3], m->v[3 * t + (k + 2) % 3], -1, &s);
            if (st != LH_OK) return st;
            m->sg[3 * t + k] = s;
        }
    }
    return LH_OK;
}

/* Regional attributes and area bounds by flood from each region's seed (none, and
 * m->tattr, m->tarea NULL, without regions or an old mesh's area bounds). */
static lh_status regions(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, size_t *ignored)
{
    if (!g->region_count && !g->cover_area) return LH_OK; /* no per-triangle data */
    m->tattr = lh__alloc(&m->al, (m->cap_t ? m->cap_t : 1) * sizeof(double));
    m->tarea = lh__alloc(&m->al, (m->cap_t ? m->cap_t : 1) * sizeof(double));
    if (!m->tattr || !m->tarea) return LH_ERR_NOMEM;
    for (size_t t = 0; t < m->nt; t++) m->tattr[t] = 0, m->tarea[t] = -1;
    for (size_t r = 0; r < g->region_count; r++) {
        const double *q = g->regions + 4 * r;
        const lh_index t = find(m, q);
        if (t < 0) {
            ++*ignored;
            continue;
        }
        const uint32_t e = lh__m2_new_epoch(m);
        c->stack_count = 0;
        lh_status st = seed(m, c, t, e);
        if (st == LH_OK) st = flood(m, c, e);
        if (st != LH_OK) return st;
        for (size_t u = 0; u < m->nt; u++)
            if (m->v[3 * u] >= 0 && m->mark[u] == e) m->tattr[u] = q[2], m->tarea[u] = q[3];
    }
    return LH_OK;
}

lh_status lh__m2_domain(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, int convex_hull,
                        size_t *holes_ignored, size_t *regions_ignored)
{
    lh__cover *cv = m->cover;
    const uint32_t e = lh__m2_new_epoch(m);
    lh_status st;
    if (cv) /* the old mesh is the domain; holes are still carved */
        st = lh__cover_outside(m, c, cv, e);
    else
        st = g->even_odd ? even_odd(m, c, e) : LH_OK;
    if (st == LH_OK && !g->even_odd) st = infect(m, c, g, convex_hull || cv, e, holes_ignored);
    if (st != LH_OK) return st;
    carve(m, e);
    if (m->live == 0) return LH_ERR_DEGENERATE;
    if ((st = seal(m)) != LH_OK || (st = regions(m, c, g, regions_ignored)) != LH_OK) return st;
    return cv && g->cover_area ? lh__cover_areas(m, cv, g->cover_area) : LH_OK;
}
