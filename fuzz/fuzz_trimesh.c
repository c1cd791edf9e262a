/*
 * fuzz_trimesh.c — libFuzzer target: lh_pslg_triangulate on small fuzzer-chosen PSLGs.
 * 3..40 vertices on the integer grid -8..8 (so collinear, cocircular and duplicate
 * vertices are common), mapped exactly by (x + offset) * 2^k (offset 0, 1e6 or 2^40:
 * the predicates' exact stages); a ring through the first r vertices and up to 60
 * segments between chosen vertices (zero-length, overlapping, crossing, through other
 * vertices), optionally only those that cross no earlier one; 0..3 hole seeds and
 * regions on the half-integer grid; even_odd, convex_hull, conforming,
 * split_crossings, min_angle in {0, 20, 25, 30, 33}, max_area and regional areas,
 * boundary_steiner 1/0/-1, max_steiner small or at most 5000 (so that no run is
 * long), 0..3 smoothing passes, a vertex attribute, and sometimes the segments' lines
 * of a file (the message then names them).
 *
 * The status must be what the input calls for, decided here exactly on the integer
 * grid: LH_ERR_DEGENERATE with "collinear" exactly when all vertices are collinear or
 * fewer than 3 distinct; else LH_ERR_CROSSING_SEGMENTS, "crosses", when two segments
 * cross (their interiors meet in one point that is no vertex), always without
 * split_crossings and never when none do, the message naming an earlier segment that
 * the later one crosses, with their lines (with split_crossings: two segments, README
 * finding 9); else, with even_odd,
 * "vertex V ends an odd number of segments" exactly when some vertex does (V the
 * first, duplicates merged); else LH_OK or the empty-domain message (never with the
 * convex hull kept and no hole). Never LH_ERR_INTERNAL, LH_ERR_INVALID_ARGUMENT or
 * LH_ERR_NOMEM. On LH_OK, with an empty message:
 *   - lh_cdt_check passes (boundary_free = 0); with conforming alone (no bound,
 *     crossing split, smoothing move, limit or unsplit subsegment), also with no
 *     subsegments (every edge Delaunay);
 *   - indices in range, neighbours symmetric across the same edge, -1 only on
 *     subsegments; the input vertices first and unchanged; a vertex equal to an
 *     earlier one in no triangle, duplicates_merged their count; a subsegment's input
 *     vertices on its parent segment, parent -1 only where the hull is kept;
 *   - no Steiner point but crossings, and no unsplit subsegment, unless refinement
 *     was asked; stats.triangles, steiner_points, crossings_split and
 *     steiner_limit_reached consistent with
 *     max_steiner (which counts refinement's points); the bad list increasing, and
 *     every triangle not on it within the angle and area bounds (measured here);
 *     min_angle at least the bound and max_area at most the global bound unless
 *     bad_triangles > 0, the Steiner limit was reached or boundary_steiner != 1;
 *   - interpolated attributes finite, the input's unchanged; triangle attributes
 *     exactly with region_attributes;
 *   - with the convex hull kept and no hole seed, the triangles' areas sum to the
 *     hull's (exactly on the grid without Steiner points, within the rounding of the
 *     points put on segments and hull edges otherwise);
 *   - a second run gives the same arrays byte for byte; with smoothing, the smallest
 *     angle is at least that of a run without it.
 * Every run's allocations are counted (fuzz_common.h): nothing may leak; a third run
 * failing one chosen allocation must return LH_ERR_NOMEM (or succeed identically).
 * The byte after the PSLG's may ask for the cover stage (refine_cover): the mesh made,
 * refined as Triangle's -r refines a .node/.ele, under the same checks.
 * Anything else aborts. Build as fuzz_delaunay.c (fuzz/README.md); with
 * -DLH_FUZZ_TRIMESH_VERBOSE an input's PSLG, options and outcome go to stderr.
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXV 40
#define MAXS (MAXV + 60)

typedef struct src { const uint8_t *p; size_t n, at; } src;

static unsigned get(src *s) { return s->at < s->n ? s->p[s->at++] : 0; }

/* A counting allocator that fails call number fail_at (0: never). */
typedef struct counter { long live, calls, fail_at, failed; } counter;

static void *count_alloc(void *user, size_t size)
{
    counter *c = user;
    if (++c->calls == c->fail_at) {
        c->failed = 1;
        return NULL;
    }
    return lh_fuzz_count_alloc(&c->live, size);
}

