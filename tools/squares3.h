/*
 * squares3.h — the representations of m as a sum of three squares, for the exactly
 * cospherical sites of sites.c in 3D (tools/ only; not part of the library).
 */
#ifndef LH_TOOLS_SQUARES3_H
#define LH_TOOLS_SQUARES3_H

#include <stdint.h>

/* floor(sqrt(v)) for v < 2^53. */
uint64_t lht_isqrt(uint64_t v);

/* Called once per triple; a nonzero return stops the walk and is returned. */
typedef int (*lht_triple_fn)(void *ctx, const int64_t t[3]);

/* Every sorted triple 0 <= a <= b <= c with a^2 + b^2 + c^2 = m (1 <= m < 2^50), in
 * lexicographic order, passed to each. Returns 0, -1 when out of memory, -2 on an
 * arithmetic inconsistency (a defect; never seen), or what each returned. Work about
 * sqrt(m) log log m, memory about sqrt(m). */
int lht_squares3_each(uint64_t m, lht_triple_fn each, void *ctx);

#endif
