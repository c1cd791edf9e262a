/*
 * tds.c — cell store and cavity insertion (see tds.h).
 *
 * Linking the new cells: the new cell N made from boundary facet (c, k) meets,
 * across its facet opposite vertex v_j (j != k), the new cell made from the other
 * boundary facet that contains the ridge R = c \ {v_k, v_j} (the cavity's boundary
 * is a closed pseudo-manifold: every ridge is in exactly two boundary facets). The
 * two are paired through a hash table keyed on R. Each new cell's old vertices are
 * sorted once; a ridge is that list minus one entry. When a ridge has at most two
 * vertices (d <= 3) the key is the ridge itself; otherwise it is the sum of a mix
 * of its vertices (one subtraction from the cell's sum) and equal keys are
 * confirmed by comparing the sorted lists, so a collision costs a probe, never a
 * wrong link.
 */
#include "tds.h"

#include "lh_alloc.h"

#include <string.h>


static void *grow(const lh_allocator *a, void *old, size_t old_bytes, size_t new_bytes)
{
    void *p = lh__alloc(a, new_bytes);
    if (!p) return NULL;
    if (old_bytes) memcpy(p, old, old_bytes);
    lh__free(a, old);
    return p;
}

static lh_status set_capacity(lh__tds *t, int32_t cap)
{
    size_t nv = (size_t)t->nv, old = (size_t)t->cap;
    int32_t *v = grow(&t->alloc, t->vert, old * nv * 4, (size_t)cap * nv * 4);
    if (!v) return LH_ERR_NOMEM;
    t->vert = v;
    int32_t *n = grow(&t->alloc, t->nbr, old * nv * 4, (size_t)cap * nv * 4);
    if (!n) return LH_ERR_NOMEM;
    t->nbr = n;
    uint32_t *s = grow(&t->alloc, t->stamp, old * 4, (size_t)cap * 4);
    if (!s) return LH_ERR_NOMEM;
    memset(s + old, 0, ((size_t)cap - old) * 4);
    t->stamp = s;
    t->cap = cap;
    return LH_OK;
}

lh_status lh__tds_init(lh__tds *t, const lh_allocator *alloc, int nv, int32_t cap_hint)
{
    memset(t, 0, sizeof *t);
    if (!lh__allocator_init(&t->alloc, alloc)) return LH_ERR_INVALID_ARGUMENT;
    t->nv = nv;
    t->free_head = -1;
    return set_capacity(t, cap_hint > 16 ? cap_hint : 16);
}

typedef struct lh__ridge {
    uint64_t key;
    uint32_t round; /* the insertion that wrote the entry */
    int32_t b;      /* the new cell t->fresh[b] */
    int32_t drop;   /* the index in its sorted list of the vertex not in the ridge */
    int32_t paired; /* both cells of the ridge linked */
} lh__ridge;

void lh__tds_release(lh__tds *t)
{
    lh__free(&t->alloc, t->ridge);
    lh__free(&t->alloc, t->sorted);
    lh__free(&t->alloc, t->spos);
    lh__free(&t->alloc, t->vert);
    lh__free(&t->alloc, t->nbr);
    lh__free(&t->alloc, t->stamp);
    lh__free(&t->alloc, t->cells);
    lh__free(&t->alloc, t->bound);
    lh__free(&t->alloc, t->fresh);
    memset(t, 0, sizeof *t);
}

lh_status lh__tds_reserve(lh__tds *t, size_t extra)
{
    size_t have = (size_t)(t->cap - t->top), freed = (size_t)(t->top - t->live);
    if (have + freed >= extra) return LH_OK;
    size_t want = (size_t)t->cap + (size_t)t->cap / 2 + 1024; /* x1.5: less overshoot */
    if (want < (size_t)t->top + extra) want = (size_t)t->top + extra;
    if (want > INT32_MAX) want = INT32_MAX;
    if (want < (size_t)t->top + extra) return LH_ERR_TOO_LARGE;
    return set_capacity(t, (int32_t)want);
}

uint32_t *lh__tds_finish(lh__tds *t)
{
    uint32_t *s = t->stamp;
    t->stamp = NULL;
    lh__free(&t->alloc, t->cells);
    lh__free(&t->alloc, t->bound);
    lh__free(&t->alloc, t->fresh);
    lh__free(&t->alloc, t->ridge);
    lh__free(&t->alloc, t->sorted);
    lh__free(&t->alloc, t->spos);
    t->cells = t->bound = t->fresh = t->sorted = NULL;
    t->ridge = NULL;
    t->spos = NULL;
    t->cells_cap = t->bound_cap = t->fresh_cap = t->ridge_cap = t->sorted_cap = 0;
    return s;
}

int32_t lh__tds_new_cell(lh__tds *t)
{
    int32_t c;
    if (t->free_head >= 0) {
        c = t->free_head;
        t->free_head = t->nbr[(size_t)c * t->nv];
    } else {
        if (t->top == t->cap && lh__tds_reserve(t, 1) != LH_OK) return -1;
        c = t->top++;
    }
    t->live++;
    return c;
}

