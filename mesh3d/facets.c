/*
 * facets.c — every facet of a PLC triangulated in its plane (facets.h).
 *
 * A facet (Si, "TetGen, a Delaunay-based quality tetrahedral mesh generator", ACM
 * TOMS 41(2) 2015, §2) is a set of polygons in one plane: rings of 3 or more vertices
 * (its outer boundary and holes' boundaries), slits (2 vertices) and lone points
 * (1 vertex), with hole points that carve holes. Its triangulation is the constrained
 * Delaunay triangulation (Chew 1989) of those polygons in the plane, computed in 2D by
 * lh_pslg_triangulate after projecting the facet to a coordinate plane:
 *
 *   - The dropped axis k is that of the largest component of the first ring's Newell
 *     normal (Newell's method: the sum of the cross products of consecutive vertices,
 *     twice the ring's vector area). The projection keeps the other two axes in cyclic
 *     order (k+1, k+2), so a ring counterclockwise there turns positively about +k.
 *   - Planarity is exact: three non-collinear points a, b, c of the facet are found
 *     (collinear in R^3 exactly when orient_2 of their projections to all three
 *     coordinate planes is 0) and every point p of the facet is tested with
 *     orient_3(a, b, c, p) = 0. For a planar facet the projection along k is
 *     one-to-one on its plane exactly when orient_2 of the projected a, b, c is
 *     nonzero (checked; else another axis where it is nonzero), and orient_2 signs
 *     there are the plane's own, so the 2D triangulation is the facet's.
 *   - A non-planar facet (some orient_3 != 0: models whose polygons were rounded out
 *     of plane) is triangulated in its projection: the constrained Delaunay
 *     triangulation of the projected polygons, lifted back to the 3D points. Its
 *     triangles then are not exactly in one plane; they cover the facet's polygons
 *     vertex for vertex, with no new point. A projection that merges two distinct
 *     points is refused, and so are edges that cross in it.
 *
 * No Steiner point is added (boundary_steiner = -1, no refinement): every triangle's
 * corners are PLC points. A quad (one ring of 4, no hole) is split along its valid
 * diagonal directly, the Delaunay one when both are valid. Triangles are oriented as
 * the first ring turns in the projection, decided exactly by orient_2 at its
 * lexicographically smallest vertex (a strictly convex corner of a simple ring), so a
 * closed surface whose rings are consistently oriented gets consistently oriented
 * triangles.
 */
#include "facets.h"

#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"
#include "lh_sort.h"

#include <stdarg.h>
#include <stdio.h>
#include <math.h>
#include <string.h>

/* Scratch reused from facet to facet; every array sized for the largest facet so far. */
typedef struct facet_work {
    const lh_plc *g;
    const lh_allocator *al;
    lh_pred *pred;
    lh_index *loc;   /* g->n: a point's local number in the current facet, -1: none */
    lh_index *ids;   /* local number -> PLC point                                   */
    lh_index *order; /* local numbers sorted by projection (non-planar facets)      */
    lh_index *tmp;   /* the sort's scratch                                          */
    lh_index *seg;   /* 2 per edge: local numbers                                   */
    double *xy;      /* 2 per local point: the projection                           */
    double *hole;    /* 2 per hole point of the facet: the projection               */
    size_t cap, hole_cap;
    size_t nid, nseg, nhole;
    size_t out_cap;
    lh__facet_tris *out;
} facet_work;

static const double *pt(const lh_plc *g, lh_index i)
{
    return g->xyz + 3 * (size_t)i;
}

/* Writes "facet F (line L): MESSAGE" (without the line when g has none) into err,
 * with err->line and err->index set. Returns st. */
