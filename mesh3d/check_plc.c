/*
 * check_plc.c — lh_tetmesh_check's conformity half: every segment of the PLC (free
 * segments, then the facets' polygon edges, each once) is a chain of subsegments
 * from one endpoint to the other, and every facet is the union of its subfaces.
 *
 * A facet F is the union of its subfaces S_F when, in F's plane projected to the
 * coordinate plane that lh__facet_axis picks (that of its first ring's Newell
 * normal's largest component, where F keeps its area: an affine bijection of the
 * plane, so areas keep their ratios and containment its answers):
 *  (a) every subface has nonzero area there and the sum of |area| over S_F equals
 *      the area of F (outer polygon, plus polygons outside it, minus the polygons
 *      around a hole point of F), exactly (sums of 2x2 determinants, lh__detsum);
 *  (b) every edge in exactly one subface of S_F is a subsegment of one of F's
 *      polygon edges, and no edge is in three.
 * By (b) the number of subfaces covering a point changes only across F's polygon
 * edges, so it is constant on each piece of F; by (a) it is 1 on F (a piece with 0
 * would need one with 2 or more, whose boundary edges (b) forbids inside F unless
 * a hole of F is filled and an equal area elsewhere left bare — a fault that (a)
 * and (b) cannot see; docs/meshing3d.md, "Checking a mesh").
 * Points not exactly in F's plane (or on a segment's line) are accepted when they
 * are Steiner points (index >= g->n) within rounding's reach of it (reach()), and
 * counted once each in off_exact; a facet with such a point among its subfaces'
 * is held to (b) only, since rounding moves its area. A facet whose points are not
 * coplanar is triangulated in that same projection (facets.h), and held to (a) and
 * (b) there.
 */
#include "check_plc.h"
#include "facets.h"
#include "lh_sort.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the PLC's own consistency --------------------------------------------------- */

static lh_status bad_plc(lh__tchk *c, const char *what, size_t i)
{
    return lh__error_say(c->err, LH_ERR_INVALID_ARGUMENT, "the PLC is malformed: %s %zu", what, i);
}

static int offsets_ok(const lh_index *first, size_t count, size_t total)
{
    if (first[0] < 0) return 0;
    for (size_t i = 0; i < count; i++)
        if (first[i + 1] < first[i]) return 0;
    return (size_t)first[count] <= total;
}

static lh_status check_g(lh__tchk *c)
{
    const lh_plc *g = c->g;
    if (g->n > c->n)
        return lh__error_say(c->err, LH_ERR_INVALID_ARGUMENT,
                             "the mesh has %zu points, fewer than the PLC's %zu", c->n, g->n);
    for (size_t i = 0; g->xyz && i < 3 * g->n; i++)
        if (g->xyz[i] != c->xyz[i])
            return lh__error_say(c->err, LH_ERR_INVALID_ARGUMENT,
                                 "the PLC's point %zu is not the mesh's point %zu", i / 3, i / 3);
    if (g->facet_count && (!g->facet_first || !g->polygon_first || !g->polygon_vertices))
        return bad_plc(c, "facet arrays NULL with facets:", g->facet_count);
    if (g->facet_count && (!offsets_ok(g->facet_first, g->facet_count, g->polygon_count) ||
                           !offsets_ok(g->polygon_first, g->polygon_count, SIZE_MAX)))
        return bad_plc(c, "offsets out of order, facets:", g->facet_count);
    for (size_t i = 0; g->facet_count && i < (size_t)g->polygon_first[g->polygon_count]; i++)
        if (g->polygon_vertices[i] < 0 || (size_t)g->polygon_vertices[i] >= g->n)
            return bad_plc(c, "polygon vertex out of range at", i);
    if (g->segment_count && !g->segments) return bad_plc(c, "segments NULL:", g->segment_count);
    for (size_t i = 0; i < 2 * g->segment_count; i++)
        if (g->segments[i] < 0 || (size_t)g->segments[i] >= g->n)
            return bad_plc(c, "segment endpoint out of range, segment", i / 2);
    if (g->facet_count && g->facet_hole_first &&
        (!offsets_ok(g->facet_hole_first, g->facet_count, SIZE_MAX) ||
         (g->facet_hole_first[g->facet_count] && !g->facet_holes)))
        return bad_plc(c, "facet hole offsets, facets:", g->facet_count);
    for (size_t i = 0; g->facet_count && g->facet_hole_first &&
                       i < 3 * (size_t)g->facet_hole_first[g->facet_count];
         i++)
        if (g->facet_holes[i] - g->facet_holes[i] != 0)
            return bad_plc(c, "facet hole point not finite:", i / 3);
    for (size_t s = 0; c->parents && s < c->nf; s++)
        if (c->parents[s] < -1 || (c->parents[s] >= 0 && (size_t)c->parents[s] >= g->facet_count))
            return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                 "subface %zu has parent %lld, not a facet (0..%zu) or -1", s,
                                 (long long)c->parents[s], g->facet_count ? g->facet_count - 1 : 0);
    return LH_OK;
}

