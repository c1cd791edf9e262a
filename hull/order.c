/*
 * order.c — what happens to the sites before the first insertion (engine.h): a radix sort on
 * Hilbert keys, which also brings exact duplicates together to be merged; the
 * insertion order (BRIO: Amenta, Choi & Rote, "Incremental constructions con BRIO",
 * SoCG 2003, Hilbert order in each round); and an initial simplex of d+1 affinely
 * independent sites, found exactly.
 */
#include "engine.h"
#include "hilbert.h"
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

/* Bits per coordinate of the Hilbert keys: enough for about 8n cells over the
 * bounding box (locality needs no more: a cell then holds at most a few sites, kept
 * in input order), at most 16 and 63/d. Equal keys only cost an exact comparison. */
static int curve_bits(int d, size_t n)
{
    int lg = 3;
    while (lg < 64 && (n >> (lg - 3)) > 1) lg++; /* about log2(8n) */
    int bits = (lg + d - 1) / d, cap = 63 / d < 16 ? 63 / d : 16;
    return bits < cap ? bits : cap;
}

/* The Hilbert key of every site: each coordinate quantised to curve_bits(d, n)
 * bits over the bounding box, the cell's index along the Hilbert curve of that
 * grid. Consecutive keys are adjacent cells, unlike Morton (Z-order) keys, whose
 * jumps made the walk from one site to the next longer: in 3D 10^6 the predicates
 * went from 59.3 to 57.3 million (the walk's orientations). A span too wide for
 * doubles quantises to 0 (keys tie; correctness does not depend on them); a span
 * so small that its reciprocal overflows is scaled by a power of two first
 * (exact). */
typedef struct curve {
    const lh__eng *t;
    uint64_t *key;
    int bits;
    double cells, lo[LH__ENGINE_MAX_DIM], scale[LH__ENGINE_MAX_DIM];
    int shift[LH__ENGINE_MAX_DIM]; /* a tiny span is first scaled up by 2^-shift */
    int tables;                    /* 2D and 3D from TABLE_SITES sites: keys from h */
    lh__hilbert h;
} curve;
/* Sites from which the tables are worth building: building them is a fixed cost,
 * repaid by a key from the tables costing less than half the transform's
 * (docs/bench-engine.md). */
enum { TABLE_SITES = 1 << 12 };

/* The low `bits` bits of x spread d places apart (bit b to bit b d): by masks
 * for d = 2 (16 bits) and d = 3 (21 bits), each step halving the runs of
 * consecutive bits, else bit by bit. */
static inline uint64_t spread_bits(uint64_t x, int d, int bits)
{
    if (d == 2) {
        x = (x | x << 8) & UINT64_C(0x00ff00ff);
        x = (x | x << 4) & UINT64_C(0x0f0f0f0f);
        x = (x | x << 2) & UINT64_C(0x33333333);
        return (x | x << 1) & UINT64_C(0x55555555);
    }
    if (d == 3) {
        x = (x | x << 32) & UINT64_C(0x001f00000000ffff);
        x = (x | x << 16) & UINT64_C(0x001f0000ff0000ff);
        x = (x | x << 8) & UINT64_C(0x100f00f00f00f00f);
        x = (x | x << 4) & UINT64_C(0x10c30c30c30c30c3);
        return (x | x << 2) & UINT64_C(0x1249249249249249);
    }
    uint64_t k = 0;
    for (int b = 0; b < bits; b++) k |= (x >> b & 1) << (b * d);
    return k;
}

/* The cell x[0..d-1] (bits each) turned in place into the transpose of its index
 * along the Hilbert curve: interleaving its bits, x[0]'s first at each level, gives
 * the index (Skilling, "Programming the Hilbert curve", AIP Conf. Proc. 707, 2004:
 * from the top level down, each coordinate's bit either inverts x[0]'s lower bits
 * or exchanges them with its own; then a Gray code). Branch-free: the bits are
 * random, so branches on them would be mispredicted half the time. */
static LH__ALWAYS_INLINE void transpose_d(uint64_t *x, const int d, int bits)
{
    for (uint64_t q = (uint64_t)1 << (bits - 1); q > 1; q >>= 1) {
        const uint64_t low = q - 1;
        for (int i = 0; i < d; i++) {
            const uint64_t set = 0 - (uint64_t)((x[i] & q) != 0);
            const uint64_t swap = (x[0] ^ x[i]) & low & ~set;
            x[0] ^= (low & set) | swap;
            x[i] ^= swap;
        }
    }
    for (int i = 1; i < d; i++) x[i] ^= x[i - 1];
    uint64_t flip = 0;
    for (uint64_t q = (uint64_t)1 << (bits - 1); q > 1; q >>= 1) flip ^= (q - 1) & (0 - (uint64_t)((x[d - 1] & q) != 0));
    for (int i = 0; i < d; i++) x[i] ^= flip;
}

