/*
 * sites.c — seeded random numbers and exactly cospherical integer sites (sites.h),
 * for `lifthull points` and the tests.
 *
 * References:
 *   - D. Blackman, S. Vigna, "Scrambled linear pseudorandom number generators",
 *     ACM TOMS 47(4), 2021: xoshiro256**, seeded through splitmix64.
 *   - G. Marsaglia, T. A. Bray, "A convenient method for generating normal random
 *     variables", SIAM Review 6(3), 1964: the polar method.
 *   - D. E. Knuth, TAOCP vol. 2, 3.4.2, Algorithm S: selection sampling.
 *   - G. H. Hardy, E. M. Wright, "An Introduction to the Theory of Numbers", ch. 16.9
 *     and 20: sums of two squares through Gaussian integers, r_2(n) = 4 prod (e_i + 1)
 *     when every prime factor of n is 1 mod 4; the average of r_d(n).
 *
 * Reproducibility: every value is computed with +, -, *, / and sqrt, which IEEE 754
 * rounds correctly, and floor/frexp, which are exact; the polar method's logarithm is
 * our own series in those operations (libm's log may differ in the last bit between
 * systems). Contraction into fused multiply-adds is off (GCC in ISO C mode by default,
 * clang through the pragma). So one seed gives the same numbers and sites on every
 * IEEE-754 machine with double evaluation.
 */
#include "sites.h"

#include "squares3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

/* ---- random numbers ------------------------------------------------------------ */

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

