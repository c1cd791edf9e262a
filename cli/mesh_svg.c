/*
 * mesh_svg.c — the SVG picture of a 2D mesh (pslg_io.h): every triangle filled by its
 * smallest angle on a colour ramp (red below the angle bound), the edges thin, the
 * subsegments (the input segments, split) thick, the triangles left bad outlined red.
 *
 * The canvas is svg.c's (the Delaunay and Voronoi pictures): the mesh's bounding box
 * plus a 5% margin, its longer side 10^4 units, y flipped, a legend band above, every
 * coordinate an integer, computed on the points multiplied by a power of two
 * (lh_cli_svg_shift: no overflow near +-DBL_MAX, nothing lost near 1e-300); triangles
 * of one colour share a few <path> elements.
 * SVG 1.1: 8.3 (path data), 11.3 (fill).
 */
#include "pslg_io.h"
#include "svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CANVAS 10000.0 /* the box's longer side in canvas units */
#define LEGEND 1250.0  /* the legend band above it               */
#define MIN_WIDTH 7000.0 /* the picture's least width, for the legend */
enum { PER_PATH = 2048, BINS = 12 }; /* subpaths per <path>; ramp bins of 5 degrees */

typedef struct view {
    int shift; /* the points are drawn multiplied by 2^-shift (lh_cli_svg_shift) */
    double x0, y1, scale, width, height, line;
} view;

/* The box of the points in triangles (all points when there is none). */
static view fit(const lh_trimesh *m)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m);
    const size_t nt = lh_trimesh_triangle_count(m), np = lh_trimesh_point_count(m);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < (nt ? 3 * nt : np); i++) {
        const double *p = xy + 2 * (size_t)(nt ? t[i] : (lh_index)i);
        for (int j = 0; j < 2; j++) lo[j] = fmin(lo[j], p[j]), hi[j] = fmax(hi[j], p[j]);
    }
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1])) lo[0] = lo[1] = 0, hi[0] = hi[1] = 1;
    view v;
    v.shift = lh_cli_svg_shift(lo, hi);
    for (int j = 0; j < 2; j++) lo[j] = ldexp(lo[j], -v.shift), hi[j] = ldexp(hi[j], -v.shift);
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(side > 0) || !isfinite(CANVAS / side)) side = 1;
    const double margin = 0.05 * side;
    v.scale = CANVAS / side;
    v.x0 = lo[0] - margin;
    v.y1 = hi[1] + margin;
    v.width = (hi[0] - lo[0] + 2 * margin) * v.scale;
    v.height = (hi[1] - lo[1] + 2 * margin) * v.scale;
    /* thin enough for the mean edge of nt triangles */
    const double spacing = sqrt(v.width * v.height / (double)(nt ? nt : 1));
    v.line = fmin(fmax(0.03 * spacing, 0.5), 12);
    return v;
}

static void put(FILE *f, const view *v, const double *p, const char *cmd)
{
    const double x = ldexp(p[0], -v->shift), y = ldexp(p[1], -v->shift);
    fprintf(f, "%s%lld %lld", cmd, llround((x - v->x0) * v->scale), llround((v->y1 - y) * v->scale));
}

/* Subpaths in <path> elements of PER_PATH each. */
static void next(FILE *f, size_t *count)
{
    if (*count % PER_PATH == 0) fputs(*count ? "\"/>\n<path d=\"" : "<path d=\"", f);
    ++*count;
}

static void close_paths(FILE *f, size_t count) { fputs(count ? "\"/>\n</g>\n" : "</g>\n", f); }

/* The smallest angle of triangle i in degrees, scale-free (lh_cli_triangle_shape). */
static double smallest_angle(const lh_trimesh *m, size_t i)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m) + 3 * i;
    const double *p[3] = {xy + 2 * (size_t)t[0], xy + 2 * (size_t)t[1], xy + 2 * (size_t)t[2]};
    double ang[3], ratio, len[3];
    lh_cli_triangle_shape(p, ang, &ratio, len);
    return fmin(ang[0], fmin(ang[1], ang[2]));
}

