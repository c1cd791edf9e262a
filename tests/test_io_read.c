/* test_io_read.c — lh_points_read: every diagnostic (status and exact one-line message,
 * line and column included), good inputs of each format, the choice of format,
 * allocation failures, declared counts that are lies, read errors. */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Input text with its length, so that NUL bytes can be part of it. */
#define TEXT(s) s, sizeof(s) - 1

/* LH_READ_MAX_POINTS as the messages show it, and the count one above it. */
#if LH_INDEX_BITS == 64
#define MAX_POINTS "9223372036854775806"
#define ABOVE_MAX "9223372036854775807"
#else
#define MAX_POINTS "2147483646"
#define ABOVE_MAX "2147483647"
#endif


static lh_status read_text(const char *name, const char *text, size_t len, lh_format fmt,
                           const lh_allocator *a, lh_points *p, lh_error *err)
{
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, name, fmt, a, p, err);
    fclose(f);
    return st;
}

typedef struct bad_case {
    lh_format fmt;
    const char *name;
    const char *text;
    size_t len;
    lh_status status;
    const char *msg;
} bad_case;

static void check_bad(lh_test_state *lh_t_, const bad_case *c)
{
    lh_error err;
    lh_points p;
    lh_test_counter k = {0, 0, 0};
    lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &k};
    lh_status st = read_text(c->name, c->text, c->len, c->fmt, &a, &p, &err);
    LH_EXPECT_EQ_INT(st, c->status);
    LH_EXPECT_EQ_INT(err.status, c->status);
    LH_EXPECT_STREQ(err.message, c->msg);
    char place[300]; /* the place in the message is the place in err */
    snprintf(place, sizeof place, "%s:%zu:%zu: ", c->name ? c->name : "<input>", err.line, err.column);
    LH_EXPECT_TRUE(err.line > 0 && err.column > 0 && strncmp(c->msg, place, strlen(place)) == 0);
    LH_EXPECT_TRUE(p.xyz == NULL && p.n == 0 && p.d == 0);
    LH_EXPECT_EQ_INT(k.live, 0);
    if (LH_FAILED()) LH_NOTE("case %s", c->name);
}

static void check_bad_cases(lh_test_state *lh_t_, const bad_case *c, size_t count)
{
    for (size_t i = 0; i < count && !LH_FAILED(); i++) check_bad(lh_t_, &c[i]);
}

#define Q LH_FORMAT_QHULL
#define N LH_FORMAT_NODE
#define C LH_FORMAT_COLUMNS
#define A LH_FORMAT_AUTO

/* The cases of tests/cli/bad_input.sh, whose CLI messages these must stay. */
LH_TEST(qhull_cli_messages)
{
    static const bad_case cases[] = {
        {A, "empty", TEXT(""), LH_ERR_PARSE, "empty:1:1: expected the dimension, found the end of the input"},
        {A, "nan", TEXT("2\n3\n0 0\n1 nan\n0 1\n"), LH_ERR_NONFINITE,
         "nan:4:3: coordinate 2 of point 2 is 'nan': NaN and infinities are not points"},
        {A, "inf", TEXT("2\n3\n-inf 0\n1 0\n0 1\n"), LH_ERR_NONFINITE,
         "inf:3:1: coordinate 1 of point 1 is '-inf': NaN and infinities are not points"},
        {A, "dim1", TEXT("1\n3\n0\n1\n2\n"), LH_ERR_DIMENSION, "dim1:1:1: expected the dimension (an integer from 2 to 8), found '1'"},
        {A, "dim9", TEXT("9\n3\n"), LH_ERR_DIMENSION, "dim9:1:1: expected the dimension (an integer from 2 to 8), found '9'"},
        {A, "truncated", TEXT("2\n3\n0 0\n1 0\n"), LH_ERR_PARSE,
         "truncated:5:1: expected coordinate 1 of point 3, found the end of the input (3 points declared)"},
        {A, "half_point", TEXT("2\n3\n0 0\n1 0\n0\n"), LH_ERR_PARSE,
         "half_point:6:1: expected coordinate 2 of point 3, found the end of the input (3 points declared)"},
        {A, "extra", TEXT("2\n3\n0 0\n1 0\n0 1\n7\n"), LH_ERR_PARSE,
         "extra:6:1: expected the end of the input after 3 points of dimension 2, found '7'"},
        {A, "text", TEXT("2\n3\n0 abc\n1 0\n0 1\n"), LH_ERR_PARSE,
         "text:3:3: expected coordinate 2 of point 1 (a number), found 'abc'"},
        {A, "count_text", TEXT("2\nmany\n0 0\n"), LH_ERR_PARSE,
         "count_text:2:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found 'many'"},
        {A, "huge_count", TEXT("2\n10000000000000000000\n0 0\n"), LH_ERR_TOO_LARGE,
         "huge_count:2:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found '10000000000000000000'"},
        {A, "binary", TEXT("\x7f" "ELF\x02\x01\x01\x00\xff\xfe"), LH_ERR_PARSE,
         "binary:1:1: expected the dimension, found a non-text byte 0x7f"},
        {A, "zero_count", TEXT("2\n0\n"), LH_ERR_PARSE,
         "zero_count:2:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found '0'"},
    };
    check_bad_cases(lh_t_, cases, LH_COUNT(cases));
}

