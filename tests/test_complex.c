/* test_complex.c — lh_tri_complex: grids give squares and cubes, cocircular sites one
 * cell, general position the simplices themselves. */
#include "lh_test.h"
#include "lifthull.h"

#include <stdlib.h>

static void grid_cells(lh_test_state *lh_t_, int d, int side, size_t want_cells, int want_size)
{
    size_t n = 1;
    for (int j = 0; j < d; j++) n *= (size_t)side;
    double *x = malloc(n * d * sizeof *x);
    for (size_t i = 0; i < n; i++) {
        size_t k = i;
        for (int j = 0; j < d; j++, k /= (size_t)side) x[i * d + j] = (double)(k % (size_t)side);
    }
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
    size_t count;
    const lh_index *off, *v;
    LH_ASSERT_EQ_INT(lh_tri_complex(t, &count, &off, &v), LH_OK);
    LH_EXPECT_EQ_U64(count, want_cells);
    for (size_t c = 0; c < count; c++) {
        LH_EXPECT_EQ_INT(off[c + 1] - off[c], want_size);
        for (lh_index k = off[c] + 1; k < off[c + 1]; k++) LH_EXPECT_LT_INT(v[k - 1], v[k]);
        if (c) LH_EXPECT_LT_INT(v[off[c - 1]], v[off[c]] + 1); /* sorted by first vertex */
    }
    size_t again;
    const lh_index *off2, *v2;
    LH_EXPECT_EQ_INT(lh_tri_complex(t, &again, &off2, &v2), LH_OK); /* cached */
    LH_EXPECT_TRUE(off2 == off && v2 == v && again == count);
    lh_tri_free(t);
    free(x);
}

LH_TEST(grids_give_squares_and_cubes)
{
    grid_cells(lh_t_, 2, 10, 81, 4);
    grid_cells(lh_t_, 3, 4, 27, 8);
    grid_cells(lh_t_, 4, 3, 16, 16);
}

LH_TEST(cocircular_sites_form_one_cell)
{
    const double x[] = {5, 0, 4, 3, 3, 4, 0, 5, -3, 4, -4, 3, -5, 0, -4, -3, -3, -4, 0, -5, 3, -4, 4, -3};
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 12, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 10);
    size_t count;
    const lh_index *off, *v;
    LH_ASSERT_EQ_INT(lh_tri_complex(t, &count, &off, &v), LH_OK);
    LH_EXPECT_EQ_U64(count, 1);
    LH_EXPECT_EQ_INT(off[1], 12);
    lh_tri_free(t);
}

LH_TEST(general_position_cells_are_the_simplices)
{
    enum { N = 300 };
    double x[N * 3];
    uint64_t s = 12345;
    for (int i = 0; i < N * 3; i++) {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        x[i] = (double)(s >> 11) * 0x1p-53;
    }
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, N, x, NULL, &t), LH_OK);
    size_t count;
    const lh_index *off, *v;
    LH_ASSERT_EQ_INT(lh_tri_complex(t, &count, &off, &v), LH_OK);
    LH_EXPECT_EQ_U64(count, lh_tri_count(t));
    LH_EXPECT_EQ_INT(off[count], 4 * (lh_index)count);
    lh_tri_free(t);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(grids_give_squares_and_cubes),
                                         LH_CASE(cocircular_sites_form_one_cell),
                                         LH_CASE(general_position_cells_are_the_simplices)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
