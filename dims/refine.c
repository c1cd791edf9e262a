/*
 * refine.c — Delaunay refinement of the constrained Delaunay triangulation: Ruppert's
 * algorithm (J. Ruppert 1995, "A Delaunay refinement algorithm for quality 2-dimensional
 * mesh generation", J. Algorithms 18(3)) as Shewchuk runs it (J. R. Shewchuk 2002,
 * "Delaunay refinement algorithms for triangular mesh generation", CGTA 22):
 *   1. a subsegment whose diametral circle holds a vertex is encroached: split it
 *      (midpoint; or, with one end an input vertex and the other not, at a power of
 *      two from the input vertex — concentric shells, §5, so that splits near a small
 *      input angle meet on circles around its apex);
 *   2. else the worst triangle whose smallest angle is below the bound (radius-edge
 *      ratio above 1/(2 sin bound)) or whose area is above its bound gets a vertex at
 *      its off-centre (A. Üngör 2004, "Off-centers: a new type of Steiner points for
 *      computing size-optimal quality-guaranteed Delaunay triangulations", LATIN) or
 *      circumcentre; a point that would encroach a subsegment is not inserted, the
 *      subsegments are split instead (Ruppert's rule).
 * Termination with small input angles (Shewchuk 2002, §6): a triangle whose shortest
 * edge joins points on two segments that meet at an input vertex at less than 60°,
 * at equal distances from it (the same shell), is not split; it is reported as bad.
 * A subsegment shorter than 2^-40 of the domain's diameter (or of its largest
 * coordinate, when larger) is never split (a guard against endless splitting by
 * rounding), nor one whose split point was refused: both are counted
 * (stats.segments_unsplit), and the Steiner budget (-S) stops everything.
 * Decisions that change the mesh are exact (m2_insert.c); the quality measures,
 * split points and centres are floating-point constructions.
 */
#include <math.h>
#include <string.h>

#include "m2.h"
#include "refine.h"

#define PI 3.14159265358979323846

typedef struct item { double key; lh_index t, a, b, c; } item; /* a bad triangle, as queued */

typedef struct rf {
    lh__m2 *m;
    lh__m2_cavity *c;
    lh__m2_ins ins;
    const lh__refine_opts *o;
    double ratio2;          /* bad when (R / shortest edge)^2 exceeds this (0: none) */
    double off_h;           /* off-centre distance from the shortest edge, per unit length */
    double minlen2;
    item *heap;
    size_t heap_count, heap_cap;
    lh_index *segq;         /* 2 per entry: subsegment, forced */
    size_t segq_count, segq_cap;
    size_t steiner;
    unsigned char *stuck;   /* per subsegment: a split was refused or is too short */
    size_t stuck_count, stuck_cap;
    lh_index *gone;         /* free vertices to remove before a split (Chew's rule) */
    size_t gone_count, gone_cap;
} rf;

static double dist2(const double *a, const double *b)
{
    const double dx = a[0] - b[0], dy = a[1] - b[1];
    return dx * dx + dy * dy;
}