/* ---- exact helpers --------------------------------------------------------------- */

/* p projected: the two coordinates other than axis. */
void lh__pchk_proj(const double *p, int axis, double *q)
{
    q[0] = p[axis == 0 ? 1 : 0];
    q[1] = p[axis == 2 ? 1 : 2];
}

int lh__pchk_orient3i(pchk *k, lh_index a, lh_index b, lh_index x, lh_index y)
{
    const double *p[4] = {lh__tchk_pt(k->c, a), lh__tchk_pt(k->c, b), lh__tchk_pt(k->c, x),
                          lh__tchk_pt(k->c, y)};
    return lh_orient(k->c->pr, 3, p);
}

/* Whether the points a, b, x of R^3 are collinear: every coordinate projection is. */
int lh__pchk_collinear(pchk *k, const double *a, const double *b, const double *x)
{
    for (int axis = 0; axis < 3; axis++) {
        double q[3][2];
        lh__pchk_proj(a, axis, q[0]), lh__pchk_proj(b, axis, q[1]), lh__pchk_proj(x, axis, q[2]);
        const double *p[3] = {q[0], q[1], q[2]};
        if (lh_orient(k->c->pr, 2, p) != 0) return 0;
    }
    return 1;
}

/* sign of sum_i orient_2(u, v, q_i), i < m (m = 1, or 3 for a triangle's centroid,
 * orient_2 being affine in its last point): added into a zero scratch sum, read,
 * taken away again (exactly zero after). */
static int orient2_sum(pchk *k, const double *u, const double *v, const double (*q)[2], int m)
{
    const double *p[3] = {u, v, q[0]};
    if (m == 1) return lh_orient(k->c->pr, 2, p);
    for (int i = 0; i < m; i++) p[2] = q[i], lh__detsum_add(k->c->pr, k->s2, p, 0);
    const int s = lh__detsum_sign(k->s2);
    for (int i = 0; i < m; i++) p[2] = q[i], lh__detsum_add(k->c->pr, k->s2, p, 1);
    return s;
}

/* sign of sum_i (q_i[j] - u[j]), i < m (the mean's coordinate j against u's). */
static int coord_sum(pchk *k, const double (*q)[2], int m, const double *u, int j)
{
    if (m == 1) return (q[0][j] > u[j]) - (q[0][j] < u[j]);
    const double *p[2] = {u + j, NULL};
    for (int i = 0; i < m; i++) p[1] = q[i] + j, lh__detsum_add(k->c->pr, k->s1, p, 0);
    const int s = lh__detsum_sign(k->s1);
    for (int i = 0; i < m; i++) p[1] = q[i] + j, lh__detsum_add(k->c->pr, k->s1, p, 1);
    return s;
}