/* Ramp bin b (5 degrees each, 0..60) as a light colour: orange, pale yellow at 30,
 * light blue at 60. Bin BINS: below the bound, red. */
static void colour(int b, char *out)
{
    if (b == BINS) {
        strcpy(out, "#f26d5b");
        return;
    }
    static const double stop[3][3] = {{252, 176, 116}, {255, 246, 186}, {132, 186, 224}};
    const double x = (b + 0.5) / BINS * 2;
    const int s = x < 1 ? 0 : 1;
    const double u = x - s;
    int rgb[3];
    for (int j = 0; j < 3; j++) rgb[j] = (int)lround(stop[s][j] + u * (stop[s + 1][j] - stop[s][j]));
    snprintf(out, 8, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
}

void lh_cli_svg_escaped(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '&') fputs("&amp;", f);
        else if (*s == '<') fputs("&lt;", f);
        else if (*s == '>') fputs("&gt;", f);
        else if ((unsigned char)*s >= 0x20) putc(*s, f);
    }
}

void lh_cli_svg_begin(FILE *f, double width, double height, double legend, const char *title)
{
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 %g %.0f %.0f\" width=\"%.0f\" height=\"%.0f\">\n",
            -legend, width, height + legend, ceil(width / 10), ceil((height + legend) / 10));
    fputs("<title>", f);
    lh_cli_svg_escaped(f, title);
    fputs("</title>\n", f);
    fprintf(f, "<rect x=\"0\" y=\"%g\" width=\"%.0f\" height=\"%.0f\" fill=\"#ffffff\"/>\n", -legend, width,
            height + legend);
}

/* Three rows: the title and counts; the smallest angle and the bad triangles; the
 * ramp's swatches with their angles. */
static void legend(FILE *f, const lh_trimesh *m, double bound, const char *title)
{
    lh_trimesh_stats s;
    lh_trimesh_stats_get(m, &s);
    const double fs = 200, x0 = 0.02 * CANVAS, row = 300;
    fprintf(f, "<g font-family=\"sans-serif\" font-size=\"%g\" fill=\"#333333\">\n<text x=\"%g\" y=\"%g\">", fs, x0,
            -LEGEND + row);
    lh_cli_svg_escaped(f, title);
    fprintf(f, ": %zu points, %zu triangles</text>\n", lh_trimesh_point_count(m), s.triangles);
    fprintf(f, "<text x=\"%g\" y=\"%g\">smallest angle %.4g&#176;", x0, -LEGEND + 2 * row, s.min_angle);
    if (s.bad_triangles)
        fprintf(f, "; %zu triangle%s below the bounds <tspan fill=\"#d7191c\">(outlined red)</tspan>",
                s.bad_triangles, s.bad_triangles > 1 ? "s" : "");
    fputs("</text>\n", f);
    const double w = 0.035 * CANVAS, h = 0.6 * fs, y = -LEGEND + 2 * row + 0.8 * fs, sx = x0 + 0.15 * CANVAS;
    fprintf(f, "<text x=\"%g\" y=\"%g\">by angle</text>\n", x0, y + 0.85 * h);
    char c[8];
    for (int b = 0; b < BINS; b++) {
        colour(bound > 0 && 5.0 * (b + 1) <= bound ? BINS : b, c);
        fprintf(f, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"%s\"/>\n", sx + b * w, y, w, h, c);
    }
    for (int b = 0; b <= BINS; b += 3)
        fprintf(f, "<text x=\"%g\" y=\"%g\" font-size=\"%g\" text-anchor=\"middle\">%d&#176;</text>\n", sx + b * w,
                y + h + 0.8 * fs, 0.75 * fs, 5 * b);
    if (bound > 0) {
        colour(BINS, c);
        fprintf(f, "<text x=\"%g\" y=\"%g\"><tspan fill=\"%s\">&#9632;</tspan> below %.4g&#176;</text>\n",
                sx + (BINS + 0.4) * w, y + 0.85 * h, c, bound);
    }
    fputs("</g>\n", f);
}

