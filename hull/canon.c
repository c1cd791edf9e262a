/* canon.c — the canonical form of lifthull's outputs (engine.h): oriented tuples in
 * increasing order but for one exchange that keeps the orientation, and tuples
 * sorted lexicographically, so that an output depends only on the site set. */
#include "engine.h"
#include "lh_sort.h"

#include <string.h>

/* Whether tuple x comes before y, their first entries being equal. With 32-bit
 * indices (nonnegative here) the entries are compared two at a time, packed into a
 * word: the first pair almost always decides, so the one data-dependent outcome is
 * a value, not a branch to mispredict. */
static inline int tail_less(const lh_index *x, const lh_index *y, int m)
{
#if LH_INDEX_BITS == 32
    for (int k = 1; k < m; k += 2) {
        const uint64_t a = (uint64_t)(uint32_t)x[k] << 32 | (k + 1 < m ? (uint32_t)x[k + 1] : 0);
        const uint64_t b = (uint64_t)(uint32_t)y[k] << 32 | (k + 1 < m ? (uint32_t)y[k + 1] : 0);
        if (a != b) return a < b;
    }
#else
    for (int k = 1; k < m; k++)
        if (x[k] != y[k]) return x[k] < y[k];
#endif
    return 0;
}

/* Insertion sort of the tuples at positions lo..hi-1 of a bucket, payload
 * alongside. */
static inline void insertion_sort(lh_index *t, lh_index *payload, size_t lo, size_t hi, int m)
{
    for (size_t i = lo + 1; i < hi; i++) {
        lh_index key[LH__ENGINE_MAX_DIM + 1], p = payload[i];
        for (int k = 0; k < m; k++) key[k] = t[i * m + k];
        size_t j = i;
        for (; j > lo && tail_less(key, t + (j - 1) * m, m); j--) {
            for (int k = 0; k < m; k++) t[j * m + k] = t[(j - 1) * m + k];
            payload[j] = payload[j - 1];
        }
        for (int k = 0; k < m; k++) t[j * m + k] = key[k];
        payload[j] = p;
    }
}

/* Bottom-up merge sort of a large bucket through an index (stable), then the
 * tuples and payload are permuted; scratch holds the bucket's size in indices (2x)
 * and tuples. */
static inline void merge_sort_bucket(lh_index *t, lh_index *payload, size_t lo, size_t hi, int m,
                                     lh_index *idx, lh_index *tmp, lh_index *copy)
{
    const size_t k = hi - lo;
    const lh_index *b = t + lo * m;
    lh_index *x = idx, *y = tmp;
    for (size_t i = 0; i < k; i++) x[i] = (lh_index)i;
    for (size_t w = 1; w < k; w *= 2) {
        for (size_t l = 0; l < k; l += 2 * w) {
            size_t mid = l + w < k ? l + w : k, r = l + 2 * w < k ? l + 2 * w : k;
            size_t i = l, j = mid, o = l;
            while (i < mid && j < r) { /* no branch on the comparison */
                const int right = tail_less(b + (size_t)x[j] * m, b + (size_t)x[i] * m, m);
                y[o++] = right ? x[j] : x[i];
                j += (size_t)right;
                i += (size_t)!right;
            }
            while (i < mid) y[o++] = x[i++];
            while (j < r) y[o++] = x[j++];
        }
        lh_index *z = x;
        x = y, y = z;
    }
    memcpy(copy, b, k * (size_t)m * sizeof *copy);
    for (size_t i = 0; i < k; i++)
        for (int c = 0; c < m; c++) t[(lo + i) * m + c] = copy[(size_t)x[i] * m + c];
    for (size_t i = 0; i < k; i++) y[i] = payload[lo + x[i]];
    memcpy(payload + lo, y, k * sizeof *y);
}

int lh__sort_buckets(const lh_allocator *a, lh_index *t, lh_index *payload, const size_t *start,
                     size_t nb, int m)
{
    enum { SMALL = 32 }; /* buckets are a vertex's simplices: usually a handful */
    size_t big = 0;
    for (size_t k = 0; k < nb; k++)
        if (start[k + 1] - start[k] > big) big = start[k + 1] - start[k];
    lh_index *idx = NULL, *tmp = NULL, *copy = NULL;
    if (big > SMALL) {
        idx = lh__alloc(a, big * sizeof *idx);
        tmp = lh__alloc(a, big * sizeof *tmp);
        copy = lh__alloc(a, big * (size_t)m * sizeof *copy);
        if (!idx || !tmp || !copy) {
            lh__free(a, idx);
            lh__free(a, tmp);
            lh__free(a, copy);
            return 0;
        }
    }
    for (size_t k = 0; k < nb; k++) {
        const size_t lo = start[k], hi = start[k + 1];
#define MERGE(mm) merge_sort_bucket(t, payload, lo, hi, mm, idx, tmp, copy)
#define INSERT(mm) insertion_sort(t, payload, lo, hi, mm)
        if (hi - lo > SMALL)
            LH__WITH_CONSTANT_M(m, MERGE);
        else if (hi - lo > 1)
            LH__WITH_CONSTANT_M(m, INSERT);
#undef MERGE
#undef INSERT
    }
    lh__free(a, idx);
    lh__free(a, tmp);
    lh__free(a, copy);
    return 1;
}

/* Few tuples for the range of indices (a 2D hull's few dozen edges among 10^6
 * sites): a merge sort of their positions, no table of n buckets. */
static int sort_few_tuples(const lh_allocator *a, const lh_index *v, int m, size_t count,
                           lh_index *out, lh_index *order)
{
    lh_index *tmp = lh__alloc(a, (count + 1) * sizeof *tmp);
    if (!tmp) return 0;
    for (size_t i = 0; i < count; i++) order[i] = (lh_index)i;
    lh__rows c = {v, m, m};
    lh__sort_idx(order, tmp, count, lh__rows_cmp, &c);
    for (size_t i = 0; i < count; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
    lh__free(a, tmp);
    return 1;
}

/* Sorts count canonical tuples (m indices each) lexicographically into out, with
 * order[i] the input position of out's tuple i: a counting sort on the first entry
 * (a site index below n) gathers the tuples bucket by bucket, then each bucket is
 * sorted (lh__sort_buckets); or, when there are few tuples for n, sort_few_tuples.
 * Returns 0 on no memory. */
int lh__sort_tuples(const lh_allocator *a, const lh_index *v, int m, size_t count,
                    size_t n, lh_index *out, lh_index *order)
{
    if (count < n / 8) return sort_few_tuples(a, v, m, count, out, order);
    size_t *start = lh__alloc(a, (n + 2) * sizeof *start);
    if (!start) return 0;
    memset(start, 0, (n + 2) * sizeof *start);
    for (size_t i = 0; i < count; i++) start[(size_t)v[i * m] + 2]++;
    for (size_t k = 2; k < n + 2; k++) start[k] += start[k - 1];
    for (size_t i = 0; i < count; i++) order[start[(size_t)v[i * m] + 1]++] = (lh_index)i;
    for (size_t i = 0; i < count; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
    int ok = lh__sort_buckets(a, out, order, start, n, m);
    lh__free(a, start);
    return ok;
}
