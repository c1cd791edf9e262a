/*
 * refine_points.c — where Delaunay refinement (refine.c) puts and removes points: a
 * subsegment's split point (its midpoint, or concentric shells about an acute input
 * corner: Ruppert 1995 §5, Shewchuk 2002 §6), a new point's marker and attributes,
 * and Chew's rule (Chew 1993): the free points inside a subsegment's diametral circle
 * removed before it is split. Distances are compared on vectors scaled by a power of
 * two (m2_geom.h).
 */
#include <math.h>
#include <string.h>

#include "m2.h"
#include "m2_geom.h"
#include "refine_rf.h"

/* Whether point x lies strictly within the circle around o of radius rm * 2^re. */
static int in_disc(const double *x, const double *o, double rm, long re)
{
    double v[2];
    const int e = lh__g_vec(o, x, v);
    return lh__g_cmp(lh__g_len(v[0], v[1]), e, rm, re) < 0;
}

/* Whether segment x-y passes strictly within that circle: its nearest point to o is
 * closer than the radius (x, y taken relative to o in one scaled frame). */
static int edge_meets_disc(const double *x, const double *y, const double *o, double rm, long re)
{
    const double *q[2] = {x, y};
    double v[2][2];
    const int e = lh__g_vecs(o, q, 2, v);
    const double dx = v[1][0] - v[0][0], dy = v[1][1] - v[0][1], l2 = dx * dx + dy * dy;
    double f = l2 > 0 ? -(v[0][0] * dx + v[0][1] * dy) / l2 : 0;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    return lh__g_cmp(lh__g_len(v[0][0] + f * dx, v[0][1] + f * dy), e, rm, re) < 0;
}

/* Whether another subsegment leaves vertex o at an angle with the direction to x whose
 * cosine exceeds cmin (0: an acute corner, where splits keep to concentric shells;
 * 1/2: below 60 degrees, a segment cluster's apex); subsegments of input segment
 * `parent` itself do not count. */
static int corner_below(const lh__m2 *m, lh_index o, lh_index x, lh_index parent, double cmin)
{
    const double *po = lh__m2_pt(m, o), *px = lh__m2_pt(m, x);
    lh__m2_fan f;
    for (lh_index t = lh__m2_fan_first(m, &f, o); t >= 0; t = lh__m2_fan_next(m, &f)) {
        const int i = lh__m2_vpos(m, t, o);
        for (int j = 1; j <= 2; j++) { /* the two edges of t at o */
            const lh_index y = m->v[3 * (size_t)t + (i + j) % 3];
            const lh_index e = m->sg[3 * (size_t)t + (i + 3 - j) % 3];
            if (y == x || e < 0 || (parent >= 0 && m->sp[e] == parent)) continue;
            if (lh__g_cos(po, px, lh__m2_pt(m, y)) > cmin) return 1;
        }
    }
    return 0;
}

/* Where to split subsegment a-b: its midpoint, or, when exactly one end is an input
 * vertex at an acute corner, at the power of two nearest half its length from that
 * vertex (concentric shells, Ruppert 1995 §5; Shewchuk 2002 §6): splits near a small
 * input angle then meet at equal distances from its apex. */
void lh__rf_split_point(const rf *r, lh_index s, double *p)
{
    const lh__m2 *m = r->m;
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    const int ia = (size_t)a < m->n_input && corner_below(m, a, b, m->sp[s], 0);
    const int ib = (size_t)b < m->n_input && corner_below(m, b, a, m->sp[s], 0);
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    double f = 0.5;
    if (ia != ib) { /* on the scaled length: the power of two scales with it */
        double v[2];
        lh__g_vec(pa, pb, v);
        const double len = lh__g_len(v[0], v[1]);
        const double d = ldexp(1.0, (int)floor(log2(len / 2) + 0.5)); /* nearest power of 2 */
        f = ia ? d / len : 1 - d / len;
    }
    lh__g_along(pa, pb, f, p);
}