static lh_status facet_say(lh_error *err, const lh_plc *g, size_t f, lh_status st, const char *fmt,
                           ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
static lh_status facet_say(lh_error *err, const lh_plc *g, size_t f, lh_status st, const char *fmt,
                           ...)
{
    if (!err) return st;
    char msg[LH_ERROR_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (g->facet_line) {
        lh__error_say(err, st, "facet %zu (line %zu): %s", f, g->facet_line[f], msg);
        err->line = g->facet_line[f];
    } else {
        lh__error_say(err, st, "facet %zu: %s", f, msg);
    }
    err->index = f;
    return st;
}

/* ---- validation ------------------------------------------------------------------ */

static int offsets_ok(const lh_index *first, size_t count, size_t total)
{
    if (!first || first[0] != 0) return 0;
    for (size_t i = 0; i < count; i++)
        if (first[i + 1] < first[i]) return 0;
    return (size_t)first[count] <= total;
}

/* g's arrays are consistent, its indices in range and its coordinates finite. */
static lh_status validate(const lh_plc *g, lh_error *err)
{
    if (g->n && !g->xyz)
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "the PLC has no point array");
    if (g->n >= (size_t)LH_INDEX_MAX)
        return lh__error_say(err, LH_ERR_TOO_LARGE, "%zu points: more than an index can number",
                             g->n);
    lh_status st = lh_coords_validate(3, g->n, g->xyz, err);
    if (st != LH_OK) return st;
    if (!g->facet_count) return LH_OK;
    if (!offsets_ok(g->facet_first, g->facet_count, g->polygon_count) ||
        (g->polygon_count && !offsets_ok(g->polygon_first, g->polygon_count, SIZE_MAX)) ||
        (g->polygon_count && g->polygon_first[g->polygon_count] && !g->polygon_vertices))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                             "the PLC's facet or polygon offsets are inconsistent");
    const size_t nv = g->polygon_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    for (size_t i = 0; i < nv; i++)
        if (g->polygon_vertices[i] < 0 || (size_t)g->polygon_vertices[i] >= g->n)
            return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                 "polygon vertex %zu: point %lld is not a point (0..%zu)", i,
                                 (long long)g->polygon_vertices[i], g->n ? g->n - 1 : 0);
    if (!g->facet_hole_first) return LH_OK;
    if (!offsets_ok(g->facet_hole_first, g->facet_count, SIZE_MAX))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                             "the PLC's facet hole offsets are inconsistent");
    const size_t nh = (size_t)g->facet_hole_first[g->facet_count];
    if (nh && !g->facet_holes)
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "the PLC has no facet hole array");
    return lh_coords_validate(3, nh, g->facet_holes, err);
}

/* ---- scratch and output ---------------------------------------------------------- */

static void work_free(facet_work *w)
{
    const lh_allocator *al = w->al;
    lh__free(al, w->loc);
    lh__free(al, w->ids);
    lh__free(al, w->order);
    lh__free(al, w->tmp);
    lh__free(al, w->seg);
    lh__free(al, w->xy);
    lh__free(al, w->hole);
    lh_pred_free(w->pred);
}

/* Room for a facet of `need` polygon vertices and `holes` hole points. */
static lh_status work_reserve(facet_work *w, size_t need, size_t holes)
{
    const lh_allocator *al = w->al;
    if (need > w->cap) {
        size_t c = need > 2 * w->cap ? need : 2 * w->cap;
        lh__free(al, w->ids), lh__free(al, w->order), lh__free(al, w->tmp);
        lh__free(al, w->seg), lh__free(al, w->xy);
        w->ids = lh__alloc(al, c * sizeof(lh_index));
        w->order = lh__alloc(al, c * sizeof(lh_index));
        w->tmp = lh__alloc(al, c * sizeof(lh_index));
        w->seg = lh__alloc(al, 2 * c * sizeof(lh_index));
        w->xy = lh__alloc(al, 2 * c * sizeof(double));
        w->cap = (w->ids && w->order && w->tmp && w->seg && w->xy) ? c : 0;
        if (!w->cap) return LH_ERR_NOMEM;
    }
    if (holes > w->hole_cap) {
        lh__free(al, w->hole);
        w->hole = lh__alloc(al, 2 * holes * sizeof(double));
        w->hole_cap = w->hole ? holes : 0;
        if (!w->hole) return LH_ERR_NOMEM;
    }
    return LH_OK;
}

/* Appends triangle (a, b, c) of facet f. */
static lh_status emit(facet_work *w, size_t f, lh_index a, lh_index b, lh_index c)
{
    lh__facet_tris *o = w->out;
    if (o->count == w->out_cap) {
        const size_t cap = w->out_cap ? 2 * w->out_cap : 64;
        if (cap > SIZE_MAX / (3 * sizeof(lh_index))) return LH_ERR_TOO_LARGE;
        lh_index *t = lh__alloc(w->al, 3 * cap * sizeof(lh_index));
        lh_index *fa = lh__alloc(w->al, cap * sizeof(lh_index));
        if (!t || !fa) {
            lh__free(w->al, t), lh__free(w->al, fa);
            return LH_ERR_NOMEM;
        }
        if (o->count) {
            memcpy(t, o->tri, 3 * o->count * sizeof(lh_index));
            memcpy(fa, o->facet, o->count * sizeof(lh_index));
        }
        lh__free(w->al, o->tri), lh__free(w->al, o->facet);
        o->tri = t, o->facet = fa, w->out_cap = cap;
    }
    lh_index *t = o->tri + 3 * o->count;
    t[0] = a, t[1] = b, t[2] = c;
    o->facet[o->count++] = (lh_index)f;
    return LH_OK;
}

