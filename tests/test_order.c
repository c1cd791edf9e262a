/* test_order.c — the Hilbert keys of the site order (hull/order.c): on every grid of
 * up to 2^16 cells in 2 to 8 dimensions, the index must number the cells once each,
 * from the origin, and consecutive indices must be adjacent cells (one coordinate
 * apart by one), which is what makes consecutive sites close. */
#include "engine.h"
#include "lh_test.h"

#include <stdlib.h>

/* The index of cell c (coordinates of `bits` bits packed from coordinate 0 up). */
static uint64_t index_of(uint64_t c, int d, int bits)
{
    uint64_t x[LH__ENGINE_MAX_DIM], k = 0;
    for (int j = 0; j < d; j++) x[j] = c >> (j * bits) & ((UINT64_C(1) << bits) - 1);
    lh__hilbert_transpose(x, d, bits);
    for (int b = bits - 1; b >= 0; b--)
        for (int j = 0; j < d; j++) k = k << 1 | (x[j] >> b & 1);
    return k;
}

static void check_grid(lh_test_state *lh_t_, int d, int bits)
{
    const uint64_t cells = UINT64_C(1) << (d * bits), mask = (UINT64_C(1) << bits) - 1;
    uint64_t *cell_at = malloc(cells * sizeof *cell_at);
    LH_EXPECT_TRUE(cell_at != NULL);
    if (!cell_at) return;
    for (uint64_t k = 0; k < cells; k++) cell_at[k] = UINT64_MAX;
    size_t twice = 0, apart = 0;
    for (uint64_t c = 0; c < cells; c++) {
        uint64_t k = index_of(c, d, bits);
        if (k >= cells || cell_at[k] != UINT64_MAX) twice++;
        else cell_at[k] = c;
    }
    LH_EXPECT_EQ_U64(twice, 0);
    LH_EXPECT_EQ_U64(cell_at[0], 0);
    for (uint64_t k = 1; k < cells && !twice; k++) {
        uint64_t steps = 0;
        for (int j = 0; j < d; j++) {
            int64_t a = (int64_t)(cell_at[k] >> (j * bits) & mask), b = (int64_t)(cell_at[k - 1] >> (j * bits) & mask);
            steps += (uint64_t)llabs(a - b);
        }
        apart += steps != 1;
    }
    LH_EXPECT_EQ_U64(apart, 0);
    free(cell_at);
}

LH_TEST(hilbert_indices_number_adjacent_cells)
{
    for (int d = 2; d <= 8 && !LH_FAILED(); d++)
        for (int bits = 1; d * bits <= 16 && !LH_FAILED(); bits++) check_grid(lh_t_, d, bits);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(hilbert_indices_number_adjacent_cells)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
