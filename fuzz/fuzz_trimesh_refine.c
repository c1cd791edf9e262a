/* fuzz_trimesh_refine.c — fuzz_trimesh's cover stage: the mesh made refined again as
 * Triangle's -r refines a .node/.ele, and the checks of that refinement. */
#include "fuzz_trimesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The refinement of a mesh (the cover stage): the old points first and unchanged,
 * the checks of check_links and check_bounds, subsegment parents the old segments' or
 * -1 (old boundary edges), the statistics consistent, the old union kept, and the
 * attributes interpolated finite. */
static void check_refined(const input *in, const lh_pslg *g, const lh_trimesh_options *o, const lh_trimesh *old,
                          const lh_trimesh *m)
{
    const size_t n = g->n, np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m),
                 ns = lh_trimesh_segment_count(m);
    const lh_index *par = lh_trimesh_segment_parents(m);
    if (np < n || memcmp(lh_trimesh_points(m), g->xy, 2 * n * sizeof(double))) abort();
    check_links(m);
    for (size_t s = 0; s < ns; s++)
        if (par[s] < -1 || par[s] >= (lh_index)g->segment_count) abort();
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    if (st.input_vertices != n || st.triangles != nt || st.steiner_points != np - n || st.crossings_split ||
        st.steiner_points > o->max_steiner ||
        (st.steiner_limit_reached && st.steiner_points + st.steiner_removed != o->max_steiner) ||
        st.steiner_on_segments > st.steiner_points || (!o->smooth && st.smoothing_moves))
        abort();
    check_bounds(o, m, &st);
    size_t moved, ignored;
    const long double got = grid_area2(in, m, n, &moved), want = grid_area2(in, old, n, &ignored);
    check_area(in, want, got, moved);
    const double *pa = lh_trimesh_point_attrs(m);
    if (g->attr_count) {
        if (!pa || lh_trimesh_point_attr_count(m) != 1) abort();
        for (size_t p = 0; p < np; p++)
            if (!isfinite(pa[p]) || (p < n && pa[p] != g->attr[p])) abort();
    }
}

/* The cover stage (Triangle's -r), when bit 0 of in->cover is set: the mesh `old`
 * refined with its triangles as lh_pslg.cover, its points (and attributes) as the
 * vertices; bit 1: its subsegments as segments too (-rp); bits 2-3: the old
 * triangles' area bounds (none, or 0.5, 2, 8 and none in turn from a start they
 * choose); bits 4-6: the angle bound; bit 7: the global area bound 2. The other
 * options are the first run's. It must succeed (the old mesh passed the checks) and
 * pass check_refined, a second run equal byte for byte, nothing leaking, and with
 * fail_mode a run failing one chosen allocation returning LH_ERR_NOMEM. */
void refine_cover(const input *in, const lh_trimesh *old)
{
    const size_t nt = lh_trimesh_triangle_count(old);
    static const double areas[4] = {0.5, 2, 8, -1};
    double *area = malloc(nt * sizeof *area);
    if (!area) abort();
    const unsigned b = in->cover;
    for (size_t t = 0; t < nt; t++) {
        const double bound = areas[(t + (b >> 2)) & 3];
        area[t] = bound > 0 ? bound * in->scale * in->scale : -1;
    }
    input r = *in; /* the options and the scale; g is the old mesh */
    lh_pslg *g = &r.g;
    memset(g, 0, sizeof *g);
    g->n = lh_trimesh_point_count(old), g->xy = (double *)lh_trimesh_points(old); /* read only */
    g->cover_count = nt, g->cover = (lh_index *)lh_trimesh_triangles(old);
    if (b & 2) g->segment_count = lh_trimesh_segment_count(old), g->segments = (lh_index *)lh_trimesh_segments(old);
    if (lh_trimesh_point_attr_count(old))
        g->attr_count = 1, g->attr = (double *)lh_trimesh_point_attrs(old);
    r.o.region_areas = (b & 12) != 0;
    g->cover_area = r.o.region_areas ? area : NULL;
    r.o.min_angle = angles[(b >> 4) & 7];
    r.o.max_area = b >> 7 ? 2 * in->scale * in->scale : 0;
    counter c1 = {0, 0, 0, 0}, c2 = c1;
    lh_trimesh *m1 = NULL, *m2 = NULL;
    char msg[256] = "x";
    const lh_status st = run(&r, &c1, &m1, msg, sizeof msg);
#ifdef LH_FUZZ_TRIMESH_VERBOSE
    fprintf(stderr, "cover stage: %zu points, %zu triangles, %zu segments, q %g a %g, areas %d -> %s \"%s\"\n", g->n,
            nt, g->segment_count, r.o.min_angle, r.o.max_area, r.o.region_areas, lh_status_name(st), msg);
#endif
    if (st != LH_OK || msg[0]) abort();
    check_refined(&r, g, &r.o, old, m1);
    if (run(&r, &c2, &m2, msg, sizeof msg) != LH_OK || !same(m1, m2)) abort();
    lh_trimesh_free(m2);
    if (r.fail_mode) check_failure(&r, m1, c1.calls);
    lh_trimesh_free(m1);
    free(area);
    if (c1.live || c2.live) abort();
}
