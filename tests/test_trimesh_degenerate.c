/* test_trimesh_degenerate.c — 2D meshing (lifthull.h, "2D meshing") of degenerate and
 * hostile geometry: each resolved with an exactly valid mesh (lh_cdt_check) and
 * reported, or refused clearly: small angles far from the origin, conforming below the
 * resolution floor, a crossing bent onto a vertex, earcut's degenerate rings, CGAL's
 * tiny edge, a duplicate vertex, a zero-length and an overlapping segment. */
#include "trimesh_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A 12-degree angle between a segment and a kept hull edge, 10^6 from the origin:
 * refinement towards its apex stops at the minimum length (here 2^-40 of the largest
 * coordinate, above the rounding), not on the grid of doubles without end. */
LH_TEST(a_small_angle_far_from_the_origin_ends)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text("4 2 0 0\n1 1000000 1000002\n2 999997 1000002\n3 1000002 999992\n"
                               "4 999992 999992\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.split_crossings = 1;
    o.convex_hull = 1;
    o.min_angle = 30;
    o.max_steiner = 20000; /* a failure ends, not runs for ever */
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "small angle at 10^6");
    lh_trimesh_stats st;
    if (m) {
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_EQ_INT(st.steiner_limit_reached, 0);
        LH_EXPECT_LE_U64(st.steiner_points, 2000);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

/* fuzz/README.md finding 10: a ring of unit features on the grid -8..8 at x + 2^40,
 * with input angles of 5 to 10 degrees at (-8,-7), conforming (-D). The resolution
 * floor (2^-40 of the largest coordinate: one grid unit) stops the splits towards
 * the apex, and edges there stay not Delaunay: the count says so. Without it the
 * mesh claimed to be conforming and was not. */
LH_TEST(conforming_below_the_floor_is_reported)
{
    static const int grid[30][2] = {
        {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, 0}, {-8, 5}, {4, 7}, {5, -6}, {-8, -7},
        {-2, -8}, {1, -8}, {-8, -7}, {2, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8},
        {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}};
    double xy[60];
    lh_index seg[60];
    for (int i = 0; i < 30; i++) {
        for (int j = 0; j < 2; j++) xy[2 * i + j] = grid[i][j] + ldexp(1, 40);
        seg[2 * i] = i, seg[2 * i + 1] = (i + 1) % 30;
    }
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 30, g.xy = xy, g.segment_count = 30, g.segments = seg;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.conforming = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "conforming at 2^40");
    if (m) {
        lh_trimesh_stats st;
        lh_trimesh_stats_get(m, &st);
        lh_error err;
        const lh_status conforming = lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m),
                                                      lh_trimesh_triangle_count(m), lh_trimesh_triangles(m), 0,
                                                      NULL, 1, NULL, &err);
        LH_EXPECT_GT_U64(st.segments_unsplit, 0);
        if (conforming != LH_OK) LH_NOTE("not conforming, as reported: %s", err.message);
    }
    lh_trimesh_free(m);
}

/* fuzz/README.md finding 9: a ring on the grid -8..8 at (x + 2^40) 2^-8, where a
 * rounded crossing vertex is 2^-12 of a grid unit off its segment. Segment 13
 * ((-8,-2) to (7,-5)) passes exactly through vertex 3 (-3,-3) after a crossing with
 * segment 7; from the bent vertex the rest missed vertex 3 and the crossing beside it
 * was refused: "segment 13 crosses segment 2" for segments that only touch. The rest
 * now goes through the vertex the input segment runs through. */
LH_TEST(a_bent_segment_still_meets_the_vertex_on_it)
{
    static const int grid[29][2] = {
        {4, -8}, {-8, 1}, {-8, -8}, {-3, -3}, {-7, -8}, {4, -8}, {-8, -4}, {-7, -7}, {1, 2}, {-1, -7},
        {-7, -8}, {-8, -8}, {-8, -8}, {-8, -2}, {7, -5}, {0, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8},
        {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}, {-8, -8}};
    double xy[58];
    lh_index seg[58];
    for (int i = 0; i < 29; i++) {
        for (int j = 0; j < 2; j++) xy[2 * i + j] = (grid[i][j] + ldexp(1, 40)) * ldexp(1, -8);
        seg[2 * i] = i, seg[2 * i + 1] = (i + 1) % 29;
    }
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 29, g.xy = xy, g.segment_count = 29, g.segments = seg, g.even_odd = 1;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.split_crossings = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "bent ring");
    if (m) {
        lh_trimesh_stats st;
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_GT_U64(st.crossings_split, 0);
        /* segment 13's chain goes through vertex 3 */
        const lh_index *par = lh_trimesh_segment_parents(m), *sv = lh_trimesh_segments(m);
        size_t at3 = 0;
        for (size_t s = 0; s < lh_trimesh_segment_count(m); s++)
            at3 += par[s] == 13 && (sv[2 * s] == 3 || sv[2 * s + 1] == 3);
        LH_EXPECT_EQ_U64(at3, 2);
    }
    lh_trimesh_free(m);
}

/* earcut's degenerate rings (zero-area, self-touching, shared points, holes outside
 * or touching, self-crossing): each meshed and exactly valid, or refused with
 * a message and LH_ERR_CROSSING_SEGMENTS (crossings without split_crossings) or
 * LH_ERR_DEGENERATE (an empty
 * domain); with split_crossings none is refused for crossing. Refined at 20 and 30
 * degrees each ends well inside a Steiner budget of 20,000 (infinite-loop-jhl's two
 * segments 10^-28 apart split without end before the resolution floor of refine.c). */
