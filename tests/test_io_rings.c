/* test_io_rings.c — lh_rings_read: its text forms, every earcut fixture (counts and
 * coordinate sums from Python's json module), its diagnostics exactly, long tokens. */
#include "io_pslg_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
typedef struct fixture {
    const char *name;
    size_t rings, n, segments;
    double sx, sy;
} fixture;

static const fixture fixtures[] = {
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

/* Segments run along rings: each starts where the previous ended (b == a + 1) or
 * closes a ring (b < a), at most once per ring, on the line of its first vertex. */
static void check_ring_cycles(lh_test_state *lh_t_, const lh_pslg *g, size_t rings)
{
    size_t cycles = 0;
    for (size_t i = 0; i < g->segment_count; i++) {
        lh_index a = g->segments[2 * i], b = g->segments[2 * i + 1];
        LH_EXPECT_TRUE(b == a + 1 || b < a);
        if (b < a) cycles++;
        LH_EXPECT_EQ_U64(g->segment_line[i], g->vertex_line[a]);
    }
    LH_EXPECT_LE_U64(cycles, rings);
}

/* One fixture read and checked against its row. */
static void check_fixture(lh_test_state *lh_t_, const fixture *f)
{
    char path[160], msg[256];
    snprintf(path, sizeof path, "polygons/%s", f->name);
    lh_pslg g;
    LH_EXPECT_EQ_INT(read_file(lh_rings_read, path, NULL, &g, msg, sizeof msg), LH_OK);
    LH_EXPECT_STREQ(msg, "");
    check_pslg(lh_t_, &g);
    LH_EXPECT_EQ_U64(g.n, f->n);
    LH_EXPECT_EQ_U64(g.segment_count, f->segments);
    double sx = 0, sy = 0;
    for (size_t i = 0; i < g.n; i++) {
        sx += g.xy[2 * i];
        sy += g.xy[2 * i + 1];
    }
    LH_EXPECT_EQ_DBL(sx, f->sx);
    LH_EXPECT_EQ_DBL(sy, f->sy);
    check_ring_cycles(lh_t_, &g, f->rings);
    LH_EXPECT_EQ_INT(g.even_odd, 1);
    lh_pslg_free(&g);
    if (LH_FAILED()) LH_NOTE("fixture %s: %s", f->name, msg);
}

LH_TEST(rings_every_fixture)
{
    for (size_t k = 0; k < LH_COUNT(fixtures) && !LH_FAILED(); k++)
        check_fixture(lh_t_, &fixtures[k]);
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

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
#ifdef LH_TEST_DATA_DIR
        LH_CASE(rings_every_fixture),
#endif
        LH_CASE(rings_text_forms), LH_CASE(rings_errors), LH_CASE(long_tokens),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