/* ---- geometry -------------------------------------------------------------------- */

int lh__orient2_along(lh_pred *pred, int k, const double *a, const double *b, const double *c)
{
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    const double *p[3] = {pa, pb, pc};
    double det = 0, err = -1;
    int s;
    if (lh__orient_filter_2(p, &s, &det, &err)) return s; /* lh_filter.gen.h */
    return lh__orient_unfiltered(pred, 2, p, det, err);
}

/* a, b, c lie on one line of R^3 (or coincide): every coordinate projection is. */
static int collinear3(lh_pred *pred, const double *a, const double *b, const double *c)
{
    for (int k = 0; k < 3; k++)
        if (lh__orient2_along(pred, k, a, b, c)) return 0;
    return 1;
}

/* Newell's normal of the polygon ring (m vertices), relative to its first vertex, the
 * differences halved and scaled by a power of two to the unit range first: no
 * product over- or underflows at any scale, and a scaled input gives the same. */
static void newell(const double *xyz, const lh_index *ring, size_t m, double nrm[3])
{
    const double *o = xyz + 3 * (size_t)ring[0];
    double big = 0;
    for (size_t i = 1; i < m; i++)
        for (int k = 0; k < 3; k++) {
            double d = xyz[3 * (size_t)ring[i] + k] / 2 - o[k] / 2;
            big = d > big ? d : -d > big ? -d : big;
        }
    int e = 0;
    frexp(big, &e);
    nrm[0] = nrm[1] = nrm[2] = 0;
    for (size_t i = 1; i + 1 < m; i++) {
        const double *p = xyz + 3 * (size_t)ring[i], *q = xyz + 3 * (size_t)ring[i + 1];
        double u[3], v[3];
        for (int k = 0; k < 3; k++)
            u[k] = ldexp(p[k] / 2 - o[k] / 2, -e), v[k] = ldexp(q[k] / 2 - o[k] / 2, -e);
        nrm[0] += u[1] * v[2] - u[2] * v[1];
        nrm[1] += u[2] * v[0] - u[0] * v[2];
        nrm[2] += u[0] * v[1] - u[1] * v[0];
    }
}

static double absd(double x)
{
    return x < 0 ? -x : x;
}

/* The axis to drop: Newell's largest component, unless the projection along it
 * flattens the non-collinear a, b, c; then the largest among those that do not. */
static int drop_axis(lh_pred *pred, const double nrm[3], const double *a, const double *b,
                     const double *c)
{
    int k = -1;
    for (int pass = 0; pass < 2 && k < 0; pass++)
        for (int i = 0; i < 3; i++) {
            if (pass == 0 && !lh__orient2_along(pred, i, a, b, c)) continue;
            if (k < 0 || absd(nrm[i]) > absd(nrm[k])) k = i;
        }
    return k;
}

int lh__facet_axis(lh_pred *pred, const lh_plc *g, const double *xyz, size_t f, const double *a,
                   const double *b, const double *c, double nrm[3])
{
    lh_index p = g->facet_first[f];
    while (p < g->facet_first[f + 1] && g->polygon_first[p + 1] - g->polygon_first[p] < 3) p++;
    nrm[0] = nrm[1] = nrm[2] = 0; /* no ring: any axis that keeps a, b, c apart */
    if (p < g->facet_first[f + 1])
        newell(xyz, g->polygon_vertices + g->polygon_first[p],
               (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]), nrm);
    return drop_axis(pred, nrm, a, b, c);
}

/* +1 when the ring (m vertices, local numbers in w->xy) turns counterclockwise in
 * the projection, -1 when clockwise: orient_2 at its lexicographically smallest
 * vertex with its neighbours; the sign of Newell's component when that is 0. */
