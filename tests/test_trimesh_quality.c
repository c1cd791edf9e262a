/* test_trimesh_quality.c — the quality refinement of lh_pslg_triangulate (refine.c):
 * - every quality decision is scale-free (m2_geom.h): A.poly scaled by 2^k from 2^-600
 *   to 2^600 gives the same mesh, byte for byte once unscaled, meeting the bound and
 *   exactly valid; a 10^-300 radian wedge counts as bad; an area bound applies at
 *   +-2^511 and +-DBL_MAX; split_segments (-s) gives the unit mesh scaled from 2^-600
 *   up to a square at +-2^1023, and its midpoints' attributes do not overflow;
 * - where the domain is pinched (a hole touching the outer ring, a ring touching
 *   itself), no triangle beside the pinch is left below the bound unless an input
 *   angle there is below it too (earcut's hole-touching-outer.json and
 *   self-tangent-4.json: a 0.81 and a 25.6 degree triangle were left, the subsegment
 *   beside them not found from the pinch vertex's fan). */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


static lh_status load(lh_test_pslg_reader rd, const char *path, lh_pslg *g)
{
    return lh_test_pslg_file(rd, LH_TEST_DATA_DIR, path, g);
}

static lh_status load_rings(const char *path, lh_pslg *g) { return load(lh_rings_read, path, g); }

/* Meshes g with o, expecting success and an exactly valid mesh: the mesh and *st. */
static lh_trimesh *mesh_valid(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                              lh_trimesh_stats *st)
{
    lh_trimesh *m = NULL;
    lh_error err;
    const lh_status s = lh_pslg_triangulate(g, o, &m, &err);
    LH_EXPECT_EQ_INT(s, LH_OK);
    if (s != LH_OK) {
        LH_NOTE("%s", err.message);
        return NULL;
    }
    lh_trimesh_stats_get(m, st);
    const lh_status c = lh_test_check_trimesh(m, &err);
    if (c != LH_OK) LH_NOTE("check: %s", err.message);
    LH_EXPECT_EQ_INT(c, LH_OK);
    return m;
}

/* Whether m's points are 2^k times ref's (exactly) and its triangles the same. */
static int same_up_to_scale(const lh_trimesh *m, const lh_trimesh *ref, int k)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m);
    if (np != lh_trimesh_point_count(ref) || nt != lh_trimesh_triangle_count(ref)) return 0;
    const double *a = lh_trimesh_points(m), *b = lh_trimesh_points(ref);
    for (size_t i = 0; i < 2 * np; i++)
        if (a[i] != ldexp(b[i], k)) return 0;
    return memcmp(lh_trimesh_triangles(m), lh_trimesh_triangles(ref), 3 * nt * sizeof(lh_index)) == 0;
}

/* A.poly scaled by 2^k at 30 degrees (the same at 34, and at 20 with an area bound
 * scaled by 2^2k): the unit-scale mesh times 2^k. Before the decisions were scale-free, 2^177
 * left a 7.18 degree triangle and reported none below the bound. */
/* lh_triangle_scaled_edges: the edges opposite each corner, the largest component in
 * [1, 2), the same at every power-of-two scale, halved where a difference overflows. */
LH_TEST(scaled_edges_are_the_meshers_frame)
{
    const double a[2] = {0, 0}, b[2] = {3, 0}, c[2] = {0, 1};
    double d[3][2];
    LH_EXPECT_EQ_INT(lh_triangle_scaled_edges(a, b, c, d), 1);
    const double want[3][2] = {{-1.5, 0.5}, {0, -0.5}, {1.5, 0}}; /* c - b, a - c, b - a over 2 */
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 2; j++) LH_EXPECT_EQ_DBL(d[k][j], want[k][j]);
    for (int s = -1070; s <= 1020; s += 415) { /* 2^s times the triangle: the same d */
        const double as[2] = {0, 0}, bs[2] = {ldexp(3, s), 0}, cs[2] = {0, ldexp(1, s)};
        double ds[3][2];
        LH_EXPECT_EQ_INT(lh_triangle_scaled_edges(as, bs, cs, ds), 1 + s);
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 2; j++) LH_EXPECT_EQ_DBL(ds[k][j], want[k][j]);
    }
    const double p[2] = {-DBL_MAX, -DBL_MAX}, q[2] = {DBL_MAX, -DBL_MAX}, r[2] = {0, DBL_MAX};
    LH_EXPECT_EQ_INT(lh_triangle_scaled_edges(p, q, r, d), 1024); /* 2 DBL_MAX: halved */
    LH_EXPECT_EQ_DBL(d[2][0], DBL_MAX / 0x1p1023);
    LH_EXPECT_EQ_DBL(d[0][1], DBL_MAX / 0x1p1023);
    LH_EXPECT_EQ_INT(lh_triangle_scaled_edges(a, a, a, d), 0);
    LH_EXPECT_EQ_DBL(d[1][0], 0);
}

