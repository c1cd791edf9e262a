/* test_trimesh_errors.c — 2D meshing (lifthull.h, "2D meshing") refusals and their
 * messages: bad input with its line, an invalid mesh to refine, API misuse, crossing
 * segments (split when asked), hole seeds on segments; the checker lh_cdt_check's own
 * rejections; every allocation failure survived. */
#include "trimesh_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void expect_failure(lh_test_state *lh_t_, const char *text, lh_status want, const char *want_msg)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text(text, &g), LH_OK);
    lh_trimesh *m = (lh_trimesh *)&g;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), want);
    LH_EXPECT_EQ_INT(err.status, want);
    LH_EXPECT_TRUE(m == NULL);
    LH_EXPECT_STREQ(err.message, want_msg);
    lh_pslg_free(&g);
}

LH_TEST(bad_input_gets_its_error_and_line)
{
    expect_failure(lh_t_, "4 2 0 0\n1 0 0\n2 2 2\n3 0 2\n4 2 0\n2 0\n1 1 2\n2 3 4\n0\n",
                   LH_ERR_CROSSING_SEGMENTS, "8: segment 2 crosses segment 1 (line 7)");
    expect_failure(lh_t_, "3 2 0 0\n1 0 0\n2 1 0\n3 2 0\n0 0\n0\n", LH_ERR_DEGENERATE,
                   "the vertices are all collinear or fewer than 3 distinct: no triangle");
    expect_failure(lh_t_, "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n1 0\n1 1 2\n0\n", LH_ERR_DEGENERATE,
                   "the domain is empty: the flood from the outside or a hole reached every "
                   "triangle (is the boundary closed?)");
    /* NaN cannot come from the reader: a caller's array */
    double xy[6] = {0, 0, 1, 0, 0, NAN};
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 3, g.xy = xy;
    lh_trimesh *m;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_NONFINITE);
    LH_EXPECT_STREQ(err.message, "vertex 2: coordinate is NaN or infinite");
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(NULL, NULL, &m, &err), LH_ERR_INVALID_ARGUMENT);
    /* an endpoint out of range (the reader catches it in files; a caller's array here) */
    xy[5] = 1;
    lh_index seg[2] = {0, 3};
    g.segments = seg, g.segment_count = 1;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "segment 0: endpoint 3 is not a vertex (0..2)");
    g.segment_count = 0;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 41;
    xy[5] = 1;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "min_angle 41 outside 0..40 degrees");
    /* just past the bound: the message shows the value, not the bound again */
    o.min_angle = 40.0000001;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "min_angle 40.000000100000001 outside 0..40 degrees");
    o.min_angle = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "min_angle nan outside 0..40 degrees");
    /* a NaN area bound is named as such (it is no angle) */
    o.min_angle = 0;
    o.max_area = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "max_area is NaN (0 or below: no area bound)");
}

/* A mesh to refine (Triangle's -r) that is no valid mesh is the caller's invalid
 * mesh, LH_ERR_INVALID_MESH with the reason (LH_ERR_DEGENERATE or
 * LH_ERR_INVALID_ARGUMENT before): crossing edges, no triangle of positive area. */
LH_TEST(an_invalid_mesh_to_refine_is_an_invalid_mesh)
{
    double sq[8] = {0, 0, 1, 0, 1, 1, 0, 1}, line[8] = {0, 0, 1, 0, 2, 0, 0, 1};
    lh_index crossing[6] = {0, 1, 2, 0, 1, 3}, flat[3] = {0, 1, 2};
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 4, g.xy = sq, g.cover_count = 2, g.cover = crossing;
    lh_trimesh *m = NULL;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "the mesh to refine has crossing edges");
    LH_EXPECT_TRUE(m == NULL);
    g.xy = line, g.cover_count = 1, g.cover = flat;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "the mesh to refine has no triangle of positive area");
    LH_EXPECT_TRUE(m == NULL);
}

/* Misuse of the API gets a status and a message, never a crash: a cover count
 * without its array (a segfault before), lh_trimesh_options_default(NULL) (a
 * segfault before), a NaN area bound, segments with no vertices, an allocator without
 * hooks, counts no array can have. */
LH_TEST(api_misuse_is_refused_with_a_message)
{
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 4, g.xy = xy, g.cover_count = 2;
    lh_trimesh *m = NULL;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "an array of the PSLG is missing");
    LH_EXPECT_TRUE(m == NULL);
    g.cover_count = 0;
    lh_trimesh_options_default(NULL);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.max_area = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "max_area is NaN (0 or below: no area bound)");
    o.max_area = 0;
    lh_allocator none = {NULL, NULL, NULL};
    o.alloc = &none;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "the allocator lacks its alloc or free hook");
    lh_index seg[2] = {0, 1};
    g.n = 0, g.segment_count = 1, g.segments = seg;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "segment 0: endpoint 0 is not a vertex (there are none)");
    LH_EXPECT_TRUE(m == NULL);
    /* counts no array can have: refused before any size is computed from them */
    g.n = 4, g.segment_count = 0, g.cover_count = SIZE_MAX, g.cover = seg;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_TOO_LARGE);
    g.cover_count = 0, g.attr_count = INT32_MAX, g.attr = xy, g.n = SIZE_MAX / 8;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_TOO_LARGE);
    LH_EXPECT_TRUE(m == NULL);
}

