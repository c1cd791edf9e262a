/* test_io_plc.c — lh_plc_read's text readers (OFF, TetGen .poly/.smesh/.node, Medit
 * .mesh, Wavefront .obj): exact contents of small inputs, one real file a format
 * (tests/data/plc/, tests/data/SOURCES.md) and every diagnostic of hostile inputs
 * (truncated files, indices out of range, facets of < 3 vertices, NaN, counts larger
 * than the data, garbage) exactly; every allocation failure reported and freed. */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define TEXT(s) s, sizeof(s) - 1

/* ---- helpers ---------------------------------------------------------------------- */

static lh_status read_text(const char *name, lh_plc_format fmt, const char *text, size_t len,
                           const lh_allocator *a, lh_plc *g, lh_error *err)
{
    const lh_error io = {LH_ERR_IO, 0, 0, LH_ERROR_NO_INDEX, ""};
    *err = io;
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_plc_read(f, name, fmt, a, g, err);
    fclose(f);
    return st;
}

static void put(char *buf, size_t size, const char *fmt, ...)
{
    size_t used = strlen(buf);
    if (used + 1 >= size) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + used, size - used, fmt, ap);
    va_end(ap);
}

/* g as text: "p x y z [attr..] mM;" a point, "f mM @LINE: a b c / d e [h x y z];" a
 * facet (its polygons, 0-based, and hole points), "s a b mM;", "h x y z;", "r x y z a v;";
 * "first F" at the end. */
static void dump(const lh_plc *g, char *buf, size_t size)
{
    buf[0] = 0;
    for (size_t i = 0; i < g->n; i++) {
        put(buf, size, "p %g %g %g", g->xyz[3 * i], g->xyz[3 * i + 1], g->xyz[3 * i + 2]);
        for (int j = 0; j < g->attr_count; j++) put(buf, size, " %g", g->attr[i * (size_t)g->attr_count + j]);
        put(buf, size, " m%d;", g->point_marker ? (int)g->point_marker[i] : 0);
    }
    for (size_t f = 0; f < g->facet_count; f++) {
        put(buf, size, "f m%d @%zu:", g->facet_marker ? (int)g->facet_marker[f] : 0,
            g->facet_line ? g->facet_line[f] : 0);
        for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
            if (p > g->facet_first[f]) put(buf, size, " /");
            for (lh_index v = g->polygon_first[p]; v < g->polygon_first[p + 1]; v++)
                put(buf, size, " %d", (int)g->polygon_vertices[v]);
        }
        for (lh_index h = g->facet_hole_first[f]; h < g->facet_hole_first[f + 1]; h++)
            put(buf, size, " [h %g %g %g]", g->facet_holes[3 * h], g->facet_holes[3 * h + 1],
                g->facet_holes[3 * h + 2]);
        put(buf, size, ";");
    }
    for (size_t i = 0; i < g->segment_count; i++)
        put(buf, size, "s %d %d m%d;", (int)g->segments[2 * i], (int)g->segments[2 * i + 1],
            g->segment_marker ? (int)g->segment_marker[i] : 0);
    for (size_t i = 0; i < g->hole_count; i++)
        put(buf, size, "h %g %g %g;", g->holes[3 * i], g->holes[3 * i + 1], g->holes[3 * i + 2]);
    for (size_t i = 0; i < g->region_count; i++)
        put(buf, size, "r %g %g %g %g %g;", g->regions[5 * i], g->regions[5 * i + 1],
            g->regions[5 * i + 2], g->regions[5 * i + 3], g->regions[5 * i + 4]);
    put(buf, size, "first %d", g->first_index);
}

/* The invariants of every reader's output. */
static void check_plc(lh_test_state *lh_t_, const lh_plc *g)
{
    LH_EXPECT_TRUE((g->n > 0) == (g->xyz != NULL));
    LH_EXPECT_TRUE(g->facet_first && g->polygon_first && g->facet_hole_first);
    LH_EXPECT_TRUE(g->first_index == 0 || g->first_index == 1);
    for (size_t i = 0; i < 3 * g->n; i++) LH_EXPECT_TRUE(isfinite(g->xyz[i]));
    LH_EXPECT_EQ_INT(g->facet_first[0], 0);
    for (size_t f = 0; f < g->facet_count; f++) {
        int big = 0;
        LH_EXPECT_TRUE(g->facet_first[f] < g->facet_first[f + 1]);
        for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
            lh_index k = g->polygon_first[p + 1] - g->polygon_first[p];
            LH_EXPECT_TRUE(k >= 1);
            big |= k >= 3;
        }
        LH_EXPECT_TRUE(big);
    }
    LH_EXPECT_EQ_U64(g->facet_first[g->facet_count], g->polygon_count);
    size_t nv = (size_t)g->polygon_first[g->polygon_count];
    for (size_t i = 0; g->n && i < nv; i++)
        LH_EXPECT_TRUE(g->polygon_vertices[i] >= 0 && (size_t)g->polygon_vertices[i] < g->n);
    for (size_t i = 0; g->n && i < 2 * g->segment_count; i++)
        LH_EXPECT_TRUE(g->segments[i] >= 0 && (size_t)g->segments[i] < g->n);
}

