/* test_io_poly.c — lh_poly_read on Triangle's own files (every field of A.poly and
 * box.poly; la.poly's regions against Triangle's rewriting of them; n = 0 files with
 * their .node through lh_pslg_take_points) and the text forms it accepts. Its
 * diagnostics: test_io_poly_errors.c; JSON rings: test_io_rings.c; memory:
 * test_io_pslg_memory.c. */
#include "io_pslg_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef LH_TEST_DATA_DIR
static lh_status read_node(const char *path, const lh_allocator *a, lh_points *p)
{
    char full[512];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, path, LH_FORMAT_NODE, a, p, NULL);
    fclose(f);
    return st;
}
#endif

/* ---- .poly: Triangle's files ---------------------------------------------------- */

#ifdef LH_TEST_DATA_DIR
LH_TEST(poly_A)
{
    static const double xy[] = {
        0.200000, -0.776400, 0.220000, -0.773200, 0.245600, -0.756400, 0.277600, -0.702000, 0.488800, -0.207600,
        0.504800, -0.207600, 0.740800, -0.739600, 0.756000, -0.761200, 0.774400, -0.772400, 0.800000, -0.776400,
        0.800000, -0.792400, 0.579200, -0.792400, 0.579200, -0.776400, 0.621600, -0.771600, 0.633600, -0.762800,
        0.639200, -0.744400, 0.620800, -0.684400, 0.587200, -0.604400, 0.360800, -0.604400, 0.319200, -0.706800,
        0.312000, -0.739600, 0.318400, -0.761200, 0.334400, -0.771600, 0.371200, -0.776400, 0.371200, -0.792400,
        0.374400, -0.570000, 0.574400, -0.570000, 0.473600, -0.330800, 0.200000, -0.792400};
    static const double attr[] = {-0.57, -0.55, -0.51, -0.53, 0.28, 0.30, 0, -0.01, 0, 0.02, 0.01, -0.21, -0.2, -0.15, -0.13,
                                  -0.1, -0.06, -0.01, -0.24, -0.39, -0.43, -0.44, -0.44, -0.41, -0.42, -0.2, 0, 0.14, -0.59};
    static const int seg[] = {28, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12,
                              13, 13, 14, 14, 15, 15, 16, 16, 17, 17, 18, 18, 19, 19, 20, 20, 21, 21, 22, 22, 23, 23,
                              24, 24, 28, 25, 26, 26, 27, 27, 25};
    lh_pslg g;
    char msg[256] = "x";
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/A.poly", NULL, &g, msg, sizeof msg), LH_OK);
    LH_EXPECT_STREQ(msg, "");
    check_pslg(lh_t_, &g);
    LH_ASSERT_EQ_U64(g.n, 29);
    LH_ASSERT_EQ_INT(g.attr_count, 1);
    for (size_t i = 0; i < 58; i++) LH_EXPECT_EQ_DBL(g.xy[i], xy[i]);
    for (size_t i = 0; i < 29; i++) LH_EXPECT_EQ_DBL(g.attr[i], attr[i]);
    LH_EXPECT_TRUE(g.vertex_marker == NULL);
    LH_ASSERT_EQ_U64(g.segment_count, 29);
    for (size_t i = 0; i < 58; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    LH_EXPECT_TRUE(g.segment_marker == NULL);
    LH_ASSERT_EQ_U64(g.hole_count, 1);
    LH_EXPECT_EQ_DBL(g.holes[0], 0.47);
    LH_EXPECT_EQ_DBL(g.holes[1], -0.5);
    LH_EXPECT_EQ_U64(g.region_count, 0);
    LH_EXPECT_TRUE(g.regions == NULL && g.region_line == NULL);
    LH_EXPECT_EQ_INT(g.even_odd, 0);
    LH_EXPECT_EQ_INT(g.first_index, 1);
    for (size_t i = 0; i < 29; i++) LH_EXPECT_EQ_U64(g.vertex_line[i], 2 + i);
    for (size_t i = 0; i < 29; i++) LH_EXPECT_EQ_U64(g.segment_line[i], 32 + i);
    LH_EXPECT_EQ_U64(g.hole_line[0], 62);
    lh_pslg_free(&g);
    LH_EXPECT_TRUE(g.xy == NULL && g.n == 0 && g.segments == NULL && g.alloc_.free == NULL);
    lh_pslg_free(&g); /* a zeroed graph */
    lh_pslg_free(NULL);
}

/* Comments after items, markers on vertices and segments, a hole. */
LH_TEST(poly_box_markers)
{
    static const double xy[] = {0, 0, 0, 3, 3, 0, 3, 3, 1, 1, 1, 2, 2, 1, 2, 2};
    static const int vmark[] = {0, 0, 0, 33, 0, 0, 0, 0}, vline[] = {13, 14, 15, 16, 18, 19, 20, 21};
    static const int seg[] = {0, 1, 4, 6, 6, 7, 7, 5, 5, 4}, smark[] = {5, 0, 0, 10, 0}, sline[] = {24, 26, 27, 28, 29};
    lh_pslg g;
    char msg[256];
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/box.poly", NULL, &g, msg, sizeof msg), LH_OK);
    check_pslg(lh_t_, &g);
    LH_ASSERT_EQ_U64(g.n, 8);
    LH_EXPECT_EQ_INT(g.attr_count, 0);
    LH_EXPECT_TRUE(g.attr == NULL);
    LH_ASSERT_TRUE(g.vertex_marker != NULL && g.segment_marker != NULL);
    for (int i = 0; i < 16; i++) LH_EXPECT_EQ_DBL(g.xy[i], xy[i]);
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_INT(g.vertex_marker[i], vmark[i]);
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_U64(g.vertex_line[i], vline[i]);
    LH_ASSERT_EQ_U64(g.segment_count, 5);
    for (int i = 0; i < 10; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    for (int i = 0; i < 5; i++) LH_EXPECT_EQ_INT(g.segment_marker[i], smark[i]);
    for (int i = 0; i < 5; i++) LH_EXPECT_EQ_U64(g.segment_line[i], sline[i]);
    LH_ASSERT_EQ_U64(g.hole_count, 1);
    LH_EXPECT_EQ_DBL(g.holes[0], 1.5);
    LH_EXPECT_EQ_DBL(g.holes[1], 1.5);
    LH_EXPECT_EQ_U64(g.hole_line[0], 32);
    LH_EXPECT_EQ_U64(g.region_count, 0);
    lh_pslg_free(&g);
}

/* Blank lines inside sections, comments after holes, three holes. */
LH_TEST(poly_face)
{
    lh_pslg g;
    char msg[256];
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/face.poly", NULL, &g, msg, sizeof msg), LH_OK);
    check_pslg(lh_t_, &g);
    LH_ASSERT_EQ_U64(g.n, 26);
    LH_ASSERT_EQ_U64(g.segment_count, 22);
    LH_ASSERT_EQ_U64(g.hole_count, 3);
    LH_EXPECT_EQ_DBL(g.xy[2 * 25], 50);
    LH_EXPECT_EQ_INT(g.vertex_marker[24], 0);
    LH_EXPECT_EQ_INT(g.vertex_marker[0], 2);
    LH_EXPECT_EQ_INT(g.segments[2 * 21], 22);
    LH_EXPECT_EQ_INT(g.segments[2 * 21 + 1], 23);
    LH_EXPECT_EQ_INT(g.segment_marker[21], 6);
    LH_EXPECT_EQ_U64(g.vertex_line[25], 36);
    LH_EXPECT_EQ_U64(g.segment_line[0], 41);
    LH_EXPECT_EQ_U64(g.segment_line[21], 66);
    static const double holes[] = {0, -50, -50, 50, 50, 50};
    for (int i = 0; i < 6; i++) LH_EXPECT_EQ_DBL(g.holes[i], holes[i]);
    LH_EXPECT_EQ_U64(g.hole_line[2], 72);
    lh_pslg_free(&g);
}

/* la.poly: 141 vertices (Fortran E notation), 148 segments, no holes, 6 regions of 4
 * fields. Triangle's own output la.1.poly writes the regions back with 5 fields and
 * la.1.node starts with the input vertices: both must equal what is read here. */
LH_TEST(poly_la_regions)
{
    lh_pslg g, out;
    char msg[256];
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/la.poly", NULL, &g, msg, sizeof msg), LH_OK);
    check_pslg(lh_t_, &g);
    LH_ASSERT_EQ_U64(g.n, 141);
    LH_ASSERT_EQ_U64(g.segment_count, 148);
    LH_EXPECT_EQ_U64(g.hole_count, 0);
    LH_EXPECT_TRUE(g.holes == NULL);
    LH_ASSERT_EQ_U64(g.region_count, 6);
    LH_EXPECT_EQ_INT(g.vertex_marker[0], 101);
    LH_EXPECT_EQ_DBL(g.xy[2], 41.8893);
    LH_EXPECT_EQ_INT(g.segment_marker[0], 102);
    LH_EXPECT_EQ_INT(g.segments[2 * 147], 138);
    LH_EXPECT_EQ_INT(g.segments[2 * 147 + 1], 140);
    LH_EXPECT_EQ_U64(g.segment_line[147], 291);
    LH_EXPECT_EQ_U64(g.region_line[0], 294);
    LH_EXPECT_EQ_U64(g.region_line[5], 299);
    LH_EXPECT_EQ_DBL(g.regions[0], 6);
    LH_EXPECT_EQ_DBL(g.regions[1], -0.2);
    LH_EXPECT_EQ_DBL(g.regions[2], 0.05);
    LH_EXPECT_EQ_DBL(g.regions[3], 0.05);
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/reference_outputs/la.1.poly", NULL, &out, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_U64(out.n, 0);
    LH_ASSERT_EQ_U64(out.region_count, 6);
    for (int i = 0; i < 24; i++) LH_EXPECT_EQ_DBL(g.regions[i], out.regions[i]);
    lh_points p;
    LH_ASSERT_EQ_INT(read_node("triangle/reference_outputs/la.1.node", NULL, &p), LH_OK);
    LH_ASSERT_TRUE(p.n >= 141);
    for (size_t i = 0; i < 2 * 141; i++) LH_EXPECT_EQ_DBL(g.xy[i], p.xyz[i]);
    lh_points_free(&p);
    lh_pslg_free(&out);
    lh_pslg_free(&g);
}

/* Every .poly of tests/data/triangle reads, with the counts its header declares. */
LH_TEST(poly_every_file)
{
    static const struct {
        const char *path;
        size_t n, segments, holes, regions;
    } files[] = {
        {"triangle/A.poly", 29, 29, 1, 0},
        {"triangle/box.poly", 8, 5, 1, 0},
        {"triangle/double_hex.poly", 96, 96, 2, 0},
        {"triangle/double_hex2.poly", 48, 48, 2, 0},
        {"triangle/double_hex3.poly", 16, 16, 2, 0},
        {"triangle/face.poly", 26, 22, 3, 0},
        {"triangle/fish-and-rectangle.poly", 31, 44, 3, 0},
        {"triangle/la.poly", 141, 148, 0, 6},
        {"triangle/square_circle_hole.poly", 826, 135, 1, 0},
        {"triangle/reference_outputs/A.1.poly", 0, 29, 1, 0},
        {"triangle/reference_outputs/box.1.poly", 0, 8, 1, 0},
        {"triangle/reference_outputs/double_hex3.1.poly", 0, 96, 2, 0},
        {"triangle/reference_outputs/la.1.poly", 0, 499, 0, 6},
    };
    for (size_t k = 0; k < LH_COUNT(files) && !LH_FAILED(); k++) {
        lh_pslg g;
        char msg[256];
        lh_test_counter c = {0, 0, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        LH_EXPECT_EQ_INT(read_file(lh_poly_read, files[k].path, &a, &g, msg, sizeof msg), LH_OK);
        LH_EXPECT_STREQ(msg, "");
        check_pslg(lh_t_, &g);
        LH_EXPECT_EQ_U64(g.n, files[k].n);
        LH_EXPECT_EQ_U64(g.segment_count, files[k].segments);
        LH_EXPECT_EQ_U64(g.hole_count, files[k].holes);
        LH_EXPECT_EQ_U64(g.region_count, files[k].regions);
        LH_EXPECT_EQ_INT(g.first_index, 1);
        lh_pslg_free(&g);
        LH_EXPECT_EQ_INT(c.live, 0);
        if (LH_FAILED()) LH_NOTE("file %s: %s", files[k].path, msg);
    }
}

/* double_hex3.poly holds its 16 vertices, double_hex3.node the same ones: equal. */
LH_TEST(poly_double_hex3_and_its_node)
{
    lh_pslg g;
    lh_points p;
    char msg[256];
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/double_hex3.poly", NULL, &g, msg, sizeof msg), LH_OK);
    LH_ASSERT_EQ_INT(read_node("triangle/double_hex3.node", NULL, &p), LH_OK);
    LH_ASSERT_EQ_U64(g.n, p.n);
    for (size_t i = 0; i < 2 * g.n; i++) LH_EXPECT_EQ_DBL(g.xy[i], p.xyz[i]);
    for (size_t i = 0; i < g.n; i++) LH_EXPECT_EQ_INT(g.vertex_marker[i], p.marker[i]);
    LH_EXPECT_EQ_INT(g.vertex_marker[15], 3);
    LH_EXPECT_EQ_DBL(g.holes[2], 0.6);
    lh_points_free(&p);
    lh_pslg_free(&g);
}

/* n = 0: Triangle's outputs (.1.poly) with their .1.node, attached by
 * lh_pslg_take_points; attributes and markers come along. */
LH_TEST(poly_n0_take_points)
{
    lh_test_counter c = {0, 0, 0};
    lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
    lh_pslg g;
    lh_points p;
    char msg[256];
    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/reference_outputs/double_hex3.1.poly", &a, &g, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_U64(g.n, 0);
    LH_EXPECT_TRUE(g.xy == NULL && g.vertex_marker == NULL && g.vertex_line == NULL && g.attr_count == 0);
    LH_ASSERT_EQ_U64(g.segment_count, 96);
    LH_EXPECT_EQ_INT(g.segments[0], 1); /* "1 2 529 1" */
    LH_EXPECT_EQ_INT(g.segments[1], 528);
    LH_EXPECT_EQ_INT(g.segment_marker[0], 1);
    LH_ASSERT_EQ_INT(read_node("triangle/reference_outputs/double_hex3.1.node", &a, &p), LH_OK);
    LH_ASSERT_EQ_INT(lh_pslg_take_points(&g, &p), LH_OK);
    LH_EXPECT_TRUE(p.xyz == NULL && p.n == 0 && p.d == 0 && p.marker == NULL);
    check_pslg(lh_t_, &g);
    LH_EXPECT_EQ_U64(g.n, 531);
    LH_EXPECT_EQ_INT(g.first_index, 1);
    LH_EXPECT_EQ_INT(g.segments[1], 528);
    LH_EXPECT_EQ_DBL(g.xy[2], 1);
    LH_EXPECT_TRUE(g.vertex_marker != NULL && g.vertex_line == NULL);
    lh_pslg_free(&g);
    lh_points_free(&p);
    LH_EXPECT_EQ_INT(c.live, 0);

    LH_ASSERT_EQ_INT(read_file(lh_poly_read, "triangle/reference_outputs/A.1.poly", &a, &g, msg, sizeof msg), LH_OK);
    LH_ASSERT_EQ_INT(read_node("triangle/reference_outputs/A.1.node", &a, &p), LH_OK);
    LH_ASSERT_EQ_INT(lh_pslg_take_points(&g, &p), LH_OK);
    LH_ASSERT_EQ_U64(g.n, 29);
    LH_ASSERT_EQ_INT(g.attr_count, 1);
    LH_EXPECT_EQ_DBL(g.attr[0], -0.57);
    LH_EXPECT_EQ_DBL(g.xy[0], 0.2);
    LH_EXPECT_EQ_INT(g.segments[0], 28);
    check_pslg(lh_t_, &g);
    lh_pslg_free(&g);
    LH_EXPECT_EQ_INT(c.live, 0);
}
#endif

/* The .node text (len bytes) read and attached to g (lh_pslg_take_points). */
static lh_status attach_node_text(lh_pslg *g, const char *text, size_t len)
{
    lh_points p;
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, "n.node", LH_FORMAT_NODE, NULL, &p, NULL);
    fclose(f);
    if (st == LH_OK) st = lh_pslg_take_points(g, &p);
    lh_points_free(&p);
    return st;
}

/* A .poly numbered from 0 whose .node is numbered from 1: the endpoints are the
 * .node's numbers (Triangle), renumbered by lh_pslg_take_points. */
LH_TEST(poly_n0_renumbered)
{
    lh_pslg g;
    char msg[256];
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "r.poly", TEXT("0 2 0 0\n2 0\n0 0 1\n1 1 2\n0\n"), NULL, &g, msg, sizeof msg),
                     LH_OK);
    LH_EXPECT_EQ_INT(g.first_index, 0);
    static const int read[] = {0, 1, 1, 2};
    for (int i = 0; i < 4; i++) LH_EXPECT_EQ_INT(g.segments[i], read[i]);
    LH_ASSERT_EQ_INT(attach_node_text(&g, TEXT("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")), LH_OK);
    LH_EXPECT_EQ_INT(g.first_index, 1);
    static const int seg[] = {-1, 0, 0, 1}; /* "0 0 1": 0 is no vertex of a 1-based .node */
    for (int i = 0; i < 4; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    lh_pslg_free(&g);
    /* Holes alone: the file's first number is the first hole's. */
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "h.poly", TEXT("0\n0\n1\n0 5 5\n"), NULL, &g, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(g.first_index, 0);
    LH_EXPECT_EQ_U64(g.hole_count, 1);
    lh_pslg_free(&g);
}

/* A .poly numbered from 1 whose .node is numbered from 0: endpoint 0 is the .node's
 * vertex 0 (Triangle reads it so), and diagnostics name segments, holes and regions as
 * the .poly numbers them, vertices as the .node does. */
LH_TEST(poly_n0_keeps_its_item_numbers)
{
    lh_pslg g;
    char msg[256];
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "s.poly", TEXT("0 2 0 0\n3 0\n1 0 1\n2 1 2\n3 1 9\n0\n"), NULL, &g,
                               msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(g.segments[0], -1); /* 0 less the .poly's base, until the .node comes */
    LH_ASSERT_EQ_INT(attach_node_text(&g, TEXT("4 2 0 0\n0 0 0\n1 2 0\n2 2 2\n3 0 2\n")), LH_OK);
    LH_EXPECT_EQ_INT(g.first_index, 0);
    LH_EXPECT_EQ_INT(g.item_first_shift, 1);
    static const int seg[] = {0, 1, 1, 2, 1, 9};
    for (int i = 0; i < 6; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    lh_trimesh *m = NULL;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "5: segment 3: endpoint 9 is not a vertex (0..3)");
    LH_EXPECT_EQ_U64(err.line, 5);
    g.segments[1] = 2, g.segments[5] = 3; /* segments 0-2 and 1-3: the diagonals cross */
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &err), LH_ERR_CROSSING_SEGMENTS);
    LH_EXPECT_STREQ(err.message, "5: segment 3 crosses segment 1 (line 3)");
    LH_EXPECT_EQ_U64(err.line, 5);
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