void lh__hilbert_transpose(uint64_t *x, int d, int bits) { transpose_d(x, d, bits); }

/* The keys of sites lo..hi-1, by the tables (hilbert.h) or the transform; with d a
 * constant in 2D and 3D (key_range), the cell stays in registers and the loops
 * unroll (a third of the site order's time otherwise, 3D 10^6). */
static LH__ALWAYS_INLINE void keys_d(const curve *m, size_t lo, size_t hi, const int d, const int tables)
{
    for (size_t i = lo; i < hi; i++) {
        const double *p = m->t->xyz + i * d;
        uint64_t cell[LH__ENGINE_MAX_DIM], k = 0;
        for (int j = 0; j < d; j++) {
            double x = (m->shift[j] ? ldexp(p[j] - m->lo[j], -m->shift[j]) : p[j] - m->lo[j]) * m->scale[j];
            cell[j] = x > 0 ? (x < m->cells ? (uint64_t)x : (uint64_t)m->cells) : 0;
        }
        if (!tables) transpose_d(cell, d, m->bits);
        for (int j = 0; j < d; j++) /* coordinate j's bit b goes to bit b d + d - 1 - j */
            k |= spread_bits(cell[j], d, m->bits) << (d - 1 - j);
        m->key[i] = tables ? lh__hilbert_key(&m->h, k, m->bits, d) : k; /* k: the Morton code */
    }
}

static void key_range(void *ctx, size_t lo, size_t hi)
{
    const curve *m = ctx;
    if (m->tables && m->t->d == 2) keys_d(m, lo, hi, 2, 1);
    else if (m->tables) keys_d(m, lo, hi, 3, 1);
    else if (m->t->d == 2) keys_d(m, lo, hi, 2, 0);
    else if (m->t->d == 3) keys_d(m, lo, hi, 3, 0);
    else keys_d(m, lo, hi, m->t->d, 0);
}

static void curve_keys(const lh__eng *t, uint64_t *key)
{
    curve m = {.t = t, .key = key, .bits = curve_bits(t->d, t->n)};
    m.tables = t->n >= TABLE_SITES && lh__hilbert_init(&m.h, t->d);
    m.cells = (double)((UINT64_C(1) << m.bits) - 1);
    for (int j = 0; j < t->d; j++) { /* the bounding box from lh__eng_init */
        m.lo[j] = t->lo[j];
        double span = t->span[j];
        if (span > 0 && span < 0x1p-900) frexp(span, &m.shift[j]); /* 1/span would overflow */
        m.scale[j] = span > 0 && span < 1e308 ? m.cells / ldexp(span, -m.shift[j]) : 0;
    }
    lh__par_range(t->threads, t->n, key_range, &m);
}

/* A stable counting-sort pass: the n items of (ka, ia) to (kb, ib) by a digit
 * below 2^MAX_DIGIT, either bits shift.. of the key (the radix sort's passes) or a
 * byte per item (dig: the BRIO rounds, keys unused). Threads share it: each counts
 * its share of the items, then moves it after the same digits of the shares before
 * it, so the result is the sequential one. */
enum { MAX_DIGIT = 12 };
typedef struct pass {
    const uint64_t *ka;
    uint64_t *kb;
    const lh_index *ia;
    lh_index *ib;
    const uint8_t *dig; /* per item its digit, or NULL: the key's bits */
    int shift;
    uint64_t mask;
    size_t n, *count;   /* per thread 2^MAX_DIGIT counts, then places */
} pass;

static inline size_t digit_of(const pass *p, size_t i)
{
    return p->dig ? p->dig[i] : (size_t)((p->ka[i] >> p->shift) & p->mask);
}

static void count_share(void *ctx, int w, int nw)
{
    const pass *p = ctx;
    size_t *count = p->count + ((size_t)w << MAX_DIGIT);
    memset(count, 0, ((size_t)p->mask + 1) * sizeof *count);
    for (size_t i = lh__share(p->n, w, nw), hi = lh__share(p->n, w + 1, nw); i < hi; i++) count[digit_of(p, i)]++;
}