/* The mean of q[0..m) against polygon p projected along axis: 1 strictly inside,
 * 0 on its boundary, -1 outside (crossing number, every test exact). */
static int in_ring(pchk *k, size_t p, int axis, const double (*q)[2], int m)
{
    const size_t len = lh__pchk_poly_len(k->g, p);
    const lh_index *v = lh__pchk_poly_v(k->g, p);
    int inside = 0;
    for (size_t i = 0; i < len; i++) {
        double u[2], w[2];
        lh__pchk_proj(lh__tchk_pt(k->c, v[i]), axis, u);
        lh__pchk_proj(lh__tchk_pt(k->c, v[(i + 1) % len]), axis, w);
        const int cu = coord_sum(k, q, m, u, 1), cw = coord_sum(k, q, m, w, 1);
        const int xu = coord_sum(k, q, m, u, 0), xw = coord_sum(k, q, m, w, 0);
        const int s = cu * cw <= 0 ? orient2_sum(k, u, w, q, m) : 1;
        if (s == 0 && xu * xw <= 0) return 0;
        if ((cu < 0) != (cw < 0) && (cw < 0 ? s > 0 : s < 0)) inside ^= 1;
    }
    return inside ? 1 : -1;
}

/* Whether the mean of q[0..m) lies in facet f's closed region: in or on an area
 * polygon and strictly inside no hole polygon. */
int lh__pchk_in_facet(pchk *k, size_t f, const double (*q)[2], int m)
{
    int in = 0;
    for (size_t p = (size_t)k->g->facet_first[f]; p < (size_t)k->g->facet_first[f + 1]; p++) {
        if (k->eps[p] == 0) continue;
        const int r = in_ring(k, p, k->axis[f], q, m);
        if (k->eps[p] < 0 && r > 0) return 0;
        if (k->eps[p] > 0 && r >= 0) in = 1;
    }
    return in;
}

/* ---- facets: planes, projections, polygon roles ------------------------------------ */

static void facet_plane(pchk *k, size_t f)
{
    const lh_plc *g = k->g;
    lh_index *pl = k->plane + 3 * f;
    pl[0] = pl[1] = pl[2] = -1;
    for (size_t p = (size_t)g->facet_first[f]; p < (size_t)g->facet_first[f + 1]; p++)
        for (size_t i = 0; i < lh__pchk_poly_len(g, p); i++) {
            const lh_index v = lh__pchk_poly_v(g, p)[i];
            const double *x = lh__tchk_pt(k->c, v);
            if (pl[0] < 0)
                pl[0] = v;
            else if (pl[1] < 0 && memcmp(x, lh__tchk_pt(k->c, pl[0]), 3 * sizeof *x))
                pl[1] = v;
            else if (pl[1] >= 0 && pl[2] < 0 &&
                     !lh__pchk_collinear(k, lh__tchk_pt(k->c, pl[0]), lh__tchk_pt(k->c, pl[1]), x))
                pl[2] = v;
        }
}

/* eps: the first polygon of 3 or more points is the outer one (+1); another is a
 * hole (-1) around a hole point of the facet, a separate piece (+1) with a point
 * outside the outer one, else a constraint inside the facet (0). */
