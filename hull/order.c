/*
 * order.c — what happens to the sites before the first insertion (engine.h): a radix sort on
 * Morton keys, which also brings exact duplicates together to be merged; the
 * insertion order (BRIO: Amenta, Choi & Rote, "Incremental constructions con BRIO",
 * SoCG 2003, Morton order in each round); and an initial simplex of d+1 affinely
 * independent sites, found exactly.
 */
#include "engine.h"
#include "lh_sort.h"

#include <math.h>
#include <string.h>

int lh__lex_cmp(const void *vctx, lh_index a, lh_index b)
{
    const lh__lex *c = vctx;
    const double *p = c->xyz + (size_t)a * c->d, *q = c->xyz + (size_t)b * c->d;
    for (int j = 0; j < c->d; j++)
        if (p[j] != q[j]) return p[j] < q[j] ? -1 : 1;
    return (a > b) - (a < b);
}

static int same_site(const lh__eng *e, lh_index a, lh_index b)
{
    const double *p = lh__eng_input(e, (size_t)a), *q = lh__eng_input(e, (size_t)b);
    for (int j = 0; j < e->d; j++)
        if (p[j] != q[j]) return 0;
    return 1;
}

/* Bits per coordinate of the Morton keys: enough for about 8n cells over the
 * bounding box (locality needs no more: a cell then holds at most a few sites, kept
 * in input order), at most 16 and 63/d. Equal keys only cost an exact comparison. */
static int morton_bits(int d, size_t n)
{
    int lg = 3;
    while (lg < 64 && (n >> (lg - 3)) > 1) lg++; /* about log2(8n) */
    int bits = (lg + d - 1) / d, cap = 63 / d < 16 ? 63 / d : 16;
    return bits < cap ? bits : cap;
}

/* Morton (Z-order) key of every site: each coordinate quantised to morton_bits(d, n)
 * bits over the bounding box, bits interleaved from the most significant down. A
 * span too wide for doubles quantises to 0 (keys tie; correctness does not depend
 * on them); a span so small that its reciprocal overflows is scaled by a power of
 * two first (exact). */
typedef struct morton {
    const lh__eng *t;
    uint64_t *key;
    int bits;
    double cells, lo[LH__ENGINE_MAX_DIM], scale[LH__ENGINE_MAX_DIM];
    int shift[LH__ENGINE_MAX_DIM]; /* a tiny span is first scaled up by 2^-shift */
} morton;

static void morton_range(void *ctx, size_t lo, size_t hi)
{
    const morton *m = ctx;
    const int d = m->t->d;
    for (size_t i = lo; i < hi; i++) {
        const double *p = m->t->xyz + i * d;
        uint64_t cell[LH__ENGINE_MAX_DIM], k = 0;
        for (int j = 0; j < d; j++) {
            double x = (m->shift[j] ? ldexp(p[j] - m->lo[j], -m->shift[j]) : p[j] - m->lo[j]) * m->scale[j];
            cell[j] = x > 0 ? (x < m->cells ? (uint64_t)x : (uint64_t)m->cells) : 0;
        }
        for (int bit = m->bits - 1; bit >= 0; bit--)
            for (int j = 0; j < d; j++) k = (k << 1) | ((cell[j] >> bit) & 1);
        m->key[i] = k;
    }
}

static void morton_keys(const lh__eng *t, uint64_t *key)
{
    morton m = {t, key, morton_bits(t->d, t->n), 0, {0}, {0}, {0}};
    m.cells = (double)((UINT64_C(1) << m.bits) - 1);
    for (int j = 0; j < t->d; j++) { /* the bounding box from lh__eng_init */
        m.lo[j] = t->lo[j];
        double span = t->span[j];
        if (span > 0 && span < 0x1p-900) frexp(span, &m.shift[j]); /* 1/span would overflow */
        m.scale[j] = span > 0 && span < 1e308 ? m.cells / ldexp(span, -m.shift[j]) : 0;
    }
    lh__par_range(t->threads, t->n, morton_range, &m);
}

/* LSD radix sort of (key, idx) pairs on the low `bits` bits, in as few passes of
 * at most 12 bits as there can be (a count table of 4096 stays in L1/L2); the
 * passes go back and forth between the arrays and the scratch k2, i2. */
static void radix_sort(uint64_t *key, lh_index *idx, uint64_t *k2, lh_index *i2, size_t n, int bits)
{
    enum { MAX_DIGIT = 12 };
    size_t count[1 << MAX_DIGIT];
    const int passes = (bits + MAX_DIGIT - 1) / MAX_DIGIT;
    const int digit = passes ? (bits + passes - 1) / passes : 0;
    const uint64_t mask = (UINT64_C(1) << digit) - 1;
    uint64_t *ka = key, *kb = k2;
    lh_index *ia = idx, *ib = i2;
    for (int shift = 0; shift < bits; shift += digit) {
        memset(count, 0, sizeof count);
        for (size_t i = 0; i < n; i++) count[(ka[i] >> shift) & mask]++;
        size_t sum = 0;
        for (size_t b = 0; b <= mask; b++) {
            size_t c = count[b];
            count[b] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++) {
            size_t o = count[(ka[i] >> shift) & mask]++;
            kb[o] = ka[i];
            ib[o] = ia[i];
        }
        uint64_t *kt = ka;
        ka = kb, kb = kt;
        lh_index *it = ia;
        ia = ib, ib = it;
    }
    if (ka != key) {
        memcpy(key, ka, n * sizeof *key);
        memcpy(idx, ia, n * sizeof *idx);
    }
}

