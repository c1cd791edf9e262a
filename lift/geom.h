/*
 * geom.h — floating-point constructions (never decisions: those are exact
 * predicates): linear solves, circumcentres. Used for barycentric coordinates,
 * Voronoi vertices and interpolation weights.
 */
#ifndef LH_GEOM_H
#define LH_GEOM_H

/* Solves the m x m system a x = b (row-major; a and b destroyed, x returned in b)
 * by Gaussian elimination with partial pivoting; returns 0 when a pivot is exactly
 * zero. */
int lh__solve(double *a, double *b, int m);

/* The centre c (d doubles) of the sphere through the k+1 points p[0..k] of R^d,
 * 1 <= k <= d, within their affine hull: c = p0 + sum_i x_i (p_i - p0) where
 * 2 (p_i - p0).(c - p0) = |p_i - p0|^2. For k = d that is the d x d system in
 * c - p0 directly (no Gram matrix, whose condition is the square). Returns 0 for
 * affinely dependent points (c is then filled with NaN). */
int lh__circumcenter(int d, int k, const double *const *p, double *c);
/* The same centre as c 2^exp (*exp from lh__scale_exp): c is finite where the
 * centre's coordinates pass DBL_MAX (lh__circumcenter's are then +-inf). */
int lh__circumcenter_exp(int d, int k, const double *const *p, double *c, int *exp);

/* The exponent e with every |p[i][j]| < 2^e (frexp of the largest; 0 when all are
 * 0): the points scaled by 2^-e (ldexp, exact but for underflow far below the
 * largest) have magnitudes below 1, so constructions neither overflow nor lose
 * subnormal digits; results scale back by 2^e. */
int lh__scale_exp(const double *const *p, int m, int d, const double *q);

#endif
