/* test_trimesh_quality.c — the quality refinement of lh_triangulate_pslg (refine.c)
 * where the domain is pinched: a hole touching the outer ring, a ring touching
 * itself. No triangle beside such a vertex may be left below the bound unless an
 * input angle there is below it too (earcut's hole-touching-outer.json and
 * self-tangent-4.json: a 0.81 and a 25.6 degree triangle were left, the subsegment
 * beside them not found from the pinch vertex's fan). */
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static lh_status load_rings(const char *path, lh_pslg *g)
{
    char full[512], msg[256];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_status st = lh_rings_read(f, path, NULL, g, msg, sizeof msg);
    fclose(f);
    return st;
}

static int same_point(const double *a, const double *b) { return a[0] == b[0] && a[1] == b[1]; }

/* The smallest angle (degrees) between two input segments ending at point p (their
 * ends compared by coordinates: the rings repeat a pinch point as several vertices),
 * 360 when fewer than two end there; *copies: how many vertices are at p. */
static double angle_at(const lh_pslg *g, const double *p, size_t *copies)
{
    *copies = 0;
    for (size_t v = 0; v < g->n; v++) *copies += same_point(g->xy + 2 * v, p);
    double best = 360;
    for (size_t s = 0; s < g->segment_count; s++)
        for (size_t t = s + 1; t < g->segment_count; t++)
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++) {
                    const double *o = g->xy + 2 * (size_t)g->segments[2 * s + i];
                    if (!same_point(o, p) || !same_point(g->xy + 2 * (size_t)g->segments[2 * t + j], p)) continue;
                    const double *a = g->xy + 2 * (size_t)g->segments[2 * s + 1 - i];
                    const double *b = g->xy + 2 * (size_t)g->segments[2 * t + 1 - j];
                    const double ang = fabs(atan2(a[1] - o[1], a[0] - o[0]) - atan2(b[1] - o[1], b[0] - o[0]));
                    best = fmin(best, fmin(ang, 2 * 3.14159265358979323846 - ang) * 180 / 3.14159265358979323846);
                }
    return best;
}

LH_TEST(a_pinched_domain_is_refined_beside_the_pinch)
{
    static const char *const files[] = {"hole-touching-outer", "self-tangent-4"};
    static const double bounds[] = {10, 30};
    for (size_t i = 0; i < LH_COUNT(files); i++) {
        char path[128];
        snprintf(path, sizeof path, "polygons/degenerate/%s.json", files[i]);
        lh_pslg g;
        LH_ASSERT_EQ_INT(load_rings(path, &g), LH_OK);
        for (size_t b = 0; b < LH_COUNT(bounds); b++) {
            lh_trimesh_options o;
            lh_trimesh_options_default(&o);
            o.min_angle = bounds[b];
            lh_trimesh *m = NULL;
            char msg[256] = "";
            LH_ASSERT_EQ_INT(lh_triangulate_pslg(&g, &o, &m, msg, sizeof msg), LH_OK);
            LH_EXPECT_EQ_INT(lh_check_trimesh(lh_trimesh_point_count(m), lh_trimesh_points(m),
                                              lh_trimesh_triangle_count(m), lh_trimesh_triangles(m),
                                              lh_trimesh_segment_count(m), lh_trimesh_segments(m), 0, NULL, msg,
                                              sizeof msg),
                             LH_OK);
            lh_trimesh_stats st;
            lh_trimesh_get_stats(m, &st);
            const lh_index *bad = lh_trimesh_bad_triangles(m), *tri = lh_trimesh_triangles(m);
            const double *xy = lh_trimesh_points(m);
            size_t at_pinch = 0;
            for (size_t k = 0; k < st.bad_triangles; k++)
                for (int j = 0; j < 3; j++) {
                    const double *p = xy + 2 * (size_t)tri[3 * (size_t)bad[k] + j];
                    size_t copies;
                    const double ang = angle_at(&g, p, &copies);
                    if (copies > 1 && ang >= bounds[b]) {
                        LH_NOTE("%s at %g: bad triangle %lld at the pinch (%g, %g), input angle %g", files[i],
                                bounds[b], (long long)bad[k], p[0], p[1], ang);
                        at_pinch++;
                    }
                }
            LH_EXPECT_EQ_U64(at_pinch, 0);
            if (i == 0) /* its one input angle below 30 degrees: 24.1 */
                LH_EXPECT_GE_INT(st.min_angle, bounds[b] < 24 ? bounds[b] : 24.0);
            lh_trimesh_free(m);
        }
        lh_pslg_free(&g);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(a_pinched_domain_is_refined_beside_the_pinch),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
