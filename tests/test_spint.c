/*
 * test_spint.c — the exact stage's sparse integers (spint.h) and its cost on mixed
 * magnitudes: digits against 128-bit arithmetic, and the work of an exact-stage call
 * (the internal counter lh_pred.exact_work: digit or limb pairs multiplied plus digits
 * or limbs written) bounded independently of the exponent range the call spans. With
 * dense integers the same calls cost a multiple of (range / 32)^2.
 */
#include "lh_test.h"
#include "lifthull.h"
#include "pred_internal.h"

#include <math.h>

static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint64_t next(void) { return lh_test_xorshift(&rng); }

/* The value of x (below 2^126 in magnitude); checks the representation's invariants. */
static __int128 value(lh_test_state *lh_t_, const lh__sp *x)
{
    __int128 v = 0;
    for (int i = x->n - 1; i >= 0; i--) {
        LH_EXPECT_TRUE(x->t[i].dig != 0);
        LH_EXPECT_TRUE(x->t[i].dig >= -(1 << 25) && x->t[i].dig < (1 << 25));
        if (i > 0) LH_EXPECT_TRUE(x->t[i - 1].off < x->t[i].off);
        v += (__int128)x->t[i].dig * ((__int128)1 << (LH__SP_BITS * x->t[i].off));
    }
    return v;
}

LH_TEST(digits_match_128_bit_arithmetic)
{
    static int64_t coef[64];
    static uint8_t flag[64];
    static lh__sd store[4096];
    lh__sp_acc acc;
    lh__sp_acc_init(&acc, coef, flag, 64);
    for (int it = 0; it < 20000 && !LH_FAILED(); it++) {
        lh__sp_pool pool = {store, 4096, 0};
        int64_t a = (int64_t)(next() >> (11 + next() % 50)) * ((next() & 1) ? 1 : -1);
        int64_t b = (int64_t)(next() >> (11 + next() % 50)) * ((next() & 1) ? 1 : -1);
        int64_t c = (int64_t)(next() >> 11) * ((next() & 1) ? 1 : -1);
        int sa = (int)(next() % 20) - 10, sb = (int)(next() % 20) - 10;
        lh__sp x, y, z;
        /* x = a 2^sa - c and y = b 2^sb at scale 2^-10 (times 2^10) */
        lh__sp_acc_add_dbl(&acc, ldexp((double)a, sa), -10, 0);
        lh__sp_acc_add_dbl(&acc, (double)c, -10, 1);
        LH_ASSERT_TRUE(lh__sp_acc_take(&acc, &pool, &x));
        lh__sp_acc_add_dbl(&acc, ldexp((double)b, sb), -10, 0);
        LH_ASSERT_TRUE(lh__sp_acc_take(&acc, &pool, &y));
        __int128 vx = value(lh_t_, &x), vy = value(lh_t_, &y);
        LH_EXPECT_TRUE(vx == (__int128)a * ((__int128)1 << (sa + 10)) - (__int128)c * 1024);
        LH_EXPECT_TRUE(vy == (__int128)b * ((__int128)1 << (sb + 10)));
        /* z = x y - y y + x, within 2^126 when |x|, |y| < 2^62 */
        if ((vx < 0 ? -vx : vx) >= ((__int128)1 << 62) || (vy < 0 ? -vy : vy) >= ((__int128)1 << 62))
            continue;
        lh__sp_acc_add_mul(&acc, &x, &y, 0);
        lh__sp_acc_add_mul(&acc, &y, &y, 1);
        lh__sp_acc_add(&acc, &x, 0);
        LH_ASSERT_TRUE(lh__sp_acc_take(&acc, &pool, &z));
        __int128 want = vx * vy - vy * vy + vx;
        LH_EXPECT_TRUE(value(lh_t_, &z) == want);
        LH_EXPECT_EQ_INT(lh__sp_sign(&z), want > 0 ? 1 : want < 0 ? -1 : 0);
        if (LH_FAILED()) LH_NOTE("iteration %d", it);
    }
}

