/* test_trimesh.c — 2D meshing (lifthull.h, "2D meshing"): lh_pslg_triangulate on
 * Triangle's files and earcut's polygons, checked exactly by lh_cdt_check (every
 * triangle counterclockwise, subsegments are edges, boundary edges are subsegments,
 * every other edge locally Delaunay); the CDT of a polygon with h holes has n + 2h - 2
 * triangles; quality bounds met but at small input angles; conforming Delaunay,
 * smoothing, area bounds, holes and regions; determinism. Degenerate inputs:
 * test_trimesh_degenerate.c; errors: test_trimesh_errors.c; refining a given mesh:
 * test_trimesh_refine.c. */
#include "trimesh_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const triangle_files[] = {
    "triangle/A.poly", "triangle/la.poly", "triangle/face.poly", "triangle/double_hex.poly",
    "triangle/double_hex2.poly", "triangle/double_hex3.poly", "triangle/square_circle_hole.poly",
    "triangle/fish-and-rectangle.poly"};

LH_TEST(cdt_of_triangle_files_is_exactly_valid)
{
    for (size_t i = 0; i < sizeof triangle_files / sizeof triangle_files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_poly_read, triangle_files[i], &g), LH_OK);
        lh_trimesh *m = mesh_checked(lh_t_, &g, NULL, triangle_files[i]);
        if (m) {
            lh_trimesh_stats st;
            lh_trimesh_stats_get(m, &st);
            LH_EXPECT_EQ_U64(st.steiner_points, 0);
            LH_EXPECT_EQ_U64(lh_trimesh_point_count(m), g.n);
            expect_segments_kept(lh_t_, &g, m);
        }
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* Polygons (an outer ring and disjoint holes, no crossing, no touching): n + 2h - 2
 * triangles, n the vertices, h the holes — the count every triangulation without
 * Steiner points has; each vertex alone inside (earcut's one-point "Steiner" rings)
 * adds 2. (boxy, eberly-3, eberly-6, rain have rings touching: another count.) */
LH_TEST(earcut_polygons_have_n_plus_2h_minus_2_triangles)
{
    static const char *const files[] = {
        "polygons/building.json", "polygons/dude.json", "polygons/earcut.json",
        "polygons/hilbert.json", "polygons/issue34.json",
        "polygons/issue35.json", "polygons/issue52.json", "polygons/steiner.json"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_rings_read, files[i], &g), LH_OK);
        lh_trimesh *m = mesh_checked(lh_t_, &g, NULL, files[i]);
        if (m) {
            lh_trimesh_stats st;
            lh_trimesh_stats_get(m, &st);
            /* rings: a segment closes each, so segments = vertices per ring; one-point
               rings (earcut's Steiner points) have no segment */
            size_t rings = 0, alone = g.n;
            for (size_t s = 0; s < g.segment_count; s++) rings += g.segments[2 * s + 1] < g.segments[2 * s];
            alone -= g.segment_count; /* a ring of k >= 2 points has k segments */
            const size_t h = rings - 1, want = g.n + alone + 2 * h - 2;
            LH_EXPECT_EQ_U64(st.duplicates_merged, 0);
            if (st.triangles != want) LH_NOTE("%s: n %zu h %zu alone %zu", files[i], g.n, h, alone);
            LH_EXPECT_EQ_U64(st.triangles, want);
        }
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* The smallest angle between two input segments at each vertex (degrees). */
static double *input_angles(const lh_pslg *g)
{
    double *a = malloc((g->n ? g->n : 1) * sizeof *a);
    if (!a) return NULL;
    for (size_t i = 0; i < g->n; i++) a[i] = 360;
    for (size_t s = 0; s < g->segment_count; s++)
        for (size_t t = s + 1; t < g->segment_count; t++)
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    const lh_index o = g->segments[2 * s + i];
                    if (o != g->segments[2 * t + j]) continue;
                    const double *po = g->xy + 2 * (size_t)o, *pa = g->xy + 2 * (size_t)g->segments[2 * s + 1 - i],
                                 *pb = g->xy + 2 * (size_t)g->segments[2 * t + 1 - j];
                    const double ang = fabs(atan2(pa[1] - po[1], pa[0] - po[0]) - atan2(pb[1] - po[1], pb[0] - po[0]));
                    const double d = fmin(ang, 2 * 3.14159265358979323846 - ang) * 180 / 3.14159265358979323846;
                    a[o] = fmin(a[o], d);
                }
    return a;
}

