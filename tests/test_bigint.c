/* test_bigint.c — the exact stage's integers against 128-bit and known values. */
#include "bigint.h"
#include "lh_test.h"

#include <math.h>

static uint32_t store[8][200];

static lh__bn mk(int i)
{
    lh__bn b = {store[i], 0, 0};
    return b;
}

/* Value of a bignum of at most 4 limbs as a signed 128-bit integer. */
static __int128 val(const lh__bn *a)
{
    unsigned __int128 v = 0;
    for (int i = a->n - 1; i >= 0; i--) v = (v << 32) | a->d[i];
    return a->neg ? -(__int128)v : (__int128)v;
}

static uint64_t rng = 88172645463325252u;
static uint64_t next(void) { return lh_test_xorshift(&rng); }

LH_TEST(doubles_convert_exactly)
{
    lh__bn a = mk(0);
    lh__bn_set_dbl(&a, 3.0, 0);
    LH_EXPECT_EQ_INT(a.n, 1);
    LH_EXPECT_EQ_U64(a.d[0], 3);
    lh__bn_set_dbl(&a, -0.75, -2);
    LH_EXPECT_EQ_INT((long long)val(&a), -3);
    lh__bn_set_dbl(&a, 0.0, -5);
    LH_EXPECT_EQ_INT(lh__bn_sign(&a), 0);
    LH_EXPECT_EQ_INT(lh__dbl_low_exp(0x1p-1074), -1074);
    LH_EXPECT_EQ_INT(lh__dbl_low_exp(12.0), 2);
    LH_EXPECT_EQ_INT(lh__dbl_low_exp(0x1.0000000000001p+1023), 1023 - 52);
    /* The widest span: DBL_MAX at the scale of the smallest subnormal, 2098 bits. */
    lh__bn_set_dbl(&a, 0x1.fffffffffffffp+1023, -1074);
    LH_EXPECT_EQ_INT(a.n, 66);
    LH_EXPECT_EQ_U64(a.d[65], 0x3ffff); /* bits 2080..2097: the top 18 of 53 */
    LH_EXPECT_EQ_U64(a.d[63], 0xe0000000u); /* lowest set bit: 971 + 1074 = 2045 = 63*32 + 29 */
}

LH_TEST(products_and_sums_match_128_bit_arithmetic)
{
    lh__bn a = mk(0), b = mk(1), p = mk(2), s = mk(3);
    for (int i = 0; i < 20000 && !LH_FAILED(); i++) {
        int64_t x = (int64_t)(next() >> 11) * ((next() & 1) ? 1 : -1);
        int64_t y = (int64_t)(next() >> (11 + next() % 40)) * ((next() & 1) ? 1 : -1);
        lh__bn_set_dbl(&a, (double)x, 0);
        lh__bn_set_dbl(&b, (double)y, 0);
        lh__bn_mul(&p, &a, &b);
        LH_EXPECT_TRUE(val(&p) == (__int128)x * y);
        lh__bn_add(&s, &a, &b, 0);
        LH_EXPECT_TRUE(val(&s) == (__int128)x + y);
        lh__bn_add(&s, &a, &b, 1);
        LH_EXPECT_TRUE(val(&s) == (__int128)x - y);
        lh__bn_add(&a, &a, &b, 1); /* aliasing r == a */
        LH_EXPECT_TRUE(val(&a) == (__int128)x - y);
        if (LH_FAILED()) LH_NOTE("x=%lld y=%lld", (long long)x, (long long)y);
    }
}

LH_TEST(cancellation_reaches_exact_zero)
{
    lh__bn a = mk(0), b = mk(1), p = mk(2), q = mk(3);
    lh__bn_set_dbl(&a, ldexp(1.0, 600) + ldexp(1.0, 548), -100);
    lh__bn_set_dbl(&b, ldexp(1.0, 600) + ldexp(1.0, 548), -100);
    lh__bn_mul(&p, &a, &b);
    lh__bn_mul(&q, &b, &a);
    lh__bn_add(&p, &p, &q, 1);
    LH_EXPECT_EQ_INT(lh__bn_sign(&p), 0);
    LH_EXPECT_EQ_INT(p.n, 0);
    LH_EXPECT_EQ_INT(p.neg, 0);
}

/* Limbs drawn from zero, all ones and random, so that products meet runs of each
 * (lh__bn_mul takes a run of all-ones limbs as a difference of two powers). */
static void sparse_limbs(lh__bn *x, int n)
{
    for (int i = 0; i < n; i++) {
        uint64_t r = next() % 5;
        x->d[i] = r < 2 ? 0 : r < 4 ? 0xffffffffu : (uint32_t)next();
    }
    if (!x->d[n - 1]) x->d[n - 1] = (next() & 1) ? 0xffffffffu : 1 + (uint32_t)(next() % 1000);
    x->n = n;
    x->neg = (int)(next() & 1);
}

LH_TEST(products_with_runs_of_zero_and_one_limbs_match_schoolbook)
{
    lh__bn a = mk(0), b = mk(1), p = mk(2);
    for (int it = 0; it < 20000 && !LH_FAILED(); it++) {
        sparse_limbs(&a, 1 + (int)(next() % 40));
        sparse_limbs(&b, 1 + (int)(next() % 40));
        lh__bn_mul(&p, &a, &b);
        uint32_t want[80] = {0};
        for (int i = 0; i < a.n; i++) {
            uint64_t carry = 0;
            for (int j = 0; j < b.n; j++) {
                uint64_t t = (uint64_t)a.d[i] * b.d[j] + want[i + j] + carry;
                want[i + j] = (uint32_t)t;
                carry = t >> 32;
            }
            want[i + b.n] = (uint32_t)carry;
        }
        int wn = a.n + b.n;
        while (wn > 0 && !want[wn - 1]) wn--;
        LH_EXPECT_EQ_INT(p.n, wn);
        LH_EXPECT_EQ_INT(p.neg, a.neg ^ b.neg);
        for (int i = 0; i < wn && i < p.n && !LH_FAILED(); i++) LH_EXPECT_EQ_U64(p.d[i], want[i]);
        if (LH_FAILED()) LH_NOTE("iteration %d: %d x %d limbs", it, a.n, b.n);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(doubles_convert_exactly),
                                         LH_CASE(products_and_sums_match_128_bit_arithmetic),
                                         LH_CASE(cancellation_reaches_exact_zero),
                                         LH_CASE(products_with_runs_of_zero_and_one_limbs_match_schoolbook)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
