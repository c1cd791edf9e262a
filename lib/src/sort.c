/* sort.c — stable bottom-up merge sort of indices, and a stable counting sort of
 * records by a point number (lh_sort.h). */
#include "lh_sort.h"

#include "lh_alloc.h"

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

lh_status lh__sort_by_index(const lh_allocator *al, void *rec, size_t count, size_t size, size_t at,
                            size_t n)
{
    size_t *pos = lh__alloc(al, (n + 1) * sizeof *pos);
    unsigned char *tmp = lh__alloc(al, count * size + 1), *r = rec;
    if (!pos || !tmp) {
        lh__free(al, pos);
        lh__free(al, tmp);
        return LH_ERR_NOMEM;
    }
    memset(pos, 0, (n + 1) * sizeof *pos);
    lh_index key;
    for (size_t i = 0; i < count; i++) memcpy(&key, r + i * size + at, sizeof key), pos[key + 1]++;
    for (size_t v = 1; v < n; v++) pos[v] += pos[v - 1];
    for (size_t i = 0; i < count; i++) {
        memcpy(&key, r + i * size + at, sizeof key);
        memcpy(tmp + pos[key]++ * size, r + i * size, size);
    }
    memcpy(r, tmp, count * size);
    lh__free(al, pos);
    lh__free(al, tmp);
    return LH_OK;
}
