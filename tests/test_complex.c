/* test_complex.c — lh_tri_complex: grids give squares and cubes, cocircular sites one
 * cell, general position the simplices themselves; lh_tri_complex_cells puts every
 * simplex in a cell that holds its vertices; lh_tri_complex_edges gives a grid's
 * unit segments (no diagonal), a cocircular polygon's sides. */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
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
    /* each simplex in a cell holding its vertices; a square is two triangles, a cube
     * (d >= 3) at least d + 2 simplices */
    const lh_index *cell;
    LH_ASSERT_EQ_INT(lh_tri_complex_cells(t, &cell), LH_OK);
    size_t *per = calloc(count + 1, sizeof *per);
    const lh_index *s = lh_tri_simplices(t);
    for (size_t i = 0; i < lh_tri_count(t) && !LH_FAILED(); i++) {
        LH_ASSERT_TRUE(cell[i] >= 0 && (size_t)cell[i] < count);
        per[cell[i]]++;
        for (int k = 0; k <= d; k++) {
            int found = 0;
            for (lh_index q = off[cell[i]]; q < off[cell[i] + 1]; q++) found |= v[q] == s[i * (d + 1) + k];
            LH_EXPECT_TRUE(found);
        }
    }
    for (size_t c = 0; c < count; c++)
        if (d == 2) LH_EXPECT_EQ_U64(per[c], 2);
        else LH_EXPECT_LE_U64((size_t)d + 2, per[c]);
    free(per);
    LH_EXPECT_EQ_INT(lh_tri_complex_cells(NULL, &cell), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_complex_cells(t, NULL), LH_ERR_INVALID_ARGUMENT);
    /* the edges: the d side^(d-1) (side-1) unit segments, increasing */
    size_t ne;
    const lh_index *e;
    LH_ASSERT_EQ_INT(lh_tri_complex_edges(t, &ne, &e), LH_OK);
    size_t want = (size_t)d * (n / (size_t)side) * (size_t)(side - 1);
    LH_EXPECT_EQ_U64(ne, want);
    for (size_t i = 0; i < ne && !LH_FAILED(); i++) {
        double l1 = 0;
        for (int j = 0; j < d; j++) l1 += fabs(x[(size_t)e[2 * i] * d + j] - x[(size_t)e[2 * i + 1] * d + j]);
        LH_EXPECT_EQ_DBL(l1, 1);
        LH_EXPECT_LT_INT(e[2 * i], e[2 * i + 1]);
        if (i) LH_EXPECT_TRUE(e[2 * i - 2] < e[2 * i] || (e[2 * i - 2] == e[2 * i] && e[2 * i - 1] < e[2 * i + 1]));
        if (LH_FAILED()) LH_NOTE("d=%d: edge %zu: %d %d", d, i, (int)e[2 * i], (int)e[2 * i + 1]);
    }
    LH_EXPECT_EQ_INT(lh_tri_complex_edges(t, NULL, &e), LH_ERR_INVALID_ARGUMENT);
    lh_tri_free(t);
    free(x);
}

LH_TEST(grids_give_squares_and_cubes)
{
    grid_cells(lh_t_, 2, 10, 81, 4);
    grid_cells(lh_t_, 3, 4, 27, 8);
    grid_cells(lh_t_, 4, 3, 16, 16);
    grid_cells(lh_t_, 5, 3, 32, 32);
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
    const lh_index *e; /* the 12 sides: i, i+1 (mod 12) */
    LH_ASSERT_EQ_INT(lh_tri_complex_edges(t, &count, &e), LH_OK);
    LH_ASSERT_EQ_U64(count, 12);
    for (size_t i = 0; i < 12; i++) LH_EXPECT_TRUE(e[2 * i + 1] - e[2 * i] == 1 || (e[2 * i] == 0 && e[2 * i + 1] == 11));
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
    /* the edges: the simplices' pairs of vertices */
    static unsigned char pair[N][N];
    size_t want = 0;
    const lh_index *sv = lh_tri_simplices(t);
    for (size_t i = 0; i < lh_tri_count(t); i++)
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                lh_index p = sv[i * 4 + a], q = sv[i * 4 + b];
                if (p < q && !pair[p][q]) {
                    pair[p][q] = 1;
                    want++;
                }
            }
    const lh_index *e;
    LH_ASSERT_EQ_INT(lh_tri_complex_edges(t, &count, &e), LH_OK);
    LH_EXPECT_EQ_U64(count, want);
    for (size_t i = 0; i < count; i++) LH_EXPECT_TRUE(pair[e[2 * i]][e[2 * i + 1]]);
    lh_tri_free(t);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(grids_give_squares_and_cubes),
                                         LH_CASE(cocircular_sites_form_one_cell),
                                         LH_CASE(general_position_cells_are_the_simplices)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