LH_TEST(poly_take_points_arguments)
{
    lh_test_counter c = {0, 0, 0};
    lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
    lh_pslg g, full;
    lh_points p, p3;
    char msg[256];
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "z.poly", TEXT("0 2\n0 0\n0\n"), &a, &g, msg, sizeof msg), LH_OK);
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "f.poly", TEXT("1 2\n1 0 0\n0\n0\n"), &a, &full, msg, sizeof msg), LH_OK);
    FILE *f = lh_test_file(TEXT("2 2\n1 0 0\n2 1 1\n"));
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "p.node", LH_FORMAT_NODE, &a, &p, NULL), LH_OK);
    fclose(f);
    f = lh_test_file(TEXT("2 3\n1 0 0 0\n2 1 1 1\n"));
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "p3.node", LH_FORMAT_NODE, &a, &p3, NULL), LH_OK);
    fclose(f);
    LH_EXPECT_EQ_INT(lh_pslg_take_points(NULL, &p), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&g, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&g, &p3), LH_ERR_INVALID_ARGUMENT); /* d = 3 */
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&full, &p), LH_ERR_INVALID_ARGUMENT); /* has vertices */
    lh_pslg other;
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "o.poly", TEXT("0\n0\n0\n"), NULL, &other, msg, sizeof msg), LH_OK);
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&other, &p), LH_ERR_INVALID_ARGUMENT); /* other hooks */
    lh_pslg mine = {0}; /* filled by the caller: no hooks */
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&mine, &p), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_U64(p.n, 2); /* untouched by the refusals */
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&g, &p), LH_OK);
    LH_EXPECT_EQ_INT(lh_pslg_take_points(&g, &p), LH_ERR_INVALID_ARGUMENT); /* p is empty now */
    LH_EXPECT_EQ_U64(g.n, 2);
    lh_pslg_free(&other);
    lh_pslg_free(&g);
    lh_pslg_free(&full);
    lh_points_free(&p3);
    LH_EXPECT_EQ_INT(c.live, 0);
}

