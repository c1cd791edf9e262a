/*
 * pred_bound.c — the filter's error bound made exact: the two stages between the
 * filter and the multi-limb exact stage. Both read the coordinates as integers
 * times powers of two (bigint.h).
 *
 * Granularity (granular_sign below) decides any sign when the bound is finer than
 * the determinant's power-of-two granularity: integer grids and dyadic data.
 *
 * Residues decide exact zeros with word arithmetic. At one power-of-two scale every
 * coordinate is an integer, so the predicate's reduced matrix (rows p_i - p_0, and for insphere the column
 * |p_i - p_0|^2, pred_exact.c) is an integer matrix whose determinant D is the
 * predicate's determinant divided by 2^S. The filter bounds it: |D| <= B =
 * (|det| + err) / 2^S. If D = 0 modulo pairwise coprime moduli whose product P
 * exceeds 2B, then D = 0 (Chinese remainder theorem: D is the one multiple of P in
 * (-P/2, P/2)). Degenerate input — grids, lattice points on a sphere, coplanar
 * sites — makes most of the calls that reach this stage exact zeros; a nonzero
 * residue passes the call on to pred_exact.c.
 *
 * The moduli are 2^64 (native wrap-around) and Mersenne numbers 2^k - 1 with
 * pairwise coprime exponents (gcd(2^a - 1, 2^b - 1) = 2^gcd(a,b) - 1), where
 * multiplying by 2^t is a rotation by t mod k and a product folds as
 * (p mod 2^k) + (p >> k). Determinants mod M by the division-free memoised Laplace
 * expansion of pred_exact.c (most moduli here are composite: no elimination).
 */
#include "pred_internal.h"

#include <limits.h>
#include <math.h>
#include <string.h>

/* Exponents: 64 stands for the modulus 2^64, any other k for 2^k - 1. The
 * product of the first j moduli is at least 2^credit, summing each's credit
 * (64 for 2^64, k - 1 for 2^k - 1). */
static const int mod_exp[] = {64, 63, 61, 59, 53, 47, 43, 41, 37, 31, 29, 23, 19, 17};
#define N_MODULI ((int)(sizeof mod_exp / sizeof mod_exp[0]))

typedef struct ring {
    int k;      /* 64: arithmetic mod 2^64; else mod 2^k - 1 */
    uint64_t m; /* 2^k - 1 (all ones for k = 64)            */
} ring;

