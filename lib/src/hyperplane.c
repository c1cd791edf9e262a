/*
 * hyperplane.c — lh_hyperplane_exp: the hyperplane through d points of R^d with its
 * offset as a mantissa and a binary exponent, so that it stays exact in range where
 * the offset's magnitude passes DBL_MAX (facets of sites near DBL_MAX: the offset
 * is a d x d minor over a (d-1) x (d-1) one, up to about DBL_MAX * sqrt(d)).
 * With rows [1, p_i] (i < d) and [1, x], det = sum_c (-1)^(d+c) x'_c M_c (x'_0 = 1,
 * x'_j = x_j; M_c the minor of the first d rows without column c), so
 * n_j = (-1)^(d+j) M_j and the offset (-1)^d M_0 give orient_d(p, x) = sign(n.x + off).
 * Each M_c is an exact integer determinant rounded once (lh__minor_value, as v 2^e);
 * the normal's cofactors are brought to a common exponent before their length is
 * taken, so neither the normal nor the mantissa overflows or underflows.
 */
#include "lh_exact.h"

#include <math.h>
#include <stdint.h>

int lh_hyperplane_exp(lh_pred *ctx, int d, const double *const *pts, double *normal,
                      double *offset, int *offset_exp)
{
    if (!ctx || !pts || !normal || !offset || !offset_exp || d < 1 || d > LH_ORIENT_MAX_DIM) return 0;
    int rows[LH_ORIENT_MAX_DIM + 1], cols[LH_ORIENT_MAX_DIM + 1], e[LH_ORIENT_MAX_DIM + 1];
    double v[LH_ORIENT_MAX_DIM + 1];
    for (int i = 0; i < d; i++) rows[i] = i;
    int emax = INT32_MIN;
    for (int c = 0; c <= d; c++) {
        for (int k = 0, j = 0; j <= d; j++)
            if (j != c) cols[k++] = j;
        v[c] = lh__minor_value(ctx, pts, d, d, rows, cols, &e[c]);
        if ((d + c) & 1) v[c] = -v[c];
        if (c > 0 && v[c] != 0 && e[c] > emax) emax = e[c];
    }
    *offset = 0;
    *offset_exp = 0;
    if (emax == INT32_MIN) { /* every normal component 0: dependent points */
        for (int j = 0; j < d; j++) normal[j] = 0;
        return 0;
    }
    double norm = 0;
    for (int j = 1; j <= d; j++) {
        v[j] = v[j] != 0 ? ldexp(v[j], e[j] - emax) : 0;
        norm += v[j] * v[j];
    }
    norm = sqrt(norm);
    for (int j = 0; j < d; j++) normal[j] = v[j + 1] / norm;
    if (v[0] != 0) { /* v[0] 2^(e[0] - emax) / norm, its mantissa in [0.5, 1) */
        int g;
        *offset = frexp(v[0] / norm, &g);
        *offset_exp = g + e[0] - emax;
    }
    return 1;
}