/* text read as `name` in format fmt must give `want` (dump()). */
static void expect_plc(lh_test_state *lh_t_, const char *name, lh_plc_format fmt, const char *text,
                       size_t len, const char *want)
{
    lh_test_counter k = {0, 0, 0};
    lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &k};
    lh_plc g;
    lh_error err;
    char got[4096];
    LH_EXPECT_EQ_INT(read_text(name, fmt, text, len, &a, &g, &err), LH_OK);
    LH_EXPECT_STREQ(err.message, "");
    if (LH_FAILED()) return;
    check_plc(lh_t_, &g);
    dump(&g, got, sizeof got);
    LH_EXPECT_STREQ(got, want);
    lh_plc_free(&g);
    LH_EXPECT_EQ_INT(k.live, 0);
    if (LH_FAILED()) LH_NOTE("input %s", name);
}

typedef struct bad_case {
    const char *name;
    lh_plc_format fmt;
    const char *text;
    size_t len;
    lh_status status;
    const char *msg;
} bad_case;

/* Each case must fail with its status and exact message, hand back a zeroed lh_plc
 * and leave nothing allocated. */
static void check_bad(lh_test_state *lh_t_, const bad_case *cases, size_t count)
{
    for (size_t i = 0; i < count && !LH_FAILED(); i++) {
        const bad_case *c = &cases[i];
        if (sizeof(lh_index) != 4 && strstr(c->msg, "2147483646")) continue;
        lh_test_counter k = {0, 0, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &k};
        lh_plc g, zero;
        lh_error err;
        memset(&zero, 0, sizeof zero);
        LH_EXPECT_EQ_INT(read_text(c->name, c->fmt, c->text, c->len, &a, &g, &err), c->status);
        LH_EXPECT_EQ_INT(err.status, c->status);
        LH_EXPECT_STREQ(err.message, c->msg);
        char place[300];
        snprintf(place, sizeof place, "%s:%zu:%zu: ", c->name, err.line, err.column);
        LH_EXPECT_TRUE(err.line > 0 && err.column > 0 && strncmp(c->msg, place, strlen(place)) == 0);
        LH_EXPECT_TRUE(memcmp(&g, &zero, sizeof g) == 0);
        LH_EXPECT_EQ_INT(k.live, 0);
        if (LH_FAILED()) LH_NOTE("case %s", c->name);
    }
}

typedef struct alloc_input {
    const char *name;
    lh_plc_format fmt;
    const char *text;
} alloc_input;

static lh_status read_with(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const alloc_input *in = user;
    lh_plc g;
    lh_error err;
    lh_status st = read_text(in->name, in->fmt, in->text, strlen(in->text), a, &g, &err);
    if (st == LH_OK) lh_plc_free(&g);
    else if (st != LH_ERR_NOMEM) LH_NOTE("%s", err.message);
    else LH_EXPECT_TRUE(g.xyz == NULL && g.facet_first == NULL && g.alloc_.alloc == NULL);
    return st;
}

#ifdef LH_TEST_DATA_DIR
/* tests/data/plc/NAME read (format from its name): its counts. */
static void expect_file(lh_test_state *lh_t_, const char *name, size_t n, size_t facets,
                        size_t polygons, size_t vertices, size_t segments)
{
    char path[512];
    snprintf(path, sizeof path, "%s/plc/%s", LH_TEST_DATA_DIR, name);
    FILE *f = fopen(path, "rb");
    LH_ASSERT_TRUE(f != NULL);
    lh_plc g;
    lh_error err;
    lh_status st = lh_plc_read(f, name, LH_PLC_AUTO, NULL, &g, &err);
    fclose(f);
    LH_EXPECT_EQ_INT(st, LH_OK);
    LH_EXPECT_STREQ(err.message, "");
    if (LH_FAILED()) return;
    check_plc(lh_t_, &g);
    LH_EXPECT_EQ_U64(g.n, n);
    LH_EXPECT_EQ_U64(g.facet_count, facets);
    LH_EXPECT_EQ_U64(g.polygon_count, polygons);
    LH_EXPECT_EQ_U64(g.polygon_first[g.polygon_count], vertices);
    LH_EXPECT_EQ_U64(g.segment_count, segments);
    lh_plc_free(&g);
}
#endif

/* ---- OFF ------------------------------------------------------------------------- */

#define OFF_TET "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
#define TET_POINTS "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;p 0 0 1 m0;"

LH_TEST(off_reads)
{
    expect_plc(lh_t_, "tet.off", LH_PLC_OFF, TEXT(OFF_TET),
               TET_POINTS "f m0 @7: 0 2 1;f m0 @8: 0 1 3;f m0 @9: 0 3 2;f m0 @10: 1 2 3;first 0");
    /* no keyword, counts on the keyword's line, comments, blank lines, a quad and a
       face colour, no edge count */
    expect_plc(lh_t_, "q.off", LH_PLC_AUTO,
               TEXT("# a square pyramid\n4 2\n\n0 0 0\n1 0 0\n1 1 0 # corner\n0 1 0\n4 0 1 2 3 1 0 0\n3 0 1 2\n"),
               "p 0 0 0 m0;p 1 0 0 m0;p 1 1 0 m0;p 0 1 0 m0;f m0 @8: 0 1 2 3;f m0 @9: 0 1 2;first 0");
    expect_plc(lh_t_, "k.off", LH_PLC_OFF, TEXT("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2"),
               "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;f m0 @5: 0 1 2;first 0");
    /* prefixed keywords: vertex normals and colours ignored */
    expect_plc(lh_t_, "c.off", LH_PLC_OFF,
               TEXT("CNOFF\n3 1 0\n0 0 0 0 0 1 1 0 0 1\n1 0 0 0 0 1 0 1 0 1\n0 1 0 0 0 1 0 0 1 1\n3 0 1 2\n"),
               "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;f m0 @6: 0 1 2;first 0");
    expect_plc(lh_t_, "p.off", LH_PLC_OFF, TEXT("OFF\n2 0 0\n0 0 0\n1 2 3\n"), "p 0 0 0 m0;p 1 2 3 m0;first 0");
    expect_plc(lh_t_, "crlf.off", LH_PLC_OFF, TEXT("OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 2 1 0\r\n"),
               "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;f m0 @6: 2 1 0;first 0");
}