/* Both 64-bit halves of a * b. */
static inline void mul_wide(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#if defined(__SIZEOF_INT128__)
    unsigned __int128 p = (unsigned __int128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
#else
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    *lo = (mid << 32) | (p00 & 0xffffffffu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

/* Residues are canonical: in [0, m) for 2^k - 1, any word for 2^64. */
static inline uint64_t r_add(const ring *R, uint64_t a, uint64_t b)
{
    uint64_t s = a + b; /* k <= 63: no wrap, both below 2^63 */
    return R->k == 64 || s < R->m ? s : s - R->m;
}

static inline uint64_t r_sub(const ring *R, uint64_t a, uint64_t b)
{
    if (R->k == 64) return a - b;
    return a >= b ? a - b : a + (R->m - b);
}

static inline uint64_t r_mul(const ring *R, uint64_t a, uint64_t b)
{
    if (R->k == 64) return a * b;
    uint64_t hi, lo;
    if (R->k <= 32) {
        hi = 0;
        lo = a * b; /* both below 2^32 */
    } else {
        mul_wide(a, b, &hi, &lo);
    }
    /* a * b < 2^2k: the high part (p >> k) is below 2^k too. */
    uint64_t high = R->k <= 32 ? lo >> R->k : (hi << (64 - R->k)) | (lo >> R->k);
    uint64_t s = (lo & R->m) + high;
    return s < R->m ? s : s - R->m;
}

/* Trailing zero bits of m != 0. */
static inline int ctz64(uint64_t m)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(m);
#else
    int z = 0;
    for (; !(m & 1); m >>= 1) z++;
    return z;
#endif
}

/* A coordinate as (-1)^neg m 2^(shift + scale): m odd, shift >= 0 at the call's
 * scale (the lowest set bit among its coordinates). */
typedef struct coord {
    uint64_t m;
    int shift, neg;
} coord;

/* The coordinates of the call's points, row by row; returns the scale, or INT_MAX
 * when every coordinate is 0. */
static int split_coords(int npts, int dim, const double *const *pts, coord *out)
{
    int scale = INT_MAX;
    for (int i = 0; i < npts; i++)
        for (int c = 0; c < dim; c++) {
            double x = pts[i][c];
            coord *o = &out[i * dim + c];
            uint64_t bits;
            memcpy(&bits, &x, sizeof bits);
            int biased = (int)((bits >> 52) & 0x7ff);
            uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
            if (biased) m |= UINT64_C(1) << 52;
            o->m = m;
            o->neg = (int)(bits >> 63);
            o->shift = 0;
            if (!m) continue;
            int z = ctz64(m);
            o->m = m >> z;
            o->shift = (biased ? biased - 1075 : -1074) + z;
            int low = o->shift;
            if (low < scale) scale = low;
        }
    if (scale == INT_MAX) return scale;
    for (int i = 0; i < npts * dim; i++) out[i].shift -= scale;
    return scale;
}

/* A coordinate divided by 2^scale, mod the ring. */
static inline uint64_t r_coord(const ring *R, const coord *x)
{
    uint64_t r;
    if (!x->m) return 0;
    if (R->k == 64) {
        r = x->shift < 64 ? x->m << x->shift : 0;
    } else {
        r = x->m; /* below 2^53: folding ends, 2^k = 1 mod 2^k - 1 */
        while (r >> R->k) r = (r & R->m) + (r >> R->k);
        if (r == R->m) r = 0;
        int t = x->shift < R->k ? x->shift : x->shift % R->k;
        if (t && r) r = ((r << t) & R->m) | (r >> (R->k - t));
    }
    return x->neg ? r_sub(R, 0, r) : r;
}

/* Determinant mod the ring of the n x n matrix e (row-major), n <= LH__MAXN - 1:
 * layer s holds det(e[R, 0..s-1]) for every s-subset R of rows (pred_exact.c).
 * WRAP selects native arithmetic mod 2^64, where the ring's branches fold away. */
#define DET_BODY(WRAP)                                                                  \
    uint64_t lay[2][LH__LAYER_SLOTS], first[LH__MAXN];                                 \
    for (int r = 0; r < n; r++) first[sub->slot[1 << r]] = e[r * n];                   \
    const uint64_t *prev = first;                                                       \
    for (int s = 2; s <= n; s++) {                                                      \
        uint64_t *cur = lay[s & 1];                                                     \
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << n); t++) {      \
            int mask = sub->by_size[s][t], pos = 0;                                     \
            uint64_t acc = 0;                                                           \
            for (int r = 0; r < n; r++) {                                               \
                if (!(mask & (1 << r))) continue;                                       \
                uint64_t x = e[r * n + s - 1], y = prev[sub->slot[mask ^ (1 << r)]];     \
                uint64_t term = WRAP ? x * y : r_mul(R, x, y);                          \
                if ((pos + s - 1) & 1)                                                  \
                    acc = WRAP ? acc - term : r_sub(R, acc, term);                      \
                else                                                                    \
                    acc = WRAP ? acc + term : r_add(R, acc, term);                      \
                pos++;                                                                  \
            }                                                                           \
            cur[sub->slot[mask]] = acc;                                                 \
        }                                                                               \
        prev = cur;                                                                     \
    }                                                                                   \
    return prev[sub->slot[(1 << n) - 1]];

static uint64_t det_wrap(const lh__subsets *sub, int n, const uint64_t *e)
{
    const ring *R = NULL;
    (void)R;
    DET_BODY(1)
}

static uint64_t det_mersenne(const ring *R, const lh__subsets *sub, int n, const uint64_t *e)
{
    DET_BODY(0)
}
#undef DET_BODY

/* det mod 2^64 of a 2x2, 3x3 or 4x4 matrix: cofactors, and for 4x4 the Laplace
 * expansion along the first two columns by complementary 2x2 minors. */
static uint64_t det_wrap_small(int n, const uint64_t *e)
{
    if (n == 2) return e[0] * e[3] - e[1] * e[2];
    if (n == 3)
        return e[0] * (e[4] * e[8] - e[5] * e[7]) - e[1] * (e[3] * e[8] - e[5] * e[6]) +
               e[2] * (e[3] * e[7] - e[4] * e[6]);
#define M2(i, j, c) (e[(i) * 4 + (c)] * e[(j) * 4 + (c) + 1] - e[(j) * 4 + (c)] * e[(i) * 4 + (c) + 1])
    return M2(0, 1, 0) * M2(2, 3, 2) - M2(0, 2, 0) * M2(1, 3, 2) + M2(0, 3, 0) * M2(1, 2, 2) +
           M2(1, 2, 0) * M2(0, 3, 2) - M2(1, 3, 0) * M2(0, 2, 2) + M2(2, 3, 0) * M2(0, 1, 2);
#undef M2
}

static uint64_t r_det(const ring *R, const lh__subsets *sub, int n, const uint64_t *e)
{
    if (n == 1) return e[0];
    if (R->k != 64) return det_mersenne(R, sub, n, e);
    return n <= 4 ? det_wrap_small(n, e) : det_wrap(sub, n, e);
}

