/* test_squares3.c — tools/squares3.c's sieve against the plain enumeration of
 * a <= b <= c with a^2 + b^2 + c^2 = m, and the 3D sphere plan built on it. */
#include "lh_test.h"
#include "sites.h"
#include "squares3.h"

#include <string.h>

enum { CAP = 8192, FULL = 7, PAST = 8 };

typedef struct triples {
    int64_t t[3 * CAP];
    size_t n;
    int64_t a_max; /* the triples with a <= a_max only */
} triples;

static int take(void *ctx, const int64_t t[3])
{
    triples *l = ctx;
    if (t[0] > l->a_max) return PAST; /* lexicographic: none of the rest is wanted */
    if (l->n == CAP) return FULL;
    memcpy(l->t + 3 * l->n++, t, 3 * sizeof *t);
    return 0;
}

/* The definition: lexicographic by construction, about sqrt(m) steps per a. */
static void enumerate(uint64_t m, triples *l)
{
    for (int64_t a = 0; a <= l->a_max && (uint64_t)(3 * a * a) <= m; a++)
        for (int64_t b = a; (uint64_t)(a * a + 2 * b * b) <= m; b++) {
            uint64_t r = m - (uint64_t)(a * a + b * b), c = lht_isqrt(r);
            const int64_t t[3] = {a, b, (int64_t)c};
            if (c * c == r && (int64_t)c >= b) take(l, t);
        }
}

static void same_as_enumeration(lh_test_state *lh_t_, uint64_t m, int64_t a_max, int status)
{
    static triples got, want;
    got.n = want.n = 0;
    got.a_max = want.a_max = a_max;
    LH_EXPECT_EQ_INT(lht_squares3_each(m, take, &got), status);
    enumerate(m, &want);
    LH_EXPECT_EQ_U64(got.n, want.n);
    int same = got.n == want.n && memcmp(got.t, want.t, 3 * got.n * sizeof *got.t) == 0;
    if (!same) LH_NOTE("m = %llu: the triples differ", (unsigned long long)m);
    LH_EXPECT_TRUE(same);
}

/* Every m to 3000 (squares, 7 mod 8, powers of 2, 4^k (8j + 7) among them) whole. */
LH_TEST(sieve_finds_every_triple_in_order)
{
    for (uint64_t m = 1; m <= 3000 && !LH_FAILED(); m++) same_as_enumeration(lh_t_, m, INT64_MAX, 0);
}

/* Large m, their first 40 values of a: m - a^2 has prime factors above 2^32 (mulmod's
 * wide path) and up to 2^40. */
LH_TEST(sieve_agrees_on_large_m)
{
    const uint64_t m[] = {(UINT64_C(1) << 40) + 1, (UINT64_C(1) << 40) + 5, 1000000000037u * 5,
                          (UINT64_C(1) << 36) * 25 + 13};
    for (size_t i = 0; i < sizeof m / sizeof *m && !LH_FAILED(); i++) same_as_enumeration(lh_t_, m[i], 40, PAST);
}

LH_TEST(each_stops_on_a_nonzero_return)
{
    triples l = {.n = CAP, .a_max = INT64_MAX};
    LH_EXPECT_EQ_INT(lht_squares3_each(3 * 3 * 5 * 5 * 13, take, &l), FULL);
}

/* The plan counts r_3(m) points: every signed permutation of every triple. */
LH_TEST(sphere_plan_counts_every_lattice_point)
{
    lht_sphere p;
    LH_ASSERT_EQ_INT(lht_sphere_plan(&p, 3, 1000), 1);
    uint64_t count = 0;
    const int64_t r = (int64_t)lht_isqrt(p.m);
    for (int64_t x = -r; x <= r; x++)
        for (int64_t y = -r; y <= r; y++) {
            const int64_t z2 = (int64_t)p.m - x * x - y * y;
            const int64_t z = z2 < 0 ? -1 : (int64_t)lht_isqrt((uint64_t)z2);
            if (z >= 0 && z * z == z2) count += z ? 2 : 1;
        }
    LH_EXPECT_EQ_U64(p.total, count);
    LH_EXPECT_TRUE(p.total >= 1000);
    lht_sphere_free(&p);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(sieve_finds_every_triple_in_order),
                                         LH_CASE(sieve_agrees_on_large_m),
                                         LH_CASE(each_stops_on_a_nonzero_return),
                                         LH_CASE(sphere_plan_counts_every_lattice_point)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
