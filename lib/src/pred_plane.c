/*
 * pred_plane.c — lh_hyperplane: the hyperplane through d points of R^d from the exact
 * cofactors of their homogeneous matrix. With rows [1, p_i] (i < d) and [1, x],
 * det = sum_c (-1)^(d+c) x'_c M_c (x'_0 = 1, x'_j = x_j; M_c the minor of the first d
 * rows without column c), so n_j = (-1)^(d+j) M_j and offset (-1)^d M_0 give
 * orient_d(p, x) = sign(n.x + offset). Each M_c is an exact integer determinant
 * rounded once (lh__minor_value); the normal is scaled by a power of two before
 * normalising, so nothing overflows: a few ulps whatever the facet's condition.
 */
#include "pred_internal.h"

#include <math.h>

int lh_hyperplane(lh_pred *ctx, int d, const double *const *pts, double *normal, double *offset)
{
    if (!ctx || !pts || !normal || !offset || d < 1 || d > LH_ORIENT_MAX_DIM) return 0;
    int rows[LH__MAXN], cols[LH__MAXN], e[LH__MAXN];
    double v[LH__MAXN];
    for (int i = 0; i < d; i++) rows[i] = i;
    int emax = INT32_MIN;
    for (int c = 0; c <= d; c++) {
        for (int k = 0, j = 0; j <= d; j++)
            if (j != c) cols[k++] = j;
        v[c] = lh__minor_value(ctx, pts, d, d, rows, cols, &e[c]);
        if ((d + c) & 1) v[c] = -v[c];
        if (c > 0 && v[c] != 0 && e[c] > emax) emax = e[c];
    }
    if (emax == INT32_MIN) { /* every normal component 0: dependent points */
        for (int j = 0; j < d; j++) normal[j] = 0;
        *offset = 0;
        return 0;
    }
    double norm = 0;
    for (int j = 1; j <= d; j++) {
        v[j] = v[j] != 0 ? ldexp(v[j], e[j] - emax) : 0;
        norm += v[j] * v[j];
    }
    norm = sqrt(norm);
    for (int j = 0; j < d; j++) normal[j] = v[j + 1] / norm;
    *offset = v[0] != 0 ? ldexp(v[0] / norm, e[0] - emax) : 0;
    return 1;
}
