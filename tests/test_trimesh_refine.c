/* test_trimesh_refine.c — refining an existing 2D mesh (lifthull.h, "2D meshing",
 * the CLI's -r): its area bounds kept, its boundary edges split and their segments
 * kept, the refined mesh covering the old one exactly. */
#include "trimesh_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Refining an existing mesh (Triangle's -ra): bbox.1's 12 triangles with their area
 * bounds (-1: none) are the domain; the result covers exactly their union and every
 * new triangle meets the bound of the old one holding its centroid. */
LH_TEST(an_existing_mesh_is_refined_with_its_area_bounds)
{
    char path[512];
    lh_error err;
    lh_points pts;
    lh_cells cells;
    snprintf(path, sizeof path, "%s/triangle/bbox.1.node", LH_TEST_DATA_DIR);
    FILE *f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_points_read(f, "bbox.1.node", LH_FORMAT_NODE, NULL, &pts, &err), LH_OK);
    fclose(f);
    snprintf(path, sizeof path, "%s/triangle/bbox.1.ele", LH_TEST_DATA_DIR);
    f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    LH_ASSERT_EQ_INT(lh_cells_read(f, "bbox.1.ele", pts.n, NULL, &cells, &err), LH_OK);
    fclose(f);
    LH_ASSERT_EQ_INT(cells.nv, 3);
    double area[12];
    snprintf(path, sizeof path, "%s/triangle/bbox.1.area", LH_TEST_DATA_DIR);
    f = fopen(path, "r");
    LH_ASSERT_TRUE(f != NULL);
    size_t k = 0;
    LH_ASSERT_TRUE(fscanf(f, "%zu", &k) == 1 && k == 12 && cells.count == 12);
    for (size_t i = 0; i < 12; i++) {
        int num;
        LH_ASSERT_TRUE(fscanf(f, "%d %lf", &num, area + i) == 2);
    }
    fclose(f);
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = pts.n, g.xy = pts.xyz, g.cover_count = cells.count, g.cover = cells.v, g.cover_area = area;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.region_areas = 1;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "bbox -ra");
    if (m) {
        double old_total = 0, total = 0;
        for (size_t i = 0; i < 12; i++) {
            const double *a = pts.xyz + 2 * (size_t)cells.v[3 * i], *b = pts.xyz + 2 * (size_t)cells.v[3 * i + 1],
                         *c = pts.xyz + 2 * (size_t)cells.v[3 * i + 2];
            old_total += fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
        }
        const double *xy = lh_trimesh_points(m);
        const lh_index *t = lh_trimesh_triangles(m);
        size_t bounded = 0;
        for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
            const double *a = xy + 2 * (size_t)t[3 * i], *b = xy + 2 * (size_t)t[3 * i + 1], *c = xy + 2 * (size_t)t[3 * i + 2];
            const double ar = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
            total += ar;
            const double p[2] = {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
            for (size_t j = 0; j < 12; j++) { /* the old triangle holding the centroid */
                const double *u = pts.xyz + 2 * (size_t)cells.v[3 * j], *v = pts.xyz + 2 * (size_t)cells.v[3 * j + 1],
                             *w = pts.xyz + 2 * (size_t)cells.v[3 * j + 2];
                const double s1 = (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
                const double s2 = (w[0] - v[0]) * (p[1] - v[1]) - (w[1] - v[1]) * (p[0] - v[0]);
                const double s3 = (u[0] - w[0]) * (p[1] - w[1]) - (u[1] - w[1]) * (p[0] - w[0]);
                if ((s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0)) {
                    if (area[j] > 0) LH_EXPECT_LE_DBL(ar, area[j]), bounded++;
                    break;
                }
            }
        }
        LH_EXPECT_TRUE(fabs(total - old_total) <= 1e-12 * old_total);
        LH_EXPECT_GT_U64(bounded, 10);
        LH_EXPECT_GT_U64(lh_trimesh_triangle_count(m), 12);
    }
    lh_trimesh_free(m);
    /* a cover naming a point that does not exist */
    cells.v[0] = (lh_index)pts.n;
    LH_EXPECT_EQ_INT(lh_pslg_triangulate(&g, &o, &m, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "the mesh to refine names a point that does not exist, or has an edge of three triangles");
    lh_cells_free(&cells);
    lh_points_free(&pts);
}

/* Twice the total area of m's triangles. */
static double area2_sum(const lh_trimesh *m)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m);
    double sum = 0;
    for (size_t i = 0; i < lh_trimesh_triangle_count(m); i++) {
        const double *a = xy + 2 * (size_t)t[3 * i], *b = xy + 2 * (size_t)t[3 * i + 1], *c = xy + 2 * (size_t)t[3 * i + 2];
        sum += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
    return sum;
}

/* Refines the mesh `old` (its points and triangles as the cover) under o: the result
 * is exactly valid, covers the same union, meets the area bound, and names its bad
 * triangles in range and in order. Returns the Steiner points put on the old
 * boundary. */
