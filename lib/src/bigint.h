/*
 * bigint.h — the exact stage's arithmetic: signed integers of 32-bit limbs whose
 * storage the caller provides (the predicate context's arena), so nothing here
 * allocates.
 *
 * A double x is the integer m * 2^e exactly (m < 2^53). Given a scale s no larger
 * than the exponent of x's lowest set bit, x / 2^s is an integer; the exact stage
 * expresses every entry of a determinant at one scale per call, so determinants of
 * doubles become determinants of integers with the same sign. There is no exponent
 * range to leave: every finite double, subnormals included, converts exactly.
 */
#ifndef LH_BIGINT_H
#define LH_BIGINT_H

#include <stdint.h>

typedef struct lh__bn {
    uint32_t *d; /* little-endian limbs; capacity is the caller's business */
    int n;       /* limbs in use; 0 means zero; d[n-1] != 0 otherwise      */
    int neg;     /* 1 when negative (never set for zero)                   */
} lh__bn;

/* Storage that lh__bn_set_dbl may write for any finite double at any valid scale:
 * values below 2^1024 with lowest bit at least 2^-1074 span 2098 bits (66 limbs),
 * written as a shifted 53-bit mantissa across three limbs (68). */
#define LH__BN_DBL_LIMBS 68

/* x = (-1)^neg * m * 2^e with m < 2^53 returned (0 for zero), from the IEEE 754
 * binary64 encoding (x finite). */
uint64_t lh__dbl_decompose(double x, int *e, int *neg);
/* Exponent of the lowest set bit of x (x finite, nonzero). */
int lh__dbl_low_exp(double x);
/* r = x / 2^scale, exactly; requires scale <= lh__dbl_low_exp(x) for x != 0.
 * Writes at most LH__BN_DBL_LIMBS limbs; the result has at most 66. */
void lh__bn_set_dbl(lh__bn *r, double x, int scale);
/* r = a * b. r must not alias a or b and must hold a->n + b->n limbs. */
void lh__bn_mul(lh__bn *r, const lh__bn *a, const lh__bn *b);
/* r = a + b (sub = 0) or r = a - b (sub = 1). r may alias a (not b) and must hold
 * max(a->n, b->n) + 1 limbs. */
void lh__bn_add(lh__bn *r, const lh__bn *a, const lh__bn *b, int sub);
/* a ~= m * 2^e with |m| < 2^96 (from the top three limbs: relative error below
 * 2^-52); m = 0, e = 0 for zero. */
double lh__bn_to_double(const lh__bn *a, int *e);
/* -1, 0 or +1. */
static inline int lh__bn_sign(const lh__bn *a) { return a->n == 0 ? 0 : a->neg ? -1 : 1; }

#endif
