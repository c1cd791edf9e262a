/*
 * pred_exact.c — the exact stage: signs of minors of the homogeneous matrix in
 * integer arithmetic.
 *
 * Every entry is made an integer by one power-of-two scale per call (bigint.h), so
 * the sign is exact for every finite double. When the minor contains the column of
 * ones, the first row is subtracted from the others and the determinant expanded
 * along that column (sign +1, the 1 sits at position (0,0)); when it also contains
 * every coordinate column, the lifted column is re-formed as |p_i - p_0|^2, a
 * column operation that leaves the determinant unchanged and keeps the integers
 * short. The determinant itself is a Laplace expansion along columns with every
 * minor of the leading columns memoised per row subset: m * 2^(m-1) products for
 * an m x m matrix, and no division. Signs of calls whose coordinates span many bits
 * (magnitudes mixed in one call) run the same expansion on sparse digits (spint.h,
 * sparse_minor_sign below); values (lh__minor_value, sums) stay on bigint.h.
 */
#include "lh_alloc.h"
#include "pred_internal.h"

#include <limits.h>
#include <string.h>

typedef struct exact_buf {
    lh__bn ent[LH__MAXN * LH__MAXN];
    lh__bn t[4];
    uint32_t *layer; /* 2 * LH__LAYER_SLOTS slots, then one product buffer */
    uint64_t work;   /* limbs of the factors multiplied and of the sums written */
} exact_buf;

/* Points the first `entries` matrix entries and the temporaries into the arena. */
static void buf_init(exact_buf *b, uint32_t *arena, int entries)
{
    for (int i = 0; i < entries; i++) b->ent[i].d = arena + (size_t)i * LH__ENTRY_LIMBS;
    uint32_t *rest = arena + (size_t)LH__MAXN * LH__MAXN * LH__ENTRY_LIMBS;
    for (int i = 0; i < 4; i++) b->t[i].d = rest + (size_t)i * LH__ENTRY_LIMBS;
    b->layer = rest + 4 * LH__ENTRY_LIMBS;
    b->work = 0;
}

/* Sign of the determinant of the m x m integer matrix e (row-major), m <= 9
 * (a homogeneous minor with the column of ones is reduced by one first).
 * Layer s holds, for every s-subset R of rows, det(e[R, 0..s-1]) expanded along
 * its last column: sum over r in R of (-1)^(pos(r)+s-1) e[r][s-1] det(R \ r). */
static lh__bn det_value(exact_buf *b, const lh__subsets *sub, int m, const lh__bn *e);

static int det_sign(exact_buf *b, const lh__subsets *sub, int m, const lh__bn *e)
{
    if (m == 0) return 1;
    lh__bn v = det_value(b, sub, m, e);
    return lh__bn_sign(&v);
}

/* The determinant of e (m >= 1); its limbs are in the buffer's storage. */
static lh__bn det_value(exact_buf *b, const lh__subsets *sub, int m, const lh__bn *e)
{
    if (m == 1) return e[0];
    int cap = m + 2;
    for (int j = 0; j < m; j++) {
        int most = 0;
        for (int i = 0; i < m; i++)
            if (e[i * m + j].n > most) most = e[i * m + j].n;
        cap += most;
    }
    const uint8_t *slot = sub->slot;
    static const int widest[LH__MAXN] = {1, 1, 2, 3, 6, 10, 20, 35, 70, 126}; /* C(m, m/2) */
    lh__bn lay[2][LH__LAYER_SLOTS];
    for (int w = 0; w < 2; w++)
        for (int k = 0; k < widest[m]; k++)
            lay[w][k].d = b->layer + ((size_t)w * LH__LAYER_SLOTS + k) * cap;
    lh__bn prod = {b->layer + (size_t)2 * LH__LAYER_SLOTS * cap, 0, 0};

    lh__bn first[LH__MAXN]; /* layer 1: the entries of column 0, shared, not copied */
    for (int r = 0; r < m; r++) first[slot[1 << r]] = e[r * m];
    const lh__bn *prev = first;
    for (int s = 2; s <= m; s++) {
        lh__bn *cur = lay[s & 1];
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << m); t++) {
            int mask = sub->by_size[s][t];
            lh__bn *acc = &cur[slot[mask]];
            acc->n = 0;
            acc->neg = 0;
            int pos = 0;
            for (int r = 0; r < m; r++) {
                if (!(mask & (1 << r))) continue;
                const lh__bn *minor = &prev[slot[mask ^ (1 << r)]];
                const lh__bn *x = &e[r * m + s - 1];
                if (minor->n && x->n) {
                    lh__bn_mul(&prod, x, minor);
                    lh__bn_add(acc, acc, &prod, (pos + s - 1) & 1);
                    b->work += (uint64_t)x->n * (uint64_t)minor->n + (uint64_t)acc->n;
                }
                pos++;
            }
        }
        prev = cur;
    }
    return prev[slot[(1 << m) - 1]];
}

