/* sort.c — stable bottom-up merge sort of indices (lh_sort.h). */
#include "lh_sort.h"

#include <string.h>

void lh__sort_idx(lh_index *idx, lh_index *tmp, size_t count, lh__cmp_fn cmp, const void *ctx)
{
    lh_index *src = idx, *dst = tmp;
    for (size_t width = 1; width < count; width *= 2) {
        for (size_t lo = 0; lo < count; lo += 2 * width) {
            size_t mid = lo + width < count ? lo + width : count;
            size_t hi = lo + 2 * width < count ? lo + 2 * width : count;
            size_t i = lo, j = mid, o = lo;
            while (i < mid && j < hi) dst[o++] = cmp(ctx, src[j], src[i]) < 0 ? src[j++] : src[i++];
            while (i < mid) dst[o++] = src[i++];
            while (j < hi) dst[o++] = src[j++];
        }
        lh_index *t = src;
        src = dst;
        dst = t;
    }
    if (src != idx) memcpy(idx, src, count * sizeof *idx);
}

int lh__rows_cmp(const void *ctx, lh_index a, lh_index b)
{
    const lh__rows *r = ctx;
    const lh_index *x = r->v + (size_t)a * r->width, *y = r->v + (size_t)b * r->width;
    for (int k = 0; k < r->keylen; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}
