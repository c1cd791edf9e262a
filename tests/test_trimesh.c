/* test_trimesh.c — 2D meshing (lifthull.h, "2D meshing"): lh_pslg_triangulate on
 * Triangle's files and earcut's polygons, checked exactly by lh_cdt_check (every
 * triangle counterclockwise, subsegments are edges, boundary edges are subsegments,
 * every other edge locally Delaunay); the CDT of a polygon with h holes has n + 2h - 2
 * triangles; quality bounds met but at small input angles; every degenerate input's
 * resolution or error (message text and status); the checker's own rejections;
 * determinism; every allocation failure. */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef lh_test_pslg_reader reader;

static lh_status load(reader rd, const char *path, lh_pslg *g) { return lh_test_pslg_file(rd, LH_TEST_DATA_DIR, path, g); }
static lh_status load_text(const char *text, lh_pslg *g) { return lh_test_pslg_text(text, g); }
static lh_status check(const lh_trimesh *m, char *msg, size_t size) { return lh_test_check_trimesh(m, msg, size); }

/* Meshes g with o (NULL: defaults), asserts the exact check, returns the mesh. */
static lh_trimesh *mesh_checked(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                                const char *what)
{
    lh_trimesh *m = NULL;
    char msg[256] = "", cmsg[256] = "";
    lh_status st = lh_pslg_triangulate(g, o, &m, msg, sizeof msg);
    if (st != LH_OK) {
        LH_NOTE("%s: %s (%s)", what, lh_status_name(st), msg);
        LH_EXPECT_EQ_INT(st, LH_OK);
        return NULL;
    }
    st = check(m, cmsg, sizeof cmsg);
    if (st != LH_OK) LH_NOTE("%s: %s", what, cmsg);
    LH_EXPECT_EQ_INT(st, LH_OK);
    return m;
}

/* Every non-degenerate input segment is covered by subsegments that name it: their
 * total count at least one per segment, and with no Steiner point exactly one. */