static int ring_turn(facet_work *w, const lh_index *ring, size_t m, double nrm_k)
{
    size_t best = 0;
    for (size_t i = 1; i < m; i++) {
        const double *p = w->xy + 2 * w->loc[ring[i]], *q = w->xy + 2 * w->loc[ring[best]];
        if (p[0] < q[0] || (p[0] == q[0] && p[1] < q[1])) best = i;
    }
    const double *p[3] = {w->xy + 2 * w->loc[ring[(best + m - 1) % m]],
                          w->xy + 2 * w->loc[ring[best]], w->xy + 2 * w->loc[ring[(best + 1) % m]]};
    const int s = lh_orient(w->pred, 2, p);
    return s ? s : (nrm_k < 0 ? -1 : 1);
}

/* Points a and b of g in lexicographic order of coordinates. */
static int cmp_point(const lh_plc *g, lh_index a, lh_index b)
{
    const double *p = pt(g, a), *q = pt(g, b);
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

static int cmp_xy(const void *ctx, lh_index a, lh_index b)
{
    const double *xy = ctx, *p = xy + 2 * a, *q = xy + 2 * b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
    return 0;
}

/* A non-planar facet's projection keeps distinct points distinct. */
static lh_status projection_injective(facet_work *w, size_t f, lh_error *err)
{
    for (size_t i = 0; i < w->nid; i++) w->order[i] = (lh_index)i;
    lh__sort_idx(w->order, w->tmp, w->nid, cmp_xy, w->xy);
    for (size_t i = 1; i < w->nid; i++) {
        const lh_index a = w->order[i - 1], b = w->order[i];
        if (cmp_xy(w->xy, a, b)) continue;
        const double *p = pt(w->g, w->ids[a]), *q = pt(w->g, w->ids[b]);
        if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;
        const long long base = w->g->first_index;
        return facet_say(err, w->g, f, LH_ERR_DEGENERATE,
                         "not planar, and its projection to a coordinate plane merges "
                         "points %lld and %lld",
                         base + (long long)w->ids[a < b ? a : b],
                         base + (long long)w->ids[a < b ? b : a]);
    }
    return LH_OK;
}

/* ---- one facet ------------------------------------------------------------------- */

/* PLC point v's projection (v in the current facet). */
static const double *xy_of(const facet_work *w, lh_index v)
{
    return w->xy + 2 * w->loc[v];
}

/* The diagonal from ring corner d to d + 2 splits the quad into two triangles that
 * turn as the ring (sign s) does. */
static int diagonal_ok(facet_work *w, const lh_index *r, int d, int s)
{
    const double *p[4];
    for (int i = 0; i < 4; i++) p[i] = xy_of(w, r[(d + i) % 4]);
    const double *t0[3] = {p[0], p[1], p[2]}, *t1[3] = {p[0], p[2], p[3]};
    return lh_orient(w->pred, 2, t0) == s && lh_orient(w->pred, 2, t1) == s;
}

/* A quad facet (one ring of 4 distinct points, no hole) triangulated directly: its
 * constrained Delaunay triangulation is the valid diagonal, the Delaunay one when
 * both are (on a circle: the one at the corner of least coordinates, so the choice
 * does not depend on where the ring starts).
 * s: the ring's turn. Returns 0 when the quad is not simple in the projection (the
 * general path then says why), else 1 with *st. */
static int quad(facet_work *w, size_t f, const lh_index *r, int s, lh_status *st)
{
    const int ok0 = diagonal_ok(w, r, 0, s), ok1 = diagonal_ok(w, r, 1, s);
    if (!ok0 && !ok1) return 0;
    int d = ok0 ? 0 : 1;
    if (ok0 && ok1) {
        const double *p[4] = {xy_of(w, r[0]), xy_of(w, r[1]), xy_of(w, r[2]), xy_of(w, r[3])};
        const int in = lh_insphere(w->pred, 2, p) * s; /* < 0: r[3] inside circle r[0..2] */
        size_t low = 0;
        for (size_t i = 1; i < 4; i++)
            if (cmp_point(w->g, r[i], r[low]) < 0) low = i;
        d = in < 0 ? 1 : in > 0 ? 0 : (int)(low % 2);
    }
    *st = emit(w, f, r[d], r[d + 1], r[(d + 2) % 4]);
    if (*st == LH_OK) *st = emit(w, f, r[d], r[(d + 2) % 4], r[(d + 3) % 4]);
    return 1;
}

/* Local number of PLC point v, numbering it when new. */
static lh_index local(facet_work *w, lh_index v)
{
    if (w->loc[v] < 0) {
        w->loc[v] = (lh_index)w->nid;
        w->ids[w->nid++] = v;
    }
    return w->loc[v];
}

/* Collects facet f's points and edges (ring edges, slits) with local numbers;
 * *ring0 the first polygon of 3 or more vertices (-1: none). */
static void collect(facet_work *w, size_t f, lh_index *ring0)
{
    const lh_plc *g = w->g;
    w->nid = w->nseg = 0;
    *ring0 = -1;
    for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
        const lh_index *v = g->polygon_vertices + g->polygon_first[p];
        const size_t m = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
        if (m >= 3 && *ring0 < 0) *ring0 = p;
        for (size_t i = 0; i < m; i++) local(w, v[i]);
        for (size_t i = 0; m >= 2 && i < (m == 2 ? 1 : m); i++) {
            w->seg[2 * w->nseg] = w->loc[v[i]];
            w->seg[2 * w->nseg + 1] = w->loc[v[(i + 1) % m]];
            w->nseg++;
        }
    }
}

