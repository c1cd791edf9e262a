/*
 * mesh_svg3.c — the SVG picture of a tetrahedral mesh's boundary (tetgen_io.h): every
 * subface filled with its facet marker's colour, shaded by the angle between its
 * normal and a fixed light, seen along a fixed oblique direction (azimuth 35 degrees,
 * elevation 25) in parallel projection. Hidden surfaces by the painter's algorithm:
 * the faces are drawn far to near by their centroids' depth, which is exact for a
 * convex surface and a picture (not a proof) otherwise.
 * Canvas as svg.c's and mesh_svg.c's: the projection's bounding box plus a 5% margin,
 * its longer side 10^4 units, y up, a legend band above, integer coordinates,
 * computed on the points multiplied by a power of two (lh_cli_svg_shift) so that no
 * coordinate overflows. SVG 1.1: 8.3 (path data), 11.3 (fill).
 */
#include "svg.h"
#include "tetgen_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define CANVAS 10000.0
#define LEGEND 900.0
#define MIN_WIDTH 7000.0
enum { PALETTE = 12 };

/* A face to paint: its index and its depth along the view (larger: farther). */
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

typedef struct camera {
    int shift;              /* points drawn multiplied by 2^-shift               */
    double right[3], up[3], dir[3];
    double u0, v1, scale, width, height;
} camera;

static void project(const camera *c, const double *p, double *u, double *v, double *depth)
{
    double q[3];
    for (int j = 0; j < 3; j++) q[j] = ldexp(p[j], -c->shift);
    *u = q[0] * c->right[0] + q[1] * c->right[1] + q[2] * c->right[2];
    *v = q[0] * c->up[0] + q[1] * c->up[1] + q[2] * c->up[2];
    if (depth) *depth = q[0] * c->dir[0] + q[1] * c->dir[1] + q[2] * c->dir[2];
}

/* The view and the canvas box of the faces' points (all points when no face). */
static camera aim(const double *xyz, size_t np, const lh_index *f, size_t nf)
{
    camera c;
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
    if (!(side > 0) || !isfinite(CANVAS / side)) side = 1;
    const double margin = 0.05 * side;
    c.scale = CANVAS / side;
    c.u0 = ulo - margin;
    c.v1 = vhi + margin;
    c.width = (uhi - ulo + 2 * margin) * c.scale;
    c.height = (vhi - vlo + 2 * margin) * c.scale;
    return c;
}

/* Marker m's colour: a palette of distinct light hues, darkened by the shade. */
static void colour(lh_index m, double shade, char out[8])
{
    static const int rgb[PALETTE][3] = {{141, 211, 199}, {255, 255, 179}, {190, 186, 218}, {251, 128, 114},
                                        {128, 177, 211}, {253, 180, 98},  {179, 222, 105}, {252, 205, 229},
                                        {217, 217, 217}, {188, 128, 189}, {204, 235, 197}, {255, 237, 111}};
    const size_t k = (size_t)(m < 0 ? -(m + 1) : m) % PALETTE;
    snprintf(out, 8, "#%02x%02x%02x", (int)lround(rgb[k][0] * shade), (int)lround(rgb[k][1] * shade),
             (int)lround(rgb[k][2] * shade));
}