/* Scale for a call: the lowest set bit among the coordinates that enter (all of a
 * row's coordinates when the lifted column enters, else only the columns used);
 * *top (when not NULL) an upper bound on their binary exponents. */
static int common_scale(const double *const *pts, int dim, int m, const int *rows,
                        const int *cols, int has_lift, int *top)
{
    int used[LH__MAXN + 1] = {0}, scale = 0, any = 0, most = INT_MIN;
    for (int b = 0; b < m; b++) used[cols[b]] = 1;
    for (int a = 0; a < m; a++) {
        for (int c = 1; c <= dim; c++) {
            double x = pts[rows[a]][c - 1];
            if (!(used[c] || has_lift) || x == 0) continue;
            int e = lh__dbl_low_exp(x), neg, hi;
            lh__dbl_decompose(x, &hi, &neg);
            hi += 53; /* x < 2^(e + 53) for x = m 2^e, m < 2^53 */
            if (!any || e < scale) scale = e;
            if (hi > most) most = hi;
            any = 1;
        }
    }
    if (top) *top = any ? most : scale;
    return scale;
}

/* out = sum over all coordinates c of (p[c] - q[c])^2 (q may be NULL: plain |p|^2),
 * at scale 2*scale. Uses b->t[0..2]. */
static void squared_norm(exact_buf *b, lh__bn *out, const double *p, const double *q,
                         int dim, int scale)
{
    lh__bn *x = &b->t[0], *y = &b->t[1], *sq = &b->t[2];
    out->n = 0;
    out->neg = 0;
    for (int c = 0; c < dim; c++) {
        lh__bn_set_dbl(x, p[c], scale);
        if (q) {
            lh__bn_set_dbl(y, q[c], scale);
            lh__bn_add(x, x, y, 1);
        }
        lh__bn_mul(sq, x, x);
        lh__bn_add(out, out, sq, 0);
    }
}

/* Fills b with the integer matrix of the minor (the rows reduced by the first when
 * the column of ones is in); returns its size n; *scale is the power of two each
 * coordinate was divided by: `forced`, or with INT_MIN the call's own (the lowest set
 * bit of the entering coordinates; a forced scale must be at most that). */
static int fill_minor(lh_pred *ctx, exact_buf *b_, const double *const *pts, int dim, int m,
                      const int *rows, const int *cols, int forced, int *scale_out)
{
    exact_buf b;
    int has_ones = cols[0] == 0, has_lift = cols[m - 1] == dim + 1;
    buf_init(&b, ctx->arena, (m - has_ones) * (m - has_ones));
    int relift = has_ones && has_lift && m - 2 == dim;
    int scale = forced != INT_MIN ? forced : common_scale(pts, dim, m, rows, cols, has_lift, NULL);
    const double *base = has_ones ? pts[rows[0]] : NULL;
    int n = m - has_ones; /* size of the integer matrix */
    lh__bn *base_lift = &b.t[3];
    if (has_lift && base && !relift) squared_norm(&b, base_lift, base, NULL, dim, scale);

    for (int i = 0; i < n; i++) {
        const double *p = pts[rows[i + has_ones]];
        for (int j = 0; j < n; j++) {
            int c = cols[j + has_ones];
            lh__bn *e = &b.ent[i * n + j];
            if (c == dim + 1) {
                squared_norm(&b, e, p, relift ? base : NULL, dim, scale);
                if (base && !relift) lh__bn_add(e, e, base_lift, 1);
            } else {
                lh__bn_set_dbl(e, p[c - 1], scale);
                if (base) {
                    lh__bn_set_dbl(&b.t[0], base[c - 1], scale);
                    lh__bn_add(e, e, &b.t[0], 1);
                }
            }
        }
    }
    *b_ = b;
    *scale_out = scale;
    return n;
}

/* The sparse path (spint.h) for calls whose coordinates span more than
 * SPARSE_MIN_BITS bits: the same matrix, the same memoised expansion, on numbers that
 * store only their nonzero digits, so a call that mixes 1e+300 and 5e-324 costs the
 * digits its products carry rather than the 2100-bit range. Below the threshold the
 * dense integers are as short and cheaper per limb. */
#define SPARSE_MIN_BITS 320
#define SPARSE_FAILED 2