LH_TEST(quality_bound_met_but_at_small_input_angles)
{
    for (size_t i = 0; i < sizeof triangle_files / sizeof triangle_files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_poly_read, triangle_files[i], &g), LH_OK);
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.min_angle = 30;
        lh_trimesh *m = mesh_checked(lh_t_, &g, &o, triangle_files[i]);
        double *small = input_angles(&g);
        if (m && small) {
            lh_trimesh_stats st;
            lh_trimesh_stats_get(m, &st);
            size_t below = 0;
            for (size_t v = 0; v < g.n; v++) below += small[v] < 30;
            if (!below) LH_EXPECT_GE_INT(st.min_angle, 30.0);
            if (!below) LH_EXPECT_EQ_U64(st.bad_triangles, 0);
            LH_EXPECT_LE_U64(st.bad_triangles, 4 * below); /* a few per small angle */
            expect_segments_kept(lh_t_, &g, m);
        }
        free(small);
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

/* Chew's rule: before a subsegment is split for a rejected centre, the free Steiner
 * points inside its diametral circle are removed. The output then has no point left
 * in no triangle, the later points renumbered with their attributes (here the affine
 * function x + 2y, which interpolation reproduces), and on double_hex3.poly at 30
 * degrees as few triangles as Triangle 1.6 -pq30 makes within 15% (60; 75 without
 * the rule). */
LH_TEST(chews_rule_removes_points_crowding_a_segment)
{
    size_t removed = 0;
    for (size_t i = 0; i < sizeof triangle_files / sizeof triangle_files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_poly_read, triangle_files[i], &g), LH_OK);
        double *const read_attr = g.attr, *f = malloc((g.n ? g.n : 1) * sizeof *f);
        const int read_count = g.attr_count;
        LH_ASSERT_TRUE(f != NULL);
        for (size_t v = 0; v < g.n; v++) f[v] = g.xy[2 * v] + 2 * g.xy[2 * v + 1];
        g.attr = f, g.attr_count = 1;
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.min_angle = 30;
        lh_trimesh *m = mesh_checked(lh_t_, &g, &o, triangle_files[i]);
        if (m) {
            lh_trimesh_stats st;
            lh_trimesh_stats_get(m, &st);
            removed += st.steiner_removed;
            const size_t np = lh_trimesh_point_count(m);
            LH_EXPECT_EQ_U64(np, g.n + st.steiner_points);
            char *used = calloc(np, 1);
            LH_ASSERT_TRUE(used != NULL);
            const lh_index *tri = lh_trimesh_triangles(m);
            for (size_t k = 0; k < 3 * lh_trimesh_triangle_count(m); k++) used[tri[k]] = 1;
            const double *xy = lh_trimesh_points(m), *at = lh_trimesh_point_attrs(m);
            size_t orphans = 0, off = 0;
            for (size_t v = g.n; v < np; v++) {
                orphans += !used[v];
                off += fabs(at[v] - (xy[2 * v] + 2 * xy[2 * v + 1])) > 1e-9;
            }
            free(used);
            LH_EXPECT_EQ_U64(orphans, 0);
            LH_EXPECT_EQ_U64(off, 0);
            if (strstr(triangle_files[i], "double_hex3")) {
                LH_EXPECT_GT_U64(st.steiner_removed, 0);
                LH_EXPECT_LE_U64(lh_trimesh_triangle_count(m), 69);
            }
        }
        lh_trimesh_free(m);
        free(f);
        g.attr = read_attr, g.attr_count = read_count;
        lh_pslg_free(&g);
    }
    LH_EXPECT_GT_U64(removed, 10);
}

/* -D: subsegments split until every edge, those on segments too, is locally Delaunay
 * (checked with no subsegments given, so that every interior edge is tested). */
/* Meshes g with o, asserts that every edge is Delaunay (the check with no subsegment),
 * nothing left unsplit and the segments kept; returns the mesh. */
static lh_trimesh *mesh_all_delaunay(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                                     const char *what)
{
    lh_trimesh *m = mesh_checked(lh_t_, g, o, what);
    lh_error err;
    if (!m) return NULL;
    LH_EXPECT_EQ_INT(lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                                      lh_trimesh_triangles(m), 0, NULL, 1, NULL, &err),
                     LH_OK);
    if (err.message[0]) LH_NOTE("%s: %s", what, err.message);
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    LH_EXPECT_EQ_U64(st.segments_unsplit, 0);
    expect_segments_kept(lh_t_, g, m);
    return m;
}