static void count_free(void *user, void *ptr)
{
    if (ptr) lh_fuzz_count_free(&((counter *)user)->live, ptr);
}

typedef struct grid { long long x, y; } grid;

static long long orient(grid a, grid b, grid c)
{
    const long long d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (d > 0) - (d < 0);
}

/* c on the closed segment a-b (exactly). */
static int on_segment(grid a, grid b, grid c)
{
    return orient(a, b, c) == 0 && (c.x - a.x) * (c.x - b.x) <= 0 && (c.y - a.y) * (c.y - b.y) <= 0;
}

/* Segments a-b and c-d cross: their interiors meet in one point that is no vertex. */
static int cross(const grid *v, size_t n, grid a, grid b, grid c, grid d)
{
    if (orient(a, b, c) * orient(a, b, d) >= 0 || orient(c, d, a) * orient(c, d, b) >= 0) return 0;
    for (size_t i = 0; i < n; i++)
        if (on_segment(a, b, v[i]) && on_segment(c, d, v[i])) return 0;
    return 1;
}

/* Twice the area of the convex hull of v[0..n-1] (Andrew's monotone chain). */
static int grid_cmp(const void *x, const void *y)
{
    const grid *a = x, *b = y;
    return a->x != b->x ? (a->x > b->x) - (a->x < b->x) : (a->y > b->y) - (a->y < b->y);
}

