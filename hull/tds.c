/*
 * tds.c — cell store and cavity insertion (see tds.h).
 *
 * Linking the new cells without a hash table: the new cell N made from boundary
 * facet (c, k) meets, across its facet opposite vertex v_j (j != k), the new cell
 * made from the other boundary facet that contains the ridge R = c \ {v_k, v_j}.
 * That facet is found by turning around R inside the cavity: leave c through the
 * facet opposite v_j; in each conflict cell entered, leave through the other facet
 * containing R; stop at the first boundary facet, whose new cell was recorded in
 * the old cell's neighbour slot. (The same rotation CGAL's and Geogram's
 * triangulations use.)
 */
#include "tds.h"

#include "lh_alloc.h"

#include <string.h>

#define LH__UNSET (-3) /* a new cell's neighbour not linked yet */

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

void lh__tds_release(lh__tds *t)
{
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
    t->cells = t->bound = t->fresh = NULL;
    t->cells_cap = t->bound_cap = t->fresh_cap = 0;
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

/* The partner of new cell N (made from boundary facet (c, k)) across its facet
 * opposite v_j: turn around the ridge c \ {v_k, v_j}. Links both sides. */
static void link_across(lh__tds *t, int32_t N, int32_t c, int k, int j, uint32_t fresh)
{
    const int nv = t->nv;
    int32_t u = t->vert[(size_t)c * nv + j], w = t->vert[(size_t)c * nv + k];
    int32_t cur = c;
    for (;;) {
        const int32_t *cv = t->vert + (size_t)cur * nv;
        int32_t nxt = t->nbr[(size_t)cur * nv + index_of(cv, nv, u)];
        if (t->stamp[nxt] == fresh) {
            int iw = index_of(cv, nv, w); /* same position in the new cell */
            t->nbr[(size_t)nxt * nv + iw] = N;
            t->nbr[(size_t)N * nv + j] = nxt;
            return;
        }
        int m = lh__tds_mirror(t, nxt, cur);
        int32_t y = t->vert[(size_t)nxt * nv + m];
        u = w;
        w = y;
        cur = nxt;
    }
}

lh_status lh__tds_insert(lh__tds *t, int32_t start, int32_t q, lh__conflict_fn conflict,
                         void *user)
{
    const int nv = t->nv;
    next_round(t);
    uint32_t in = 4 * t->round, out = in + 1, fresh = in + 2;
    if (!grow_region(t, start, conflict, user, in, out)) return LH_ERR_NOMEM;
    if (t->fresh_cap < t->nbound) {
        int32_t *p = grow(&t->alloc, t->fresh, 0, t->nbound * 2 * 4);
        if (!p) return LH_ERR_NOMEM;
        t->fresh = p;
        t->fresh_cap = t->nbound * 2;
    }
    lh_status st = lh__tds_reserve(t, t->nbound);
    if (st != LH_OK) return st;

    for (size_t b = 0; b < t->nbound; b++) {
        int32_t c = t->bound[2 * b], k = t->bound[2 * b + 1];
        int32_t N = lh__tds_new_cell(t); /* cannot fail after the reserve */
        int32_t *nv_ = t->vert + (size_t)N * nv, *nn = t->nbr + (size_t)N * nv;
        const int32_t *cv = t->vert + (size_t)c * nv;
        for (int j = 0; j < nv; j++) {
            nv_[j] = cv[j];
            nn[j] = LH__UNSET;
        }
        nv_[k] = q;
        int32_t outside = t->nbr[(size_t)c * nv + k];
        nn[k] = outside;
        t->nbr[(size_t)outside * nv + lh__tds_mirror(t, outside, c)] = N;
        t->nbr[(size_t)c * nv + k] = N; /* c dies below; the slot maps its facet to N */
        t->stamp[N] = fresh;
        t->fresh[b] = N;
    }
    for (size_t b = 0; b < t->nbound; b++) {
        int32_t N = t->fresh[b], c = t->bound[2 * b];
        int k = t->bound[2 * b + 1];
        for (int j = 0; j < nv; j++)
            if (j != k && t->nbr[(size_t)N * nv + j] == LH__UNSET) link_across(t, N, c, k, j, fresh);
    }
    for (size_t i = 0; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return LH_OK;
}