int lh_cli_trimesh_svg(FILE *f, const lh_trimesh *m, double min_angle, const char *title)
{
    const size_t nt = lh_trimesh_triangle_count(m), ns = lh_trimesh_segment_count(m);
    const lh_index *t = lh_trimesh_triangles(m), *nb = lh_trimesh_neighbors(m), *sg = lh_trimesh_segments(m);
    const double *xy = lh_trimesh_points(m);
    unsigned char *bin = malloc(nt ? nt : 1);
    if (!bin) return -1;
    for (size_t i = 0; i < nt; i++) {
        const double a = smallest_angle(m, i);
        const int b = (int)(a / 5);
        bin[i] = (unsigned char)(min_angle > 0 && a < min_angle ? BINS : b < 0 ? 0 : b >= BINS ? BINS - 1 : b);
    }
    const view v = fit(m);
    const double W = ceil(fmax(v.width, MIN_WIDTH)), H = ceil(v.height);
    lh_cli_svg_begin(f, W, H, LEGEND, title);
    legend(f, m, min_angle, title);
    /* the triangles, one group per colour */
    for (int b = 0; b <= BINS; b++) {
        char c[8];
        colour(b, c);
        size_t count = 0;
        fprintf(f, "<g id=\"angle%s%d\" fill=\"%s\" stroke=\"none\">\n", b == BINS ? "-bad" : "-", b == BINS ? 0 : 5 * b, c);
        for (size_t i = 0; i < nt; i++) {
            if (bin[i] != b) continue;
            next(f, &count);
            for (int k = 0; k < 3; k++) put(f, &v, xy + 2 * (size_t)t[3 * i + k], k ? "L" : "M");
            fputc('Z', f);
        }
        close_paths(f, count);
    }
    /* every edge once: from the triangle with the larger index, or across the boundary */
    size_t count = 0;
    fprintf(f, "<g id=\"edges\" fill=\"none\" stroke=\"#505050\" stroke-width=\"%.3g\" stroke-linecap=\"round\">\n", v.line);
    for (size_t i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++) {
            if (nb[3 * i + k] >= 0 && (size_t)nb[3 * i + k] < i) continue;
            next(f, &count);
            put(f, &v, xy + 2 * (size_t)t[3 * i + (k + 1) % 3], "M");
            put(f, &v, xy + 2 * (size_t)t[3 * i + (k + 2) % 3], "L");
        }
    close_paths(f, count);
    count = 0;
    fprintf(f, "<g id=\"segments\" fill=\"none\" stroke=\"#141414\" stroke-width=\"%.3g\" stroke-linecap=\"round\">\n",
            3 * v.line);
    for (size_t i = 0; i < ns; i++) {
        next(f, &count);
        put(f, &v, xy + 2 * (size_t)sg[2 * i], "M");
        put(f, &v, xy + 2 * (size_t)sg[2 * i + 1], "L");
    }
    close_paths(f, count);
    lh_trimesh_stats s;
    lh_trimesh_stats_get(m, &s);
    const lh_index *bad = lh_trimesh_bad_triangles(m);
    count = 0;
    fprintf(f, "<g id=\"bad\" fill=\"none\" stroke=\"#d7191c\" stroke-width=\"%.3g\" stroke-linejoin=\"round\">\n",
            2 * v.line);
    for (size_t j = 0; j < s.bad_triangles; j++) {
        next(f, &count);
        for (int k = 0; k < 3; k++) put(f, &v, xy + 2 * (size_t)t[3 * (size_t)bad[j] + k], k ? "L" : "M");
        fputc('Z', f);
    }
    close_paths(f, count);
    fputs("</svg>\n", f);
    free(bin);
    return fflush(f) != 0 || ferror(f) ? -1 : 0;
}
