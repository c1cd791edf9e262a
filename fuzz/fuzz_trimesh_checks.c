/* fuzz_trimesh_checks.c — fuzz_trimesh's checks of a successful run (fuzz_trimesh.c's
 * header): links, bounds, areas on the grid, and the whole mesh. */
#include "fuzz_trimesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The checks of a successful run (the header's list). */
/* lh_cdt_check passes; indices in range, neighbours symmetric across the same
 * edge, -1 only on subsegments. */
void check_links(const lh_trimesh *m)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m), ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *nb = lh_trimesh_neighbors(m), *seg = lh_trimesh_segments(m);
    lh_error err;
    if (!nt || lh_cdt_check(np, xy, nt, tri, ns, seg, 0, NULL, &err) != LH_OK) {
#ifdef LH_FUZZ_TRIMESH_VERBOSE
        fprintf(stderr, "lh_cdt_check: %s\n", err.message);
#endif
        abort();
    }
    for (size_t i = 0; i < 3 * nt; i++)
        if (tri[i] < 0 || (size_t)tri[i] >= np || nb[i] < -1 || nb[i] >= (lh_index)nt) abort();
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            const lh_index a = tri[3 * t + (k + 1) % 3], b = tri[3 * t + (k + 2) % 3], u = nb[3 * t + k];
            int on_seg = 0;
            for (size_t s = 0; s < ns && !on_seg; s++)
                on_seg = (seg[2 * s] == a && seg[2 * s + 1] == b) || (seg[2 * s] == b && seg[2 * s + 1] == a);
            if (u < 0) {
                if (!on_seg) abort();
                continue;
            }
            int back = -1;
            for (int j = 0; j < 3; j++)
                if (nb[3 * (size_t)u + j] == (lh_index)t) back = j;
            if (back < 0 || tri[3 * (size_t)u + (back + 1) % 3] != b || tri[3 * (size_t)u + (back + 2) % 3] != a)
                abort();
        }
}

/* The bad list increasing, and every triangle not on it within o's angle and global
 * area bounds (measured here by atan2); the extremes within them unless refinement
 * was stopped. */
void check_bounds(const lh_trimesh_options *o, const lh_trimesh *m, const lh_trimesh_stats *st)
{
    const size_t nt = lh_trimesh_triangle_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *bad = lh_trimesh_bad_triangles(m);
    for (size_t i = 0; i < st->bad_triangles; i++)
        if (bad[i] < 0 || (size_t)bad[i] >= nt || (i && bad[i] <= bad[i - 1])) abort();
    const int stopped = st->bad_triangles > 0 || st->steiner_limit_reached || o->boundary_steiner != 1;
    if (!stopped && o->min_angle > 0 && st->min_angle < o->min_angle - 1e-6) abort();
    if (!stopped && o->max_area > 0 && st->max_area > o->max_area * (1 + 1e-9)) abort();
    for (size_t t = 0, b = 0; t < nt; t++) {
        if (b < st->bad_triangles && (size_t)bad[b] == t) {
            b++;
            continue;
        }
        const double *q[3];
        for (int k = 0; k < 3; k++) q[k] = xy + 2 * (size_t)tri[3 * t + k];
        double small = 180;
        for (int k = 0; k < 3; k++) {
            const double ux = q[(k + 1) % 3][0] - q[k][0], uy = q[(k + 1) % 3][1] - q[k][1];
            const double vx = q[(k + 2) % 3][0] - q[k][0], vy = q[(k + 2) % 3][1] - q[k][1];
            const double a = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180 / 3.14159265358979323846);
            small = a < small ? a : small;
        }
        const double area = ((q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0])) / 2;
        if ((o->min_angle > 0 && small < o->min_angle - 1e-6) || (o->max_area > 0 && area > o->max_area * (1 + 1e-9)))
            abort();
    }
}

/* Twice the area of m's triangles in grid units (exact but for the long double sums
 * of points off the grid); *moved: the points from `from` on that end subsegments. */
long double grid_area2(const input *in, const lh_trimesh *m, size_t from, size_t *moved)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m), ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *seg = lh_trimesh_segments(m);
    long double got = 0;
    for (size_t t = 0; t < nt; t++) {
        long double q[3][2];
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 2; j++)
                q[k][j] = (long double)xy[2 * (size_t)tri[3 * t + k] + j] / in->scale - in->off;
        got += (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    }
    unsigned char *on = calloc(np, 1);
    if (!on) abort();
    *moved = 0;
    for (size_t s = 0; s < 2 * ns; s++)
        if ((size_t)seg[s] >= from && !on[seg[s]]) on[seg[s]] = 1, ++*moved;
    free(on);
    return got;
}