static long long hull_area2(const grid *v, size_t n)
{
    grid p[MAXV], h[2 * MAXV + 2];
    memcpy(p, v, n * sizeof *p);
    qsort(p, n, sizeof *p, grid_cmp);
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    for (size_t i = n - 1, t = k + 1; i-- > 0;) {
        while (k >= t && orient(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    long long a = 0;
    for (size_t i = 0; i + 1 < k; i++) a += h[i].x * h[i + 1].y - h[i + 1].x * h[i].y;
    return a;
}

typedef struct input {
    lh_pslg g;
    lh_trimesh_options o;
    grid v[MAXV];
    double xy[2 * MAXV], attr[MAXV], holes[6], regions[12], off, scale;
    lh_index seg[2 * MAXS];
    size_t seg_line[MAXS];
    int crossing, collinear, keep_hull, refine, fail_mode;
    lh_index open;         /* the first vertex ending an odd number of segments, or -1 */
    size_t dups;
    unsigned fail_pick, cover; /* cover: the byte after the PSLG's (refine_cover) */
} input;

static const double angles[8] = {0, 20, 25, 30, 33, 0, 20, 30};

static void decode(const uint8_t *data, size_t size, input *in)
{
    src s = {data, size, 0};
    memset(in, 0, sizeof *in);
    const unsigned f0 = get(&s), f1 = get(&s), f2 = get(&s), kb = get(&s), nvb = get(&s),
                   nsb = get(&s), ring = get(&s);
    in->fail_mode = f0 >> 7;
    in->fail_pick = get(&s) << 8;
    in->fail_pick |= get(&s);
    const int k = (int8_t)kb / 2; /* 2^-64 .. 2^63 */
    const int mode = f2 & 3;
    in->scale = mode & 1 ? ldexp(1.0, k) : 1;
    in->off = mode & 2 ? (f2 & 4 ? 0x1p40 : 1e6) : 0;
    lh_pslg *g = &in->g;
    lh_trimesh_options *o = &in->o;
    lh_trimesh_options_default(o);
    g->even_odd = f0 & 1;
    o->convex_hull = (f0 >> 1) & 1;
    o->conforming = (f0 >> 2) & 1;
    const int noncrossing = (f0 >> 3) & 1;
    o->min_angle = angles[(f0 >> 4) & 7];
    const int bs = f1 & 3;
    o->boundary_steiner = bs < 2 ? 1 : bs == 2 ? 0 : -1;
    const double unit = in->scale * in->scale; /* areas scale with 4^k */
    static const double areas[4] = {0, 0.5, 2, 8};
    o->max_area = areas[(f1 >> 2) & 3] * unit;
    const int ms = (f1 >> 4) & 3;
    o->max_steiner = ms == 1 ? (size_t)(kb & 15) : ms == 2 ? 64 : 5000;
    o->region_areas = (f1 >> 6) & 1;
    o->region_attributes = f1 >> 7;
    o->split_crossings = ring >> 7;
    o->smooth = (int)(in->fail_pick >> 14); /* 0..3 passes */

    const size_t n = 3 + nvb % (MAXV - 2);
    g->n = n;
    g->xy = in->xy;
    for (size_t i = 0; i < n; i++) {
        in->v[i].x = (long long)(get(&s) % 17) - 8;
        in->v[i].y = (long long)(get(&s) % 17) - 8;
        in->xy[2 * i] = ((double)in->v[i].x + in->off) * in->scale;
        in->xy[2 * i + 1] = ((double)in->v[i].y + in->off) * in->scale;
        in->attr[i] = (double)i;
        for (size_t j = 0; j < i; j++)
            if (in->v[j].x == in->v[i].x && in->v[j].y == in->v[i].y) {
                in->dups++;
                break;
            }
    }
    if (f2 >> 7) {
        g->attr_count = 1;
        g->attr = in->attr;
    }
    /* segments: a ring through the first r vertices, then chosen pairs */
    size_t ns = 0;
    const size_t r = (ring & 63) < n ? (ring & 63) : n, extra = nsb % 61;
    for (size_t i = 0; i < r + extra; i++) {
        lh_index a, b;
        if (i < r) {
            a = (lh_index)i, b = (lh_index)((i + 1) % r);
        } else {
            a = (lh_index)(get(&s) % n);
            b = (lh_index)(get(&s) % n);
        }
        int c = 0;
        for (size_t j = 0; j < ns && !c; j++)
            c = cross(in->v, n, in->v[a], in->v[b], in->v[in->seg[2 * j]], in->v[in->seg[2 * j + 1]]);
        if (c && noncrossing) continue;
        in->crossing |= c;
        in->seg[2 * ns] = a;
        in->seg[2 * ns++ + 1] = b;
    }
    g->segment_count = ns;
    g->segments = ns ? in->seg : NULL;
    if (ring & 64) { /* as from a reader: numbered from 1, each segment with its line */
        g->first_index = 1;
        for (size_t i = 0; i < ns; i++) in->seg_line[i] = 100 + 2 * i;
        g->segment_line = ns ? in->seg_line : NULL;
    }
    g->hole_count = (f2 >> 3) & 3;
    g->holes = g->hole_count ? in->holes : NULL;
    for (size_t i = 0; i < 2 * g->hole_count; i++)
        in->holes[i] = ((double)(get(&s) % 33) / 2 - 8 + in->off) * in->scale;
    g->region_count = (f2 >> 5) & 3;
    g->regions = g->region_count ? in->regions : NULL;
    for (size_t i = 0; i < g->region_count; i++) {
        double *q = in->regions + 4 * i;
        q[0] = ((double)(get(&s) % 33) / 2 - 8 + in->off) * in->scale;
        q[1] = ((double)(get(&s) % 33) / 2 - 8 + in->off) * in->scale;
        const unsigned b = get(&s);
        q[2] = (double)(b >> 2);
        q[3] = areas[b & 3] * unit - (b & 3 ? 0 : 1);
    }
    in->collinear = 1;
    for (size_t i = 2; i < n && in->collinear; i++)
        for (size_t j = 1; j < i && in->collinear; j++)
            if (orient(in->v[0], in->v[j], in->v[i])) in->collinear = 0;
    in->keep_hull = !g->even_odd && (o->convex_hull || ns == 0);
    unsigned char odd[MAXV] = {0};
    for (size_t i = 0; i < 2 * ns; i++) {
        size_t a = (size_t)in->seg[i];
        for (size_t j = 0; j < a; j++)
            if (in->v[j].x == in->v[a].x && in->v[j].y == in->v[a].y) {
                a = j;
                break;
            }
        odd[a] ^= 1;
    }
    in->open = -1;
    for (size_t i = n; i-- > 0;)
        if (odd[i]) in->open = (lh_index)i;
    in->refine = o->min_angle > 0 || o->max_area > 0 || o->region_areas || o->conforming;
    in->cover = get(&s); /* after everything else: the inputs written before it mean the same */
}

static int same(const lh_trimesh *a, const lh_trimesh *b)
{
    const size_t np = lh_trimesh_point_count(a), nt = lh_trimesh_triangle_count(a),
                 ns = lh_trimesh_segment_count(a);
    lh_trimesh_stats sa, sb;
    lh_trimesh_stats_get(a, &sa);
    lh_trimesh_stats_get(b, &sb);
    return np == lh_trimesh_point_count(b) && nt == lh_trimesh_triangle_count(b) &&
           ns == lh_trimesh_segment_count(b) && !memcmp(&sa, &sb, sizeof sa) &&
           !memcmp(lh_trimesh_points(a), lh_trimesh_points(b), 2 * np * sizeof(double)) &&
           !memcmp(lh_trimesh_triangles(a), lh_trimesh_triangles(b), 3 * nt * sizeof(lh_index)) &&
           !memcmp(lh_trimesh_neighbors(a), lh_trimesh_neighbors(b), 3 * nt * sizeof(lh_index)) &&
           !memcmp(lh_trimesh_segments(a), lh_trimesh_segments(b), 2 * ns * sizeof(lh_index)) &&
           !memcmp(lh_trimesh_segment_parents(a), lh_trimesh_segment_parents(b), ns * sizeof(lh_index)) &&
           !memcmp(lh_trimesh_bad_triangles(a), lh_trimesh_bad_triangles(b), sa.bad_triangles * sizeof(lh_index));
}

/* "[LINE: ]segment S crosses segment O[ (line L)]": S and O numbered from first_index
 * name two segments that cross, O before S, with their lines when the PSLG has them. */
static void check_crossing(const input *in, const char *msg)
{
    const lh_pslg *g = &in->g;
    long long s, o;
    size_t ls = 0, lo = 0;
    int used = 0;
    if (g->segment_line ? sscanf(msg, "%zu: segment %lld crosses segment %lld (line %zu)%n", &ls, &s, &o, &lo, &used) != 4
                        : sscanf(msg, "segment %lld crosses segment %lld%n", &s, &o, &used) != 2)
        abort();
    s -= g->first_index, o -= g->first_index;
    if (msg[used] || o < 0 || o >= s || s >= (long long)g->segment_count) abort();
    if (g->segment_line && (ls != g->segment_line[s] || lo != g->segment_line[o])) abort();
    /* with split_crossings the error comes when a rounded crossing cannot go in; the
       chains are bent at earlier crossings then, so the two need not cross exactly
       (a segment through a vertex of the other, missed after a bend: README, finding 9) */
    const lh_index *S = g->segments + 2 * s, *O = g->segments + 2 * o;
    if (!in->o.split_crossings && !cross(in->v, g->n, in->v[S[0]], in->v[S[1]], in->v[O[0]], in->v[O[1]]))
        abort();
    (void)lh_fuzz_check_message; /* the readers' contract; unused here */
}

static lh_status run(const input *in, counter *c, lh_trimesh **m, char *msg, size_t size)
{
    lh_allocator al = {count_alloc, count_free, c};
    lh_trimesh_options o = in->o;
    o.alloc = &al;
    return lh_pslg_triangulate(&in->g, &o, m, msg, size);
}

/* The checks of a successful run (the header's list). */
/* lh_cdt_check passes; indices in range, neighbours symmetric across the same
 * edge, -1 only on subsegments. */
static void check_links(const lh_trimesh *m)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m), ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *nb = lh_trimesh_neighbors(m), *seg = lh_trimesh_segments(m);
    char msg[256];
    if (!nt || lh_cdt_check(np, xy, nt, tri, ns, seg, 0, NULL, msg, sizeof msg) != LH_OK) {
#ifdef LH_FUZZ_TRIMESH_VERBOSE
        fprintf(stderr, "lh_cdt_check: %s\n", msg);
#endif
        abort();
    }
    for (size_t i = 0; i < 3 * nt; i++)
        if (tri[i] < 0 || (size_t)tri[i] >= np || nb[i] < -1 || nb[i] >= (lh_index)nt) abort();
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            const lh_index a = tri[3 * t + (k + 1) % 3], b = tri[3 * t + (k + 2) % 3], u = nb[3 * t + k];
            int on_seg = 0;
            for (size_t s = 0; s < ns && !on_seg; s++)
                on_seg = (seg[2 * s] == a && seg[2 * s + 1] == b) || (seg[2 * s] == b && seg[2 * s + 1] == a);
            if (u < 0) {
                if (!on_seg) abort();
                continue;
            }
            int back = -1;
            for (int j = 0; j < 3; j++)
                if (nb[3 * (size_t)u + j] == (lh_index)t) back = j;
            if (back < 0 || tri[3 * (size_t)u + (back + 1) % 3] != b || tri[3 * (size_t)u + (back + 2) % 3] != a)
                abort();
        }
}

