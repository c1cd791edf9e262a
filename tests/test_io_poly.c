/* test_io_poly.c — the PSLG readers (lifthull.h, "2D meshing"): lh_poly_read on
 * Triangle's own files (every field of A.poly and box.poly; la.poly's regions against
 * Triangle's rewriting of them; n = 0 files with their .node through
 * lh_pslg_take_points), lh_rings_read on every earcut fixture (counts and coordinate
 * sums from Python's json module), every diagnostic exactly, every allocation failure. */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Input text with its length, so that NUL bytes can be part of it. */
#define TEXT(s) s, sizeof(s) - 1

typedef lh_status (*reader)(FILE *, const char *, const lh_allocator *, lh_pslg *, char *, size_t);

static lh_status read_text(reader rd, const char *name, const char *text, size_t len,
                           const lh_allocator *a, lh_pslg *g, char *msg, size_t size)
{
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = rd(f, name, a, g, msg, size);
    fclose(f);
    return st;
}

#ifdef LH_TEST_DATA_DIR
static lh_status read_file(reader rd, const char *path, const lh_allocator *a, lh_pslg *g,
                           char *msg, size_t size)
{
    char full[512];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_status st = rd(f, path, a, g, msg, size);
    fclose(f);
    return st;
}

static lh_status read_node(const char *path, const lh_allocator *a, lh_points *p)
{
    char full[512], msg[256];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, path, LH_FORMAT_NODE, a, p, msg, sizeof msg);
    fclose(f);
    return st;
}
#endif

/* The invariants of every reader's output: arrays present exactly when counted,
 * finite numbers, endpoints in range (when the vertices are there). */
static void check_pslg(lh_test_state *lh_t_, const lh_pslg *g)
{
    LH_EXPECT_TRUE((g->n > 0) == (g->xy != NULL));
    LH_EXPECT_TRUE((g->n > 0 && g->attr_count > 0) == (g->attr != NULL));
    LH_EXPECT_TRUE((g->segment_count > 0) == (g->segments != NULL));
    LH_EXPECT_TRUE((g->segment_count > 0) == (g->segment_line != NULL));
    LH_EXPECT_TRUE((g->hole_count > 0) == (g->holes != NULL && g->hole_line != NULL));
    LH_EXPECT_TRUE((g->region_count > 0) == (g->regions != NULL && g->region_line != NULL));
    LH_EXPECT_TRUE(g->first_index == 0 || g->first_index == 1);
    for (size_t i = 0; i < 2 * g->n; i++) LH_EXPECT_TRUE(isfinite(g->xy[i]));
    for (size_t i = 0; g->n && i < 2 * g->segment_count; i++)
        LH_EXPECT_TRUE(g->segments[i] >= 0 && (size_t)g->segments[i] < g->n);
    for (size_t i = 1; g->vertex_line && i < g->n; i++) LH_EXPECT_TRUE(g->vertex_line[i] >= g->vertex_line[i - 1]);
}

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
    char msg[256];
    lh_points p;
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, "n.node", LH_FORMAT_NODE, NULL, &p, msg, sizeof msg);
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
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(msg, "5: segment 3: endpoint 9 is not a vertex (0..3)");
    g.segments[1] = 2, g.segments[5] = 3; /* segments 0-2 and 1-3: the diagonals cross */
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, msg, sizeof msg), LH_ERR_CROSSING_SEGMENTS);
    LH_EXPECT_STREQ(msg, "5: segment 3 crosses segment 1 (line 3)");
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
    LH_ASSERT_EQ_INT(lh_points_read(f, "p.node", LH_FORMAT_NODE, &a, &p, msg, sizeof msg), LH_OK);
    fclose(f);
    f = lh_test_file(TEXT("2 3\n1 0 0 0\n2 1 1 1\n"));
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "p3.node", LH_FORMAT_NODE, &a, &p3, msg, sizeof msg), LH_OK);
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

/* ---- diagnostics ---------------------------------------------------------------- */

typedef struct bad_case {
    const char *name;
    const char *text;
    size_t len;
    lh_status status;
    const char *msg;
} bad_case;

static void check_bad_cases(lh_test_state *lh_t_, reader rd, const bad_case *cases, size_t count)
{
    for (size_t i = 0; i < count && !LH_FAILED(); i++) {
        const bad_case *c = &cases[i];
        /* The counts' limit is LH_INDEX_MAX - 1: these messages are the 32-bit build's. */
        if (sizeof(lh_index) != 4 && strstr(c->msg, "2147483646")) continue;
        char msg[512];
        lh_pslg g;
        lh_test_counter k = {0, 0, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &k};
        LH_EXPECT_EQ_INT(read_text(rd, c->name, c->text, c->len, &a, &g, msg, sizeof msg), c->status);
        LH_EXPECT_STREQ(msg, c->msg);
        LH_EXPECT_TRUE(g.xy == NULL && g.n == 0 && g.segments == NULL && g.segment_count == 0 && g.holes == NULL &&
                       g.regions == NULL && g.vertex_line == NULL && g.alloc_.alloc == NULL);
        LH_EXPECT_EQ_INT(k.live, 0);
        if (LH_FAILED()) LH_NOTE("case %s", c->name);
    }
}

#define V3 "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n" /* three vertices, numbered from 1 */

