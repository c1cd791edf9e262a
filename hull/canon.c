/* canon.c — the canonical form of lifthull's outputs (engine.h): oriented tuples in
 * increasing order but for one exchange that keeps the orientation, and tuples
 * sorted lexicographically, so that an output depends only on the site set. */
#include "engine.h"
#include "lh_sort.h"

#include <string.h>

static int tuple_less(const lh_index *x, const lh_index *y, int m)
{
    for (int k = 0; k < m; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

typedef struct tuple_ctx {
    const lh_index *v;
    int m;
} tuple_ctx;

static int tuple_cmp(const void *vctx, lh_index a, lh_index b)
{
    const tuple_ctx *c = vctx;
    const lh_index *x = c->v + (size_t)a * c->m, *y = c->v + (size_t)b * c->m;
    for (int k = 0; k < c->m; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* Insertion sort of the tuples at positions lo..hi-1, payload alongside. */
static void insertion_sort(lh_index *t, lh_index *payload, size_t lo, size_t hi, int m)
{
    for (size_t i = lo + 1; i < hi; i++) {
        lh_index key[LH__ENGINE_MAX_DIM + 1], p = payload[i];
        memcpy(key, t + i * m, (size_t)m * sizeof *key);
        size_t j = i;
        for (; j > lo && tuple_less(key, t + (j - 1) * m, m); j--) {
            memcpy(t + j * m, t + (j - 1) * m, (size_t)m * sizeof *t);
            payload[j] = payload[j - 1];
        }
        memcpy(t + j * m, key, (size_t)m * sizeof *key);
        payload[j] = p;
    }
}

/* Merge sort of a large bucket through an index, then the tuples and payload are
 * permuted; scratch holds the bucket's size in indices (2x) and tuples. */
static void merge_sort_bucket(lh_index *t, lh_index *payload, size_t lo, size_t hi, int m,
                              lh_index *idx, lh_index *tmp, lh_index *copy)
{
    size_t k = hi - lo;
    for (size_t i = 0; i < k; i++) idx[i] = (lh_index)i;
    tuple_ctx c = {t + lo * m, m};
    lh__sort_idx(idx, tmp, k, tuple_cmp, &c);
    memcpy(copy, t + lo * m, k * (size_t)m * sizeof *copy);
    for (size_t i = 0; i < k; i++) memcpy(t + (lo + i) * m, copy + (size_t)idx[i] * m, (size_t)m * sizeof *t);
    for (size_t i = 0; i < k; i++) tmp[i] = payload[lo + idx[i]];
    memcpy(payload + lo, tmp, k * sizeof *tmp);
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
        if (start[k + 1] - start[k] > SMALL)
            merge_sort_bucket(t, payload, start[k], start[k + 1], m, idx, tmp, copy);
        else
            insertion_sort(t, payload, start[k], start[k + 1], m);
    }
    lh__free(a, idx);
    lh__free(a, tmp);
    lh__free(a, copy);
    return 1;
}

/* Sorts count canonical tuples (m indices each) lexicographically into out, with
 * order[i] the input position of out's tuple i: a counting sort on the first entry
 * (a site index below n) gathers the tuples bucket by bucket, then each bucket is
 * sorted (lh__sort_buckets). Returns 0 on no memory. */
int lh__sort_tuples(const lh_allocator *a, const lh_index *v, int m, size_t count,
                    size_t n, lh_index *out, lh_index *order)
{
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
