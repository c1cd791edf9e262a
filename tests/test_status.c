/* test_status.c — pinned status values, messages, names, version, index width. */
#include "lh_test.h"
#include "lifthull.h"

#include <stdio.h>
#include <string.h>

LH_TEST(status_values_are_pinned)
{
    LH_EXPECT_EQ_INT(LH_OK, 0);
    LH_EXPECT_EQ_INT(LH_ERR_NOMEM, 1);
    LH_EXPECT_EQ_INT(LH_ERR_INVALID_ARGUMENT, 2);
    LH_EXPECT_EQ_INT(LH_ERR_NONFINITE, 3);
    LH_EXPECT_EQ_INT(LH_ERR_DIMENSION, 4);
    LH_EXPECT_EQ_INT(LH_ERR_TOO_LARGE, 5);
    LH_EXPECT_EQ_INT(LH_ERR_DEGENERATE, 6);
    LH_EXPECT_EQ_INT(LH_ERR_IO, 7);
    LH_EXPECT_EQ_INT(LH_ERR_PARSE, 8);
    LH_EXPECT_EQ_INT(LH_ERR_INTERNAL, 9);
    LH_EXPECT_EQ_INT(LH_ERR_INVALID_MESH, 10);
    LH_EXPECT_EQ_INT(LH_ERR_BUFFER_TOO_SMALL, 11);
    LH_EXPECT_EQ_INT(LH_ERR_CROSSING_SEGMENTS, 12);
}

LH_TEST(status_messages_are_distinct)
{
    for (int a = 0; a <= LH_ERR_CROSSING_SEGMENTS; a++) {
        const char *ma = lh_status_message((lh_status)a);
        LH_EXPECT_TRUE(strcmp(ma, "unknown status") != 0);
        LH_EXPECT_TRUE(strncmp(lh_status_name((lh_status)a), "LH_", 3) == 0);
        for (int b = a + 1; b <= LH_ERR_CROSSING_SEGMENTS; b++)
            LH_EXPECT_TRUE(strcmp(ma, lh_status_message((lh_status)b)) != 0);
    }
    LH_EXPECT_STREQ(lh_status_message(LH_ERR_NONFINITE), "coordinate is NaN or infinite");
    LH_EXPECT_STREQ(lh_status_name(LH_ERR_NOMEM), "LH_ERR_NOMEM");
    LH_EXPECT_STREQ(lh_status_message((lh_status)1234), "unknown status");
}

LH_TEST(version_matches_header)
{
    LH_EXPECT_STREQ(lh_version_string(), LH_VERSION_STRING);
    LH_EXPECT_EQ_INT(lh_version_number(),
                     LH_VERSION_MAJOR * 10000 + LH_VERSION_MINOR * 100 + LH_VERSION_PATCH);
}

/* The library was built with the index width the header (lifthull_config.h) says. */
LH_TEST(index_width_matches_header)
{
    LH_EXPECT_EQ_INT(lh_index_bits(), LH_INDEX_BITS);
    LH_EXPECT_EQ_INT(LH_INDEX_BITS, 8 * (int)sizeof(lh_index));
    LH_EXPECT_TRUE(LH_INDEX_BITS == 32 || LH_INDEX_BITS == 64);
    LH_EXPECT_TRUE(LH_INDEX_MAX == (LH_INDEX_BITS == 64 ? INT64_MAX : INT32_MAX));
    LH_EXPECT_TRUE(LH_READ_MAX_POINTS == LH_INDEX_MAX - 1);
    char text[32];
    snprintf(text, sizeof text, "%" LH_INDEX_PRI, (lh_index)-LH_INDEX_MAX);
    LH_EXPECT_STREQ(text, LH_INDEX_BITS == 64 ? "-9223372036854775807" : "-2147483647");
}

/* Every *_default accepts NULL and does nothing; every *_free(NULL) is a no-op, and so
 * is freeing a zeroed reader struct (the conventions at the top of lifthull.h). */
LH_TEST(defaults_and_frees_accept_null)
{
    lh_options_default(NULL);
    lh_trimesh_options_default(NULL);
    lh_pred_free(NULL);
    lh_tri_free(NULL);
    lh_hull_free(NULL);
    lh_trimesh_free(NULL);
    lh_points_free(NULL);
    lh_cells_free(NULL);
    lh_pslg_free(NULL);
    lh_points p;
    lh_cells c;
    lh_pslg g;
    memset(&p, 0, sizeof p);
    memset(&c, 0, sizeof c);
    memset(&g, 0, sizeof g);
    lh_points_free(&p);
    lh_cells_free(&c);
    lh_pslg_free(&g);
    lh_options o;
    lh_options_default(&o);
    LH_EXPECT_EQ_INT(o.threads, 1);
    lh_trimesh_options t;
    lh_trimesh_options_default(&t);
    LH_EXPECT_EQ_INT(t.boundary_steiner, 1);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(status_values_are_pinned),
                                         LH_CASE(defaults_and_frees_accept_null),
                                         LH_CASE(status_messages_are_distinct),
                                         LH_CASE(version_matches_header),
                                         LH_CASE(index_width_matches_header)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