LH_TEST(poly_header_errors)
{
    static const bad_case cases[] = {
        {"empty.poly", TEXT(""), LH_ERR_PARSE, "empty.poly:1:1: expected the number of vertices, found the end of the input"},
        {"text.poly", TEXT("vertices 3 2\n"), LH_ERR_PARSE,
         "text.poly:1:1: expected the number of vertices (an integer from 0 to 2147483646), found 'vertices'"},
        {"neg.poly", TEXT("-3 2\n"), LH_ERR_PARSE,
         "neg.poly:1:1: expected the number of vertices (an integer from 0 to 2147483646), found '-3'"},
        {"big.poly", TEXT("3000000000 2\n"), LH_ERR_TOO_LARGE,
         "big.poly:1:1: expected the number of vertices (an integer from 0 to 2147483646), found '3000000000'"},
        {"d3.poly", TEXT("3 3 0 0\n"), LH_ERR_DIMENSION, "d3.poly:1:3: expected the dimension (2: a .poly file is planar), found '3'"},
        {"dx.poly", TEXT("3 two\n"), LH_ERR_PARSE, "dx.poly:1:3: expected the dimension (2: a .poly file is planar), found 'two'"},
        {"a.poly", TEXT("3 2 -1\n"), LH_ERR_PARSE, "a.poly:1:5: expected the number of attributes (an integer from 0 to 1000), found '-1'"},
        {"m.poly", TEXT("3 2 0 2\n"), LH_ERR_PARSE, "m.poly:1:7: expected the number of boundary markers (0 or 1), found '2'"},
        {"h.poly", TEXT("3 2 0 0 9\n"), LH_ERR_PARSE,
         "h.poly:1:9: expected the end of the header line (vertices, dimension, attributes, markers), found '9'"},
        {"elf.poly", TEXT("\x7f" "ELF\x02\x01"), LH_ERR_PARSE, "elf.poly:1:1: expected the number of vertices, found a non-text byte 0x7f"},
        {"nul.poly", TEXT("3 2\0"), LH_ERR_PARSE, "nul.poly:1:4: expected the number of attributes (an integer from 0 to 1000), found a NUL byte"},
    };
    check_bad_cases(lh_t_, lh_poly_read, cases, LH_COUNT(cases));
}

LH_TEST(poly_vertex_errors)
{
    static const bad_case cases[] = {
        {"f.poly", TEXT("1 2\n2 0 0\n"), LH_ERR_PARSE, "f.poly:2:1: expected the first vertex's number (0 or 1), found '2'"},
        {"s.poly", TEXT("3 2\n1 0 0\n2 1 0\n4 0 1\n"), LH_ERR_PARSE,
         "s.poly:4:1: expected vertex number 3 (numbers are consecutive), found '4'"},
        {"few.poly", TEXT("3 2\n1 0 0\n2 1 0\n"), LH_ERR_PARSE,
         "few.poly:4:1: expected vertex number 3, found the end of the input (3 vertices declared)"},
        {"y.poly", TEXT("1 2\n1 0\n"), LH_ERR_PARSE, "y.poly:2:4: expected coordinate 2 of vertex 1, found the end of the line"},
        {"t.poly", TEXT("1 2\n1 0 abc\n"), LH_ERR_PARSE, "t.poly:2:5: expected coordinate 2 of vertex 1 (a number), found 'abc'"},
        {"nan.poly", TEXT("1 2\n1 nan 0\n"), LH_ERR_NONFINITE,
         "nan.poly:2:3: coordinate 1 of vertex 1 is 'nan': NaN and infinities are not points"},
        {"over.poly", TEXT("1 2\n1 0 -1e999\n"), LH_ERR_NONFINITE,
         "over.poly:2:5: coordinate 2 of vertex 1 is '-1e999', which overflows a double"},
        {"at.poly", TEXT("1 2 1\n1 0 0 inf\n"), LH_ERR_NONFINITE,
         "at.poly:2:7: attribute 1 of vertex 1 is 'inf': NaN and infinities are not accepted"},
        {"mk.poly", TEXT("1 2 0 1\n1 0 0 0.5\n"), LH_ERR_PARSE,
         "mk.poly:2:7: expected the boundary marker of vertex 1 (an integer), found '0.5'"},
        {"x.poly", TEXT("1 2\n1 0 0 5\n"), LH_ERR_PARSE, "x.poly:2:7: expected the end of the line after vertex 1, found '5'"},
    };
    check_bad_cases(lh_t_, lh_poly_read, cases, LH_COUNT(cases));
}

