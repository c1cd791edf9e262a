/*
 * check_facets.c — lh_tetmesh_check's facet test (check_plc.c says what (a) and (b)
 * are and why they suffice): subfaces assigned to facets (by face_parents, else by
 * exact coplanarity and containment), each facet's subfaces' area against its own,
 * and the border of its subfaces on its polygon edges.
 */
#include "check_plc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- facets ---------------------------------------------------------------------- */

static void face_proj(pchk *k, size_t s, int axis, double (*q)[2])
{
    for (int i = 0; i < 3; i++)
        lh__pchk_proj(lh__tchk_pt(k->c, k->c->faces[3 * s + i]), axis, q[i]);
}

/* Whether subface s lies in facet f: its points in f's plane, they and its
 * centroid in f's closed region. */
static int facet_has(pchk *k, size_t f, size_t s)
{
    const lh_index *pl = k->plane + 3 * f, *v = k->c->faces + 3 * s;
    if (pl[0] < 0 || !k->planar[f]) return 0;
    for (int i = 0; i < 3; i++)
        if (lh__pchk_orient3i(k, pl[0], pl[1], pl[2], v[i]) != 0) return 0;
    double q[3][2];
    face_proj(k, s, k->axis[f], q);
    for (int i = 0; i < 3; i++)
        if (!lh__pchk_in_facet(k, f, (const double(*)[2])q + i, 1)) return 0;
    return lh__pchk_in_facet(k, f, (const double(*)[2])q, 3);
}

/* Subfaces to facets by containment: first the facets at their PLC points, then all. */
static lh_status assign_parents(pchk *k)
{
    const lh_plc *g = k->g;
    const size_t nv = g->facet_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    size_t *first = lh__alloc(&k->c->al, (g->n + 2) * sizeof *first);
    lh_index *inc = lh__alloc(&k->c->al, (nv + 1) * sizeof *inc);
    if (!first || !inc) {
        lh__free(&k->c->al, first), lh__free(&k->c->al, inc);
        return LH_ERR_NOMEM;
    }
    memset(first, 0, (g->n + 2) * sizeof *first);
    for (size_t f = 0; f < g->facet_count; f++)
        for (size_t p = (size_t)g->facet_first[f]; p < (size_t)g->facet_first[f + 1]; p++)
            for (size_t i = 0; i < lh__pchk_poly_len(g, p); i++)
                first[lh__pchk_poly_v(g, p)[i] + 2]++;
    for (size_t v = 0; v < g->n; v++) first[v + 2] += first[v + 1];
    for (size_t f = 0; f < g->facet_count; f++)
        for (size_t p = (size_t)g->facet_first[f]; p < (size_t)g->facet_first[f + 1]; p++)
            for (size_t i = 0; i < lh__pchk_poly_len(g, p); i++)
                inc[first[lh__pchk_poly_v(g, p)[i] + 1]++] = (lh_index)f;
    for (size_t s = 0; s < k->c->nf; s++) {
        k->par[s] = -1;
        for (int i = 0; i < 3 && k->par[s] < 0; i++) {
            const lh_index v = k->c->faces[3 * s + i];
            for (size_t j = (size_t)v < g->n ? first[v] : 0;
                 (size_t)v < g->n && j < first[v + 1] && k->par[s] < 0; j++)
                if (facet_has(k, (size_t)inc[j], s)) k->par[s] = inc[j];
        }
        for (size_t f = 0; k->par[s] < 0 && f < g->facet_count; f++)
            if (facet_has(k, f, s)) k->par[s] = (lh_index)f;
    }
    lh__free(&k->c->al, first);
    lh__free(&k->c->al, inc);
    return LH_OK;
}

static void group_by_facet(pchk *k)
{
    const size_t nfac = k->g->facet_count;
    memset(k->ffirst, 0, (nfac + 2) * sizeof *k->ffirst);
    for (size_t s = 0; s < k->c->nf; s++)
        if (k->par[s] >= 0) k->ffirst[k->par[s] + 2]++;
    for (size_t f = 0; f < nfac; f++) k->ffirst[f + 2] += k->ffirst[f + 1];
    for (size_t s = 0; s < k->c->nf; s++)
        if (k->par[s] >= 0) k->flist[k->ffirst[k->par[s] + 1]++] = (lh_index)s;
}

static lh_status not_covered(pchk *k, size_t f, const char *why, size_t s)
{
    const lh_index *v = k->c->faces + 3 * s;
    return lh__error_say(k->c->err, LH_ERR_INVALID_MESH,
                         "facet %zu is not covered: %s (subface %zu (%lld %lld %lld))", f, why, s,
                         (long long)v[0], (long long)v[1], (long long)v[2]);
}

