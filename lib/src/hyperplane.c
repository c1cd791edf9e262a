/*
 * hyperplane.c — lh_hyperplane_exp: lh_hyperplane with the offset as a mantissa and
 * a binary exponent, exact in range where the offset's magnitude passes DBL_MAX
 * (facets of sites near DBL_MAX: up to about DBL_MAX sqrt(d)) or falls below DBL_MIN.
 * With M_c the minor of the homogeneous rows [1, p_i] without column c, lh_hyperplane
 * gives n_j = (-1)^(d+c) M_c / |M| (c = j + 1) and offset (-1)^d M_0 / |M|, |M| the
 * length of (M_1..M_d). So offset = (-1)^d M_0 n_j / ((-1)^(d+c) M_c) for any j with
 * n_j != 0. Where lh_hyperplane's offset is a normal double it is taken as it is;
 * else (+-inf, subnormal or an underflowed 0) it is formed at the largest |n_j|
 * (>= 1/sqrt(d)) from M_0 and M_c as mantissas and exponents (lh__minor_value: each
 * exact, rounded once): nothing overflows or underflows, relative error a few ulps.
 */
#include "lh_exact.h"

#include <math.h>

/* The minor without column c of the first d rows, signed (-1)^(d+c), as v 2^e. */
static double cofactor(lh_pred *ctx, int d, const double *const *pts, int c, int *e)
{
    int rows[LH_ORIENT_MAX_DIM + 1], cols[LH_ORIENT_MAX_DIM + 1];
    for (int i = 0; i < d; i++) rows[i] = i;
    for (int k = 0, j = 0; j <= d; j++)
        if (j != c) cols[k++] = j;
    double v = lh__minor_value(ctx, pts, d, d, rows, cols, e);
    return (d + c) & 1 ? -v : v;
}

int lh_hyperplane_exp(lh_pred *ctx, int d, const double *const *pts, double *normal,
                      double *offset, int *offset_exp)
{
    if (!offset || !offset_exp) return 0;
    double off;
    *offset = 0;
    *offset_exp = 0;
    if (!lh_hyperplane(ctx, d, pts, normal, &off)) return 0;
    if (isnormal(off)) { /* in range: lh_hyperplane's offset, bit for bit */
        *offset = frexp(off, offset_exp);
        return 1;
    }
    int j = 0;
    for (int k = 1; k < d; k++)
        if (fabs(normal[k]) > fabs(normal[j])) j = k;
    int e0, ec, g;
    double v0 = cofactor(ctx, d, pts, 0, &e0);
    if (v0 == 0) return 1; /* through the origin */
    double vc = cofactor(ctx, d, pts, j + 1, &ec);
    *offset = frexp(v0 / vc * normal[j], &g);
    *offset_exp = g + e0 - ec;
    return 1;
}