/* Numbering from 0, every header field omitted or given, regions of 5 and 4 fields,
 * CRLF, tabs, comments anywhere, no regions line, an empty regions section. */
LH_TEST(poly_text_forms)
{
    static const char zero[] = "# from 0\n"
                               "3 2 1 1\n"
                               "0 0 0 10 -1\r\n"
                               "1\t1\t0\t11\t-2\n"
                               "\n"
                               "2 0 1 12 -3 # last vertex\n"
                               "3 1 # segments\n"
                               "0 0 1 7\n1 1 2 8\n2 2 0 9\n"
                               "1\n0 0.25 0.25\n"
                               "2\n"
                               "0 0.1 0.1 5 0.5\n"
                               "1 0.2 0.2 6\n"
                               "# trailing comment\n\n";
    lh_pslg g;
    char msg[256];
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "zero.poly", TEXT(zero), NULL, &g, msg, sizeof msg), LH_OK);
    check_pslg(lh_t_, &g);
    LH_EXPECT_EQ_INT(g.first_index, 0);
    LH_ASSERT_EQ_U64(g.n, 3);
    LH_ASSERT_EQ_INT(g.attr_count, 1);
    static const double attr[] = {10, 11, 12}, regions[] = {0.1, 0.1, 5, 0.5, 0.2, 0.2, 6, 6};
    static const int vmark[] = {-1, -2, -3}, seg[] = {0, 1, 1, 2, 2, 0}, smark[] = {7, 8, 9};
    for (int i = 0; i < 3; i++) LH_EXPECT_EQ_DBL(g.attr[i], attr[i]);
    for (int i = 0; i < 3; i++) LH_EXPECT_EQ_INT(g.vertex_marker[i], vmark[i]);
    LH_ASSERT_EQ_U64(g.segment_count, 3);
    for (int i = 0; i < 6; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    for (int i = 0; i < 3; i++) LH_EXPECT_EQ_INT(g.segment_marker[i], smark[i]);
    LH_ASSERT_EQ_U64(g.region_count, 2);
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_DBL(g.regions[i], regions[i]);
    LH_EXPECT_EQ_U64(g.vertex_line[2], 6);
    LH_EXPECT_EQ_U64(g.hole_line[0], 12);
    LH_EXPECT_EQ_U64(g.region_line[1], 15);
    lh_pslg_free(&g);

    /* Triangle's defaults: no dimension, no attributes, no markers. */
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "one.poly", TEXT("2\n1 0 0\n2 1 1\n1\n1 1 2\n0\n0\n"), NULL, &g, msg, sizeof msg),
                     LH_OK);
    LH_EXPECT_EQ_INT(g.first_index, 1);
    LH_EXPECT_EQ_INT(g.attr_count, 0);
    LH_EXPECT_TRUE(g.vertex_marker == NULL && g.segment_marker == NULL && g.regions == NULL);
    LH_EXPECT_EQ_INT(g.segments[0], 0);
    LH_EXPECT_EQ_INT(g.segments[1], 1);
    lh_pslg_free(&g);
    /* A UTF-8 BOM, and a file of nothing but empty sections. */
    LH_ASSERT_EQ_INT(read_text(lh_poly_read, "bom.poly", TEXT("\xEF\xBB\xBF" "0 2 0 0\n0 0\n0\n"), NULL, &g, msg, sizeof msg),
                     LH_OK);
    LH_EXPECT_TRUE(g.n == 0 && g.segment_count == 0 && g.hole_count == 0 && g.first_index == 0);
    lh_pslg_free(&g);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
#ifdef LH_TEST_DATA_DIR
        LH_CASE(poly_A), LH_CASE(poly_box_markers), LH_CASE(poly_face),
        LH_CASE(poly_la_regions), LH_CASE(poly_every_file),
        LH_CASE(poly_double_hex3_and_its_node), LH_CASE(poly_n0_take_points),
#endif
        LH_CASE(poly_n0_renumbered), LH_CASE(poly_n0_keeps_its_item_numbers),
        LH_CASE(poly_take_points_arguments), LH_CASE(poly_text_forms),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
