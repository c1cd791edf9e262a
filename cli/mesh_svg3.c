/*
 * mesh_svg3.c — the SVG picture of a tetrahedral mesh's boundary (tetgen_io.h): every
 * subface filled with its facet marker's colour, shaded by the angle between its
 * normal and a fixed light, in svg3.h's view, a legend band above. SVG 1.1: 11.3
 * (fill).
 */
#include "svg.h"
#include "svg3.h"
#include "tetgen_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CANVAS LH_SVG3_CANVAS
#define LEGEND 900.0
#define MIN_WIDTH 7000.0
enum { PALETTE = 12 };

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
    const lh_cli_camera c = lh_cli_camera_aim(xyz, np, fc, nf);
    size_t *order = lh_cli_camera_order(&c, xyz, fc, nf);
    if (!order) return -1;
    const double W = ceil(fmax(c.width, MIN_WIDTH)), H = ceil(c.height);
    const double line = fmin(fmax(0.15 * sqrt(c.width * c.height / (double)(nf ? nf : 1)), 0.5), 8);
    lh_cli_svg_begin(f, W, H, LEGEND, title);
    legend(f, m, mk, nf, title, W);
    fprintf(f, "<g id=\"faces\" stroke=\"#303030\" stroke-width=\"%.3g\" stroke-linejoin=\"round\">\n", line);
    for (size_t j = 0; j < nf; j++) {
        const size_t i = order[j];
        char col[8];
        colour(mk[i], lh_cli_camera_shade(&c, xyz, fc + 3 * i), col);
        lh_cli_camera_path(f, &c, xyz, fc + 3 * i);
        fprintf(f, " fill=\"%s\"/>\n", col);
    }
    fputs("</g>\n</svg>\n", f);
    free(order);
    return fflush(f) != 0 || ferror(f) ? -1 : 0;
}