/* The reduced matrix mod the ring: rows p_i - p_0 (i = 1..dim+lifted), and for
 * insphere the last column |p_i - p_0|^2. Returns its size. */
static int r_matrix(const ring *R, int dim, int lifted, const coord *x, uint64_t *e)
{
    int n = dim + lifted;
    uint64_t base[LH__MAXN];
    for (int c = 0; c < dim; c++) base[c] = r_coord(R, &x[c]);
    for (int i = 0; i < n; i++) {
        uint64_t norm = 0;
        for (int c = 0; c < dim; c++) {
            uint64_t v = r_sub(R, r_coord(R, &x[(i + 1) * dim + c]), base[c]);
            e[i * n + c] = v;
            norm = r_add(R, norm, r_mul(R, v, v));
        }
        if (lifted) e[i * n + dim] = norm;
    }
    return n;
}

/*
 * The granularity rule. Every coordinate in column j is a multiple of 2^g_j (g_j the
 * lowest set bit over the column's coordinates), hence so is every exact entry
 * p_i - p_0 of the translated matrix, and the lifted entries are multiples of
 * 2^(2 min g_j); the determinant is then a multiple of 2^G, G = sum g_j (+ 2 min g_j).
 * If the filter's proven bound err < 2^(G-1), the determinant is the multiple of 2^G
 * within err of the computed value: 0 when |computed| <= err. This decides integer
 * grids and other exactly degenerate dyadic data, nonzero signs too.
 */
static int granular_sign(int dim, int lifted, const coord *x, int scale, double det,
                         double err, int *sign)
{
    int npts = dim + 1 + lifted, G = 0, gmin = INT_MAX;
    for (int j = 0; j < dim; j++) {
        int g = INT_MAX;
        for (int i = 0; i < npts; i++)
            if (x[i * dim + j].m && x[i * dim + j].shift < g) g = x[i * dim + j].shift;
        g = g == INT_MAX ? 0 : g + scale; /* an all-zero column: any granularity holds */
        G += g;
        if (g < gmin) gmin = g;
    }
    if (lifted) G += 2 * gmin;
    if (G < -2000 || !(err < ldexp(1.0, G - 1))) return 0;
    *sign = det > err ? 1 : det < -err ? -1 : 0;
    return 1;
}

/* Whether every residue of the determinant is 0 for moduli whose product exceeds
 * twice the bound (|det| + err) / 2^S, S = scale * (dim + 2 lifted). */
static int residues_zero(const lh__subsets *sub, int dim, int lifted, const coord *x,
                         int scale, double det, double err)
{
    double b = (fabs(det) + err) * (1 + 0x1p-50); /* rounded up */
    if (!(b < INFINITY)) return 0;
    int need;
    (void)frexp(b, &need); /* b < 2^need */
    need -= scale * (dim + 2 * lifted);
    if (!(b > 0)) need = 0;
    int credit = 0, used = 0;
    while (used < N_MODULI && credit < need + 1) {
        credit += mod_exp[used] == 64 ? 64 : mod_exp[used] - 1;
        used++;
    }
    if (credit < need + 1) return 0; /* too wide for these moduli */
    uint64_t e[(LH__MAXN - 1) * (LH__MAXN - 1)];
    for (int j = 0; j < used; j++) {
        int k = mod_exp[j];
        ring R = {k, k == 64 ? ~UINT64_C(0) : (UINT64_C(1) << k) - 1};
        int n = r_matrix(&R, dim, lifted, x, e);
        if (r_det(&R, sub, n, e) != 0) return 0;
    }
    return 1;
}

/* Whether every coordinate of the call's points is an integer: then every g_j >= 0,
 * G >= 0, and the granularity rule holds whenever err < 1/2 (integer grids, without
 * splitting the coordinates). */
static int integer_coords(int npts, int dim, const double *const *pts)
{
    int fractions = 0;
    for (int i = 0; i < npts; i++)
        for (int c = 0; c < dim; c++) fractions += lh__dbl_fraction(pts[i][c]);
    return !fractions;
}

int lh__bound_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                   double det, double err, int residues, int *sign)
{
    if (!(err >= 0)) return 0;
    if (err < 0.5 && integer_coords(dim + 1 + lifted, dim, pts)) {
        *sign = det > err ? 1 : det < -err ? -1 : 0;
        return LH__BY_GRANULARITY;
    }
    coord x[LH__MAXN * (LH__MAXN - 2)];
    int scale = split_coords(dim + 1 + lifted, dim, pts, x);
    if (scale == INT_MAX) scale = 0; /* every coordinate 0 */
    if (granular_sign(dim, lifted, x, scale, det, err, sign)) return LH__BY_GRANULARITY;
    if (!residues || !residues_zero(sub, dim, lifted, x, scale, det, err)) return 0;
    *sign = 0;
    return LH__BY_RESIDUES;
}