/* Points put on segments (and on hull or old boundary edges) are within an ulp of
 * them: each moves the area by at most about an ulp of the coordinates times the
 * grid's size. */
void check_area(const input *in, long double want, long double got, size_t moved)
{
    const double ulp = ldexp(1.0, -52) * (in->off + 8) * 64;
    if (fabsl(got - want) > (long double)moved * ulp + 1e-9L * want) abort();
}

void check_mesh(const input *in, const lh_trimesh *m)
{
    const lh_pslg *g = &in->g;
    const size_t n = g->n, np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m),
                 ns = lh_trimesh_segment_count(m);
    const double *xy = lh_trimesh_points(m);
    const lh_index *tri = lh_trimesh_triangles(m), *seg = lh_trimesh_segments(m), *par = lh_trimesh_segment_parents(m);
    lh_error err;
    if (np < n || memcmp(xy, g->xy, 2 * n * sizeof(double))) abort();
    check_links(m);
    /* a merged duplicate (equal to an earlier vertex) is in no triangle */
    for (size_t i = 0; i < 3 * nt; i++)
        if ((size_t)tri[i] < n)
            for (size_t j = 0; j < (size_t)tri[i]; j++)
                if (in->v[j].x == in->v[tri[i]].x && in->v[j].y == in->v[tri[i]].y) abort();
    for (size_t s = 0; s < ns; s++) {
        const lh_index p = par[s];
        if (p < -1 || p >= (lh_index)g->segment_count || (p < 0 && !in->keep_hull)) abort();
        for (int j = 0; j < 2 && p >= 0; j++) {
            const lh_index x = seg[2 * s + j];
            if ((size_t)x < n && !on_segment(in->v[g->segments[2 * p]], in->v[g->segments[2 * p + 1]], in->v[x]))
                abort();
        }
    }
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    const lh_trimesh_options *o = &in->o;
    if (st.input_vertices != n || st.duplicates_merged != in->dups || st.triangles != nt ||
        st.steiner_points != np - n || st.crossings_split > st.steiner_on_segments ||
        (st.crossings_split && !(in->crossing && o->split_crossings)) ||
        st.steiner_points - st.crossings_split > o->max_steiner ||
        /* the budget counts the points refinement inserted, removed again (Chew's rule) or not */
        (st.steiner_limit_reached && st.steiner_points + st.steiner_removed - st.crossings_split != o->max_steiner) ||
        (!in->refine && (st.steiner_points != st.crossings_split || st.steiner_removed || st.segments_unsplit)) ||
        st.steiner_on_segments > st.steiner_points ||
        (!o->smooth && st.smoothing_moves))
        abort();
    check_bounds(o, m, &st);
    /* conforming alone: every edge Delaunay. Not with crossings split (rounding beside
       chains bent at rounded crossings leaves some subsegments unsplittable), with an
       angle or area bound (splits towards a small angle's apex stop at the minimum
       length, a subsegment there still encroached) or with smoothing (it restores the
       constrained Delaunay property only), nor with subsegments refinement could not
       split (README finding 10: unit features at 2^40, the resolution floor) */
    if (o->conforming && !st.steiner_limit_reached && !st.segments_unsplit && o->boundary_steiner == 1 &&
        !st.crossings_split && o->min_angle == 0 && o->max_area <= 0 && !o->region_areas && !st.smoothing_moves &&
        lh_cdt_check(np, xy, nt, tri, 0, NULL, 1, NULL, &err) != LH_OK)
        abort();
    if ((o->region_attributes != 0) != (lh_trimesh_triangle_attrs(m) != NULL)) abort();
    const double *pa = lh_trimesh_point_attrs(m);
    if (g->attr_count) {
        if (!pa || lh_trimesh_point_attr_count(m) != 1) abort();
        for (size_t p = 0; p < np; p++)
            if (!isfinite(pa[p]) || (p < n && pa[p] != in->attr[p])) abort();
    }
    if (in->keep_hull && !g->hole_count) {
        grid v[MAXV];
        memcpy(v, in->v, n * sizeof *v);
        size_t moved;
        const long double got = grid_area2(in, m, n, &moved);
        check_area(in, (long double)hull_area2(v, n), got, moved);
    }
}
