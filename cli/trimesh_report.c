/* trimesh_report.c — the quality report of a 2D mesh (pslg_io.h): what Triangle's -V
 * prints, plus radius-edge ratios and the triangles left below the angle bound. */
#include "pslg_io.h"

#include <math.h>

static double len(const double *a, const double *b) { return hypot(b[0] - a[0], b[1] - a[1]); }

void lh_cli_trimesh_unsplit(FILE *out, const lh_trimesh_stats *s)
{
    fprintf(out, "%zu subsegments could not be split (shorter than 2^-40 of the domain's size, or their "
                 "split point refused): edges beside them may not be Delaunay, nor triangles meet the bounds\n",
            s->segments_unsplit);
}

void lh_cli_trimesh_report(FILE *out, const lh_trimesh *m, double min_angle)
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
        const double a = len(p[1], p[2]), b = len(p[2], p[0]), c = len(p[0], p[1]);
        const double area = fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])) / 2;
        const double r = a * b * c / (4 * area), sh = fmin(a, fmin(b, c));
        rmin = fmin(rmin, r / sh), rmax = fmax(rmax, r / sh);
        emin = fmin(emin, sh), emax = fmax(emax, fmax(a, fmax(b, c)));
        const double e[3] = {a, b, c};
        for (int k = 0; k < 3; k++) { /* law of cosines, clamped */
            const double x = e[k], y = e[(k + 1) % 3], z = e[(k + 2) % 3];
            double cs = (y * y + z * z - x * x) / (2 * y * z);
            cs = cs > 1 ? 1 : cs < -1 ? -1 : cs;
            int bin = (int)(acos(cs) * 180 / 3.14159265358979323846 / 10);
            hist[bin > 17 ? 17 : bin < 0 ? 0 : bin]++;
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
        for (size_t i = 0; i < s.bad_triangles && i < 10; i++) fprintf(out, "%s%lld", i ? " " : ": ", (long long)bad[i]);
        fprintf(out, "%s\n", s.bad_triangles > 10 ? " ..." : "");
    }
}
