/* m2_geom.c — scale-free floating-point geometry (m2_geom.h). */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "lifthull.h"
#include "m2_geom.h"

/* 2^k for -1074 <= k <= 1023, from its bits (ldexp's result, without the call). */
static double pow2(int k)
{
    const uint64_t b = k >= -1022 ? (uint64_t)(k + 1023) << 52 : (uint64_t)1 << (k + 1074);
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* The exponent of x > 0 finite (ilogb's), from its bits when x is normal. */
static int exponent(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    const int f = (int)(b >> 52 & 0x7ff);
    return f ? f - 1023 : ilogb(x);
}

/* x * 2^-e for the exponent e of the largest |value| (so the result is at most 2):
 * one rounding, as ldexp(x, -e). */
static double scale_down(double x, int e)
{
    return -e <= 1023 ? x * pow2(-e) : x * 0x1p1000 * pow2(-e - 1000);
}

int lh__g_vecs(const double *o, const double *const *p, int n, double (*vecs)[2])
{
    int half = 0;
    for (int i = 0; i < n && !half; i++)
        for (int j = 0; j < 2; j++) {
            vecs[i][j] = p[i][j] - o[j];
            if (isinf(vecs[i][j])) half = 1;
        }
    if (half) /* both coordinates beyond 2^970 in magnitude where it overflows: halves exact */
        for (int i = 0; i < n; i++)
            for (int j = 0; j < 2; j++) vecs[i][j] = p[i][j] / 2 - o[j] / 2;
    double big = 0;
    for (int i = 0; i < n; i++) big = fmax(big, fmax(fabs(vecs[i][0]), fabs(vecs[i][1])));
    if (big == 0) return 0;
    const int e = exponent(big);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 2; j++) vecs[i][j] = scale_down(vecs[i][j], e);
    return e + half;
}

int lh__g_vec(const double *o, const double *p, double v[2])
{
    const double *q[1] = {p};
    double w[1][2];
    const int e = lh__g_vecs(o, q, 1, w);
    v[0] = w[0][0], v[1] = w[0][1];
    return e;
}

int lh__g_cmp(double a, long ea, double b, long eb)
{
    if (a == 0 || b == 0) return (a > 0) - (b > 0);
    if (isinf(a) || isinf(b)) return (isinf(a) != 0) - (isinf(b) != 0);
    const long ta = (long)exponent(a) + ea, tb = (long)exponent(b) + eb;
    if (ta != tb) return ta < tb ? -1 : 1;
    const double fa = scale_down(a, exponent(a)), fb = scale_down(b, exponent(b)); /* in [1, 2) */
    return (fa > fb) - (fa < fb);
}

double lh__g_norm(double a, long ea, long *e)
{
    if (a == 0) {
        *e = LONG_MIN;
        return 0;
    }
    const int x = exponent(a);
    *e = ea + x;
    return scale_down(a, x);
}

double lh__g_cross(const double *u, const double *v)
{
    const double p = u[1] * v[0];
    const double err = fma(u[1], v[0], -p); /* u1 v0 = p + err exactly */
    return fma(u[0], v[1], -p) - err;
}

double lh__g_hypot(double x, double y) { return hypot(x, y); }

double lh__g_dot(const double *u, const double *v)
{
    const double p = u[1] * v[1];
    const double err = fma(u[1], v[1], -p);
    return fma(u[0], v[0], p) + err;
}

int lh_triangle_scaled_edges(const double a[2], const double b[2], const double c[2],
                             double d[3][2])
{
    /* d[k] from corner k+1 to corner k+2, each rounded once from the coordinates,
       all three scaled by one power of two */
    const double *from[3] = {b, c, a}, *to[3] = {c, a, b};
    int half = 0;
    for (int k = 0; k < 3 && !half; k++)
        for (int j = 0; j < 2; j++) {
            d[k][j] = to[k][j] - from[k][j];
            if (isinf(d[k][j])) half = 1;
        }
    if (half)
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 2; j++) d[k][j] = to[k][j] / 2 - from[k][j] / 2;
    double big = 0;
    for (int k = 0; k < 3; k++) big = fmax(big, fmax(fabs(d[k][0]), fabs(d[k][1])));
    const int e = big > 0 ? exponent(big) : 0;
    for (int k = 0; k < 3; k++) d[k][0] = scale_down(d[k][0], e), d[k][1] = scale_down(d[k][1], e);
    return e + half;
}

void lh__g_measure(const double *a, const double *b, const double *c, lh__g_tri *t)
{
    t->e = lh_triangle_scaled_edges(a, b, c, t->d);
    t->k = 0;
    for (int k = 0; k < 3; k++) {
        t->len[k] = lh__g_len(t->d[k][0], t->d[k][1]);
        if (t->len[k] < t->len[t->k]) t->k = k;
    }
    /* at corner k, the edges to corners k+1 and k+2 are d[k+2] and -d[k+1] */
    const int k = t->k, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    t->area2 = lh__g_cross(t->d[k1], t->d[k2]);
    const double den = t->len[k1] * t->len[k2];
    t->sin_min = den > 0 ? t->area2 / den : 0;
}

int lh__g_area_above(const lh__g_tri *t, double bound)
{
    /* area = area2 / 2 * 2^2e */
    return bound > 0 && lh__g_cmp(t->area2, 2L * t->e - 1, bound, 0) > 0;
}

double lh__g_cos(const double *o, const double *x, const double *y)
{
    double u[2], v[2];
    lh__g_vec(o, x, u);
    lh__g_vec(o, y, v);
    const double lu = lh__g_len(u[0], u[1]), lv = lh__g_len(v[0], v[1]);
    if (lu == 0 || lv == 0) return 1;
    const double c = lh__g_dot(u, v) / (lu * lv);
    return c > 1 ? 1 : c < -1 ? -1 : c;
}

void lh__g_along(const double *a, const double *b, double f, double *p)
{
    double d[2];
    const int e = lh__g_vec(a, b, d);
    p[0] = a[0] + ldexp(f * d[0], e);
    p[1] = a[1] + ldexp(f * d[1], e);
}
