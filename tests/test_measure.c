/* test_measure.c — lh_simplex_measures, lh_tri_measures, lh_hull_measures: exact
 * results where the measure is a dyadic rational (a cube far from the origin, a
 * thin triangle, lengths near DBL_MAX), a few ulps where it is irrational, the
 * Delaunay total equal to the hull's volume, and bad arguments. */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>

/* |a - b| <= ulps * ulp(b), b > 0. */
static int near_ulps(double a, double b, double ulps)
{
    return fabs(a - b) <= ulps * (nextafter(b, INFINITY) - b);
}

LH_TEST(cube_far_from_origin_is_exact)
{
    /* the unit cube's corners, a site on a face, one on an edge, one inside, all
     * shifted by 2^40: area 6, volume 1 exactly */
    double x[11 * 3];
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 3; j++) x[i * 3 + j] = ((i >> j) & 1) + 0x1p40;
    const double extra[9] = {0.5, 0.5, 0, 0.25, 0, 0, 0.5, 0.5, 0.5};
    for (int i = 0; i < 9; i++) x[24 + i] = extra[i] + 0x1p40;
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(3, 11, x, NULL, &h), LH_OK);
    size_t m = lh_hull_facet_count(h);
    double *each = malloc(m * sizeof *each), area = 0, volume = 0, sum = 0;
    LH_ASSERT_TRUE(each != NULL);
    LH_EXPECT_EQ_INT(lh_hull_measures(h, x, 11, each, &area, &volume), LH_OK);
    LH_EXPECT_EQ_DBL(area, 6.0);
    LH_EXPECT_EQ_DBL(volume, 1.0);
    for (size_t f = 0; f < m; f++) sum += each[f];
    LH_EXPECT_EQ_DBL(sum, 6.0); /* halves and quarters of unit squares: exact */
    volume = 0;
    LH_EXPECT_EQ_INT(lh_hull_measures(h, x, 11, NULL, NULL, &volume), LH_OK);
    LH_EXPECT_EQ_DBL(volume, 1.0);
    LH_EXPECT_EQ_INT(lh_hull_measures(h, x, 5, NULL, NULL, &volume), LH_ERR_INVALID_ARGUMENT);
    free(each);
    lh_hull_free(h);

    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, 11, x, NULL, &t), LH_OK);
    double total = 0;
    LH_EXPECT_EQ_INT(lh_tri_measures(t, NULL, &total), LH_OK);
    LH_EXPECT_EQ_DBL(total, 1.0);
    lh_tri_free(t);
}

LH_TEST(thin_huge_and_flat)
{
    /* a triangle of height 1e-300: area 1e-300 / 2, exactly */
    const double thin[6] = {0, 0, 1, 0, 1, 1e-300};
    const lh_index tri[3] = {0, 1, 2};
    double a = 0, total = 0;
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, thin, 3, 1, tri, &a, &total), LH_OK);
    LH_EXPECT_EQ_DBL(a, 0.5e-300);
    LH_EXPECT_EQ_DBL(total, 0.5e-300);
    /* a square of side 2e300: perimeter 8e300 exactly (sides as 1-simplices in R^2);
     * its area 4e600 is +inf */
    const double sq[8] = {-1e300, -1e300, 1e300, -1e300, 1e300, 1e300, -1e300, 1e300};
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(2, 4, sq, NULL, &h), LH_OK);
    double perimeter = 0, area = 0;
    LH_EXPECT_EQ_INT(lh_hull_measures(h, sq, 4, NULL, &perimeter, &area), LH_OK);
    LH_EXPECT_EQ_DBL(perimeter, 8e300);
    LH_EXPECT_TRUE(isinf(area));
    lh_hull_free(h);
    /* a triangle of area just below DBL_MAX whose doubled area is above it: the
     * division by 2! comes before the scaling, so no overflow on the way */
    const double big[6] = {0, 0, 0x1p513, 0, 0, 0x1.fffffffffffffp511};
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, big, 3, 1, tri, &a, &total), LH_OK);
    LH_EXPECT_EQ_DBL(a, 0x1.fffffffffffffp1023); /* DBL_MAX */
    LH_EXPECT_EQ_DBL(total, 0x1.fffffffffffffp1023);
    /* a right triangle tilted in R^3: area sqrt(2) / 2 (Cauchy-Binet over 3 minors) */
    const double tilt[9] = {0, 0, 0, 1, 0, 0, 0, 1, 1};
    LH_EXPECT_EQ_INT(lh_simplex_measures(3, 2, tilt, 3, 1, tri, &a, NULL), LH_OK);
    LH_EXPECT_TRUE(near_ulps(a, sqrt(0.5), 2));
    /* the standard 4-simplex: 1/24 within 2 ulps (one determinant, one division) */
    double s4[5 * 4] = {0};
    for (int i = 0; i < 4; i++) s4[(i + 1) * 4 + i] = 1;
    const lh_index simp[5] = {4, 0, 2, 1, 3};
    LH_EXPECT_EQ_INT(lh_simplex_measures(4, 4, s4, 5, 1, simp, &a, &total), LH_OK);
    LH_EXPECT_TRUE(near_ulps(a, 1.0 / 24, 2));
    LH_EXPECT_TRUE(near_ulps(total, 1.0 / 24, 2));
}

LH_TEST(bad_arguments)
{
    const double x[6] = {0, 0, 1, 0, 0, 1};
    const lh_index bad[3] = {0, 1, 3}, neg[3] = {0, -1, 2}, ok[3] = {0, 1, 2};
    double a;
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, x, 3, 1, bad, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, x, 3, 1, neg, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 3, x, 3, 1, ok, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_simplex_measures(9, 2, x, 3, 1, ok, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, NULL, 3, 1, ok, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_simplex_measures(2, 2, NULL, 0, 0, NULL, NULL, &a), LH_OK);
    LH_EXPECT_EQ_DBL(a, 0.0);
    LH_EXPECT_EQ_INT(lh_tri_measures(NULL, &a, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_hull_measures(NULL, x, 3, NULL, &a, NULL), LH_ERR_INVALID_ARGUMENT);
}

/* A total past DBL_MAX of finite measures is +inf, never nan (the compensated sum's
 * correction was inf - inf: qconvex FS printed -nan for sites near DBL_MAX). */
LH_TEST(totals_past_dbl_max_are_infinite)
{
    const double M = 1.7e308, x[8] = {0, 0, M, 0, M, M, 0, M};
    const lh_index edges[8] = {0, 1, 1, 2, 2, 3, 3, 0};
    double each[4], total;
    LH_ASSERT_EQ_INT(lh_simplex_measures(2, 1, x, 4, 4, edges, each, &total), LH_OK);
    for (int i = 0; i < 4; i++) LH_EXPECT_TRUE(near_ulps(each[i], M, 1));
    LH_EXPECT_TRUE(isinf(total) && total > 0);
    const double big[6] = {0, 0, 1e200, 0, 0, 1e200}; /* area 5e399: +inf, edges finite */
    const lh_index tri[3] = {0, 1, 2};
    LH_ASSERT_EQ_INT(lh_simplex_measures(2, 2, big, 3, 1, tri, each, &total), LH_OK);
    LH_EXPECT_TRUE(isinf(total) && total > 0);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(cube_far_from_origin_is_exact),
                                         LH_CASE(thin_huge_and_flat), LH_CASE(bad_arguments),
                                         LH_CASE(totals_past_dbl_max_are_infinite)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
