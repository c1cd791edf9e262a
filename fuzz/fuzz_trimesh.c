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
 * Anything else aborts. The target's other files: fuzz_trimesh.h. Build as
 * fuzz_delaunay.c (fuzz/README.md); with -DLH_FUZZ_TRIMESH_VERBOSE an input's PSLG,
 * options and outcome go to stderr.
 */
#include "fuzz_common.h"
#include "fuzz_trimesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A counting allocator that fails call number fail_at (0: never). */
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

int same(const lh_trimesh *a, const lh_trimesh *b)
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

lh_status run(const input *in, counter *c, lh_trimesh **m, char *msg, size_t size)
{
    lh_allocator al = {count_alloc, count_free, c};
    lh_trimesh_options o = in->o;
    o.alloc = &al;
    lh_error err;
    const lh_status st = lh_pslg_triangulate(&in->g, &o, m, &err);
    /* the lh_error agrees with the return; a line it names starts the message */
    char head[32];
    const int k = snprintf(head, sizeof head, "%zu: ", err.line);
    if (err.status != st || (err.line && strncmp(err.message, head, (size_t)k) != 0)) abort();
    if (size) { /* err.message cut to size */
        size_t len = strlen(err.message);
        if (len >= size) len = size - 1;
        memcpy(msg, err.message, len);
        msg[len] = 0;
    }
    return st;
}

/* A run failing allocation number 1 + fail_pick % calls (calls: the first run's) must
 * return LH_ERR_NOMEM and nothing, or succeed with m's arrays, leaking nothing. */
void check_failure(const input *in, const lh_trimesh *m, long calls)
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