/* split_crossings: an X becomes four segments meeting at a new vertex; earcut's
 * self-crossing water polygons (proper crossings counted by the oracle harness: 2, 19,
 * 65, 133) are meshed with one vertex per crossing. */
LH_TEST(crossings_are_split_when_asked)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text("4 2 0 0\n1 0 0\n2 2 2\n3 0 2\n4 2 0\n2 0\n1 1 2\n2 3 4\n0\n", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.split_crossings = 1;
    o.convex_hull = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "X");
    lh_trimesh_stats st;
    if (m) {
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_EQ_U64(st.crossings_split, 1);
        LH_EXPECT_EQ_U64(lh_trimesh_point_count(m), 5);
        LH_EXPECT_EQ_U64(lh_trimesh_triangle_count(m), 4);
        const double *x = lh_trimesh_points(m) + 8;
        LH_EXPECT_EQ_DBL(x[0], 1.0);
        LH_EXPECT_EQ_DBL(x[1], 1.0);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
    static const struct { const char *file; size_t crossings; } water[] = {
        {"polygons/simplified-us-border.json", 2}, {"polygons/water.json", 19}};
    for (size_t i = 0; i < sizeof water / sizeof water[0]; i++) {
        LH_ASSERT_EQ_INT(load(lh_rings_read, water[i].file, &g), LH_OK);
        lh_error err;
        LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_CROSSING_SEGMENTS);
        o.convex_hull = 0;
        m = mesh_checked(lh_t_, &g, &o, water[i].file);
        if (m) {
            lh_trimesh_stats_get(m, &st);
            LH_EXPECT_EQ_U64(st.crossings_split, water[i].crossings);
        }
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* A segment repeated after a crossing bent its first copy (a rounded crossing vertex)
 * follows the bent chain and shares its edges, making no second crossing (fuzz_trimesh:
 * the second, almost coincident chain made refinement split without end); earcut's
 * water-huge polygons, refused before for a crossing their rounded points could not
 * split, are meshed. */
LH_TEST(an_overlap_follows_a_chain_bent_at_a_crossing)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text("4 2 0 0\n1 8 0\n2 -8 -8\n3 1 8\n4 8 -8\n"
                               "5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 2\n5 2 1\n0\n", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.split_crossings = 1;
    o.min_angle = 20;
    o.max_steiner = 10000; /* a failure ends, not runs for ever */
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "repeated segment");
    lh_trimesh_stats st;
    if (m) {
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_EQ_U64(st.crossings_split, 1);
        LH_EXPECT_EQ_U64(st.segments_overlapping, 1);
        LH_EXPECT_LE_U64(st.steiner_points, 100);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
    o.min_angle = 0;
    o.max_steiner = SIZE_MAX;
    const char *huge[] = {"polygons/water-huge.json", "polygons/water-huge2.json"};
    for (size_t i = 0; i < 2; i++) {
        LH_ASSERT_EQ_INT(load(lh_rings_read, huge[i], &g), LH_OK);
        lh_trimesh_free(mesh_checked(lh_t_, &g, &o, huge[i]));
        lh_pslg_free(&g);
    }
}

/* A hole seed exactly on a segment (the inner square's bottom edge, inside and at an
 * endpoint) is refused, naming both: which side it would carve is undefined. A seed
 * beside it carves the inner square. */
LH_TEST(a_hole_seed_on_a_segment_is_refused)
{
    static const char *const seeds[] = {"2 1", "1 1", "3 3"};
    static const char *const want[] = {"20: hole 1 lies on segment 5", "20: hole 1 lies on segment 5",
                                       "20: hole 1 lies on segment 6"};
    for (int i = 0; i < 4; i++) {
        char text[256];
        snprintf(text, sizeof text,
                 "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n7 3 3\n8 1 3\n8 0\n1 1 2\n2 2 3\n"
                 "3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 %s\n", i < 3 ? seeds[i] : "2 1.5");
        lh_pslg g;
        LH_ASSERT_EQ_INT(load_text(text, &g), LH_OK);
        lh_trimesh *m = NULL;
        lh_error err;
        const lh_status st = lh_pslg_triangulate(&g, NULL, &m, &err);
        if (i < 3) {
            LH_EXPECT_EQ_INT(st, LH_ERR_DEGENERATE);
            LH_EXPECT_STREQ(err.message, want[i]);
        } else {
            LH_EXPECT_EQ_INT(st, LH_OK);
            if (m) LH_EXPECT_EQ_U64(lh_trimesh_triangle_count(m), 8); /* the annulus */
        }
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* Hole seeds on vertices that end no segment (a 3 x 3 grid inside a square ring, a
 * seed on each) are no error: the first carves the inside, the others are ignored
 * (tests/cli/scaling.sh: the check of each seed costs its vertex's degree). */
LH_TEST(hole_seeds_on_free_vertices_carve)
{
    const char *text = "17 2 0 0\n1 0 0\n2 6 0\n3 6 6\n4 0 6\n5 1 1\n6 5 1\n7 5 5\n8 1 5\n"
                       "9 1.5 1.5\n10 2.5 1.5\n11 3.5 1.5\n12 1.5 2.5\n13 2.5 2.5\n14 3.5 2.5\n"
                       "15 1.5 3.5\n16 2.5 3.5\n17 3.5 3.5\n8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
                       "5 5 6\n6 6 7\n7 7 8\n8 8 5\n9\n1 1.5 1.5\n2 2.5 1.5\n3 3.5 1.5\n4 1.5 2.5\n"
                       "5 2.5 2.5\n6 3.5 2.5\n7 1.5 3.5\n8 2.5 3.5\n9 3.5 3.5\n";
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text(text, &g), LH_OK);
    lh_trimesh *m = NULL;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_OK);
    if (m) {
        lh_trimesh_stats s;
        lh_trimesh_stats_get(m, &s);
        LH_EXPECT_EQ_U64(lh_trimesh_triangle_count(m), 8); /* the ring */
        LH_EXPECT_EQ_U64(s.holes_ignored, 8);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

LH_TEST(the_check_rejects_what_is_not_a_cdt)
{
    /* the unit square split by the diagonal 0-2, and a fifth point near the centre */
    const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    const lh_index good[] = {0, 1, 2, 0, 2, 3}, flipped[] = {0, 2, 1, 0, 2, 3};
    const lh_index hull[] = {0, 1, 1, 2, 2, 3, 3, 0};
    lh_error err;
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 4, hull, 0, NULL, &err), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, flipped, 4, hull, 0, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "triangle 0 is not counterclockwise with positive area");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 3, hull, 0, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "a boundary edge of triangle 1 is not a subsegment");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 3, hull, 1, NULL, &err), LH_OK);
    /* misuse: a message says which argument */
    const lh_index far_seg[] = {0, 1, 1, 7};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 2, far_seg, 1, NULL, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "subsegment 1: endpoint 7 is not a point (0..3)");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, NULL, 2, good, 0, NULL, 1, NULL, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "xy is NULL with a count above 0");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, NULL, 0, NULL, 1, NULL, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "tris is NULL with a count above 0");
    const lh_allocator half = {NULL, NULL, NULL};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 0, NULL, 1, &half, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "the allocator lacks alloc or free");
    /* a kite whose diagonal is not Delaunay: (0,0) (2,-1) (4,0) (2,1) split 1-3 is
       Delaunay, split 0-2 is not */
    const double kite[] = {0, 0, 2, -0.5, 4, 0, 2, 0.5};
    const lh_index long_diag[] = {0, 1, 2, 0, 2, 3}, short_diag[] = {0, 1, 3, 1, 2, 3};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, short_diag, 0, NULL, 1, NULL, &err), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, long_diag, 0, NULL, 1, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "an unconstrained edge of triangle 0 is not locally Delaunay");
    const lh_index seg[] = {0, 2}; /* ... unless that diagonal is a subsegment */
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, long_diag, 1, seg, 1, NULL, &err), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, short_diag, 1, seg, 1, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "subsegment 0 is not an edge of the triangulation");
}