LH_TEST(conforming_delaunay_has_every_edge_delaunay)
{
    for (size_t i = 0; i < sizeof triangle_files / sizeof triangle_files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_poly_read, triangle_files[i], &g), LH_OK);
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.conforming = 1;
        lh_trimesh *m = mesh_all_delaunay(lh_t_, &g, &o, triangle_files[i]);
        lh_trimesh *cdt = mesh_checked(lh_t_, &g, NULL, "cdt");
        lh_error err;
        /* the plain CDT of these files is not conforming: the test can fail */
        if (cdt && i == 1) /* la.poly */
            LH_EXPECT_EQ_INT(lh_cdt_check(lh_trimesh_point_count(cdt), lh_trimesh_points(cdt),
                                              lh_trimesh_triangle_count(cdt), lh_trimesh_triangles(cdt), 0, NULL,
                                              1, NULL, &err),
                             LH_ERR_INVALID_MESH);
        lh_trimesh_free(m);
        lh_trimesh_free(cdt);
        lh_pslg_free(&g);
    }
}

/* Smoothing: points move, the mesh stays an exactly valid CDT, its smallest angle does
 * not go down and the area bound still holds; the mean of the triangles' smallest
 * angles goes up. */
static double mean_min_angle(const lh_trimesh *m)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m);
    double sum = 0;
    for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
        double worst = 180;
        for (int k = 0; k < 3; k++) {
            const double *o = xy + 2 * (size_t)t[3 * i + k], *u = xy + 2 * (size_t)t[3 * i + (k + 1) % 3],
                         *v = xy + 2 * (size_t)t[3 * i + (k + 2) % 3];
            const double a = atan2(fabs((u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])),
                                   (u[0] - o[0]) * (v[0] - o[0]) + (u[1] - o[1]) * (v[1] - o[1]));
            worst = fmin(worst, a * 180 / 3.14159265358979323846);
        }
        sum += worst;
    }
    return sum / (double)lh_trimesh_triangle_count(m);
}

LH_TEST(smoothing_raises_angles_and_keeps_the_mesh_valid)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 25;
    o.max_area = 0.0005;
    lh_trimesh *a = mesh_checked(lh_t_, &g, &o, "A");
    o.smooth = 5;
    lh_trimesh *b = mesh_checked(lh_t_, &g, &o, "A smoothed");
    if (a && b) {
        lh_trimesh_stats sa, sb;
        lh_trimesh_stats_get(a, &sa);
        lh_trimesh_stats_get(b, &sb);
        LH_EXPECT_GT_U64(sb.smoothing_moves, 10);
        LH_EXPECT_EQ_U64(sb.triangles, sa.triangles);
        LH_EXPECT_LE_DBL(sa.min_angle, sb.min_angle);
        LH_EXPECT_LE_DBL(sb.max_area, 0.0005);
        const double ma = mean_min_angle(a), mb = mean_min_angle(b);
        LH_NOTE("mean smallest angle %.3f -> %.3f, smallest %.3f -> %.3f, %zu moves", ma, mb, sa.min_angle,
                sb.min_angle, sb.smoothing_moves);
        LH_EXPECT_LE_DBL(ma + 0.5, mb);
        expect_segments_kept(lh_t_, &g, b);
    }
    lh_trimesh_free(a);
    lh_trimesh_free(b);
    lh_pslg_free(&g);
}