/* The bad list increasing, and every triangle not on it within o's angle and global
 * area bounds (measured here by atan2); the extremes within them unless refinement
 * was stopped. */
static void check_bounds(const lh_trimesh_options *o, const lh_trimesh *m, const lh_trimesh_stats *st)
{
    const size_t nt = lh_trimesh_triangle_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *bad = lh_trimesh_bad_triangles(m);
    for (size_t i = 0; i < st->bad_triangles; i++)
        if (bad[i] < 0 || (size_t)bad[i] >= nt || (i && bad[i] <= bad[i - 1])) abort();
    const int stopped = st->bad_triangles > 0 || st->steiner_limit_reached || o->boundary_steiner != 1;
    if (!stopped && o->min_angle > 0 && st->min_angle < o->min_angle - 1e-6) abort();
    if (!stopped && o->max_area > 0 && st->max_area > o->max_area * (1 + 1e-9)) abort();
    for (size_t t = 0, b = 0; t < nt; t++) {
        if (b < st->bad_triangles && (size_t)bad[b] == t) {
            b++;
            continue;
        }
        const double *q[3];
        for (int k = 0; k < 3; k++) q[k] = xy + 2 * (size_t)tri[3 * t + k];
        double small = 180;
        for (int k = 0; k < 3; k++) {
            const double ux = q[(k + 1) % 3][0] - q[k][0], uy = q[(k + 1) % 3][1] - q[k][1];
            const double vx = q[(k + 2) % 3][0] - q[k][0], vy = q[(k + 2) % 3][1] - q[k][1];
            const double a = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180 / 3.14159265358979323846);
            small = a < small ? a : small;
        }
        const double area = ((q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0])) / 2;
        if ((o->min_angle > 0 && small < o->min_angle - 1e-6) || (o->max_area > 0 && area > o->max_area * (1 + 1e-9)))
            abort();
    }
}