static lh_status mesh_with(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 25;
    o.region_attributes = 1;
    o.alloc = a;
    lh_trimesh *m = NULL;
    lh_status st = lh_pslg_triangulate(user, &o, &m, NULL);
    if (st != LH_OK) LH_EXPECT_TRUE(m == NULL);
    lh_trimesh_free(m);
    return st;
}

static lh_status check_with(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)lh_t_;
    const lh_trimesh *m = user;
    return lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                            lh_trimesh_triangles(m), lh_trimesh_segment_count(m), lh_trimesh_segments(m), 0, a, NULL);
}

LH_TEST(every_allocation_failure_is_survived)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
    LH_EXPECT_GT_U64(lh_test_every_failure(lh_t_, mesh_with, &g), 20);
    lh_trimesh *m = mesh_checked(lh_t_, &g, NULL, "A");
    if (m) LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, check_with, m), 2);
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(bad_input_gets_its_error_and_line),
        LH_CASE(an_invalid_mesh_to_refine_is_an_invalid_mesh),
        LH_CASE(api_misuse_is_refused_with_a_message),
        LH_CASE(crossings_are_split_when_asked),
        LH_CASE(an_overlap_follows_a_chain_bent_at_a_crossing),
        LH_CASE(a_hole_seed_on_a_segment_is_refused),
        LH_CASE(hole_seeds_on_free_vertices_carve),
        LH_CASE(the_check_rejects_what_is_not_a_cdt),
        LH_CASE(every_allocation_failure_is_survived),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