void lh__rf_point_data(rf *r, lh_index pi, lh_index s, const double *w, const lh_index *from)
{
    lh__m2 *m = r->m;
    const int na = m->attr_count;
    if (s >= 0) {
        const lh_index parent = m->sp[s];
        m->pmark[pi] = parent >= 0 && m->seg_marker ? m->seg_marker[parent] : 1;
    }
    for (int j = 0; j < na; j++) {
        double x = 0;
        for (int k = 0; k < 3 && from[k] >= 0; k++) x += w[k] * m->attr[(size_t)from[k] * na + j];
        m->attr[(size_t)pi * na + j] = x;
    }
}

/* The free vertices strictly inside the circle around o of radius rm * 2^re, about
 * subsegment s, in r->gone: a flood from s's sides across unconstrained edges that
 * pass within it. */
static lh_status free_vertices_in_circle(rf *r, lh_index s, const double *o, double rm, long re)
{
    lh__m2 *m = r->m;
    lh__m2_cavity *c = r->c;
    int pos;
    const lh_index t = lh__m2_find_subseg(m, s, &pos);
    r->gone_count = c->stack_count = 0;
    if (t < 0) return LH_OK;
    const uint32_t e = lh__m2_new_epoch(m);
    const lh_index start[2] = {t, m->nb[3 * (size_t)t + pos]};
    lh_status st;
    for (int j = 0; j < 2; j++) {
        if (start[j] < 0) continue;
        m->mark[start[j]] = e;
        if ((st = lh__m2_stack_push(m, c, start[j])) != LH_OK) return st;
    }
    for (size_t i = 0; i < c->stack_count; i++) {
        const size_t u = (size_t)c->stack[i];
        for (int k = 0; k < 3; k++) {
            const lh_index x = m->v[3 * u + k], n = m->nb[3 * u + k];
            if ((size_t)x >= m->n_input && m->pseg[x] == -1 && in_disc(lh__m2_pt(m, x), o, rm, re)) {
                size_t g = 0;
                while (g < r->gone_count && r->gone[g] != x) g++;
                if (g == r->gone_count &&
                    !lh__m2_grow(m, (void **)&r->gone, r->gone_count, &r->gone_cap, g + 1, sizeof(lh_index)))
                    return LH_ERR_NOMEM;
                if (g == r->gone_count) r->gone[r->gone_count++] = x;
            }
            if (n < 0 || m->mark[n] == e || m->sg[3 * u + k] >= 0 ||
                !edge_meets_disc(lh__m2_pt(m, m->v[3 * u + (k + 1) % 3]), lh__m2_pt(m, m->v[3 * u + (k + 2) % 3]), o, rm, re))
                continue;
            m->mark[n] = e;
            if ((st = lh__m2_stack_push(m, c, n)) != LH_OK) return st;
        }
    }
    return LH_OK;
}

/* Chew's rule (Chew 1993; Triangle runs it too): the free vertices strictly inside
 * the diametral circle of subsegment s, about to be split because a triangle's centre
 * was rejected, are removed first (m2_remove.c), and the triangles that replace them
 * queued like an insertion's; a vertex whose removal is declined stays. Fewer points
 * then crowd the segment (docs/meshing.md). */
lh_status lh__rf_remove_free(rf *r, lh_index s)
{
    lh__m2 *m = r->m;
    const double *a = lh__m2_pt(m, m->sv[2 * (size_t)s]), *b = lh__m2_pt(m, m->sv[2 * (size_t)s + 1]);
    double o[2], d[2];
    lh__g_along(a, b, 0.5, o);
    const int e = lh__g_vec(a, b, d);
    lh_status st = free_vertices_in_circle(r, s, o, lh__g_len(d[0], d[1]) / 2, e);
    for (size_t g = 0; g < r->gone_count && st == LH_OK; g++) {
        int removed;
        st = lh__m2_remove_vertex(m, r->c, r->gone[g], &removed);
        if (st != LH_OK || !removed) continue;
        r->o->out->steiner_removed++;
        st = lh__rf_after_insert(r);
    }
    return st;
}
