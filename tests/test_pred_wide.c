/*
 * test_pred_wide.c — the wide-exponent filter (pred_wide.c) on sites that mix
 * magnitudes the double filter cannot hold in one product (1e+300, 1e-300, 5e-324,
 * 0, small integers): every sign it claims is the exact stage's, it claims most of
 * them, and triangulations of such sites are exactly valid while the exact stage
 * answers only a share of the predicate calls (before it, every call went there:
 * 20 sites in 8D took about a minute).
 */
#include "lh_test.h"
#include "lifthull.h"
#include "pred_internal.h"

#include <math.h>
#include <stdlib.h>

static uint64_t rng = 0x243F6A8885A308D3u;
static uint64_t next(void) { return lh_test_xorshift(&rng); }

/* A coordinate drawn as in the reproducer: a few values of each magnitude. */
static double mixed_value(void)
{
    static const double pool[] = {1e300, -5e300, 9.000000000000001e300, 2e300, -7e300,
                                  -3e-300, 4e-300, -5e-300, 1e-323, 2.5e-323, 5e-324,
                                  0.0, 1.0, 5.0, -2.0};
    double x = pool[next() % (sizeof pool / sizeof *pool)];
    return (next() & 3) == 0 ? x * (double)(1 + next() % 7) : x;
}

LH_TEST(claimed_signs_are_exact)
{
    lh_pred *ctx = NULL;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    double p[LH__MAXN][8];
    const double *row[LH__MAXN];
    for (int i = 0; i < LH__MAXN; i++) row[i] = p[i];
    long claimed = 0, cases = 0;
    for (int d = 2; d <= 8 && !LH_FAILED(); d++)
        for (int lifted = 0; lifted <= 1; lifted++)
            for (int k = 0; k < (d < 6 ? 400 : 60) && !LH_FAILED(); k++) {
                for (int i = 0; i < d + 1 + lifted; i++)
                    for (int c = 0; c < d; c++) p[i][c] = mixed_value();
                int s = 0;
                cases++;
                if (!lh__wide_sign(&ctx->sub, d, lifted, row, 0, &s) &&
                    !lh__wide_sign(&ctx->sub, d, lifted, row, 1, &s))
                    continue;
                claimed++;
                int exact = lifted ? lh__insphere_exact(ctx, d, row) : lh__orient_exact(ctx, d, row);
                if (s != exact) {
                    LH_NOTE("d %d lifted %d case %d: wide %d, exact %d", d, lifted, k, s, exact);
                    LH_EXPECT_EQ_INT(s, exact);
                }
            }
    LH_EXPECT_GT_INT(claimed, cases / 2);
    lh_pred_free(ctx);
}

/* Triangulates the n sites x in R^d: exactly valid, and at most per_mille / 1000 of
 * the predicate calls reach the exact stage. */
static void few_exact(lh_test_state *lh_t_, int d, size_t n, const double *x, unsigned per_mille)
{
    lh_options opt;
    lh_options_default(&opt);
    lh_tri *t = NULL;
    LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, &opt, &t), LH_OK);
    lh_error err;
    LH_EXPECT_EQ_INT(lh_delaunay_check(d, n, x, lh_tri_count(t), lh_tri_simplices(t), NULL, &err),
                     LH_OK);
    lh_pred_counters c;
    lh_tri_pred_counters_get(t, &c);
    LH_NOTE("d %d n %zu: calls %llu, exact %llu, zero %llu", d, n, (unsigned long long)c.calls,
            (unsigned long long)c.exact_exits, (unsigned long long)c.zero_results);
    LH_EXPECT_LE_U64(c.exact_exits * 1000, c.calls * per_mille);
    lh_tri_free(t);
}

/* n mixed-magnitude sites in R^d (all their calls were exact without this filter). */
static void triangulate_mixed(lh_test_state *lh_t_, int d, size_t n, unsigned percent)
{
    double *x = malloc(n * (size_t)d * sizeof *x);
    LH_ASSERT_TRUE(x != NULL);
    for (size_t i = 0; i < n * (size_t)d; i++) x[i] = mixed_value();
    few_exact(lh_t_, d, n, x, 10 * percent);
    free(x);
}

LH_TEST(mixed_magnitudes_triangulate_without_the_exact_stage)
{
    /* The rest are near-cancellations: large terms that cancel exactly, leaving a
     * determinant far below the rounding error of the large ones. */
    triangulate_mixed(lh_t_, 8, 20, 1);
    triangulate_mixed(lh_t_, 5, 60, 5);
    triangulate_mixed(lh_t_, 3, 200, 15);
}

/* n sites in R^d from 10 Gaussian clusters with standard deviations 1e-6 .. 1e-2
 * (Box-Muller) about uniform centres. */
static void clustered(int d, size_t n, double *x)
{
    double centre[10][8];
    for (int c = 0; c < 10; c++)
        for (int j = 0; j < d; j++) centre[c][j] = (double)(next() >> 11) * 0x1p-53;
    for (size_t i = 0; i < n; i++) {
        int c = (int)(i % 10);
        double sigma = pow(10.0, -6.0 + 4.0 * c / 9.0);
        for (int j = 0; j < d; j++) {
            double u = ((double)(next() >> 11) + 1) * 0x1p-53, v = (double)(next() >> 11) * 0x1p-53;
            x[i * (size_t)d + j] = centre[c][j] + sigma * sqrt(-2 * log(u)) * cos(6.283185307179586 * v);
        }
    }
}

/* Cells with most points in one tight cluster and one far away: subtracting a far
 * point makes the expansion cancel; the filter's pivot in the cluster does not, so
 * the exact stage answers almost nothing (it answered 10% of the calls in 5D). */
LH_TEST(clustered_sites_avoid_the_exact_stage)
{
    enum { N = 300, D = 5 };
    static double x[N * D];
    clustered(D, N, x);
    few_exact(lh_t_, D, N, x, 10); /* at most 1% */
}

/* The grid {0,1,2}^5 with every coordinate x moved to x (1 + 1e-12 u) (0 to 1e-12 u),
 * u uniform in [-1, 1): determinants about 1e-12 of their terms, beyond the double
 * filters, decided by the double-word stage (6.5% of the calls were exact before). */
LH_TEST(perturbed_grid_avoids_the_exact_stage)
{
    enum { N = 243, D = 5 };
    static double x[N * D];
    for (int i = 0; i < N; i++)
        for (int j = 0, v = i; j < D; j++, v /= 3) {
            double u = (double)(next() >> 11) * 0x1p-52 - 1.0;
            x[i * D + j] = v % 3 ? (v % 3) * (1.0 + 1e-12 * u) : 1e-12 * u;
        }
    few_exact(lh_t_, D, N, x, 1); /* at most 0.1% */
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(claimed_signs_are_exact),
        LH_CASE(mixed_magnitudes_triangulate_without_the_exact_stage),
        LH_CASE(clustered_sites_avoid_the_exact_stage),
        LH_CASE(perturbed_grid_avoids_the_exact_stage)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