LH_TEST(qhull_header_errors)
{
    static const bad_case cases[] = {
        {Q, "c", TEXT("# only a comment\n\n  \n"), LH_ERR_PARSE, "c:4:1: expected the dimension, found the end of the input"},
        {Q, "t", TEXT("a title and nothing else\n"), LH_ERR_PARSE, "t:2:1: expected the dimension, found the end of the input"},
        {Q, "f", TEXT("2.5 3\n"), LH_ERR_PARSE, "f:1:1: expected the dimension (an integer from 2 to 8), found '2.5'"},
        {Q, "s", TEXT("-x\n"), LH_ERR_PARSE, "s:1:1: expected the dimension (an integer from 2 to 8), found '-x'"},
        {Q, "z", TEXT("  0 3\n"), LH_ERR_DIMENSION, "z:1:3: expected the dimension (an integer from 2 to 8), found '0'"},
        {Q, "neg", TEXT("-3\n"), LH_ERR_DIMENSION, "neg:1:1: expected the dimension (an integer from 2 to 8), found '-3'"},
        {Q, "big", TEXT("99999999999999999999999\n"), LH_ERR_DIMENSION,
         "big:1:1: expected the dimension (an integer from 2 to 8), found '99999999999999999999...'"},
        {Q, "nocount", TEXT("3 rbox c\n"), LH_ERR_PARSE, "nocount:2:1: expected the number of points, found the end of the input"},
        {Q, "negcount", TEXT("3 -4\n"), LH_ERR_PARSE,
         "negcount:1:3: expected the number of points (an integer from 1 to " MAX_POINTS "), found '-4'"},
        {Q, "fcount", TEXT("3\n4.0\n"), LH_ERR_PARSE,
         "fcount:2:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found '4.0'"},
        {Q, "maxcount", TEXT("3\n" ABOVE_MAX "\n"), LH_ERR_TOO_LARGE,
         "maxcount:2:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found '" ABOVE_MAX "'"},
        {Q, "nulc", TEXT("# a\0b\n2 1\n0 0\n"), LH_ERR_PARSE, "nulc:1:4: expected the dimension, found a NUL byte"},
        {Q, "bytecount", TEXT("2\n\x01\n"), LH_ERR_PARSE, "bytecount:2:1: expected the number of points, found a non-text byte 0x01"},
        {Q, "utf16", TEXT("\xff\xfe" "2\0"), LH_ERR_PARSE, "utf16:1:1: expected the dimension, found a non-text byte 0xff"},
    };
    check_bad_cases(lh_t_, cases, LH_COUNT(cases));
}