void lh__tds_kill(lh__tds *t, int32_t c)
{
    size_t base = (size_t)c * t->nv;
    t->vert[base] = LH__DEAD;
    t->nbr[base] = t->free_head;
    t->free_head = c;
    t->live--;
}

int lh__tds_mirror(const lh__tds *t, int32_t c, int32_t other)
{
    const int32_t *n = t->nbr + (size_t)c * t->nv;
    for (int k = 0; k < t->nv; k++)
        if (n[k] == other) return k;
    return -1;
}

static int index_of(const int32_t *v, int nv, int32_t x)
{
    for (int k = 0; k < nv; k++)
        if (v[k] == x) return k;
    return -1;
}

void lh__tds_link_all(lh__tds *t, const int32_t *list, int count)
{
    int nv = t->nv;
    for (int a = 0; a < count; a++) {
        const int32_t *va = t->vert + (size_t)list[a] * nv;
        for (int b = 0; b < count; b++) {
            if (a == b) continue;
            const int32_t *vb = t->vert + (size_t)list[b] * nv;
            int missing = -1, shared = 0;
            for (int k = 0; k < nv; k++) {
                if (index_of(vb, nv, va[k]) >= 0)
                    shared++;
                else
                    missing = k;
            }
            if (shared == nv - 1) t->nbr[(size_t)list[a] * nv + missing] = list[b];
        }
    }
}

static int push_slow(lh__tds *t, int32_t **arr, size_t *cap, size_t *len, int32_t x)
{
    size_t nc = *cap ? *cap * 2 : 64;
    int32_t *p = grow(&t->alloc, *arr, *cap * 4, nc * 4);
    if (!p) return 0;
    *arr = p;
    *cap = nc;
    (*arr)[(*len)++] = x;
    return 1;
}

static inline int push(lh__tds *t, int32_t **arr, size_t *cap, size_t *len, int32_t x)
{
    if (*len < *cap) {
        (*arr)[(*len)++] = x;
        return 1;
    }
    return push_slow(t, arr, cap, len, x);
}

static void next_round(lh__tds *t)
{
    if (t->round >= UINT32_MAX / 4 - 1) {
        memset(t->stamp, 0, (size_t)t->cap * sizeof *t->stamp);
        if (t->ridge) memset(t->ridge, 0, t->ridge_cap * sizeof *t->ridge);
        t->round = 0;
    }
    t->round++;
}

/* Finds the conflict region from `start`: t->cells, and its boundary facets as pairs
 * (cell, k) in t->bound. Returns 0 when memory runs out. */
static int grow_region(lh__tds *t, int32_t start, lh__conflict_fn conflict, void *user,
                       uint32_t in, uint32_t out)
{
    const int nv = t->nv;
    t->ncells = t->nbound = 0;
    size_t nb2 = 0;
    t->stamp[start] = in;
    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, start)) return 0;
    for (size_t i = 0; i < t->ncells; i++) {
        int32_t c = t->cells[i];
        for (int k = 0; k < nv; k++) {
            int32_t n = t->nbr[(size_t)c * nv + k];
            uint32_t st = t->stamp[n];
            if (st == in) continue;
            if (st != out) {
                if (conflict(user, n)) {
                    t->stamp[n] = in;
                    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, n)) return 0;
                    continue;
                }
                t->stamp[n] = out;
            }
            if (!push(t, &t->bound, &t->bound_cap, &nb2, c) ||
                !push(t, &t->bound, &t->bound_cap, &nb2, k))
                return 0;
        }
    }
    t->nbound = nb2 / 2;
    return 1;
}

static inline uint64_t mix(int32_t v) /* one multiply and a fold: nonlinear in v */
{
    uint64_t z = (uint64_t)(uint32_t)v * UINT64_C(0x9e3779b97f4a7c15);
    return z ^ (z >> 29);
}

/* Room for the ridges of nbound new cells (the table at most half full) and their
 * sorted vertex lists. */
static int ridge_room(lh__tds *t)
{
    const size_t m = (size_t)t->nv - 1, nb = t->nbound;
    if (t->sorted_cap < nb) {
        size_t cap = 2 * nb;
        int32_t *s = grow(&t->alloc, t->sorted, 0, cap * m * sizeof *s);
        if (!s) return 0;
        t->sorted = s;
        int8_t *p = grow(&t->alloc, t->spos, 0, cap * m * sizeof *p);
        if (!p) return 0;
        t->spos = p;
        t->sorted_cap = cap;
    }
    size_t want = 16;
    while (want < 2 * nb * m) want *= 2;
    if (t->ridge_cap >= want) return 1;
    lh__ridge *r = grow(&t->alloc, t->ridge, 0, want * sizeof *r);
    if (!r) return 0;
    memset(r, 0, want * sizeof *r);
    t->ridge = r;
    t->ridge_cap = want;
    return 1;
}

/* The old vertices of new cell b (all but position k), increasing, with their
 * positions. */