LH_TEST(poly_segment_errors)
{
    static const bad_case cases[] = {
        {"ns.poly", TEXT(V3), LH_ERR_PARSE, "ns.poly:5:1: expected the number of segments, found the end of the input"},
        {"sm.poly", TEXT(V3 "1 2\n"), LH_ERR_PARSE,
         "sm.poly:5:3: expected the number of segment boundary markers (0 or 1), found '2'"},
        {"sh.poly", TEXT(V3 "1 0 0\n"), LH_ERR_PARSE,
         "sh.poly:5:5: expected the end of the line after the number of segments and markers, found '0'"},
        {"e4.poly", TEXT(V3 "1 0\n1 1 4\n"), LH_ERR_PARSE,
         "e4.poly:6:5: expected an endpoint of segment 1 (a vertex number from 1 to 3), found '4'"},
        {"e0.poly", TEXT(V3 "2 0\n1 1 2\n2 0 3\n"), LH_ERR_PARSE,
         "e0.poly:7:3: expected an endpoint of segment 2 (a vertex number from 1 to 3), found '0'"},
        {"e1.poly", TEXT(V3 "1 0\n1 1\n"), LH_ERR_PARSE,
         "e1.poly:6:4: expected an endpoint of segment 1 (a vertex number from 1 to 3), found the end of the line"},
        {"ef.poly", TEXT(V3 "1 0\n1 1 2.0\n"), LH_ERR_PARSE,
         "ef.poly:6:5: expected an endpoint of segment 1 (a vertex number from 1 to 3), found '2.0'"},
        {"n0.poly", TEXT("0 2\n1 0\n1 -1 1\n"), LH_ERR_PARSE,
         "n0.poly:3:3: expected an endpoint of segment 1 (a vertex number of the .node, from 0), found '-1'"},
        {"n0big.poly", TEXT("0 2\n1 0\n0 0 99999999999999999999\n"), LH_ERR_PARSE, /* past either width */
         "n0big.poly:3:5: expected an endpoint of segment 0 (a vertex number of the .node, from 0), found '99999999999999999999'"},
        {"s0.poly", TEXT(V3 "2 0\n0 1 2\n1 2 3\n"), LH_ERR_PARSE,
         "s0.poly:6:1: expected segment number 1 (this file numbers from 1), found '0'"},
        {"sn.poly", TEXT(V3 "2 0\n1 1 2\n3 2 3\n"), LH_ERR_PARSE,
         "sn.poly:7:1: expected segment number 2 (numbers are consecutive), found '3'"},
        {"smk.poly", TEXT(V3 "1 1\n1 1 2\n"), LH_ERR_PARSE,
         "smk.poly:6:6: expected the boundary marker of segment 1 (an integer), found the end of the line"},
        {"sx.poly", TEXT(V3 "1 0\n1 1 2 7\n"), LH_ERR_PARSE, "sx.poly:6:7: expected the end of the line after segment 1, found '7'"},
        {"st.poly", TEXT(V3 "3 0\n1 1 2\n"), LH_ERR_PARSE,
         "st.poly:7:1: expected segment number 2, found the end of the input (3 segments declared)"},
        {"sbig.poly", TEXT(V3 "3000000000\n"), LH_ERR_TOO_LARGE,
         "sbig.poly:5:1: expected the number of segments (an integer from 0 to 2147483646), found '3000000000'"},
    };
    check_bad_cases(lh_t_, lh_poly_read, cases, LH_COUNT(cases));
}

LH_TEST(poly_hole_region_errors)
{
    static const bad_case cases[] = {
        {"nh.poly", TEXT(V3 "0\n"), LH_ERR_PARSE, "nh.poly:6:1: expected the number of holes, found the end of the input"},
        {"hx.poly", TEXT(V3 "0\nholes\n"), LH_ERR_PARSE,
         "hx.poly:6:1: expected the number of holes (an integer from 0 to 2147483646), found 'holes'"},
        {"h2.poly", TEXT(V3 "0\n1 2\n"), LH_ERR_PARSE, "h2.poly:6:3: expected the end of the line after the number of holes, found '2'"},
        {"hy.poly", TEXT(V3 "0\n1\n1 0.5\n"), LH_ERR_PARSE, "hy.poly:7:6: expected coordinate 2 of hole 1, found the end of the line"},
        {"hi.poly", TEXT(V3 "0\n1\n1 inf 0\n"), LH_ERR_NONFINITE,
         "hi.poly:7:3: coordinate 1 of hole 1 is 'inf': NaN and infinities are not points"},
        {"h0.poly", TEXT("0 2\n1 0\n0 1 2\n1\n1 0 0\n"), LH_ERR_PARSE,
         "h0.poly:5:1: expected hole number 0 (this file numbers from 0), found '1'"},
        {"hn.poly", TEXT(V3 "0\n2\n1 0 0\n1 1 1\n"), LH_ERR_PARSE,
         "hn.poly:8:1: expected hole number 2 (numbers are consecutive), found '1'"},
        {"ht.poly", TEXT(V3 "0\n2\n1 0 0\n"), LH_ERR_PARSE,
         "ht.poly:8:1: expected hole number 2, found the end of the input (2 holes declared)"},
        {"rx.poly", TEXT(V3 "0\n0\nfoo\n"), LH_ERR_PARSE,
         "rx.poly:7:1: expected the number of regions (an integer from 0 to 2147483646) or the end of the input, found 'foo'"},
        {"rb.poly", TEXT(V3 "0\n0\n\x01"), LH_ERR_PARSE,
         "rb.poly:7:1: expected the number of regions or the end of the input, found a non-text byte 0x01"},
        {"ra.poly", TEXT(V3 "0\n0\n1\n1 0 0\n"), LH_ERR_PARSE, "ra.poly:8:6: expected the attribute of region 1, found the end of the line"},
        {"rn.poly", TEXT(V3 "0\n0\n1\n1 0 0 nan\n"), LH_ERR_NONFINITE,
         "rn.poly:8:7: the attribute of region 1 is 'nan': NaN and infinities are not accepted"},
        {"rm.poly", TEXT(V3 "0\n0\n1\n1 0 0 1 big\n"), LH_ERR_PARSE,
         "rm.poly:8:9: expected the maximum area of region 1 (a number), found 'big'"},
        {"re.poly", TEXT(V3 "0\n0\n1\n1 0 0 1 2 3\n"), LH_ERR_PARSE, "re.poly:8:11: expected the end of the line after region 1, found '3'"},
        {"rt.poly", TEXT(V3 "0\n0\n1\n1 0 0 1 2\n3\n"), LH_ERR_PARSE,
         "rt.poly:9:1: expected the end of the input after 1 region, found '3'"},
        {"r0t.poly", TEXT(V3 "0\n0\n0\n0\n"), LH_ERR_PARSE, "r0t.poly:8:1: expected the end of the input after 0 regions, found '0'"},
    };
    check_bad_cases(lh_t_, lh_poly_read, cases, LH_COUNT(cases));
}

