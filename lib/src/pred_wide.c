/*
 * pred_wide.c — the wide-exponent filter: the floating-point filter's determinant
 * and error bound evaluated on numbers m * 2^e with a double m and an integer e, so
 * that no product overflows or underflows whatever the magnitudes (1e+300 beside
 * 5e-324). It runs only where the double filter's band ends, before the exact stage.
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

int lh__wide_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                  int *sign)
{
    int n = dim + lifted; /* rows p_1..p_n minus p_0 */
    wide e[(LH__MAXN - 1) * (LH__MAXN - 1)];
    for (int i = 0; i < n; i++) {
        wide lift = {0, 0};
        for (int c = 0; c < dim; c++) {
            wide x = w_make(pts[i + 1][c], 0), y = w_make(-pts[0][c], 0);
            wide diff = w_add(x, y);
            if (c < n) e[i * n + c] = diff;
            if (lifted) lift = w_add(lift, w_mul(diff, diff));
        }
        if (lifted) e[i * n + dim] = lift;
    }
    wide det, perm;
    expand(sub, n, e, &det, &perm);
    int g = n * (n + 1) / 2 - 1 + dim + 2;
    wide bound = w_mul(perm, w_make(4.0 * (g + 2), -53));
    if (perm.m == 0 || !w_abs_greater(det, bound)) return 0;
    *sign = det.m > 0 ? 1 : -1;
    return 1;
}