LH_TEST(qhull_coordinate_errors)
{
    static const bad_case cases[] = {
        {Q, "few", TEXT("2 3\n0 0\n1 1\n"), LH_ERR_PARSE,
         "few:4:1: expected coordinate 1 of point 3, found the end of the input (3 points declared)"},
        {Q, "one", TEXT("2 1\n0"), LH_ERR_PARSE,
         "one:2:2: expected coordinate 2 of point 1, found the end of the input (1 point declared)"},
        {Q, "more", TEXT("2 1\n0 0 # fine\n\n  5 # not fine\n"), LH_ERR_PARSE,
         "more:4:3: expected the end of the input after 1 point of dimension 2, found '5'"},
        {Q, "over", TEXT("2 1\n1e999 0\n"), LH_ERR_NONFINITE, "over:2:1: coordinate 1 of point 1 is '1e999', which overflows a double"},
        {Q, "inf", TEXT("2 1\n0 Infinity\n"), LH_ERR_NONFINITE,
         "inf:2:3: coordinate 2 of point 1 is 'Infinity': NaN and infinities are not points"},
        {Q, "nanp", TEXT("3 1\n0 0 -nan(0x1)\n"), LH_ERR_NONFINITE,
         "nanp:2:5: coordinate 3 of point 1 is '-nan(0x1)': NaN and infinities are not points"},
        {Q, "comma", TEXT("2 1\n0,0\n"), LH_ERR_PARSE, "comma:2:1: expected coordinate 1 of point 1 (a number), found '0,0'"},
        {Q, "nul", TEXT("2 1\n0\0 0\n"), LH_ERR_PARSE, "nul:2:2: expected coordinate 2 of point 1 (a number), found a NUL byte"},
        {Q, "ctl", TEXT("2 1\n0 \x1b[0m\n"), LH_ERR_PARSE,
         "ctl:2:3: expected coordinate 2 of point 1 (a number), found a non-text byte 0x1b"},
        {Q, "high", TEXT("2 1\n0 1\xc2\xb5\n"), LH_ERR_PARSE,
         "high:2:4: expected the end of the input after 1 point of dimension 2, found a non-text byte 0xc2"},
        {Q, "crlf", TEXT("2\r\n3\r\n0 0\r\n1 x\r\n"), LH_ERR_PARSE, "crlf:4:3: expected coordinate 2 of point 2 (a number), found 'x'"},
        {Q, "tabs", TEXT("2\t2\n\t0\t0\n\t1\tq\n"), LH_ERR_PARSE, "tabs:3:4: expected coordinate 2 of point 2 (a number), found 'q'"},
    };
    check_bad_cases(lh_t_, cases, LH_COUNT(cases));
}

LH_TEST(long_tokens)
{
    char text[600];
    lh_error err;
    memcpy(text, "2 1\n0 ", 6);
    memset(text + 6, '1', 300);
    memcpy(text + 306, "\n", 2);
    lh_points p;
    LH_EXPECT_EQ_INT(read_text("long", text, strlen(text), Q, NULL, &p, &err), LH_ERR_PARSE);
    LH_EXPECT_STREQ(err.message, "long:2:3: expected coordinate 2 of point 1 (a number), found a token of more than 255 bytes");
    /* 255 bytes is still a token: a number with many digits. */
    memset(text + 6, '0', 254);
    text[260] = '1';
    memcpy(text + 261, "\n", 2);
    LH_ASSERT_EQ_INT(read_text("ok", text, strlen(text), Q, NULL, &p, &err), LH_OK);
    LH_EXPECT_EQ_DBL(p.xyz[1], 1.0);
    LH_EXPECT_STREQ(err.message, "");
    lh_points_free(&p);
}

