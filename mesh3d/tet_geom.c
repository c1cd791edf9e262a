/*
 * tet_geom.c — tetrahedron and triangle measures in floating point (tet_geom.h): the
 * measures of Shewchuk's Delaunay refinement ("Tetrahedral mesh generation by Delaunay
 * refinement", SoCG 1998): circumradius over shortest edge, and the dihedral angles.
 */
#include "tet_geom.h"

#include <math.h>

void lh__t3_cross(const double *u, const double *v, double *w)
{
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

double lh__t3_dot(const double *u, const double *v)
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

/* The power of two e with every |p[i] - p[0]| / 2^e below 2 (at least one at 1 or
 * more unless all are equal): differences taken halved, so none overflows. */
static int frame_exp(const double *const *p, int n)
{
    double big = 0;
    for (int i = 1; i < n; i++)
        for (int k = 0; k < 3; k++) big = fmax(big, fabs(p[i][k] / 2 - p[0][k] / 2));
    int e;
    frexp(big, &e);
    return big > 0 ? e + 1 : 0;
}

/* (q - p) / 2^e, exact but for the subtraction's rounding: the halved difference
 * times 2^(1-e), a power of two (subnormal only when e is 1024 or 1025, and the
 * product is then still near 1, so exact). */
static void rel(const double *q, const double *p, int e, double *out)
{
    const double f = ldexp(1, 1 - e);
    for (int k = 0; k < 3; k++) out[k] = (q[k] / 2 - p[k] / 2) * f;
}

int lh__t3_frame(const double *const *p, int n, double (*q)[3])
{
    const int e = frame_exp(p, n);
    for (int i = 0; i < n; i++) rel(p[i], p[0], e, q[i]);
    return e;
}

static int before(const double *x, const double *y)
{
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

void lh__t3_sort_corners(const double **p, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && before(p[j], p[j - 1]); j--) {
            const double *x = p[j];
            p[j] = p[j - 1];
            p[j - 1] = x;
        }
}

/* y - x into d when every nonzero component's square and the sum of three squares are
 * normal doubles: then the figures computed on d equal, bit for bit, those computed in
 * the scaled frame (scaling by a power of two commutes with rounding there). */
static int direct(const double *x, const double *y, double d[3])
{
    for (int k = 0; k < 3; k++) {
        d[k] = y[k] - x[k];
        const double a = fabs(d[k]);
        if (!(a <= 0x1p+510) || (a != 0 && a < 0x1p-510)) return 0;
    }
    return 1;
}

double lh__t3_dist(const double *x, const double *y)
{
    double d[3];
    if (direct(x, y, d)) return sqrt(lh__t3_dot(d, d));
    const double *p[2] = {x, y};
    int e = frame_exp(p, 2);
    double v[3];
    rel(y, x, e, v);
    return ldexp(sqrt(lh__t3_dot(v, v)), e);
}

int lh__t3_in_diametral(const double *a, const double *b, const double *x)
{
    double da[3], db[3];
    if (direct(x, a, da) && direct(x, b, db)) return lh__t3_dot(da, db) < 0;
    const double *p[3] = {x, a, b};
    int e = frame_exp(p, 3);
    double u[3], v[3];
    rel(a, x, e, u), rel(b, x, e, v);
    return lh__t3_dot(u, v) < 0;
}

/* The dihedral angle at edge a b between the planes through c and d, as the point
 * (cos, sin) times a positive factor: atan2(dih[1], dih[0]) is the angle. */
static void dihedral(const double *a, const double *b, const double *c, const double *d,
                     double dih[2])
{
    double u[3], vc[3], vd[3], nc[3], nd[3], w[3];
    for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], vc[k] = c[k] - a[k], vd[k] = d[k] - a[k];
    lh__t3_cross(u, vc, nc), lh__t3_cross(u, vd, nd), lh__t3_cross(nc, nd, w);
    dih[0] = lh__t3_dot(nc, nd), dih[1] = sqrt(lh__t3_dot(w, w));
}

void lh__t3_tet_measure(const double *const *p, t3_tet_measure *m)
{
    static const int e[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    double q[4][3];
    const int s = lh__t3_frame(p, 4, q);
    double shortest = INFINITY, least[2] = {0, 0};
    for (int i = 0; i < 6; i++) { /* angles compare as their (cos, sin) points turn */
        double v[3], dih[2];
        for (int k = 0; k < 3; k++) v[k] = q[e[i][0]][k] - q[e[i][1]][k];
        shortest = fmin(shortest, sqrt(lh__t3_dot(v, v)));
        dihedral(q[e[i][0]], q[e[i][1]], q[e[i][2]], q[e[i][3]], dih);
        if (i == 0 || dih[0] * least[1] - dih[1] * least[0] > 0)
            least[0] = dih[0], least[1] = dih[1];
    }
    /* circumcentre of 0, q1, q2, q3: (|b|^2 c x d + |c|^2 d x b + |d|^2 b x c) / 2 b.(c x d) */
    double cd[3], db[3], bc[3], num[3];
    lh__t3_cross(q[2], q[3], cd), lh__t3_cross(q[3], q[1], db), lh__t3_cross(q[1], q[2], bc);
    for (int k = 0; k < 3; k++)
        num[k] = lh__t3_dot(q[1], q[1]) * cd[k] + lh__t3_dot(q[2], q[2]) * db[k] + lh__t3_dot(q[3], q[3]) * bc[k];
    const double vol6 = lh__t3_dot(q[1], cd);
    for (int k = 0; k < 3; k++) m->cc[k] = p[0][k] + ldexp(num[k] / (2 * vol6), s);
    const double r = sqrt(lh__t3_dot(num, num)) / fabs(2 * vol6);
    m->radius = ldexp(r, s);
    m->shortest = ldexp(shortest, s);
    m->ratio = vol6 != 0 ? r / shortest : INFINITY;
    m->volume_frac = fabs(vol6) / 6;
    m->scale_exp = s;
    m->min_dihedral = atan2(least[1], least[0]);
}

int lh__t3_volume_over(const t3_tet_measure *m, double v)
{
    return m->volume_frac > ldexp(v, -3 * m->scale_exp);
}

int lh__t3_tri_circumcentre(const double *a, const double *b, const double *c, double cc[3],
                            double *radius)
{
    const double *p[3] = {a, b, c};
    const int s = frame_exp(p, 3);
    double u[3], v[3], n[3], w[3], x[3];
    rel(b, a, s, u), rel(c, a, s, v);
    lh__t3_cross(u, v, n);
    const double nn = lh__t3_dot(n, n);
    if (!(nn > 0)) return 0;
    /* a + ((|u|^2 v - |v|^2 u) x n) / (2 |n|^2) */
    for (int k = 0; k < 3; k++) w[k] = lh__t3_dot(u, u) * v[k] - lh__t3_dot(v, v) * u[k];
    lh__t3_cross(w, n, x);
    for (int k = 0; k < 3; k++) x[k] /= 2 * nn;
    for (int k = 0; k < 3; k++) cc[k] = a[k] + ldexp(x[k], s);
    *radius = ldexp(sqrt(lh__t3_dot(x, x)), s);
    return 1;
}