static void sort_old_vertices(lh__tds *t, size_t b, int32_t N, int k)
{
    const int nv = t->nv, m = nv - 1;
    const int32_t *v = t->vert + (size_t)N * nv;
    int32_t *s = t->sorted + b * m;
    int8_t *p = t->spos + b * m;
    int n = 0;
    for (int j = 0; j < nv; j++) {
        if (j == k) continue;
        int i = n++;
        for (; i > 0 && s[i - 1] > v[j]; i--) {
            s[i] = s[i - 1];
            p[i] = p[i - 1];
        }
        s[i] = v[j];
        p[i] = (int8_t)j;
    }
}

/* Whether the sorted lists of new cells a and b, minus entries da and db, agree. */
static int same_ridge(const lh__tds *t, size_t a, int da, size_t b, int db)
{
    const int m = t->nv - 1;
    const int32_t *x = t->sorted + a * m, *y = t->sorted + b * m;
    for (int i = 0, j = 0; i < m; i++, j++) {
        if (i == da) i++;
        if (j == db) j++;
        if (i < m && x[i] != y[j]) return 0;
    }
    return 1;
}

/* The key of the ridge of sorted list s (m entries, sum of mixes `sum`) without
 * entry drop: the ridge itself when it has at most two vertices. */
static inline uint64_t ridge_key(const int32_t *s, int m, int drop, uint64_t sum)
{
    if (m == 2) return (uint32_t)s[1 - drop];
    if (m == 3) {
        int a = drop == 0 ? 1 : 0, c = drop == 2 ? 1 : 2;
        return (uint64_t)(uint32_t)s[a] << 32 | (uint32_t)s[c];
    }
    return sum - mix(s[drop]);
}

/* Pairs the new cells t->fresh[] across their ridges (see the top). */
static void link_new_cells(lh__tds *t, uint32_t round)
{
    const int nv = t->nv, m = nv - 1, exact = m <= 3;
    const size_t mask = t->ridge_cap - 1;
    for (size_t b = 0; b < t->nbound; b++) sort_old_vertices(t, b, t->fresh[b], t->bound[2 * b + 1]);
    for (size_t b = 0; b < t->nbound; b++) {
        const int32_t N = t->fresh[b], *s = t->sorted + b * m;
        uint64_t sum = 0;
        if (!exact)
            for (int i = 0; i < m; i++) sum += mix(s[i]);
        for (int i = 0; i < m; i++) {
            uint64_t key = ridge_key(s, m, i, sum);
            for (size_t h = (size_t)((key * UINT64_C(0x9e3779b97f4a7c15)) >> 40) & mask;; h = (h + 1) & mask) {
                lh__ridge *r = t->ridge + h;
                if (r->round != round) { /* free: the first of the pair */
                    r->key = key;
                    r->round = round;
                    r->b = (int32_t)b;
                    r->drop = i;
                    r->paired = 0;
                    break;
                }
                if (!r->paired && r->key == key && (exact || same_ridge(t, b, i, (size_t)r->b, r->drop))) {
                    int32_t M = t->fresh[r->b];
                    t->nbr[(size_t)N * nv + t->spos[b * m + i]] = M;
                    t->nbr[(size_t)M * nv + t->spos[(size_t)r->b * m + r->drop]] = N;
                    r->paired = 1;
                    break;
                }
            }
        }
    }
}

lh_status lh__tds_insert(lh__tds *t, int32_t start, int32_t q, lh__conflict_fn conflict,
                         void *user)
{
    const int nv = t->nv;
    next_round(t);
    uint32_t in = 4 * t->round, out = in + 1;
    if (!grow_region(t, start, conflict, user, in, out)) return LH_ERR_NOMEM;
    if (t->fresh_cap < t->nbound) {
        int32_t *p = grow(&t->alloc, t->fresh, 0, t->nbound * 2 * 4);
        if (!p) return LH_ERR_NOMEM;
        t->fresh = p;
        t->fresh_cap = t->nbound * 2;
    }
    if (!ridge_room(t)) return LH_ERR_NOMEM;
    lh_status st = lh__tds_reserve(t, t->nbound);
    if (st != LH_OK) return st;

    for (size_t b = 0; b < t->nbound; b++) {
        int32_t c = t->bound[2 * b], k = t->bound[2 * b + 1];
        int32_t N = lh__tds_new_cell(t); /* cannot fail after the reserve */
        int32_t *nv_ = t->vert + (size_t)N * nv, *nn = t->nbr + (size_t)N * nv;
        const int32_t *cv = t->vert + (size_t)c * nv;
        for (int j = 0; j < nv; j++) nv_[j] = cv[j];
        nv_[k] = q;
        int32_t outside = t->nbr[(size_t)c * nv + k];
        nn[k] = outside;
        t->nbr[(size_t)outside * nv + lh__tds_mirror(t, outside, c)] = N;
        t->fresh[b] = N;
    }
    link_new_cells(t, t->round);
    for (size_t i = 0; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return LH_OK;
}