static size_t refine_cover(lh_test_state *lh_t_, const lh_trimesh *old, const lh_trimesh_options *o,
                           const char *what)
{
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = lh_trimesh_point_count(old), g.xy = (double *)lh_trimesh_points(old); /* read only */
    g.cover_count = lh_trimesh_triangle_count(old), g.cover = (lh_index *)lh_trimesh_triangles(old);
    lh_trimesh *m = mesh_checked(lh_t_, &g, o, what);
    if (!m) return 0;
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    const double before = area2_sum(old), after = area2_sum(m);
    if (fabs(after - before) > 1e-12 * before) LH_NOTE("%s: area %.17g, was %.17g", what, after / 2, before / 2);
    LH_EXPECT_TRUE(fabs(after - before) <= 1e-12 * before);
    if (o->max_area > 0) LH_EXPECT_GT_U64(st.steiner_points, 0);
    if (o->max_area > 0) LH_EXPECT_LE_DBL(st.max_area, o->max_area);
    const lh_index *bad = lh_trimesh_bad_triangles(m);
    for (size_t i = 0; i < st.bad_triangles; i++) {
        LH_EXPECT_TRUE(bad[i] >= 0 && (size_t)bad[i] < lh_trimesh_triangle_count(m));
        if (i) LH_EXPECT_LT_INT(bad[i - 1], bad[i]);
    }
    const size_t on_boundary = st.steiner_on_segments;
    lh_trimesh_free(m);
    return on_boundary;
}

/* Triangle's -r with -a or -q (`-pc box.poly` then `-rpa0.2 box.1`; `-rq30 face.1`):
 * Steiner points on the old mesh's boundary edges (subsegment parents -2, -3, ...)
 * were taken for removed points (pseg -2), dropped, and their triangles left naming
 * point -1: reads before the point array, a double free. Every such refinement is
 * exactly valid; the unit square split along a diagonal, and meshes of Triangle's
 * files, each refined by area, angle and both. */
LH_TEST(refining_a_mesh_splits_its_boundary_edges)
{
    const char *const files[] = {"triangle/box.poly", "triangle/face.poly", "triangle/A.poly"};
    for (size_t i = 0; i < sizeof files / sizeof files[0] + 1; i++) {
        lh_trimesh *old = NULL;
        if (i == 0) { /* the unit square, two triangles */
            static double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
            static lh_index cover[] = {0, 1, 3, 1, 2, 3};
            lh_pslg sq;
            memset(&sq, 0, sizeof sq);
            sq.n = 4, sq.xy = xy, sq.cover_count = 2, sq.cover = cover;
            old = mesh_checked(lh_t_, &sq, NULL, "the unit square as a cover");
        } else {
            lh_pslg g;
            LH_ASSERT_EQ_INT(load(lh_poly_read, files[i - 1], &g), LH_OK);
            lh_trimesh_options c;
            lh_trimesh_options_default(&c);
            c.convex_hull = 1; /* -pc */
            old = mesh_checked(lh_t_, &g, &c, files[i - 1]);
            lh_pslg_free(&g);
        }
        if (!old) continue;
        const double area = area2_sum(old) / 2;
        lh_trimesh_options o;
        lh_trimesh_options_default(&o);
        o.max_area = area / 50;
        size_t on_boundary = refine_cover(lh_t_, old, &o, "-ra");
        o.max_area = 0, o.min_angle = 30;
        refine_cover(lh_t_, old, &o, "-rq30");
        o.max_area = area / 200;
        on_boundary += refine_cover(lh_t_, old, &o, "-rq30a");
        LH_EXPECT_GT_U64(on_boundary, 0);
        lh_trimesh_free(old);
    }
}

/* -rp: the input segments along the old mesh's boundary give their markers and
 * parents to its pieces and to the Steiner points put there (as Triangle's -rpa on
 * box.1, reference_outputs/box.2: cli_triangle_ref), not the old boundary's 1 and -1. */
LH_TEST(refining_a_mesh_keeps_the_segments_along_its_boundary)
{
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    lh_index cover[6] = {0, 1, 3, 1, 2, 3}, seg[8] = {0, 1, 1, 2, 2, 3, 3, 0}, mark[4] = {5, 6, 7, 8};
    lh_pslg g;
    memset(&g, 0, sizeof g);
    g.n = 4, g.xy = xy, g.cover_count = 2, g.cover = cover;
    g.segment_count = 4, g.segments = seg, g.segment_marker = mark;
    lh_trimesh_options o;
    lh_trimesh_options_default(&o);
    o.max_area = 0.01;
    lh_trimesh *m = mesh_checked(lh_t_, &g, &o, "-rpa0.01 square");
    LH_ASSERT_TRUE(m != NULL);
    const double *p = lh_trimesh_points(m);
    const lh_index *pm = lh_trimesh_point_markers(m), *sv = lh_trimesh_segments(m),
                   *sm = lh_trimesh_segment_markers(m), *sp = lh_trimesh_segment_parents(m);
    size_t on_bottom = 0;
    for (size_t i = 4; i < lh_trimesh_point_count(m); i++)
        if (p[2 * i + 1] == 0) LH_EXPECT_EQ_INT(pm[i], 5), on_bottom++;
    LH_EXPECT_GT_U64(on_bottom, 0);
    for (size_t s = 0; s < lh_trimesh_segment_count(m); s++) {
        LH_EXPECT_TRUE(sp[s] >= 0 && sp[s] < 4);
        if (sp[s] >= 0 && sp[s] < 4) LH_EXPECT_EQ_INT(sm[s], mark[sp[s]]);
        if (p[2 * sv[2 * s] + 1] == 0 && p[2 * sv[2 * s + 1] + 1] == 0) LH_EXPECT_EQ_INT(sp[s], 0);
    }
    lh_trimesh_free(m);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(an_existing_mesh_is_refined_with_its_area_bounds),
        LH_CASE(refining_a_mesh_splits_its_boundary_edges),
        LH_CASE(refining_a_mesh_keeps_the_segments_along_its_boundary),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
