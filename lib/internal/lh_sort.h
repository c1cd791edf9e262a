/* lh_sort.h — a stable sort of lh_index indices with a comparator that takes a context
 * (C11 has no qsort_r). Bottom-up merge sort; tmp holds count entries. */
#ifndef LH_SORT_H
#define LH_SORT_H

#include "lifthull.h" /* lh_index */

#include <stddef.h>
#include <stdint.h>

typedef int (*lh__cmp_fn)(const void *ctx, lh_index a, lh_index b);

void lh__sort_idx(lh_index *idx, lh_index *tmp, size_t count, lh__cmp_fn cmp, const void *ctx);

/* Rows of `width` indices compared lexicographically on their first `keylen`. */
typedef struct lh__rows {
    const lh_index *v;
    int width, keylen;
} lh__rows;
/* An lh__cmp_fn over rows a and b of the lh__rows at ctx. */
int lh__rows_cmp(const void *ctx, lh_index a, lh_index b);

/* Stable counting sort of count records of `size` bytes by the lh_index at byte
 * offset `at` in each, a number from 0 to n - 1, through a scratch copy allocated with
 * al: LH_OK or LH_ERR_NOMEM (rec unchanged). Sorting by the last key first, then by
 * the others, sorts lexicographically (least significant digit first). */
lh_status lh__sort_by_index(const lh_allocator *al, void *rec, size_t count, size_t size, size_t at,
                            size_t n);

#endif
