/*
 * measure.c — lh_tetmesh_measure: the quality figures of any tetrahedral mesh, those
 * TetGen's -V prints (volumes, edges, aspect ratio, face and dihedral angles with
 * TetGen's histogram bins; Si, TetGen manual 1.5, sec. 4.2.2) and the radius-edge
 * ratio of Shewchuk's Delaunay refinement. Floating point, each tetrahedron and
 * face measured in its own frame (tet_geom.h), so no square over- or underflows and
 * the figures are the same at every power-of-two scale. Figures for reports only.
 */
#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_sort.h"
#include "tet_geom.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

static const double RADIUS_EDGE[] = {0,     0.7, 0.8, 0.9, 1, 1.1, 1.2, 1.3,
                                     1.414, 1.5, 2,   3,   5, 10,  100};
static const double ASPECT[] = {0, 1.5, 2, 2.5, 3, 4, 6, 10, 15, 25, 50, 100};
static const double FACE_ANGLE[] = {0,  10,  20,  30,  40,  50,  60,  70,  80,
                                    90, 100, 110, 120, 130, 140, 150, 160, 170};
static const double DIHEDRAL[] = {0,  5,   10,  20,  30,  40,  50,  60,  70,
                                  80, 110, 120, 130, 140, 150, 160, 170, 175};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define DEGREES(x) ((x) * (180 / 3.14159265358979323846))

static void hist_init(lh_histogram *h, const double *lower, int bins)
{
    memset(h, 0, sizeof *h);
    h->bins = bins, h->lower = lower;
}

/* x into the last bin whose lower edge it reaches (NaN: the last bin). */
static void hist_add(lh_histogram *h, double x)
{
    int k = h->bins - 1;
    while (k > 0 && x < h->lower[k]) k--;
    h->count[k]++;
}

static double norm(const double *u)
{
    return sqrt(lh__t3_dot(u, u));
}

/* The angle between u and v, degrees. */
static double angle(const double *u, const double *v)
{
    double w[3];
    lh__t3_cross(u, v, w);
    return DEGREES(atan2(norm(w), lh__t3_dot(u, v)));
}

static void range(double x, double *lo, double *hi)
{
    *lo = fmin(*lo, x), *hi = fmax(*hi, x);
}