LH_TEST(area_bound_and_steiner_limit)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/A.poly", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 20;
    o.max_area = 0.01;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "A -q20 -a0.01");
    lh_trimesh_stats st;
    if (m) {
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_LE_DBL(st.max_area, 0.01);
        LH_EXPECT_GT_U64(st.triangles, 60);
    }
    lh_trimesh_free(m);
    o.max_steiner = 10;
    m = mesh_checked(lh_t_, &g, &o, "A -S10");
    if (m) {
        lh_trimesh_stats_get(m, &st);
        LH_EXPECT_EQ_U64(st.steiner_points, 10);
        LH_EXPECT_EQ_INT(st.steiner_limit_reached, 1);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

static const char square_with_hole[] =
    "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n7 3 3\n8 1 3\n"
    "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
    "1\n1 2 2\n";

LH_TEST(holes_are_carved_and_regions_marked)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text(square_with_hole, &g), LH_OK);
    lh_trimesh *m = mesh_checked(lh_t_, &g, NULL, "square with hole");
    if (m) LH_EXPECT_EQ_U64(lh_trimesh_triangle_count(m), 8); /* 8 + 2 - 2 */
    lh_trimesh_free(m);
    g.hole_count = 0; /* no hole: the inner square is meshed too, 2 more triangles */
    m = mesh_checked(lh_t_, &g, NULL, "no hole");
    if (m) LH_EXPECT_EQ_U64(lh_trimesh_triangle_count(m), 10);
    lh_trimesh_free(m);
    /* regions: the inner square gets attribute 7 */
    double reg[8] = {2, 2, 7, -1, 0.5, 0.5, 3, -1};
    g.regions = reg;
    g.region_count = 2;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.region_attributes = 1;
    m = mesh_checked(lh_t_, &g, &o, "regions");
    if (m) {
        const double *at = lh_trimesh_triangle_attrs(m);
        size_t seven = 0, three = 0;
        for (size_t t = 0; t < lh_trimesh_triangle_count(m); t++) seven += at[t] == 7, three += at[t] == 3;
        LH_EXPECT_EQ_U64(seven, 2);
        LH_EXPECT_EQ_U64(three, 8);
    }
    lh_trimesh_free(m);
    g.regions = NULL; /* the reader's arrays only */
    g.region_count = 0;
    lh_pslg_free(&g);
}

/* Two unit fields side by side, split by the segment x = 1, the left one with the
 * finer area bound (regions: x, y, attribute, area). */
static const char two_fields[] = "6 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 2 1\n5 1 1\n6 0 1\n"
                                 "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n"
                                 "2\n1 0.5 0.5 1 0.002\n2 1.5 0.5 2 0.5\n";

/* Refinement keeps Triangle's regions: a triangle's pieces keep its attribute and
 * area bound (the split segment's cavity lies on both sides; before the fix the left
 * field's leaked across x = 1 with each split: 767 triangles wrong, 814 points where
 * Triangle makes 432). Markers by Triangle's rule, no marker in the file: a point
 * on the boundary 1, inside 0 (on the inner segment too: it was 1). */
LH_TEST(regions_and_markers_survive_refinement)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text(two_fields, &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 20, o.region_areas = 1, o.region_attributes = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "two fields");
    if (m) {
        const double *xy = lh_trimesh_points(m), *at = lh_trimesh_triangle_attrs(m);
        const lh_index *t = lh_trimesh_triangles(m), *mk = lh_trimesh_point_markers(m);
        size_t wrong = 0, over = 0, badmark = 0;
        for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
            const double *a = xy + 2 * t[3 * i], *b = xy + 2 * t[3 * i + 1], *c = xy + 2 * t[3 * i + 2];
            const int left = a[0] + b[0] + c[0] < 3; /* the centroid left of x = 1 (exact here) */
            const double area = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
            wrong += at[i] != (left ? 1 : 2);
            over += area > (left ? 0.002 : 0.5) * (1 + 1e-12);
        }
        for (size_t p = 0; p < lh_trimesh_point_count(m); p++) {
            const double x = xy[2 * p], y = xy[2 * p + 1];
            badmark += mk[p] != (x == 0 || x == 2 || y == 0 || y == 1);
        }
        LH_EXPECT_EQ_U64(wrong, 0);
        LH_EXPECT_EQ_U64(over, 0);
        LH_EXPECT_EQ_U64(badmark, 0);
        LH_EXPECT_LE_U64(lh_trimesh_point_count(m), 600);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
    /* box.poly with the hull kept (Triangle's -pc box, its box.1.node): the corners
       (0,0) and (1,2) take the markers 5 and 10 of the segments they end, not the 1 of
       the hull and hole edges there */
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/box.poly", &g), LH_OK);
    lh_trimesh_options_default(&o);
    o.convex_hull = 1;
    m = mesh_checked(lh_t_, &g, &o, "box -c");
    if (m) {
        static const lh_index want[8] = {5, 5, 1, 33, 1, 10, 1, 10};
        const lh_index *mk = lh_trimesh_point_markers(m);
        for (int p = 0; p < 8; p++) LH_EXPECT_EQ_INT(mk[p], want[p]);
    }
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

/* split_segments (Triangle's -s): every edge Delaunay, each segment a chain of edges;
 * A.poly gets Triangle's 2 Steiner points. */