#define OFF3 "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"

LH_TEST(off_errors)
{
    static const bad_case cases[] = {
        {"empty.off", LH_PLC_OFF, TEXT(""), LH_ERR_PARSE, "empty.off:1:1: expected the number of vertices, found the end of the input"},
        {"kw.off", LH_PLC_OFF, TEXT("PLY\n"), LH_ERR_PARSE,
         "kw.off:1:1: expected the OFF header ('OFF', 'COFF', 'NOFF', 'CNOFF', 'STOFF'...) or the number of vertices, found 'PLY'"},
        {"4d.off", LH_PLC_OFF, TEXT("4OFF\n1 0 0\n0 0 0 0\n"), LH_ERR_PARSE,
         "4d.off:1:1: expected the OFF header ('OFF', 'COFF', 'NOFF', 'CNOFF', 'STOFF'...) or the number of vertices, found '4OFF'"},
        {"bin.off", LH_PLC_OFF, TEXT("OFF BINARY\n"), LH_ERR_PARSE, "bin.off:1:5: binary OFF is not read: write it as text"},
        {"nv.off", LH_PLC_OFF, TEXT("OFF\n0 0 0\n"), LH_ERR_PARSE,
         "nv.off:2:1: expected the number of vertices (an integer from 1 to 2147483646), found '0'"},
        {"big.off", LH_PLC_OFF, TEXT("OFF\n3000000000 1 0\n"), LH_ERR_TOO_LARGE,
         "big.off:2:1: expected the number of vertices (an integer from 1 to 2147483646), found '3000000000'"},
        {"nf.off", LH_PLC_OFF, TEXT("OFF\n3\n"), LH_ERR_PARSE, "nf.off:2:2: expected the number of faces, found the end of the line"},
        {"ne.off", LH_PLC_OFF, TEXT("OFF\n3 1 x\n"), LH_ERR_PARSE,
         "ne.off:2:5: expected the number of edges (an integer from 0) or the end of the line, found 'x'"},
        {"h4.off", LH_PLC_OFF, TEXT("OFF\n3 1 0 0\n"), LH_ERR_PARSE,
         "h4.off:2:7: expected the end of the line after the counts (vertices, faces, edges), found '0'"},
        {"short.off", LH_PLC_OFF, TEXT("OFF\n3 1 0\n0 0 0\n1 0 0\n"), LH_ERR_PARSE,
         "short.off:5:1: expected coordinate 1 of vertex 2, found the end of the input (3 vertices declared)"},
        {"y.off", LH_PLC_OFF, TEXT("OFF\n3 1 0\n0 0\n"), LH_ERR_PARSE, "y.off:3:4: expected coordinate 3 of vertex 0, found the end of the line"},
        {"nan.off", LH_PLC_OFF, TEXT("OFF\n3 1 0\n0 nan 0\n"), LH_ERR_NONFINITE,
         "nan.off:3:3: coordinate 2 of vertex 0 is 'nan': NaN and infinities are not points"},
        {"inf.off", LH_PLC_OFF, TEXT("OFF\n3 1 0\n0 0 1e999\n"), LH_ERR_NONFINITE,
         "inf.off:3:5: coordinate 3 of vertex 0 is '1e999', which overflows a double"},
        {"col.off", LH_PLC_OFF, TEXT("OFF\n3 1 0\n0 0 0 1\n"), LH_ERR_PARSE,
         "col.off:3:7: expected the end of the line after vertex 0, found '1'"},
        {"nofaces.off", LH_PLC_OFF, TEXT(OFF3), LH_ERR_PARSE,
         "nofaces.off:6:1: expected the number of vertices of face 0, found the end of the input (1 face declared)"},
        {"k2.off", LH_PLC_OFF, TEXT(OFF3 "2 0 1\n"), LH_ERR_PARSE,
         "k2.off:6:1: expected the number of vertices of face 0 (an integer from 3 to 2147483646), found '2'"},
        {"kx.off", LH_PLC_OFF, TEXT(OFF3 "three 0 1 2\n"), LH_ERR_PARSE,
         "kx.off:6:1: expected the number of vertices of face 0 (an integer from 3 to 2147483646), found 'three'"},
        {"range.off", LH_PLC_OFF, TEXT(OFF3 "3 0 1 3\n"), LH_ERR_PARSE,
         "range.off:6:7: expected vertex 3 of face 0 (a vertex number from 0 to 2), found '3'"},
        {"neg.off", LH_PLC_OFF, TEXT(OFF3 "3 0 -1 2\n"), LH_ERR_PARSE,
         "neg.off:6:5: expected vertex 2 of face 0 (a vertex number from 0 to 2), found '-1'"},
        {"cut.off", LH_PLC_OFF, TEXT(OFF3 "4 0 1 2\n"), LH_ERR_PARSE,
         "cut.off:6:8: expected vertex 4 of face 0 (a vertex number from 0 to 2), found the end of the line"},
        {"junk.off", LH_PLC_OFF, TEXT(OFF3 "3 0 1 2 red\n"), LH_ERR_PARSE,
         "junk.off:6:9: expected the end of the line after face 0 (or its colour: up to 4 numbers), found 'red'"},
        {"more.off", LH_PLC_OFF, TEXT(OFF3 "3 0 1 2\n3 0 1 2\n"), LH_ERR_PARSE,
         "more.off:7:1: expected the end of the input after 1 face, found '3'"},
        {"nul.off", LH_PLC_OFF, TEXT(OFF3 "3 0 1\0 2\n"), LH_ERR_PARSE,
         "nul.off:6:6: expected vertex 3 of face 0 (a vertex number from 0 to 2), found a NUL byte"},
    };
    check_bad(lh_t_, cases, LH_COUNT(cases));
}