LH_TEST(node_errors)
{
    static const bad_case cases[] = {
        {N, "e.node", TEXT("# nothing\n"), LH_ERR_PARSE, "e.node:2:1: expected the number of points, found the end of the input"},
        {N, "d.node", TEXT("5\n"), LH_ERR_PARSE, "d.node:1:2: expected the dimension, found the end of the line"},
        {N, "d9.node", TEXT("5 9 0 0\n"), LH_ERR_DIMENSION, "d9.node:1:3: expected the dimension (an integer from 2 to 8), found '9'"},
        {N, "a.node", TEXT("3 2 x\n"), LH_ERR_PARSE,
         "a.node:1:5: expected the number of attributes (an integer from 0 to 1000), found 'x'"},
        {N, "m.node", TEXT("3 2 0 2\n"), LH_ERR_PARSE, "m.node:1:7: expected the number of boundary markers (0 or 1), found '2'"},
        {N, "h.node", TEXT("3 2 0 0 7\n"), LH_ERR_PARSE,
         "h.node:1:9: expected the end of the header line (points, dimension, attributes, markers), found '7'"},
        {N, "f.node", TEXT("2 2 0 0\n2 0 0\n3 1 1\n"), LH_ERR_PARSE,
         "f.node:2:1: expected the first point's number (0 or 1), found '2'"},
        {N, "s.node", TEXT("3 2 0 0\n1 0 0\n3 1 1\n"), LH_ERR_PARSE,
         "s.node:3:1: expected point number 2 (numbers are consecutive), found '3'"},
        {N, "c.node", TEXT("2 2 0 0\n1 0\n2 1 1\n"), LH_ERR_PARSE, "c.node:2:4: expected coordinate 2 of point 1, found the end of the line"},
        {N, "crlf.node", TEXT("2 2 0 0\r\n0 0\r\n1 1 1\r\n"), LH_ERR_PARSE,
         "crlf.node:2:4: expected coordinate 2 of point 0, found the end of the line"},
        {N, "t.node", TEXT("2 2 0 0\n1 0 y\n"), LH_ERR_PARSE, "t.node:2:5: expected coordinate 2 of point 1 (a number), found 'y'"},
        {N, "mk.node", TEXT("2 2 0 1\n1 0 0\n"), LH_ERR_PARSE,
         "mk.node:2:6: expected the boundary marker of point 1 (an integer), found the end of the line"},
        {N, "mf.node", TEXT("2 2 0 1\n1 0 0 0.5\n"), LH_ERR_PARSE,
         "mf.node:2:7: expected the boundary marker of point 1 (an integer), found '0.5'"},
        {N, "x.node", TEXT("2 2 0 0\n1 0 0 5\n"), LH_ERR_PARSE, "x.node:2:7: expected the end of the line after point 1, found '5'"},
        {N, "few.node", TEXT("3 2 0 0\n1 0 0\n2 1 1\n"), LH_ERR_PARSE,
         "few.node:4:1: expected point number 3, found the end of the input (3 points declared)"},
        {N, "more.node", TEXT("1 2 0 0\n1 0 0\n2 1 1\n"), LH_ERR_PARSE,
         "more.node:3:1: expected the end of the input after 1 point, found '2'"},
        {N, "na.node", TEXT("1 2 1 0\n1 0 0 nan\n"), LH_ERR_NONFINITE,
         "na.node:2:7: attribute 1 of point 1 is 'nan': NaN and infinities are not accepted"},
        {N, "nc.node", TEXT("1 3 0 0\n1 0 inf 0\n"), LH_ERR_NONFINITE,
         "nc.node:2:5: coordinate 2 of point 1 is 'inf': NaN and infinities are not points"},
        {N, "big.node", TEXT("10000000000000000000 2 0 0\n"), LH_ERR_TOO_LARGE,
         "big.node:1:1: expected the number of points (an integer from 1 to " MAX_POINTS "), found '10000000000000000000'"},
    };
    check_bad_cases(lh_t_, cases, LH_COUNT(cases));
}

LH_TEST(columns_errors)
{
    static const bad_case cases[] = {
        {C, "e", TEXT(""), LH_ERR_PARSE, "e:1:1: expected a line of coordinates, found the end of the input"},
        {C, "short", TEXT("1 2 3\n\n4 5\n"), LH_ERR_PARSE,
         "short:3:4: expected coordinate 3 of point 2 (3 per line, as on line 1), found the end of the line"},
        {C, "long", TEXT("# c\n1 2\n3 4 5\n"), LH_ERR_PARSE,
         "long:3:5: expected the end of the line after 2 coordinates (as on line 2), found '5'"},
        {C, "one", TEXT("1\n2\n"), LH_ERR_DIMENSION, "one:1:2: expected coordinate 2 of point 1 (2 to 8 per line), found the end of the line"},
        {C, "nine", TEXT("1 2 3 4 5 6 7 8 9\n"), LH_ERR_DIMENSION,
         "nine:1:17: expected the end of the line after 8 coordinates (8 is the largest dimension), found '9'"},
        {C, "e.csv", TEXT("1,,2\n"), LH_ERR_PARSE, "e.csv:1:3: expected coordinate 2 of point 1 (a number), found ','"},
        {C, "lead.csv", TEXT("1,2\n,1,2\n"), LH_ERR_PARSE, "lead.csv:2:1: expected coordinate 1 of point 2 (a number), found ','"},
        {C, "t.csv", TEXT("1,2,\n"), LH_ERR_PARSE, "t.csv:1:5: expected coordinate 3 of point 1, found the end of the line"},
        {C, "h.csv", TEXT("x,y\r\n"), LH_ERR_PARSE, "h.csv:2:1: expected a line of coordinates, found the end of the input"},
        {C, "h2.csv", TEXT("x,y\n1,2\na,b\n"), LH_ERR_PARSE, "h2.csv:3:1: expected coordinate 1 of point 2 (a number), found 'a'"},
        {C, "n.csv", TEXT("x,y\n1,2\n3, NaN\n"), LH_ERR_NONFINITE,
         "n.csv:3:4: coordinate 2 of point 2 is 'NaN': NaN and infinities are not points"},
        {C, "crlf.csv", TEXT("1,2,3\r\n4,5\r\n"), LH_ERR_PARSE,
         "crlf.csv:2:4: expected coordinate 3 of point 2 (3 per line, as on line 1), found the end of the line"},
        {C, "nul", TEXT("1 2\n3\0 4\n"), LH_ERR_PARSE, "nul:2:2: expected coordinate 2 of point 2 (a number), found a NUL byte"},
    };
    check_bad_cases(lh_t_, cases, LH_COUNT(cases));
}

