/* bigint.c — schoolbook signed-magnitude integers for the predicates' exact stage
 * (Knuth, TAOCP vol. 2, 4.3.1, algorithms A, S and M). */
#include "bigint.h"

#include <string.h>

/* Trailing zero bits of m != 0. */
static int low_zero_bits(uint64_t m)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(m);
#else
    int z = 0;
    while (!(m & 1)) {
        m >>= 1;
        z++;
    }
    return z;
#endif
}

uint64_t lh__dbl_decompose(double x, int *e, int *neg)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    *neg = (int)(bits >> 63);
    int biased = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
    if (biased == 0) {
        *e = -1074;
    } else {
        m |= UINT64_C(1) << 52;
        *e = biased - 1075;
    }
    return m;
}

int lh__dbl_low_exp(double x)
{
    int e, neg;
    uint64_t m = lh__dbl_decompose(x, &e, &neg);
    return m ? e + low_zero_bits(m) : 0;
}

static void trim(lh__bn *r)
{
    while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
    if (r->n == 0) r->neg = 0;
}

void lh__bn_set_dbl(lh__bn *r, double x, int scale)
{
    int e, neg;
    uint64_t m = lh__dbl_decompose(x, &e, &neg);
    r->n = 0;
    r->neg = 0;
    if (!m) return;
    int z = low_zero_bits(m);
    m >>= z;
    int shift = e + z - scale; /* >= 0 by precondition, up to 2097 */
    int limb = shift / 32, bit = shift % 32;
    memset(r->d, 0, (size_t)limb * sizeof *r->d);
    /* m << bit spans at most 85 bits: three limbs. */
    uint64_t lo = m << bit;
    uint64_t hi = bit ? m >> (64 - bit) : 0;
    r->d[limb] = (uint32_t)lo;
    r->d[limb + 1] = (uint32_t)(lo >> 32);
    r->d[limb + 2] = (uint32_t)hi;
    r->n = limb + 3;
    r->neg = neg;
    trim(r);
}

/* Limb classes for the product: zero, all ones (2^32 - 1) and plain. */
#define ONES UINT32_C(0xffffffff)

/* End of the run of limbs of x starting at j that are all ones (ones = 1) or all
 * plain (ones = 0). */
static int run_end(const lh__bn *x, int j, int ones)
{
    while (j < x->n && x->d[j] && ((x->d[j] == ONES) == ones)) j++;
    return j;
}

/* Counts for the cost of lh__bn_mul: nonzero limbs, limbs multiplied when x is the
 * inner factor (all but runs of ones below the top limb) and those runs of ones. */
typedef struct mul_counts {
    long nz, plain, ones;
} mul_counts;

static mul_counts count_limbs(const lh__bn *x)
{
    mul_counts c = {0, 0, 0};
    for (int j = 0; j < x->n;) {
        if (!x->d[j]) {
            j++;
            continue;
        }
        int ones = x->d[j] == ONES, k = run_end(x, j, ones);
        c.nz += k - j;
        if (ones && k < x->n)
            c.ones++;
        else
            c.plain += k - j;
        j = k;
    }
    return c;
}

/* Work with a as the outer factor and b split into runs: a's nonzero limbs times b's
 * plain limbs, plus two shifted additions of a per run of ones. */
static long mul_cost(const lh__bn *a, mul_counts ca, mul_counts cb)
{
    return ca.nz * cb.plain + 2 * cb.ones * a->n;
}

/* r[off..n) += a (sub = 0) or -= a (sub = 1), the carry or borrow propagated; the
 * caller guarantees the result lies in [0, 2^(32 n)). */
static void add_shifted(uint32_t *r, const lh__bn *a, int off, int sub)
{
    uint64_t c = 0;
    int i = 0;
    for (; i < a->n; i++) {
        uint64_t t = sub ? (uint64_t)r[off + i] - a->d[i] - c : (uint64_t)r[off + i] + a->d[i] + c;
        r[off + i] = (uint32_t)t;
        c = sub ? (t >> 63) : (t >> 32);
    }
    for (; c; i++) {
        uint64_t t = sub ? (uint64_t)r[off + i] - c : (uint64_t)r[off + i] + c;
        r[off + i] = (uint32_t)t;
        c = sub ? (t >> 63) : (t >> 32);
    }
}

