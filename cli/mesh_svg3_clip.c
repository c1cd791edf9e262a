/*
 * mesh_svg3_clip.c — the SVG picture of a tetrahedral mesh's quality (tetgen_io.h):
 * the mesh cut by the plane through the middle of its depth range, facing the view
 * (svg3.h's), the tetrahedra whose centroid lies behind it kept whole (a "crinkle"
 * cut: no tetrahedron is sliced), every face of the kept ones that no other kept one
 * shares painted in the colour of its tetrahedron's smallest dihedral angle, shaded;
 * below, the histogram of all the dihedral angles (lh_tetmesh_measure) in the same
 * colours. SVG 1.1: 8.3 (path data), 11.3 (fill), 10.4 (text).
 */
#include "svg.h"
#include "svg3.h"
#include "tetgen_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CANVAS LH_SVG3_CANVAS
#define LEGEND 900.0
#define BAND 3200.0 /* the histogram's band below the view */
#define MIN_WIDTH 7000.0

/* The classes of the smallest dihedral angle (degrees, lower edges) and their
 * colours, red (slivers) to blue. */
enum { CLASSES = 6 };
static const double class_lower[CLASSES] = {0, 5, 10, 20, 30, 40};
static const int class_rgb[CLASSES][3] = {{165, 0, 38},    {244, 109, 67},  {253, 174, 97},
                                          {254, 224, 144}, {171, 217, 233}, {69, 117, 180}};

static int class_of(double degrees)
{
    int k = CLASSES - 1;
    while (k > 0 && !(degrees >= class_lower[k])) k--;
    return k;
}

static void class_colour(int k, double shade, char out[8])
{
    snprintf(out, 8, "#%02x%02x%02x", (int)lround(class_rgb[k][0] * shade),
             (int)lround(class_rgb[k][1] * shade), (int)lround(class_rgb[k][2] * shade));
}

/* The faces drawn: 3 points each, and the class of their tetrahedron. */
typedef struct cut {
    lh_index *tri;
    int *cls;
    size_t count;
} cut;

/* Tet t's smallest dihedral angle, degrees (0 when it cannot be measured). */
static double tet_min_dihedral(const double *xyz, const lh_index *v)
{
    double p[12];
    static const lh_index one[4] = {0, 1, 2, 3};
    for (int j = 0; j < 4; j++) memcpy(p + 3 * j, xyz + 3 * (size_t)v[j], 3 * sizeof(double));
    lh_tetmesh_quality q;
    lh_error err;
    return lh_tetmesh_measure(4, p, 1, one, NULL, &q, &err) == LH_OK ? q.min_dihedral : 0;
}

/* keep[t]: tet t's centroid at or behind the middle of the points' depth range. */
static unsigned char *behind_middle(const lh_tetmesh *m, const lh_cli_camera *c)
{
    const size_t nt = lh_tetmesh_tet_count(m);
    const double *xyz = lh_tetmesh_points(m);
    const lh_index *tv = lh_tetmesh_tets(m);
    unsigned char *keep = malloc(nt ? nt : 1);
    if (!keep) return NULL;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t t = 0; t < nt; t++)
        for (int j = 0; j < 4; j++) {
            const double d = lh_cli_camera_depth(c, xyz + 3 * (size_t)tv[4 * t + j]);
            lo = fmin(lo, d), hi = fmax(hi, d);
        }
    const double mid = lo / 2 + hi / 2;
    for (size_t t = 0; t < nt; t++) {
        double d = 0;
        for (int j = 0; j < 4; j++)
            d += lh_cli_camera_depth(c, xyz + 3 * (size_t)tv[4 * t + j]) / 4;
        keep[t] = d >= mid;
    }
    return keep;
}

/* The faces of kept tets across which no kept tet lies, with their tet's class. */
static int cut_faces(const lh_tetmesh *m, const unsigned char *keep, cut *out)
{
    const size_t nt = lh_tetmesh_tet_count(m);
    const double *xyz = lh_tetmesh_points(m);
    const lh_index *tv = lh_tetmesh_tets(m), *nb = lh_tetmesh_neighbors(m);
    memset(out, 0, sizeof *out);
    out->tri = malloc((nt ? 4 * nt : 1) * 3 * sizeof *out->tri);
    out->cls = malloc((nt ? 4 * nt : 1) * sizeof *out->cls);
    if (!out->tri || !out->cls) return 0;
    for (size_t t = 0; t < nt; t++) {
        if (!keep[t]) continue;
        int cls = -1;
        for (int k = 0; k < 4; k++) {
            const lh_index o = nb[4 * t + k];
            if (o >= 0 && keep[o]) continue;
            if (cls < 0) cls = class_of(tet_min_dihedral(xyz, tv + 4 * t));
            lh_index *f = out->tri + 3 * out->count;
            for (int j = 0, i = 0; j < 4; j++)
                if (j != k) f[i++] = tv[4 * t + j];
            out->cls[out->count++] = cls;
        }
    }
    return 1;
}