static void move_share(void *ctx, int w, int nw)
{
    const pass *p = ctx;
    size_t *place = p->count + ((size_t)w << MAX_DIGIT);
    for (size_t i = lh__share(p->n, w, nw), hi = lh__share(p->n, w + 1, nw); i < hi; i++) {
        const size_t o = place[digit_of(p, i)]++;
        if (p->kb) p->kb[o] = p->ka[i];
        p->ib[o] = p->ia[i];
    }
}

static void counting_pass(pass *p, int nw)
{
    lh__par_for(nw, count_share, p);
    size_t sum = 0; /* digit by digit, thread by thread: a thread's first place */
    for (size_t b = 0; b <= p->mask; b++)
        for (int w = 0; w < nw; w++) {
            size_t *c = p->count + ((size_t)w << MAX_DIGIT) + b, k = *c;
            *c = sum;
            sum += k;
        }
    lh__par_for(nw, move_share, p);
}

/* After counting_pass: where the items of digit b end (the last share's places have
 * moved past its own, which come last in b). */
static inline size_t digit_end(const pass *p, int nw, size_t b) { return p->count[((size_t)(nw - 1) << MAX_DIGIT) + b]; }

/* LSD radix sort of (key, idx) pairs on the low `bits` bits, in as few passes of
 * at most MAX_DIGIT bits as there can be (a count table of 4096 stays in L1/L2);
 * the passes go back and forth between the arrays and the scratch k2, i2. count:
 * nw << MAX_DIGIT entries. */