/* ---- JSON rings ----------------------------------------------------------------- */

LH_TEST(rings_text_forms)
{
    static const char text[] = "[\n"
                               "  [ [0,0], [ 4 , 0 ],[4,4],\n"
                               "    [-0,4.0e0], [0, 0] ],\n"      /* closed: the last point is dropped */
                               "  [[1,1],[1,2E0],[2,2],[2,1]],\n"
                               "  [[3.5e-1, -1.25E+1]],\n"         /* one point: no segment */
                               "\t[[3,3],[3,3.5]]\r\n"             /* two points: two segments */
                               "]\n";
    static const double xy[] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 2, 2, 2, 2, 1, 0.35, -12.5, 3, 3, 3, 3.5};
    static const int seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 9, 10, 10, 9};
    static const size_t vline[] = {2, 2, 2, 3, 4, 4, 4, 4, 5, 6, 6}, sline[] = {2, 2, 2, 3, 4, 4, 4, 4, 6, 6};
    lh_pslg g;
    char msg[256] = "x";
    LH_ASSERT_EQ_INT(read_text(lh_rings_read, "t.json", TEXT(text), NULL, &g, msg, sizeof msg), LH_OK);
    LH_EXPECT_STREQ(msg, "");
    check_pslg(lh_t_, &g);
    LH_EXPECT_EQ_INT(g.even_odd, 1);
    LH_EXPECT_EQ_INT(g.first_index, 0);
    LH_ASSERT_EQ_U64(g.n, 11);
    for (int i = 0; i < 22; i++) LH_EXPECT_EQ_DBL(g.xy[i], xy[i]);
    LH_EXPECT_TRUE(signbit(g.xy[6]) != 0); /* -0 is kept */
    LH_ASSERT_EQ_U64(g.segment_count, 10);
    for (int i = 0; i < 20; i++) LH_EXPECT_EQ_INT(g.segments[i], seg[i]);
    for (int i = 0; i < 11; i++) LH_EXPECT_EQ_U64(g.vertex_line[i], vline[i]);
    for (int i = 0; i < 10; i++) LH_EXPECT_EQ_U64(g.segment_line[i], sline[i]);
    LH_EXPECT_TRUE(g.attr == NULL && g.vertex_marker == NULL && g.segment_marker == NULL && g.holes == NULL &&
                   g.regions == NULL && g.hole_count == 0 && g.region_count == 0 && g.attr_count == 0);
    lh_pslg_free(&g);
    /* A ring of two equal points is one point; a closing point only once. */
    LH_ASSERT_EQ_INT(read_text(lh_rings_read, "d.json", TEXT("[[[1,1],[1,1]],[[0,0],[1,0],[0,0],[0,0]]]"), NULL, &g, msg, sizeof msg),
                     LH_OK);
    LH_EXPECT_EQ_U64(g.n, 4);
    LH_EXPECT_EQ_U64(g.segment_count, 3);
    lh_pslg_free(&g);
}

#ifdef LH_TEST_DATA_DIR
/* Every earcut fixture: vertices (closing points dropped), segments and the sums of
 * the coordinates in reading order, from Python's json module (tests/data/polygons). */
