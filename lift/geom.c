/* geom.c — linear solves and circumcentres (geom.h). */
#include "geom.h"

#include <math.h>
#include <stddef.h>

enum { MAXD = 8 };

int lh__solve(double *a, double *b, int m)
{
    for (int k = 0; k < m; k++) {
        int p = k;
        for (int i = k + 1; i < m; i++)
            if (fabs(a[i * m + k]) > fabs(a[p * m + k])) p = i;
        if (a[p * m + k] == 0) return 0;
        if (p != k) {
            for (int j = 0; j < m; j++) {
                double x = a[k * m + j];
                a[k * m + j] = a[p * m + j];
                a[p * m + j] = x;
            }
            double x = b[k];
            b[k] = b[p];
            b[p] = x;
        }
        for (int i = k + 1; i < m; i++) {
            double f = a[i * m + k] / a[k * m + k];
            for (int j = k; j < m; j++) a[i * m + j] -= f * a[k * m + j];
            b[i] -= f * b[k];
        }
    }
    for (int k = m - 1; k >= 0; k--) {
        for (int j = k + 1; j < m; j++) b[k] -= a[k * m + j] * b[j];
        b[k] /= a[k * m + k];
    }
    return 1;
}

int lh__scale_exp(const double *const *p, int m, int d, const double *q)
{
    double big = 0;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < d; j++) big = fmax(big, fabs(p[i][j]));
    for (int j = 0; q && j < d; j++) big = fmax(big, fabs(q[j]));
    int e = 0;
    if (big > 0) frexp(big, &e);
    return e;
}

/* Computed on the points scaled by 2^-s (lh__scale_exp), relative to p0. */
int lh__circumcenter_exp(int d, int k, const double *const *p, double *c, int *exp)
{
    double a[MAXD * MAXD], b[MAXD], e[MAXD][MAXD], p0[MAXD];
    const int sc = lh__scale_exp(p, k + 1, d, NULL);
    *exp = sc;
    for (int j = 0; j < d; j++) p0[j] = ldexp(p[0][j], -sc);
    for (int i = 0; i < k; i++) {
        b[i] = 0;
        for (int j = 0; j < d; j++) {
            e[i][j] = ldexp(p[i + 1][j], -sc) - p0[j];
            b[i] += e[i][j] * e[i][j];
        }
    }
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) {
            double s = 0;
            if (k == d) {
                s = 2 * e[i][j];
            } else {
                for (int l = 0; l < d; l++) s += e[i][l] * e[j][l];
                s *= 2;
            }
            a[i * k + j] = s;
        }
    int ok = lh__solve(a, b, k);
    for (int j = 0; j < d; j++) {
        double x = p0[j];
        if (k == d) {
            x += b[j];
        } else {
            for (int i = 0; i < k; i++) x += b[i] * e[i][j];
        }
        c[j] = ok ? x : NAN;
    }
    return ok;
}

int lh__circumcenter(int d, int k, const double *const *p, double *c)
{
    int e;
    int ok = lh__circumcenter_exp(d, k, p, c, &e);
    for (int j = 0; j < d; j++) c[j] = ldexp(c[j], e);
    return ok;
}
