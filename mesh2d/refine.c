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
 * split points and centres are floating-point constructions, each on difference
 * vectors scaled by a power of two (m2_geom.h): no square or product over- or
 * underflows for any finite coordinates, and the mesh of 2^k P is 2^k times the mesh
 * of P while the coordinates of both stay normal.
 */
#include <math.h>
#include <string.h>

#include "m2.h"
#include "m2_geom.h"
#include "refine.h"
#include "refine_rf.h"

#define PI 3.14159265358979323846

/* Triangle t measured scale-free (m2_geom.h). */
static void measure(const lh__m2 *m, lh_index t, lh__g_tri *g)
{
    const lh_index *v = m->v + 3 * (size_t)t;
    lh__g_measure(lh__m2_pt(m, v[0]), lh__m2_pt(m, v[1]), lh__m2_pt(m, v[2]), g);
}

/* The badness of triangle t: 1 for an angle below the bound (radius-edge ratio
 * above 1 / (2 sin bound), i.e. the smallest angle's sine below sin bound), -1 for an
 * area above its bound only, 0 for a good triangle. Scale-free: m2_geom.h. */
static int badness(const rf *r, lh_index t, lh__g_tri *g)
{
    const lh__m2 *m = r->m;
    measure(m, t, g);
    if (r->sin_bound > 0 && g->sin_min < r->sin_bound) return 1;
    double bound = r->o->max_area;
    if (r->o->region_areas && m->tarea && m->tarea[t] > 0 && (bound <= 0 || m->tarea[t] < bound))
        bound = m->tarea[t];
    return lh__g_area_above(g, bound) ? -1 : 0;
}

/* Whether a-b is shorter than the resolution floor. */
static int below_minlen(const rf *r, const double *a, const double *b)
{
    double d[2];
    const int e = lh__g_vec(a, b, d);
    return lh__g_cmp(lh__g_len(d[0], d[1]), e, r->minlen_m, r->minlen_e) < 0;
}

/* Whether x goes before y in the queue. */
static int higher(const item *x, const item *y)
{
    if (x->area_only != y->area_only) return y->area_only;
    return !x->area_only && (x->ke != y->ke ? x->ke < y->ke : x->km < y->km);
}

static void heap_up(item *h, size_t i)
{
    while (i) {
        const size_t p = (i - 1) / 2;
        if (!higher(&h[i], &h[p])) break;
        const item x = h[p];
        h[p] = h[i], h[i] = x, i = p;
    }
}

static void heap_down(item *h, size_t n, size_t i)
{
    for (;;) {
        size_t l = 2 * i + 1, b = i;
        if (l < n && higher(&h[l], &h[b])) b = l;
        if (l + 1 < n && higher(&h[l + 1], &h[b])) b = l + 1;
        if (b == i) return;
        const item x = h[b];
        h[b] = h[i], h[i] = x, i = b;
    }
}

static lh_status queue_triangle(rf *r, lh_index t)
{
    lh__g_tri g;
    const int q = badness(r, t, &g);
    if (q == 0) return LH_OK;
    if (!lh__m2_grow(r->m, (void **)&r->heap, r->heap_count, &r->heap_cap, r->heap_count + 1, sizeof(item)))
        return LH_ERR_NOMEM;
    const lh_index *v = r->m->v + 3 * (size_t)t;
    /* the triangle with the shortest shortest edge first (angle-bad ones; then those
       only too large): small features fix their neighbourhoods' sizes before larger
       triangles are split, which leaves fewer triangles than the worst angle first
       (docs/meshing.md; Shewchuk 1996 §3 compares worst-first with first-in first-out) */
    long ke;
    const double km = lh__g_norm(g.len[g.k], g.e, &ke);
    r->heap[r->heap_count] = (item){q < 0, ke, km, t, v[0], v[1], v[2]};
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
    const double *a = lh__m2_pt(m, m->sv[2 * (size_t)s]), *q[2] = {lh__m2_pt(m, m->sv[2 * (size_t)s + 1]), p};
    double v[2][2];
    lh__g_vecs(a, q, 2, v);
    const double cr = lh__g_cross(v[0], v[1]), l2 = v[0][0] * v[0][0] + v[0][1] * v[0][1];
    return fabs(cr) >= ldexp(l2, -40); /* distance = |cr| / |ab| */
}

/* Whether triangle t is a sliver below the resolution floor: its smallest altitude
 * (twice its area over its longest edge) under 2^-40 of its longest edge, an angle
 * under 2^-40 radians. Its rejected centre forces no split (see
 * encroaches_resolvably); it is left, and reported. */