/* A count far beyond the data must not be allocated up front. */
LH_TEST(declared_count_is_not_trusted)
{
    lh_test_biggest b;
    lh_allocator a = lh_test_biggest_allocator(&b);
    lh_error err;
    lh_points p;
    LH_EXPECT_EQ_INT(read_text("lie", TEXT("8 2000000000\n0 0 0 0 0 0 0 0\n"), Q, &a, &p, &err), LH_ERR_PARSE);
    LH_EXPECT_STREQ(err.message, "lie:3:1: expected coordinate 1 of point 2, found the end of the input (2000000000 points declared)");
    LH_EXPECT_LE_U64(b.largest, 1u << 20);
    LH_EXPECT_EQ_INT(b.live, 0);
    LH_EXPECT_EQ_INT(read_text("lie.node", TEXT("2000000000 3 2 1\n1 0 0 0 1 2 3\n"), N, &a, &p, &err), LH_ERR_PARSE);
    LH_EXPECT_STREQ(err.message, "lie.node:3:1: expected point number 2, found the end of the input (2000000000 points declared)");
    LH_EXPECT_LE_U64(b.largest, 1u << 20);
    LH_EXPECT_EQ_INT(b.live, 0);
}

static void expect_points(lh_test_state *lh_t_, const lh_points *p, int d, size_t n, const double *xyz)
{
    LH_ASSERT_EQ_INT(p->d, d);
    LH_ASSERT_EQ_U64(p->n, n);
    for (size_t i = 0; i < n * (size_t)d; i++) LH_EXPECT_EQ_DBL(p->xyz[i], xyz[i]);
}

LH_TEST(qhull_good)
{
    static const double tri[] = {0, 0, 1, 0, 0, 1};
    static const char *inputs[] = {
        "2\n3\n0 0\n1 0\n0 1\n",
        "2 3\n0 0 1 0 0 1",
        "2 rbox 3 D2\n3\n0 0\n1 0\n0 1\n",
        "2 3 a comment after the count\n0 0\n1 0\n0 1\n",
        "2\n3 a comment after the count\n0 0\n1 0\n0 1\n",
        "points from somewhere\n\n# and a comment\n2 3\n0 0\n1 0\n0 1\n",
        "# title\r\n2 # dim\r\n3\r\n0 0 # a\r\n1 0\r\n\r\n0 1\r\n",
        ("\xEF\xBB\xBF" "2 3\n+0 -0\n0x1p0 0\n0 1e0"),
        "  2\t3\n\t0\t0\n1\v0\f0 1",
    };
    for (size_t i = 0; i < LH_COUNT(inputs) && !LH_FAILED(); i++) {
        lh_points p;
        lh_error err;
        LH_EXPECT_EQ_INT(read_text("good", inputs[i], strlen(inputs[i]), A, NULL, &p, &err), LH_OK);
        LH_EXPECT_STREQ(err.message, "");
        LH_EXPECT_EQ_INT(p.format, LH_FORMAT_QHULL);
        LH_EXPECT_TRUE(p.attr == NULL && p.marker == NULL && p.attr_count == 0 && p.first_index == 0);
        expect_points(lh_t_, &p, 2, 3, tri);
        lh_points_free(&p);
        if (LH_FAILED()) LH_NOTE("input %zu", i);
    }
}