/* Twice the area of m's triangles in grid units (exact but for the long double sums
 * of points off the grid); *moved: the points from `from` on that end subsegments. */
static long double grid_area2(const input *in, const lh_trimesh *m, size_t from, size_t *moved)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m), ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *seg = lh_trimesh_segments(m);
    long double got = 0;
    for (size_t t = 0; t < nt; t++) {
        long double q[3][2];
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 2; j++)
                q[k][j] = (long double)xy[2 * (size_t)tri[3 * t + k] + j] / in->scale - in->off;
        got += (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    }
    unsigned char *on = calloc(np, 1);
    if (!on) abort();
    *moved = 0;
    for (size_t s = 0; s < 2 * ns; s++)
        if ((size_t)seg[s] >= from && !on[seg[s]]) on[seg[s]] = 1, ++*moved;
    free(on);
    return got;
}

/* Points put on segments (and on hull or old boundary edges) are within an ulp of
 * them: each moves the area by at most about an ulp of the coordinates times the
 * grid's size. */
static void check_area(const input *in, long double want, long double got, size_t moved)
{
    const double ulp = ldexp(1.0, -52) * (in->off + 8) * 64;
    if (fabsl(got - want) > (long double)moved * ulp + 1e-9L * want) abort();
}

static void check_mesh(const input *in, const lh_trimesh *m)
{
    const lh_pslg *g = &in->g;
    const size_t n = g->n, np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m),
                 ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *seg = lh_trimesh_segments(m), *par = lh_trimesh_segment_parents(m);
    char msg[256];
    if (np < n || memcmp(xy, g->xy, 2 * n * sizeof(double))) abort();
    check_links(m);
    /* a merged duplicate (equal to an earlier vertex) is in no triangle */
    for (size_t i = 0; i < 3 * nt; i++)
        if ((size_t)tri[i] < n)
            for (size_t j = 0; j < (size_t)tri[i]; j++)
                if (in->v[j].x == in->v[tri[i]].x && in->v[j].y == in->v[tri[i]].y) abort();
    for (size_t s = 0; s < ns; s++) {
        const lh_index p = par[s];
        if (p < -1 || p >= (lh_index)g->segment_count || (p < 0 && !in->keep_hull)) abort();
        for (int j = 0; j < 2 && p >= 0; j++) {
            const lh_index x = seg[2 * s + j];
            if ((size_t)x < n && !on_segment(in->v[g->segments[2 * p]], in->v[g->segments[2 * p + 1]], in->v[x]))
                abort();
        }
    }
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    const lh_trimesh_options *o = &in->o;
    if (st.input_vertices != n || st.duplicates_merged != in->dups || st.triangles != nt ||
        st.steiner_points != np - n || st.crossings_split > st.steiner_on_segments ||
        (st.crossings_split && !(in->crossing && o->split_crossings)) ||
        st.steiner_points - st.crossings_split > o->max_steiner ||
        /* the budget counts the points refinement inserted, removed again (Chew's rule) or not */
        (st.steiner_limit_reached && st.steiner_points + st.steiner_removed - st.crossings_split != o->max_steiner) ||
        (!in->refine && (st.steiner_points != st.crossings_split || st.steiner_removed || st.segments_unsplit)) ||
        st.steiner_on_segments > st.steiner_points ||
        (!o->smooth && st.smoothing_moves))
        abort();
    check_bounds(o, m, &st);
    /* conforming alone: every edge Delaunay. Not with crossings split (rounding beside
       chains bent at rounded crossings leaves some subsegments unsplittable), with an
       angle or area bound (splits towards a small angle's apex stop at the minimum
       length, a subsegment there still encroached) or with smoothing (it restores the
       constrained Delaunay property only), nor with subsegments refinement could not
       split (README finding 10: unit features at 2^40, the resolution floor) */
    if (o->conforming && !st.steiner_limit_reached && !st.segments_unsplit && o->boundary_steiner == 1 &&
        !st.crossings_split && o->min_angle == 0 && o->max_area <= 0 && !o->region_areas && !st.smoothing_moves &&
        lh_cdt_check(np, xy, nt, tri, 0, NULL, 1, NULL, msg, sizeof msg) != LH_OK)
        abort();
    if ((o->region_attributes != 0) != (lh_trimesh_triangle_attrs(m) != NULL)) abort();
    const double *pa = lh_trimesh_point_attrs(m);
    if (g->attr_count) {
        if (!pa || lh_trimesh_point_attr_count(m) != 1) abort();
        for (size_t p = 0; p < np; p++)
            if (!isfinite(pa[p]) || (p < n && pa[p] != in->attr[p])) abort();
    }
    if (in->keep_hull && !g->hole_count) {
        grid v[MAXV];
        memcpy(v, in->v, n * sizeof *v);
        size_t moved;
        const long double got = grid_area2(in, m, n, &moved);
        check_area(in, (long double)hull_area2(v, n), got, moved);
    }
}