LH_TEST(earcut_degenerate_rings_are_valid_or_refused_clearly)
{
    static const char *const files[] = {
        "bad-diagonals", "bad-hole", "collinear-diagonal", "degenerate", "empty-square",
        "filtered-bridge-jhl", "hole-touching-outer", "hourglass", "infinite-loop-jhl",
        "issue107", "issue111", "issue119", "issue131", "issue142", "issue147", "issue149",
        "issue16", "issue17", "issue186", "issue29", "issue45", "issue83", "outside-ring",
        "self-tangent-1", "self-tangent-2", "self-tangent-3", "self-tangent-4", "self-touching",
        "shared-points", "touching-holes", "touching-holes2", "touching-holes3",
        "touching-holes4", "touching-holes5", "touching-holes6", "touching2", "touching3",
        "touching4"};
    size_t meshed = 0;
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[128];
        snprintf(path, sizeof path, "polygons/degenerate/%s.json", files[i]);
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_rings_read, path, &g), LH_OK);
        for (int run = 0; run < 6; run++) {
            const int split = run & 1;
            lh_trimesh_options o;
            lh_trimesh_options_default(&o);
            o.split_crossings = split;
            o.min_angle = run < 2 ? 0 : run < 4 ? 20 : 30;
            o.max_steiner = 20000;
            lh_trimesh *m = NULL;
            lh_error err, cerr;
            lh_status st = lh_pslg_triangulate(&g, &o, &m, &err);
            if (st == LH_OK) {
                LH_EXPECT_EQ_INT(check(m, &cerr), LH_OK);
                if (cerr.message[0]) LH_NOTE("%s: %s", files[i], cerr.message);
                lh_trimesh_stats ts;
                lh_trimesh_stats_get(m, &ts);
                if (ts.steiner_limit_reached) LH_NOTE("%s run %d: the Steiner budget ran out", files[i], run);
                LH_EXPECT_EQ_INT(ts.steiner_limit_reached, 0);
                meshed += run == 1;
            } else {
                const int crosses = strstr(err.message, "crosses") != NULL;
                if (st != (crosses ? LH_ERR_CROSSING_SEGMENTS : LH_ERR_DEGENERATE) || !err.message[0])
                    LH_NOTE("%s split %d: %s %s", files[i], split, lh_status_name(st), err.message);
                LH_EXPECT_EQ_INT(st, crosses ? LH_ERR_CROSSING_SEGMENTS : LH_ERR_DEGENERATE);
                LH_EXPECT_TRUE(err.message[0] != 0);
                if (split) LH_EXPECT_TRUE(!crosses);
            }
            lh_trimesh_free(m);
        }
        lh_pslg_free(&g);
    }
    LH_NOTE("%zu of %zu meshed with split_crossings", meshed, sizeof files / sizeof files[0]);
    LH_EXPECT_GE_INT(meshed, 30);
}

/* CGAL's Mesh_2 regression: an edge 8e-16 long among nine constraints. */
LH_TEST(cgal_tiny_edge_is_meshed)
{
    char full[512];
    snprintf(full, sizeof full, "%s/degenerate/cgal_issue_781_very_tiny_edge.txt", LH_TEST_DATA_DIR);
    FILE *f = fopen(full, "r");
    LH_ASSERT_TRUE(f != NULL);
    double xy[40];
    lh_index seg[18];
    size_t np = 0, k;
    LH_ASSERT_TRUE(fscanf(f, "%zu", &k) == 1 && k == 1);
    LH_ASSERT_TRUE(fscanf(f, "%lf %lf", xy, xy + 1) == 2);
    np = 1;
    LH_ASSERT_TRUE(fscanf(f, "%zu", &k) == 1 && k == 9);
    for (size_t s = 0; s < 9; s++) {
        LH_ASSERT_TRUE(fscanf(f, "%lf %lf %lf %lf", xy + 2 * np, xy + 2 * np + 1, xy + 2 * np + 2, xy + 2 * np + 3) == 4);
        seg[2 * s] = (lh_index)np, seg[2 * s + 1] = (lh_index)np + 1;
        np += 2;
    }
    fclose(f);
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = np, g.xy = xy, g.segment_count = 9, g.segments = seg;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.convex_hull = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "tiny edge");
    lh_trimesh_free(m);
    o.min_angle = 20.7;
    m = mesh_checked(lh_t_, &g, &o, "tiny edge -q20.7");
    lh_trimesh_free(m);
}

LH_TEST(degenerate_input_is_resolved_and_reported)
{
    /* vertex 5 duplicates 1, segment 5 has zero length after merging, segment 6
       overlaps segment 1 in part (vertex 6 lies on it and splits it), the hole seed
       is outside the domain */
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text("6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 0 0\n6 2 0\n"
                               "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 5\n6 1 6\n1\n1 9 9\n",
                               &g),
                     LH_OK);
    lh_trimesh *m = mesh_checked(lh_t_, &g, NULL, "degenerate");
    if (m) {
        lh_trimesh_stats st;
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_EQ_U64(st.duplicates_merged, 1);
        LH_EXPECT_EQ_U64(st.segments_dropped, 1);
        LH_EXPECT_EQ_U64(st.segments_overlapping, 1);
        LH_EXPECT_EQ_U64(st.holes_ignored, 1);
        LH_EXPECT_EQ_U64(st.triangles, 3); /* the square with vertex 6 on its bottom side */
        LH_EXPECT_EQ_U64(lh_trimesh_segment_count(m), 5);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(a_small_angle_far_from_the_origin_ends),
        LH_CASE(conforming_below_the_floor_is_reported),
        LH_CASE(a_bent_segment_still_meets_the_vertex_on_it),
        LH_CASE(earcut_degenerate_rings_are_valid_or_refused_clearly),
        LH_CASE(cgal_tiny_edge_is_meshed),
        LH_CASE(degenerate_input_is_resolved_and_reported),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
