/* test_cells.c — lh_cells_read: Qhull's 'i' and Triangle/TetGen .ele cell lists, their
 * diagnostics (message and status, exactly), and every allocation failing in turn. */
#include "lh_api_test.h"

#include <stdio.h>
#include <string.h>

static lh_status read_text(const char *name, const char *text, size_t n_points, const lh_allocator *a,
                           lh_cells *c, lh_error *err)
{
    FILE *f = lh_test_file(text, strlen(text));
    if (!f) return LH_ERR_IO;
    lh_status st = lh_cells_read(f, name, n_points, a, c, err);
    fclose(f);
    return st;
}

LH_TEST(good_lists)
{
    lh_cells c;
    lh_error err;
    LH_ASSERT_EQ_INT(read_text("i", "2\n0 1 2 \n2 1 3 \n", 4, NULL, &c, &err), LH_OK);
    LH_EXPECT_EQ_INT(c.nv, 3);
    LH_EXPECT_EQ_U64(c.count, 2);
    LH_EXPECT_EQ_INT(c.v[3], 2);
    LH_EXPECT_EQ_INT(c.v[5], 3);
    LH_EXPECT_STREQ(err.message, "");
    lh_cells_free(&c);
    /* .ele, 1-based with an attribute, CRLF and a comment: rebased to 0 */
    LH_ASSERT_EQ_INT(read_text("m.ele", "2 4 1\r\n# tets\r\n1 1 2 3 4 0.5\r\n2 2 3 4 5 7\r\n", 5, NULL, &c, &err), LH_OK);
    LH_EXPECT_EQ_INT(c.nv, 4);
    LH_EXPECT_EQ_INT(c.first_index, 1);
    LH_EXPECT_EQ_INT(c.v[0], 0);
    LH_EXPECT_EQ_INT(c.v[7], 4);
    LH_EXPECT_EQ_INT(c.attr_count, 1); /* the attributes kept */
    LH_EXPECT_TRUE(c.attr && c.attr[0] == 0.5 && c.attr[1] == 7);
    lh_cells_free(&c);
    LH_ASSERT_EQ_INT(read_text("i", "1\n0 1 2\n", 4, NULL, &c, &err), LH_OK);
    LH_EXPECT_TRUE(c.attr_count == 0 && c.attr == NULL);
    lh_cells_free(&c);
    lh_cells_free(NULL);
}

LH_TEST(bad_lists_say_where_and_what)
{
    static const struct {
        const char *text;
        size_t n;
        lh_status st;
        const char *msg;
    } cases[] = {
        {"", 4, LH_ERR_PARSE, "c:1:1: expected the number of cells, found the end of the input"},
        {"2\n0 1 2\n", 4, LH_ERR_PARSE, "c:3:1: expected cell 2, found the end of the input (2 cells declared)"},
        {"1\n0 1 x\n", 4, LH_ERR_PARSE, "c:2:5: expected a point index of cell 1 (an integer from 0 to 3), found 'x'"},
        {"1\n0 1 9\n", 4, LH_ERR_PARSE, "c:2:5: expected a point index of cell 1 (an integer from 0 to 3), found '9'"},
        {"2\n0 1 2\n0 1\n", 4, LH_ERR_PARSE, "c:3:4: expected a point index of cell 2 (an integer from 0 to 3), found the end of the line"},
        {"2\n0 1 2\n0 1 2 3\n", 4, LH_ERR_PARSE, "c:3:7: expected the end of the line after cell 2 (3 indices), found '3'"},
        {"1\n0 1 2\n5\n", 4, LH_ERR_PARSE, "c:3:1: expected the end of the input after 1 cell, found '5'"},
        {"1\n7\n", 8, LH_ERR_PARSE, "c:2:1: a cell of fewer than 2 points"},
        {"1 3 0\n2 0 1 2\n", 4, LH_ERR_PARSE, "c:2:1: expected the first cell's number (0 or 1), found '2'"},
        {"2 3 0\n0 0 1 2\n2 0 1 3\n", 4, LH_ERR_PARSE, "c:3:1: expected cell number 1, found '2'"},
        {"1 12 0\n", 4, LH_ERR_PARSE, "c:1:3: expected the number of points per cell (an integer from 2 to 9), found '12'"},
        {"1 3 1\n1 1 2 3 nan\n", 4, LH_ERR_NONFINITE,
         "c:2:9: attribute 1 of cell 1 is 'nan': NaN and infinities are not accepted"},
        {"2 3 1\n1 1 2 3 0.5\n2 2 3 4 1e400\n", 4, LH_ERR_NONFINITE,
         "c:3:9: attribute 1 of cell 2 is '1e400', which overflows a double"},
        {"1 3 1\n1 1 2 3 x\n", 4, LH_ERR_PARSE, "c:2:9: expected attribute 1 of cell 1 (a number), found 'x'"},
        {"1\n0 1\0 2\n", 4, LH_ERR_PARSE, "c:2:4: expected a point index or the end of the line, found a NUL byte"},
    };
    for (size_t i = 0; i < LH_COUNT(cases); i++) {
        lh_cells c;
        lh_error err;
        size_t len = i == LH_COUNT(cases) - 1 ? 10 : strlen(cases[i].text); /* the last: a NUL */
        FILE *f = lh_test_file(cases[i].text, len);
        LH_ASSERT_TRUE(f != NULL);
        lh_status st = lh_cells_read(f, "c", cases[i].n, NULL, &c, &err);
        fclose(f);
        LH_EXPECT_EQ_INT(st, cases[i].st);
        LH_EXPECT_STREQ(err.message, cases[i].msg);
        LH_EXPECT_TRUE(c.v == NULL && c.count == 0);
    }
    lh_cells c;
    LH_EXPECT_EQ_INT(lh_cells_read(NULL, "x", 0, NULL, &c, NULL), LH_ERR_INVALID_ARGUMENT);
}

static lh_status run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)user;
    char text[20000] = "600\n";
    for (int i = 0; i < 600; i++) sprintf(text + strlen(text), "%d %d %d\n", i, i + 1, i + 2);
    lh_cells c;
    lh_error err;
    lh_status st = read_text("big", text, 700, a, &c, &err);
    if (st == LH_OK) LH_EXPECT_EQ_U64(c.count, 600);
    else LH_EXPECT_TRUE(strstr(err.message, "out of memory") != NULL);
    lh_cells_free(&c);
    return st;
}

LH_TEST(every_allocation_failure_is_survived)
{
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, run, NULL), 1);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(good_lists), LH_CASE(bad_lists_say_where_and_what),
                                         LH_CASE(every_allocation_failure_is_survived)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