static void expect_segments_kept(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh *m)
{
    size_t *hits = calloc(g->segment_count + 1, sizeof *hits);
    LH_ASSERT_TRUE(hits != NULL);
    const lh_index *par = lh_trimesh_segment_parents(m);
    for (size_t s = 0; s < lh_trimesh_segment_count(m); s++)
        if (par[s] >= 0) hits[par[s]]++;
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    /* a segment with an endpoint in no triangle lay in a hole or outside: removed */
    char *used = calloc(lh_trimesh_point_count(m) + 1, 1);
    LH_ASSERT_TRUE(used != NULL);
    const lh_index *tri = lh_trimesh_triangles(m);
    for (size_t i = 0; i < 3 * lh_trimesh_triangle_count(m); i++) used[tri[i]] = 1;
    size_t missing = 0;
    for (size_t s = 0; s < g->segment_count; s++)
        missing += hits[s] == 0 && used[g->segments[2 * s]] && used[g->segments[2 * s + 1]];
    free(used);
    LH_EXPECT_EQ_U64(missing, st.segments_dropped + st.segments_overlapping);
    free(hits);
}

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
    char msg[256] = "";
    if (!m) return NULL;
    LH_EXPECT_EQ_INT(lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                                      lh_trimesh_triangles(m), 0, NULL, 1, NULL, msg, sizeof msg),
                     LH_OK);
    if (msg[0]) LH_NOTE("%s: %s", what, msg);
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
        char msg[256] = "";
        /* the plain CDT of these files is not conforming: the test can fail */
        if (cdt && i == 1) /* la.poly */
            LH_EXPECT_EQ_INT(lh_cdt_check(lh_trimesh_point_count(cdt), lh_trimesh_points(cdt),
                                              lh_trimesh_triangle_count(cdt), lh_trimesh_triangles(cdt), 0, NULL,
                                              1, NULL, msg, sizeof msg),
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

static void expect_failure(lh_test_state *lh_t_, const char *text, lh_status want, const char *want_msg)
{
    lh_pslg g;
    LH_ASSERT_EQ_INT(load_text(text, &g), LH_OK);
    lh_trimesh *m = (lh_trimesh *)&g;
    char msg[256];
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), want);
    LH_EXPECT_TRUE(m == NULL);
    LH_EXPECT_STREQ(msg, want_msg);
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
    char msg[128];
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_NONFINITE);
    LH_EXPECT_STREQ(msg, "vertex 2: coordinate is NaN or infinite");
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(NULL, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    /* an endpoint out of range (the reader catches it in files; a caller's array here) */
    xy[5] = 1;
    lh_index seg[2] = {0, 3};
    g.segments = seg, g.segment_count = 1;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "segment 0: endpoint 3 is not a vertex (0..2)");
    g.segment_count = 0;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 41;
    xy[5] = 1;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "min_angle 41 outside 0..40 degrees");
    /* just past the bound: the message shows the value, not the bound again */
    o.min_angle = 40.0000001;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "min_angle 40.000000100000001 outside 0..40 degrees");
    o.min_angle = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "min_angle nan outside 0..40 degrees");
    /* a NaN area bound is named as such (it is no angle) */
    o.min_angle = 0;
    o.max_area = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "max_area is NaN (0 or below: no area bound)");
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
    char msg[128];
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "the mesh to refine has crossing edges");
    LH_EXPECT_TRUE(m == NULL);
    g.xy = line, g.cover_count = 1, g.cover = flat;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "the mesh to refine has no triangle of positive area");
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
    char msg[128];
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "an array of the PSLG is missing");
    LH_EXPECT_TRUE(m == NULL);
    g.cover_count = 0;
    lh_trimesh_options_default(NULL);
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.max_area = NAN;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "max_area is NaN (0 or below: no area bound)");
    o.max_area = 0;
    lh_allocator none = {NULL, NULL, NULL};
    o.alloc = &none;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "the allocator lacks its alloc or free hook");
    lh_index seg[2] = {0, 1};
    g.n = 0, g.segment_count = 1, g.segments = seg;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "segment 0: endpoint 0 is not a vertex (there are none)");
    LH_EXPECT_TRUE(m == NULL);
    /* counts no array can have: refused before any size is computed from them */
    g.n = 4, g.segment_count = 0, g.cover_count = SIZE_MAX, g.cover = seg;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_TOO_LARGE);
    g.cover_count = 0, g.attr_count = INT32_MAX, g.attr = xy, g.n = SIZE_MAX / 8;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_TOO_LARGE);
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
        char msg[256];
        LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_CROSSING_SEGMENTS);
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
        char msg[256] = "";
        const lh_status conforming = lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m),
                                                      lh_trimesh_triangle_count(m), lh_trimesh_triangles(m), 0,
                                                      NULL, 1, NULL, msg, sizeof msg);
        LH_EXPECT_GT_U64(st.segments_unsplit, 0);
        if (conforming != LH_OK) LH_NOTE("not conforming, as reported: %s", msg);
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
            char msg[256] = "", cmsg[256] = "";
            lh_status st = lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg);
            if (st == LH_OK) {
                LH_EXPECT_EQ_INT(check(m, cmsg, sizeof cmsg), LH_OK);
                if (cmsg[0]) LH_NOTE("%s: %s", files[i], cmsg);
                lh_trimesh_stats ts;
                lh_trimesh_stats_get(m, &ts);
                if (ts.steiner_limit_reached) LH_NOTE("%s run %d: the Steiner budget ran out", files[i], run);
                LH_EXPECT_EQ_INT(ts.steiner_limit_reached, 0);
                meshed += run == 1;
            } else {
                const int crosses = strstr(msg, "crosses") != NULL;
                if (st != (crosses ? LH_ERR_CROSSING_SEGMENTS : LH_ERR_DEGENERATE) || !msg[0])
                    LH_NOTE("%s split %d: %s %s", files[i], split, lh_status_name(st), msg);
                LH_EXPECT_EQ_INT(st, crosses ? LH_ERR_CROSSING_SEGMENTS : LH_ERR_DEGENERATE);
                LH_EXPECT_TRUE(msg[0] != 0);
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

/* Refining an existing mesh (Triangle's -ra): bbox.1's 12 triangles with their area
 * bounds (-1: none) are the domain; the result covers exactly their union and every
 * new triangle meets the bound of the old one holding its centroid. */
LH_TEST(an_existing_mesh_is_refined_with_its_area_bounds)
{
    char path[512], msg[256];
    lh_points pts;
    lh_cells cells;
    snprintf(path, sizeof path, "%s/triangle/bbox.1.node", LH_TEST_DATA_DIR);
    FILE *f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "bbox.1.node", LH_FORMAT_NODE, NULL, &pts, msg, sizeof msg), LH_OK);
    fclose(f);
    snprintf(path, sizeof path, "%s/triangle/bbox.1.ele", LH_TEST_DATA_DIR);
    f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_cells_read(f, "bbox.1.ele", pts.n, NULL, &cells, msg, sizeof msg), LH_OK);
    fclose(f);
    LH_ASSERT_EQ_INT(cells.nv, 3);
    double area[12];
    snprintf(path, sizeof path, "%s/triangle/bbox.1.area", LH_TEST_DATA_DIR);
    f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    size_t k = 0;
    LH_ASSERT_TRUE(fscanf(f, "%zu", &k) == 1 && k == 12 && cells.count == 12);
    for (size_t i = 0; i < 12; i++) {
        int num;
        LH_ASSERT_TRUE(fscanf(f, "%d %lf", &num, area + i) == 2);
    }
    fclose(f);
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = pts.n, g.xy = pts.xyz, g.cover_count = cells.count, g.cover = cells.v, g.cover_area = area;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.region_areas = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "bbox -ra");
    if (m) {
        double old_total = 0, total = 0;
        for (size_t i = 0; i < 12; i++) {
            const double *a = pts.xyz + 2 * (size_t)cells.v[3 * i], *b = pts.xyz + 2 * (size_t)cells.v[3 * i + 1],
                         *c = pts.xyz + 2 * (size_t)cells.v[3 * i + 2];
            old_total += fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
        }
        const double *xy = lh_trimesh_points(m);
        const lh_index *t = lh_trimesh_triangles(m);
        size_t bounded = 0;
        for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
            const double *a = xy + 2 * (size_t)t[3 * i], *b = xy + 2 * (size_t)t[3 * i + 1], *c = xy + 2 * (size_t)t[3 * i + 2];
            const double ar = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
            total += ar;
            const double p[2] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
            for (size_t j = 0; j < 12; j++) { /* the old triangle holding the centroid */
                const double *u = pts.xyz + 2 * (size_t)cells.v[3 * j], *v = pts.xyz + 2 * (size_t)cells.v[3 * j + 1],
                             *w = pts.xyz + 2 * (size_t)cells.v[3 * j + 2];
                const double s1 = (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
                const double s2 = (w[0] - v[0]) * (p[1] - v[1]) - (w[1] - v[1]) * (p[0] - v[0]);
                const double s3 = (u[0] - w[0]) * (p[1] - w[1]) - (u[1] - w[1]) * (p[0] - w[0]);
                if ((s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0)) {
                    if (area[j] > 0) LH_EXPECT_LE_DBL(ar, area[j]), bounded++;
                    break;
                }
            }
        }
        LH_EXPECT_TRUE(fabs(total - old_total) <= 1e-12 * old_total);
        LH_EXPECT_GT_U64(bounded, 10);
        LH_EXPECT_GT_U64(lh_trimesh_triangle_count(m), 12);
    }
    lh_trimesh_free(m);
    /* a cover naming a point that does not exist */
    cells.v[0] = (lh_index)pts.n;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "the mesh to refine names a point that does not exist, or has an edge of three triangles");
    lh_cells_free(&cells);
    lh_points_free(&pts);
}

