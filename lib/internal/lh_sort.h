/* lh_sort.h — a stable sort of int32 indices with a comparator that takes a context
 * (C11 has no qsort_r). Bottom-up merge sort; tmp holds count entries. */
#ifndef LH_SORT_H
#define LH_SORT_H

#include <stddef.h>
#include <stdint.h>

typedef int (*lh__cmp_fn)(const void *ctx, int32_t a, int32_t b);

void lh__sort_idx(int32_t *idx, int32_t *tmp, size_t count, lh__cmp_fn cmp, const void *ctx);

#endif
