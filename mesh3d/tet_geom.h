/*
 * tet_geom.h — floating-point measures of tetrahedra and triangles: quality figures
 * and where refinement puts its points. They steer choices only; validity is the
 * exact predicates' (every insertion is checked exactly). Each shape is translated
 * to its first point and scaled by a power of two first, so no square over- or
 * underflows and the figures are the same at every power-of-two scale.
 */
#ifndef LH_TET_GEOM_H
#define LH_TET_GEOM_H

typedef struct t3_tet_measure {
    double cc[3];       /* circumcentre                                             */
    double radius;      /* circumradius                                             */
    double shortest;    /* shortest edge                                            */
    double ratio;       /* radius / shortest: the radius-edge ratio                 */
    double volume_frac; /* volume = volume_frac * 2^(3 scale_exp), exact scaling    */
    int scale_exp;
    double min_dihedral; /* radians                                                  */
} t3_tet_measure;

/* The measures of tet p[0..3] (any orientation; a flat one has ratio infinity). */
void lh__t3_tet_measure(const double *const *p, t3_tet_measure *m);
/* Whether the tet's volume exceeds v (> 0), compared without overflow. */
int lh__t3_volume_over(const t3_tet_measure *m, double v);
/* The circumcentre of triangle a b c in its plane and its radius; 0 when the
 * triangle is flat in floating point. */
int lh__t3_tri_circumcentre(const double *a, const double *b, const double *c, double cc[3],
                            double *radius);
/* Whether x lies inside the diametral sphere of segment a b (sees it under more than
 * 90 degrees). */
int lh__t3_in_diametral(const double *a, const double *b, const double *x);
/* w = u x v; u . v (plain doubles: callers scale into a frame first). */
void lh__t3_cross(const double *u, const double *v, double *w);
double lh__t3_dot(const double *u, const double *v);
/* |x - y|, without overflow. */
double lh__t3_dist(const double *x, const double *y);
/* The points p[0..n) (n <= 4) in a frame at p[0] scaled by 2^-e so that no square
 * over- or underflows: q[i] = (p[i] - p[0]) / 2^e, each below 2 in every coordinate;
 * returns e. */
int lh__t3_frame(const double *const *p, int n, double (*q)[3]);
/* Points p[0..n) sorted in coordinate order (lexicographic), so that figures measured
 * on them do not depend on the points' numbering. */
void lh__t3_sort_corners(const double **p, int n);

#endif