/* The light's cosine with face f's normal, from 0.55 (edge on) to 1 (facing it). */
static double shading(const double *xyz, const lh_index *f, int shift)
{
    double p[3][3], n[3];
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++) p[k][j] = ldexp(xyz[3 * (size_t)f[k] + j], -shift);
    const double a[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double b[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    n[0] = a[1] * b[2] - a[2] * b[1], n[1] = a[2] * b[0] - a[0] * b[2], n[2] = a[0] * b[1] - a[1] * b[0];
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double light[3] = {0.37, 0.56, 0.74}; /* unit: from upper right, front */
    const double cosine = len > 0 ? fabs(n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / len : 0;
    return 0.55 + 0.45 * (isfinite(cosine) ? fmin(cosine, 1) : 0);
}

static void put(FILE *f, const camera *c, const double *p, const char *cmd)
{
    double u, v;
    project(c, p, &u, &v, NULL);
    fprintf(f, "%s%lld %lld", cmd, llround((u - c->u0) * c->scale), llround((c->v1 - v) * c->scale));
}


/* The title with the counts, and a swatch per marker (the first PALETTE). */
static void legend(FILE *f, const lh_tetmesh *m, const lh_index *mk, size_t nf, const char *title, double width)
{
    const double fs = 200, x0 = 0.02 * CANVAS, row = 300;
    char counts[160];
    snprintf(counts, sizeof counts, ": %zu points, %zu tetrahedra, %zu boundary faces", lh_tetmesh_point_count(m),
             lh_tetmesh_tet_count(m), nf);
    /* a line longer than the picture (0.62 em a character, sans-serif) gets a smaller font */
    const double room = width - 2 * x0, wide = 0.62 * fs * (double)(strlen(title) + strlen(counts));
    fprintf(f, "<g font-family=\"sans-serif\" font-size=\"%g\" fill=\"#333333\">\n<text x=\"%g\" y=\"%g\"", fs, x0,
            -LEGEND + row);
    if (wide > room) fprintf(f, " font-size=\"%.0f\"", fs * room / wide);
    fputc('>', f);
    lh_cli_svg_escaped(f, title);
    fprintf(f, "%s</text>\n", counts);
    fprintf(f, "<text x=\"%g\" y=\"%g\">by facet marker</text>\n", x0, -LEGEND + 2 * row);
    lh_index seen[PALETTE];
    int n = 0;
    for (size_t i = 0; i < nf && n < PALETTE; i++) {
        int dup = 0;
        for (int j = 0; j < n; j++) dup |= seen[j] == mk[i];
        if (!dup) seen[n++] = mk[i];
    }
    for (int i = 1; i < n; i++) /* ascending */
        for (int j = i; j > 0 && seen[j - 1] > seen[j]; j--) {
            const lh_index t = seen[j];
            seen[j] = seen[j - 1];
            seen[j - 1] = t;
        }
    for (int j = 0; j < n; j++) {
        char c[8];
        colour(seen[j], 1, c);
        const double x = x0 + 0.17 * CANVAS + j * 0.065 * CANVAS;
        fprintf(f, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"%s\" stroke=\"#333333\"/>", x,
                -LEGEND + 2 * row - 0.7 * fs, 0.7 * fs, 0.7 * fs, c);
        fprintf(f, "<text x=\"%g\" y=\"%g\">%lld</text>\n", x + fs, -LEGEND + 2 * row, (long long)seen[j]);
    }
    fputs("</g>\n", f);
}

int lh_cli_tetmesh_svg(FILE *f, const lh_tetmesh *m, const char *title)
{
    const size_t nf = lh_tetmesh_face_count(m), np = lh_tetmesh_point_count(m);
    const lh_index *fc = lh_tetmesh_faces(m), *mk = lh_tetmesh_face_markers(m);
    const double *xyz = lh_tetmesh_points(m);
    const camera c = aim(xyz, np, fc, nf);
    face_depth *order = malloc((nf ? nf : 1) * sizeof *order);
    if (!order) return -1;
    for (size_t i = 0; i < nf; i++) {
        double sum = 0;
        for (int k = 0; k < 3; k++) {
            double u, v, d;
            project(&c, xyz + 3 * (size_t)fc[3 * i + k], &u, &v, &d);
            sum += d;
        }
        order[i].depth = sum, order[i].i = i;
    }
    qsort(order, nf, sizeof *order, farther_first);
    const double W = ceil(fmax(c.width, MIN_WIDTH)), H = ceil(c.height);
    const double line = fmin(fmax(0.15 * sqrt(c.width * c.height / (double)(nf ? nf : 1)), 0.5), 8);
    lh_cli_svg_begin(f, W, H, LEGEND, title);
    legend(f, m, mk, nf, title, W);
    fprintf(f, "<g id=\"faces\" stroke=\"#303030\" stroke-width=\"%.3g\" stroke-linejoin=\"round\">\n", line);
    for (size_t j = 0; j < nf; j++) {
        const size_t i = order[j].i;
        char col[8];
        colour(mk[i], shading(xyz, fc + 3 * i, c.shift), col);
        fputs("<path d=\"", f);
        for (int k = 0; k < 3; k++) put(f, &c, xyz + 3 * (size_t)fc[3 * i + k], k ? "L" : "M");
        fprintf(f, "Z\" fill=\"%s\"/>\n", col);
    }
    fputs("</g>\n</svg>\n", f);
    free(order);
    return fflush(f) != 0 || ferror(f) ? -1 : 0;
}