#ifdef LH_TEST_DATA_DIR
/* Real rbox output (qhull 2020.2: "rbox 10 D3 t1"), committed in tests/data/io. */
LH_TEST(rbox_file)
{
    FILE *f = fopen(LH_TEST_DATA_DIR "/io/rbox_10_D3.txt", "rb");
    LH_ASSERT_TRUE(f != NULL);
    lh_points p;
    lh_error err;
    lh_status st = lh_points_read(f, "rbox_10_D3.txt", A, NULL, &p, &err);
    fclose(f);
    LH_ASSERT_EQ_INT(st, LH_OK);
    LH_EXPECT_EQ_INT(p.format, LH_FORMAT_QHULL);
    LH_EXPECT_EQ_INT(p.d, 3);
    LH_EXPECT_EQ_U64(p.n, 10);
    for (size_t i = 0; i < 30; i++) LH_EXPECT_TRUE(fabs(p.xyz[i]) <= 0.5);
    lh_points_free(&p);
}
#endif

LH_TEST(node_good)
{
    static const char text[] = "# a .node with attributes and markers\n"
                               "3 2 2 1 # n d attributes markers\n"
                               "1 0 0 0.5 1.5 7\r\n"
                               "2 1 0 2 3 -1\n\n"
                               "  3 0 1 4 5 0 # last\n";
    static const double xyz[] = {0, 0, 1, 0, 0, 1}, attr[] = {0.5, 1.5, 2, 3, 4, 5};
    static const lh_index marker[] = {7, -1, 0};
    lh_points p;
    lh_error err;
    LH_ASSERT_EQ_INT(read_text("good.node", TEXT(text), A, NULL, &p, &err), LH_OK);
    LH_EXPECT_EQ_INT(p.format, LH_FORMAT_NODE);
    LH_EXPECT_EQ_INT(p.first_index, 1);
    expect_points(lh_t_, &p, 2, 3, xyz);
    LH_ASSERT_EQ_INT(p.attr_count, 2);
    LH_ASSERT_TRUE(p.attr != NULL && p.marker != NULL);
    for (int i = 0; i < 6; i++) LH_EXPECT_EQ_DBL(p.attr[i], attr[i]);
    for (int i = 0; i < 3; i++) LH_EXPECT_EQ_INT(p.marker[i], marker[i]);
    lh_points_free(&p);
    /* TetGen style, 0-based, header fields omitted. */
    static const double xyz3[] = {1, 2, 3, 4, 5, 6};
    LH_ASSERT_EQ_INT(read_text("tet.node", TEXT("2 3\n0 1 2 3\n1 4 5 6"), A, NULL, &p, &err), LH_OK);
    LH_EXPECT_EQ_INT(p.first_index, 0);
    LH_EXPECT_TRUE(p.attr == NULL && p.marker == NULL);
    expect_points(lh_t_, &p, 3, 2, xyz3);
    lh_points_free(&p);
}

LH_TEST(columns_good)
{
    static const double xyz[] = {1, 2, 3, 4, 5, 6};
    static const char *inputs[] = {
        "1 2 3\n4 5 6\n",
        "\xEF\xBB\xBFx,y,z\r\n1,2,3\r\n4 , 5 ,\t6\r\n",
        "# comment\n\"x\";\"y\";\"z\" a quoted header\n1\t2\t3   # trailing\n\n4 5 6",
        "1,2 3\n4 5,6\n",
    };
    for (size_t i = 0; i < LH_COUNT(inputs) && !LH_FAILED(); i++) {
        lh_points p;
        lh_error err;
        LH_EXPECT_EQ_INT(read_text("cols.csv", inputs[i], strlen(inputs[i]), A, NULL, &p, &err), LH_OK);
        LH_EXPECT_EQ_INT(p.format, LH_FORMAT_COLUMNS);
        expect_points(lh_t_, &p, 3, 2, xyz);
        lh_points_free(&p);
        if (LH_FAILED()) LH_NOTE("input %zu: %s", i, err.message);
    }
}

