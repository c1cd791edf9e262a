/*
 * order.c — what happens to the sites before the first insertion: exact duplicates
 * merged (lexicographic sort), the insertion order (BRIO: Amenta, Choi & Rote,
 * "Incremental constructions con BRIO", SoCG 2003, with a Morton order in each
 * round), and an initial simplex of d+1 affinely independent sites, found exactly.
 */
#include "dt.h"
#include "lh_sort.h"

#include <string.h>

typedef struct lex_ctx {
    const double *xyz;
    int d;
} lex_ctx;

static int lex_cmp(const void *vctx, int32_t a, int32_t b)
{
    const lex_ctx *c = vctx;
    const double *p = c->xyz + (size_t)a * c->d, *q = c->xyz + (size_t)b * c->d;
    for (int j = 0; j < c->d; j++)
        if (p[j] != q[j]) return p[j] < q[j] ? -1 : 1;
    return (a > b) - (a < b);
}

static int same_site(const lh_tri *t, int32_t a, int32_t b)
{
    const double *p = t->xyz + (size_t)a * t->d, *q = t->xyz + (size_t)b * t->d;
    for (int j = 0; j < t->d; j++)
        if (p[j] != q[j]) return 0;
    return 1;
}

lh_status lh__dt_merge_duplicates(lh__dt *b)
{
    lh_tri *t = b->t;
    size_t n = t->n;
    int32_t *idx = lh__alloc(&t->alloc, n * sizeof *idx), *tmp = lh__alloc(&t->alloc, n * sizeof *tmp);
    if (!idx || !tmp) {
        lh__free(&t->alloc, idx);
        lh__free(&t->alloc, tmp);
        return LH_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++) idx[i] = (int32_t)i;
    lex_ctx c = {t->xyz, t->d};
    lh__sort_idx(idx, tmp, n, lex_cmp, &c);
    /* Equal sites are adjacent, smallest index first (the comparator breaks ties by
     * index): that one is the vertex. The distinct sites are compacted into idx, in
     * lexicographic order. */
    size_t nrep = 0;
    int32_t prev = -1;
    t->ndup = 0;
    for (size_t i = 0; i < n; i++) {
        int32_t s = idx[i];
        if (prev >= 0 && same_site(t, s, prev)) {
            t->dup[s] = t->dup[prev];
            t->ndup++;
        } else {
            t->dup[s] = s;
            idx[nrep++] = s;
        }
        prev = s;
    }
    lh__free(&t->alloc, tmp);
    b->order = idx;
    b->norder = nrep;
    return LH_OK;
}

/* Morton (Z-order) key: each coordinate quantised to 63/d bits over the bounding box,
 * bits interleaved from the most significant down. */
static void morton_keys(const lh__dt *b, uint64_t *key)
{
    int d = b->d, bits = 63 / d;
    double lo[LH_DELAUNAY_MAX_DIM], scale[LH_DELAUNAY_MAX_DIM];
    for (int j = 0; j < d; j++) {
        double mn = lh__dt_site(b, b->order[0])[j], mx = mn;
        for (size_t i = 1; i < b->norder; i++) {
            double x = lh__dt_site(b, b->order[i])[j];
            if (x < mn) mn = x;
            if (x > mx) mx = x;
        }
        lo[j] = mn;
        double span = mx - mn; /* may overflow to inf for huge spreads: then all 0 */
        scale[j] = span > 0 && span < 1e308 ? ((double)((UINT64_C(1) << bits) - 1)) / span : 0;
    }
    for (size_t i = 0; i < b->norder; i++) {
        const double *p = lh__dt_site(b, b->order[i]);
        uint64_t cell[LH_DELAUNAY_MAX_DIM], k = 0;
        for (int j = 0; j < d; j++) {
            double x = (p[j] - lo[j]) * scale[j];
            cell[j] = x > 0 ? (uint64_t)x : 0;
        }
        for (int bit = bits - 1; bit >= 0; bit--)
            for (int j = 0; j < d; j++) k = (k << 1) | ((cell[j] >> bit) & 1);
        key[b->order[i]] = k;
    }
}