LH_TEST(split_segments_makes_every_edge_delaunay)
{
    for (size_t i = 0; i < sizeof triangle_files / sizeof triangle_files[0]; i++) {
        lh_pslg g;
        LH_ASSERT_EQ_INT(load(lh_poly_read, triangle_files[i], &g), LH_OK);
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.split_segments = 1;
        lh_trimesh *m = mesh_all_delaunay(lh_t_, &g, &o, triangle_files[i]);
        if (m && i == 0) LH_EXPECT_EQ_U64(lh_trimesh_point_count(m), 31); /* A.poly: Triangle's -ps */
        lh_trimesh_free(m);
        lh_pslg_free(&g);
    }
}

static int cmp3(const void *x, const void *y)
{
    const lh_index *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* Whether two triangle lists hold the same triangles (each rotated to start at its
 * smallest vertex, then sorted). */
static int same_triangles(size_t n, const lh_index *a, const lh_index *b)
{
    lh_index *x = malloc((3 * n + 1) * sizeof *x), *y = malloc((3 * n + 1) * sizeof *y);
    int same = x && y;
    for (size_t t = 0; same && t < n; t++) {
        int ia = 0, ib = 0;
        for (int k = 1; k < 3; k++) {
            if (a[3 * t + k] < a[3 * t + ia]) ia = k;
            if (b[3 * t + k] < b[3 * t + ib]) ib = k;
        }
        for (int k = 0; k < 3; k++) x[3 * t + k] = a[3 * t + (ia + k) % 3], y[3 * t + k] = b[3 * t + (ib + k) % 3];
    }
    if (same) {
        qsort(x, n, 3 * sizeof *x, cmp3);
        qsort(y, n, 3 * sizeof *y, cmp3);
        same = !memcmp(x, y, 3 * n * sizeof *x);
    }
    free(x);
    free(y);
    return same;
}

LH_TEST(output_is_deterministic_and_independent_of_segment_order)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load(lh_poly_read, "triangle/la.poly", &g), LH_OK);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    lh_trimesh *a = mesh_checked(lh_t_, &g, &o, "la"), *b = mesh_checked(lh_t_, &g, &o, "la again");
    if (a && b) {
        LH_ASSERT_EQ_U64(lh_trimesh_triangle_count(a), lh_trimesh_triangle_count(b));
        LH_EXPECT_TRUE(!memcmp(lh_trimesh_triangles(a), lh_trimesh_triangles(b),
                               3 * lh_trimesh_triangle_count(a) * sizeof(lh_index)));
    }
    /* segments reversed in order and direction: the same triangles (a CDT of points in
       general position is unique), as sets */
    for (size_t s = 0; s < g.segment_count / 2; s++)
        for (int j = 0; j < 2; j++) {
            const lh_index x = g.segments[2 * s + j];
            g.segments[2 * s + j] = g.segments[2 * (g.segment_count - 1 - s) + 1 - j];
            g.segments[2 * (g.segment_count - 1 - s) + 1 - j] = x;
        }
    lh_trimesh *c = mesh_checked(lh_t_, &g, &o, "la reversed");
    if (a && c) {
        LH_ASSERT_EQ_U64(lh_trimesh_triangle_count(a), lh_trimesh_triangle_count(c));
        LH_EXPECT_EQ_INT(same_triangles(lh_trimesh_triangle_count(a), lh_trimesh_triangles(a),
                                        lh_trimesh_triangles(c)), 1);
    }
    lh_trimesh_free(a);
    lh_trimesh_free(b);
    lh_trimesh_free(c);
    lh_pslg_free(&g);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(cdt_of_triangle_files_is_exactly_valid),
        LH_CASE(earcut_polygons_have_n_plus_2h_minus_2_triangles),
        LH_CASE(quality_bound_met_but_at_small_input_angles),
        LH_CASE(chews_rule_removes_points_crowding_a_segment),
        LH_CASE(conforming_delaunay_has_every_edge_delaunay),
        LH_CASE(smoothing_raises_angles_and_keeps_the_mesh_valid),
        LH_CASE(area_bound_and_steiner_limit),
        LH_CASE(holes_are_carved_and_regions_marked),
        LH_CASE(regions_and_markers_survive_refinement),
        LH_CASE(split_segments_makes_every_edge_delaunay),
        LH_CASE(output_is_deterministic_and_independent_of_segment_order),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
