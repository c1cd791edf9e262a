/* trimesh_report.c — the quality report of a 2D mesh (pslg_io.h): what Triangle's -V
 * prints, plus radius-edge ratios and the triangles left below the angle bound. */
#include "pslg_io.h"

#include <math.h>

/* A length or area m * 2^e (m >= 0), kept beyond the range of doubles: the report is
 * computed per triangle on its difference vectors scaled by a power of two (largest
 * component in [1, 2)), so it reads the same for the mesh scaled by any 2^k. */
typedef struct xval {
    double m;
    long e;
} xval;

static int xless(xval a, xval b)
{
    if (a.m == 0 || b.m == 0) return a.m < b.m;
    int ea, eb;
    const double fa = frexp(a.m, &ea), fb = frexp(b.m, &eb);
    return ea + a.e != eb + b.e ? ea + a.e < eb + b.e : fa < fb;
}

/* As %.6g, with a decimal exponent computed from e when the value is no normal double. */
static void xprint(FILE *out, xval v)
{
    int ex;
    frexp(v.m, &ex);
    if (v.m == 0 || (ex + v.e > -1021 && ex + v.e < 1024)) {
        fprintf(out, "%.6g", ldexp(v.m, (int)v.e));
        return;
    }
    const double l = log10(v.m) + (double)v.e * 0.30102999566398119521;
    double x = floor(l), mant = pow(10, l - x);
    if (mant >= 9.999995) mant /= 10, x += 1;
    fprintf(out, "%.6ge%+.0f", mant, x);
}

/* Triangle p in the frame of lh_triangle_scaled_edges (edge k = d[k] * 2^ex, opposite
 * p[k]): the edges' lengths l, the area |d1 x d2| / 2, the radius-edge ratio
 * R / shortest = l0 l1 l2 / (4 area shortest) (infinity when flat) and the corners'
 * angles in radians (ang[k] between d[k+2] and -d[k+1], atan2 of the cross and dot
 * products); no product overflows or vanishes in that frame. */
typedef struct shape {
    double d[3][2], l[3], area, ratio, ang[3];
    int ex;
} shape;

static void shape_of(const double *const p[3], shape *t)
{
    t->ex = lh_triangle_scaled_edges(p[0], p[1], p[2], t->d);
    for (int k = 0; k < 3; k++) {
        const double *u = t->d[(k + 2) % 3], *v = t->d[(k + 1) % 3];
        t->ang[k] = atan2(fabs(u[0] * v[1] - u[1] * v[0]), -(u[0] * v[0] + u[1] * v[1]));
        t->l[k] = hypot(t->d[k][0], t->d[k][1]);
    }
    t->area = fabs(t->d[1][0] * t->d[2][1] - t->d[1][1] * t->d[2][0]) / 2;
    const int m = t->l[0] <= t->l[1] && t->l[0] <= t->l[2] ? 0 : t->l[1] <= t->l[2] ? 1 : 2;
    /* the shortest edge cancelled, not divided: no underflow for a needle */
    t->ratio = t->area > 0 ? t->l[(m + 1) % 3] * t->l[(m + 2) % 3] / (4 * t->area) : INFINITY;
}

void lh_cli_triangle_shape(const double *const p[3], double ang[3], double *ratio, double len[3])
{
    shape t;
    shape_of(p, &t);
    for (int k = 0; k < 3; k++) {
        ang[k] = t.ang[k] * (180 / 3.14159265358979323846);
        len[k] = ldexp(t.l[k], t.ex); /* infinity for an edge longer than DBL_MAX */
    }
    *ratio = t.ratio;
}

void lh_cli_trimesh_unsplit(FILE *out, const lh_trimesh_stats *s)
{
    fprintf(out, "%zu subsegments could not be split (shorter than 2^-40 of the domain's size, or their "
                 "split point refused): edges beside them may not be Delaunay, nor triangles meet the bounds\n",
            s->segments_unsplit);
}

void lh_cli_trimesh_budget(FILE *out, const lh_trimesh_stats *s, double min_angle)
{
    fprintf(out, "Refinement stopped at its budget of %zu Steiner points: the angle bound %.4g degrees is above "
                 "%.4g, where Delaunay refinement need not end; %zu triangles are below the bounds\n",
            s->steiner_budget, min_angle, LH_TRIMESH_PROVABLE_ANGLE, s->bad_triangles);
}

void lh_cli_trimesh_report(FILE *out, const lh_trimesh *m, double min_angle, int first)
{
    lh_trimesh_stats s;
    lh_trimesh_stats_get(m, &s);
    const size_t nt = lh_trimesh_triangle_count(m);
    const lh_index *t = lh_trimesh_triangles(m);
    const double *xy = lh_trimesh_points(m);
    size_t hist[18] = {0};
    double rmin = INFINITY, rmax = 0;
    xval emin = {INFINITY, 0}, emax = {0, 0}, amin = {nt ? INFINITY : 0, 0}, amax = {0, 0};
    for (size_t i = 0; i < nt; i++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = xy + 2 * (size_t)t[3 * i + k];
        shape sh;
        shape_of(p, &sh);
        rmin = fmin(rmin, sh.ratio), rmax = fmax(rmax, sh.ratio);
        const double *l = sh.l;
        const xval xs = {fmin(l[0], fmin(l[1], l[2])), sh.ex}, xl = {fmax(l[0], fmax(l[1], l[2])), sh.ex};
        const xval xa = {sh.area, 2 * sh.ex};
        if (i == 0 || xless(xs, emin)) emin = xs;
        if (xless(emax, xl)) emax = xl;
        if (i == 0 || xless(xa, amin)) amin = xa;
        if (xless(amax, xa)) amax = xa;
        for (int k = 0; k < 3; k++) { /* an angle of [0, pi]: a bin of 0..17 */
            const int bin = (int)(sh.ang[k] * 180 / 3.14159265358979323846 / 10);
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
    if (s.steiner_budget_reached) lh_cli_trimesh_budget(out, &s, min_angle);
    if (s.steiner_removed) fprintf(out, "Steiner points removed again (Chew's rule): %zu\n", s.steiner_removed);
    if (s.smoothing_moves) fprintf(out, "Smoothing: %zu moves\n", s.smoothing_moves);
    if (s.crossings_split) fprintf(out, "Crossing segments split: %zu\n", s.crossings_split);
    fprintf(out, "Angles: smallest %.4g, largest %.4g degrees\n", s.min_angle, s.max_angle);
    const xval xv[4] = {amin, amax, nt ? emin : (xval){0, 0}, emax};
    const char *const xn[4] = {"Areas: smallest ", ", largest ", "; edges: shortest ", ", longest "};
    for (int k = 0; k < 4; k++) fputs(xn[k], out), xprint(out, xv[k]);
    fputc('\n', out);
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