/* Triangle t's squared edge lengths (l2[k] opposite vertex k); returns twice its area. */
static double measure(const lh__m2 *m, lh_index t, double l2[3])
{
    const lh_index *v = m->v + 3 * (size_t)t;
    const double *a = lh__m2_pt(m, v[0]), *b = lh__m2_pt(m, v[1]), *c = lh__m2_pt(m, v[2]);
    l2[0] = dist2(b, c), l2[1] = dist2(c, a), l2[2] = dist2(a, b);
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* The badness of triangle t: > 0 for an angle below the bound (the squared ratio),
 * -1 for an area above its bound only, 0 for a good triangle. */
static double badness(const rf *r, lh_index t)
{
    const lh__m2 *m = r->m;
    double l2[3];
    const double area2 = measure(m, t, l2), la = l2[0], lb = l2[1], lc = l2[2];
    if (r->ratio2 > 0) {
        const double lmin = la < lb ? (la < lc ? la : lc) : (lb < lc ? lb : lc);
        /* R^2 = la lb lc / (4 area2^2) with squared lengths and twice the area, so
           q = 4 (R / shortest)^2 */
        const double q = la * lb * lc / (area2 * area2 * lmin);
        if (q > r->ratio2) return q;
    }
    double bound = r->o->max_area;
    if (r->o->region_areas && m->tarea && m->tarea[t] > 0 && (bound <= 0 || m->tarea[t] < bound))
        bound = m->tarea[t];
    return bound > 0 && area2 / 2 > bound ? -1 : 0;
}

/* Whether segment x-y passes strictly within the circle (o, r2): its nearest point
 * to o is closer than the radius. */
static int edge_meets_disc(const double *x, const double *y, const double *o, double r2)
{
    const double dx = y[0] - x[0], dy = y[1] - x[1], l2 = dx * dx + dy * dy;
    double f = l2 > 0 ? ((o[0] - x[0]) * dx + (o[1] - x[1]) * dy) / l2 : 0;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    const double q[2] = {x[0] + f * dx, x[1] + f * dy};
    return dist2(q, o) < r2;
}

static void heap_up(item *h, size_t i)
{
    while (i) {
        const size_t p = (i - 1) / 2;
        if (h[p].key >= h[i].key) break;
        const item x = h[p];
        h[p] = h[i], h[i] = x, i = p;
    }
}

static void heap_down(item *h, size_t n, size_t i)
{
    for (;;) {
        size_t l = 2 * i + 1, b = i;
        if (l < n && h[l].key > h[b].key) b = l;
        if (l + 1 < n && h[l + 1].key > h[b].key) b = l + 1;
        if (b == i) return;
        const item x = h[b];
        h[b] = h[i], h[i] = x, i = b;
    }
}

static lh_status queue_triangle(rf *r, lh_index t)
{
    const double q = badness(r, t);
    if (q == 0) return LH_OK;
    if (!lh__m2_grow(r->m, (void **)&r->heap, r->heap_count, &r->heap_cap, r->heap_count + 1, sizeof(item)))
        return LH_ERR_NOMEM;
    const lh_index *v = r->m->v + 3 * (size_t)t;
    /* the triangle with the shortest shortest edge first (angle-bad ones; then those
       only too large): small features fix their neighbourhoods' sizes before larger
       triangles are split, which measured 10-30% fewer triangles than the worst
       angle first (Shewchuk 1996 §3 compares worst-first with first-in first-out) */
    const double *a = lh__m2_pt(r->m, v[0]), *b = lh__m2_pt(r->m, v[1]), *c = lh__m2_pt(r->m, v[2]);
    const double key = q > 0 ? -fmin(dist2(b, c), fmin(dist2(c, a), dist2(a, b))) : -HUGE_VAL;
    r->heap[r->heap_count] = (item){key, t, v[0], v[1], v[2]};
    heap_up(r->heap, r->heap_count++);
    return LH_OK;
}

/* Subsegment s cannot be split: its rounded split point was refused (the cavity not
 * star-shaped from it, as beside the slightly bent chain of a rounded crossing) or it
 * is shorter than minlen. Invariant: every pass of run() inserts a point or removes a
 * queue entry for good; a triangle requeued for a subsegment that never splits would
 * loop forever without a Steiner point (the -S budget never reached), so such a
 * subsegment is never queued again and the triangle is treated as at a -Y segment. */
static lh_status set_stuck(rf *r, lh_index s)
{
    const size_t need = (size_t)s + 1;
    if (need > r->stuck_count) {
        if (!lh__m2_grow(r->m, (void **)&r->stuck, r->stuck_count, &r->stuck_cap, need, 1)) return LH_ERR_NOMEM;
        memset(r->stuck + r->stuck_count, 0, need - r->stuck_count);
        r->stuck_count = need;
    }
    r->stuck[s] = 1;
    return LH_OK;
}

/* Whether the policy allows splitting subsegment s (Triangle's -Y, -YY), and it can. */
static int splittable(const rf *r, lh_index s, lh_index t, int pos)
{
    if ((size_t)s < r->stuck_count && r->stuck[s]) return 0;
    if (r->o->boundary_steiner > 0) return 1;
    if (r->o->boundary_steiner < 0) return 0;
    (void)s;
    return r->m->nb[3 * (size_t)t + pos] >= 0;
}

static lh_status queue_segment(rf *r, lh_index s, int forced)
{
    if (!lh__m2_grow(r->m, (void **)&r->segq, 2 * r->segq_count, &r->segq_cap, 2 * (r->segq_count + 1),
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    r->segq[2 * r->segq_count] = s;
    r->segq[2 * r->segq_count++ + 1] = forced;
    return LH_OK;
}

/* Whether vertex p encroaches subsegment s for splitting: inside its lens or circle
 * (lh__m2_encroaches), and not within 2^-40 of s's length from its line. A vertex
 * nearer than that is a feature below the resolution floor: halving s would go on
 * until the pieces are 2^40 times shorter, each one encroached again by the vertices
 * of the other side — 2^40 pieces for two segments 10^-28 apart (earcut's
 * infinite-loop-jhl.json: without end). Such a feature is left, and reported. */
static int encroaches_resolvably(const rf *r, lh_index s, const double *p)
{
    const lh__m2 *m = r->m;
    if (!lh__m2_encroaches(m, s, p)) return 0;
    const double *a = lh__m2_pt(m, m->sv[2 * (size_t)s]), *b = lh__m2_pt(m, m->sv[2 * (size_t)s + 1]);
    const double cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    const double l2 = dist2(a, b);
    return cr * cr >= 0x1p-80 * l2 * l2; /* distance = |cr| / |ab| */
}

/* Whether triangle t is a sliver below the resolution floor: its smallest altitude
 * (twice its area over its longest edge) under 2^-40 of its longest edge, an angle
 * under 2^-40 radians. Its rejected centre forces no split (see
 * encroaches_resolvably); it is left, and reported. */
static int below_floor(const rf *r, lh_index t)
{
    double l2[3];
    const double area2 = measure(r->m, t, l2), lmax = fmax(l2[0], fmax(l2[1], l2[2]));
    return area2 * area2 < 0x1p-80 * lmax * lmax;
}

/* Subsegment s encroached by the apex of a triangle beside it (and splittable):
 * returns 1 and the triangle/edge holding it. */
static int encroached(const rf *r, lh_index s, lh_index *tt, int *pp)
{
    const lh__m2 *m = r->m;
    int pos;
    const lh_index t = lh__m2_find_subseg(m, s, &pos);
    if (t < 0) return 0;
    *tt = t, *pp = pos;
    const lh_index n = m->nb[3 * (size_t)t + pos];
    if (encroaches_resolvably(r, s, lh__m2_pt(m, m->v[3 * (size_t)t + pos]))) return 1;
    return n >= 0 && encroaches_resolvably(r, s, lh__m2_pt(m, m->v[3 * (size_t)n + lh__m2_npos(m, n, t)]));
}

/* After an insertion: queue the new triangles that are bad and the subsegments on
 * their edges that are encroached. */
static lh_status after_insert(rf *r)
{
    lh__m2 *m = r->m;
    lh_status st;
    for (size_t i = 0; i < r->c->stack_count; i++) {
        const lh_index t = r->c->stack[i];
        if (r->o->cover_area) lh__cover_area_of(m, m->cover, r->o->cover_area, t);
        if ((st = queue_triangle(r, t)) != LH_OK) return st;
        for (int k = 0; k < 3; k++) {
            const lh_index s = m->sg[3 * (size_t)t + k];
            lh_index tt;
            int pp;
            if (s >= 0 && encroached(r, s, &tt, &pp) && splittable(r, s, tt, pp) &&
                (st = queue_segment(r, s, 0)) != LH_OK)
                return st;
        }
    }
    return LH_OK;
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
            const double *py = lh__m2_pt(m, y);
            const double ux = px[0] - po[0], uy = px[1] - po[1], vx = py[0] - po[0], vy = py[1] - po[1];
            const double dot = ux * vx + uy * vy;
            if (dot > 0 && dot * dot > cmin * cmin * (ux * ux + uy * uy) * (vx * vx + vy * vy)) return 1;
        }
    }
    return 0;
}

/* Where to split subsegment a-b: its midpoint, or, when exactly one end is an input
 * vertex at an acute corner, at the power of two nearest half its length from that
 * vertex (concentric shells, Ruppert 1995 §5; Shewchuk 2002 §6): splits near a small
 * input angle then meet at equal distances from its apex. */
static void split_point(const rf *r, lh_index s, double *p)
{
    const lh__m2 *m = r->m;
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    const int ia = (size_t)a < m->n_input && corner_below(m, a, b, m->sp[s], 0);
    const int ib = (size_t)b < m->n_input && corner_below(m, b, a, m->sp[s], 0);
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    double f = 0.5;
    if (ia != ib) {
        const double len = sqrt(dist2(pa, pb));
        const double d = ldexp(1.0, (int)floor(log2(len / 2) + 0.5)); /* nearest power of 2 */
        f = ia ? d / len : 1 - d / len;
    }
    p[0] = pa[0] + f * (pb[0] - pa[0]);
    p[1] = pa[1] + f * (pb[1] - pa[1]);
}

static void set_point_data(rf *r, lh_index pi, lh_index s, const double *w, const lh_index *from)
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

/* The free vertices strictly inside the circle (o, r2) around subsegment s, in
 * r->gone: a flood from s's sides across unconstrained edges that pass within it. */
static lh_status free_vertices_in_circle(rf *r, lh_index s, const double *o, double r2)
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
            if ((size_t)x >= m->n_input && m->pseg[x] == -1 && dist2(lh__m2_pt(m, x), o) < r2) {
                size_t g = 0;
                while (g < r->gone_count && r->gone[g] != x) g++;
                if (g == r->gone_count &&
                    !lh__m2_grow(m, (void **)&r->gone, r->gone_count, &r->gone_cap, g + 1, sizeof(lh_index)))
                    return LH_ERR_NOMEM;
                if (g == r->gone_count) r->gone[r->gone_count++] = x;
            }
            if (n < 0 || m->mark[n] == e || m->sg[3 * u + k] >= 0 ||
                !edge_meets_disc(lh__m2_pt(m, m->v[3 * u + (k + 1) % 3]), lh__m2_pt(m, m->v[3 * u + (k + 2) % 3]), o, r2))
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
 * then crowd the segment (double_hex3.poly at 30 degrees: 75 triangles -> 60). */
static lh_status remove_free_in_circle(rf *r, lh_index s)
{
    lh__m2 *m = r->m;
    const double *a = lh__m2_pt(m, m->sv[2 * (size_t)s]), *b = lh__m2_pt(m, m->sv[2 * (size_t)s + 1]);
    const double o[2] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    lh_status st = free_vertices_in_circle(r, s, o, dist2(a, b) / 4);
    for (size_t g = 0; g < r->gone_count && st == LH_OK; g++) {
        int removed;
        st = lh__m2_remove_vertex(m, r->c, r->gone[g], &removed);
        if (st != LH_OK || !removed) continue;
        r->o->out->steiner_removed++;
        st = after_insert(r);
    }
    return st;
}

static lh_status split_segment(rf *r, lh_index s, int forced, int *done)
{
    lh__m2 *m = r->m;
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    *done = 0;
    if ((size_t)s < r->stuck_count && r->stuck[s]) return LH_OK;
    if (dist2(lh__m2_pt(m, a), lh__m2_pt(m, b)) < r->minlen2) return set_stuck(r, s);
    lh_status st;
    if (forced && (st = remove_free_in_circle(r, s)) != LH_OK) return st;
    double p[2];
    split_point(r, s, p);
    r->ins.check_encroach = 0;
    r->ins.origin = NULL;
    if ((st = lh__m2_insert_point(m, r->c, p, -1, s, &r->ins)) != LH_OK) return st;
    if (r->ins.result != LH__M2_INSERTED) return set_stuck(r, s);
    const double la = sqrt(dist2(p, lh__m2_pt(m, a))), lb = sqrt(dist2(p, lh__m2_pt(m, b)));
    const double w[3] = {lb / (la + lb), la / (la + lb), 0};
    const lh_index from[3] = {a, b, -1};
    set_point_data(r, r->ins.vertex, s, w, from);
    r->steiner++;
    *done = 1;
    return after_insert(r);
}

/* Shewchuk's rule: the shortest edge u-v joins two segments' points on one shell
 * around the input vertex where the segments meet at less than 60 degrees. */
static int on_small_angle_shell(const rf *r, lh_index u, lh_index v)
{
    const lh__m2 *m = r->m;
    const lh_index su = m->pseg[u], sv = m->pseg[v];
    if (su < 0 || sv < 0 || su == sv || !r->o->segments) return 0;
    const lh_index *A = r->o->segments + 2 * (size_t)su, *B = r->o->segments + 2 * (size_t)sv;
    lh_index apex = -1, ea = -1, eb = -1;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            if (r->o->dup[A[i]] == r->o->dup[B[j]]) apex = r->o->dup[A[i]], ea = r->o->dup[A[1 - i]], eb = r->o->dup[B[1 - j]];
    if (apex < 0) return 0;
    const double *o = lh__m2_pt(m, apex), *pa = lh__m2_pt(m, ea), *pb = lh__m2_pt(m, eb);
    const double ax = pa[0] - o[0], ay = pa[1] - o[1], bx = pb[0] - o[0], by = pb[1] - o[1];
    const double cosang = (ax * bx + ay * by) / sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
    if (cosang <= 0.5) return 0; /* 60 degrees or more */
    const double du = dist2(lh__m2_pt(m, u), o), dv = dist2(lh__m2_pt(m, v), o);
    return fabs(du - dv) <= 2e-3 * (du > dv ? du : dv); /* distances within 0.1% */
}

/* The point to insert for bad triangle t: its off-centre or circumcentre. */
static void centre(const rf *r, lh_index t, int by_angle, double *p, lh_index *su, lh_index *sv)
{
    const lh__m2 *m = r->m;
    const lh_index *v = m->v + 3 * (size_t)t;
    int k = 0; /* the shortest edge is opposite vertex k */
    double best = INFINITY;
    for (int j = 0; j < 3; j++) {
        const double l = dist2(lh__m2_pt(m, v[(j + 1) % 3]), lh__m2_pt(m, v[(j + 2) % 3]));
        if (l < best) best = l, k = j;
    }
    *su = v[(k + 1) % 3], *sv = v[(k + 2) % 3];
    /* circumcentre relative to the apex opposite the shortest edge's first point */
    const double *a = lh__m2_pt(m, v[k]), *b = lh__m2_pt(m, v[(k + 1) % 3]), *c = lh__m2_pt(m, v[(k + 2) % 3]);
    const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    const double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
    if (by_angle && r->off_h > 0) {
        /* off-centre: on the bisector of b-c, at off_h * |bc| from its midpoint */
        const double mx = (bx + cx) / 2, my = (by + cy) / 2, dx = ux - mx, dy = uy - my;
        const double dist = sqrt(dx * dx + dy * dy), h = r->off_h * sqrt(best);
        if (dist > h) ux = mx + dx * (h / dist), uy = my + dy * (h / dist);
    }
    p[0] = a[0] + ux;
    p[1] = a[1] + uy;
}

/* Barycentric weights of p in triangle t, for attribute interpolation. */
static void weights(const lh__m2 *m, lh_index ia, lh_index ib, lh_index ic, const double *p,
                    double *w)
{
    const double *a = lh__m2_pt(m, ia), *b = lh__m2_pt(m, ib), *c = lh__m2_pt(m, ic);
    const double den = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    w[1] = ((p[0] - a[0]) * (c[1] - a[1]) - (p[1] - a[1]) * (c[0] - a[0])) / den;
    w[2] = ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / den;
    w[0] = 1 - w[1] - w[2];
}

/* One bad triangle: split at its centre, or its encroached subsegments first. */
static lh_status split_triangle(rf *r, const item *it)
{
    lh__m2 *m = r->m;
    lh_index su, sv;
    double p[2], w[3];
    if (badness(r, it->t) > 0) {
        centre(r, it->t, 1, p, &su, &sv);
        if (on_small_angle_shell(r, su, sv) || dist2(lh__m2_pt(m, su), lh__m2_pt(m, sv)) < r->minlen2)
            return LH_OK;
    } else {
        centre(r, it->t, 0, p, &su, &sv);
    }
    /* walk from the triangle's centroid (inside it unless rounding says otherwise) */
    double g[2];
    const double *ta = lh__m2_pt(m, it->a), *tb = lh__m2_pt(m, it->b), *tc = lh__m2_pt(m, it->c);
    g[0] = (ta[0] + tb[0] + tc[0]) / 3, g[1] = (ta[1] + tb[1] + tc[1]) / 3;
    const int inside = lh__m2_orient_pt(m, it->a, it->b, g) > 0 && lh__m2_orient_pt(m, it->b, it->c, g) > 0 &&
                       lh__m2_orient_pt(m, it->c, it->a, g) > 0;
    r->ins.origin = inside ? g : NULL;
    r->ins.check_encroach = 1;
    lh_status st = lh__m2_insert_point(m, r->c, p, it->t, -1, &r->ins);
    if (st != LH_OK) return st;
    if (r->ins.result == LH__M2_ENCROACHES || r->ins.result == LH__M2_BLOCKED) {
        if (below_floor(r, it->t)) return LH_OK; /* left bad */
        size_t queued = 0;
        const size_t n = r->ins.result == LH__M2_BLOCKED ? 1 : r->ins.enc_count;
        for (size_t i = 0; i < n; i++) {
            const lh_index s = r->ins.result == LH__M2_BLOCKED ? r->ins.blocked : r->ins.enc[i];
            int pos;
            const lh_index t = lh__m2_find_subseg(m, s, &pos);
            if (t >= 0 && splittable(r, s, t, pos)) {
                if ((st = queue_segment(r, s, 1)) != LH_OK) return st;
                queued++;
            }
        }
        if (queued) return queue_triangle(r, it->t);
        if (r->ins.result == LH__M2_BLOCKED) return LH_OK;
        r->ins.check_encroach = 0; /* -Y: the segments stay whole, the point goes in */
        if ((st = lh__m2_insert_point(m, r->c, p, it->t, -1, &r->ins)) != LH_OK) return st;
    }
    r->ins.origin = NULL;
    if (r->ins.result != LH__M2_INSERTED) return LH_OK;
    /* attributes: linear in the split triangle's vertices (extrapolated when the
       centre lies beyond it, as it may) */
    const lh_index from[3] = {it->a, it->b, it->c};
    weights(m, it->a, it->b, it->c, p, w);
    set_point_data(r, r->ins.vertex, -1, w, from);
    r->steiner++;
    return after_insert(r);
}

static int stale(const lh__m2 *m, const item *it)
{
    const lh_index *v = m->v + 3 * (size_t)it->t;
    return v[0] != it->a || v[1] != it->b || v[2] != it->c;
}

static lh_status run(rf *r)
{
    lh__m2 *m = r->m;
    lh_status st;
    for (;;) {
        if (r->steiner >= r->o->max_steiner) {
            r->o->out->steiner_limit_reached = 1;
            return LH_OK;
        }
        if (r->segq_count) {
            const lh_index s = r->segq[2 * (r->segq_count - 1)];
            const int forced = (int)r->segq[2 * (r->segq_count - 1) + 1];
            r->segq_count--;
            lh_index t;
            int pos, done;
            if (!encroached(r, s, &t, &pos) && !forced) continue;
            if ((st = split_segment(r, s, forced, &done)) != LH_OK) return st;
            continue;
        }
        if (!r->heap_count) return LH_OK;
        const item it = r->heap[0];
        r->heap[0] = r->heap[--r->heap_count];
        heap_down(r->heap, r->heap_count, 0);
        if (stale(m, &it)) continue;
        if ((st = split_triangle(r, &it)) != LH_OK) return st;
    }
}

static lh_status start(rf *r)
{
    lh__m2 *m = r->m;
    lh_status st;
    for (size_t s = 0; s < m->ns; s++) {
        lh_index t;
        int pos;
        if (encroached(r, (lh_index)s, &t, &pos) && splittable(r, (lh_index)s, t, pos) &&
            (st = queue_segment(r, (lh_index)s, 0)) != LH_OK)
            return st;
    }
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0 && (st = queue_triangle(r, (lh_index)t)) != LH_OK) return st;
    return LH_OK;
}