/* Schoolbook product that skips zero limbs and takes a run of all-ones limbs
 * b[lo..hi) as 2^(32 hi) - 2^(32 lo): exact entries that mix magnitudes
 * (2^1000 - 2^-1000) are a few short runs of plain limbs between long runs of zeros
 * or of ones (borrows), so the cost follows the limbs that carry information, not the
 * exponent range. Runs are taken in ascending order, so after each r = a * (b's limbs
 * below the run's end) < 2^(32 n); within a run of ones ending at hi <= b->n - 1, r
 * stays below a * 2^(32 hi + 1) <= 2^(32 n). */
void lh__bn_mul(lh__bn *r, const lh__bn *a, const lh__bn *b)
{
    if (!a->n || !b->n) {
        r->n = 0;
        r->neg = 0;
        return;
    }
    mul_counts ca = count_limbs(a), cb = count_limbs(b);
    if (mul_cost(b, cb, ca) < mul_cost(a, ca, cb)) {
        const lh__bn *t = a;
        a = b;
        b = t;
    }
    int n = a->n + b->n;
    memset(r->d, 0, (size_t)n * sizeof *r->d);
    for (int j = 0; j < b->n;) {
        if (!b->d[j]) {
            j++;
            continue;
        }
        int ones = b->d[j] == ONES, hi = run_end(b, j, ones);
        if (ones && hi < b->n) {
            add_shifted(r->d, a, hi, 0);
            add_shifted(r->d, a, j, 1);
            j = hi;
            continue;
        }
        for (int i = 0; i < a->n; i++) {
            uint64_t ai = a->d[i], carry = 0;
            if (!ai) continue;
            for (int k = j; k < hi; k++) {
                /* (2^32-1)^2 + 2*(2^32-1) = 2^64-1: no overflow. */
                uint64_t t = ai * b->d[k] + r->d[i + k] + carry;
                r->d[i + k] = (uint32_t)t;
                carry = t >> 32;
            }
            for (int k = i + hi; carry; k++) {
                uint64_t t = (uint64_t)r->d[k] + carry;
                r->d[k] = (uint32_t)t;
                carry = t >> 32;
            }
        }
        j = hi;
    }
    r->n = n;
    r->neg = a->neg ^ b->neg;
    trim(r);
}

static int cmp_mag(const lh__bn *a, const lh__bn *b)
{
    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    for (int i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* |r| = |x| + |y|; r may alias x or y. */
static void add_mag(lh__bn *r, const lh__bn *x, const lh__bn *y)
{
    const lh__bn *lg = x->n >= y->n ? x : y, *sm = x->n >= y->n ? y : x;
    int ln = lg->n, sn = sm->n;
    uint64_t carry = 0;
    for (int i = 0; i < ln; i++) {
        uint64_t t = (uint64_t)lg->d[i] + (i < sn ? sm->d[i] : 0) + carry;
        r->d[i] = (uint32_t)t;
        carry = t >> 32;
    }
    r->d[ln] = (uint32_t)carry;
    r->n = ln + 1;
}

/* |r| = |x| - |y| where |x| >= |y|; r may alias x or y. */
static void sub_mag(lh__bn *r, const lh__bn *x, const lh__bn *y)
{
    int xn = x->n, yn = y->n;
    int64_t borrow = 0;
    for (int i = 0; i < xn; i++) {
        int64_t t = (int64_t)x->d[i] - (i < yn ? (int64_t)y->d[i] : 0) - borrow;
        borrow = t < 0;
        r->d[i] = (uint32_t)(t + (borrow ? (INT64_C(1) << 32) : 0));
    }
    r->n = xn;
}

void lh__bn_add(lh__bn *r, const lh__bn *a, const lh__bn *b, int sub)
{
    int bneg = b->n ? b->neg ^ sub : 0;
    int aneg = a->neg;
    if (aneg == bneg) {
        add_mag(r, a, b);
        r->neg = aneg;
    } else if (cmp_mag(a, b) >= 0) {
        sub_mag(r, a, b);
        r->neg = aneg;
    } else {
        sub_mag(r, b, a);
        r->neg = bneg;
    }
    trim(r);
}

double lh__bn_to_double(const lh__bn *a, int *e)
{
    *e = 0;
    if (a->n == 0) return 0;
    double m = 0;
    int lo = a->n > 3 ? a->n - 3 : 0;
    for (int i = a->n - 1; i >= lo; i--) m = m * 4294967296.0 + (double)a->d[i];
    *e = 32 * lo;
    return a->neg ? -m : m;
}