LH_TEST(rings_every_fixture)
{
    static const struct {
        const char *name;
        size_t rings, n, segments;
        double sx, sy;
    } files[] = {
        {"boxy.json", 5, 64, 64, 216200.0, 178462.0},
        {"building.json", 1, 15, 15, 10675.0, 1569.0},
        {"dude.json", 3, 104, 104, 34763.26629, 53996.15154999998},
        {"earcut.json", 7, 548, 548, 3601019.0, 1326426.0},
        {"eberly-3.json", 3, 73, 73, 158760.0, 190216.0},
        {"eberly-6.json", 16, 1402, 1402, 197983.15800000017, -11122.76200000001},
        {"hilbert.json", 1, 1026, 1026, -15870.0, -15903.0},
        {"issue34.json", 8, 127, 127, 127500.0, 67876.0},
        {"issue35.json", 30, 790, 790, 1265526.0, 1036116.0},
        {"issue52.json", 6, 101, 101, 168534.0, 82940.0},
        {"rain.json", 8, 2685, 2685, 5586838.0, 5969887.0},
        {"simplified-us-border.json", 2, 124, 124, 123659.0, 194863.0},
        {"steiner.json", 5, 8, 4, 370.0, 420.0},
        {"water-huge.json", 193, 5487, 5476, 19023493.0, 10938068.0},
        {"water-huge2.json", 443, 5062, 5060, 12288119.0, 9676568.0},
        {"water-huge3.json", 1444, 12864, 12864, 18694677.0, 17168475.0},
        {"water.json", 10, 2513, 2513, 7254905.0, 7322617.0},
        {"water2.json", 8, 1227, 1227, 2891984.0, 2673107.0},
        {"water3.json", 6, 206, 206, 766315.0, 308642.0},
        {"water3b.json", 3, 29, 29, 107879.0, 11434.0},
        {"water4.json", 6, 714, 714, 2487271.0, 2001142.0},
        {"degenerate/bad-diagonals.json", 1, 11, 11, 3856.0, 46056.0},
        {"degenerate/bad-hole.json", 4, 44, 44, 37361.0, 124922.0},
        {"degenerate/collinear-diagonal.json", 1, 24, 24, 82123.0, 44589.0},
        {"degenerate/degenerate.json", 1, 6, 6, 800.0, 700.0},
        {"degenerate/empty-square.json", 2, 8, 8, 16000.0, 16000.0},
        {"degenerate/filtered-bridge-jhl.json", 5, 22, 22, 233.0, 142.0},
        {"degenerate/hole-touching-outer.json", 2, 79, 79, 175001.0, 127247.0},
        {"degenerate/hourglass.json", 1, 6, 6, 50.0, 93.0},
        {"degenerate/infinite-loop-jhl.json", 2, 6, 6, 2.0, 2.0},
        {"degenerate/issue107.json", 2, 12, 12, 95.96943317089651, 557.4882186580013},
        {"degenerate/issue111.json", 4, 22, 22, 16195.0, 101707.0},
        {"degenerate/issue119.json", 5, 16, 16, 210.0, 257.0},
        {"degenerate/issue131.json", 3, 12, 12, 289.0, -9094.0},
        {"degenerate/issue142.json", 2, 14, 14, -35.36268519247819, 143.23309136410563},
        {"degenerate/issue147.json", 4, 30, 30, -32917.0, -16394.0},
        {"degenerate/issue149.json", 2, 15, 15, 27936.0, 82784.0},
        {"degenerate/issue16.json", 2, 12, 12, 1897.2143274050613, 827.3919299198315},
        {"degenerate/issue17.json", 2, 11, 11, 3767198.576654799, 41344807.138701424},
        {"degenerate/issue186.json", 1, 83, 83, 16800.0, 12500.0},
        {"degenerate/issue29.json", 2, 40, 40, 9138.291579202047, 2794.6391494437794},
        {"degenerate/issue45.json", 3, 10, 10, 165.0, 255.0},
        {"degenerate/issue83.json", 3, 199, 199, 15809.0, 15809.0},
        {"degenerate/outside-ring.json", 3, 66, 66, 147074.0, 76119.0},
        {"degenerate/self-tangent-1.json", 3, 23, 23, 74255.0, 77077.0},
        {"degenerate/self-tangent-2.json", 3, 25, 25, 74182.0, 63195.0},
        {"degenerate/self-tangent-3.json", 23, 147, 147, 116315.0, 223363.0},
        {"degenerate/self-tangent-4.json", 273, 2616, 2616, 2092913.0, 9680804.0},
        {"degenerate/self-touching.json", 3, 122, 122, 19569.424218750006, 1367.7146721307236},
        {"degenerate/shared-points.json", 1, 10, 10, 41344.0, 9992.0},
        {"degenerate/touching-holes.json", 8, 49, 49, 183366.0, 102378.0},
        {"degenerate/touching-holes2.json", 3, 10, 10, 72.0, 135.0},
        {"degenerate/touching-holes3.json", 27, 82, 82, 803.0, 975.0},
        {"degenerate/touching-holes4.json", 27, 82, 82, -451.0, 975.0},
        {"degenerate/touching-holes5.json", 53, 160, 160, 312.0, 1900.0},
        {"degenerate/touching-holes6.json", 169, 2832, 2832, 3694778.0, 7901096.0},
        {"degenerate/touching2.json", 2, 9, 9, 645.0, 19249.0},
        {"degenerate/touching3.json", 3, 15, 15, 18426.0, 13527.0},
        {"degenerate/touching4.json", 5, 16, 16, 87.0, 84.0},
    };
    for (size_t k = 0; k < LH_COUNT(files) && !LH_FAILED(); k++) {
        char path[160], msg[256];
        snprintf(path, sizeof path, "polygons/%s", files[k].name);
        lh_pslg g;
        LH_EXPECT_EQ_INT(read_file(lh_rings_read, path, NULL, &g, msg, sizeof msg), LH_OK);
        LH_EXPECT_STREQ(msg, "");
        check_pslg(lh_t_, &g);
        LH_EXPECT_EQ_U64(g.n, files[k].n);
        LH_EXPECT_EQ_U64(g.segment_count, files[k].segments);
        double sx = 0, sy = 0;
        for (size_t i = 0; i < g.n; i++) {
            sx += g.xy[2 * i];
            sy += g.xy[2 * i + 1];
        }
        LH_EXPECT_EQ_DBL(sx, files[k].sx);
        LH_EXPECT_EQ_DBL(sy, files[k].sy);
        /* Cycles: each segment starts where the previous ended, or a new ring. */
        size_t cycles = 0;
        for (size_t i = 0; i < g.segment_count; i++) {
            lh_index a = g.segments[2 * i], b = g.segments[2 * i + 1];
            LH_EXPECT_TRUE(b == a + 1 || b < a);
            if (b < a) cycles++;
            LH_EXPECT_EQ_U64(g.segment_line[i], g.vertex_line[a]);
        }
        LH_EXPECT_LE_U64(cycles, files[k].rings);
        LH_EXPECT_EQ_INT(g.even_odd, 1);
        lh_pslg_free(&g);
        if (LH_FAILED()) LH_NOTE("fixture %s: %s", files[k].name, msg);
    }
}
#endif