static void legend(FILE *f, const lh_tetmesh *m, const cut *c, const char *title, double width)
{
    const double fs = 200, x0 = 0.02 * CANVAS, row = 300;
    char counts[160];
    snprintf(counts, sizeof counts,
             ": %zu points, %zu tetrahedra, cut through the middle (%zu faces drawn)",
             lh_tetmesh_point_count(m), lh_tetmesh_tet_count(m), c->count);
    const double room = width - 2 * x0, wide = 0.62 * fs * (double)(strlen(title) + strlen(counts));
    fprintf(
        f,
        "<g font-family=\"sans-serif\" font-size=\"%g\" fill=\"#333333\">\n<text x=\"%g\" y=\"%g\"",
        fs, x0, -LEGEND + row);
    if (wide > room) fprintf(f, " font-size=\"%.0f\"", fs * room / wide);
    fputc('>', f);
    lh_cli_svg_escaped(f, title);
    fprintf(f, "%s</text>\n", counts);
    fprintf(f, "<text x=\"%g\" y=\"%g\">smallest dihedral angle</text>\n", x0, -LEGEND + 2 * row);
    for (int k = 0; k < CLASSES; k++) {
        char col[8];
        class_colour(k, 1, col);
        const double x = x0 + 0.25 * CANVAS + k * 0.11 * CANVAS;
        fprintf(
            f,
            "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"%s\" stroke=\"#333333\"/>",
            x, -LEGEND + 2 * row - 0.7 * fs, 0.7 * fs, 0.7 * fs, col);
        if (k + 1 < CLASSES)
            fprintf(f, "<text x=\"%g\" y=\"%g\">%g-%g&#176;</text>\n", x + fs, -LEGEND + 2 * row,
                    class_lower[k], class_lower[k + 1]);
        else
            fprintf(f, "<text x=\"%g\" y=\"%g\">%g&#176; +</text>\n", x + fs, -LEGEND + 2 * row,
                    class_lower[k]);
    }
    fputs("</g>\n", f);
}

/* The dihedral angles' histogram in the band [top, top + BAND): a bar per bin, its
 * count above it and its lower edge below. */
static void histogram(FILE *f, const lh_histogram *h, double top, double width)
{
    const double fs = 160, x0 = 0.05 * width, x1 = 0.97 * width, base = top + BAND - 2.2 * fs;
    const double tall = BAND - 5 * fs, bar = (x1 - x0) / h->bins;
    size_t most = 1;
    for (int k = 0; k < h->bins; k++) most = h->count[k] > most ? h->count[k] : most;
    fprintf(f,
            "<g id=\"histogram\" font-family=\"sans-serif\" font-size=\"%g\" fill=\"#333333\" "
            "text-anchor=\"middle\">\n",
            fs);
    fprintf(f,
            "<text x=\"%g\" y=\"%g\" text-anchor=\"start\">dihedral angles (six per tetrahedron), "
            "degrees</text>\n",
            x0, top + 1.2 * fs);
    for (int k = 0; k < h->bins; k++) {
        char col[8];
        class_colour(class_of(h->lower[k]), 1, col);
        const double x = x0 + k * bar, ht = tall * (double)h->count[k] / (double)most;
        fprintf(f,
                "<rect x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" height=\"%.0f\" fill=\"%s\" "
                "stroke=\"#333333\"/>",
                x, base - ht, 0.9 * bar, ht, col);
        fprintf(f, "<text x=\"%.0f\" y=\"%.0f\">%zu</text>", x + 0.45 * bar, base - ht - 0.3 * fs,
                h->count[k]);
        fprintf(f, "<text x=\"%.0f\" y=\"%.0f\">%g</text>\n", x, base + 1.2 * fs, h->lower[k]);
    }
    fputs("</g>\n", f);
}

int lh_cli_tetmesh_svg_clip(FILE *f, const lh_tetmesh *m, const char *title)
{
    const double *xyz = lh_tetmesh_points(m);
    const lh_cli_camera c = lh_cli_camera_aim(xyz, lh_tetmesh_point_count(m), lh_tetmesh_faces(m),
                                              lh_tetmesh_face_count(m));
    lh_tetmesh_quality q;
    lh_error err;
    unsigned char *keep = behind_middle(m, &c);
    cut cf;
    size_t *order = NULL;
    int ok = keep && cut_faces(m, keep, &cf) &&
             (order = lh_cli_camera_order(&c, xyz, cf.tri, cf.count)) &&
             lh_tetmesh_measure(lh_tetmesh_point_count(m), xyz, lh_tetmesh_tet_count(m),
                                lh_tetmesh_tets(m), NULL, &q, &err) == LH_OK;
    if (ok) {
        const double W = ceil(fmax(c.width, MIN_WIDTH)), H = ceil(c.height);
        const double line =
            fmin(fmax(0.1 * sqrt(c.width * c.height / (double)(cf.count ? cf.count : 1)), 0.5), 8);
        lh_cli_svg_begin(f, W, H + BAND, LEGEND, title);
        legend(f, m, &cf, title, W);
        fprintf(
            f,
            "<g id=\"faces\" stroke=\"#303030\" stroke-width=\"%.3g\" stroke-linejoin=\"round\">\n",
            line);
        for (size_t j = 0; j < cf.count; j++) {
            const lh_index *t = cf.tri + 3 * order[j];
            char col[8];
            class_colour(cf.cls[order[j]], lh_cli_camera_shade(&c, xyz, t), col);
            lh_cli_camera_path(f, &c, xyz, t);
            fprintf(f, " fill=\"%s\"/>\n", col);
        }
        fputs("</g>\n", f);
        histogram(f, &q.dihedral, H, W);
        fputs("</svg>\n", f);
    }
    free(order);
    if (keep) free(cf.tri), free(cf.cls);
    free(keep);
    return ok && fflush(f) == 0 && !ferror(f) ? 0 : -1;
}