/* Twice the total area of m's triangles. */
static double area2_sum(const lh_trimesh *m)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m);
    double sum = 0;
    for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
        const double *a = xy + 2 * (size_t)t[3 * i], *b = xy + 2 * (size_t)t[3 * i + 1], *c = xy + 2 * (size_t)t[3 * i + 2];
        sum += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
    return sum;
}

/* Refines the mesh `old` (its points and triangles as the cover) under o: the result
 * is exactly valid, covers the same union, meets the area bound, and names its bad
 * triangles in range and in order. Returns the Steiner points put on the old
 * boundary. */
static size_t refine_cover(lh_test_state *lh_t_, const lh_trimesh *old, const lh_trimesh_options *o,
                           const char *what)
{
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = lh_trimesh_point_count(old), g.xy = (double *)lh_trimesh_points(old); /* read only */
    g.cover_count = lh_trimesh_triangle_count(old), g.cover = (lh_index *)lh_trimesh_triangles(old);
    lh_trimesh *m = mesh_checked(lh_t_, &g, o, what);
    if (!m) return 0;
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    const double before = area2_sum(old), after = area2_sum(m);
    if (fabs(after - before) > 1e-12 * before) LH_NOTE("%s: area %.17g, was %.17g", what, after / 2, before / 2);
    LH_EXPECT_TRUE(fabs(after - before) <= 1e-12 * before);
    if (o->max_area > 0) LH_EXPECT_GT_U64(st.steiner_points, 0);
    if (o->max_area > 0) LH_EXPECT_LE_DBL(st.max_area, o->max_area);
    const lh_index *bad = lh_trimesh_bad_triangles(m);
    for (size_t i = 0; i < st.bad_triangles; i++) {
        LH_EXPECT_TRUE(bad[i] >= 0 && (size_t)bad[i] < lh_trimesh_triangle_count(m));
        if (i) LH_EXPECT_LT_INT(bad[i - 1], bad[i]);
    }
    const size_t on_boundary = st.steiner_on_segments;
    lh_trimesh_free(m);
    return on_boundary;
}