/* (a): the subfaces' |area| minus the facet's, exactly; off-plane points. */
static lh_status facet_area(pchk *k, size_t f)
{
    const lh_index *pl = k->plane + 3 * f, *list = k->flist + k->ffirst[f];
    const size_t cnt = k->ffirst[f + 1] - k->ffirst[f];
    const int axis = k->axis[f];
    /* No subface at all: the facet lies outside the mesh (between a hole and the
       outside, as TetGen's example.poly's windows), which a facet may. */
    if (cnt == 0) return LH_OK;
    int rounded = 0; /* a subface has a point off its line or plane up to rounding */
    for (size_t i = 0; i < cnt; i++) {
        const size_t s = (size_t)list[i];
        for (int j = 0; j < 3; j++) rounded |= k->c->off[k->c->faces[3 * s + j]] != 0;
        for (int j = 0; k->planar[f] && j < 3; j++) {
            const lh_index v = k->c->faces[3 * s + j];
            if (lh__pchk_orient3i(k, pl[0], pl[1], pl[2], v) == 0) continue;
            if ((size_t)v < k->g->n) return not_covered(k, f, "an input point off its plane", s);
            if (!lh__pchk_near_plane(lh__tchk_pt(k->c, pl[0]), lh__tchk_pt(k->c, pl[1]),
                                     lh__tchk_pt(k->c, pl[2]), lh__tchk_pt(k->c, v)))
                return not_covered(k, f, "a Steiner point off its plane beyond rounding", s);
            lh__pchk_mark_off(k, v);
            rounded = 1;
        }
        double q[3][2];
        face_proj(k, s, axis, q);
        const double *p[3] = {q[0], q[1], q[2]};
        if (lh_orient(k->c->pr, 2, p) == 0)
            return not_covered(k, f, "a subface without area in its plane", s);
    }
    if (rounded) return LH_OK; /* (b) only: rounding moved the area */
    for (size_t i = 0; i < cnt; i++) {
        double q[3][2];
        face_proj(k, (size_t)list[i], axis, q);
        const double *p[3] = {q[0], q[1], q[2]};
        lh__detsum_add(k->c->pr, k->sum, p, lh_orient(k->c->pr, 2, p) < 0);
    }
    const lh_plc *g = k->g;
    for (size_t pg = (size_t)g->facet_first[f]; pg < (size_t)g->facet_first[f + 1]; pg++) {
        if (k->eps[pg] == 0) continue;
        const size_t len = lh__pchk_poly_len(g, pg);
        double q[3][2];
        const double *p[3] = {q[0], q[1], q[2]};
        int sign = 0;
        for (int pass = 0; pass < 3; pass++) {
            for (size_t i = 1; i + 1 < len; i++) {
                lh__pchk_proj(lh__tchk_pt(k->c, lh__pchk_poly_v(g, pg)[0]), axis, q[0]);
                lh__pchk_proj(lh__tchk_pt(k->c, lh__pchk_poly_v(g, pg)[i]), axis, q[1]);
                lh__pchk_proj(lh__tchk_pt(k->c, lh__pchk_poly_v(g, pg)[i + 1]), axis, q[2]);
                if (pass < 2)
                    lh__detsum_add(k->c->pr, k->s2, p, pass == 1);
                else
                    lh__detsum_add(k->c->pr, k->sum, p, k->eps[pg] * sign > 0);
            }
            if (pass == 0) sign = lh__detsum_sign(k->s2);
        }
    }
    const int d = lh__detsum_sign(k->sum);
    if (d != 0)
        return lh__error_say(k->c->err, LH_ERR_INVALID_MESH,
                             "facet %zu is not covered: its %zu subfaces' area is %s than the "
                             "facet's",
                             f, cnt, d > 0 ? "larger" : "smaller");
    return LH_OK;
}

/* The polygon edges (3 vertices or more) of facet f, sorted, into k->re. */
static size_t ring_edges(pchk *k, size_t f)
{
    const lh_plc *g = k->g;
    size_t m = 0;
    for (size_t p = (size_t)g->facet_first[f]; p < (size_t)g->facet_first[f + 1]; p++)
        for (size_t i = 0, len = lh__pchk_poly_len(g, p); len >= 3 && i < len; i++) {
            const lh_index a = lh__pchk_poly_v(g, p)[i], b = lh__pchk_poly_v(g, p)[(i + 1) % len];
            k->re[m++] = (prec){a < b ? a : b, a < b ? b : a, 0};
        }
    qsort(k->re, m, sizeof *k->re, lh__pchk_prec_cmp);
    return m;
}