LH_TEST(quality_decisions_are_scale_free)
{
    static const int ks[] = {-600, -260, -177, -1, 0, 1, 177, 260, 600};
    static const double angles[] = {30, 34, 20};
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
    double *xy0 = malloc(2 * g.n * sizeof *xy0), h0[2] = {g.holes[0], g.holes[1]};
    LH_ASSERT_TRUE(xy0 != NULL);
    memcpy(xy0, g.xy, 2 * g.n * sizeof *xy0);
    for (size_t a = 0; a < LH_COUNT(angles); a++) {
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.min_angle = angles[a];
        const double area0 = a == 2 ? 1e-3 : 0;
        lh_trimesh *ref = NULL;
        lh_error err;
        memcpy(g.xy, xy0, 2 * g.n * sizeof *xy0);
        g.holes[0] = h0[0], g.holes[1] = h0[1];
        o.max_area = area0;
        LH_ASSERT_EQ_INT(lh_pslg_triangulate(&g, &o, &ref, &err), LH_OK);
        for (size_t i = 0; i < LH_COUNT(ks); i++) {
            const int k = ks[i];
            if (area0 > 0 && abs(k) > 500) continue; /* the bound times 2^2k: beyond the doubles */
            for (size_t v = 0; v < 2 * g.n; v++) g.xy[v] = ldexp(xy0[v], k);
            g.holes[0] = ldexp(h0[0], k), g.holes[1] = ldexp(h0[1], k);
            o.max_area = ldexp(area0, 2 * k);
            lh_trimesh_stats st;
            lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
            if (!m) return;
            if (!same_up_to_scale(m, ref, k)) LH_NOTE("angle %g, 2^%d: not the unit mesh scaled", angles[a], k);
            LH_EXPECT_TRUE(same_up_to_scale(m, ref, k));
            LH_EXPECT_EQ_U64(st.bad_triangles, 0);
            LH_EXPECT_LE_DBL(angles[a], st.min_angle);
            LH_EXPECT_TRUE(st.max_angle < 180);
            lh_trimesh_free(m);
        }
        lh_trimesh_free(ref);
    }
    free(xy0);
    lh_pslg_free(&g);
}

/* Above the provable 20.7 degrees: A.poly at 38 degrees (which ran without end) stops
 * at its Steiner budget, valid, the triangles left below the bound counted; at 34
 * degrees it meets the bound within the budget. */
LH_TEST(refinement_above_the_provable_angle_ends)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
    static const double angles[] = {20, 34, 38};
    for (size_t a = 0; a < LH_COUNT(angles); a++) {
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.min_angle = angles[a];
        lh_trimesh_stats st;
        lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
        if (!m) return;
        LH_EXPECT_EQ_INT(st.steiner_budget_reached, a == 2);
        LH_EXPECT_EQ_INT(st.steiner_budget > 0, a > 0);
        if (a < 2) LH_EXPECT_EQ_U64(st.bad_triangles, 0);
        if (a == 2) {
            LH_EXPECT_GT_U64(st.bad_triangles, 0);
            LH_EXPECT_LE_U64(st.steiner_points, st.steiner_budget);
            LH_EXPECT_LE_U64(st.steiner_budget, 100000);
        }
        lh_trimesh_free(m);
    }
    lh_pslg_free(&g);
}

/* (0,0), (1,0), (1,1e-300): its 10^-300 radian angle is below any bound (the squared
 * lengths underflowed, and the triangle was counted good with angles 0 and 0). */