static void radix_sort(uint64_t *key, lh_index *idx, uint64_t *k2, lh_index *i2, size_t n, int bits,
                       size_t *count, int nw)
{
    const int passes = (bits + MAX_DIGIT - 1) / MAX_DIGIT;
    const int digit = passes ? (bits + passes - 1) / passes : 0;
    uint64_t *ka = key, *kb = k2;
    lh_index *ia = idx, *ib = i2;
    for (int shift = 0; shift < bits; shift += digit) {
        pass p = {ka, kb, ia, ib, NULL, shift, (UINT64_C(1) << digit) - 1, n, count};
        counting_pass(&p, nw);
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

/* Equal sites share a Hilbert key, and the radix sort keeps a run of equal keys in
 * increasing index order. A short run is searched pair by pair for equal sites, a
 * long one sorted exactly (lexicographically, ties by index) so that equal sites are
 * adjacent; either way the smallest index of equal sites is the vertex. Threads
 * share the runs (runs_share): each compacts the distinct sites of its runs at the
 * start of its share of idx, and the shares are then put end to end (merge_runs),
 * which returns the number of distinct sites, in Hilbert order in idx. */
typedef struct runs {
    lh__eng *t;
    const uint64_t *key;
    lh_index *idx, *tmp;
    size_t from[LH__MAX_THREADS + 1]; /* share w: runs starting in from[w]..from[w+1]-1 */
    size_t nrep[LH__MAX_THREADS], ndup[LH__MAX_THREADS];
} runs;

static void runs_share(void *ctx, int w, int nw)
{
    enum { FEW = 8 }; /* the keys' resolution makes most runs one or two sites */
    runs *u = ctx;
    lh__eng *t = u->t;
    const uint64_t *key = u->key;
    lh_index *idx = u->idx;
    lh__lex c = {t->xyz, t->d};
    const size_t lo = u->from[w], hi = u->from[w + 1];
    size_t nrep = lo, ndup = 0;
    (void)nw;
    for (size_t i = lo; i < hi;) {
        size_t j = i + 1;
        while (j < hi && key[j] == key[i]) j++;
        const int sorted = j - i > FEW;
        if (sorted) lh__sort_idx(idx + i, u->tmp + i, j - i, lh__lex_cmp, &c);
        const size_t first = nrep; /* this run's distinct sites: idx[first..nrep) */
        for (size_t k = i; k < j; k++) {
            lh_index s = idx[k], rep = s;
            for (size_t r = sorted && nrep > first ? nrep - 1 : first; r < nrep; r++)
                if (same_site(t, s, idx[r])) {
                    rep = idx[r];
                    break;
                }
            if (rep != s) /* a distinct site's entry is itself already (identity_range) */
                t->dup[s] = rep, ndup++;
            else
                idx[nrep++] = s;
        }
        i = j;
    }
    u->nrep[w] = nrep - lo;
    u->ndup[w] = ndup;
}

/* Entries lo..hi-1 of the index array ctx set to their own positions. */
static void identity_range(void *ctx, size_t lo, size_t hi)
{
    lh_index *dup = ctx;
    for (size_t i = lo; i < hi; i++) dup[i] = (lh_index)i;
}

static size_t merge_runs(lh__eng *t, const uint64_t *key, lh_index *idx, lh_index *tmp, int nw)
{
    runs u = {.t = t, .key = key, .idx = idx, .tmp = tmp};
    const size_t n = t->n;
    /* every site its own first: the runs then write only the duplicates (the
       sites come in Hilbert order, so each write of every site's entry would be a
       cache miss) */
    lh__par_range(t->threads, n, identity_range, t->dup);
    for (int w = 0; w <= nw; w++) { /* share boundaries moved to the next run's start */
        size_t x = lh__share(n, w, nw);
        while (x > 0 && x < n && key[x] == key[x - 1]) x++;
        u.from[w] = w && x < u.from[w - 1] ? u.from[w - 1] : x;
    }
    lh__par_for(nw, runs_share, &u);
    size_t nrep = u.nrep[0];
    t->ndup = u.ndup[0];
    for (int w = 1; w < nw; w++) {
        memmove(idx + nrep, idx + u.from[w], u.nrep[w] * sizeof *idx);
        nrep += u.nrep[w];
        t->ndup += u.ndup[w];
    }
    return nrep;
}

/* BRIO rounds: a site joins round r with probability 2^-(r+1) (r capped), drawn
 * from a hash of the seed and its position (so that threads can share the draw);
 * rounds go from the rarest to the commonest, each keeping the Hilbert order. */
typedef struct brio {
    uint8_t *round;
    uint64_t seed;
} brio;

/* The number of consecutive 1 bits at the bottom of x (one instruction, not a
 * loop whose exit is a coin toss to mispredict). */
static inline int trailing_ones(uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
    return ~x ? __builtin_ctzll(~x) : 64;
#else
    int r = 0;
    while (r < 64 && (x >> r & 1)) r++;
    return r;
#endif
}

static void draw_rounds(void *ctx, size_t lo, size_t hi)
{
    const brio *b = ctx;
    for (size_t i = lo; i < hi; i++) {
        uint64_t x = b->seed + (uint64_t)i * UINT64_C(0x9e3779b97f4a7c15); /* splitmix64 */
        x = (x ^ (x >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
        x = (x ^ (x >> 27)) * UINT64_C(0x94d049bb133111eb);
        x ^= x >> 31;
        const int r = trailing_ones(x); /* each with probability 1/2 */
        b->round[i] = (uint8_t)(LH__BRIO_ROUNDS - 1 - (r < LH__BRIO_ROUNDS - 1 ? r : LH__BRIO_ROUNDS - 1));
    }
}

static void brio_rounds(lh__eng *e, lh_index *tmp, uint8_t *round, size_t *count, int nw)
{
    const size_t n = e->norder;
    brio b = {round, lh__rng_next(&e->rng)};
    lh__par_range(e->threads, n, draw_rounds, &b);
    _Static_assert(LH__BRIO_ROUNDS <= 32, "a round is a digit below 32");
    pass p = {NULL, NULL, e->order, tmp, round, 0, 31, n, count};
    counting_pass(&p, nw);
    for (int r = 0; r < LH__BRIO_ROUNDS; r++) e->round_end[r] = digit_end(&p, nw, (size_t)r);
    memcpy(e->order, tmp, n * sizeof *tmp);
}

lh_status lh__eng_order(lh__eng *b)
{
    lh__eng *t = b;
    size_t n = t->n;
    const int nw = lh__par_width(t->threads, n);
    uint64_t *key = lh__alloc(&t->alloc, (n + 1) * sizeof *key), *k2 = lh__alloc(&t->alloc, (n + 1) * sizeof *k2);
    lh_index *idx = lh__alloc(&t->alloc, (n + 1) * sizeof *idx), *i2 = lh__alloc(&t->alloc, (n + 1) * sizeof *i2);
    size_t *count = lh__alloc(&t->alloc, ((size_t)nw << MAX_DIGIT) * sizeof *count);
    lh_status st = key && k2 && idx && i2 && count ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK && n) {
        curve_keys(t, key);
        lh__par_range(t->threads, n, identity_range, idx);
        radix_sort(key, idx, k2, i2, n, curve_bits(t->d, n) * t->d, count, nw);
        b->order = idx;
        b->norder = merge_runs(t, key, idx, i2, nw);
        brio_rounds(b, i2, (uint8_t *)k2, count, lh__par_width(t->threads, b->norder));
        idx = NULL; /* now b->order */
    }
    lh__free(&t->alloc, key);
    lh__free(&t->alloc, k2);
    lh__free(&t->alloc, idx);
    lh__free(&t->alloc, i2);
    lh__free(&t->alloc, count);
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