LH_TEST(rings_errors)
{
    static const bad_case cases[] = {
        {"e.json", TEXT(""), LH_ERR_PARSE, "e.json:1:1: expected '[' (a polygon: a list of rings), found the end of the input"},
        {"o.json", TEXT(" {\"type\": \"Polygon\"}"), LH_ERR_PARSE, "o.json:1:2: expected '[' (a polygon: a list of rings), found '{'"},
        {"a.json", TEXT("[]"), LH_ERR_PARSE, "a.json:1:2: expected '[' (ring 1: a list of points), found ']'"},
        {"r.json", TEXT("[[]]"), LH_ERR_PARSE, "r.json:1:3: expected '[' (point 1 of ring 1), found ']'"},
        {"p1.json", TEXT("[[[1]]]"), LH_ERR_PARSE, "p1.json:1:5: expected ',' after coordinate 1 of point 1 of ring 1, found ']'"},
        {"p3.json", TEXT("[[[1,2,3]]]"), LH_ERR_PARSE,
         "p3.json:1:7: expected ']' after coordinate 2 of point 1 of ring 1 (a point is [x, y]), found ','"},
        {"s.json", TEXT("[[[1,\"2\"]]]"), LH_ERR_PARSE, "s.json:1:6: expected coordinate 2 of point 1 of ring 1 (a number), found '\"'"},
        {"nan.json", TEXT("[[[NaN,0]]]"), LH_ERR_NONFINITE,
         "nan.json:1:4: coordinate 1 of point 1 of ring 1 is 'NaN': NaN and infinities are not points"},
        {"inf.json", TEXT("[[[0,0],\n [-Infinity, 0]]]"), LH_ERR_NONFINITE,
         "inf.json:2:3: coordinate 1 of point 2 of ring 1 is '-Infinity': NaN and infinities are not points"},
        {"over.json", TEXT("[[[0,1e400]]]"), LH_ERR_NONFINITE,
         "over.json:1:6: coordinate 2 of point 1 of ring 1 is '1e400', which overflows a double"},
        {"lead.json", TEXT("[[[01,0]]]"), LH_ERR_PARSE, "lead.json:1:4: expected coordinate 1 of point 1 of ring 1 (a number), found '01'"},
        {"hex.json", TEXT("[[[0x10,0]]]"), LH_ERR_PARSE, "hex.json:1:4: expected coordinate 1 of point 1 of ring 1 (a number), found '0x10'"},
        {"dot.json", TEXT("[[[1.,0]]]"), LH_ERR_PARSE, "dot.json:1:4: expected coordinate 1 of point 1 of ring 1 (a number), found '1.'"},
        {"plus.json", TEXT("[[[+1,0]]]"), LH_ERR_PARSE, "plus.json:1:4: expected coordinate 1 of point 1 of ring 1 (a number), found '+1'"},
        {"deep.json", TEXT("[[[[0,0]]]]"), LH_ERR_PARSE, "deep.json:1:4: expected coordinate 1 of point 1 of ring 1 (a number), found '['"},
        {"sp.json", TEXT("[[[0,0] [1,0]]]"), LH_ERR_PARSE, "sp.json:1:9: expected ',' or ']' after point 1 of ring 1, found '['"},
        {"trunc.json", TEXT("[[[0,0],[1,0]"), LH_ERR_PARSE,
         "trunc.json:1:14: expected ',' or ']' after point 2 of ring 1, found the end of the input"},
        {"comma.json", TEXT("[[[0,0]],]"), LH_ERR_PARSE, "comma.json:1:10: expected '[' (ring 2: a list of points), found ']'"},
        {"rings.json", TEXT("[[[0,0]]}"), LH_ERR_PARSE, "rings.json:1:9: expected ',' or ']' after ring 1, found '}'"},
        {"tail.json", TEXT("[[[0,0]],[[1,1]]]\n\n x"), LH_ERR_PARSE,
         "tail.json:3:2: expected the end of the input after the polygon (2 rings), found 'x'"},
        {"two.json", TEXT("[[[0,0]]] [[[0,0]]]"), LH_ERR_PARSE,
         "two.json:1:11: expected the end of the input after the polygon (1 ring), found '['"},
        {"nul.json", TEXT("[\0"), LH_ERR_PARSE, "nul.json:1:2: expected '[' (ring 1: a list of points), found a NUL byte"},
        {"utf.json", TEXT("[[[0,\xc2\xb5]]]"), LH_ERR_PARSE,
         "utf.json:1:6: expected coordinate 2 of point 1 of ring 1, found a non-text byte 0xc2"},
        {"ml.json", TEXT("[\n  [[0, 0], [1, 0],\n   [1, x]]\n]"), LH_ERR_PARSE,
         "ml.json:3:8: expected coordinate 2 of point 3 of ring 1 (a number), found 'x'"},
    };
    check_bad_cases(lh_t_, lh_rings_read, cases, LH_COUNT(cases));
}

