/*
 * test_alloc.c — every allocation failing in turn, for the public entry points not
 * covered next to their own tests: lh_coords_affine_dim, lh_delaunay_check, lh_tri_check,
 * lh_tri_complex, lh_tri_complex_cells, lh_tri_complex_edges, lh_tri_measures,
 * lh_convex_hull of a grid (flat faces: the corners and the rebuilt hull) and
 * lh_hull_measures on it, and lh_tri_locate at a point shared
 * by more than 64 simplices. Each
 * failing run must return LH_ERR_NOMEM and leave nothing allocated
 * (lh_test_every_failure). The others: lh_pred_create (test_pred_basic),
 * lh_delaunay and lh_convex_hull (test_delaunay), lh_tri_insert (test_insert), the
 * flat path (test_flat), lh_tri_circumcenters, lh_tri_nearest, lh_tri_interpolate
 * (test_voronoi), lh_tri_natural_coords (test_natural), lh_points_read (test_io_read),
 * lh_cells_read (test_cells). The rest allocate nothing.
 */
#include "lh_api_test.h"
#include "lh_families.h"

#include <stdlib.h>

enum { N = 125 }; /* a 5^3 grid: every cell cospherical, centres shared by many simplices */

/* The grid into x, and options with allocator a. */
static lh_options grid(double *x, const lh_allocator *a)
{
    for (int i = 0; i < N; i++) x[3 * i] = i % 5, x[3 * i + 1] = i / 5 % 5, x[3 * i + 2] = i / 25;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    return o;
}

static lh_status affine_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)user;
    double x[N * 3];
    lh_options o = grid(x, a);
    int k = -2;
    lh_status st = lh_coords_affine_dim(3, N, x, &o, &k);
    if (st == LH_OK) LH_EXPECT_EQ_INT(k, 3);
    return st;
}

/* A triangulation built without the failing allocator, checked with it. */
static lh_status check_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)user;
    double x[N * 3];
    lh_options o = grid(x, a);
    lh_tri *t;
    LH_EXPECT_EQ_INT(lh_delaunay(3, N, x, NULL, &t), LH_OK);
    lh_error err;
    lh_status st = lh_delaunay_check(3, N, x, lh_tri_count(t), lh_tri_simplices(t), &o, &err);
    lh_tri_free(t);
    return st;
}

/* Handle queries use the handle's allocator: built with it, each query fails in turn. */
typedef lh_status (*query_fn)(lh_test_state *lh_t_, lh_tri *t);

static lh_status q_check(lh_test_state *lh_t_, lh_tri *t)
{
    (void)lh_t_;
    return lh_tri_check(t, NULL);
}

static lh_status q_complex(lh_test_state *lh_t_, lh_tri *t)
{
    size_t count;
    const lh_index *off, *v;
    lh_status st = lh_tri_complex(t, &count, &off, &v);
    if (st == LH_OK) LH_EXPECT_EQ_U64(count, 64); /* the 4^3 unit cubes */
    return st;
}

static lh_status q_complex_edges(lh_test_state *lh_t_, lh_tri *t)
{
    size_t count;
    const lh_index *e, *cell;
    lh_status st = lh_tri_complex_cells(t, &cell);
    if (st == LH_OK) st = lh_tri_complex_edges(t, &count, &e);
    if (st == LH_OK) LH_EXPECT_EQ_U64(count, 300); /* the grid's unit segments */
    return st;
}

static lh_status q_measures(lh_test_state *lh_t_, lh_tri *t)
{
    double total = 0;
    lh_status st = lh_tri_measures(t, NULL, &total);
    if (st == LH_OK) LH_EXPECT_EQ_DBL(total, 64); /* the cube [0, 4]^3 */
    return st;
}

/* lh_convex_hull of the 5^3 grid: its 8 corners, 12 triangles. */
static lh_status hull_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)user;
    double x[N * 3];
    lh_options o = grid(x, a);
    lh_hull *h;
    lh_status st = lh_convex_hull(3, N, x, &o, &h);
    if (st != LH_OK) return st;
    LH_EXPECT_EQ_U64(lh_hull_vertex_count(h), 8);
    LH_EXPECT_EQ_U64(lh_hull_facet_count(h), 12);
    double area = 0, volume = 0;
    st = lh_hull_measures(h, x, N, NULL, &area, &volume);
    if (st == LH_OK) LH_EXPECT_EQ_DBL(area, 96), LH_EXPECT_EQ_DBL(volume, 64);
    lh_hull_free(h);
    return st;
}

/* lh_tri_locate's scratch: a vertex of the 5^4 grid lies in 120 simplices (over the
 * 64 it keeps on the stack). */
static lh_status locate_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    (void)user;
    static double x[625 * 4];
    for (int i = 0; i < 625; i++)
        x[4 * i] = i % 5, x[4 * i + 1] = i / 5 % 5, x[4 * i + 2] = i / 25 % 5, x[4 * i + 3] = i / 125;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    lh_tri *t;
    lh_status st = lh_delaunay(4, 625, x, &o, &t);
    if (st != LH_OK) return st;
    const double vertex[4] = {2, 2, 2, 2};
    lh_location loc;
    st = lh_tri_locate(t, vertex, -1, &loc);
    if (st == LH_OK) LH_EXPECT_TRUE(loc.simplex >= 0);
    lh_tri_free(t);
    return st;
}

static lh_status query_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const query_fn *q = user;
    double x[N * 3];
    lh_options o = grid(x, a);
    lh_tri *t;
    lh_status st = lh_delaunay(3, N, x, &o, &t);
    if (st != LH_OK) return st;
    st = (*q)(lh_t_, t);
    lh_tri_free(t);
    return st;
}

LH_TEST(every_allocation_failure_is_survived)
{
    static const query_fn queries[] = {q_check, q_complex, q_complex_edges, q_measures};
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, affine_run, NULL), 1);
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, check_run, NULL), 1);
    for (size_t i = 0; i < LH_COUNT(queries); i++)
        LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, query_run, &queries[i]), 1);
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, locate_run, NULL), 1);
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, hull_run, NULL), 1);
}

/* Counts the hook's allocations. */
static void *counting_alloc(void *user, size_t size)
{
    ++*(size_t *)user;
    return malloc(size);
}
static void counting_free(void *user, void *p)
{
    (void)user;
    free(p);
}

/* lh_tri_measures and lh_hull_measures allocate (their exact sums) through the
 * handle's hooks, as every query on a handle does; they used malloc. */
LH_TEST(measures_use_the_handles_allocator)
{
    size_t calls = 0;
    const lh_allocator al = {counting_alloc, counting_free, &calls};
    double x[N * 3];
    lh_options o = grid(x, &al);
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, N, x, &o, &t), LH_OK);
    size_t before = calls;
    double total = 0;
    LH_EXPECT_EQ_INT(lh_tri_measures(t, NULL, &total), LH_OK);
    LH_EXPECT_EQ_DBL(total, 64);
    LH_EXPECT_GT_U64(calls, before);
    lh_tri_free(t);
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(3, N, x, &o, &h), LH_OK);
    before = calls;
    double area = 0, volume = 0;
    LH_EXPECT_EQ_INT(lh_hull_measures(h, x, N, NULL, &area, &volume), LH_OK);
    LH_EXPECT_EQ_DBL(volume, 64);
    LH_EXPECT_GT_U64(calls, before);
    lh_hull_free(h);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(every_allocation_failure_is_survived),
                                         LH_CASE(measures_use_the_handles_allocator)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