/* ---- TetGen .poly, .smesh, .node --------------------------------------------------- */

/* A unit cube's points, 1-based, one attribute and markers. */
#define CUBE_NODES "8 3 1 1\n1 0 0 0 10 1\n2 1 0 0 20 1\n3 1 1 0 30 1\n4 0 1 0 40 1\n" \
                   "5 0 0 1 50 2\n6 1 0 1 60 2\n7 1 1 1 70 2\n8 0 1 1 80 2\n"
#define CUBE_POINTS "p 0 0 0 10 m1;p 1 0 0 20 m1;p 1 1 0 30 m1;p 0 1 0 40 m1;" \
                    "p 0 0 1 50 m2;p 1 0 1 60 m2;p 1 1 1 70 m2;p 0 1 1 80 m2;"

LH_TEST(poly_reads)
{
    /* the bottom facet has a slit, a lone point (the centre... of nothing: point 7)
       and a hole point; markers on some facets only; a hole, two regions */
    expect_plc(lh_t_, "cube.poly", LH_PLC_AUTO,
               TEXT(CUBE_NODES "# facets\n6 1\n3 1 5\n4 1 2 3 4\n2 1 3\n1 7\n1 0.5 0.5 0\n"
                    "1\n4 5 6 7 8\n1 0 3\n4 1 2 6 5\n1 0 4 # marker 4\n4 2 3 7 6\n1\n4 3 4 8 7\n1\n4 4 1 5 8\n"
                    "1\n1 0.5 0.5 0.5\n2\n1 0.1 0.1 0.1 7 0.25\n2 0.2 0.2 0.2 -3\n"),
               CUBE_POINTS "f m5 @12: 0 1 2 3 / 0 2 / 6 [h 0.5 0.5 0];f m0 @17: 4 5 6 7;f m3 @19: 0 1 5 4;"
                           "f m4 @21: 1 2 6 5;f m0 @23: 2 3 7 6;f m0 @25: 3 0 4 7;"
                           "h 0.5 0.5 0.5;r 0.1 0.1 0.1 7 0.25;r 0.2 0.2 0.2 -3 -1;first 1");
    /* no hole nor region section, 0-based, default header fields */
    expect_plc(lh_t_, "t.poly", LH_PLC_POLY, TEXT("3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n1\n1\n3 0 1 2\n"),
               "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;f m0 @6: 0 1 2;first 0");
    expect_plc(lh_t_, "cube.smesh", LH_PLC_AUTO,
               TEXT(CUBE_NODES "6 1\n4 1 2 3 4 5\n4 5 6 7 8 6\n4 1 2 6 5\n4 2 3 7 6 0\n4 3 4 8 7 -1\n4 4 1 5 8 9\n0\n0\n"),
               CUBE_POINTS "f m5 @11: 0 1 2 3;f m6 @12: 4 5 6 7;f m0 @13: 0 1 5 4;f m0 @14: 1 2 6 5;"
                           "f m-1 @15: 2 3 7 6;f m9 @16: 3 0 4 7;first 1");
    expect_plc(lh_t_, "p.node", LH_PLC_AUTO, TEXT("2 3 0 1\n0 1 2 3 -4\n1 4 5 6 7\n"),
               "p 1 2 3 m-4;p 4 5 6 m7;first 0");
}

/* A .poly without points takes a .node's, numbered from the .node's first number. */
LH_TEST(poly_take_points)
{
    lh_plc g;
    lh_points p;
    lh_error err;
    char got[1024];
    LH_ASSERT_EQ_INT(read_text("n0.smesh", LH_PLC_SMESH, TEXT("0 3 0 0\n1 0\n3 1 2 3\n0\n"), NULL, &g, &err), LH_OK);
    LH_EXPECT_EQ_U64(g.n, 0);
    FILE *f = lh_test_file(TEXT("3 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"));
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "n0.node", LH_FORMAT_NODE, NULL, &p, &err), LH_OK);
    fclose(f);
    LH_ASSERT_EQ_INT(lh_plc_take_points(&g, &p), LH_OK);
    dump(&g, got, sizeof got);
    LH_EXPECT_STREQ(got, "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;f m0 @3: 0 1 2;first 1");
    lh_plc_free(&g);
}

#define POLY3 "3 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"