typedef struct sparse_ws {
    lh__sp_acc acc;
    lh__sp_pool ent;    /* entries and temporaries */
    lh__sp_pool lay[2]; /* the layers of det_value, by parity */
} sparse_ws;

/* The pools share the dense stage's arena (the two stages never overlap in time). */
static void sparse_init(sparse_ws *w, lh_pred *ctx)
{
    lh__sp_acc_init(&w->acc, ctx->sp_coef, ctx->sp_flag, LH__SP_OFFSETS);
    lh__sd *d = (lh__sd *)(void *)ctx->arena;
    size_t total = LH__ARENA_LIMBS * sizeof *ctx->arena / sizeof *d, part = total / 4;
    w->ent = (lh__sp_pool){d, part, 0};
    w->lay[0] = (lh__sp_pool){d + part, (total - part) / 2, 0};
    w->lay[1] = (lh__sp_pool){d + part + (total - part) / 2, (total - part) / 2, 0};
}

/* Accumulates sum over all coordinates c of (p[c] - q[c])^2 (q NULL: |p|^2). */
static int sparse_norm(sparse_ws *w, const double *p, const double *q, int dim, int scale)
{
    lh__sp diff[LH__MAXN];
    for (int c = 0; c < dim; c++) {
        lh__sp_acc_add_dbl(&w->acc, p[c], scale, 0);
        if (q) lh__sp_acc_add_dbl(&w->acc, q[c], scale, 1);
        if (!lh__sp_acc_take(&w->acc, &w->ent, &diff[c])) return 0;
    }
    for (int c = 0; c < dim; c++) lh__sp_acc_add_mul(&w->acc, &diff[c], &diff[c], 0);
    return 1;
}

/* fill_minor's matrix as sparse numbers; its size, or -1 when a pool ran out. */
static int sparse_fill(sparse_ws *w, lh__sp *ent, const double *const *pts, int dim, int m,
                       const int *rows, const int *cols, int scale)
{
    int has_ones = cols[0] == 0, has_lift = cols[m - 1] == dim + 1;
    int relift = has_ones && has_lift && m - 2 == dim;
    const double *base = has_ones ? pts[rows[0]] : NULL;
    int n = m - has_ones;
    lh__sp base_lift = {NULL, 0};
    if (has_lift && base && !relift &&
        !(sparse_norm(w, base, NULL, dim, scale) && lh__sp_acc_take(&w->acc, &w->ent, &base_lift)))
        return -1;
    for (int i = 0; i < n; i++) {
        const double *p = pts[rows[i + has_ones]];
        for (int j = 0; j < n; j++) {
            int c = cols[j + has_ones];
            if (c == dim + 1) {
                if (!sparse_norm(w, p, relift ? base : NULL, dim, scale)) return -1;
                if (base && !relift) lh__sp_acc_add(&w->acc, &base_lift, 1);
            } else {
                lh__sp_acc_add_dbl(&w->acc, p[c - 1], scale, 0);
                if (base) lh__sp_acc_add_dbl(&w->acc, base[c - 1], scale, 1);
            }
            if (!lh__sp_acc_take(&w->acc, &w->ent, &ent[i * n + j])) return -1;
        }
    }
    return n;
}

/* Sign of det(e) for the n x n sparse matrix e by det_value's expansion, or
 * SPARSE_FAILED when a layer's pool ran out. */
static int sparse_det_sign(sparse_ws *w, const lh__subsets *sub, int n, const lh__sp *e)
{
    if (n == 0) return 1;
    const uint8_t *slot = sub->slot;
    lh__sp lay[2][LH__LAYER_SLOTS], first[LH__MAXN];
    for (int r = 0; r < n; r++) first[slot[1 << r]] = e[r * n];
    const lh__sp *prev = first;
    for (int s = 2; s <= n; s++) {
        lh__sp *cur = lay[s & 1];
        lh__sp_pool *pool = &w->lay[s & 1];
        pool->used = 0;
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << n); t++) {
            int mask = sub->by_size[s][t], pos = 0;
            for (int r = 0; r < n; r++) {
                if (!(mask & (1 << r))) continue;
                lh__sp_acc_add_mul(&w->acc, &e[r * n + s - 1], &prev[slot[mask ^ (1 << r)]],
                                   (pos + s - 1) & 1);
                pos++;
            }
            if (!lh__sp_acc_take(&w->acc, pool, &cur[slot[mask]])) return SPARSE_FAILED;
        }
        prev = cur;
    }
    return lh__sp_sign(&prev[slot[(1 << n) - 1]]);
}

