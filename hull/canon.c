/* canon.c — the canonical form of lifthull's outputs (engine.h): oriented tuples in
 * increasing order but for one exchange that keeps the orientation, and tuples
 * sorted lexicographically, so that an output depends only on the site set. */
#include "engine.h"
#include "lh_sort.h"

#include <string.h>

/* Sorts v[0..m-1] increasing; returns the permutation's parity (1 = odd) and, in
 * from[p], the original position of the value now at p. */
static int sort_with_parity(int32_t *v, int *from, int m)
{
    int parity = 0;
    for (int i = 0; i < m; i++) from[i] = i;
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            int32_t x = v[j];
            v[j] = v[j - 1];
            v[j - 1] = x;
            int f = from[j];
            from[j] = from[j - 1];
            from[j - 1] = f;
            parity ^= 1;
        }
    return parity;
}

/* Canonical order of an oriented tuple: increasing, then the last two exchanged if
 * the sort was an odd permutation (so the orientation is kept). */
void lh__canonical(int32_t *v, int *from, int m)
{
    if (sort_with_parity(v, from, m)) {
        int32_t x = v[m - 1];
        v[m - 1] = v[m - 2];
        v[m - 2] = x;
        int f = from[m - 1];
        from[m - 1] = from[m - 2];
        from[m - 2] = f;
    }
}

static int tuple_less(const int32_t *x, const int32_t *y, int m)
{
    for (int k = 0; k < m; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

typedef struct tuple_ctx {
    const int32_t *v;
    int m;
} tuple_ctx;

static int tuple_cmp(const void *vctx, int32_t a, int32_t b)
{
    const tuple_ctx *c = vctx;
    const int32_t *x = c->v + (size_t)a * c->m, *y = c->v + (size_t)b * c->m;
    for (int k = 0; k < c->m; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* Sorts count canonical tuples (m int32 each) lexicographically into out, with
 * order[i] the input position of out's tuple i: a counting sort on the first entry
 * (a site index below n) gathers the tuples bucket by bucket; each bucket, now
 * contiguous, is sorted on the rest — insertion sort for the usual small buckets,
 * merge sort for large ones (a vertex of huge degree). Returns 0 on no memory. */
int lh__sort_tuples(const lh_allocator *a, const int32_t *v, int m, size_t count,
                       size_t n, int32_t *out, int32_t *order)
{
    size_t *start = lh__alloc(a, (n + 2) * sizeof *start);
    int32_t *tmp = lh__alloc(a, (count + 1) * sizeof *tmp);
    if (!start || !tmp) {
        lh__free(a, start);
        lh__free(a, tmp);
        return 0;
    }
    memset(start, 0, (n + 2) * sizeof *start);
    for (size_t i = 0; i < count; i++) start[(size_t)v[i * m] + 2]++;
    for (size_t k = 2; k < n + 2; k++) start[k] += start[k - 1];
    for (size_t i = 0; i < count; i++) order[start[(size_t)v[i * m] + 1]++] = (int32_t)i;
    for (size_t i = 0; i < count; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
    tuple_ctx c = {v, m};
    for (size_t k = 0; k < n; k++) {
        size_t lo = start[k], hi = start[k + 1];
        if (hi - lo > 32) { /* rare: sort indices, then regather this bucket */
            lh__sort_idx(order + lo, tmp, hi - lo, tuple_cmp, &c);
            for (size_t i = lo; i < hi; i++) memcpy(out + i * m, v + (size_t)order[i] * m, (size_t)m * sizeof *v);
            continue;
        }
        for (size_t i = lo + 1; i < hi; i++) {
            int32_t key[LH__ENGINE_MAX_DIM + 1], o = order[i];
            memcpy(key, out + i * m, (size_t)m * sizeof *key);
            size_t j = i;
            for (; j > lo && tuple_less(key, out + (j - 1) * m, m); j--) {
                memcpy(out + j * m, out + (j - 1) * m, (size_t)m * sizeof *out);
                order[j] = order[j - 1];
            }
            memcpy(out + j * m, key, (size_t)m * sizeof *key);
            order[j] = o;
        }
    }
    lh__free(a, start);
    lh__free(a, tmp);
    return 1;
}