LH_TEST(poly_errors)
{
    static const bad_case cases[] = {
        {"empty.poly", LH_PLC_POLY, TEXT(""), LH_ERR_PARSE, "empty.poly:1:1: expected the number of points, found the end of the input"},
        {"d2.poly", LH_PLC_POLY, TEXT("3 2\n"), LH_ERR_DIMENSION, "d2.poly:1:3: expected the dimension (3: a .poly file is 3D), found '2'"},
        {"d2.node", LH_PLC_NODE, TEXT("3 2\n"), LH_ERR_DIMENSION, "d2.node:1:3: expected the dimension (3: a .node file is 3D), found '2'"},
        {"n0.node", LH_PLC_NODE, TEXT("0 3\n"), LH_ERR_PARSE,
         "n0.node:1:1: expected the number of points (an integer from 1 to 2147483646), found '0'"},
        {"hdr.smesh", LH_PLC_SMESH, TEXT("3 3 0 0 0\n"), LH_ERR_PARSE,
         "hdr.smesh:1:9: expected the end of the header line (points, dimension, attributes, markers), found '0'"},
        {"first.poly", LH_PLC_POLY, TEXT("3 3\n2 0 0 0\n"), LH_ERR_PARSE, "first.poly:2:1: expected the first point's number (0 or 1), found '2'"},
        {"gap.poly", LH_PLC_POLY, TEXT("3 3\n1 0 0 0\n3 0 0 0\n"), LH_ERR_PARSE,
         "gap.poly:3:1: expected point number 2 (numbers are consecutive), found '3'"},
        {"cut.node", LH_PLC_NODE, TEXT("3 3\n1 0 0 0\n2 1 0 0\n"), LH_ERR_PARSE,
         "cut.node:4:1: expected point number 3, found the end of the input (3 points declared)"},
        {"z.poly", LH_PLC_POLY, TEXT("3 3\n1 0 0\n"), LH_ERR_PARSE, "z.poly:2:6: expected coordinate 3 of point 1, found the end of the line"},
        {"nan.poly", LH_PLC_POLY, TEXT("3 3\n1 0 NaN 0\n"), LH_ERR_NONFINITE,
         "nan.poly:2:5: coordinate 2 of point 1 is 'NaN': NaN and infinities are not points"},
        {"mk.node", LH_PLC_NODE, TEXT("1 3 0 1\n1 0 0 0 x\n"), LH_ERR_PARSE,
         "mk.node:2:9: expected the boundary marker of point 1 (an integer), found 'x'"},
        {"more.node", LH_PLC_NODE, TEXT("1 3\n1 0 0 0\n2 0 0 0\n"), LH_ERR_PARSE,
         "more.node:3:1: expected the end of the input after 1 point, found '2'"},
        {"nofacets.poly", LH_PLC_POLY, TEXT(POLY3), LH_ERR_PARSE,
         "nofacets.poly:5:1: expected the number of facets, found the end of the input"},
        {"fm.poly", LH_PLC_POLY, TEXT(POLY3 "1 2\n"), LH_ERR_PARSE,
         "fm.poly:5:3: expected the number of facet boundary markers (0 or 1), found '2'"},
        {"few.poly", LH_PLC_POLY, TEXT(POLY3 "2 0\n1\n3 1 2 3\n"), LH_ERR_PARSE,
         "few.poly:8:1: expected the number of polygons of facet 2, found the end of the input (2 facets declared)"},
        {"p0.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n0\n"), LH_ERR_PARSE,
         "p0.poly:6:1: expected the number of polygons of facet 1 (an integer from 1 to 2147483646), found '0'"},
        {"k0.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1\n0\n"), LH_ERR_PARSE,
         "k0.poly:7:1: expected the number of vertices of polygon 1 of facet 1 (an integer from 1 to 2147483646), found '0'"},
        {"slit.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n2\n2 1 2\n1 3\n"), LH_ERR_PARSE,
         "slit.poly:6:1: facet 1 has no polygon of 3 or more vertices"},
        {"range.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1\n3 1 2 4\n"), LH_ERR_PARSE,
         "range.poly:7:7: expected vertex 3 of polygon 1 of facet 1 (a vertex number from 1 to 3), found '4'"},
        {"zero.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1\n3 0 1 2\n"), LH_ERR_PARSE,
         "zero.poly:7:3: expected vertex 1 of polygon 1 of facet 1 (a vertex number from 1 to 3), found '0'"},
        {"kcut.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1\n4 1 2 3\n"), LH_ERR_PARSE,
         "kcut.poly:7:8: expected vertex 4 of polygon 1 of facet 1 (a vertex number from 1 to 3), found the end of the line"},
        {"ptail.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1\n3 1 2 3 4\n"), LH_ERR_PARSE,
         "ptail.poly:7:9: expected the end of the line after polygon 1 of facet 1, found '4'"},
        {"polys.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n2\n3 1 2 3\n"), LH_ERR_PARSE,
         "polys.poly:8:1: expected the number of vertices of polygon 2 of facet 1, found the end of the input (2 polygons declared)"},
        {"fmk.poly", LH_PLC_POLY, TEXT(POLY3 "1 1\n1 0 b\n3 1 2 3\n"), LH_ERR_PARSE,
         "fmk.poly:6:5: expected the boundary marker of facet 1 (an integer), found 'b'"},
        {"ftail.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1 0 7\n3 1 2 3\n"), LH_ERR_PARSE,
         "ftail.poly:6:5: expected the end of the line after facet 1, found '7'"},
        {"fh.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1 1\n3 1 2 3\n1 0 inf 0\n"), LH_ERR_NONFINITE,
         "fh.poly:8:5: coordinate 2 of hole point 1 of facet 1 is 'inf': NaN and infinities are not points"},
        {"fhcut.poly", LH_PLC_POLY, TEXT(POLY3 "1 0\n1 2\n3 1 2 3\n1 0 0 0\n"), LH_ERR_PARSE,
         "fhcut.poly:9:1: expected the number of hole point 2 of facet 1, found the end of the input (2 hole points declared)"},
        {"k2.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n2 1 2\n"), LH_ERR_PARSE,
         "k2.smesh:6:1: expected the number of vertices of facet 1 (an integer from 3 to 2147483646), found '2'"},
        {"sr.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 -3\n"), LH_ERR_PARSE,
         "sr.smesh:6:7: expected vertex 3 of facet 1 (a vertex number from 1 to 3), found '-3'"},
        {"sm.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 1\n3 1 2 3 1.5\n"), LH_ERR_PARSE,
         "sm.smesh:6:9: expected the boundary marker of facet 1 (an integer), found '1.5'"},
        {"one.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n"), LH_ERR_PARSE,
         "one.smesh:6:1: expected the number of vertices of facet 1, found the end of the input (1 facet declared)"},
        {"sfew.smesh", LH_PLC_SMESH, TEXT(POLY3 "3 0\n3 1 2 3\n"), LH_ERR_PARSE,
         "sfew.smesh:7:1: expected the number of vertices of facet 2, found the end of the input (3 facets declared)"},
        {"hx.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\nholes\n"), LH_ERR_PARSE,
         "hx.smesh:7:1: expected the number of holes (an integer from 0 to 2147483646), found 'holes'"},
        {"hcut.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n2\n1 0 0 0\n"), LH_ERR_PARSE,
         "hcut.smesh:9:1: expected the number of hole 2, found the end of the input (2 holes declared)"},
        {"hn.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n1\nh 0 0 0\n"), LH_ERR_PARSE,
         "hn.smesh:8:1: expected the number of hole 1 (an integer), found 'h'"},
        {"ra.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n0\n1\n1 0 0 0\n"), LH_ERR_PARSE,
         "ra.smesh:9:8: expected the attribute of region 1, found the end of the line"},
        {"rv.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n0\n1\n1 0 0 0 1 nan\n"), LH_ERR_NONFINITE,
         "rv.smesh:9:11: the maximum volume of region 1 is 'nan': NaN and infinities are not accepted"},
        {"rt.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n0\n1\n1 0 0 0 1 2 3\n"), LH_ERR_PARSE,
         "rt.smesh:9:13: expected the end of the line after region 1, found '3'"},
        {"tail.smesh", LH_PLC_SMESH, TEXT(POLY3 "1 0\n3 1 2 3\n0\n0\n0\n"), LH_ERR_PARSE,
         "tail.smesh:9:1: expected the end of the input after 0 regions, found '0'"},
    };
    check_bad(lh_t_, cases, LH_COUNT(cases));
}

