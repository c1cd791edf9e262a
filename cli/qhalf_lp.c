/*
 * qhalf_lp.c — an interior point for `lifthull qhalf` when none is given: the
 * Chebyshev centre of the halfspaces, the centre of the largest ball inside them,
 * from the linear program
 *
 *     max t  subject to  u_i.x + t <= beta_i   (u_i = a_i / |a_i|, beta_i = -b_i / |a_i|)
 *
 * (Boyd and Vandenberghe, "Convex Optimization", 2004, sec. 8.5.1; Qhull's manual,
 * "qhalf notes", suggests the same program). It is solved through its dual,
 *
 *     min sum beta_i y_i  subject to  sum y_i u_i = 0, sum y_i = 1, y >= 0,
 *
 * d + 1 equality rows over n variables, by the two-phase simplex method on a dense
 * tableau (Dantzig's rule; Bland's after too many pivots, which cannot cycle), in
 * floating point: (x, t) are the optimal basis' simplex multipliers. The caller
 * checks x exactly against every halfspace, so a rounding error can make this fail,
 * never make it return a point that is not strictly inside.
 */
#include "qhalf.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct tableau {
    int rows;      /* d + 1                                               */
    size_t cols;   /* n + rows: the y_i, then one artificial per row      */
    double *t;     /* rows * (cols + 1): the last column is the right side */
    size_t *basis; /* rows: the basic column of each row                  */
} tableau;

#define AT(T, r, c) ((T)->t[(size_t)(r) * ((T)->cols + 1) + (c)])

static void pivot(tableau *T, int pr, size_t pc)
{
    double p = AT(T, pr, pc);
    for (size_t c = 0; c <= T->cols; c++) AT(T, pr, c) /= p;
    for (int r = 0; r < T->rows; r++) {
        double f = AT(T, r, pc);
        if (r == pr || f == 0) continue;
        for (size_t c = 0; c <= T->cols; c++) AT(T, r, c) -= f * AT(T, pr, c);
    }
    T->basis[pr] = pc;
}

/* Minimises cost.y over the tableau's columns below `limit` from its current basis.
 * 1 at an optimum; 0 when unbounded or out of pivots. */
static int simplex(tableau *T, const double *cost, size_t limit)
{
    const double eps = 1e-12;
    size_t most = 50 * (T->cols + 10);
    for (size_t it = 0; it < most; it++) {
        int bland = it > most / 2;
        size_t enter = (size_t)-1;
        double best = -eps;
        for (size_t c = 0; c < limit; c++) {
            double rc = cost[c];
            for (int r = 0; r < T->rows; r++) rc -= cost[T->basis[r]] * AT(T, r, c);
            if (rc < best) {
                enter = c;
                best = rc;
                if (bland) break;
            }
        }
        if (enter == (size_t)-1) return 1;
        int leave = -1;
        double ratio = INFINITY;
        for (int r = 0; r < T->rows; r++) {
            double a = AT(T, r, enter);
            if (a > eps && AT(T, r, T->cols) / a < ratio) ratio = AT(T, r, T->cols) / a, leave = r;
        }
        if (leave < 0) return 0;
        pivot(T, leave, enter);
    }
    return 0;
}

/* The dual's rows: column i is (u_i, 1) with cost beta_i, beta scaled to at most 1
 * (*scale: the factor); a halfspace 0.x + b <= 0 with b < 0 holds everywhere: its
 * column stays 0 and never enters. Then the artificial basis. 0 for 0.x + b <= 0
 * with b >= 0 (nothing is inside it). */
static int setup(tableau *T, const lh_cli_halfspaces *hs, double *beta, double *scale)
{
    const int d = hs->d;
    const size_t n = hs->n;
    *scale = 0;
    memset(T->t, 0, (size_t)T->rows * (T->cols + 1) * sizeof *T->t);
    for (size_t i = 0; i < n; i++) {
        const double *a = hs->h + i * (size_t)(d + 1);
        double big = 0, s = 0;
        for (int j = 0; j < d; j++) big = fmax(big, fabs(a[j]));
        for (int j = 0; j < d && big > 0; j++) s += (a[j] / big) * (a[j] / big);
        double len = big * sqrt(s); /* |a| without overflow */
        beta[i] = 0;
        if (big == 0) {
            if (!(a[d] < 0)) return 0;
            continue;
        }
        for (int j = 0; j < d; j++) AT(T, j, i) = a[j] / len;
        AT(T, d, i) = 1;
        beta[i] = -a[d] / len;
        *scale = fmax(*scale, fabs(beta[i]));
    }
    for (size_t i = 0; i < n && *scale > 0; i++) beta[i] /= *scale;
    for (int r = 0; r < T->rows; r++) {
        AT(T, r, n + (size_t)r) = 1;
        AT(T, r, T->cols) = r == d;
        T->basis[r] = n + (size_t)r;
    }
    return isfinite(*scale);
}

int lh_cli_qhalf_centre(const lh_cli_halfspaces *hs, double *x)
{
    const int d = hs->d, rows = d + 1;
    const size_t n = hs->n, cols = n + (size_t)rows;
    tableau T = {rows, cols, malloc((size_t)rows * (cols + 1) * sizeof(double)),
                 malloc((size_t)rows * sizeof(size_t))};
    double *cost = calloc(cols, sizeof *cost), *beta = malloc((n ? n : 1) * sizeof *beta);
    double scale, art = 0, t = 0;
    int ok = T.t && T.basis && cost && beta && setup(&T, hs, beta, &scale);
    for (int r = 0; ok && r < rows; r++) cost[n + (size_t)r] = 1; /* phase 1: sum of artificials */
    ok = ok && simplex(&T, cost, cols);
    for (int r = 0; ok && r < rows; r++)
        if (T.basis[r] >= n) art += AT(&T, r, cols);
    ok = ok && art < 1e-9; /* feasible: sum y_i u_i = 0 with sum y_i = 1 */
    for (size_t i = 0; ok && i < cols; i++) cost[i] = i < n ? beta[i] : 0; /* phase 2 */
    ok = ok && simplex(&T, cost, n);
    for (int j = 0; ok && j < rows; j++) { /* multipliers c_B B^-1: B^-1 in the artificial columns */
        double pi = 0;
        for (int r = 0; r < rows; r++) pi += cost[T.basis[r]] * AT(&T, r, n + (size_t)j);
        if (j < d) x[j] = pi * scale;
        else t = pi;
    }
    ok = ok && t > 0; /* the radius (scaled) */
    for (int j = 0; ok && j < d; j++) ok = isfinite(x[j]);
    free(T.t);
    free(T.basis);
    free(cost);
    free(beta);
    return ok;
}