/* The PLC points of local segment s, for messages. */
static void seg_points(const facet_work *w, long long s, long long *a, long long *b)
{
    const long long base = w->g->first_index;
    *a = base + w->ids[w->seg[2 * s]];
    *b = base + w->ids[w->seg[2 * s + 1]];
}

/* lh_pslg_triangulate's refusal restated for facet f. */
static lh_status pslg_failure(facet_work *w, size_t f, lh_status st, const lh_error *e,
                              lh_error *err)
{
    long long s, t, a, b, c, d;
    if (st == LH_ERR_CROSSING_SEGMENTS &&
        sscanf(e->message, "segment %lld crosses segment %lld", &s, &t) == 2 && s >= 0 && t >= 0 &&
        (size_t)s < w->nseg && (size_t)t < w->nseg) {
        seg_points(w, s < t ? s : t, &a, &b);
        seg_points(w, s < t ? t : s, &c, &d);
        return facet_say(err, w->g, f, st,
                         "edges %lld-%lld and %lld-%lld cross in the facet's plane", a, b, c, d);
    }
    if (st == LH_ERR_DEGENERATE || st == LH_ERR_CROSSING_SEGMENTS)
        return facet_say(err, w->g, f, st, "in the facet's plane: %s", e->message);
    return st;
}

/* Triangulates facet f in its projection (the file's comment) and emits it. */
static lh_status facet_project(facet_work *w, size_t f, lh_index ring0, lh_error *err)
{
    const lh_plc *g = w->g;
    const double *a = pt(g, w->ids[0]), *b = NULL, *c = NULL;
    for (size_t i = 1; i < w->nid && !c; i++) {
        const double *p = pt(g, w->ids[i]);
        if (!b) {
            if (p[0] != a[0] || p[1] != a[1] || p[2] != a[2]) b = p;
        } else if (!collinear3(w->pred, a, b, p)) {
            c = p;
        }
    }
    if (!c)
        return facet_say(err, g, f, LH_ERR_DEGENERATE, "its points are all collinear (zero area)");
    int planar = 1;
    for (size_t i = 0; i < w->nid && planar; i++) {
        const double *p[4] = {a, b, c, pt(g, w->ids[i])};
        planar = lh_orient(w->pred, 3, p) == 0;
    }
    w->out->nonplanar += !planar;
    const lh_index *ring = g->polygon_vertices + g->polygon_first[ring0];
    const size_t m = (size_t)(g->polygon_first[ring0 + 1] - g->polygon_first[ring0]);
    double nrm[3];
    const int k = lh__facet_axis(w->pred, g, g->xyz, f, a, b, c, nrm), i = (k + 1) % 3,
              j = (k + 2) % 3;
    w->out->axis[f] = (signed char)k;
    for (size_t v = 0; v < w->nid; v++) {
        const double *p = pt(g, w->ids[v]);
        w->xy[2 * v] = p[i], w->xy[2 * v + 1] = p[j];
    }
    w->nhole = 0;
    if (g->facet_hole_first)
        for (lh_index h = g->facet_hole_first[f]; h < g->facet_hole_first[f + 1]; h++, w->nhole++) {
            w->hole[2 * w->nhole] = g->facet_holes[3 * h + i];
            w->hole[2 * w->nhole + 1] = g->facet_holes[3 * h + j];
        }
    lh_status st = planar ? LH_OK : projection_injective(w, f, err);
    if (st != LH_OK) return st;
    const size_t polygons = (size_t)(g->facet_first[f + 1] - g->facet_first[f]);
    const int turn = ring_turn(w, ring, m, nrm[k]);
    if (polygons == 1 && m == 4 && w->nid == 4 && !w->nhole && quad(w, f, ring, turn, &st))
        return st;
    lh_pslg p;
    memset(&p, 0, sizeof p);
    p.n = w->nid, p.xy = w->xy;
    p.segment_count = w->nseg, p.segments = w->seg;
    p.hole_count = w->nhole, p.holes = w->hole;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.alloc = w->al;
    o.boundary_steiner = -1;
    lh_trimesh *tm = NULL;
    lh_error e;
    st = lh_pslg_triangulate(&p, &o, &tm, &e);
    if (st != LH_OK) return pslg_failure(w, f, st, &e, err);
    const size_t tc = lh_trimesh_triangle_count(tm);
    const lh_index *t = lh_trimesh_triangles(tm);
    if (lh_trimesh_point_count(tm) != w->nid) st = LH_ERR_INTERNAL; /* no Steiner point */
    for (size_t q = 0; q < tc && st == LH_OK; q++) {
        const lh_index u = w->ids[t[3 * q]], v = w->ids[t[3 * q + 1]], x = w->ids[t[3 * q + 2]];
        st = turn > 0 ? emit(w, f, u, v, x) : emit(w, f, u, x, v);
    }
    lh_trimesh_free(tm);
    return st;
}