/* Triangle's -r with -a or -q (`-pc box.poly` then `-rpa0.2 box.1`; `-rq30 face.1`):
 * Steiner points on the old mesh's boundary edges (subsegment parents -2, -3, ...)
 * were taken for removed points (pseg -2), dropped, and their triangles left naming
 * point -1: reads before the point array, a double free. Every such refinement is
 * exactly valid; the unit square split along a diagonal, and meshes of Triangle's
 * files, each refined by area, angle and both. */
LH_TEST(refining_a_mesh_splits_its_boundary_edges)
{
    const char *const files[] = {"triangle/box.poly", "triangle/face.poly", "triangle/A.poly"};
    for (size_t i = 0; i < sizeof files / sizeof files[0] + 1; i++) {
        lh_trimesh *old = NULL;
        if (i == 0) { /* the unit square, two triangles */
            static double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
            static lh_index cover[] = {0, 1, 3, 1, 2, 3};
            lh_pslg sq;
            memset(&sq, 0, sizeof sq);
            sq.n = 4, sq.xy = xy, sq.cover_count = 2, sq.cover = cover;
            old = mesh_checked(lh_t_, &sq, NULL, "the unit square as a cover");
        } else {
            lh_pslg g;
            LH_ASSERT_EQ_INT(load(lh_poly_read, files[i - 1], &g), LH_OK);
            lh_trimesh_options c;
            lh_trimesh_options_default(&c);
            c.convex_hull = 1; /* -pc */
            old = mesh_checked(lh_t_, &g, &c, files[i - 1]);
            lh_pslg_free(&g);
        }
        if (!old) continue;
        const double area = area2_sum(old) / 2;
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.max_area = area / 50;
        size_t on_boundary = refine_cover(lh_t_, old, &o, "-ra");
        o.max_area = 0, o.min_angle = 30;
        refine_cover(lh_t_, old, &o, "-rq30");
        o.max_area = area / 200;
        on_boundary += refine_cover(lh_t_, old, &o, "-rq30a");
        LH_EXPECT_GT_U64(on_boundary, 0);
        lh_trimesh_free(old);
    }
}

/* -rp: the input segments along the old mesh's boundary give their markers and
 * parents to its pieces and to the Steiner points put there (as Triangle's -rpa on
 * box.1, reference_outputs/box.2: cli_triangle_ref), not the old boundary's 1 and -1. */
