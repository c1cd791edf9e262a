/* test_io_poly_errors.c — every diagnostic of lh_poly_read exactly: the header, the
 * vertices, the segments, the holes and regions (FILE:LINE:COL: problem). */
#include "io_pslg_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- diagnostics ---------------------------------------------------------------- */

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

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(poly_header_errors), LH_CASE(poly_vertex_errors), LH_CASE(poly_segment_errors),
        LH_CASE(poly_hole_region_errors),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