/* Tet p[0..3]'s figures into q: volume, edges, aspect, radius-edge, dihedrals. */
static void tet_figures(const double *const *p, lh_tetmesh_quality *q)
{
    static const int edge[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                   {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    double f[4][3];
    const int s = lh__t3_frame(p, 4, f);
    double lmin = INFINITY, lmax = 0, amax = 0;
    for (int i = 0; i < 6; i++) {
        const double *a = f[edge[i][0]], *b = f[edge[i][1]], *c = f[edge[i][2]], *d = f[edge[i][3]];
        double u[3], vc[3], vd[3], nc[3], nd[3];
        for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], vc[k] = c[k] - a[k], vd[k] = d[k] - a[k];
        lmin = fmin(lmin, norm(u)), lmax = fmax(lmax, norm(u));
        lh__t3_cross(u, vc, nc), lh__t3_cross(u, vd, nd);
        amax = fmax(amax, fmax(norm(nc), norm(nd))); /* twice the faces' areas */
        const double dih = angle(nc, nd);
        range(dih, &q->min_dihedral, &q->max_dihedral);
        hist_add(&q->dihedral, dih);
    }
    double cd[3], db[3], bc[3], num[3]; /* circumcentre as in tet_geom.c */
    lh__t3_cross(f[2], f[3], cd), lh__t3_cross(f[3], f[1], db), lh__t3_cross(f[1], f[2], bc);
    for (int k = 0; k < 3; k++)
        num[k] = lh__t3_dot(f[1], f[1]) * cd[k] + lh__t3_dot(f[2], f[2]) * db[k] +
                 lh__t3_dot(f[3], f[3]) * bc[k];
    const double vol6 = fabs(lh__t3_dot(f[1], cd));
    const double ratio = vol6 > 0 ? norm(num) / (2 * vol6) / lmin : INFINITY;
    const double aspect = vol6 > 0 ? lmax * amax / vol6 : INFINITY; /* lmax / (3V / A) */
    range(ldexp(vol6 / 6, 3 * s), &q->min_volume, &q->max_volume);
    range(ldexp(lmin, s), &q->min_edge, &q->max_edge);
    range(ldexp(lmax, s), &q->min_edge, &q->max_edge);
    range(aspect, &q->min_aspect, &q->max_aspect);
    range(ratio, &q->min_radius_edge, &q->max_radius_edge);
    hist_add(&q->aspect, aspect);
    hist_add(&q->radius_edge, ratio);
}

static void face_figures(const double *const *p, lh_tetmesh_quality *q)
{
    double f[3][3];
    lh__t3_frame(p, 3, f);
    for (int i = 0; i < 3; i++) {
        double u[3], v[3];
        const double *a = f[i], *b = f[(i + 1) % 3], *c = f[(i + 2) % 3];
        for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
        const double x = angle(u, v);
        range(x, &q->min_face_angle, &q->max_face_angle);
        hist_add(&q->face_angle, x);
    }
}

typedef struct face_key {
    lh_index v[3]; /* ascending */
} face_key;

/* Every face of the mesh once: the tets' faces sorted (least significant corner
 * first) and measured where they differ from the one before. */
static lh_status faces_measure(const lh_allocator *al, size_t n, const double *xyz, size_t nt,
                               const lh_index *tets, lh_tetmesh_quality *q)
{
    face_key *k = lh__alloc(al, (nt ? 4 * nt : 1) * sizeof *k);
    if (!k) return LH_ERR_NOMEM;
    for (size_t t = 0; t < nt; t++)
        for (int o = 0; o < 4; o++) {
            face_key *e = k + 4 * t + o;
            for (int i = 0, j = 0; i < 4; i++)
                if (i != o) {
                    int m = j++;
                    for (; m > 0 && e->v[m - 1] > tets[4 * t + i]; m--) e->v[m] = e->v[m - 1];
                    e->v[m] = tets[4 * t + i];
                }
        }
    lh_status st = LH_OK;
    for (int c = 2; c >= 0 && st == LH_OK; c--)
        st = lh__sort_by_index(al, k, 4 * nt, sizeof *k,
                               offsetof(face_key, v) + (size_t)c * sizeof(lh_index), n);
    for (size_t i = 0; st == LH_OK && i < 4 * nt; i++) {
        if (i && !memcmp(k[i].v, k[i - 1].v, sizeof k[i].v)) continue;
        const double *p[3];
        for (int j = 0; j < 3; j++) p[j] = xyz + 3 * (size_t)k[i].v[j];
        face_figures(p, q);
        q->faces++;
    }
    lh__free(al, k);
    return st;
}

static lh_status measure_args(size_t n, const double *xyz, size_t nt, const lh_index *tets,
                              lh_error *err)
{
    if ((n && !xyz) || (nt && !tets))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "%s is NULL with a count above 0",
                             n && !xyz ? "xyz" : "tets");
    if (n > SIZE_MAX / 3 / sizeof(double) || n > (size_t)LH_INDEX_MAX || nt > SIZE_MAX / 64)
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                             "a count is larger than the address space holds");
    for (size_t i = 0; i < 3 * n; i++)
        if (xyz[i] - xyz[i] != 0)
            return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                 "point %zu has a NaN or infinite coordinate", i / 3);
    for (size_t i = 0; i < 4 * nt; i++)
        if (tets[i] < 0 || (size_t)tets[i] >= n)
            return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                 "tetrahedron %zu has point %lld, not one of the %zu points", i / 4,
                                 (long long)tets[i], n);
    return LH_OK;
}

lh_status lh_tetmesh_measure(size_t n, const double *xyz, size_t tet_count, const lh_index *tets,
                             const lh_allocator *alloc, lh_tetmesh_quality *q, lh_error *err)
{
    lh__error_clear(err);
    if (!q) return lh__error_done(err, lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "q is NULL"));
    memset(q, 0, sizeof *q);
    hist_init(&q->radius_edge, RADIUS_EDGE, COUNT(RADIUS_EDGE));
    hist_init(&q->aspect, ASPECT, COUNT(ASPECT));
    hist_init(&q->face_angle, FACE_ANGLE, COUNT(FACE_ANGLE));
    hist_init(&q->dihedral, DIHEDRAL, COUNT(DIHEDRAL));
    lh_allocator al;
    if (!lh__allocator_init(&al, alloc))
        return lh__error_done(
            err, lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "the allocator lacks alloc or free"));
    lh_status st = measure_args(n, xyz, tet_count, tets, err);
    if (st != LH_OK || !tet_count) return lh__error_done(err, st);
    q->min_volume = q->min_edge = q->min_aspect = q->min_face_angle = INFINITY;
    q->min_dihedral = q->min_radius_edge = INFINITY;
    for (size_t t = 0; t < tet_count; t++) {
        const double *p[4];
        for (int j = 0; j < 4; j++) p[j] = xyz + 3 * (size_t)tets[4 * t + j];
        tet_figures(p, q);
    }
    q->tets = tet_count;
    st = faces_measure(&al, n, xyz, tet_count, tets, q);
    if (st == LH_ERR_NOMEM) lh__error_say(err, st, "out of memory");
    return lh__error_done(err, st);
}