/* ---- Medit .mesh ------------------------------------------------------------------- */

#define MESH_HEAD "MeshVersionFormatted 2\nDimension 3\n"
#define MESH_V4 MESH_HEAD "Vertices\n4\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n"

LH_TEST(medit_reads)
{
    expect_plc(lh_t_, "t.mesh", LH_PLC_AUTO,
               TEXT("MeshVersionFormatted 1\n\nDimension\n3\n# points\nVertices 4\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n"
                    "Triangles\n2\n1 3 2 7\n1 2 4 8\nTetrahedra\n1\n1 2 3 4 0\nQuadrilaterals\n1\n1 2 3 4 -5\n"
                    "Corners\n2\n1\n2\nEdges\n1\n3 4 9\nTriangles\n1\n2 3 4 0\nEnd\n"),
               "p 0 0 0 m1;p 1 0 0 m2;p 0 1 0 m3;p 0 0 1 m4;f m7 @13: 0 2 1;f m8 @14: 0 1 3;f m-5 @20: 0 1 2 3;"
               "f m0 @30: 1 2 3;s 2 3 m9;first 1");
    expect_plc(lh_t_, "noend.mesh", LH_PLC_MEDIT, TEXT(MESH_V4), "p 0 0 0 m1;p 1 0 0 m2;p 0 1 0 m3;p 0 0 1 m4;first 1");
}