void lht_rng_seed(lht_rng *r, uint64_t seed)
{
    for (int i = 0; i < 4; i++) r->s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

uint64_t lht_rng_next(lht_rng *r)
{
    uint64_t *s = r->s;
    uint64_t out = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return out;
}

/* Uniform in [0, 1), a multiple of 2^-53. */
double lht_rng_unit(lht_rng *r) { return (double)(lht_rng_next(r) >> 11) * 0x1.0p-53; }

/* Uniform in [0, n), n >= 1, without modulo bias: draws below 2^64 mod n are redrawn,
 * so the accepted range is a whole number of copies of [0, n). */
uint64_t lht_rng_below(lht_rng *r, uint64_t n)
{
    uint64_t low = (0 - n) % n, x;
    do x = lht_rng_next(r);
    while (x < low);
    return x % n;
}

/* log(x), x > 0 finite, in +, -, *, / only: x = m 2^e with m in [sqrt(1/2), sqrt(2)),
 * log x = e log 2 + 2 atanh(z), z = (m - 1)/(m + 1), |z| < 0.172; the series to z^41
 * leaves a remainder below 1e-33. */
static double det_log(double x)
{
    int e;
    double m = frexp(x, &e); /* exact, m in [0.5, 1) */
    if (m < 0.70710678118654752) {
        m *= 2;
        e--;
    }
    double z = (m - 1) / (m + 1), z2 = z * z, s = 1.0 / 41;
    for (int k = 39; k >= 1; k -= 2) s = s * z2 + 1.0 / k;
    return e * 0.69314718055994530942 + 2 * z * s;
}

/* A standard normal variate by the polar method (the second variate is dropped). */
double lht_rng_normal(lht_rng *r)
{
    for (;;) {
        double u = 2 * lht_rng_unit(r) - 1, v = 2 * lht_rng_unit(r) - 1, s = u * u + v * v;
        if (s > 0 && s < 1) return u * sqrt(-2 * det_log(s) / s);
    }
}

/* ---- exactly cospherical integer points ------------------------------------------- */

/*
 * Design: choose a squared radius M with at least N integer points v, |v|^2 = M;
 * enumerate all of them in a fixed order and keep a uniformly random N of them by
 * selection sampling (keep the next candidate with probability still-needed /
 * still-left), streaming, so memory stays small.
 *   d = 2:  M = a product of primes p = 1 mod 4, chosen greedily (gain in points per
 *           factor of M) while M < 2^104, so that every coordinate (below 2^52 in
 *           magnitude) and every partial product is exact; p = pi conj(pi) in the Gaussian integers and
 *           the points are the 4 unit multiples of the products that take
 *           pi^j conj(pi)^(e-j) from each p^e: all r_2(M) = 4 prod (e + 1) of them.
 *   d >= 3: from M0, where the average of r_d (pi^(d/2) / Gamma(d/2) M^(d/2-1)) reaches
 *           N, the first M whose points suffice, found by enumerating the sorted
 *           tuples 0 <= a_1 <= .. <= a_d with sum a_i^2 = M; each tuple stands for its
 *           distinct permutations times the signs of its nonzero entries.
 */
static const int64_t gauss_prime[LHT_GAUSS_PRIMES] = {5,  13,  17,  29,  37,  41,  53,
                                                    61, 73,  89,  97,  101, 109, 113,
                                                    137, 149, 157, 173, 181, 193, 197};

/* M < 2^104 kept exactly in two limbs, M = hi 2^52 + lo with lo < 2^52. */
typedef struct circle_norm {
    uint64_t hi, lo;
} circle_norm;

/* 1 and *m times q (q < 2^11) when the product stays below 2^104, else 0 and *m kept. */
static int circle_norm_mul(circle_norm *m, uint64_t q)
{
    const uint64_t mask = (UINT64_C(1) << 52) - 1;
    uint64_t lo = m->lo * q, hi = m->hi * q + (lo >> 52);
    if (hi >> 52) return 0;
    m->hi = hi, m->lo = lo & mask;
    return 1;
}

/* d = 2: the greedy exponents; 0 when N points need M >= 2^104. */
static int plan_circle(lht_sphere *p, uint64_t n)
{
    uint64_t count = 1; /* prod (e + 1): the points are 4 * count */
    circle_norm m = {0, 1};
    while (4 * count < n) {
        int best = -1;
        double best_gain = 0;
        for (int i = 0; i < LHT_GAUSS_PRIMES; i++) {
            circle_norm t = m;
            if (!circle_norm_mul(&t, (uint64_t)gauss_prime[i])) continue;
            double g = det_log((p->exps[i] + 2.0) / (p->exps[i] + 1.0)) / det_log((double)gauss_prime[i]);
            if (g > best_gain) best = i, best_gain = g;
        }
        if (best < 0) return 0;
        count = count / (uint64_t)(p->exps[best] + 1) * (uint64_t)(p->exps[best] + 2);
        p->exps[best]++;
        circle_norm_mul(&m, (uint64_t)gauss_prime[best]);
    }
    p->total = 4 * count;
    return 1;
}

/* Distinct signed permutations of a sorted tuple: d! / prod(run length!) * 2^nonzeros. */
static uint64_t signed_perms(const int64_t *a, int d)
{
    uint64_t perms = 1; /* after step i: the multinomial of a[0..i], an integer */
    int run = 1;
    for (int i = 1; i < d; i++) {
        perms *= (uint64_t)(i + 1);
        if (a[i] == a[i - 1]) perms /= (uint64_t)++run;
        else run = 1;
    }
    for (int i = 0; i < d; i++)
        if (a[i]) perms *= 2;
    return perms;
}

static int push_tuple(lht_sphere *p, const int64_t *a)
{
    if (p->tuple_count == p->tuple_cap) {
        size_t cap = p->tuple_cap ? 2 * p->tuple_cap : 64;
        int64_t *t = realloc(p->tuples, cap * (size_t)p->d * sizeof *t);
        if (!t) return -1;
        p->tuples = t;
        p->tuple_cap = cap;
    }
    memcpy(p->tuples + p->tuple_count++ * (size_t)p->d, a, (size_t)p->d * sizeof *a);
    return 0;
}

static int take_triple(void *ctx, const int64_t t[3])
{
    lht_sphere *p = ctx;
    p->total += signed_perms(t, 3);
    return push_tuple(p, t);
}

/* Sorted tuples a[pos..d-1] >= lo with squares summing to rem; -1 out of memory
 * (d >= 4; in 3D lht_squares3_each finds them in about sqrt(m) steps, not m). */
static int find_tuples(lht_sphere *p, int64_t *a, int pos, int64_t lo, uint64_t rem)
{
    if (pos == p->d - 1) {
        uint64_t s = lht_isqrt(rem);
        if (s * s != rem || (int64_t)s < lo) return 0;
        a[pos] = (int64_t)s;
        p->total += signed_perms(a, p->d);
        return push_tuple(p, a);
    }
    for (int64_t v = lo; (uint64_t)(p->d - pos) * (uint64_t)(v * v) <= rem; v++) {
        a[pos] = v;
        if (find_tuples(p, a, pos + 1, v, rem - (uint64_t)(v * v)) != 0) return -1;
    }
    return 0;
}

/* d >= 3: the first M from M0 on with at least n points. 1 found, 0 none below 2^50,
 * -1 out of memory. M0 by bisection on c_d^2 M^(d-2) >= n^2 (products only). */
static int plan_sphere(lht_sphere *p, uint64_t n)
{
    static const double c2[LHT_MAX_DIM + 1] = {0, 0, 0, 39.47841760435743, 97.40909103400243,
        173.17171739378205, 240.34729839382604, 273.46181506141994, 263.5703060019603};
    uint64_t lo = 0, hi = UINT64_C(1) << 50;
    while (hi - lo > 1) {
        uint64_t mid = lo + (hi - lo) / 2;
        double v = c2[p->d];
        for (int i = 0; i < p->d - 2; i++) v *= (double)mid;
        if (v >= (double)n * (double)n) hi = mid;
        else lo = mid;
    }
    int64_t a[LHT_MAX_DIM];
    for (uint64_t m = hi, tries = 0; m < (UINT64_C(1) << 50); m++) {
        if (p->d == 3 && (m % 8 == 7 || m % 4 == 0)) continue; /* none, or 2x those of m/4 */
        p->tuple_count = 0;
        p->total = 0;
        if ((p->d == 3 ? lht_squares3_each(m, take_triple, p) : find_tuples(p, a, 0, 0, m)) != 0)
            return -1;
        if (p->total >= n) {
            p->m = m;
            return 1;
        }
        if (++tries % 16 == 0) m += m / 8; /* unlucky stretch: move on faster */
    }
    return 0;
}

/* Selection sampling into the output: each candidate kept with probability need/left. */
typedef struct picker {
    lht_site_fn emit;
    void *ctx;
    lht_rng *r;
    int d;
    uint64_t need, left;
} picker;

static void pick(picker *k, const int64_t *v)
{
    if (k->need && lht_rng_below(k->r, k->left) < k->need) {
        double x[LHT_MAX_DIM];
        for (int j = 0; j < k->d; j++) x[j] = (double)v[j];
        k->emit(k->ctx, k->d, x);
        k->need--;
    }
    k->left--;
}

/* d = 2: every point of the circle, choice by choice (a mixed-radix counter j[i] in
 * 0..exps[i]), through the picker. */
static void offer_circle(const lht_sphere *p, picker *k)
{
    int64_t root[LHT_GAUSS_PRIMES][2];
    int j[LHT_GAUSS_PRIMES] = {0};
    for (int i = 0; i < LHT_GAUSS_PRIMES; i++) /* p = a^2 + b^2, a > b > 0 */
        lht_gauss_split((uint64_t)gauss_prime[i], root[i]);
    for (;;) {
        int64_t z[2] = {1, 0};
        for (int i = 0; i < LHT_GAUSS_PRIMES; i++)
            for (int t = 0; t < p->exps[i]; t++) lht_gauss_mul(z, root[i][0], t < j[i] ? root[i][1] : -root[i][1]);
        int64_t units[4][2] = {{z[0], z[1]}, {-z[1], z[0]}, {-z[0], -z[1]}, {z[1], -z[0]}};
        for (int u = 0; u < 4; u++) pick(k, units[u]);
        int i = 0;
        while (i < LHT_GAUSS_PRIMES && ++j[i] > p->exps[i]) j[i++] = 0;
        if (i == LHT_GAUSS_PRIMES) return;
    }
}

/* Lexicographic successor of a multiset permutation; 0 after the last. */
static int next_perm(int64_t *a, int d)
{
    int i = d - 2;
    while (i >= 0 && a[i] >= a[i + 1]) i--;
    if (i < 0) return 0;
    int j = d - 1;
    while (a[j] <= a[i]) j--;
    int64_t t = a[i];
    a[i] = a[j];
    a[j] = t;
    for (int lo = i + 1, hi = d - 1; lo < hi; lo++, hi--) t = a[lo], a[lo] = a[hi], a[hi] = t;
    return 1;
}

/* d >= 3: each tuple's permutations, each with every sign pattern of its nonzeros. */
static void offer_sphere(const lht_sphere *p, picker *k)
{
    int64_t a[LHT_MAX_DIM], v[LHT_MAX_DIM];
    for (size_t t = 0; t < p->tuple_count; t++) {
        memcpy(a, p->tuples + t * (size_t)p->d, (size_t)p->d * sizeof *a);
        do {
            int nz = 0;
            for (int j = 0; j < p->d; j++) nz += a[j] != 0;
            for (uint32_t mask = 0; mask < (UINT32_C(1) << nz); mask++) {
                for (int j = 0, b = 0; j < p->d; j++)
                    v[j] = a[j] && ((mask >> b++) & 1) ? -a[j] : a[j];
                pick(k, v);
            }
        } while (next_perm(a, p->d));
    }
}

/* The most points --exact-sphere gives in 2D (M < 2^104). */
uint64_t lht_circle_max(void)
{
    lht_sphere p = {.d = 2};
    plan_circle(&p, UINT64_MAX);
    uint64_t count = 4;
    for (int i = 0; i < LHT_GAUSS_PRIMES; i++) count *= (uint64_t)(p.exps[i] + 1);
    return count;
}

int lht_sphere_plan(lht_sphere *p, int d, uint64_t n)
{
    memset(p, 0, sizeof *p);
    p->d = d;
    return d == 2 ? plan_circle(p, n) : plan_sphere(p, n);
}

void lht_sphere_pick(const lht_sphere *p, lht_rng *r, uint64_t n, lht_site_fn emit, void *ctx)
{
    picker k = {emit, ctx, r, p->d, n, p->total};
    if (p->d == 2) offer_circle(p, &k);
    else offer_sphere(p, &k);
}

void lht_sphere_free(lht_sphere *p)
{
    free(p->tuples);
    p->tuples = NULL;
    p->tuple_count = p->tuple_cap = 0;
}