/* The refinement of a mesh (the cover stage): the old points first and unchanged,
 * the checks of check_links and check_bounds, subsegment parents the old segments' or
 * -1 (old boundary edges), the statistics consistent, the old union kept, and the
 * attributes interpolated finite. */
static void check_refined(const input *in, const lh_pslg *g, const lh_trimesh_options *o, const lh_trimesh *old,
                          const lh_trimesh *m)
{
    const size_t n = g->n, np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m),
                 ns = lh_trimesh_segment_count(m);
    const lh_index *par = lh_trimesh_segment_parents(m);
    if (np < n || memcmp(lh_trimesh_points(m), g->xy, 2 * n * sizeof(double))) abort();
    check_links(m);
    for (size_t s = 0; s < ns; s++)
        if (par[s] < -1 || par[s] >= (lh_index)g->segment_count) abort();
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    if (st.input_vertices != n || st.triangles != nt || st.steiner_points != np - n || st.crossings_split ||
        st.steiner_points > o->max_steiner ||
        (st.steiner_limit_reached && st.steiner_points + st.steiner_removed != o->max_steiner) ||
        st.steiner_on_segments > st.steiner_points || (!o->smooth && st.smoothing_moves))
        abort();
    check_bounds(o, m, &st);
    size_t moved, ignored;
    const long double got = grid_area2(in, m, n, &moved), want = grid_area2(in, old, n, &ignored);
    check_area(in, want, got, moved);
    const double *pa = lh_trimesh_point_attrs(m);
    if (g->attr_count) {
        if (!pa || lh_trimesh_point_attr_count(m) != 1) abort();
        for (size_t p = 0; p < np; p++)
            if (!isfinite(pa[p]) || (p < n && pa[p] != g->attr[p])) abort();
    }
}

/* A run failing allocation number 1 + fail_pick % calls (calls: the first run's) must
 * return LH_ERR_NOMEM and nothing, or succeed with m's arrays, leaking nothing. */