LH_TEST(medit_errors)
{
    static const bad_case cases[] = {
        {"e.mesh", LH_PLC_MEDIT, TEXT(""), LH_ERR_PARSE, "e.mesh:1:1: expected 'MeshVersionFormatted', found the end of the input"},
        {"lc.mesh", LH_PLC_MEDIT, TEXT("meshversionformatted 1\n"), LH_ERR_PARSE,
         "lc.mesh:1:1: expected 'MeshVersionFormatted', found 'meshversionformatted'"},
        {"v9.mesh", LH_PLC_MEDIT, TEXT("MeshVersionFormatted 9\n"), LH_ERR_PARSE,
         "v9.mesh:1:22: expected the mesh version (an integer from 1 to 4), found '9'"},
        {"d2.mesh", LH_PLC_MEDIT, TEXT("MeshVersionFormatted 1\nDimension 2\n"), LH_ERR_DIMENSION,
         "d2.mesh:2:11: expected the dimension (3: a PLC is 3D), found '2'"},
        {"nov.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "End\n"), LH_ERR_PARSE, "nov.mesh:3:1: expected the Vertices section, found 'End'"},
        {"v0.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "Vertices 0\n"), LH_ERR_PARSE,
         "v0.mesh:3:10: a mesh needs vertices: Vertices 0"},
        {"tb.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "Triangles 1\n1 2 3 0\n"), LH_ERR_PARSE, "tb.mesh:3:1: Triangles before Vertices"},
        {"vv.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Vertices 0\n"), LH_ERR_PARSE, "vv.mesh:9:1: a second Vertices section"},
        {"vcut.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "Vertices\n3\n0 0 0 0\n"), LH_ERR_PARSE,
         "vcut.mesh:6:1: expected coordinate 1 of vertex 2, found the end of the input (3 Vertices declared)"},
        {"vnan.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "Vertices\n1\n0 -nan 0 0\n"), LH_ERR_NONFINITE,
         "vnan.mesh:5:3: coordinate 2 of vertex 1 is '-nan': NaN and infinities are not points"},
        {"vref.mesh", LH_PLC_MEDIT, TEXT(MESH_HEAD "Vertices\n1\n0 0 0\n"), LH_ERR_PARSE,
         "vref.mesh:5:6: expected the reference of vertex 1 (an integer), found the end of the line"},
        {"trange.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Triangles\n1\n1 2 5 0\n"), LH_ERR_PARSE,
         "trange.mesh:11:5: expected vertex 3 of triangle 1 (a vertex number from 1 to 4), found '5'"},
        {"t0.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Triangles\n1\n0 1 2 0\n"), LH_ERR_PARSE,
         "t0.mesh:11:1: expected vertex 1 of triangle 1 (a vertex number from 1 to 4), found '0'"},
        {"tcut.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Triangles\n2\n1 2 3 0\n"), LH_ERR_PARSE,
         "tcut.mesh:12:1: expected vertex 1 of triangle 2, found the end of the input (2 Triangles declared)"},
        {"t2.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Triangles\n1\n1 2\n"), LH_ERR_PARSE,
         "t2.mesh:11:4: expected vertex 3 of triangle 1 (a vertex number from 1 to 4), found the end of the line"},
        {"tx.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Triangles\n1\n1 2 3 0 0\n"), LH_ERR_PARSE,
         "tx.mesh:11:9: expected the end of the line after triangle 1, found '0'"},
        {"ecount.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Edges\nmany\n"), LH_ERR_PARSE,
         "ecount.mesh:10:1: expected the number of Edges (an integer from 0 to 2147483646), found 'many'"},
        {"skip.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "Tetrahedra\n2\n1 2 3 4 0\n"), LH_ERR_PARSE,
         "skip.mesh:12:1: expected line 2 of Tetrahedra, found the end of the input (2 Tetrahedra declared)"},
        {"kw.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "7\n"), LH_ERR_PARSE,
         "kw.mesh:9:1: expected a keyword (Vertices, Triangles, Quadrilaterals, Edges, ..., End), found '7'"},
        {"after.mesh", LH_PLC_MEDIT, TEXT(MESH_V4 "End\nVertices\n"), LH_ERR_PARSE,
         "after.mesh:10:1: expected the end of the input after End, found 'Vertices'"},
    };
    check_bad(lh_t_, cases, LH_COUNT(cases));
}

/* ---- Wavefront .obj ------------------------------------------------------------------ */

#define OBJ_V4 "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"

LH_TEST(obj_reads)
{
    expect_plc(lh_t_, "t.obj", LH_PLC_AUTO,
               TEXT("# comment\nmtllib t.mtl\no tet\nv 0 0 0\nv 1 0 0 1.0\nv 0 1 0 0.5 0.5 0.5\nvt 0 0\nvn 0 0 1\n"
                    "g side\ns off\nusemtl red\nf 1 3 2\nf 1/1 2/1 -1/1\nv 0 0 1 # late\nf 1//1 4//1 3//1\n"
                    "f -3/1/1 -2/1/1 -1/1/1\nl 1 2 3\nl -1 1\n"),
               "p 0 0 0 m0;p 1 0 0 m0;p 0 1 0 m0;p 0 0 1 m0;f m0 @12: 0 2 1;f m0 @13: 0 1 2;f m0 @15: 0 3 2;"
               "f m0 @16: 1 2 3;s 0 1 m0;s 1 2 m0;s 3 0 m0;first 1");
    expect_plc(lh_t_, "quad.obj", LH_PLC_OBJ, TEXT("v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4"),
               "p 0 0 0 m0;p 1 0 0 m0;p 1 1 0 m0;p 0 1 0 m0;f m0 @5: 0 1 2 3;first 1");
}