static void facet_roles(pchk *k, size_t f)
{
    const lh_plc *g = k->g;
    const size_t p0 = (size_t)g->facet_first[f], p1 = (size_t)g->facet_first[f + 1];
    size_t outer = p1;
    for (size_t p = p0; p < p1; p++) {
        k->eps[p] = 0;
        if (lh__pchk_poly_len(g, p) < 3) continue;
        if (outer == p1) {
            outer = p, k->eps[p] = 1;
            continue;
        }
        if (k->plane[3 * f] < 0) continue;
        for (size_t h = g->facet_hole_first ? (size_t)g->facet_hole_first[f] : 0;
             g->facet_hole_first && h < (size_t)g->facet_hole_first[f + 1]; h++) {
            double q[1][2];
            lh__pchk_proj(g->facet_holes + 3 * h, k->axis[f], q[0]);
            if (in_ring(k, p, k->axis[f], (const double(*)[2])q, 1) > 0) k->eps[p] = -1;
        }
        for (size_t i = 0; k->eps[p] == 0 && i < lh__pchk_poly_len(g, p); i++) {
            double q[1][2];
            lh__pchk_proj(lh__tchk_pt(k->c, lh__pchk_poly_v(g, p)[i]), k->axis[f], q[0]);
            if (in_ring(k, outer, k->axis[f], (const double(*)[2])q, 1) < 0) k->eps[p] = 1;
        }
    }
}

void lh__pchk_prepare_facets(pchk *k)
{
    const lh_plc *g = k->g;
    for (size_t f = 0; f < g->facet_count; f++) {
        facet_plane(k, f);
        lh_index *pl = k->plane + 3 * f;
        k->planar[f] = pl[2] >= 0;
        double nrm[3];
        k->axis[f] = pl[2] >= 0
                         ? lh__facet_axis(k->c->pr, g, k->c->xyz, f, lh__tchk_pt(k->c, pl[0]),
                                          lh__tchk_pt(k->c, pl[1]), lh__tchk_pt(k->c, pl[2]), nrm)
                         : 0;
        for (size_t p = (size_t)g->facet_first[f];
             k->planar[f] && p < (size_t)g->facet_first[f + 1]; p++)
            for (size_t i = 0; i < lh__pchk_poly_len(g, p); i++)
                if (lh__pchk_orient3i(k, pl[0], pl[1], pl[2], lh__pchk_poly_v(g, p)[i]) != 0)
                    k->planar[f] = 0;
        if (pl[2] < 0) pl[0] = -1;
        facet_roles(k, f);
    }
}

/* ---- segments -------------------------------------------------------------------- */

int lh__pchk_prec_cmp(const void *x, const void *y)
{
    const prec *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return p->pos < q->pos ? -1 : p->pos > q->pos;
}

static int prec_pos_cmp(const void *x, const void *y)
{
    const prec *p = x, *q = y;
    return p->pos < q->pos ? -1 : p->pos > q->pos;
}

int lh__pchk_hrec_cmp(const void *x, const void *y)
{
    const hrec *p = x, *q = y;
    if (p->from != q->from) return p->from < q->from ? -1 : 1;
    return p->to < q->to ? -1 : p->to > q->to;
}

/* The free segments, then the polygon edges (2-vertex polygons: one) in order of
 * first appearance, each once. tmp holds one record per polygon vertex. */
static void list_segments(pchk *k, prec *tmp)
{
    const lh_plc *g = k->g;
    size_t m = 0;
    for (size_t p = 0; g->facet_count && p < g->polygon_count; p++) {
        const size_t len = lh__pchk_poly_len(g, p);
        for (size_t i = 0; len >= 2 && i < (len == 2 ? 1 : len); i++) {
            const lh_index a = lh__pchk_poly_v(g, p)[i], b = lh__pchk_poly_v(g, p)[(i + 1) % len];
            if (a != b) tmp[m] = (prec){a < b ? a : b, a < b ? b : a, (lh_index)m}, m++;
        }
    }
    qsort(tmp, m, sizeof *tmp, lh__pchk_prec_cmp);
    size_t u = 0;
    for (size_t i = 0; i < m; i++)
        if (i == 0 || tmp[i].a != tmp[i - 1].a || tmp[i].b != tmp[i - 1].b) tmp[u++] = tmp[i];
    qsort(tmp, u, sizeof *tmp, prec_pos_cmp);
    if (g->segment_count) memcpy(k->seg, g->segments, 2 * g->segment_count * sizeof *k->seg);
    k->ns = g->segment_count;
    for (size_t i = 0; i < u; i++, k->ns++) {
        k->seg[2 * k->ns] = tmp[i].a;
        k->seg[2 * k->ns + 1] = tmp[i].b;
    }
}

