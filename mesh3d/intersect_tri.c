/*
 * intersect_tri.c — whether two closed triangles of R^3 meet other than in what they
 * share (intersect.h), from exact orientation signs only.
 *
 * Non-coplanar triangles meet exactly when an edge of one meets the other: their
 * intersection is a segment of the planes' common line whose ends lie on edges
 * (Möller, "A fast triangle-triangle intersection test", JGT 2(2) 1997, and Guigue &
 * Devillers, "Fast and robust triangle-triangle overlap test using orientation
 * predicates", JGT 8(1) 2003, restated here with exact signs: no interval or
 * intersection point is ever computed). A closed segment pq meets a closed triangle
 * abc crossing its plane when orient_3(p, q, a, b), orient_3(p, q, b, c) and
 * orient_3(p, q, c, a) are not of mixed strict signs. Coplanar configurations are
 * decided by orient_2 in a coordinate projection along which the triangle does not
 * collapse (one-to-one on its plane), where closed triangles meet exactly when two
 * edges meet or a vertex of one lies in the other.
 *
 * Sharing a vertex v, the triangles meet elsewhere exactly when the far end of their
 * (convex) intersection beyond v lies on an edge of one: the edge opposite v of one
 * meets the other, or an edge at v of one lies in the other's plane and points into
 * its angle at v. Sharing an edge, they meet elsewhere exactly when they are
 * coplanar and on one side of it.
 */
#include "intersect.h"

#include "facets.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"

typedef const double *pt3;

/* orient_3, the inline filter first (lh_filter.gen.h), then the exact stages. */
static int o3(lh_pred *pr, pt3 a, pt3 b, pt3 c, pt3 d)
{
    const double *p[4] = {a, b, c, d};
    double det = 0, err = -1;
    int s;
    if (lh__orient_filter_3(p, &s, &det, &err)) return s;
    return lh__orient_unfiltered(pr, 3, p, det, err);
}

/* An axis along which triangle t projects with nonzero area (t non-degenerate). */
static int flat_axis(lh_pred *pr, const pt3 t[3])
{
    for (int k = 0; k < 2; k++)
        if (lh__orient2_along(pr, k, t[0], t[1], t[2])) return k;
    return 2;
}

/* c, known collinear with a and b in projection k, lies between them there. */
static int between(int k, pt3 a, pt3 b, pt3 c)
{
    for (int s = 1; s <= 2; s++) {
        const int i = (k + s) % 3;
        const double lo = a[i] < b[i] ? a[i] : b[i], hi = a[i] < b[i] ? b[i] : a[i];
        if (c[i] < lo || c[i] > hi) return 0;
    }
    return 1;
}

/* Closed segments ab and cd meet in projection k. */
static int seg_seg2(lh_pred *pr, int k, pt3 a, pt3 b, pt3 c, pt3 d)
{
    const int d1 = lh__orient2_along(pr, k, a, b, c), d2 = lh__orient2_along(pr, k, a, b, d);
    const int d3 = lh__orient2_along(pr, k, c, d, a), d4 = lh__orient2_along(pr, k, c, d, b);
    if (d1 * d2 < 0 && d3 * d4 < 0) return 1;
    return (!d1 && between(k, a, b, c)) || (!d2 && between(k, a, b, d)) ||
           (!d3 && between(k, c, d, a)) || (!d4 && between(k, c, d, b));
}

/* Point p lies in closed triangle t in projection k (t's area nonzero there). */
static int in_tri2(lh_pred *pr, int k, pt3 p, const pt3 t[3])
{
    const int s = lh__orient2_along(pr, k, t[0], t[1], t[2]);
    for (int i = 0; i < 3; i++)
        if (lh__orient2_along(pr, k, t[i], t[(i + 1) % 3], p) * s < 0) return 0;
    return 1;
}

/* Closed segment pq meets closed triangle t, all in t's plane (projection k). */
static int seg_tri2(lh_pred *pr, int k, pt3 p, pt3 q, const pt3 t[3])
{
    if (in_tri2(pr, k, p, t) || in_tri2(pr, k, q, t)) return 1;
    for (int i = 0; i < 3; i++)
        if (seg_seg2(pr, k, p, q, t[i], t[(i + 1) % 3])) return 1;
    return 0;
}

/* Closed segment pq meets closed triangle t. */
static int seg_tri(lh_pred *pr, pt3 p, pt3 q, const pt3 t[3])
{
    const int op = o3(pr, t[0], t[1], t[2], p), oq = o3(pr, t[0], t[1], t[2], q);
    if (op * oq > 0) return 0;
    if (!op && !oq) return seg_tri2(pr, flat_axis(pr, t), p, q, t);
    int pos = 0, neg = 0;
    for (int i = 0; i < 3; i++) {
        const int s = o3(pr, p, q, t[i], t[(i + 1) % 3]);
        pos |= s > 0, neg |= s < 0;
    }
    return !(pos && neg);
}

