/*
 * recover_inside.c — Steiner points off the boundary (-Y, TetGen's "no Steiner point
 * on the boundary"): where splitting would put a point x on a subsegment or inside a
 * facet, a point strictly inside the tet of the mesh holding x goes in instead: its
 * centroid, else a point on the way from it to x. The constraint stays whole; the
 * next round's Delaunay tetrahedralization holds the new point, and flips try again
 * around it (Si 2015, sec. 3.2, puts such points where flips get stuck too; its
 * placement is not this one's).
 *
 * The tet is the first holding x in an order of coordinates, so that the point does
 * not depend on the input's order where x lies on a face, an edge or a vertex.
 * Exact where it matters: the point is kept only when orient_3 says it is strictly
 * inside the tet and it lies on no facet triangle and no segment (its rounding could
 * have put it on one: axis-aligned models have many such coordinates), else the next
 * weighting is tried.
 */
#include "facets.h"
#include "recover.h"

#include <math.h>

static const double *pt(const t3_ctx *c, lh_index p)
{
    return c->xyz + 3 * (size_t)p;
}

static int cmp3(const double *p, const double *q)
{
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* Whether q is in the box of the k points v (boundary included). */
static int in_box(const t3_ctx *c, const lh_index *v, int k, const double *q)
{
    for (int a = 0; a < 3; a++) {
        double lo = pt(c, v[0])[a], hi = lo;
        for (int i = 1; i < k; i++) lo = fmin(lo, pt(c, v[i])[a]), hi = fmax(hi, pt(c, v[i])[a]);
        if (q[a] < lo || q[a] > hi) return 0;
    }
    return 1;
}

/* Exact: q lies in the closed triangle f (q in its plane). */
static int in_triangle(t3_ctx *c, const lh_index *f, const double *q)
{
    const double *a = pt(c, f[0]), *b = pt(c, f[1]), *d = pt(c, f[2]);
    int k = 0; /* a projection in which the triangle keeps its area */
    while (k < 2 && !lh__orient2_along(c->pred, k, a, b, d)) k++;
    const int s = lh__orient2_along(c->pred, k, a, b, d);
    return lh__orient2_along(c->pred, k, a, b, q) * s >= 0 &&
           lh__orient2_along(c->pred, k, b, d, q) * s >= 0 &&
           lh__orient2_along(c->pred, k, d, a, q) * s >= 0;
}

/* Whether q lies on a facet triangle or a segment. */
static int on_constraint(t3_ctx *c, const double *q)
{
    for (size_t t = 0; t < c->tri_count; t++) {
        const lh_index *f = c->tri + 3 * t;
        if (!in_box(c, f, 3, q)) continue;
        const double *p[4] = {pt(c, f[0]), pt(c, f[1]), pt(c, f[2]), q};
        if (lh_orient(c->pred, 3, p) == 0 && in_triangle(c, f, q)) return 1;
    }
    for (size_t s = 0; s < c->seg_count; s++) {
        const lh_index e[2] = {c->seg[s].a, c->seg[s].b};
        if (in_box(c, e, 2, q) && lh__t3_collinear(c->pred, pt(c, e[0]), pt(c, e[1]), q)) return 1;
    }
    return 0;
}

/* The largest coordinate difference between two corners of tet t. */
static double tet_size(const t3_ctx *c, lh_index t)
{
    double m = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            for (int a = 0; a < 3; a++)
                m = fmax(m, fabs(pt(c, c->tv[4 * (size_t)t + i])[a] -
                                 pt(c, c->tv[4 * (size_t)t + j])[a]));
    return m;
}

/* Points go only into tets larger than 2^-T3_INSIDE_BITS of the input's coordinate
 * bound: where points placed so far have not let flips recover a constraint, more of
 * them crowding toward it would not either. */
#define T3_INSIDE_BITS 24

/* Weights of x and of the tet's centroid, tried in turn: the centroid first, which
 * lets flips recover more (eight.off, part.off, mpi.off) than points nearer x. */
static const double weights[][2] = {{0, 1}, {0.25, 0.75}, {0.5, 0.5}};

/* The centroid of tet t, a quarter at a time (no overflow), into g. */
static void centroid(const t3_ctx *c, lh_index t, double g[3])
{
    for (int a = 0; a < 3; a++) {
        g[a] = 0;
        for (int k = 0; k < 4; k++) g[a] += pt(c, c->tv[4 * (size_t)t + k])[a] / 4;
    }
}

/* Whether tet t comes before tet u: their corners, sorted by coordinates, compared
 * so (the order does not depend on how points or tets are numbered). */
static int tet_before(const t3_ctx *c, lh_index t, lh_index u)
{
    const double *k[2][4];
    for (int s = 0; s < 2; s++) {
        for (int i = 0; i < 4; i++) k[s][i] = pt(c, c->tv[4 * (size_t)(s ? u : t) + i]);
        for (int i = 1; i < 4; i++) /* insertion sort */
            for (int j = i; j > 0 && cmp3(k[s][j], k[s][j - 1]) < 0; j--) {
                const double *x = k[s][j];
                k[s][j] = k[s][j - 1], k[s][j - 1] = x;
            }
    }
    for (int i = 0; i < 4; i++)
        if (cmp3(k[0][i], k[1][i])) return cmp3(k[0][i], k[1][i]) < 0;
    return 0;
}

/* Tets searched for the first one holding x. */
#define T3_HOLDERS 256

/* The tet holding x (closed) first in tet_before's order, from a walk from tet t0:
 * x may lie on a face, edge or vertex of several; -1 when x is outside the mesh. */
static lh_index holder(t3_ctx *c, lh_index t0, const double *x)
{
    lh_index got[T3_HOLDERS], t = lh__t3_mesh_walk(c, t0, x), best = t;
    int n = t >= 0;
    got[0] = t;
    for (int i = 0; i < n; i++) /* across the faces x lies on */
        for (int j = 0; j < 4; j++) {
            lh_index u = c->tn[4 * (size_t)got[i] + j];
            int seen = u < 0 || lh__t3_mesh_side(c, (size_t)got[i], j, x) != 0;
            for (int k = 0; k < n && !seen; k++) seen = got[k] == u;
            if (seen || n == T3_HOLDERS) continue;
            got[n++] = u;
            if (tet_before(c, u, best)) best = u;
        }
    return best;
}

lh_status lh__t3_queue_inside(t3_ctx *c, lh_index near, const double *x0)
{
    double x[3] = {x0[0], x0[1], x0[2]}, g[3];
    lh_index t = c->vtet[near] < 0 ? -1 : holder(c, c->vtet[near], x);
    if (t < 0 && c->vtet[near] >= 0) { /* x rounded off the hull: halfway into a tet at near */
        size_t k;
        lh_status st = lh__t3_mesh_star(c, near, &k);
        if (st != LH_OK) return st;
        lh_index s = c->sbuf[0];
        for (size_t i = 1; i < k; i++)
            if (tet_before(c, c->sbuf[i], s)) s = c->sbuf[i];
        centroid(c, s, g);
        for (int a = 0; a < 3; a++) x[a] = x[a] / 2 + g[a] / 2;
        t = holder(c, s, x);
    }
    if (t >= 0 && tet_size(c, t) < ldexp(1, c->unit_exp - T3_INSIDE_BITS)) t = -1;
    for (size_t w = 0; t >= 0 && w < sizeof weights / sizeof weights[0]; w++) {
        double q[3];
        centroid(c, t, g);
        for (int a = 0; a < 3; a++) q[a] = weights[w][0] * x[a] + weights[w][1] * g[a];
        int inside = 1;
        for (int j = 0; j < 4 && inside; j++) inside = lh__t3_mesh_side(c, (size_t)t, j, q) > 0;
        if (inside && !on_constraint(c, q)) return lh__t3_queue(c, lh__t3_inside_seg(c), 0, -1, q);
    }
    return lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                      "-Y: Steiner points off the boundary did not recover the boundary at (%.17g, "
                      "%.17g, %.17g); without -Y, points on segments and facets do",
                      x0[0], x0[1], x0[2]);
}
