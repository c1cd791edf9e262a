/* test_order.c — the Hilbert keys of the site order (hull/order.c): on every grid of
 * up to 2^16 cells in 2 to 8 dimensions, the index must number the cells once each,
 * from the origin, and consecutive indices must be adjacent cells (one coordinate
 * apart by one), which is what makes consecutive sites close. The tables of
 * hull/hilbert.h must give the same keys in 2D and 3D. */
#include "engine.h"
#include "hilbert.h"
#include "lh_test.h"

#include <stdlib.h>

/* The coordinates x[0..d-1] (`bits` bits each) interleaved, the top level first and
 * coordinate 0 first in a level: the key's layout. */
static uint64_t interleave(const uint64_t *x, int d, int bits)
{
    uint64_t k = 0;
    for (int b = bits - 1; b >= 0; b--)
        for (int j = 0; j < d; j++) k = k << 1 | (x[j] >> b & 1);
    return k;
}

/* The index of cell c (coordinates of `bits` bits packed from coordinate 0 up). */
static uint64_t index_of(uint64_t c, int d, int bits)
{
    uint64_t x[LH__ENGINE_MAX_DIM];
    for (int j = 0; j < d; j++) x[j] = c >> (j * bits) & ((UINT64_C(1) << bits) - 1);
    lh__hilbert_transpose(x, d, bits);
    return interleave(x, d, bits);
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

/* The tables' key of cell c against the transform's. */
static int table_key_agrees(const lh__hilbert *h, uint64_t c, int d, int bits)
{
    uint64_t x[3];
    for (int j = 0; j < d; j++) x[j] = c >> (j * bits) & ((UINT64_C(1) << bits) - 1);
    return lh__hilbert_key(h, interleave(x, d, bits), bits, d) == index_of(c, d, bits);
}

/* Every cell of the grids of up to 2^16 cells, then random cells of every
 * resolution up to 16 bits a coordinate (the most order.c takes). */
LH_TEST(hilbert_tables_give_the_transform_keys)
{
    lh__hilbert h;
    LH_EXPECT_EQ_INT(lh__hilbert_init(&h, 4), 0);
    uint64_t r = 12345;
    for (int d = 2; d <= 3 && !LH_FAILED(); d++) {
        LH_EXPECT_EQ_INT(lh__hilbert_init(&h, d), 1);
        LH_EXPECT_TRUE(h.nstates > 1 && h.nstates <= LH__HILBERT_STATES);
        size_t wrong = 0;
        for (int bits = 1; d * bits <= 16; bits++)
            for (uint64_t c = 0; c < UINT64_C(1) << (d * bits); c++) wrong += !table_key_agrees(&h, c, d, bits);
        for (int bits = 1; bits <= 16; bits++)
            for (int i = 0; i < 20000; i++) {
                r = r * UINT64_C(6364136223846793005) + 1442695040888963407u;
                wrong += !table_key_agrees(&h, r >> (64 - d * bits), d, bits);
            }
        LH_EXPECT_EQ_U64(wrong, 0);
        LH_NOTE("d=%d: %d states", d, h.nstates);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(hilbert_indices_number_adjacent_cells),
                                         LH_CASE(hilbert_tables_give_the_transform_keys)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