LH_TEST(obj_errors)
{
    static const bad_case cases[] = {
        {"e.obj", LH_PLC_OBJ, TEXT("# nothing\n"), LH_ERR_PARSE, "e.obj:2:1: expected a vertex ('v x y z'), found the end of the input"},
        {"kw.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "x 1 2 3\n"), LH_ERR_PARSE,
         "kw.obj:5:1: expected an OBJ statement (v, f, l, vt, vn, g, o, s, usemtl, mtllib, ...), found 'x'"},
        {"bin.obj", LH_PLC_OBJ, TEXT("v 0 0 0\n\x01\x02"), LH_ERR_PARSE,
         "bin.obj:2:1: expected an OBJ statement (v, f, l, vt, vn, g, o, s, usemtl, mtllib, ...), found a non-text byte 0x01"},
        {"vz.obj", LH_PLC_OBJ, TEXT("v 0 0\n"), LH_ERR_PARSE, "vz.obj:1:6: expected coordinate 3 of vertex 1, found the end of the line"},
        {"vnan.obj", LH_PLC_OBJ, TEXT("v 0 0 nan\n"), LH_ERR_NONFINITE,
         "vnan.obj:1:7: coordinate 3 of vertex 1 is 'nan': NaN and infinities are not points"},
        {"vx.obj", LH_PLC_OBJ, TEXT("v 0 0 0 1 2 3 4 5\n"), LH_ERR_PARSE,
         "vx.obj:1:17: expected the end of the line after vertex 1, found '5'"},
        {"vy.obj", LH_PLC_OBJ, TEXT("v 0 0 0 w\n"), LH_ERR_PARSE,
         "vy.obj:1:9: expected the end of the line after vertex 1, found 'w'"},
        {"f2.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2\n"), LH_ERR_PARSE, "f2.obj:5:1: face 1 has 2 vertices: a facet needs 3 or more"},
        {"f0v.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f\n"), LH_ERR_PARSE, "f0v.obj:5:1: face 1 has 0 vertices: a facet needs 3 or more"},
        {"l1.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "l 1\n"), LH_ERR_PARSE, "l1.obj:5:1: polyline 1 has 1 vertex: a polyline needs 2 or more"},
        {"f5.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2 5\n"), LH_ERR_PARSE,
         "f5.obj:5:7: expected vertex 3 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '5'"},
        {"f0.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 0 1 2\n"), LH_ERR_PARSE,
         "f0.obj:5:3: expected vertex 1 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '0'"},
        {"fneg.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2 -5\n"), LH_ERR_PARSE,
         "fneg.obj:5:7: expected vertex 3 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '-5'"},
        {"early.obj", LH_PLC_OBJ, TEXT("f 1 2 3\n"), LH_ERR_PARSE,
         "early.obj:1:3: expected vertex 1 of face 1 (a vertex number; no vertex is defined yet), found '1'"},
        {"slash.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1/ 2 3\n"), LH_ERR_PARSE,
         "slash.obj:5:3: expected vertex 1 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '1/'"},
        {"s3.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2/1/1/1 3\n"), LH_ERR_PARSE,
         "s3.obj:5:5: expected vertex 2 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '2/1/1/1'"},
        {"st.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2/a 3\n"), LH_ERR_PARSE,
         "st.obj:5:5: expected vertex 2 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '2/a'"},
        {"fx.obj", LH_PLC_OBJ, TEXT(OBJ_V4 "f 1 2 3 4.5\n"), LH_ERR_PARSE,
         "fx.obj:5:9: expected vertex 4 of face 1 (a vertex number from 1 to 4 or from -4 to -1), found '4.5'"},
    };
    check_bad(lh_t_, cases, LH_COUNT(cases));
}

/* ---- every format ----------------------------------------------------------------- */

LH_TEST(every_allocation_failure)
{
    static const alloc_input inputs[] = {
        {"tet.off", LH_PLC_OFF, OFF_TET},
        {"cube.poly", LH_PLC_POLY, CUBE_NODES "2 1\n3 1 1\n4 1 2 3 4\n2 1 3\n1 7\n1 0.5 0.5 0\n1\n4 5 6 7 8\n"
                                 "1\n1 0.5 0.5 0.5\n1\n1 0.1 0.1 0.1 7 0.25\n"},
        {"t.mesh", LH_PLC_MEDIT, MESH_V4 "Triangles 1\n1 2 3 0\nEdges 1\n1 4 0\nQuadrilaterals 1\n1 2 3 4 0\n"},
        {"t.obj", LH_PLC_OBJ, OBJ_V4 "f 1 2 3 4\nl 1 2 3\nf -1 -2 -3\n"},
        {"cube.smesh", LH_PLC_SMESH, CUBE_NODES "2 1\n4 1 2 3 4 5\n4 5 6 7 8 6\n0\n"},
    };
    for (size_t i = 0; i < LH_COUNT(inputs) && !LH_FAILED(); i++)
        LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, read_with, &inputs[i]), 3);
}

#ifdef LH_TEST_DATA_DIR
LH_TEST(real_files)
{
    expect_file(lh_t_, "star.off", 14, 24, 24, 72, 0);
    expect_file(lh_t_, "spike-1-7.smesh", 8, 8, 8, 28, 0);
    expect_file(lh_t_, "star.1.mesh", 14, 48, 48, 144, 36);
    expect_file(lh_t_, "star.obj", 14, 24, 24, 72, 0);
}
#endif

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(off_reads), LH_CASE(off_errors), LH_CASE(poly_reads), LH_CASE(poly_take_points),
        LH_CASE(poly_errors), LH_CASE(medit_reads), LH_CASE(medit_errors),
        LH_CASE(obj_reads), LH_CASE(obj_errors), LH_CASE(every_allocation_failure),
#ifdef LH_TEST_DATA_DIR
        LH_CASE(real_files),
#endif
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
