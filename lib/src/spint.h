/*
 * spint.h — sparse signed-digit integers for the exact stage's signs when the
 * magnitudes of one call mix (1e+300 beside 5e-324).
 *
 * A number is a list of digits d_k at offsets o_k (strictly increasing), value
 * sum of d_k * 2^(26 o_k), every digit in [-2^25, 2^25) and nonzero: a balanced
 * radix-2^26 representation that stores only the digits that carry information. The
 * dense integers of bigint.h span the whole exponent range of a call (2100 bits per
 * coordinate); a difference 2^1000 - 2^-1000 is there a run of all-ones limbs, here
 * a few digits, and a product of a 2^1000 term and a 2^-1000 term costs its digits,
 * not the range. The sign is the top digit's: the digits below offset o sum to at
 * most 2^25 (2^(26 o) - 1) / (2^26 - 1) < 2^(26 o) in magnitude.
 *
 * Sums of products are formed in an accumulator: an int64 coefficient and a flag per
 * offset, normalised into a list (carries propagated upwards) only when a value is
 * complete, so the cost follows the digit pairs multiplied, not the exponent range.
 * A digit product is below 2^50 and at most LH__SP_MAX_ADDS = 2^12 of them (or
 * smaller terms) land on one offset between two normalisations (enforced), so no
 * coefficient leaves (-2^62, 2^62). Nothing here allocates: the caller provides the
 * storage; an accumulator or pool that is too small, or a value that would add too
 * often to one offset, makes the result void and take() report it (the caller then
 * takes the dense path).
 */
#ifndef LH_SPINT_H
#define LH_SPINT_H

#include <stddef.h>
#include <stdint.h>

#define LH__SP_BITS 26
#define LH__SP_MAX_ADDS 4096

typedef struct lh__sd {
    int32_t off; /* the digit weighs 2^(26 off)  */
    int32_t dig; /* in [-2^25, 2^25), nonzero    */
} lh__sd;

typedef struct lh__sp {
    const lh__sd *t; /* n digits, offsets increasing; n = 0 is zero */
    int n;
} lh__sp;

/* Coefficients c[0..size) and flags (nonzero where an offset was added to since the
 * last normalisation), both all zero between values; work counts digit pairs
 * multiplied plus digits written. */
typedef struct lh__sp_acc {
    int64_t *c;
    uint8_t *flag;
    int size;   /* offsets 0..size-1 */
    int lo, hi; /* least and greatest offset added to (lo > hi: none) */
    int load;   /* additions per offset since the last normalisation, at most */
    int failed; /* the value is void (room or load exceeded) */
    uint64_t work;
} lh__sp_acc;

/* A bump allocator of digits. */
typedef struct lh__sp_pool {
    lh__sd *d;
    size_t cap, used;
} lh__sp_pool;

/* size offsets of coefficients c and flags flag, both zeroed by the caller. */
void lh__sp_acc_init(lh__sp_acc *a, int64_t *c, uint8_t *flag, int size);
/* acc += x / 2^scale (acc -= when neg); requires scale <= lh__dbl_low_exp(x). */
void lh__sp_acc_add_dbl(lh__sp_acc *a, double x, int scale, int neg);
/* acc += x * y (acc -= when neg). */
void lh__sp_acc_add_mul(lh__sp_acc *a, const lh__sp *x, const lh__sp *y, int neg);
/* acc += x (acc -= when neg). */
void lh__sp_acc_add(lh__sp_acc *a, const lh__sp *x, int neg);
/* Normalises the accumulated value into digits taken from pool, *r pointing at them,
 * and clears the accumulator. 0 when the value was void or the pool too small (the
 * accumulator is cleared all the same), else 1. */
int lh__sp_acc_take(lh__sp_acc *a, lh__sp_pool *pool, lh__sp *r);

static inline int lh__sp_sign(const lh__sp *x)
{
    return x->n == 0 ? 0 : x->t[x->n - 1].dig > 0 ? 1 : -1;
}

#endif
