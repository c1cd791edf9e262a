/*
 * pred_wide.c — the wide-exponent filter: the floating-point filter's determinant
 * and error bound evaluated on numbers m * 2^e with a double m and an integer e, so
 * that no product overflows or underflows whatever the magnitudes (1e+300 beside
 * 5e-324). It runs where the double filter could not decide, before the exact stage,
 * translated to the point that makes the expansion cancel least (pivot() below), in
 * plain doubles when the entries allow, then once more in double-word arithmetic
 * (dw_sign() below) for near-degenerate input.
 *
 * Error bound (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
 * 3.1 and 3.3; the derivation of docs/predicates.md, "The filter's error bound").
 * The m x m determinant of rows p_i - p_k (and |p_i - p_k|^2 for insphere) is
 * expanded along columns with every minor of the leading columns computed once per
 * row subset. A product's path through the expansion passes at most
 *     g = m(m+1)/2 - 1 + (d + 2)
 * roundings (levels 2..m: one product and at most s - 1 additions; the entries: one
 * rounding per difference, d + 2 for the lifted one), each of relative size at most
 * u = 2^-53: products of mantissas in [1/2, 1) never underflow, and a sum whose
 * smaller operand is shifted below the subnormal range loses at most 2^-1074 of the
 * larger operand (that much more per operation, absorbed below). So
 *     |computed - det| <= gamma_g * P,   P = sum over permutations of prod |e_ij|,
 * and P is computed by the same expansion on absolute values (all additions of
 * non-negative terms), which underestimates it by at most a factor (1 - u)^g. The
 * bound used is 4 (g + 2) u * P_computed, more than twice gamma_g * P for every
 * g <= 64 here; the sign is claimed only when |computed| exceeds it.
 */
#include "pred_internal.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* x = m * 2^e with 1/2 <= |m| < 1, or m = 0 (e = 0). */
typedef struct wide {
    double m;
    int64_t e;
} wide;

/* 2^k for -1074 <= k <= 1023, from its encoding. */
static double pow2(int k)
{
    uint64_t bits = k >= -1022 ? (uint64_t)(k + 1023) << 52 : UINT64_C(1) << (k + 1074);
    double r;
    memcpy(&r, &bits, sizeof r);
    return r;
}

static wide w_make(double m, int64_t e)
{
    uint64_t bits;
    memcpy(&bits, &m, sizeof bits);
    int biased = (int)((bits >> 52) & 0x7ff);
    wide r;
    if (biased == 0) { /* zero or subnormal */
        int k;
        r.m = frexp(m, &k); /* exact; 0 stays 0 */
        r.e = r.m == 0 ? 0 : e + k;
        return r;
    }
    /* normal: m = (1.f) 2^(biased - 1023) = (0.1f) 2^(biased - 1022) */
    bits = (bits & ~(UINT64_C(0x7ff) << 52)) | (UINT64_C(1022) << 52);
    memcpy(&r.m, &bits, sizeof r.m);
    r.e = e + biased - 1022;
    return r;
}

static wide w_mul(wide a, wide b) { return w_make(a.m * b.m, a.e + b.e); }

static wide w_add(wide a, wide b)
{
    if (a.m == 0) return b;
    if (b.m == 0) return a;
    if (a.e < b.e) {
        wide t = a;
        a = b;
        b = t;
    }
    int64_t shift = b.e - a.e; /* <= 0 */
    if (shift < -1100) return a; /* |b| < 2^-1099 |a| */
    /* b.m 2^shift rounded once, as ldexp would: multiplying by a power of two is
     * exact, or one rounding into the subnormal range. */
    double bs = shift >= -1074 ? b.m * pow2((int)shift) : ldexp(b.m, (int)shift);
    return w_make(a.m + bs, a.e);
}

static wide w_abs(wide a)
{
    a.m = fabs(a.m);
    return a;
}

/* |a| > b for b >= 0. */
static int w_abs_greater(wide a, wide b)
{
    if (a.m == 0) return 0;
    if (b.m == 0) return 1;
    if (a.e != b.e) return a.e > b.e;
    return fabs(a.m) > b.m;
}

/* Determinant and permanent of |e| of the n x n matrix e by the memoised Laplace
 * expansion (the layers of pred_exact.c's det_value). */