lh_status lh__m2_refine(lh__m2 *m, lh__m2_cavity *c, const lh__refine_opts *o)
{
    rf r;
    memset(&r, 0, sizeof r);
    r.m = m, r.c = c, r.o = o;
    if (o->min_angle > 0) {
        const double s = sin(o->min_angle * PI / 180);
        r.ratio2 = 1 / (s * s); /* 4 (R / shortest)^2 > 1 / sin^2 */
        const double cs = cos(o->min_angle * PI / 180);
        r.off_h = 0.475 * sqrt((1 + cs) / (1 - cs));
    }
    /* the lens of the angle bound; with none (area bounds only) the lens is flat, a
       point encroaches only what it lies on (as Triangle does without -q), and only
       centres beyond a subsegment split it */
    const double cs = cos(o->min_angle * PI / 180);
    if (!o->conforming) m->lens = (2 * cs * cs - 1) * (2 * cs * cs - 1);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < m->np; i++)
        for (int j = 0; j < 2; j++) {
            const double x = m->xy[2 * i + j];
            lo[j] = x < lo[j] ? x : lo[j], hi[j] = x > hi[j] ? x : hi[j];
        }
    /* 2^-40 of the larger of the diameter and the largest coordinate: relative to the
       diameter alone it could lie below the rounding of coordinates far from the
       origin (an ulp of 10^6 is 1.2e-10), and splits towards a small angle's apex
       went down onto the grid of doubles, where rounded points keep no shell's shape,
       without end (fuzz/README.md, finding 8) */
    const double mag = fmax(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fabs(lo[1]), fabs(hi[1])));
    r.minlen2 = ldexp(fmax(dist2(lo, hi), mag * mag), -80);
    lh_status st = start(&r);
    if (st == LH_OK) st = run(&r);
    o->out->steiner_points = r.steiner;
    o->out->segments_unsplit = 0;
    for (size_t s = 0; s < r.stuck_count; s++) o->out->segments_unsplit += r.stuck[s];
    lh__free(&m->al, r.heap);
    lh__free(&m->al, r.segq);
    lh__free(&m->al, r.stuck);
    lh__free(&m->al, r.gone);
    lh__free(&m->al, r.ins.enc);
    return st;
}

/* The triangles still bad (bad != NULL: their indices, *count of them). */
lh_status lh__m2_bad_triangles(lh__m2 *m, const lh__refine_opts *o, lh_index *bad, size_t *count)
{
    rf r;
    memset(&r, 0, sizeof r);
    r.m = m, r.o = o;
    if (o->min_angle > 0) {
        const double s = sin(o->min_angle * PI / 180);
        r.ratio2 = 1 / (s * s);
    }
    size_t n = 0;
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0 || badness(&r, (lh_index)t) == 0) continue;
        if (bad) bad[n] = (lh_index)t;
        n++;
    }
    *count = n;
    return LH_OK;
}