static void check_failure(const input *in, const lh_trimesh *m, long calls)
{
    if (calls <= 0) return;
    counter c3 = {0, 0, 1 + (long)(in->fail_pick % (unsigned long)calls), 0};
    lh_trimesh *m3 = NULL;
    char msg[256];
    const lh_status s3 = run(in, &c3, &m3, msg, sizeof msg);
    if (!c3.failed || (s3 == LH_OK ? !same(m, m3) : s3 != LH_ERR_NOMEM || m3)) abort();
    lh_trimesh_free(m3);
    if (c3.live) abort();
}

/* The cover stage (Triangle's -r), when bit 0 of in->cover is set: the mesh `old`
 * refined with its triangles as lh_pslg.cover, its points (and attributes) as the
 * vertices; bit 1: its subsegments as segments too (-rp); bits 2-3: the old
 * triangles' area bounds (none, or 0.5, 2, 8 and none in turn from a start they
 * choose); bits 4-6: the angle bound; bit 7: the global area bound 2. The other
 * options are the first run's. It must succeed (the old mesh passed the checks) and
 * pass check_refined, a second run equal byte for byte, nothing leaking, and with
 * fail_mode a run failing one chosen allocation returning LH_ERR_NOMEM. */
static void refine_cover(const input *in, const lh_trimesh *old)
{
    const size_t nt = lh_trimesh_triangle_count(old);
    static const double areas[4] = {0.5, 2, 8, -1};
    double *area = malloc(nt * sizeof *area);
    if (!area) abort();
    const unsigned b = in->cover;
    for (size_t t = 0; t < nt; t++) {
        const double bound = areas[(t + (b >> 2)) & 3];
        area[t] = bound > 0 ? bound * in->scale * in->scale : -1;
    }
    input r = *in; /* the options and the scale; g is the old mesh */
    lh_pslg *g = &r.g;
    memset(g, 0, sizeof *g);
    g->n = lh_trimesh_point_count(old), g->xy = (double *)lh_trimesh_points(old); /* read only */
    g->cover_count = nt, g->cover = (lh_index *)lh_trimesh_triangles(old);
    if (b & 2) g->segment_count = lh_trimesh_segment_count(old), g->segments = (lh_index *)lh_trimesh_segments(old);
    if (lh_trimesh_point_attr_count(old))
        g->attr_count = 1, g->attr = (double *)lh_trimesh_point_attrs(old);
    r.o.region_areas = (b & 12) != 0;
    g->cover_area = r.o.region_areas ? area : NULL;
    r.o.min_angle = angles[(b >> 4) & 7];
    r.o.max_area = b >> 7 ? 2 * in->scale * in->scale : 0;
    counter c1 = {0, 0, 0, 0}, c2 = c1;
    lh_trimesh *m1 = NULL, *m2 = NULL;
    char msg[256] = "x";
    const lh_status st = run(&r, &c1, &m1, msg, sizeof msg);
#ifdef LH_FUZZ_TRIMESH_VERBOSE
    fprintf(stderr, "cover stage: %zu points, %zu triangles, %zu segments, q %g a %g, areas %d -> %s \"%s\"\n", g->n,
            nt, g->segment_count, r.o.min_angle, r.o.max_area, r.o.region_areas, lh_status_name(st), msg);
#endif
    if (st != LH_OK || msg[0]) abort();
    check_refined(&r, g, &r.o, old, m1);
    if (run(&r, &c2, &m2, msg, sizeof msg) != LH_OK || !same(m1, m2)) abort();
    lh_trimesh_free(m2);
    if (r.fail_mode) check_failure(&r, m1, c1.calls);
    lh_trimesh_free(m1);
    free(area);
    if (c1.live || c2.live) abort();
}