static void expand(const lh__subsets *sub, int n, const wide *e, wide *det, wide *perm)
{
    wide lay[2][2][LH__LAYER_SLOTS]; /* [layer parity][det, perm][subset slot] */
    for (int r = 0; r < n; r++) {
        lay[1][0][sub->slot[1 << r]] = e[r * n];
        lay[1][1][sub->slot[1 << r]] = w_abs(e[r * n]);
    }
    for (int s = 2; s <= n; s++) {
        wide(*cur)[LH__LAYER_SLOTS] = lay[s & 1], (*prev)[LH__LAYER_SLOTS] = lay[(s - 1) & 1];
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << n); t++) {
            int mask = sub->by_size[s][t], pos = 0;
            wide acc = {0, 0}, acc_abs = {0, 0};
            for (int r = 0; r < n; r++) {
                if (!(mask & (1 << r))) continue;
                int j = sub->slot[mask ^ (1 << r)];
                wide x = e[r * n + s - 1], term = w_mul(x, prev[0][j]);
                if ((pos + s - 1) & 1) term.m = -term.m;
                acc = w_add(acc, term);
                acc_abs = w_add(acc_abs, w_mul(w_abs(x), prev[1][j]));
                pos++;
            }
            cur[0][sub->slot[mask]] = acc;
            cur[1][sub->slot[mask]] = acc_abs;
        }
    }
    int top = sub->slot[(1 << n) - 1];
    *det = lay[n & 1][0][top];
    *perm = lay[n & 1][1][top];
}

/* The same expansion in doubles, valid when no product can overflow or underflow. */
static void expand_dbl(const lh__subsets *sub, int n, const double *e, double *det, double *perm)
{
    double lay[2][2][LH__LAYER_SLOTS];
    for (int r = 0; r < n; r++) {
        lay[1][0][sub->slot[1 << r]] = e[r * n];
        lay[1][1][sub->slot[1 << r]] = fabs(e[r * n]);
    }
    for (int s = 2; s <= n; s++) {
        double(*cur)[LH__LAYER_SLOTS] = lay[s & 1], (*prev)[LH__LAYER_SLOTS] = lay[(s - 1) & 1];
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << n); t++) {
            int mask = sub->by_size[s][t], pos = 0;
            double acc = 0, acc_abs = 0;
            for (int r = 0; r < n; r++) {
                if (!(mask & (1 << r))) continue;
                int j = sub->slot[mask ^ (1 << r)];
                double x = e[r * n + s - 1], term = x * prev[0][j];
                acc = ((pos + s - 1) & 1) ? acc - term : acc + term;
                acc_abs = acc_abs + fabs(x) * prev[1][j];
                pos++;
            }
            cur[0][sub->slot[mask]] = acc;
            cur[1][sub->slot[mask]] = acc_abs;
        }
    }
    int top = sub->slot[(1 << n) - 1];
    *det = lay[n & 1][0][top];
    *perm = lay[n & 1][1][top];
}

/* Double-word numbers hi + lo, |lo| <= ulp(hi) / 2 (Joldes, Muller, Popescu, "Tight and
 * rigorous error bounds for basic building blocks of double-word arithmetic", ACM TOMS
 * 44(2), 2017): the sum below is their AccurateDWPlusDW (relative error at most
 * 3u^2 / (1 - 4u)), the product their DWTimesDW1 (at most 7u^2), exact transforms by
 * Knuth's TwoSum and Dekker's TwoProduct. Valid without overflow or underflow, which
 * the band of dd_band() excludes, and only under round-to-nearest double evaluation. */
typedef struct dword {
    double hi, lo;
} dword;

static dword two_sum(double a, double b)
{
    double s = a + b, bb = s - a;
    dword r = {s, (a - (s - bb)) + (b - bb)};
    return r;
}

static dword fast_two_sum(double a, double b) /* |a| >= |b| or a == 0 */
{
    double s = a + b;
    dword r = {s, b - (s - a)};
    return r;
}

static void split(double a, double *hi, double *lo)
{
    double c = 134217729.0 * a; /* 2^27 + 1 */
    *hi = c - (c - a);
    *lo = a - *hi;
}