static int sparse_minor_sign(lh_pred *ctx, const double *const *pts, int dim, int m,
                             const int *rows, const int *cols, int scale)
{
    sparse_ws w;
    sparse_init(&w, ctx);
    lh__sp ent[LH__MAXN * LH__MAXN];
    int n = sparse_fill(&w, ent, pts, dim, m, rows, cols, scale);
    int s = n < 0 ? SPARSE_FAILED : sparse_det_sign(&w, &ctx->sub, n, ent);
    ctx->exact_work += w.acc.work;
    return s;
}

int lh__minor_sign(lh_pred *ctx, const double *const *pts, int dim, int m,
                   const int *rows, const int *cols)
{
    if (m == 0) return 1;
    int top, has_lift = cols[m - 1] == dim + 1;
    int scale = common_scale(pts, dim, m, rows, cols, has_lift, &top);
    if (top - scale > SPARSE_MIN_BITS) {
        int s = sparse_minor_sign(ctx, pts, dim, m, rows, cols, scale);
        if (s != SPARSE_FAILED) return s;
    }
    exact_buf b;
    int n = fill_minor(ctx, &b, pts, dim, m, rows, cols, scale, &scale);
    int s = det_sign(&b, &ctx->sub, n, b.ent);
    ctx->exact_work += b.work;
    return s;
}

double lh__minor_value(lh_pred *ctx, const double *const *pts, int dim, int m, const int *rows,
                       const int *cols, int *e)
{
    *e = 0;
    if (m == 0) return 1;
    exact_buf b;
    int scale, n = fill_minor(ctx, &b, pts, dim, m, rows, cols, INT_MIN, &scale);
    if (n == 0) return 1;
    lh__bn det = det_value(&b, &ctx->sub, n, b.ent);
    double v = lh__bn_to_double(&det, e);
    *e += n * scale; /* no lifted column: every entry was divided by 2^scale */
    return v;
}

static int full_minor(lh_pred *ctx, const double *const *pts, int dim, int n)
{
    int idx[LH__MAXN];
    for (int i = 0; i < n; i++) idx[i] = i;
    return lh__minor_sign(ctx, pts, dim, n, idx, idx);
}

int lh__orient_exact(lh_pred *ctx, int k, const double *const *pts)
{
    return full_minor(ctx, pts, k, k + 1);
}

int lh__insphere_exact(lh_pred *ctx, int d, const double *const *pts)
{
    return full_minor(ctx, pts, d, d + 2);
}

/* Exact sums of orientation determinants (lh_exact.h). */
struct lh__detsum {
    lh_allocator alloc;
    int d, scale;
    lh__bn acc;
};

lh_status lh__detsum_create(const lh_allocator *alloc, int d, int scale, lh__detsum **out)
{
    lh_allocator a;
    *out = NULL;
    if (!lh__allocator_init(&a, alloc)) return LH_ERR_INVALID_ARGUMENT;
    lh__detsum *s = lh__alloc(&a, sizeof *s);
    uint32_t *limbs = lh__alloc(&a, (LH__DET_LIMBS + 4) * sizeof *limbs);
    if (!s || !limbs) {
        lh__free(&a, s);
        lh__free(&a, limbs);
        return LH_ERR_NOMEM;
    }
    s->alloc = a;
    s->d = d;
    s->scale = scale;
    s->acc.d = limbs;
    s->acc.n = s->acc.neg = 0;
    *out = s;
    return LH_OK;
}

void lh__detsum_free(lh__detsum *s)
{
    if (!s) return;
    lh_allocator a = s->alloc;
    lh__free(&a, s->acc.d);
    lh__free(&a, s);
}

void lh__detsum_add(lh_pred *ctx, lh__detsum *s, const double *const *pts, int negate)
{
    int idx[LH__MAXN], scale;
    for (int i = 0; i <= s->d; i++) idx[i] = i;
    exact_buf b;
    int n = fill_minor(ctx, &b, pts, s->d, s->d + 1, idx, idx, s->scale, &scale);
    lh__bn det = det_value(&b, &ctx->sub, n, b.ent);
    lh__bn_add(&s->acc, &s->acc, &det, negate);
}

int lh__detsum_sign(const lh__detsum *s) { return lh__bn_sign(&s->acc); }

/* The rows were reduced by the first, so the integer matrix is d x d, every entry
 * the coordinate difference divided by 2^scale: the sum is the integer times
 * 2^(d * scale). */
double lh__detsum_value(const lh__detsum *s, int *e)
{
    double v = lh__bn_to_double(&s->acc, e);
    *e += s->d * s->scale;
    return v;
}