static int same_seg(const pchk *k, lh_index s, lh_index u, lh_index v)
{
    const lh_index a = k->seg[2 * s], b = k->seg[2 * s + 1];
    return (a == u && b == v) || (a == v && b == u);
}

/* Whether point p lies on polygon edge u v: an endpoint, exactly on the open
 * segment, or a Steiner point that the chain of segment u v passes. */
static int on_edge(pchk *k, lh_index u, lh_index v, lh_index p)
{
    if (p == u || p == v) return 1;
    const double *pu = lh__tchk_pt(k->c, u), *pv = lh__tchk_pt(k->c, v), *x = lh__tchk_pt(k->c, p);
    int axis = 0;
    for (int i = 1; i < 3; i++)
        if (fabs(pv[i] - pu[i]) > fabs(pv[axis] - pu[axis])) axis = i;
    if (lh__pchk_strictly_between(pu[axis], x[axis], pv[axis]) && lh__pchk_collinear(k, pu, pv, x))
        return 1;
    return (size_t)p >= k->g->n && k->pt_seg[p] >= 0 && same_seg(k, k->pt_seg[p], u, v);
}

/* Whether subsegment a b lies on a polygon edge of the facet (k->re, nre sorted):
 * first the segment whose chain took it, then every polygon edge. */
static int on_polygon_edge(pchk *k, size_t nre, lh_index a, lh_index b)
{
    const hrec key = {a, b, 0};
    const hrec *h = bsearch(&key, k->h, 2 * k->c->ne, sizeof *k->h, lh__pchk_hrec_cmp);
    if (!h) return 0;
    const lh_index s = k->seg_of[h->sub];
    if (s >= 0) {
        const lh_index u = k->seg[2 * s], v = k->seg[2 * s + 1];
        const prec rk = {u < v ? u : v, u < v ? v : u, 0};
        if (bsearch(&rk, k->re, nre, sizeof *k->re, lh__pchk_prec_cmp)) return 1;
    }
    for (size_t i = 0; i < nre; i++)
        if (on_edge(k, k->re[i].a, k->re[i].b, a) && on_edge(k, k->re[i].a, k->re[i].b, b))
            return 1;
    return 0;
}

/* (b): every edge in one subface of f lies on a polygon edge of f. */
static lh_status facet_edges(pchk *k, size_t f)
{
    const lh_index *list = k->flist + k->ffirst[f];
    const size_t cnt = k->ffirst[f + 1] - k->ffirst[f], nre = ring_edges(k, f);
    for (size_t i = 0; i < cnt; i++)
        for (int j = 0; j < 3; j++) {
            const lh_index *v = k->c->faces + 3 * (size_t)list[i];
            const lh_index a = v[j], b = v[(j + 1) % 3];
            k->pe[3 * i + j] = (prec){a < b ? a : b, a < b ? b : a, list[i]};
        }
    qsort(k->pe, 3 * cnt, sizeof *k->pe, lh__pchk_prec_cmp);
    for (size_t i = 0; i < 3 * cnt;) {
        size_t j = i + 1;
        while (j < 3 * cnt && k->pe[j].a == k->pe[i].a && k->pe[j].b == k->pe[i].b) j++;
        const prec *e = k->pe + i;
        if (j - i > 2)
            return lh__error_say(k->c->err, LH_ERR_INVALID_MESH,
                                 "facet %zu: edge (%lld %lld) is in %zu of its subfaces", f,
                                 (long long)e->a, (long long)e->b, j - i);
        if (j - i == 1 && !on_polygon_edge(k, nre, e->a, e->b))
            return not_covered(k, f,
                               "an edge on the subfaces' border lies on no polygon edge "
                               "of the facet",
                               (size_t)e->pos);
        i = j;
    }
    return LH_OK;
}

lh_status lh__pchk_check_facets(pchk *k)
{
    lh__pchk_prepare_facets(k);
    lh_status st = LH_OK;
    if (k->c->parents)
        memcpy(k->par, k->c->parents, k->c->nf * sizeof *k->par);
    else
        st = assign_parents(k);
    if (st) return st;
    group_by_facet(k);
    for (size_t f = 0; f < k->g->facet_count; f++) {
        if (k->plane[3 * f] < 0) {
            if (k->ffirst[f + 1] > k->ffirst[f])
                return not_covered(k, f, "the facet has no area but has subfaces",
                                   (size_t)k->flist[k->ffirst[f]]);
            continue;
        }
        if ((st = facet_area(k, f)) || (st = facet_edges(k, f))) return st;
    }
    return LH_OK;
}