#ifdef LH_FUZZ_TRIMESH_VERBOSE
static void describe(const input *in, lh_status st, const lh_trimesh *m, const char *msg)
{
    const lh_pslg *g = &in->g;
    const lh_trimesh_options *o = &in->o;
    fprintf(stderr, "n %zu (x + %g) * %g, even_odd %d convex_hull %d conforming %d split %d q %g a %g Y %d S %zu "
                    "region_areas %d attrs %d; collinear %d crossing %d open %d duplicates %zu\n",
            g->n, in->off, in->scale, g->even_odd, o->convex_hull, o->conforming, o->split_crossings, o->min_angle,
            o->max_area, o->boundary_steiner, o->max_steiner, o->region_areas, g->attr_count, in->collinear,
            in->crossing, (int)in->open, in->dups);
    for (size_t i = 0; i < g->n; i++) fprintf(stderr, "  v%zu %lld %lld\n", i, in->v[i].x, in->v[i].y);
    for (size_t i = 0; i < g->segment_count; i++)
        fprintf(stderr, "  s%zu %d %d\n", i, (int)g->segments[2 * i], (int)g->segments[2 * i + 1]);
    for (size_t i = 0; i < g->hole_count; i++)
        fprintf(stderr, "  hole %g %g\n", g->holes[2 * i] / in->scale - in->off, g->holes[2 * i + 1] / in->scale - in->off);
    for (size_t i = 0; i < g->region_count; i++)
        fprintf(stderr, "  region %g %g attr %g area %g\n", g->regions[4 * i] / in->scale - in->off,
                g->regions[4 * i + 1] / in->scale - in->off, g->regions[4 * i + 2], g->regions[4 * i + 3]);
    fprintf(stderr, "-> %s \"%s\"", lh_status_name(st), msg);
    if (m) {
        lh_trimesh_stats s;
        lh_trimesh_stats_get(m, &s);
        fprintf(stderr, ": %zu triangles, %zu Steiner (%zu on segments)%s, %zu bad, angles %.3f..%.3f",
                s.triangles, s.steiner_points, s.steiner_on_segments, s.steiner_limit_reached ? " limit" : "",
                s.bad_triangles, s.min_angle, s.max_angle);
    }
    fprintf(stderr, "\n");
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static input in; /* large: off the stack */
    decode(data, size, &in);
    counter c1 = {0, 0, 0, 0}, c2 = c1;
    lh_trimesh *m1 = NULL, *m2 = NULL;
    char msg[256] = "x";
#ifdef LH_FUZZ_TRIMESH_VERBOSE
    describe(&in, LH_OK, NULL, "(before the run)");
#endif
    const lh_status st = run(&in, &c1, &m1, msg, sizeof msg);
#ifdef LH_FUZZ_TRIMESH_VERBOSE /* -DLH_FUZZ_TRIMESH_VERBOSE: what an input is, and its outcome */
    describe(&in, st, m1, msg);
#endif
    if (st == LH_ERR_DEGENERATE || st == LH_ERR_CROSSING_SEGMENTS) {
        /* the message says which degeneracy, and it must be the one the input has */
        const int said_collinear = strstr(msg, "collinear") != NULL, said_cross = strstr(msg, "crosses") != NULL,
                  said_open = strstr(msg, "ends an odd number of segments") != NULL;
        if (!msg[0] || m1 || c1.live || said_cross != (st == LH_ERR_CROSSING_SEGMENTS)) abort();
        /* split_crossings: a crossing is an error only when its rounded point cannot go in */
        if (in.collinear != said_collinear || (!in.collinear && !in.crossing && said_cross) ||
            (!in.collinear && in.crossing && !in.o.split_crossings && !said_cross))
            abort();
        /* even-odd with a chain that is not closed: the first vertex ending an odd number */
        const int open = in.g.even_odd && in.open >= 0 && !in.collinear && !said_cross;
        long long at = -1;
        if (open != said_open || (open && (sscanf(msg, "vertex %lld", &at) != 1 ||
                                           at != in.g.first_index + (long long)in.open)))
            abort();
        if (!said_collinear && !said_cross && in.keep_hull && !in.g.hole_count) abort(); /* empty domain */
        if (said_cross) check_crossing(&in, msg);
        return 0;
    }
    if (st != LH_OK || in.collinear || (in.crossing && !in.o.split_crossings) || (in.g.even_odd && in.open >= 0) ||
        msg[0])
        abort();
    check_mesh(&in, m1);
    if (run(&in, &c2, &m2, msg, sizeof msg) != LH_OK || !same(m1, m2)) abort();
    lh_trimesh_free(m2);
    if (in.o.smooth > 0) { /* smoothing never lowers the smallest angle */
        input plain = in;
        plain.o.smooth = 0;
        lh_trimesh_stats a, b;
        lh_trimesh_stats_get(m1, &a);
        if (run(&plain, &c2, &m2, msg, sizeof msg) != LH_OK) abort();
        lh_trimesh_stats_get(m2, &b);
        if (a.min_angle < b.min_angle - 1e-9 || b.smoothing_moves) abort();
        lh_trimesh_free(m2);
    }
    if (in.cover & 1) refine_cover(&in, m1);
    if (in.fail_mode) check_failure(&in, m1, c1.calls);
    lh_trimesh_free(m1);
    if (c1.live || c2.live) abort();
    return 0;
}