/* Rounding's reach: a Steiner point counts as on a line or plane up to rounding when
 * it is within 64 machine epsilons of the largest coordinate involved (a rounded
 * construction is within an ulp; text output at 16 digits within a few). The only
 * tolerance of the check, and it decides only which points are counted in
 * off_exact; a point beyond it is a fault. Evaluated in floating point: the
 * distance's own error is far below the margin. */
static double reach(const double *const *p, int m)
{
    double big = 0;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < 3; j++) big = fabs(p[i][j]) > big ? fabs(p[i][j]) : big;
    return 64 * DBL_EPSILON * big;
}

static void cross(const double *a, const double *b, const double *c, double *out)
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    out[0] = u[1] * w[2] - u[2] * w[1], out[1] = u[2] * w[0] - u[0] * w[2];
    out[2] = u[0] * w[1] - u[1] * w[0];
}

static double norm(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* Whether x is within rounding's reach of the line a b. */
static int near_line(const double *a, const double *b, const double *x)
{
    const double *p[3] = {a, b, x}, d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double c[3];
    cross(a, b, x, c);
    return norm(c) <= reach(p, 3) * norm(d);
}

/* Whether x is within rounding's reach of the plane a b c. */
int lh__pchk_near_plane(const double *a, const double *b, const double *c, const double *x)
{
    const double *p[4] = {a, b, c, x};
    double n[3];
    cross(a, b, c, n);
    const double h = n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2]);
    return fabs(h) <= reach(p, 4) * norm(n);
}

void lh__pchk_mark_off(pchk *k, lh_index v)
{
    if (!k->c->off[v]) k->c->off[v] = 1, k->c->off_count++;
}

int lh__pchk_strictly_between(double p, double x, double q)
{
    return (p < x && x < q) || (q < x && x < p);
}

/* The next point of segment s's chain from cur: b itself, else the nearest point
 * exactly on the line a b strictly between cur and b along the axis, else the
 * nearest Steiner point so between (*off set). -1 for none. */
static const hrec *next_on(pchk *k, const hrec *h, size_t nh, lh_index a, lh_index b, int axis,
                           int *off)
{
    const hrec *best = NULL;
    int best_off = 1;
    const double *pa = lh__tchk_pt(k->c, a), *pb = lh__tchk_pt(k->c, b);
    const double cur = lh__tchk_pt(k->c, h->from)[axis];
    for (size_t i = 0; i < nh && h[i].from == h->from; i++) {
        if (h[i].to == b) {
            *off = 0;
            return h + i;
        }
        const double *x = lh__tchk_pt(k->c, h[i].to);
        if (!lh__pchk_strictly_between(cur, x[axis], pb[axis])) continue;
        const int is_off = !lh__pchk_collinear(k, pa, pb, x);
        if (is_off && ((size_t)h[i].to < k->g->n || !near_line(pa, pb, x))) continue;
        if (!best || is_off < best_off ||
            (is_off == best_off &&
             lh__pchk_strictly_between(cur, x[axis], lh__tchk_pt(k->c, best->to)[axis])))
            best = h + i, best_off = is_off;
    }
    *off = best_off;
    return best;
}

/* Whether the ray from mesh point v towards w enters no tetrahedron at v: w lies in
 * none of their closed cones at v. */