typedef struct key_ctx {
    const uint64_t *key;
} key_ctx;

static int key_cmp(const void *vctx, int32_t a, int32_t b)
{
    const uint64_t *k = ((const key_ctx *)vctx)->key;
    return (k[a] > k[b]) - (k[a] < k[b]);
}

lh_status lh__dt_insertion_order(lh__dt *b)
{
    lh_tri *t = b->t;
    size_t n = b->norder;
    if (n < 2) return LH_OK;
    uint64_t *key = lh__alloc(&t->alloc, t->n * sizeof *key);
    int32_t *tmp = lh__alloc(&t->alloc, n * sizeof *tmp);
    if (!key || !tmp) {
        lh__free(&t->alloc, key);
        lh__free(&t->alloc, tmp);
        return LH_ERR_NOMEM;
    }
    morton_keys(b, key);
    key_ctx kc = {key};
    lh__sort_idx(b->order, tmp, n, key_cmp, &kc);
    /* BRIO rounds: a site joins round r with probability 2^-(r+1) (r capped); rounds
     * go from the rarest to the commonest, each in Morton order (a stable pass). */
    enum { ROUNDS = 24 };
    size_t start[ROUNDS + 1] = {0};
    uint8_t *round = (uint8_t *)key; /* reuse: key is no longer needed after this */
    for (size_t i = 0; i < n; i++) {
        uint64_t x = lh__rng_next(&b->rng);
        int r = 0;
        while (r < ROUNDS - 1 && (x & 1)) {
            r++;
            x >>= 1;
        }
        round[i] = (uint8_t)(ROUNDS - 1 - r);
        start[round[i] + 1]++;
    }
    for (int r = 0; r < ROUNDS; r++) start[r + 1] += start[r];
    for (size_t i = 0; i < n; i++) tmp[start[round[i]]++] = b->order[i];
    memcpy(b->order, tmp, n * sizeof *tmp);
    lh__free(&t->alloc, key);
    lh__free(&t->alloc, tmp);
    return LH_OK;
}

/* Whether pts[k] is outside the affine hull of pts[0..k-1] (affinely independent, in
 * R^d), exactly: some (k+1)-subset K of the coordinates gives a nonzero orient_k of
 * the points projected onto K (a nonzero maximal minor of [1, p]). */
int lh__affine_independent(lh_pred *pred, int d, const double *const *pts, int k)
{
    if (k == 0) return 1;
    if (k == d) return lh_orient(pred, d, pts) != 0;
    double proj[LH_DELAUNAY_MAX_DIM + 1][LH_DELAUNAY_MAX_DIM];
    const double *pp[LH_DELAUNAY_MAX_DIM + 1];
    for (int mask = 0; mask < (1 << d); mask++) {
        int cols[LH_DELAUNAY_MAX_DIM], m = 0;
        for (int j = 0; j < d; j++)
            if (mask & (1 << j)) cols[m++] = j;
        if (m != k) continue;
        for (int i = 0; i <= k; i++) {
            for (int j = 0; j < k; j++) proj[i][j] = pts[i][cols[j]];
            pp[i] = proj[i];
        }
        if (lh_orient(pred, k, pp)) return 1;
    }
    return 0;
}

/* Moves d+1 affinely independent sites to the front of the insertion order, taking
 * each site in order when it raises the affine dimension. Returns the affine
 * dimension of the distinct sites when it is below d, else d. */
int lh__dt_initial_simplex(lh__dt *b)
{
    int d = b->d, k = 0;
    const double *pts[LH_DELAUNAY_MAX_DIM + 1];
    if (b->norder == 0) return -1;
    pts[0] = lh__dt_site(b, b->order[0]);
    for (size_t i = 1; i < b->norder && k < d; i++) {
        pts[k + 1] = lh__dt_site(b, b->order[i]);
        if (lh__affine_independent(b->pred, d, pts, k + 1)) {
            k++;
            int32_t s = b->order[i]; /* keep the rest in order: rotate it forward */
            memmove(b->order + k + 1, b->order + k, (i - (size_t)k) * sizeof *b->order);
            b->order[k] = s;
        }
    }
    return k;
}