/* A pool too small voids the value and leaves the accumulator clean. */
LH_TEST(a_full_pool_fails_cleanly)
{
    static int64_t coef[64];
    static uint8_t flag[64];
    lh__sd store[2];
    lh__sp_acc acc;
    lh__sp_acc_init(&acc, coef, flag, 64);
    lh__sp_pool pool = {store, 2, 0};
    lh__sp x;
    lh__sp_acc_add_dbl(&acc, 0x1.5555555555555p+200, 0, 0); /* 53 bits: three digits */
    LH_EXPECT_EQ_INT(lh__sp_acc_take(&acc, &pool, &x), 0);
    for (int i = 0; i < 64; i++) LH_EXPECT_TRUE(coef[i] == 0 && flag[i] == 0);
    lh__sp_acc_add_dbl(&acc, 0x1p+1000, -600, 0); /* offset 61: no room for carries */
    LH_EXPECT_EQ_INT(lh__sp_acc_take(&acc, &pool, &x), 0);
    pool.used = 0;
    lh__sp_acc_add_dbl(&acc, 3.0, 0, 0);
    LH_EXPECT_EQ_INT(lh__sp_acc_take(&acc, &pool, &x), 1);
    LH_EXPECT_TRUE(x.n == 1 && x.t[0].dig == 3);
}

/* Points (t, 0), (B, B), (0, -t) with B = 2^E, t = 2^-E: the rows p_i - p_0 are
 * (B - t, B) and (-t, -t), the terms B t cancel exactly, orient = t^2 > 0, some
 * 4E bits below the terms: no filter decides it, the exact stage does. Its work must
 * not grow with E (dense integers: entries of 2E bits, work ~ (2E / 32)^2). */
LH_TEST(exact_work_does_not_grow_with_the_exponent_range)
{
    lh_pred *ctx = NULL;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    static const int exps[] = {200, 400, 700, 1000};
    uint64_t first = 0;
    for (int k = 0; k < 4; k++) {
        double B = ldexp(1.0, exps[k]), t = ldexp(1.0, -exps[k]);
        double p0[2] = {t, 0}, p1[2] = {B, B}, p2[2] = {0, -t};
        const double *pts[3] = {p0, p1, p2};
        lh_pred_counters_reset(ctx);
        ctx->exact_work = 0;
        LH_EXPECT_EQ_INT(lh_orient(ctx, 2, pts), 1);
        lh_pred_counters c;
        lh_pred_counters_get(ctx, &c);
        LH_EXPECT_EQ_U64(c.exact_exits, 1);
        LH_NOTE("E %d: exact work %llu", exps[k], (unsigned long long)ctx->exact_work);
        LH_EXPECT_LE_U64(ctx->exact_work, 64);
        if (k == 0) first = ctx->exact_work;
        LH_EXPECT_EQ_U64(ctx->exact_work, first);
    }
    lh_pred_free(ctx);
}

/* insphere_5 calls of the 200-site mixed-magnitude reproducer
 * (tests/data/points/mixed_magnitudes_5d_200.txt) that reach the exact stage: large
 * terms cancel exactly, the sign sits about 1000 bits below them. Signs from an
 * independent exact evaluation (Python fractions, Gaussian elimination). */
static const struct {
    int sign;
    double p[7][5];
} repro_calls[] = {
#include "test_spint_cases.inc"
};

LH_TEST(mixed_magnitude_calls_are_exact_within_a_digit_budget)
{
    lh_pred *ctx = NULL;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    for (size_t k = 0; k < sizeof repro_calls / sizeof *repro_calls; k++) {
        const double *pts[7];
        for (int i = 0; i < 7; i++) pts[i] = repro_calls[k].p[i];
        lh_pred_counters_reset(ctx);
        ctx->exact_work = 0;
        LH_EXPECT_EQ_INT(lh_insphere(ctx, 5, pts), repro_calls[k].sign);
        lh_pred_counters c;
        lh_pred_counters_get(ctx, &c);
        LH_EXPECT_EQ_U64(c.exact_exits, 1);
        LH_NOTE("call %zu: exact work %llu", k, (unsigned long long)ctx->exact_work);
        LH_EXPECT_LE_U64(ctx->exact_work, 60000); /* dense integers: over 10^6 */
    }
    lh_pred_free(ctx);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(digits_match_128_bit_arithmetic), LH_CASE(a_full_pool_fails_cleanly),
        LH_CASE(exact_work_does_not_grow_with_the_exponent_range),
        LH_CASE(mixed_magnitude_calls_are_exact_within_a_digit_budget)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
