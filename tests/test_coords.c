/* test_coords.c — the accepted coordinate range (lifthull.h) and its rejections. */
#include "lh_test.h"
#include "lifthull.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

LH_TEST(every_finite_double_is_accepted)
{
    const double x[] = {0.0, -0.0, DBL_MIN, -DBL_MIN, 4.9e-324, DBL_MAX, -DBL_MAX, 1e-300, 1e300, 1.0};
    lh_error bad = {LH_ERR_NONFINITE, 1, 2, 77, "x"};
    LH_EXPECT_EQ_INT(lh_coords_validate(2, 5, x, &bad), LH_OK);
    LH_EXPECT_EQ_INT(bad.status, LH_OK); /* reset on success */
    LH_EXPECT_EQ_U64(bad.index, LH_ERROR_NO_INDEX);
    LH_EXPECT_STREQ(bad.message, "");
}

LH_TEST(nan_and_inf_are_rejected_with_their_index)
{
    double x[6] = {1, 2, 3, 4, 5, 6};
    lh_error bad;
    x[4] = NAN;
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 2, x, &bad), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(bad.status, LH_ERR_NONFINITE);
    LH_EXPECT_EQ_U64(bad.index, 4);
    LH_EXPECT_STREQ(bad.message, "xyz[4] is NaN or infinite (point 1, coordinate 1, from 0)");
    LH_EXPECT_EQ_U64(bad.line, 0);
    x[4] = 5;
    x[1] = -INFINITY;
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 2, x, &bad), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_U64(bad.index, 1);
    LH_EXPECT_EQ_INT(lh_coords_validate(3, 2, x, NULL), LH_ERR_NONFINITE);
}

LH_TEST(bad_arguments_are_rejected)
{
    double x[2] = {0, 0};
    LH_EXPECT_EQ_INT(lh_coords_validate(0, 1, x, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_coords_validate(-3, 1, x, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_coords_validate(2, 1, NULL, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_coords_validate(2, 0, NULL, NULL), LH_OK);
    LH_EXPECT_EQ_INT(lh_coords_validate(8, SIZE_MAX / 4, x, NULL), LH_ERR_TOO_LARGE);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(every_finite_double_is_accepted),
                                         LH_CASE(nan_and_inf_are_rejected_with_their_index),
                                         LH_CASE(bad_arguments_are_rejected)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
