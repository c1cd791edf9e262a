/* test_locate.c — lh_tri_locate: inside, the simplex really contains q (exact) and
 * the barycentric coordinates rebuild q; outside, the distance is the distance to the
 * hull (brute force over hull edges in 2D, bounded by the nearest vertex elsewhere). */
#include "lh_families.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>


static double seg_dist(const double *a, const double *b, const double *q)
{
    double ux = b[0] - a[0], uy = b[1] - a[1];
    double t = ((q[0] - a[0]) * ux + (q[1] - a[1]) * uy) / (ux * ux + uy * uy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(a[0] + t * ux - q[0], a[1] + t * uy - q[1]);
}

/* q located in simplex loc->simplex: q is on the inner side of every facet (exact),
 * the barycentric coordinates are >= 0 (to rounding), sum to 1 and rebuild q. */
static void check_inside(lh_test_state *lh_t_, lh_pred *pred, lh_tri *t, const double *x, int d,
                         const double *q, const lh_location *loc)
{
    const int nv = d + 1;
    const lh_index *v = lh_tri_simplices(t) + (size_t)loc->simplex * nv;
    const double *p[9];
    for (int f = 0; f < nv; f++) { /* q on the inner side of every facet */
        for (int j = 0; j < nv; j++) p[j] = j == f ? q : x + (size_t)v[j] * d;
        LH_EXPECT_GE_INT(lh_orient(pred, d, p), 0);
    }
    double sum = 0;
    for (int j = 0; j < nv; j++) {
        sum += loc->bary[j];
        LH_EXPECT_TRUE(loc->bary[j] > -1e-9);
    }
    LH_EXPECT_TRUE(fabs(sum - 1) < 1e-9);
    for (int c = 0; c < d; c++) {
        double r = 0;
        for (int j = 0; j < nv; j++) r += loc->bary[j] * x[(size_t)v[j] * d + c];
        LH_EXPECT_TRUE(fabs(r - q[c]) < 1e-9);
    }
    LH_EXPECT_EQ_INT(loc->hull_facet, -1);
}

/* q outside the hull: the distance is positive, at most the nearest site's, the
 * reported point of hull facet loc->hull_facet is at that distance, and in 2D it is
 * the distance to the nearest hull edge (brute force). */
static void check_outside(lh_test_state *lh_t_, lh_tri *t, const double *x, size_t n, int d,
                          const double *q, const lh_location *loc)
{
    LH_ASSERT_TRUE(loc->hull_facet >= 0 && (size_t)loc->hull_facet < lh_tri_hull_count(t));
    LH_EXPECT_TRUE(loc->distance > 0);
    double nearest_site = INFINITY;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (int c = 0; c < d; c++) s += (x[i * d + c] - q[c]) * (x[i * d + c] - q[c]);
        if (sqrt(s) < nearest_site) nearest_site = sqrt(s);
    }
    LH_EXPECT_LE_DBL(loc->distance, nearest_site + 1e-12);
    const lh_index *f = lh_tri_hull_facets(t) + (size_t)loc->hull_facet * d;
    double r2 = 0; /* the reported nearest point is at that distance */
    for (int c = 0; c < d; c++) {
        double r = 0;
        for (int j = 0; j < d; j++) r += loc->bary[j] * x[(size_t)f[j] * d + c];
        r2 += (r - q[c]) * (r - q[c]);
    }
    LH_EXPECT_TRUE(fabs(sqrt(r2) - loc->distance) < 1e-9);
    if (d == 2) { /* brute force: every hull edge */
        double best = INFINITY;
        for (size_t e = 0; e < lh_tri_hull_count(t); e++) {
            const lh_index *h = lh_tri_hull_facets(t) + 2 * e;
            double s = seg_dist(x + 2 * h[0], x + 2 * h[1], q);
            if (s < best) best = s;
        }
        LH_EXPECT_TRUE(fabs(best - loc->distance) < 1e-12);
    }
}

