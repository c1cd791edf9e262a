/* test_status.c — pinned status values, messages, names, version, index width; the
 * API conventions: defaults and frees of NULL, error detail in an lh_error. */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
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
    LH_EXPECT_EQ_INT(LH_ERR_INTERSECTING_FACETS, 13);
    LH_EXPECT_EQ_INT(LH_ERR_STEINER_LIMIT, 14);
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

/* ---- error detail: one lh_error, the last parameter (lifthull.h's conventions) ---- */

static const lh_error stale = {LH_ERR_IO, 7, 8, 9, "stale"};

/* The success state: every field reset, whatever was there before. */
static void expect_clear(lh_test_state *lh_t_, const lh_error *e)
{
    LH_EXPECT_EQ_INT(e->status, LH_OK);
    LH_EXPECT_STREQ(e->message, "");
    LH_EXPECT_EQ_U64(e->line, 0);
    LH_EXPECT_EQ_U64(e->column, 0);
    LH_EXPECT_EQ_U64(e->index, LH_ERROR_NO_INDEX);
}

static lh_status points_from(const char *text, lh_points *p, lh_error *e)
{
    FILE *f = lh_test_file(text, strlen(text));
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, "p.txt", LH_FORMAT_QHULL, NULL, p, e);
    fclose(f);
    return st;
}

static lh_status poly_from(const char *text, lh_pslg *g, lh_error *e)
{
    FILE *f = lh_test_file(text, strlen(text));
    if (!f) return LH_ERR_IO;
    lh_status st = lh_poly_read(f, "g.poly", NULL, g, e);
    fclose(f);
    return st;
}

LH_TEST(reader_error_has_status_message_and_place)
{
    lh_points p;
    LH_EXPECT_EQ_INT(points_from("2 3\n0 0\n1 x\n", &p, NULL), LH_ERR_PARSE); /* NULL: no detail */
    lh_error e = stale;
    LH_EXPECT_EQ_INT(points_from("2 3\n0 0\n1 x\n", &p, &e), LH_ERR_PARSE);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_PARSE);
    LH_EXPECT_STREQ(e.message, "p.txt:3:3: expected coordinate 2 of point 2 (a number), found 'x'");
    LH_EXPECT_EQ_U64(e.line, 3);
    LH_EXPECT_EQ_U64(e.column, 3);
    LH_EXPECT_EQ_U64(e.index, LH_ERROR_NO_INDEX);
    LH_ASSERT_EQ_INT(points_from("2 3\n0 0\n1 0\n0 1\n", &p, &e), LH_OK);
    expect_clear(lh_t_, &e);
    lh_points_free(&p);
    /* an argument refused before any reading: the status, no message, no place */
    e = stale;
    LH_EXPECT_EQ_INT(lh_points_read(NULL, "x", LH_FORMAT_QHULL, NULL, &p, &e), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(e.message, "");
    LH_EXPECT_EQ_U64(e.line, 0);
    LH_EXPECT_EQ_U64(e.index, LH_ERROR_NO_INDEX);
    /* the checks: the triangulation of the points, then a simplex that repeats a site */
    lh_tri *t = NULL;
    LH_ASSERT_EQ_INT(points_from("2 3\n0 0\n1 0\n0 1\n", &p, NULL), LH_OK);
    LH_ASSERT_EQ_INT(lh_delaunay(2, p.n, p.xyz, NULL, &t), LH_OK);
    e = stale;
    LH_EXPECT_EQ_INT(lh_tri_check(t, &e), LH_OK);
    expect_clear(lh_t_, &e);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    const lh_index repeat[] = {0, 1, 1};
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, p.n, p.xyz, 1, repeat, NULL, &e), LH_ERR_INVALID_MESH);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(e.message, "simplex 0 repeats site 1");
    LH_EXPECT_EQ_U64(e.line, 0);
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, p.n, p.xyz, 1, repeat, NULL, NULL), LH_ERR_INVALID_MESH);
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, p.n, p.xyz, lh_tri_count(t), lh_tri_simplices(t), NULL, &e), LH_OK);
    expect_clear(lh_t_, &e);
    lh_tri_free(t);
    lh_points_free(&p);
}

LH_TEST(coords_validate_names_the_flat_index)
{
    const double x[] = {0, 1, 2, 3, 4, NAN};
    lh_error e = stale;
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 2, x, &e), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_NONFINITE);
    LH_EXPECT_EQ_U64(e.index, 5); /* point 1, coordinate 2: 1 * 3 + 2 */
    LH_EXPECT_STREQ(e.message, "xyz[5] is NaN or infinite (point 1, coordinate 2, from 0)");
    LH_EXPECT_EQ_U64(e.line, 0);
    LH_EXPECT_EQ_U64(e.column, 0);
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 2, x, NULL), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 1, x, &e), LH_OK);
    expect_clear(lh_t_, &e);
    LH_EXPECT_EQ_INT(lh_coords_validate(0, 1, x, &e), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_U64(e.index, LH_ERROR_NO_INDEX);
}

/* The mesher names the line of the item at fault when the PSLG came from a reader. */
LH_TEST(mesher_error_names_the_line)
{
    static const char crossing[] = "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n"
                                   "2 0\n0 0 2\n1 1 3\n0\n";
    lh_pslg g;
    lh_error e = stale;
    LH_ASSERT_EQ_INT(poly_from(crossing, &g, &e), LH_OK);
    expect_clear(lh_t_, &e);
    lh_trimesh *m = NULL;
    e = stale;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &e), LH_ERR_CROSSING_SEGMENTS);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_CROSSING_SEGMENTS);
    LH_EXPECT_STREQ(e.message, "8: segment 1 crosses segment 0 (line 7)");
    LH_EXPECT_EQ_U64(e.line, 8);
    LH_EXPECT_EQ_U64(e.column, 0);
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, NULL), LH_ERR_CROSSING_SEGMENTS);
    g.segment_count = 0; /* no segments: the hull is the domain */
    LH_ASSERT_EQ_INT(lh_pslg_triangulate(&g, NULL, &m, &e), LH_OK);
    expect_clear(lh_t_, &e);
    e = stale;
    LH_EXPECT_EQ_INT(lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                                  lh_trimesh_triangles(m), 0, NULL, 1, NULL, &e),
                     LH_OK);
    expect_clear(lh_t_, &e);
    const lh_index cw[] = {0, 2, 1};
    LH_EXPECT_EQ_INT(lh_cdt_check(4, g.xy, 1, cw, 0, NULL, 1, NULL, &e), LH_ERR_INVALID_MESH);
    LH_EXPECT_EQ_INT(e.status, LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(e.message, "triangle 0 is not counterclockwise with positive area");
    LH_EXPECT_EQ_INT(lh_cdt_check(4, g.xy, 1, cw, 0, NULL, 1, NULL, NULL), LH_ERR_INVALID_MESH);
    lh_trimesh_free(m);
    lh_pslg_free(&g);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(status_values_are_pinned),
                                         LH_CASE(defaults_and_frees_accept_null),
                                         LH_CASE(status_messages_are_distinct),
                                         LH_CASE(version_matches_header),
                                         LH_CASE(index_width_matches_header),
                                         LH_CASE(reader_error_has_status_message_and_place),
                                         LH_CASE(coords_validate_names_the_flat_index),
                                         LH_CASE(mesher_error_names_the_line)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