LH_TEST(a_wedge_of_1e_300_is_counted_bad)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(lh_test_pslg_text("3 2 0 0\n1 0 0\n2 1 0\n3 1 1e-300\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n", &g),
                     LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 30;
    lh_trimesh_stats st;
    lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
    if (!m) return;
    LH_EXPECT_GT_U64(st.bad_triangles, 0);
    LH_EXPECT_TRUE(st.min_angle > 0 && st.min_angle < 1e-290);
    LH_EXPECT_LE_DBL(89.0, st.max_angle);
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

/* An area bound on squares +-2^511 (area 2^1024, just beyond the doubles; bound
 * 2^1021) and +-DBL_MAX (bound DBL_MAX): refined, not ignored (the areas overflowed). */
LH_TEST(an_area_bound_applies_at_the_ends_of_the_range)
{
    static const char *const text[] = {
        "4 2 0 0\n1 -0x1p511 -0x1p511\n2 0x1p511 -0x1p511\n3 0x1p511 0x1p511\n4 -0x1p511 0x1p511\n"
        "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n",
        "4 2 0 0\n1 -1.7976931348623157e308 -1.7976931348623157e308\n2 1.7976931348623157e308 -1.7976931348623157e308\n"
        "3 1.7976931348623157e308 1.7976931348623157e308\n4 -1.7976931348623157e308 1.7976931348623157e308\n"
        "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n"};
    for (int i = 0; i < 2; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(lh_test_pslg_text(text[i], &g), LH_OK);
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.max_area = i ? DBL_MAX : 0x1p1021;
        o.max_steiner = 200;
        lh_trimesh_stats st;
        lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
        if (!m) return;
        LH_EXPECT_GT_U64(st.steiner_points, 0);
        if (!i) { /* met: every triangle's area at most 2^1021, computed at 2^-511 */
            LH_EXPECT_EQ_INT(st.steiner_limit_reached, 0);
            LH_EXPECT_EQ_U64(st.bad_triangles, 0);
            const double *xy = lh_trimesh_points(m);
            const lh_index *t = lh_trimesh_triangles(m);
            size_t above = 0;
            for (size_t k = 0; k < lh_trimesh_triangle_count(m); k++) {
                const double *p[3];
                for (int j = 0; j < 3; j++) p[j] = xy + 2 * (size_t)t[3 * k + j];
                const double ax = ldexp(p[1][0] - p[0][0], -511), ay = ldexp(p[1][1] - p[0][1], -511);
                const double bx = ldexp(p[2][0] - p[0][0], -511), by = ldexp(p[2][1] - p[0][1], -511);
                above += (ax * by - ay * bx) / 2 > 0.5;
            }
            LH_EXPECT_EQ_U64(above, 0);
        } else {
            LH_EXPECT_EQ_INT(st.steiner_limit_reached, 1);
            LH_EXPECT_GT_U64(st.bad_triangles, 0);
        }
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* split_segments (Triangle's -s) is scale-free too: a square +-1 with an inner
 * segment and a point beside it, and A.poly, scaled by 2^k up to the square at
 * +-2^1023, give the unit-scale mesh times 2^k. At +-2^1023 the midpoint of the inner
 * segment was computed as a + (b - a) / 2 with b - a overflowing: an infinite point,
 * refused, the segment left unsplit (7 points instead of 8). */
LH_TEST(split_segments_are_scale_free)
{
    static const int ks[] = {-600, -1, 0, 1, 600, 1023};
    for (int f = 0; f < 2; f++) {
        lh_pslg g;
        if (f) LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
        else
            LH_ASSERT_EQ_INT(lh_test_pslg_text("7 2 0 0\n1 -1 -1\n2 1 -1\n3 1 1\n4 -1 1\n5 -1 0\n6 1 0\n"
                                               "7 0 0.0625\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n0\n", &g),
                             LH_OK);
        double *xy0 = malloc(2 * g.n * sizeof *xy0), h0[2] = {g.hole_count ? g.holes[0] : 0, g.hole_count ? g.holes[1] : 0};
        LH_ASSERT_TRUE(xy0 != NULL);
        memcpy(xy0, g.xy, 2 * g.n * sizeof *xy0);
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.split_segments = 1;
        lh_trimesh *ref = NULL;
        lh_error err;
        LH_ASSERT_EQ_INT(lh_pslg_triangulate(&g, &o, &ref, &err), LH_OK);
        if (!f) LH_EXPECT_EQ_U64(lh_trimesh_point_count(ref), 8);
        for (size_t i = 0; i < LH_COUNT(ks); i++) {
            const int k = ks[i];
            if (f && k > 600) continue; /* A.poly is not centred: 2^1023 overflows */
            for (size_t v = 0; v < 2 * g.n; v++) g.xy[v] = ldexp(xy0[v], k);
            if (g.hole_count) g.holes[0] = ldexp(h0[0], k), g.holes[1] = ldexp(h0[1], k);
            lh_trimesh_stats st;
            lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
            if (!m) break;
            if (!same_up_to_scale(m, ref, k)) LH_NOTE("file %d, 2^%d: not the unit mesh scaled", f, k);
            LH_EXPECT_TRUE(same_up_to_scale(m, ref, k));
            LH_EXPECT_EQ_U64(st.segments_unsplit, 0);
            lh_trimesh_free(m);
        }
        lh_trimesh_free(ref);
        free(xy0);
        lh_pslg_free(&g);
    }
}

/* split_segments interpolates the vertex attributes at the midpoints without
 * overflowing: every attribute 1.5e308 stays 1.5e308 (the point put on the inner
 * segment got (a + b) / 2 = inf). */
LH_TEST(split_segments_attributes_stay_finite)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(lh_test_pslg_text("7 2 1 0\n1 -1 -1 1.5e308\n2 1 -1 1.5e308\n3 1 1 1.5e308\n4 -1 1 1.5e308\n"
                                       "5 -1 0 1.5e308\n6 1 0 1.5e308\n7 0 0.0625 1.5e308\n"
                                       "5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n0\n", &g),
                     LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.split_segments = 1;
    lh_trimesh_stats st;
    lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
    if (m) {
        LH_EXPECT_EQ_U64(lh_trimesh_point_count(m), 8);
        LH_ASSERT_EQ_INT(lh_trimesh_point_attr_count(m), 1);
        for (size_t p = 0; p < lh_trimesh_point_count(m); p++)
            LH_EXPECT_EQ_DBL(lh_trimesh_point_attrs(m)[p], 1.5e308);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

static int same_point(const double *a, const double *b) { return a[0] == b[0] && a[1] == b[1]; }

/* The smallest angle (degrees) between two input segments ending at point p (their
 * ends compared by coordinates: the rings repeat a pinch point as several vertices),
 * 360 when fewer than two end there; *copies: how many vertices are at p (not a
 * pinch, fewer than 2: 360 without looking). */
static double angle_at(const lh_pslg *g, const double *p, size_t *copies)
{
    *copies = 0;
    for (size_t v = 0; v < g->n; v++) *copies += same_point(g->xy + 2 * v, p);
    double best = 360;
    if (*copies < 2) return best; /* only pinches are asked about */
    for (size_t s = 0; s < g->segment_count; s++)
        for (size_t t = s + 1; t < g->segment_count; t++)
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    const double *o = g->xy + 2 * (size_t)g->segments[2 * s + i];
                    if (!same_point(o, p) || !same_point(g->xy + 2 * (size_t)g->segments[2 * t + j], p)) continue;
                    const double *a = g->xy + 2 * (size_t)g->segments[2 * s + 1 - i];
                    const double *b = g->xy + 2 * (size_t)g->segments[2 * t + 1 - j];
                    const double ang = fabs(atan2(a[1] - o[1], a[0] - o[0]) - atan2(b[1] - o[1], b[0] - o[0]));
                    best = fmin(best, fmin(ang, 2 * 3.14159265358979323846 - ang) * 180 / 3.14159265358979323846);
                }
    return best;
}

LH_TEST(a_pinched_domain_is_refined_beside_the_pinch)
{
    static const char *const files[] = {"hole-touching-outer", "self-tangent-4"};
    static const double bounds[] = {10, 30};
    for (size_t i = 0; i < LH_COUNT(files); i++) {
        char path[128];
        snprintf(path, sizeof path, "polygons/degenerate/%s.json", files[i]);
        lh_pslg g;
        LH_ASSERT_EQ_INT(load_rings(path, &g), LH_OK);
        for (size_t b = 0; b < LH_COUNT(bounds); b++) {
            lh_trimesh_options o;
            lh_trimesh_options_default(&o);
            o.min_angle = bounds[b];
            lh_trimesh_stats st;
            lh_trimesh *m = mesh_valid(lh_t_, &g, &o, &st);
            if (!m) return;
            const lh_index *bad = lh_trimesh_bad_triangles(m), *tri = lh_trimesh_triangles(m);
            const double *xy = lh_trimesh_points(m);
            size_t at_pinch = 0;
            for (size_t k = 0; k < st.bad_triangles; k++)
                for (int j = 0; j < 3; j++) {
                    const double *p = xy + 2 * (size_t)tri[3 * (size_t)bad[k] + j];
                    size_t copies;
                    const double ang = angle_at(&g, p, &copies);
                    if (copies > 1 && ang >= bounds[b]) {
                        LH_NOTE("%s at %g: bad triangle %lld at the pinch (%g, %g), input angle %g", files[i],
                                bounds[b], (long long)bad[k], p[0], p[1], ang);
                        at_pinch++;
                    }
                }
            LH_EXPECT_EQ_U64(at_pinch, 0);
            if (i == 0) /* its one input angle below 30 degrees: 24.1 */
                LH_EXPECT_LE_DBL(bounds[b] < 24 ? bounds[b] : 24.0, st.min_angle);
            lh_trimesh_free(m);
        }
        lh_pslg_free(&g);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(quality_decisions_are_scale_free),
        LH_CASE(a_wedge_of_1e_300_is_counted_bad),
        LH_CASE(refinement_above_the_provable_angle_ends),
        LH_CASE(an_area_bound_applies_at_the_ends_of_the_range),
        LH_CASE(split_segments_are_scale_free), LH_CASE(scaled_edges_are_the_meshers_frame),
        LH_CASE(split_segments_attributes_stay_finite),
        LH_CASE(a_pinched_domain_is_refined_beside_the_pinch),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
