/*
 * pred_wide.c — the wide-exponent filter: the floating-point filter's determinant
 * and error bound evaluated on numbers m * 2^e with a double m and an integer e, so
 * that no product overflows or underflows whatever the magnitudes (1e+300 beside
 * 5e-324). It runs where the double filter could not decide, before the exact stage,
 * translated to the point that makes the expansion cancel least (pivot() below), and
 * in plain doubles when the entries allow.
 *
 * Error bound (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
 * 3.1 and 3.3; the derivation of docs/predicates.md, "The filter's error bound").
 * The m x m determinant of rows p_i - p_0 (and |p_i - p_0|^2 for insphere) is
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

#include <math.h>
#include <stdint.h>

/* x = m * 2^e with 1/2 <= |m| < 1, or m = 0 (e = 0). */
typedef struct wide {
    double m;
    int64_t e;
} wide;

static wide w_make(double m, int64_t e)
{
    int k;
    wide r;
    r.m = frexp(m, &k); /* exact; 0 stays 0 */
    r.e = r.m == 0 ? 0 : e + k;
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
    return w_make(a.m + ldexp(b.m, (int)shift), a.e);
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

/* The row to subtract from the others: the point k minimising the product over i of
 * max_c |p_i[c] - p_k[c]| (compared by binary exponents), so that a cell with most of
 * its points in a small cluster and one far away is translated to the cluster, where
 * its small rows are formed without rounding and the expansion cancels little. */
static int pivot(int dim, int rows, const double *const *pts)
{
    int best = 0;
    long best_sum = 0;
    for (int k = 0; k < rows; k++) {
        long sum = 0;
        for (int i = 0; i < rows; i++) {
            if (i == k) continue;
            double most = 0;
            for (int c = 0; c < dim; c++) most = fmax(most, fabs(pts[i][c] - pts[k][c]));
            sum += most == 0 ? -1100 : !isfinite(most) ? 1100 : ilogb(most);
        }
        if (k == 0 || sum < best_sum) {
            best = k;
            best_sum = sum;
        }
    }
    return best;
}

/* Whether every nonzero |x| of the n x n entries lies in [2^-100, 2^100] (the lifted
 * column, when present: [2^-200, 2^200]): then every product of the expansion lies in
 * [2^-1000, 2^1000] and every partial sum below 9! 2^1000, so doubles hold them. */
static int in_band(int n, int dim, int lifted, const double *e)
{
    for (int i = 0; i < n * n; i++) {
        double a = fabs(e[i]), lim = lifted && i % n == dim ? 0x1p200 : 0x1p100;
        if (a != 0 && !(a >= 1 / lim && a <= lim)) return 0;
    }
    return 1;
}

int lh__wide_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                  int *sign)
{
    int n = dim + lifted; /* rows p_i - p_k for i != k */
    int k = pivot(dim, n + 1, pts);
    /* Subtracting row k of the homogeneous matrix from the others and expanding along
     * the column of ones leaves (-1)^k times the determinant of these rows. */
    int flip = k & 1;
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
    if (in_band(n, dim, lifted, ed)) {
        double det, perm;
        expand_dbl(sub, n, ed, &det, &perm);
        if (perm == 0 || !(fabs(det) > perm * (4.0 * (g + 2) * 0x1p-53))) return 0;
        *sign = (det > 0) != flip ? 1 : -1;
        return 1;
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
