/* svg3.c — the view of svg3.h: parallel projection along a fixed oblique direction,
 * far-to-near order, shading. SVG 1.1: 8.3 (path data). */
#include "svg3.h"

#include "svg.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static void project(const lh_cli_camera *c, const double *p, double *u, double *v, double *depth)
{
    double q[3];
    for (int j = 0; j < 3; j++) q[j] = ldexp(p[j], -c->shift);
    *u = q[0] * c->right[0] + q[1] * c->right[1] + q[2] * c->right[2];
    *v = q[0] * c->up[0] + q[1] * c->up[1] + q[2] * c->up[2];
    if (depth) *depth = q[0] * c->dir[0] + q[1] * c->dir[1] + q[2] * c->dir[2];
}

lh_cli_camera lh_cli_camera_aim(const double *xyz, size_t np, const lh_index *f, size_t nf)
{
    lh_cli_camera c;
    const double az = 35 * PI / 180, el = 25 * PI / 180;
    /* looking from (cos el cos az, cos el sin az, sin el) * far towards the origin */
    const double eye[3] = {cos(el) * cos(az), cos(el) * sin(az), sin(el)};
    for (int j = 0; j < 3; j++) c.dir[j] = -eye[j];
    c.right[0] = -sin(az), c.right[1] = cos(az), c.right[2] = 0;
    c.up[0] = -sin(el) * cos(az), c.up[1] = -sin(el) * sin(az), c.up[2] = cos(el);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < (nf ? 3 * nf : np); i++) {
        const double *p = xyz + 3 * (size_t)(nf ? f[i] : (lh_index)i);
        for (int j = 0; j < 3; j++) lo[j] = fmin(lo[j], p[j]), hi[j] = fmax(hi[j], p[j]);
    }
    if (!(lo[0] <= hi[0])) lo[0] = lo[1] = lo[2] = 0, hi[0] = hi[1] = hi[2] = 1;
    const double lo2[2] = {lo[2], lo[2]}, hi2[2] = {hi[2], hi[2]};
    const int s1 = lh_cli_svg_shift(lo, hi), s2 = lh_cli_svg_shift(lo2, hi2);
    c.shift = s1 > s2 ? s1 : s2;
    double ulo = INFINITY, uhi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
    for (size_t i = 0; i < (nf ? 3 * nf : np); i++) {
        double u, v;
        project(&c, xyz + 3 * (size_t)(nf ? f[i] : (lh_index)i), &u, &v, NULL);
        ulo = fmin(ulo, u), uhi = fmax(uhi, u), vlo = fmin(vlo, v), vhi = fmax(vhi, v);
    }
    if (!(ulo <= uhi && vlo <= vhi)) ulo = vlo = 0, uhi = vhi = 1;
    double side = fmax(uhi - ulo, vhi - vlo);
    if (!(side > 0) || !isfinite(LH_SVG3_CANVAS / side)) side = 1;
    const double margin = 0.05 * side;
    c.scale = LH_SVG3_CANVAS / side;
    c.u0 = ulo - margin;
    c.v1 = vhi + margin;
    c.width = (uhi - ulo + 2 * margin) * c.scale;
    c.height = (vhi - vlo + 2 * margin) * c.scale;
    return c;
}

double lh_cli_camera_depth(const lh_cli_camera *c, const double *p)
{
    double u, v, d;
    project(c, p, &u, &v, &d);
    return d;
}

/* A triangle to paint: its index and its depth along the view (larger: farther). */
typedef struct face_depth {
    double depth;
    size_t i;
} face_depth;

static int farther_first(const void *pa, const void *pb)
{
    const face_depth *a = pa, *b = pb;
    if (a->depth != b->depth) return a->depth > b->depth ? -1 : 1;
    return a->i < b->i ? -1 : a->i > b->i;
}

size_t *lh_cli_camera_order(const lh_cli_camera *c, const double *xyz, const lh_index *tri,
                            size_t count)
{
    face_depth *fd = malloc((count ? count : 1) * sizeof *fd);
    size_t *order = malloc((count ? count : 1) * sizeof *order);
    if (!fd || !order) {
        free(fd), free(order);
        return NULL;
    }
    for (size_t i = 0; i < count; i++) {
        double sum = 0;
        for (int k = 0; k < 3; k++) sum += lh_cli_camera_depth(c, xyz + 3 * (size_t)tri[3 * i + k]);
        fd[i].depth = sum, fd[i].i = i;
    }
    qsort(fd, count, sizeof *fd, farther_first);
    for (size_t i = 0; i < count; i++) order[i] = fd[i].i;
    free(fd);
    return order;
}

double lh_cli_camera_shade(const lh_cli_camera *c, const double *xyz, const lh_index *f)
{
    double p[3][3], n[3];
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++) p[k][j] = ldexp(xyz[3 * (size_t)f[k] + j], -c->shift);
    const double a[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double b[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    n[0] = a[1] * b[2] - a[2] * b[1], n[1] = a[2] * b[0] - a[0] * b[2],
    n[2] = a[0] * b[1] - a[1] * b[0];
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double light[3] = {0.37, 0.56, 0.74}; /* unit: from upper right, front */
    const double cosine =
        len > 0 ? fabs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / len : 0;
    return 0.55 + 0.45 * (isfinite(cosine) ? fmin(cosine, 1) : 0);
}

void lh_cli_camera_path(FILE *f, const lh_cli_camera *c, const double *xyz, const lh_index *t)
{
    fputs("<path d=\"", f);
    for (int k = 0; k < 3; k++) {
        double u, v;
        project(c, xyz + 3 * (size_t)t[k], &u, &v, NULL);
        fprintf(f, "%s%lld %lld", k ? "L" : "M", llround((u - c->u0) * c->scale),
                llround((c->v1 - v) * c->scale));
    }
    fputs("Z\"", f);
}
