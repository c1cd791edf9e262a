/*
 * squares3.h — the representations of m as a sum of three squares, for the exactly
 * cospherical sites of sites.c in 3D (tools/ only; not part of the library).
 */
#ifndef LH_TOOLS_SQUARES3_H
#define LH_TOOLS_SQUARES3_H

#include <stdint.h>

/* floor(sqrt(v)) for v < 2^53. */
uint64_t lht_isqrt(uint64_t v);

/* z times re + im i, in place (Gaussian integers; the caller keeps the product exact). */
void lht_gauss_mul(int64_t z[2], int64_t re, int64_t im);

/* pi = u + vi with u^2 + v^2 = p and u > v > 0, for a prime p = 1 mod 4 below 2^50;
 * 0, or -2 when p is no such prime (then pi means nothing). */
int lht_gauss_split(uint64_t p, int64_t pi[2]);

/* Called once per triple; a nonzero return stops the walk and is returned. */
typedef int (*lht_triple_fn)(void *ctx, const int64_t t[3]);

/* Every sorted triple 0 <= a <= b <= c with a^2 + b^2 + c^2 = m (1 <= m < 2^50), in
 * lexicographic order, passed to each. Returns 0, -1 when out of memory, -2 on an
 * arithmetic inconsistency (a defect; never seen), or what each returned. Work about
 * sqrt(m) log log m, memory about sqrt(m). */
int lht_squares3_each(uint64_t m, lht_triple_fn each, void *ctx);

#endif