/* Facet f: one triangle passes through; any other is projected. */
static lh_status facet_one(facet_work *w, size_t f, lh_error *err)
{
    const lh_plc *g = w->g;
    const lh_index p0 = g->facet_first[f];
    if (g->facet_first[f + 1] == p0)
        return facet_say(err, g, f, LH_ERR_DEGENERATE, "no polygon of 3 or more vertices");
    const size_t holes =
        g->facet_hole_first ? (size_t)(g->facet_hole_first[f + 1] - g->facet_hole_first[f]) : 0;
    const size_t need = (size_t)(g->polygon_first[g->facet_first[f + 1]] - g->polygon_first[p0]);
    if (g->facet_first[f + 1] - p0 == 1 && need == 3 && !holes) {
        const lh_index *v = g->polygon_vertices + g->polygon_first[p0];
        if (collinear3(w->pred, pt(g, v[0]), pt(g, v[1]), pt(g, v[2])))
            return facet_say(err, g, f, LH_ERR_DEGENERATE,
                             "its points are all collinear (zero area)");
        return emit(w, f, v[0], v[1], v[2]);
    }
    lh_status st = work_reserve(w, need, holes);
    if (st != LH_OK) return st;
    lh_index ring0;
    collect(w, f, &ring0);
    if (ring0 < 0)
        st = facet_say(err, g, f, LH_ERR_DEGENERATE, "no polygon of 3 or more vertices");
    else
        st = facet_project(w, f, ring0, err);
    for (size_t i = 0; i < w->nid; i++) w->loc[w->ids[i]] = -1;
    return st;
}

lh_status lh__facets_triangulate(const lh_plc *g, const lh_allocator *al, lh__facet_tris *out,
                                 lh_error *err)
{
    memset(out, 0, sizeof *out);
    lh_allocator hooks;
    if (!g || !lh__allocator_init(&hooks, al))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "no PLC, or an allocator without hooks");
    lh_status st = validate(g, err);
    if (st != LH_OK) return st;
    facet_work w;
    memset(&w, 0, sizeof w);
    w.g = g, w.al = &hooks, w.out = out;
    out->axis = lh__alloc(w.al, g->facet_count + 1);
    st = out->axis ? lh_pred_create(al, &w.pred) : LH_ERR_NOMEM;
    if (out->axis) memset(out->axis, -1, g->facet_count + 1);
    if (st == LH_OK && g->n) {
        w.loc = lh__alloc(w.al, g->n * sizeof(lh_index));
        if (!w.loc)
            st = LH_ERR_NOMEM;
        else
            for (size_t i = 0; i < g->n; i++) w.loc[i] = -1;
    }
    for (size_t f = 0; f < g->facet_count && st == LH_OK; f++) st = facet_one(&w, f, err);
    work_free(&w);
    if (st != LH_OK) lh__facet_tris_free(al, out);
    return st;
}

void lh__facet_tris_free(const lh_allocator *al, lh__facet_tris *out)
{
    lh_allocator hooks;
    if (!lh__allocator_init(&hooks, al)) return;
    lh__free(&hooks, out->tri);
    lh__free(&hooks, out->facet);
    lh__free(&hooks, out->axis);
    memset(out, 0, sizeof *out);
}
