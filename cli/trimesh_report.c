/* trimesh_report.c — the quality report of a 2D mesh (pslg_io.h): what Triangle's -V
 * prints, plus radius-edge ratios and the triangles left below the angle bound. */
#include "pslg_io.h"

#include <math.h>

#define DEG (180 / 3.14159265358979323846)

/* e[k] = p[k+2] - p[k+1] (the edge opposite corner k) with every coordinate first
 * multiplied by 2^-shift (exact but where subnormals lose their last bits). */
static void edge_vectors(const double *const p[3], int shift, double e[3][2])
{
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 2; j++) e[k][j] = ldexp(p[(k + 2) % 3][j], -shift) - ldexp(p[(k + 1) % 3][j], -shift);
}

void lh_cli_triangle_shape(const double *const p[3], double ang[3], double *ratio, double len[3])
{
    double e[3][2], big = 0;
    int shift = 0; /* a difference of coordinates near +-DBL_MAX overflows: halve them first */
    edge_vectors(p, 0, e);
    for (int k = 0; k < 6 && !shift; k++) shift = !isfinite(e[k / 2][k % 2]);
    if (shift) edge_vectors(p, 1, e);
    for (int k = 0; k < 6; k++) big = fmax(big, fabs(e[k / 2][k % 2]));
    if (!(big > 0)) { /* three equal points */
        for (int k = 0; k < 3; k++) ang[k] = len[k] = 0;
        *ratio = INFINITY;
        return;
    }
    int ex; /* the edges scaled by a power of two to a largest component in [1/2, 1) */
    frexp(big, &ex);
    double l[3];
    for (int k = 0; k < 3; k++) {
        e[k][0] = ldexp(e[k][0], -ex), e[k][1] = ldexp(e[k][1], -ex);
        l[k] = hypot(e[k][0], e[k][1]);
        len[k] = ldexp(l[k], ex + shift); /* infinity for an edge longer than DBL_MAX */
    }
    for (int k = 0; k < 3; k++) { /* between p[k+1] - p[k] = e[k+2] and p[k+2] - p[k] = -e[k+1] */
        const double *u = e[(k + 2) % 3], *v = e[(k + 1) % 3];
        ang[k] = atan2(fabs(u[0] * v[1] - u[1] * v[0]), -(u[0] * v[0] + u[1] * v[1])) * DEG;
    }
    /* R = l0 l1 l2 / (4 area) = l0 l1 l2 / (2 |e0 x e1|), over the shortest edge */
    const double a2 = fabs(e[0][0] * e[1][1] - e[0][1] * e[1][0]), lmin = fmin(l[0], fmin(l[1], l[2]));
    *ratio = a2 > 0 && lmin > 0 ? l[0] * l[1] * l[2] / (2 * a2 * lmin) : INFINITY;
}

void lh_cli_trimesh_unsplit(FILE *out, const lh_trimesh_stats *s)
{
    fprintf(out, "%zu subsegments could not be split (shorter than 2^-40 of the domain's size, or their "
                 "split point refused): edges beside them may not be Delaunay, nor triangles meet the bounds\n",
            s->segments_unsplit);
}

void lh_cli_trimesh_report(FILE *out, const lh_trimesh *m, double min_angle, int first)
{
    lh_trimesh_stats s;
    lh_trimesh_get_stats(m, &s);
    const size_t nt = lh_trimesh_triangle_count(m);
    const lh_index *t = lh_trimesh_triangles(m);
    const double *xy = lh_trimesh_points(m);
    size_t hist[18] = {0};
    double rmin = INFINITY, rmax = 0, emin = INFINITY, emax = 0;
    for (size_t i = 0; i < nt; i++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = xy + 2 * (size_t)t[3 * i + k];
        double ang[3], ratio, e[3];
        lh_cli_triangle_shape(p, ang, &ratio, e);
        rmin = fmin(rmin, ratio), rmax = fmax(rmax, ratio);
        emin = fmin(emin, fmin(e[0], fmin(e[1], e[2]))), emax = fmax(emax, fmax(e[0], fmax(e[1], e[2])));
        for (int k = 0; k < 3; k++) { /* an angle of [0, 180] degrees: a bin of 0..17 */
            const int bin = (int)(ang[k] / 10);
            hist[bin > 17 ? 17 : bin]++;
        }
    }
    fprintf(out, "Mesh: %zu points (%zu input, %zu Steiner: %zu on segments), %zu triangles, %zu subsegments\n",
            lh_trimesh_point_count(m), s.input_vertices, s.steiner_points, s.steiner_on_segments, nt,
            lh_trimesh_segment_count(m));
    if (s.duplicates_merged || s.segments_dropped || s.segments_overlapping || s.holes_ignored || s.regions_ignored)
        fprintf(out, "Input resolved: %zu duplicate vertices merged, %zu zero-length segments dropped, "
                     "%zu overlapping segments shared, %zu holes and %zu regions outside the domain ignored\n",
                s.duplicates_merged, s.segments_dropped, s.segments_overlapping, s.holes_ignored, s.regions_ignored);
    if (s.segments_unsplit) lh_cli_trimesh_unsplit(out, &s);
    if (s.steiner_removed) fprintf(out, "Steiner points removed again (Chew's rule): %zu\n", s.steiner_removed);
    if (s.smoothing_moves) fprintf(out, "Smoothing: %zu moves\n", s.smoothing_moves);
    if (s.crossings_split) fprintf(out, "Crossing segments split: %zu\n", s.crossings_split);
    fprintf(out, "Angles: smallest %.4g, largest %.4g degrees\n", s.min_angle, s.max_angle);
    fprintf(out, "Areas: smallest %.6g, largest %.6g; edges: shortest %.6g, longest %.6g\n", s.min_area,
            s.max_area, emin, emax);
    fprintf(out, "Radius-edge ratio: %.4g to %.4g\n", nt ? rmin : 0, rmax);
    fprintf(out, "Angle histogram (corners per 10 degrees):\n");
    for (int b = 0; b < 9; b++)
        fprintf(out, "  %3d - %3d: %9zu    |  %3d - %3d: %9zu\n", 10 * b, 10 * b + 10, hist[b], 90 + 10 * b,
                100 + 10 * b, hist[9 + b]);
    if (min_angle > 0 || s.bad_triangles) {
        fprintf(out, "Triangles below the bounds: %zu%s", s.bad_triangles,
                s.steiner_limit_reached ? " (the Steiner point limit was reached)" : "");
        const lh_index *bad = lh_trimesh_bad_triangles(m);
        if (s.bad_triangles) fprintf(out, ", numbered from %d as the files", first);
        for (size_t i = 0; i < s.bad_triangles && i < 10; i++)
            fprintf(out, "%s%lld", i ? " " : ": ", (long long)bad[i] + first);
        fprintf(out, "%s\n", s.bad_triangles > 10 ? " ..." : "");
    }
}