/* Closed coplanar triangles a and b meet (projection k, where both keep their area). */
static int tri_tri2(lh_pred *pr, int k, const pt3 a[3], const pt3 b[3])
{
    if (in_tri2(pr, k, a[0], b) || in_tri2(pr, k, b[0], a)) return 1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (seg_seg2(pr, k, a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return 1;
    return 0;
}

/* sg[i] = orient_3(t, p[i]) for i = from..2; returns 1 when they are all > 0 or all
 * < 0 (p's vertices from `from` on strictly on one side of t's plane). */
static int one_side(lh_pred *pr, const pt3 t[3], const pt3 p[3], int from, int sg[3])
{
    int pos = 0, neg = 0;
    for (int i = from; i < 3; i++) {
        sg[i] = o3(pr, t[0], t[1], t[2], p[i]);
        pos += sg[i] > 0, neg += sg[i] < 0;
    }
    return pos == 3 - from || neg == 3 - from;
}

static int disjoint_meet(lh_pred *pr, const pt3 a[3], const pt3 b[3])
{
    int sb[3], sa[3];
    if (one_side(pr, a, b, 0, sb)) return 0;
    if (!sb[0] && !sb[1] && !sb[2]) return tri_tri2(pr, flat_axis(pr, a), a, b);
    if (one_side(pr, b, a, 0, sa)) return 0;
    for (int i = 0; i < 3; i++)
        if (seg_tri(pr, a[i], a[(i + 1) % 3], b) || seg_tri(pr, b[i], b[(i + 1) % 3], a)) return 1;
    return 0;
}

/* The edge v-x (x in t's plane) points into t's closed angle at v = t[0], in
 * projection k where t keeps its area. */
static int ray_in_angle2(lh_pred *pr, int k, pt3 x, const pt3 t[3])
{
    const int s = lh__orient2_along(pr, k, t[0], t[1], t[2]);
    return lh__orient2_along(pr, k, t[0], t[1], x) * s >= 0 &&
           lh__orient2_along(pr, k, t[0], x, t[2]) * s >= 0;
}

/* As ray_in_angle2 for x in or off t's plane (orient_3 sign known: side). */
static int ray_in_angle(lh_pred *pr, int side, pt3 x, const pt3 t[3])
{
    return !side && ray_in_angle2(pr, flat_axis(pr, t), x, t);
}

/* Coplanar a and b sharing a = b[0]: all in projection k. Their intersection is
 * convex and holds the vertex, so it reaches beyond it exactly when their angles
 * there share a ray; two closed convex angles at one apex do exactly when a side
 * of one lies in the other (a side of their intersection is one of theirs). */
static int vertex_meet2(lh_pred *pr, int k, const pt3 a[3], const pt3 b[3])
{
    return ray_in_angle2(pr, k, a[1], b) || ray_in_angle2(pr, k, a[2], b) ||
           ray_in_angle2(pr, k, b[1], a) || ray_in_angle2(pr, k, b[2], a);
}

static int vertex_meet(lh_pred *pr, const pt3 a[3], const pt3 b[3])
{
    int sb[3], sa[3];
    if (one_side(pr, a, b, 1, sb)) return 0;
    if (!sb[1] && !sb[2]) return vertex_meet2(pr, flat_axis(pr, a), a, b);
    if (one_side(pr, b, a, 1, sa)) return 0;
    return seg_tri(pr, a[1], a[2], b) || seg_tri(pr, b[1], b[2], a) ||
           ray_in_angle(pr, sa[1], a[1], b) || ray_in_angle(pr, sa[2], a[2], b) ||
           ray_in_angle(pr, sb[1], b[1], a) || ray_in_angle(pr, sb[2], b[2], a);
}

/* On opposite sides of the edge in a projection where a keeps its area, a and b
 * meet only in it (coplanar or not): orient_3 only when they are on one side. */
static int edge_meet(lh_pred *pr, const pt3 a[3], const pt3 b[3])
{
    const int k = flat_axis(pr, a);
    if (lh__orient2_along(pr, k, a[0], a[1], a[2]) != lh__orient2_along(pr, k, a[0], a[1], b[2]))
        return 0;
    return !o3(pr, a[0], a[1], a[2], b[2]);
}

int lh__tri_tri_meet(lh_pred *pred, const double *const a[3], const double *const b[3], int shared)
{
    switch (shared) {
    case 0: return disjoint_meet(pred, a, b);
    case 1: return vertex_meet(pred, a, b);
    case 2: return edge_meet(pred, a, b);
    default: return 1;
    }
}
