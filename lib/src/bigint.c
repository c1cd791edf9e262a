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

/* x = (-1)^neg * m * 2^e with m < 2^53, from the IEEE 754 binary64 encoding. */
static uint64_t decompose(double x, int *e, int *neg)
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
    uint64_t m = decompose(x, &e, &neg);
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
    uint64_t m = decompose(x, &e, &neg);
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

void lh__bn_mul(lh__bn *r, const lh__bn *a, const lh__bn *b)
{
    if (!a->n || !b->n) {
        r->n = 0;
        r->neg = 0;
        return;
    }
    int n = a->n + b->n;
    memset(r->d, 0, (size_t)n * sizeof *r->d);
    for (int i = 0; i < a->n; i++) {
        uint64_t ai = a->d[i], carry = 0;
        if (!ai) continue; /* r->d[i + b->n] is still 0 from the memset */
        for (int j = 0; j < b->n; j++) {
            /* (2^32-1)^2 + 2*(2^32-1) = 2^64-1: no overflow. */
            uint64_t t = ai * b->d[j] + r->d[i + j] + carry;
            r->d[i + j] = (uint32_t)t;
            carry = t >> 32;
        }
        r->d[i + b->n] = (uint32_t)carry;
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