LH_TEST(refining_a_mesh_keeps_the_segments_along_its_boundary)
{
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    lh_index cover[6] = {0, 1, 3, 1, 2, 3}, seg[8] = {0, 1, 1, 2, 2, 3, 3, 0}, mark[4] = {5, 6, 7, 8};
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 4, g.xy = xy, g.cover_count = 2, g.cover = cover;
    g.segment_count = 4, g.segments = seg, g.segment_marker = mark;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.max_area = 0.01;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "-rpa0.01 square");
    LH_ASSERT_TRUE(m != NULL);
    const double *p = lh_trimesh_points(m);
    const lh_index *pm = lh_trimesh_point_markers(m), *sv = lh_trimesh_segments(m),
                   *sm = lh_trimesh_segment_markers(m), *sp = lh_trimesh_segment_parents(m);
    size_t on_bottom = 0;
    for (size_t i = 4; i < lh_trimesh_point_count(m); i++)
        if (p[2 * i + 1] == 0) LH_EXPECT_EQ_INT(pm[i], 5), on_bottom++;
    LH_EXPECT_GT_U64(on_bottom, 0);
    for (size_t s = 0; s < lh_trimesh_segment_count(m); s++) {
        LH_EXPECT_TRUE(sp[s] >= 0 && sp[s] < 4);
        if (sp[s] >= 0 && sp[s] < 4) LH_EXPECT_EQ_INT(sm[s], mark[sp[s]]);
        if (p[2 * sv[2 * s] + 1] == 0 && p[2 * sv[2 * s + 1] + 1] == 0) LH_EXPECT_EQ_INT(sp[s], 0);
    }
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
        char msg[128];
        const lh_status st = lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg);
        if (i < 3) {
            LH_EXPECT_EQ_INT(st, LH_ERR_DEGENERATE);
            LH_EXPECT_STREQ(msg, want[i]);
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
    char msg[128];
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_OK);
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
    char msg[128];
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 4, hull, 0, NULL, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, flipped, 4, hull, 0, NULL, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "triangle 0 is not counterclockwise with positive area");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 3, hull, 0, NULL, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "a boundary edge of triangle 1 is not a subsegment");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 3, hull, 1, NULL, msg, sizeof msg), LH_OK);
    /* misuse: a message says which argument */
    const lh_index far_seg[] = {0, 1, 1, 7};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 2, far_seg, 1, NULL, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "subsegment 1: endpoint 7 is not a point (0..3)");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, NULL, 2, good, 0, NULL, 1, NULL, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "xy is NULL with a count above 0");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, NULL, 0, NULL, 1, NULL, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "tris is NULL with a count above 0");
    const lh_allocator half = {NULL, NULL, NULL};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, xy, 2, good, 0, NULL, 1, &half, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "the allocator lacks alloc or free");
    /* a kite whose diagonal is not Delaunay: (0,0) (2,-1) (4,0) (2,1) split 1-3 is
       Delaunay, split 0-2 is not */
    const double kite[] = {0, 0, 2, -0.5, 4, 0, 2, 0.5};
    const lh_index long_diag[] = {0, 1, 2, 0, 2, 3}, short_diag[] = {0, 1, 3, 1, 2, 3};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, short_diag, 0, NULL, 1, NULL, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, long_diag, 0, NULL, 1, NULL, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "an unconstrained edge of triangle 0 is not locally Delaunay");
    const lh_index seg[] = {0, 2}; /* ... unless that diagonal is a subsegment */
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, long_diag, 1, seg, 1, NULL, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(lh_cdt_check(4, kite, 2, short_diag, 1, seg, 1, NULL, msg, sizeof msg), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(msg, "subsegment 0 is not an edge of the triangulation");
}

static lh_status mesh_with(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.min_angle = 25;
    o.region_attributes = 1;
    o.alloc = a;
    lh_trimesh *m = NULL;
    lh_status st = lh_pslg_triangulate(user, &o, &m, NULL, 0);
    if (st != LH_OK) LH_EXPECT_TRUE(m == NULL);
    lh_trimesh_free(m);
    return st;
}

static lh_status check_with(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)lh_t_;
    const lh_trimesh *m = user;
    return lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                            lh_trimesh_triangles(m), lh_trimesh_segment_count(m), lh_trimesh_segments(m), 0, a,
                            NULL, 0);
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
        LH_CASE(cdt_of_triangle_files_is_exactly_valid), LH_CASE(earcut_polygons_have_n_plus_2h_minus_2_triangles),
        LH_CASE(quality_bound_met_but_at_small_input_angles), LH_CASE(chews_rule_removes_points_crowding_a_segment),
        LH_CASE(conforming_delaunay_has_every_edge_delaunay),
        LH_CASE(smoothing_raises_angles_and_keeps_the_mesh_valid), LH_CASE(area_bound_and_steiner_limit),
        LH_CASE(holes_are_carved_and_regions_marked), LH_CASE(regions_and_markers_survive_refinement),
        LH_CASE(split_segments_makes_every_edge_delaunay), LH_CASE(bad_input_gets_its_error_and_line),
        LH_CASE(crossings_are_split_when_asked), LH_CASE(an_overlap_follows_a_chain_bent_at_a_crossing),
        LH_CASE(a_small_angle_far_from_the_origin_ends), LH_CASE(a_bent_segment_still_meets_the_vertex_on_it),
        LH_CASE(conforming_below_the_floor_is_reported),
        LH_CASE(earcut_degenerate_rings_are_valid_or_refused_clearly),
        LH_CASE(cgal_tiny_edge_is_meshed), LH_CASE(an_existing_mesh_is_refined_with_its_area_bounds),
        LH_CASE(refining_a_mesh_splits_its_boundary_edges), LH_CASE(api_misuse_is_refused_with_a_message),
        LH_CASE(an_invalid_mesh_to_refine_is_an_invalid_mesh),
        LH_CASE(refining_a_mesh_keeps_the_segments_along_its_boundary),
        LH_CASE(degenerate_input_is_resolved_and_reported),
        LH_CASE(output_is_deterministic_and_independent_of_segment_order),
        LH_CASE(a_hole_seed_on_a_segment_is_refused), LH_CASE(hole_seeds_on_free_vertices_carve),
        LH_CASE(the_check_rejects_what_is_not_a_cdt),
        LH_CASE(every_allocation_failure_is_survived),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