LH_TEST(queries_inside_outside_and_on_sites)
{
    lh_pred *pred;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &pred), LH_OK);
    lh_fam_seed(3);
    for (int d = 2; d <= 5 && !LH_FAILED(); d++) {
        size_t n = d == 2 ? 500 : d == 3 ? 300 : 100;
        double *x = malloc(n * d * sizeof *x);
        for (size_t i = 0; i < n * d; i++) x[i] = lh_fam_unif();
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        int inside = 0, outside = 0;
        lh_index hint = -1;
        for (int k = 0; k < 400 && !LH_FAILED(); k++) {
            double q[8];
            if (k % 4 == 3) /* a site: on the triangulation's vertices */
                for (int j = 0; j < d; j++) q[j] = x[(size_t)(k % n) * d + j];
            else
                for (int j = 0; j < d; j++) q[j] = 1.4 * lh_fam_unif() - 0.2;
            lh_location loc;
            LH_ASSERT_EQ_INT(lh_tri_locate(t, q, hint, &loc), LH_OK);
            if (loc.simplex >= 0) {
                inside++;
                hint = loc.simplex;
                check_inside(lh_t_, pred, t, x, d, q, &loc);
            } else {
                outside++;
                check_outside(lh_t_, t, x, n, d, q, &loc);
            }
        }
        LH_EXPECT_GT_INT(inside, 50);
        LH_EXPECT_GT_INT(outside, 20);
        lh_location loc;
        double bad[8] = {0};
        bad[1] = NAN;
        LH_EXPECT_EQ_INT(lh_tri_locate(t, bad, -1, &loc), LH_ERR_NONFINITE);
        LH_EXPECT_EQ_INT(lh_tri_locate(t, NULL, -1, &loc), LH_ERR_INVALID_ARGUMENT);
        lh_tri_free(t);
        free(x);
    }
    lh_pred_free(pred);
}

/* On a grid, queries at sites, edge midpoints and cell centres lie in many simplices:
 * the answer is the smallest index among them (brute force), whatever the hint. */
LH_TEST(points_on_shared_faces_get_the_smallest_simplex)
{
    lh_pred *pred;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &pred), LH_OK);
    for (int d = 2; d <= 4 && !LH_FAILED(); d++) {
        int side = d == 2 ? 8 : d == 3 ? 5 : 3;
        size_t n = 1;
        for (int j = 0; j < d; j++) n *= (size_t)side;
        double *x = malloc(n * d * sizeof *x);
        for (size_t i = 0; i < n; i++)
            for (int j = 0, r = (int)i; j < d; j++, r /= side) x[i * d + j] = r % side;
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        const int nv = d + 1;
        for (int k = 0; k < 200 && !LH_FAILED(); k++) {
            double q[8];
            for (int j = 0; j < d; j++) q[j] = 0.5 * (double)(lh_fam_rnd() % (uint64_t)(2 * side - 1));
            lh_index want = -1;
            for (size_t c = 0; c < lh_tri_count(t) && want < 0; c++) {
                const lh_index *v = lh_tri_simplices(t) + c * nv;
                int in = 1;
                for (int f = 0; f < nv && in; f++) {
                    const double *p[9];
                    for (int j = 0; j < nv; j++) p[j] = j == f ? q : x + (size_t)v[j] * d;
                    in = lh_orient(pred, d, p) >= 0;
                }
                if (in) want = (lh_index)c;
            }
            for (int h = -1; h < 3; h++) {
                lh_location loc;
                lh_index hint = h < 0 ? -1 : (lh_index)((size_t)h * lh_tri_count(t) / 3);
                LH_ASSERT_EQ_INT(lh_tri_locate(t, q, hint, &loc), LH_OK);
                if (loc.simplex != want) LH_NOTE("d=%d query %d hint %" LH_INDEX_PRI, d, k, hint);
                LH_EXPECT_EQ_INT(loc.simplex, want);
            }
        }
        lh_tri_free(t);
        free(x);
    }
    lh_pred_free(pred);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(queries_inside_outside_and_on_sites),
                                         LH_CASE(points_on_shared_faces_get_the_smallest_simplex)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