static dword two_prod(double a, double b)
{
    double p = a * b, ah, al, bh, bl;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    dword r = {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
    return r;
}

static dword dw_add(dword x, dword y)
{
    dword s = two_sum(x.hi, y.hi), t = two_sum(x.lo, y.lo);
    dword v = fast_two_sum(s.hi, s.lo + t.hi);
    return fast_two_sum(v.hi, t.lo + v.lo);
}

static dword dw_mul(dword x, dword y)
{
    dword c = two_prod(x.hi, y.hi);
    return fast_two_sum(c.hi, c.lo + (x.hi * y.lo + x.lo * y.hi));
}

/* The expansion on double-word entries: the determinant, and in doubles the permanent
 * of |hi| + |lo|. */
static void expand_dw(const lh__subsets *sub, int n, const dword *e, dword *det, double *perm)
{
    dword lay[2][LH__LAYER_SLOTS];
    double lay_abs[2][LH__LAYER_SLOTS];
    for (int r = 0; r < n; r++) {
        lay[1][sub->slot[1 << r]] = e[r * n];
        lay_abs[1][sub->slot[1 << r]] = fabs(e[r * n].hi) + fabs(e[r * n].lo);
    }
    for (int s = 2; s <= n; s++) {
        dword *cur = lay[s & 1], *prev = lay[(s - 1) & 1];
        double *cur_abs = lay_abs[s & 1], *prev_abs = lay_abs[(s - 1) & 1];
        for (int t = 0; t < sub->count[s] && sub->by_size[s][t] < (1 << n); t++) {
            int mask = sub->by_size[s][t], pos = 0;
            dword acc = {0, 0};
            double acc_abs = 0;
            for (int r = 0; r < n; r++) {
                if (!(mask & (1 << r))) continue;
                int j = sub->slot[mask ^ (1 << r)];
                dword x = e[r * n + s - 1], term = dw_mul(x, prev[j]);
                if ((pos + s - 1) & 1) {
                    term.hi = -term.hi;
                    term.lo = -term.lo;
                }
                acc = dw_add(acc, term);
                acc_abs = acc_abs + (fabs(x.hi) + fabs(x.lo)) * prev_abs[j];
                pos++;
            }
            cur[sub->slot[mask]] = acc;
            cur_abs[sub->slot[mask]] = acc_abs;
        }
    }
    int top = sub->slot[(1 << n) - 1];
    *det = lay[n & 1][top];
    *perm = lay_abs[n & 1][top];
}

/* ilogb(x) for finite x > 0, from the encoding when x is normal. */
static int binary_exponent(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int biased = (int)(bits >> 52); /* x > 0: no sign bit */
    return biased ? biased - 1023 : ilogb(x);
}

/* The row to subtract from the others: the point k minimising the product over i of
 * max_c |p_i[c] - p_k[c]| (compared by binary exponents), so that a cell with most of
 * its points in a small cluster and one far away is translated to the cluster, where
 * its small rows are formed without rounding and the expansion cancels little. */
static int pivot(int dim, int rows, const double *const *pts)
{
    /* Each pair once: |p_i[c] - p_k[c]| = |p_k[c] - p_i[c]| exactly. */
    long sum[LH__MAXN + 1] = {0};
    for (int k = 0; k < rows; k++) {
        for (int i = k + 1; i < rows; i++) {
            double most = 0;
            for (int c = 0; c < dim; c++) {
                double d = fabs(pts[i][c] - pts[k][c]);
                if (d > most) most = d;
            }
            long x = most == 0 ? -1100 : !isfinite(most) ? 1100 : binary_exponent(most);
            sum[k] += x;
            sum[i] += x;
        }
    }
    int best = 0;
    for (int k = 1; k < rows; k++)
        if (sum[k] < sum[best]) best = k;
    return best;
}

/* Whether every nonzero |x| of the n x n entries lies in [2^-b, 2^b] (the lifted
 * column, when present: [2^-2b, 2^2b]). With b = 100 every product of the expansion
 * lies in [2^-1000, 2^1000] and every partial sum below 9! 2^1000: doubles hold them. */
static int in_band(int n, int dim, int lifted, const double *e, int b)
{
    for (int i = 0; i < n * n; i++) {
        double a = fabs(e[i]);
        int lift = lifted && i % n == dim;
        if (a != 0 && !(a >= pow2(lift ? -2 * b : -b) && a <= pow2(lift ? 2 * b : b))) return 0;
    }
    return 1;
}

/* The double-word stage for rows p_i - p_k (flip: k odd): the entries formed exactly
 * (a difference of doubles and a sum of squares, each as a double word), every nonzero
 * one in [2^-50, 2^50] (lifted: squared), so that every product of the leading words
 * lies in [2^-500, 2^500] and its rounding error far inside the normal range; an
 * underflow among the low words costs at most 2^-1074 per operation, far below
 * u^2 P (P >= 2^-500 when nonzero), absorbed by the factor 4 below. Each of the g steps of
 * a product's path multiplies its relative error by at most 1 + 8u^2 (the two
 * operations' bounds above; the entries add none but the lifted sum's d - 1
 * additions), so |computed - det| <= ((1 + 8u^2)^g - 1) P, below 32 (g + 2) u^2 P. */
static int dw_sign(const lh__subsets *sub, int n, int dim, int lifted, const double *const *pts,
                   int k, int flip, int *sign)
{
#if FLT_EVAL_METHOD == 0
    dword e[(LH__MAXN - 1) * (LH__MAXN - 1)];
    double mag[(LH__MAXN - 1) * (LH__MAXN - 1)];
    for (int i = 0, r = 0; i <= n; i++) {
        if (i == k) continue;
        dword lift = {0, 0};
        for (int c = 0; c < dim; c++) {
            dword diff = two_sum(pts[i][c], -pts[k][c]);
            e[r * n + c] = diff;
            mag[r * n + c] = diff.hi;
            if (lifted) lift = dw_add(lift, dw_mul(diff, diff));
        }
        if (lifted) {
            e[r * n + dim] = lift;
            mag[r * n + dim] = lift.hi;
        }
        r++;
    }
    if (!in_band(n, dim, lifted, mag, 50)) return 0;
    int g = n * (n + 1) / 2 - 1 + dim + 2;
    dword det;
    double perm;
    expand_dw(sub, n, e, &det, &perm);
    if (perm == 0 || !(fabs(det.hi) > perm * (32.0 * (g + 2) * 0x1p-106))) return 0;
    *sign = (det.hi > 0) != flip ? 1 : -1;
    return 1;
#else
    (void)sub, (void)n, (void)dim, (void)lifted, (void)pts, (void)k, (void)flip, (void)sign;
    return 0;
#endif
}

/* x 2^k rounded once (only into the subnormal range: absolute error at most 2^-1075),
 * for |x 2^k| <= 1 (so k <= 1074) or x = 0 (any k); below -2100 every finite x gives 0
 * (|x 2^k| < 2^-1075). */
static double scale2(double x, int k)
{
    if (x == 0 || k < -2100) return 0 * x;
    int h = k / 2; /* both factors' exponents in [-1050, 1023]; the first product is
                    * at least the final one in magnitude, so at most one more
                    * rounding, below 2^-1075 */
    return x * pow2(h) * pow2(k - h);
}

/* The first pass in plain doubles on the matrix scaled by powers of two where its
 * entries leave the band of in_band(): row r (point i != k) by 2^-a_r, a_r from its
 * largest |p_i[c] - p_k[c]|, then column j by 2^-b_j, so that every entry is at most 1
 * and the column's largest at least 1/2 (det changes by a power of two, not its sign).
 * Each scaled entry is formed from the unscaled difference (or from the row's scaled
 * sum of squares S_r in [1/4, d), lifted entry S_r 2^(a_r - b_L), a_r - b_L <= 1) with
 * the roundings counted in g, plus an underflow of at most 2^-1066 absolute in all.
 * In the expansion (entries <= 1, minors <= 8!) products underflow by at most
 * 2^-1075 each and sums exactly, so the absolute errors, carried through cofactors of
 * magnitude at most 9!, stay below 2^-1030 in total; the permanent computed is at
 * most that much (and a factor (1 - u)^g) below the true one. Hence
 *     |computed - det| <= 2 gamma_g P_computed + 2^-1029
 *                      <  4 (g + 2) u P_computed + 2^-1000,
 * the bound used. 1 with *sign set (before the pivot's flip) when it decides, -1 when
 * the scaled matrix has a zero row or column (possibly an exact zero), else 0. */
static int scaled_sign(const lh__subsets *sub, int n, int dim, int lifted,
                       const double *const *pts, int k, int g, int *sign)
{
    double diff[(LH__MAXN - 1) * (LH__MAXN - 1)], e[(LH__MAXN - 1) * (LH__MAXN - 1)];
    int a[LH__MAXN], most[LH__MAXN], lift_exp[LH__MAXN];
    for (int c = 0; c < dim; c++) most[c] = INT_MIN;
    for (int i = 0, r = 0; i <= n; i++) {
        if (i == k) continue;
        double big = 0;
        for (int c = 0; c < dim; c++) {
            double x = pts[i][c] - pts[k][c];
            if (!isfinite(x)) return 0;
            diff[r * n + c] = x;
            if (fabs(x) > big) big = fabs(x);
        }
        if (big == 0) return -1;
        a[r] = binary_exponent(big) + 1; /* big 2^-a[r] in [1/2, 1) */
        for (int c = 0; c < dim; c++) {
            double x = fabs(diff[r * n + c]);
            if (x != 0 && binary_exponent(x) + 1 - a[r] > most[c])
                most[c] = binary_exponent(x) + 1 - a[r];
        }
        if (lifted) { /* S_r = sum of (diff 2^-a_r)^2, in [1/4, d) */
            double sum = 0;
            for (int c = 0; c < dim; c++) {
                double t = scale2(diff[r * n + c], -a[r]);
                sum += t * t;
            }
            e[r * n + dim] = sum;
            lift_exp[r] = a[r] + binary_exponent(sum) + 1; /* S_r 2^a_r < 2^lift_exp */
        }
        r++;
    }
    for (int c = 0; c < dim; c++) {
        if (most[c] == INT_MIN) return -1;
        for (int r = 0; r < n; r++) e[r * n + c] = scale2(diff[r * n + c], -(a[r] + most[c]));
    }
    if (lifted) {
        int top = INT_MIN;
        for (int r = 0; r < n; r++)
            if (lift_exp[r] > top) top = lift_exp[r];
        for (int r = 0; r < n; r++) e[r * n + dim] = scale2(e[r * n + dim], a[r] - top);
    }
    double det, perm;
    expand_dbl(sub, n, e, &det, &perm);
    if (!(fabs(det) > perm * (4.0 * (g + 2) * 0x1p-53) + 0x1p-1000)) return 0;
    *sign = det > 0 ? 1 : -1;
    return 1;
}

int lh__wide_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                  int double_word, int *sign)
{
    int n = dim + lifted; /* rows p_i - p_k for i != k */
    int k = pivot(dim, n + 1, pts);
    /* Subtracting row k of the homogeneous matrix from the others and expanding along
     * the column of ones leaves (-1)^k times the determinant of these rows. */
    int flip = k & 1;
    if (double_word) return dw_sign(sub, n, dim, lifted, pts, k, flip, sign);
    int g = n * (n + 1) / 2 - 1 + dim + 2;
    double ed[(LH__MAXN - 1) * (LH__MAXN - 1)];
    for (int i = 0, r = 0; i <= n; i++) {
        if (i == k) continue;
        double lift = 0;
        for (int c = 0; c < dim; c++) {
            double diff = pts[i][c] - pts[k][c];
            ed[r * n + c] = diff;
            lift += diff * diff;
        }
        if (lifted) ed[r * n + dim] = lift;
        r++;
    }
    if (in_band(n, dim, lifted, ed, 100)) {
        double det, perm;
        expand_dbl(sub, n, ed, &det, &perm);
        if (perm != 0 && fabs(det) > perm * (4.0 * (g + 2) * 0x1p-53)) {
            *sign = (det > 0) != flip ? 1 : -1;
            return 1;
        }
        return 0;
    }
    int decided = scaled_sign(sub, n, dim, lifted, pts, k, g, sign);
    if (decided) {
        if (decided > 0 && flip) *sign = -*sign;
        return decided > 0;
    }
    wide e[(LH__MAXN - 1) * (LH__MAXN - 1)];
    for (int i = 0, r = 0; i <= n; i++) {
        if (i == k) continue;
        wide lift = {0, 0};
        for (int c = 0; c < dim; c++) {
            wide diff = w_add(w_make(pts[i][c], 0), w_make(-pts[k][c], 0));
            e[r * n + c] = diff;
            if (lifted) lift = w_add(lift, w_mul(diff, diff));
        }
        if (lifted) e[r * n + dim] = lift;
        r++;
    }
    wide det, perm;
    expand(sub, n, e, &det, &perm);
    wide bound = w_mul(perm, w_make(4.0 * (g + 2), -53));
    if (perm.m == 0 || !w_abs_greater(det, bound)) return 0;
    *sign = (det.m > 0) != flip ? 1 : -1;
    return 1;
}
