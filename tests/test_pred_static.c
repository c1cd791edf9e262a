/*
 * test_pred_static.c — the static filters of the fixed-dimension engines
 * (lh_filter.gen.h: lh__orient_static_d, lh__insphere_static_d, lh__static_bound):
 * over a point set, with the bound from the set's column spans, every sign they
 * claim is the exact sign (lh_orient / lh_insphere), on sets made to be hard:
 * integer grids (exact zeros), grids moved by 1e-12, a large offset with a small
 * spread, mixed magnitudes, near-cospherical points. Also: a span outside the band
 * disables the filter, and a bound 10^6 times too small is caught (the test can
 * fail). The paired insphere filter (lh__static2_d) gives each lane the sign the
 * single one gives, under the real bound and under no bound at all (the rounded
 * determinant's own sign, so every operation must match).
 */
#include "lh_families.h"
#include "lh_filter.gen.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>

static int static_sign(int lifted, int d, const double *const *p, double eb)
{
    switch (d * 2 + lifted) {
    case 4: return lh__orient_static_2(p, eb);
    case 5: return lh__insphere_static_2(p, eb);
    case 6: return lh__orient_static_3(p, eb);
    case 7: return lh__insphere_static_3(p, eb);
    case 8: return lh__orient_static_4(p, eb);
    case 9: return lh__insphere_static_4(p, eb);
    case 10: return lh__orient_static_5(p, eb);
    default: return lh__insphere_static_5(p, eb);
    }
}

static void spans(int d, size_t n, const double *x, double *span)
{
    for (int j = 0; j < d; j++) {
        double lo = x[j], hi = x[j];
        for (size_t i = 1; i < n; i++) {
            lo = fmin(lo, x[i * d + j]);
            hi = fmax(hi, x[i * d + j]);
        }
        span[j] = hi - lo;
    }
}

/* Random tuples of the set: returns the number of wrong claims; *decided counts the
 * claims. `shrink` scales the bound (1: the real one). */
static long run(lh_pred *ctx, int lifted, int d, size_t n, const double *x, double shrink, long *decided)
{
    double span[8];
    spans(d, n, x, span);
    double eb = lh__static_bound(lifted, d, span) * shrink;
    long wrong = 0;
    for (int t = 0; t < 4000; t++) {
        const double *p[8];
        for (int i = 0; i < d + 1 + lifted; i++) p[i] = x + (lh_fam_rnd() % n) * d;
        int s = static_sign(lifted, d, p, eb);
        if (!s) continue;
        ++*decided;
        int exact = lifted ? lh_insphere(ctx, d, p) : lh_orient(ctx, d, p);
        wrong += s != exact;
    }
    return wrong;
}

LH_TEST(claims_are_exact_signs)
{
    static const int fams[] = {F_CUBE, F_GRID, F_GRID_JITTER, F_OFFSET_1E9, F_SPREAD_1E9, F_MIXED,
                               F_NEAR_PLANE, F_SPHERE_EXACT};
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    for (int d = 2; d <= 5; d++)
        for (size_t f = 0; f < LH_COUNT(fams); f++)
            for (int lifted = 0; lifted < 2; lifted++) {
                double *x = malloc(200 * d * sizeof *x);
                lh_fam_seed((uint64_t)(100 * d + f));
                size_t n = lh_fam_make(fams[f], d, 200, x);
                long decided = 0, wrong = run(ctx, lifted, d, n, x, 1, &decided);
                if (wrong) LH_NOTE("d=%d %s %s: %ld wrong of %ld", d, lifted ? "insphere" : "orient", lh_fam_name[fams[f]], wrong, decided);
                LH_EXPECT_EQ_INT(wrong, 0);
                if (fams[f] == F_CUBE) LH_EXPECT_GT_INT(decided, 3000); /* it does decide (repeats give 0) */
                free(x);
            }
    lh_pred_free(ctx);
}

LH_TEST(a_too_small_bound_is_caught)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    long wrong = 0, decided = 0;
    for (int d = 2; d <= 3; d++) {
        double *x = malloc(200 * d * sizeof *x);
        lh_fam_seed(7);
        size_t n = lh_fam_make(F_GRID_JITTER, d, 200, x);
        for (int lifted = 0; lifted < 2; lifted++) wrong += run(ctx, lifted, d, n, x, 1e-6, &decided);
        free(x);
    }
    LH_EXPECT_GT_INT(wrong, 0);
    lh_pred_free(ctx);
}

LH_TEST(paired_filter_matches_single_lane_by_lane)
{
#ifdef __GNUC__
    LH_EXPECT_TRUE(LH__HAVE_V2D); /* the vector path is the one tested */
#endif
    static const int fams[] = {F_CUBE, F_GRID, F_GRID_JITTER, F_OFFSET_1E9, F_MIXED, F_SPHERE_EXACT};
    long compared = 0, mismatched = 0;
    for (int d = 2; d <= 5; d++)
        for (size_t f = 0; f < LH_COUNT(fams); f++) {
            double *x = malloc(200 * d * sizeof *x), span[8];
            lh_fam_seed((uint64_t)(300 * d + f));
            size_t n = lh_fam_make(fams[f], d, 200, x);
            spans(d, n, x, span);
            const double bounds[2] = {lh__static_bound(1, d, span), 0};
            for (int t = 0; t < 2000; t++) {
                const double *p[8], *r[8];
                for (int i = 0; i < d + 2; i++) {
                    p[i] = x + (lh_fam_rnd() % n) * d;
                    r[i] = x + (lh_fam_rnd() % n) * d;
                }
                for (int b = 0; b < 2; b++) {
                    int two[2];
                    lh__static2_d(d, p, r, bounds[b], two);
                    mismatched += (two[0] != static_sign(1, d, p, bounds[b])) + (two[1] != static_sign(1, d, r, bounds[b]));
                    compared += 2;
                }
            }
            free(x);
        }
    LH_EXPECT_EQ_INT(mismatched, 0);
    LH_EXPECT_GT_INT(compared, 90000);
}

LH_TEST(out_of_band_spans_disable_the_filter)
{
    const double tiny[3] = {1e-200, 1, 1}, huge[3] = {1, 1e200, 1}, zero[3] = {0, 1, 1}, fine[3] = {1, 2, 3};
    LH_EXPECT_TRUE(isinf(lh__static_bound(1, 3, tiny)));
    LH_EXPECT_TRUE(isinf(lh__static_bound(0, 3, huge)));
    LH_EXPECT_TRUE(isinf(lh__static_bound(1, 3, zero)));
    LH_EXPECT_TRUE(isfinite(lh__static_bound(1, 3, fine)) && lh__static_bound(1, 3, fine) > 0);
    LH_EXPECT_TRUE(isinf(lh__static_bound(1, 6, fine)));
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(claims_are_exact_signs), LH_CASE(a_too_small_bound_is_caught),
                                         LH_CASE(paired_filter_matches_single_lane_by_lane),
                                         LH_CASE(out_of_band_spans_disable_the_filter)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
