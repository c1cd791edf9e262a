/* test_pred_fma.c — the predicate code is compiled without floating-point
 * contraction: a*b + c rounds twice there, as the filter's error analysis assumes.
 * Fails if the library were built with contraction on (e.g. -ffp-contract=fast
 * with -mfma, or a compiler that fuses by default). */
#include "lh_test.h"
#include "pred_internal.h"

#include <math.h>

LH_TEST(predicate_code_does_not_fuse_multiply_add)
{
    /* a*b = 1 - 2^-60 exactly; rounded it is 1, so a*b - 1 is 0 when rounded twice
     * and -2^-60 when fused. */
    const double a = 1.0 + 0x1p-30, b = 1.0 - 0x1p-30, c = -1.0;
    volatile double prod = a * b; /* volatile: this file's own code cannot fuse */
    double two_roundings = prod + c;
    double fused = fma(a, b, c);
    LH_ASSERT_TRUE(two_roundings != fused); /* the probe can tell them apart */
    LH_EXPECT_EQ_DBL(two_roundings, 0.0);
    LH_EXPECT_EQ_DBL(fused, -0x1p-60);
    LH_EXPECT_EQ_DBL(lh__fp_contract_probe(a, b, c), two_roundings);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(predicate_code_does_not_fuse_multiply_add)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