LH_TEST(auto_detection)
{
    static const struct {
        const char *name, *text;
        lh_format want;
    } cases[] = {
        {"a.node", "2 2\n1 0 0\n2 1 1\n", N},
        {"a.NODE", "2 2\n1 0 0\n2 1 1\n", N},
        {"a.CSV", "2 2\n1 0\n", C},
        {"x.txt", "3 rbox 2 D3\n2\n0 0 0\n1 1 1\n", Q},
        {"x.txt", "1.5 2.5\n3 4\n", C},
        {"x", "2 3\n0 0\n1 0\n0 1\n", Q},
        {"x", "2 3\n4 5\n6 7\n", C},     /* whole input: two columns, not 3 points */
        {"x", "3 2\n1 2\n3 4\n5 6\n", Q}, /* 6 numbers: Qhull's 2 points of 3D */
        {"x", "x y\n1 2\n3 4\n", C},
        {"x", "a title\n2 2\n0 0\n1 1\n", Q},
        {"x", "10 0\n10 0.01\n10 0.02\n", C},
        {"x", "", Q},
        {"x", "\n# c\n", Q},
        {"x", "1,2\n3,4\n", C},
        {"x", "# c\n2\n2\n0 0\n1 1\n", Q},
        {"x", "1 2 3\n4 5 6\n", C},
        {"x", "2 2 # d n\n0 0\n1 1\n", Q},
    };
    for (size_t i = 0; i < LH_COUNT(cases) && !LH_FAILED(); i++) {
        lh_points p;
        lh_error err;
        lh_status st = read_text(cases[i].name, cases[i].text, strlen(cases[i].text), A, NULL, &p, &err);
        LH_EXPECT_EQ_INT(st == LH_OK ? p.format : cases[i].want, cases[i].want);
        LH_EXPECT_TRUE(st == LH_OK || !strcmp(cases[i].text, "") || !strcmp(cases[i].text, "\n# c\n"));
        lh_points_free(&p);
        if (LH_FAILED()) LH_NOTE("case %zu: %s", i, err.message);
    }
}

/* n points of dimension d in Qhull's, .node's or the columns' format, past the 4 KiB
 * prefix and past the first capacity. */
static char *big_input(lh_format fmt, int d, size_t n, size_t *len)
{
    size_t cap = 64 + n * (size_t)(d * 26 + 32);
    char *s = malloc(cap), *w = s;
    if (!s) return NULL;
    if (fmt == Q) w += sprintf(w, "%d rbox-like\n%zu\n", d, n);
    if (fmt == N) w += sprintf(w, "%zu %d 1 1\n", n, d);
    if (fmt == C) w += sprintf(w, "x,y,z\n");
    for (size_t i = 0; i < n; i++) {
        if (fmt == N) w += sprintf(w, "%zu ", i + 1);
        for (int j = 0; j < d; j++) w += sprintf(w, j && fmt == C ? ",%.17g" : " %.17g", (double)i / 7 + j);
        if (fmt == N) w += sprintf(w, " %.17g %d", -(double)i, (int)i % 3);
        w += sprintf(w, "\r\n");
    }
    *len = (size_t)(w - s);
    return s;
}

LH_TEST(large_inputs)
{
    static const lh_format fmts[] = {Q, N, C};
    for (int k = 0; k < 3; k++) {
        size_t len = 0, n = 3000;
        char *s = big_input(fmts[k], 3, n, &len);
        LH_ASSERT_TRUE(s != NULL);
        lh_points p;
        lh_error err;
        lh_status st = read_text("big", s, len, fmts[k], NULL, &p, &err);
        free(s);
        LH_ASSERT_EQ_INT(st, LH_OK);
        LH_EXPECT_EQ_U64(p.n, n);
        for (size_t i = 0; i < n; i++)
            for (int j = 0; j < 3; j++) LH_EXPECT_EQ_DBL(p.xyz[3 * i + j], (double)i / 7 + j);
        if (fmts[k] == N)
            for (size_t i = 0; i < n; i++) {
                LH_EXPECT_EQ_DBL(p.attr[i], -(double)i);
                LH_EXPECT_EQ_INT(p.marker[i], (int)i % 3);
            }
        lh_points_free(&p);
    }
}

typedef struct alloc_case {
    const char *text;
    size_t len;
    lh_format fmt;
} alloc_case;

static lh_status run_read(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const alloc_case *c = user;
    lh_points p;
    lh_error err;
    lh_status st = read_text("alloc", c->text, c->len, c->fmt, a, &p, &err);
    if (st == LH_ERR_NOMEM)
        LH_EXPECT_TRUE(strstr(err.message, "alloc:") == err.message && (strstr(err.message, ": out of memory for point ") ||
                                                       !strcmp(err.message, "alloc:1:1: out of memory for the input buffer")));
    else LH_EXPECT_EQ_INT(st, LH_OK);
    lh_points_free(&p);
    return st;
}

/* The 1000-point 2D input of format fmt as c (its text malloc'ed, returned). */
static char *big_case(lh_format fmt, alloc_case *c)
{
    char *s = big_input(fmt, 2, 1000, &c->len);
    c->text = s;
    c->fmt = fmt;
    return s;
}