static int leaves_mesh(pchk *k, lh_index v, lh_index w)
{
    for (size_t t = 0; t < k->c->nt; t++) {
        const lh_index *q = k->c->tets + 4 * t;
        int i = 0;
        while (i < 4 && q[i] != v) i++;
        if (i == 4) continue;
        const lh_index a = q[(i + 1) % 4], b = q[(i + 2) % 4], c = q[(i + 3) % 4];
        const int s = lh__pchk_orient3i(k, v, a, b, c); /* each face at v sees the far corner so */
        if (s * lh__pchk_orient3i(k, v, a, b, w) >= 0 &&
            s * lh__pchk_orient3i(k, v, b, c, w) >= 0 && s * lh__pchk_orient3i(k, v, c, a, w) >= 0)
            return 0;
    }
    return 1;
}

static lh_status seg_not_covered(pchk *k, size_t s, lh_index cur)
{
    const long long a = k->seg[2 * s], b = k->seg[2 * s + 1];
    return lh__error_say(k->c->err, LH_ERR_INVALID_MESH,
                         "segment %zu (%lld %lld) is not covered: its chain of "
                         "subsegments from %lld stops at %lld",
                         s, a, b, a, (long long)cur);
}

static lh_status walk_segment(pchk *k, size_t s)
{
    const lh_index a = k->seg[2 * s], b = k->seg[2 * s + 1];
    const double *pa = lh__tchk_pt(k->c, a), *pb = lh__tchk_pt(k->c, b);
    int axis = 0;
    for (int i = 1; i < 3; i++)
        if (fabs(pb[i] - pa[i]) > fabs(pb[axis] - pa[axis])) axis = i;
    if (pa[axis] == pb[axis]) return LH_OK; /* coincident endpoints: no length */
    const size_t nh = 2 * k->c->ne;
    lh_index cur = a;
    while (cur != b) {
        const hrec key = {cur, -1, 0};
        size_t lo = 0, hi = nh;
        while (lo < hi) {
            const size_t mid = lo + (hi - lo) / 2;
            if (lh__pchk_hrec_cmp(k->h + mid, &key) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        int off = 0;
        const hrec *nx = lo < nh && k->h[lo].from == cur
                             ? next_on(k, k->h + lo, nh - lo, a, b, axis, &off)
                             : NULL;
        if (!nx && cur == a && leaves_mesh(k, a, b) && leaves_mesh(k, b, a)) {
            k->away[k->naway++] = (lh_index)s; /* decided with the facets */
            return LH_OK;
        }
        if (!nx) return seg_not_covered(k, s, cur);
        if (off) lh__pchk_mark_off(k, nx->to);
        if (k->seg_of[nx->sub] < 0) k->seg_of[nx->sub] = (lh_index)s;
        if (nx->to != b && k->pt_seg[nx->to] < 0) k->pt_seg[nx->to] = (lh_index)s;
        cur = nx->to;
    }
    return LH_OK;
}

static lh_status check_segments(pchk *k)
{
    const size_t ne = k->c->ne;
    for (size_t s = 0; s < ne; s++) {
        const lh_index a = k->c->edges[2 * s], b = k->c->edges[2 * s + 1];
        k->h[2 * s] = (hrec){a, b, (lh_index)s};
        k->h[2 * s + 1] = (hrec){b, a, (lh_index)s};
        k->seg_of[s] = -1;
    }
    qsort(k->h, 2 * ne, sizeof *k->h, lh__pchk_hrec_cmp);
    for (size_t i = 0; i < k->c->n; i++) k->pt_seg[i] = -1;
    for (size_t s = 0; s < k->ns; s++) {
        const lh_status st = walk_segment(k, s);
        if (st) return st;
    }
    return LH_OK;
}

/* Whether facet f's polygons run along a b one way (1), both ways (2: a slit or a
 * spike, no wider than the edge), or not at all (0). */
static int runs(const lh_plc *g, size_t f, lh_index a, lh_index b)
{
    int fwd = 0, back = 0;
    for (size_t p = (size_t)g->facet_first[f]; p < (size_t)g->facet_first[f + 1]; p++) {
        const size_t len = lh__pchk_poly_len(g, p);
        const lh_index *v = lh__pchk_poly_v(g, p);
        for (size_t j = 0; len >= 2 && j < (len == 2 ? 1 : len); j++) {
            const lh_index x = v[j], y = v[(j + 1) % len];
            fwd |= x == a && y == b, back |= x == b && y == a;
        }
    }
    return fwd && back ? 2 : fwd || back;
}

/* A segment with no subsegment at all, leaving the mesh at both its ends, lies
 * outside it: it crosses no facet, and the mesh's boundary is made of facets. It
 * was carved away whole with the region around it (outside the surface, or a hole)
 * when it is a polygon edge of facets that all were, with no subface: as a facet may
 * be (check_facets.c) — or when a facet runs along it both ways (a spike out of the
 * facet's area, which has no area beside it: check_facets.c checks the area). A free
 * segment may not. */
static lh_status check_away(pchk *k)
{
    const lh_plc *g = k->g;
    for (size_t i = 0; i < k->naway; i++) {
        const size_t s = (size_t)k->away[i];
        const lh_index a = k->seg[2 * s], b = k->seg[2 * s + 1];
        int bounds_kept = s < g->segment_count;
        for (size_t f = 0; !bounds_kept && f < g->facet_count; f++)
            bounds_kept = runs(g, f, a, b) == 1 && k->ffirst[f + 1] > k->ffirst[f];
        if (bounds_kept) return seg_not_covered(k, s, a);
    }
    return LH_OK;
}

/* ---- entry ----------------------------------------------------------------------- */

static int coords_scale(const lh__tchk *c)
{
    int scale = 0, any = 0;
    for (size_t i = 0; i < 3 * c->n; i++)
        if (c->xyz[i] != 0) {
            const int e = lh__dbl_low_exp(c->xyz[i]);
            scale = any && scale < e ? scale : e;
            any = 1;
        }
    return scale;
}

static void pchk_free(pchk *k)
{
    const lh_allocator *al = &k->c->al;
    lh__free(al, k->seg), lh__free(al, k->away), lh__free(al, k->h), lh__free(al, k->seg_of),
        lh__free(al, k->pt_seg);
    lh__free(al, k->plane), lh__free(al, k->axis), lh__free(al, k->planar);
    lh__free(al, k->eps), lh__free(al, k->par), lh__free(al, k->ffirst);
    lh__free(al, k->flist), lh__free(al, k->pe), lh__free(al, k->re);
    lh__detsum_free(k->sum), lh__detsum_free(k->s2), lh__detsum_free(k->s1);
}

static lh_status check_merged(lh__tchk *c);

static int cmp_coords(const void *ctx, lh_index a, lh_index b)
{
    const double *x = (const double *)ctx + 3 * (size_t)a, *y = (const double *)ctx + 3 * (size_t)b;
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* The PLC with every point index replaced by the first point of equal coordinates
 * (the PLC's points are the mesh's first g->n, checked by check_g)
 * (a mesher merges exact duplicates, as lh_delaunay does): *copy shares g's arrays
 * but polygon_vertices and segments, allocated into *pv and *sv. */
static lh_status merge_duplicates(lh__tchk *c, lh_plc *copy, lh_index **pv, lh_index **sv)
{
    const lh_plc *g = c->g;
    const lh_allocator *al = &c->al;
    const size_t n = g->n, nv = g->facet_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    lh_index *idx = lh__alloc(al, (2 * n + 1) * sizeof *idx),
             *rep = lh__alloc(al, (n + 1) * sizeof *rep);
    *pv = lh__alloc(al, (nv + 1) * sizeof **pv);
    *sv = lh__alloc(al, (2 * g->segment_count + 1) * sizeof **sv);
    lh_status st = idx && rep && *pv && *sv ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        for (size_t i = 0; i < n; i++) idx[i] = (lh_index)i;
        lh__sort_idx(idx, idx + n, n, cmp_coords, c->xyz); /* stable: the first first */
        for (size_t i = 0; i < n; i++)
            rep[idx[i]] = i && !cmp_coords(c->xyz, idx[i - 1], idx[i]) ? rep[idx[i - 1]] : idx[i];
        for (size_t i = 0; i < nv; i++) (*pv)[i] = rep[g->polygon_vertices[i]];
        for (size_t i = 0; i < 2 * g->segment_count; i++) (*sv)[i] = rep[g->segments[i]];
        *copy = *g;
        copy->polygon_vertices = *pv;
        copy->segments = *sv;
    }
    lh__free(al, idx);
    lh__free(al, rep);
    return st;
}

lh_status lh__tchk_plc(lh__tchk *c)
{
    lh_status st = check_g(c);
    if (st) return st;
    lh_plc merged;
    lh_index *pv = NULL, *sv = NULL;
    const lh_plc *given = c->g;
    st = merge_duplicates(c, &merged, &pv, &sv);
    if (st == LH_OK) {
        c->g = &merged;
        st = check_merged(c);
        c->g = given;
    }
    lh__free(&c->al, pv);
    lh__free(&c->al, sv);
    return st;
}

/* lh__tchk_plc on the PLC with its duplicate points merged. */
static lh_status check_merged(lh__tchk *c)
{
    lh_status st;
    const lh_plc *g = c->g;
    const lh_allocator *al = &c->al;
    const size_t nv = g->facet_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    const size_t nfac = g->facet_count, np = g->facet_count ? g->polygon_count : 0;
    pchk k = {.c = c, .g = g};
    k.seg = lh__alloc(al, (2 * (g->segment_count + nv) + 1) * sizeof *k.seg);
    k.away = lh__alloc(al, (g->segment_count + nv + 1) * sizeof *k.away);
    k.h = lh__alloc(al, (2 * c->ne + 1) * sizeof *k.h);
    k.seg_of = lh__alloc(al, (c->ne + 1) * sizeof *k.seg_of);
    k.pt_seg = lh__alloc(al, (c->n + 1) * sizeof *k.pt_seg);
    k.plane = lh__alloc(al, (3 * nfac + 1) * sizeof *k.plane);
    k.axis = lh__alloc(al, (nfac + 1) * sizeof *k.axis);
    k.planar = lh__alloc(al, nfac + 1);
    k.eps = lh__alloc(al, np + 1);
    k.par = lh__alloc(al, (c->nf + 1) * sizeof *k.par);
    k.ffirst = lh__alloc(al, (nfac + 2) * sizeof *k.ffirst);
    k.flist = lh__alloc(al, (c->nf + 1) * sizeof *k.flist);
    k.pe = lh__alloc(al, (3 * c->nf + 1) * sizeof *k.pe);
    k.re = lh__alloc(al, (nv + 1) * sizeof *k.re);
    const int scale = coords_scale(c);
    st = k.seg && k.away && k.h && k.seg_of && k.pt_seg && k.plane && k.axis && k.planar && k.eps &&
                 k.par && k.ffirst && k.flist && k.pe && k.re
             ? LH_OK
             : LH_ERR_NOMEM;
    if (st == LH_OK) st = lh__detsum_create(al, 2, scale, &k.sum);
    if (st == LH_OK) st = lh__detsum_create(al, 2, scale, &k.s2);
    if (st == LH_OK) st = lh__detsum_create(al, 1, scale, &k.s1);
    prec *tmp = st == LH_OK ? lh__alloc(al, (nv + 1) * sizeof *tmp) : NULL;
    if (st == LH_OK && !tmp) st = LH_ERR_NOMEM;
    if (st == LH_OK) list_segments(&k, tmp);
    lh__free(al, tmp);
    if (st == LH_OK) st = check_segments(&k);
    if (st == LH_OK) st = lh__pchk_check_facets(&k);
    if (st == LH_OK) st = check_away(&k);
    pchk_free(&k);
    return st;
}
