/*
 * quality.c — the mesh's quality figures in lh_tetmesh_stats: the smallest dihedral
 * angle and the largest radius-edge ratio (circumradius over shortest edge), the
 * measures of Shewchuk's Delaunay refinement ("Tetrahedral mesh generation by
 * Delaunay refinement", SoCG 1998). Floating point: figures for reports, not
 * decisions. Each tet is translated to its first point and scaled by its longest
 * edge first, so no square overflows or underflows at any scale.
 */
#include "t3.h"

#include <math.h>

static void sub(const double *p, const double *q, double s, double *out)
{
    for (int k = 0; k < 3; k++) out[k] = (p[k] - q[k]) * s;
}

static void cross(const double *u, const double *v, double *w)
{
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

static double dot(const double *u, const double *v)
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

/* The dihedral angle at edge a b between the planes through c and d, as the point
 * (cos, sin) times a positive factor: atan2(dih[1], dih[0]) is the angle. */
static void dihedral(const double *a, const double *b, const double *c, const double *d,
                     double dih[2])
{
    double u[3], vc[3], vd[3], nc[3], nd[3], w[3];
    sub(b, a, 1, u), sub(c, a, 1, vc), sub(d, a, 1, vd);
    cross(u, vc, nc), cross(u, vd, nd), cross(nc, nd, w);
    dih[0] = dot(nc, nd), dih[1] = sqrt(dot(w, w));
}

/* The tet's smallest dihedral angle (radians) and radius-edge ratio. Angles in
 * [0, pi] compare as their (cos, sin) points turn: x before y when cross(x, y) > 0,
 * so atan2 runs once. */
static void tet_quality(const double *const *p, double *min_dih, double *ratio)
{
    static const int e[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    double longest = 0, q[4][3];
    for (int i = 0; i < 6; i++) {
        double v[3];
        sub(p[e[i][0]], p[e[i][1]], 1, v);
        longest = fmax(longest, sqrt(dot(v, v)));
    }
    for (int i = 0; i < 4; i++) sub(p[i], p[0], 1 / longest, q[i]);
    double shortest = INFINITY, least[2] = {0, 0};
    for (int i = 0; i < 6; i++) {
        double v[3], dih[2];
        sub(q[e[i][0]], q[e[i][1]], 1, v);
        shortest = fmin(shortest, sqrt(dot(v, v)));
        dihedral(q[e[i][0]], q[e[i][1]], q[e[i][2]], q[e[i][3]], dih);
        if (i == 0 || dih[0] * least[1] - dih[1] * least[0] > 0)
            least[0] = dih[0], least[1] = dih[1];
    }
    *min_dih = atan2(least[1], least[0]);
    /* circumcentre of 0, q1, q2, q3: (|b|^2 c x d + |c|^2 d x b + |d|^2 b x c) / 2 b.(c x d) */
    double cd[3], db[3], bc[3], num[3];
    cross(q[2], q[3], cd), cross(q[3], q[1], db), cross(q[1], q[2], bc);
    for (int k = 0; k < 3; k++)
        num[k] = dot(q[1], q[1]) * cd[k] + dot(q[2], q[2]) * db[k] + dot(q[3], q[3]) * bc[k];
    double vol6 = dot(q[1], cd);
    *ratio = sqrt(dot(num, num)) / fabs(2 * vol6) / shortest;
}

void lh__tetmesh_quality(lh_tetmesh *m)
{
    double min_dih = INFINITY, max_ratio = 0;
    for (size_t t = 0; t < m->tet_count; t++) {
        const double *p[4];
        for (int j = 0; j < 4; j++) p[j] = m->xyz + 3 * (size_t)m->tets[4 * t + j];
        double d, r;
        tet_quality(p, &d, &r);
        min_dih = fmin(min_dih, d);
        max_ratio = fmax(max_ratio, r);
    }
    m->stats.min_dihedral = m->tet_count ? min_dih * (180 / 3.14159265358979323846) : 0;
    m->stats.max_radius_edge = max_ratio;
}