/* A reader's stack stays small (a caller's thread may have a small one): the
 * scanner's 16 KiB block, its read-ahead bytes and the attributes' scratch live on
 * the heap. */
LH_TEST(reading_needs_little_stack)
{
    static const lh_format fmts[] = {Q, N, C};
    for (int k = 0; k < 3; k++) {
        alloc_case c;
        char *text = big_case(fmts[k], &c);
        LH_ASSERT_TRUE(text != NULL);
        size_t used;
        LH_EXPECT_EQ_INT(lh_test_run_on_thread(lh_t_, run_read, &c, &used), LH_OK);
        LH_EXPECT_GT_INT(used, 0);
        LH_EXPECT_LE_U64(used, 12288); /* under the 16 KiB block alone; sanitizers widen frames */
        if (LH_FAILED()) LH_NOTE("format %d: %zu bytes of stack", (int)fmts[k], used);
        free(text);
    }
}

LH_TEST(every_allocation_failure)
{
    static const lh_format fmts[] = {Q, N, C};
    for (int k = 0; k < 3; k++) {
        alloc_case c;
        char *s = big_case(fmts[k], &c);
        LH_ASSERT_TRUE(s != NULL);
        long runs = lh_test_every_failure(lh_t_, run_read, &c);
        LH_EXPECT_GE_INT(runs, fmts[k] == N ? 10 : 4); /* growth happened, for each array */
        free(s);
    }
}

LH_TEST(read_error_and_arguments)
{
    lh_error err;
    lh_points p;
    FILE *f = tmpfile();
    LH_ASSERT_TRUE(f != NULL);
    FILE *w = fopen("/dev/null", "w");
    if (w) { /* reading a write-only stream fails with an error, not an end */
        LH_EXPECT_EQ_INT(lh_points_read(w, "wo", Q, NULL, &p, &err), LH_ERR_IO);
        LH_EXPECT_STREQ(err.message, "wo:1:1: expected the dimension, found a read error");
        fclose(w);
    }
    LH_EXPECT_EQ_INT(lh_points_read(NULL, "x", Q, NULL, &p, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_points_read(f, "x", Q, NULL, NULL, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_points_read(f, "x", (lh_format)7, NULL, &p, &err), LH_ERR_INVALID_ARGUMENT);
    lh_allocator half = {lh_test_counting_alloc, NULL, NULL};
    LH_EXPECT_EQ_INT(lh_points_read(f, "x", Q, &half, &p, &err), LH_ERR_INVALID_ARGUMENT);
    fclose(f);
    /* No name, no lh_error. */
    LH_EXPECT_EQ_INT(read_text(NULL, TEXT("2 -x"), Q, NULL, &p, NULL), LH_ERR_PARSE);
    LH_EXPECT_EQ_INT(read_text(NULL, TEXT("2 -x"), Q, NULL, &p, &err), LH_ERR_PARSE);
    LH_EXPECT_STREQ(err.message, "<input>:1:3: expected the number of points (an integer from 1 to " MAX_POINTS "), found '-x'");
    char max_points[32]; /* MAX_POINTS is LH_READ_MAX_POINTS */
    snprintf(max_points, sizeof max_points, "%" LH_INDEX_PRI, LH_READ_MAX_POINTS);
    LH_EXPECT_STREQ(max_points, MAX_POINTS);
    lh_points_free(NULL);
    lh_points_free(&p);
    LH_EXPECT_STREQ(lh_format_name(LH_FORMAT_COLUMNS), "columns");
    LH_EXPECT_STREQ(lh_format_name((lh_format)9), "unknown");
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(qhull_cli_messages), LH_CASE(qhull_header_errors), LH_CASE(qhull_coordinate_errors),
        LH_CASE(long_tokens), LH_CASE(node_errors), LH_CASE(columns_errors),
        LH_CASE(declared_count_is_not_trusted), LH_CASE(qhull_good),
#ifdef LH_TEST_DATA_DIR
        LH_CASE(rbox_file),
#endif
        LH_CASE(node_good), LH_CASE(columns_good), LH_CASE(auto_detection), LH_CASE(large_inputs),
        LH_CASE(every_allocation_failure), LH_CASE(reading_needs_little_stack),
        LH_CASE(read_error_and_arguments),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