static int below_floor(const rf *r, lh_index t)
{
    lh__g_tri g;
    measure(r->m, t, &g);
    const double lmax = fmax(g.len[0], fmax(g.len[1], g.len[2]));
    return g.area2 < ldexp(lmax * lmax, -40);
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
lh_status lh__rf_after_insert(rf *r)
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

static lh_status split_segment(rf *r, lh_index s, int forced, int *done)
{
    lh__m2 *m = r->m;
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    *done = 0;
    if ((size_t)s < r->stuck_count && r->stuck[s]) return LH_OK;
    if (below_minlen(r, lh__m2_pt(m, a), lh__m2_pt(m, b))) return set_stuck(r, s);
    lh_status st;
    if (forced && (st = lh__rf_remove_free(r, s)) != LH_OK) return st;
    double p[2];
    lh__rf_split_point(r, s, p);
    r->ins.check_encroach = 0;
    r->ins.origin = NULL;
    if ((st = lh__m2_insert_point(m, r->c, p, -1, s, &r->ins)) != LH_OK) return st;
    if (r->ins.result != LH__M2_INSERTED) return set_stuck(r, s);
    const double *q[2] = {lh__m2_pt(m, a), lh__m2_pt(m, b)};
    double d[2][2];
    lh__g_vecs(p, q, 2, d);
    const double la = lh__g_len(d[0][0], d[0][1]), lb = lh__g_len(d[1][0], d[1][1]);
    const double w[3] = {lb / (la + lb), la / (la + lb), 0};
    const lh_index from[3] = {a, b, -1};
    lh__rf_point_data(r, r->ins.vertex, s, w, from);
    r->steiner++;
    *done = 1;
    return lh__rf_after_insert(r);
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
    const double *o = lh__m2_pt(m, apex);
    if (lh__g_cos(o, lh__m2_pt(m, ea), lh__m2_pt(m, eb)) <= 0.5) return 0; /* 60 degrees or more */
    const double *q[2] = {lh__m2_pt(m, u), lh__m2_pt(m, v)};
    double d[2][2];
    lh__g_vecs(o, q, 2, d);
    const double du = d[0][0] * d[0][0] + d[0][1] * d[0][1], dv = d[1][0] * d[1][0] + d[1][1] * d[1][1];
    return fabs(du - dv) <= 2e-3 * (du > dv ? du : dv); /* distances within 0.1% */
}

/* The point to insert for bad triangle t: its off-centre or circumcentre. With b-c
 * the shortest edge and a the corner opposite (the smallest angle, alpha), the
 * circumcentre lies on the bisector of b-c, |bc| cot(alpha) / 2 from its midpoint
 * towards a; the off-centre (Üngör 2004) no further than off_h |bc|. Computed in the
 * triangle's scaled frame (m2_geom.h), so no circumcentre ever overflows: a sliver's
 * is put 2^60 |bc| away at most. */
static void centre(const rf *r, lh_index t, int by_angle, double *p, lh_index *su, lh_index *sv)
{
    const lh__m2 *m = r->m;
    const lh_index *v = m->v + 3 * (size_t)t;
    lh__g_tri g;
    measure(m, t, &g);
    const int k = g.k, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    *su = v[k1], *sv = v[k2];
    const double *u = g.d[k2], w[2] = {-g.d[k1][0], -g.d[k1][1]}, *bc = g.d[k]; /* a->b, a->c, b->c */
    double h = lh__g_dot(u, w) / g.area2 / 2;
    if (by_angle && r->off_h > 0 && h > r->off_h) h = r->off_h;
    if (!(h <= 0x1p60)) h = 0x1p60;
    const double *a = lh__m2_pt(m, v[k]);
    p[0] = a[0] + ldexp((u[0] + w[0]) / 2 - bc[1] * h, g.e);
    p[1] = a[1] + ldexp((u[1] + w[1]) / 2 + bc[0] * h, g.e);
}

/* Barycentric weights of p in triangle t, for attribute interpolation. */
static void weights(const lh__m2 *m, lh_index ia, lh_index ib, lh_index ic, const double *p,
                    double *w)
{
    const double *q[3] = {lh__m2_pt(m, ib), lh__m2_pt(m, ic), p};
    double d[3][2]; /* b - a, c - a, p - a, scaled together: the ratios are scale-free */
    lh__g_vecs(lh__m2_pt(m, ia), q, 3, d);
    const double den = lh__g_cross(d[0], d[1]);
    w[1] = lh__g_cross(d[2], d[1]) / den;
    w[2] = lh__g_cross(d[0], d[2]) / den;
    w[0] = 1 - w[1] - w[2];
}

/* One bad triangle: split at its centre, or its encroached subsegments first. */
static lh_status split_triangle(rf *r, const item *it)
{
    lh__m2 *m = r->m;
    lh_index su, sv;
    double p[2], w[3];
    lh__g_tri gt;
    if (badness(r, it->t, &gt) > 0) {
        centre(r, it->t, 1, p, &su, &sv);
        if (on_small_angle_shell(r, su, sv) || below_minlen(r, lh__m2_pt(m, su), lh__m2_pt(m, sv))) return LH_OK;
    } else {
        centre(r, it->t, 0, p, &su, &sv);
    }
    /* walk from the triangle's centroid (inside it unless rounding says otherwise) */
    double g[2], d[2][2];
    const double *ta = lh__m2_pt(m, it->a), *tbc[2] = {lh__m2_pt(m, it->b), lh__m2_pt(m, it->c)};
    const int e = lh__g_vecs(ta, tbc, 2, d);
    g[0] = ta[0] + ldexp((d[0][0] + d[1][0]) / 3, e), g[1] = ta[1] + ldexp((d[0][1] + d[1][1]) / 3, e);
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
    lh__rf_point_data(r, r->ins.vertex, -1, w, from);
    r->steiner++;
    return lh__rf_after_insert(r);
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
        if (r->budget && r->steiner >= r->budget) {
            r->o->out->steiner_budget_reached = 1;
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

/* The Steiner budget above the provable angle bound, where refinement may add points
 * without end. A quality mesh grades from each
 * feature geometrically, so its size grows with the logarithm of the feature sizes'
 * ratios: each triangle t of the mesh before refinement allows 64 (1 + log2 of its
 * longest edge squared over its area) points, plus 4 per multiple of its area bound
 * that its area is, plus 1024 (docs/meshing.md compares it with what Triangle's
 * example inputs take at 34 degrees). */
static size_t budget(const rf *r)
{
    const lh__m2 *m = r->m;
    double sum = 1024;
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0) continue;
        lh__g_tri g;
        measure(m, (lh_index)t, &g);
        const double lmax = fmax(g.len[0], fmax(g.len[1], g.len[2]));
        sum += 64 * (1 + log2(lmax * lmax / g.area2));
        double bound = r->o->max_area;
        if (r->o->region_areas && m->tarea && m->tarea[t] > 0 && (bound <= 0 || m->tarea[t] < bound))
            bound = m->tarea[t];
        if (bound > 0) sum += 4 * ldexp(g.area2 / 2 / bound, 2 * g.e);
    }
    return sum < 0x1p62 ? (size_t)sum : SIZE_MAX;
}

void lh__m2_length_floor(const lh__m2 *m, double *fm, long *fe)
{
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
    double d[2];
    const int e = lh__g_vec(lo, hi, d);
    const double diam = lh__g_len(d[0], d[1]);
    const int by_diam = lh__g_cmp(diam, e, mag, 0) > 0;
    *fm = by_diam ? diam : mag, *fe = (by_diam ? e : 0) - 40;
}

lh_status lh__m2_refine(lh__m2 *m, lh__m2_cavity *c, const lh__refine_opts *o)
{
    rf r;
    memset(&r, 0, sizeof r);
    r.m = m, r.c = c, r.o = o;
    if (o->min_angle > 0) {
        r.sin_bound = sin(o->min_angle * PI / 180);
        const double cs = cos(o->min_angle * PI / 180);
        r.off_h = 0.475 * sqrt((1 + cs) / (1 - cs));
    }
    /* the lens of the angle bound; with none (area bounds only) the lens is flat, a
       point encroaches only what it lies on (as Triangle does without -q), and only
       centres beyond a subsegment split it */
    const double cs = cos(o->min_angle * PI / 180);
    if (!o->conforming) m->lens = (2 * cs * cs - 1) * (2 * cs * cs - 1);
    lh__m2_length_floor(m, &r.minlen_m, &r.minlen_e);
    if (o->min_angle > LH_TRIMESH_PROVABLE_ANGLE) r.budget = o->out->steiner_budget = budget(&r);
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
    if (o->min_angle > 0) r.sin_bound = sin(o->min_angle * PI / 180);
    size_t n = 0;
    for (size_t t = 0; t < m->nt; t++) {
        lh__g_tri g;
        if (m->v[3 * t] < 0 || badness(&r, (lh_index)t, &g) == 0) continue;
        if (bad) bad[n] = (lh_index)t;
        n++;
    }
    *count = n;
    return LH_OK;
}