LH_TEST(long_tokens)
{
    char text[700], msg[512];
    memcpy(text, "[[[1,", 5);
    memset(text + 5, '1', 300);
    memcpy(text + 305, "]]]", 4);
    lh_pslg g;
    LH_EXPECT_EQ_INT(read_text(lh_rings_read, "long.json", text, strlen(text), NULL, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "long.json:1:6: expected coordinate 2 of point 1 of ring 1, found a token of more than 255 bytes");
    memcpy(text, "1 2\n1 0 ", 8);
    memset(text + 8, '2', 300);
    memcpy(text + 308, "\n0\n0\n", 6);
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "long.poly", text, strlen(text), NULL, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "long.poly:2:5: expected coordinate 2 of vertex 1 (a number), found a token of more than 255 bytes");
}

/* ---- memory --------------------------------------------------------------------- */

/* The largest single allocation, to see that a declared count is not trusted. */
typedef struct biggest {
    size_t largest;
    long live;
} biggest;

static void *big_alloc(void *user, size_t size)
{
    biggest *b = user;
    if (size > b->largest) b->largest = size;
    b->live++;
    return malloc(size);
}

static void big_free(void *user, void *ptr)
{
    biggest *b = user;
    if (ptr) b->live--;
    free(ptr);
}

LH_TEST(declared_counts_are_not_trusted)
{
    biggest b = {0, 0};
    lh_allocator a = {big_alloc, big_free, &b};
    char msg[256];
    lh_pslg g;
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie.poly", TEXT("2000000000 2 3 1\n1 0 0 1 2 3 4\n"), &a, &g, msg, sizeof msg),
                     LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie.poly:3:1: expected vertex number 2, found the end of the input (2000000000 vertices declared)");
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie2.poly", TEXT("0\n2000000000 1\n1 1 2 3\n"), &a, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie2.poly:4:1: expected segment number 2, found the end of the input (2000000000 segments declared)");
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie3.poly", TEXT("0\n0\n0\n2000000000\n1 0 0 1 1\n"), &a, &g, msg, sizeof msg),
                     LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie3.poly:6:1: expected region number 2, found the end of the input (2000000000 regions declared)");
    LH_EXPECT_LE_U64(b.largest, 1u << 16);
    LH_EXPECT_EQ_INT(b.live, 0);
}

/* A .poly of n vertices (2 attributes, markers), n segments with markers, n holes and
 * n regions: every array grows several times. */
static char *big_poly(size_t n, size_t *len)
{
    size_t cap = 200 * n + 100, k = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    k += (size_t)snprintf(s + k, cap - k, "%zu 2 2 1\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu %zu 0.5 1 2 %zu\n", i + 1, i, i % 3);
    k += (size_t)snprintf(s + k, cap - k, "%zu 1\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu %zu %zu 4\n", i + 1, i + 1, (i + 1) % n + 1);
    k += (size_t)snprintf(s + k, cap - k, "%zu\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu 0.5 %zu.5\n", i + 1, i);
    k += (size_t)snprintf(s + k, cap - k, "%zu\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu 0.5 %zu.5 1 -1\n", i + 1, i);
    *len = k;
    return s;
}

/* Rings: n points in rings of 7. */
static char *big_rings(size_t n, size_t *len)
{
    size_t cap = 40 * n + 100, k = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    s[k++] = '[';
    for (size_t i = 0; i < n; i++) {
        int first = i % 7 == 0, last = i % 7 == 6 || i + 1 == n;
        k += (size_t)snprintf(s + k, cap - k, "%s%s[%zu,%zu]%s", first && i ? "," : "", first ? "[" : ",", i, i % 7,
                              last ? "]" : "");
    }
    s[k++] = ']';
    *len = k;
    return s;
}

typedef struct alloc_case {
    reader rd;
    const char *text;
    size_t len;
} alloc_case;

static lh_status run_read(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const alloc_case *c = user;
    lh_pslg g;
    char msg[256];
    lh_status st = read_text(c->rd, "alloc", c->text, c->len, a, &g, msg, sizeof msg);
    if (st == LH_ERR_NOMEM) {
        LH_EXPECT_TRUE(strstr(msg, "alloc:") == msg && strstr(msg, ": out of memory for "));
        LH_EXPECT_TRUE(g.xy == NULL && g.segments == NULL && g.alloc_.alloc == NULL);
    } else {
        LH_EXPECT_EQ_INT(st, LH_OK);
        check_pslg(lh_t_, &g);
    }
    lh_pslg_free(&g);
    return st;
}

LH_TEST(every_allocation_failure)
{
    alloc_case c;
    size_t len = 0;
    char *s = big_poly(300, &len);
    LH_ASSERT_TRUE(s != NULL);
    c = (alloc_case){lh_poly_read, s, len};
    LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_read, &c), 4 * 2 + 3 * 2 + 2 * 2 + 2 * 2 + 1);
    free(s);
    s = big_rings(1000, &len);
    LH_ASSERT_TRUE(s != NULL);
    c = (alloc_case){lh_rings_read, s, len};
    LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_read, &c), 2 * 4 + 2 * 4);
    free(s);
}

