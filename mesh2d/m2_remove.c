/*
 * m2_remove.c — deleting a free vertex from the constrained Delaunay triangulation.
 *
 * The triangles around p are replaced by the constrained Delaunay triangulation of
 * its link polygon, clipped one ear at a time: an ear (u, v, w) of three consecutive
 * link vertices is taken when it turns left and its circumcircle holds no other link
 * vertex strictly inside (nor one on its closed triangle), all decided exactly. In
 * the unconstrained case every triangle of the Delaunay triangulation of the link's
 * vertices restricted to the polygon passes that test, and a triangulated polygon has
 * an ear, so one is always found (Devillers 1999, "On deletion in Delaunay
 * triangulations", §2, orders the same ears by a power; any passing ear will do).
 * Each ear is Delaunay with respect to the link; the polygon's boundary edges stay
 * locally Delaunay (the outside apex sees the new one through the edge, inside the new
 * triangle). Subsegments on the link can hide a vertex behind them; when that leaves
 * no passing ear the removal is declined and nothing changes.
 *
 * Used by refinement (refine.c) for Chew's rule (L. P. Chew 1993, "Guaranteed-quality
 * mesh generation for curved surfaces", SoCG): before a subsegment is split because a
 * triangle's centre was rejected, the free vertices inside its diametral circle go.
 */
#include "m2.h"

#define LINK_MAX 64 /* links longer than this are declined (a free vertex has ~6) */

/* The link of p counterclockwise (link[i] -> link[i+1] is the edge opposite p in
 * fan[i]); 0 when p is on the boundary, on a subsegment, or its link is too long. */
static size_t link_of(const lh__m2 *m, lh_index p, lh_index *link, lh_index *fan)
{
    const lh_index t0 = m->vt[p];
    if (t0 < 0) return 0;
    size_t k = 0;
    lh_index t = t0;
    do {
        if (k == LINK_MAX) return 0;
        const int i = lh__m2_vpos(m, t, p);
        const size_t b = 3 * (size_t)t;
        if (m->sg[b + (i + 1) % 3] >= 0 || m->sg[b + (i + 2) % 3] >= 0) return 0;
        link[k] = m->v[b + (i + 1) % 3];
        fan[k++] = t;
        t = m->nb[b + (i + 1) % 3]; /* across v[i+2]-p: the next triangle counterclockwise */
        if (t < 0) return 0;
    } while (t != t0);
    for (size_t i = 0; i < k; i++) /* a vertex twice in the link: not a simple polygon */
        for (size_t j = i + 1; j < k; j++)
            if (link[i] == link[j]) return 0;
    return k;
}

/* Whether (a, b, c) is an ear the constrained Delaunay triangulation of the polygon
 * `link` (n vertices) may take: left turn, and no other link vertex strictly inside
 * its circumcircle or on its closed triangle. */
static int good_ear(const lh__m2 *m, const lh_index *link, size_t n, lh_index a, lh_index b, lh_index c)
{
    if (lh__m2_orient(m, a, b, c) <= 0) return 0;
    for (size_t j = 0; j < n; j++) {
        const lh_index w = link[j];
        if (w == a || w == b || w == c) continue;
        const double *pw = lh__m2_pt(m, w);
        const int s = lh__m2_incircle(m, a, b, c, pw);
        if (s < 0) return 0;
        if (s == 0 && lh__m2_orient_pt(m, a, b, pw) >= 0 && lh__m2_orient_pt(m, b, c, pw) >= 0 &&
            lh__m2_orient_pt(m, c, a, pw) >= 0)
            return 0;
    }
    return 1;
}

lh_status lh__m2_remove_vertex(lh__m2 *m, lh__m2_cavity *c, lh_index p, int *removed)
{
    lh_index link[LINK_MAX], fan[LINK_MAX];
    *removed = 0;
    size_t n = link_of(m, p, link, fan);
    if (n < 3) return LH_OK;
    lh__m2_cavity_clear(c);
    lh_status st;
    for (size_t i = 0; i < n; i++)
        if ((st = lh__m2_cavity_push_dead(m, c, fan[i])) != LH_OK) return st;
    while (n > 3) {
        size_t i = 0; /* the first passing ear from the start of the list: deterministic */
        while (i < n && !good_ear(m, link, n, link[(i + n - 1) % n], link[i], link[(i + 1) % n])) i++;
        if (i == n) return LH_OK; /* declined: the mesh is unchanged */
        if ((st = lh__m2_cavity_push_tri(m, c, link[(i + n - 1) % n], link[i], link[(i + 1) % n], NULL)) != LH_OK)
            return st;
        for (size_t j = i; j + 1 < n; j++) link[j] = link[j + 1];
        n--;
    }
    if (lh__m2_orient(m, link[0], link[1], link[2]) <= 0) return LH_OK;
    if ((st = lh__m2_cavity_push_tri(m, c, link[0], link[1], link[2], NULL)) != LH_OK) return st;
    if ((st = lh__m2_cavity_apply(m, c)) != LH_OK) return st;
    m->vt[p] = -1;
    m->pseg[p] = LH__M2_REMOVED;
    m->walk_hint = c->stack[0];
    *removed = 1;
    return LH_OK;
}

lh_status lh__m2_drop_removed(lh__m2 *m)
{
    size_t gone = 0;
    for (size_t p = m->n_input; p < m->np; p++) gone += m->pseg[p] == LH__M2_REMOVED;
    if (!gone) return LH_OK;
    lh_index *map = lh__alloc(&m->al, m->np * sizeof *map);
    if (!map) return LH_ERR_NOMEM;
    const size_t na = (size_t)m->attr_count;
    size_t q = m->n_input;
    for (size_t p = 0; p < m->n_input; p++) map[p] = (lh_index)p;
    for (size_t p = m->n_input; p < m->np; p++) {
        if (m->pseg[p] == LH__M2_REMOVED) {
            map[p] = -1;
            continue;
        }
        map[p] = (lh_index)q;
        m->xy[2 * q] = m->xy[2 * p], m->xy[2 * q + 1] = m->xy[2 * p + 1];
        m->pseg[q] = m->pseg[p], m->vt[q] = m->vt[p], m->pmark[q] = m->pmark[p];
        for (size_t j = 0; j < na; j++) m->attr[q * na + j] = m->attr[p * na + j];
        q++;
    }
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0)
            for (int k = 0; k < 3; k++) m->v[3 * t + k] = map[m->v[3 * t + k]];
    for (size_t s = 0; s < 2 * m->ns; s++) m->sv[s] = map[m->sv[s]];
    m->np = q;
    lh__free(&m->al, map);
    return LH_OK;
}
