/*
 * pred_dist.c — lh_distance_compare: the sign of |q - a|^2 - |q - b|^2, exactly.
 *
 * Filter: A = sum (q_j - a_j)^2 and B likewise in double. Each term carries at most
 * three roundings and the running sum d - 1 more, so |fl(A) - A| <= gamma_{d+2} A
 * (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., §3.1), the
 * same for B, and the final subtraction one more unit: the bound
 * err = 2 (d + 4) eps (fl(A) + fl(B)), eps = 2^-53, covers all of it with room for
 * the rounding of err itself. Underflow breaks relative bounds, so the filter
 * answers only when fl(A) + fl(B) >= 2^-900 (any underflowed term is then far
 * below err) and both are finite. Otherwise the exact stage: every coordinate an
 * integer at one power-of-two scale (bigint.h), differences squared and summed.
 */
#include "pred_internal.h"

#include <limits.h>
#include <math.h>

static int filter(int d, const double *q, const double *a, const double *b, int *sign)
{
    double A = 0, B = 0;
    for (int j = 0; j < d; j++) {
        double x = q[j] - a[j], y = q[j] - b[j];
        A += x * x;
        B += y * y;
    }
    double S = A + B;
    if (!(S >= 0x1p-900) || !isfinite(S)) return 0;
    double D = A - B, err = (double)(2 * (d + 4)) * 0x1p-53 * S;
    if (D > err) *sign = 1;
    else if (D < -err) *sign = -1;
    else return 0;
    return 1;
}

/* sum_j (q_j - p_j)^2 at scale s into acc; tmp: three scratch numbers. */
static void sum_squares(int d, const double *q, const double *p, int s, lh__bn *acc, lh__bn *tmp)
{
    acc->n = acc->neg = 0;
    for (int j = 0; j < d; j++) {
        lh__bn_set_dbl(&tmp[0], q[j], s);
        lh__bn_set_dbl(&tmp[1], p[j], s);
        lh__bn_add(&tmp[0], &tmp[0], &tmp[1], 1);
        lh__bn_mul(&tmp[2], &tmp[0], &tmp[0]);
        lh__bn_add(acc, acc, &tmp[2], 0);
    }
}

static int exact(lh_pred *ctx, int d, const double *q, const double *a, const double *b)
{
    int s = INT_MAX;
    const double *pts[3] = {q, a, b};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < d; j++)
            if (pts[i][j] != 0) {
                int e = lh__dbl_low_exp(pts[i][j]);
                if (e < s) s = e;
            }
    if (s == INT_MAX) return 0; /* all zero */
    lh__bn num[5];
    for (int i = 0; i < 5; i++) num[i].d = ctx->arena + (size_t)i * LH__ENTRY_LIMBS;
    sum_squares(d, q, a, s, &num[3], num);
    sum_squares(d, q, b, s, &num[4], num);
    lh__bn_add(&num[3], &num[3], &num[4], 1);
    return lh__bn_sign(&num[3]);
}

int lh_distance_compare(lh_pred *ctx, int d, const double *q, const double *a, const double *b)
{
    if (!ctx || !q || !a || !b || d < 1 || d > LH_ORIENT_MAX_DIM) return 0;
    ctx->count.calls++;
    int sign;
    if (filter(d, q, a, b, &sign)) {
        ctx->count.filter_exits++;
        return sign;
    }
    ctx->count.exact_exits++;
    sign = exact(ctx, d, q, a, b);
    if (!sign) ctx->count.zero_results++;
    return sign;
}