/* The readers' stack stays small (a caller's thread may have a small one): the
 * scanner's block and the attributes' scratch live on the heap. */
LH_TEST(reading_needs_little_stack)
{
    for (int k = 0; k < 2; k++) {
        alloc_case c = {k ? lh_rings_read : lh_poly_read, NULL, 0};
        char *text = k ? big_rings(1000, &c.len) : big_poly(300, &c.len);
        LH_ASSERT_TRUE(text != NULL);
        c.text = text;
        size_t used;
        LH_EXPECT_EQ_INT(lh_test_run_on_thread(lh_t_, run_read, &c, &used), LH_OK);
        LH_EXPECT_GT_INT(used, 0);
        LH_EXPECT_LE_U64(used, 12288); /* under the 16 KiB block alone; sanitizers widen frames */
        if (LH_FAILED()) LH_NOTE("%s: %zu bytes of stack", k ? "rings" : ".poly", used);
        free(text);
    }
}

#ifdef LH_TEST_DATA_DIR
typedef struct file_case {
    reader rd;
    const char *path;
} file_case;

static lh_status run_file(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const file_case *c = user;
    lh_pslg g;
    char msg[256];
    lh_status st = read_file(c->rd, c->path, a, &g, msg, sizeof msg);
    if (st == LH_ERR_NOMEM) LH_EXPECT_TRUE(strstr(msg, ": out of memory for ") != NULL);
    else LH_EXPECT_EQ_INT(st, LH_OK);
    lh_pslg_free(&g);
    return st;
}

LH_TEST(every_allocation_failure_files)
{
    static const file_case files[] = {
        {lh_poly_read, "triangle/A.poly"}, {lh_poly_read, "triangle/box.poly"}, {lh_poly_read, "triangle/la.poly"},
        {lh_poly_read, "triangle/reference_outputs/double_hex3.1.poly"}, {lh_rings_read, "polygons/dude.json"},
        {lh_rings_read, "polygons/steiner.json"},
    };
    for (size_t k = 0; k < LH_COUNT(files) && !LH_FAILED(); k++) {
        LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_file, &files[k]), 3);
        if (LH_FAILED()) LH_NOTE("file %s", files[k].path);
    }
}
#endif

LH_TEST(read_error_and_arguments)
{
    char msg[256] = "x";
    lh_pslg g;
    FILE *w = fopen("/dev/null", "w");
    if (w) { /* reading a write-only stream fails with an error, not an end */
        LH_EXPECT_EQ_INT(lh_poly_read(w, "wo", NULL, &g, msg, sizeof msg), LH_ERR_IO);
        LH_EXPECT_STREQ(msg, "wo:1:1: expected the number of vertices, found a read error");
        LH_EXPECT_EQ_INT(lh_rings_read(w, "wo", NULL, &g, msg, sizeof msg), LH_ERR_IO);
        LH_EXPECT_STREQ(msg, "wo:1:1: expected '[' (a polygon: a list of rings), found a read error");
        fclose(w);
    }
    FILE *f = lh_test_file(TEXT("0\n0\n0\n"));
    LH_ASSERT_TRUE(f != NULL);
    lh_allocator half = {lh_test_counting_alloc, NULL, NULL};
    reader rds[] = {lh_poly_read, lh_rings_read};
    for (int k = 0; k < 2; k++) {
        memset(&g, 0xff, sizeof g);
        LH_EXPECT_EQ_INT(rds[k](NULL, "x", NULL, &g, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_TRUE(g.xy == NULL && g.n == 0 && g.alloc_.alloc == NULL); /* zeroed */
        LH_EXPECT_EQ_INT(rds[k](f, "x", NULL, NULL, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_EQ_INT(rds[k](f, "x", &half, &g, msg, sizeof msg), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_TRUE(g.alloc_.alloc == NULL);
    }
    fclose(f);
    /* No name, no message buffer, a message buffer of one byte. */
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, NULL, TEXT("3 x"), NULL, &g, NULL, 0), LH_ERR_PARSE);
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, NULL, TEXT("3 x"), NULL, &g, msg, 1), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "");
    LH_EXPECT_EQ_INT(read_text(lh_rings_read, NULL, TEXT("x"), NULL, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "<input>:1:1: expected '[' (a polygon: a list of rings), found 'x'");
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
#ifdef LH_TEST_DATA_DIR
        LH_CASE(poly_A), LH_CASE(poly_box_markers), LH_CASE(poly_face), LH_CASE(poly_la_regions),
        LH_CASE(poly_every_file), LH_CASE(poly_double_hex3_and_its_node), LH_CASE(poly_n0_take_points),
        LH_CASE(rings_every_fixture), LH_CASE(every_allocation_failure_files),
#endif
        LH_CASE(poly_n0_renumbered), LH_CASE(poly_n0_keeps_its_item_numbers), LH_CASE(poly_take_points_arguments), LH_CASE(poly_text_forms),
        LH_CASE(poly_header_errors), LH_CASE(poly_vertex_errors), LH_CASE(poly_segment_errors),
        LH_CASE(poly_hole_region_errors), LH_CASE(rings_text_forms), LH_CASE(rings_errors), LH_CASE(long_tokens),
        LH_CASE(declared_counts_are_not_trusted), LH_CASE(every_allocation_failure), LH_CASE(reading_needs_little_stack),
        LH_CASE(read_error_and_arguments),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
