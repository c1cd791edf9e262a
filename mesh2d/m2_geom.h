/*
 * m2_geom.h — scale-free floating-point geometry for the quality decisions of 2D
 * refinement (refine.c, smooth.c, m2_insert.c, trimesh.c): the bad-triangle test,
 * encroachment, the Steiner point placement and the statistics.
 *
 * Every measure is computed on difference vectors scaled by a power of two (exact
 * but for values that become subnormal) so that their largest component lies in
 * [1, 2): squares and products then
 * neither overflow nor underflow for any pair of finite doubles, and a measure that is
 * a ratio (a sine, a cosine, a weight) is the same double for the input scaled by any
 * 2^k. A length or area is that scaled value with its exponent, compared through
 * lh__g_cmp without ever forming it. A difference b - a is rounded once (it overflows
 * only when both coordinates exceed 2^970 in magnitude: then the halves, exact there,
 * are subtracted). Rounding commutes with scaling by 2^k as long as no value is
 * subnormal at one scale and not the other, so a mesh of 2^k P is 2^k times the mesh
 * of P when every coordinate of both stays normal or zero.
 *
 * Error bounds (u = 2^-53): the scaled differences have relative error u; a length
 * 2u; the cross product (Kahan's algorithm with fma) 2u relative plus an
 * absolute 2^-1074 from underflow; a sine or cosine about 6u relative plus 2^-1070
 * absolute. A triangle whose angle's sine lies below 2^-1000 thus compares as an angle
 * 0; every other comparison is exact up to those relative errors.
 */
#ifndef LH_M2_GEOM_H
#define LH_M2_GEOM_H

#include <math.h>

/* vecs[i] = (p[i] - o) * 2^-e for i < n, e returned: the largest |component| in
 * [1, 2) (all zero: e = 0). */
int lh__g_vecs(const double *o, const double *const *p, int n, double (*vecs)[2]);
/* One vector p - o, scaled alone. */
int lh__g_vec(const double *o, const double *p, double v[2]);
/* Sign of a * 2^ea - b * 2^eb for a, b >= 0 finite (+inf compares above every finite). */
int lh__g_cmp(double a, long ea, double b, long eb);
/* a * 2^ea as m * 2^*e with m in [1, 2) (a > 0 finite; a = 0: m = 0, *e = LONG_MIN):
 * such pairs order as (e, m) lexicographically. */
double lh__g_norm(double a, long ea, long *e);
/* u x v, accurate (Kahan's algorithm with fma). */
double lh__g_cross(const double *u, const double *v);
double lh__g_dot(const double *u, const double *v);
/* The length of a scaled vector (components at most 2 in magnitude): sqrt of the sum
 * of squares unless that is below 2^-1000, where hypot keeps it from underflowing. */
double lh__g_hypot(double x, double y);
static inline double lh__g_len(double x, double y)
{
    const double s = x * x + y * y;
    return s >= 0x1p-1000 ? sqrt(s) : lh__g_hypot(x, y);
}

/* A triangle a, b, c (counterclockwise) measured: d[k] the edge opposite corner k
 * (from corner k+1 to corner k+2: lh_triangle_scaled_edges, the public face of this
 * frame) and len[k] its length, both scaled by 2^-e; area2
 * twice the area scaled by 2^-2e; k the shortest edge; sin_min the sine of the
 * smallest angle (at corner k), scale-free. */
typedef struct lh__g_tri {
    double d[3][2], len[3], area2, sin_min;
    int e, k;
} lh__g_tri;
void lh__g_measure(const double *a, const double *b, const double *c, lh__g_tri *t);
/* Whether the area of t is above bound (> 0). */
int lh__g_area_above(const lh__g_tri *t, double bound);
/* The cosine of the angle at o between o->x and o->y (each vector scaled alone);
 * 1 when either is zero. */
double lh__g_cos(const double *o, const double *x, const double *y);
/* p = a + f (b - a), the difference scaled and rounded once. */
void lh__g_along(const double *a, const double *b, double f, double *p);

#endif