/* Equal sites share a Morton key, and the radix sort keeps a run of equal keys in
 * increasing index order. A short run is searched pair by pair for equal sites, a
 * long one sorted exactly (lexicographically, ties by index) so that equal sites are
 * adjacent; either way the smallest index of equal sites is the vertex. Compacts the
 * distinct sites into idx (Morton order) and returns their number. */
static size_t merge_runs(lh__eng *t, const uint64_t *key, lh_index *idx, lh_index *tmp)
{
    enum { FEW = 8 }; /* the keys' resolution makes most runs one or two sites */
    lh__lex c = {t->xyz, t->d};
    size_t nrep = 0;
    t->ndup = 0;
    for (size_t i = 0; i < t->n;) {
        size_t j = i + 1;
        while (j < t->n && key[j] == key[i]) j++;
        const int sorted = j - i > FEW;
        if (sorted) lh__sort_idx(idx + i, tmp, j - i, lh__lex_cmp, &c);
        const size_t first = nrep; /* this run's distinct sites: idx[first..nrep) */
        for (size_t k = i; k < j; k++) {
            lh_index s = idx[k], rep = s;
            for (size_t r = sorted && nrep > first ? nrep - 1 : first; r < nrep; r++)
                if (same_site(t, s, idx[r])) {
                    rep = idx[r];
                    break;
                }
            t->dup[s] = rep;
            if (rep != s)
                t->ndup++;
            else
                idx[nrep++] = s;
        }
        i = j;
    }
    return nrep;
}

/* BRIO rounds: a site joins round r with probability 2^-(r+1) (r capped); rounds
 * go from the rarest to the commonest, each keeping the Morton order. */
static void brio_rounds(lh__eng *b, lh_index *tmp, uint8_t *round)
{
    enum { ROUNDS = LH__BRIO_ROUNDS };
    size_t n = b->norder, start[ROUNDS + 1] = {0};
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
    for (int r = 0; r < ROUNDS; r++) b->round_end[r] = start[r]; /* now the ends */
    memcpy(b->order, tmp, n * sizeof *tmp);
}

lh_status lh__eng_order(lh__eng *b)
{
    lh__eng *t = b;
    size_t n = t->n;
    uint64_t *key = lh__alloc(&t->alloc, (n + 1) * sizeof *key), *k2 = lh__alloc(&t->alloc, (n + 1) * sizeof *k2);
    lh_index *idx = lh__alloc(&t->alloc, (n + 1) * sizeof *idx), *i2 = lh__alloc(&t->alloc, (n + 1) * sizeof *i2);
    lh_status st = key && k2 && idx && i2 ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK && n) {
        morton_keys(t, key);
        for (size_t i = 0; i < n; i++) idx[i] = (lh_index)i;
        radix_sort(key, idx, k2, i2, n, morton_bits(t->d, n) * t->d);
        b->order = idx;
        b->norder = merge_runs(t, key, idx, i2);
        brio_rounds(b, i2, (uint8_t *)k2);
        idx = NULL; /* now b->order */
    }
    lh__free(&t->alloc, key);
    lh__free(&t->alloc, k2);
    lh__free(&t->alloc, idx);
    lh__free(&t->alloc, i2);
    return st;
}

int lh__independent_coords(lh_pred *pred, int d, const double *const *pts, int k, int *J)
{
    double proj[LH__ENGINE_MAX_DIM + 1][LH__ENGINE_MAX_DIM];
    const double *pp[LH__ENGINE_MAX_DIM + 1];
    for (int mask = 0; mask < (1 << d); mask++) {
        int m = 0;
        for (int j = 0; j < d; j++)
            if (mask & (1 << j)) J[m++] = j;
        if (m != k) continue;
        for (int i = 0; i <= k; i++) {
            for (int j = 0; j < k; j++) proj[i][j] = pts[i][J[j]];
            pp[i] = proj[i];
        }
        if (lh_orient(pred, k, pp)) return 1;
    }
    return 0;
}

/* Whether pts[k] is outside the affine hull of pts[0..k-1] (affinely independent, in
 * R^d), exactly: some (k+1)-subset K of the coordinates gives a nonzero orient_k of
 * the points projected onto K (a nonzero maximal minor of [1, p]). */
int lh__affine_independent(lh_pred *pred, int d, const double *const *pts, int k)
{
    if (k == 0) return 1;
    if (k == d) return lh_orient(pred, d, pts) != 0;
    int J[LH__ENGINE_MAX_DIM];
    return lh__independent_coords(pred, d, pts, k, J);
}

/* Moves d+1 affinely independent sites to the front of the insertion order, taking
 * each site in order when it raises the affine dimension. Returns the affine
 * dimension of the distinct sites when it is below d, else d. */
int lh__eng_initial_simplex(lh__eng *b)
{
    int d = b->d, k = 0;
    const double *pts[LH__ENGINE_MAX_DIM + 1];
    if (b->norder == 0) return -1;
    pts[0] = lh__eng_input(b, (size_t)b->order[0]);
    for (size_t i = 1; i < b->norder && k < d; i++) {
        pts[k + 1] = lh__eng_input(b, (size_t)b->order[i]);
        if (lh__affine_independent(b->pred, d, pts, k + 1)) {
            k++;
            lh_index s = b->order[i]; /* keep the rest in order: rotate it forward */
            memmove(b->order + k + 1, b->order + k, (i - (size_t)k) * sizeof *b->order);
            b->order[k] = s;
        }
    }
    return k;
}
