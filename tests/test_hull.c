/* test_hull.c — lh_convex_hull: every site inside or on every facet (exactly), the
 * facets close up (every ridge in exactly two), no facet flat; in general position
 * the facets are exactly the Delaunay triangulation's hull facets; degenerate and
 * bad inputs. */
#include "lh_test.h"
#include "lifthull.h"

#include <stdlib.h>
#include <string.h>

static uint64_t rng_state;
static double unif(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

/* Exact: all sites on the inner side of (or on) every facet, every facet non-flat
 * (some site strictly inside its hyperplane's inner side), every ridge shared by
 * exactly two facets. */
static void check_hull(lh_test_state *lh_t_, int d, size_t n, const double *x, const lh_hull *h)
{
    lh_pred *p;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &p), LH_OK);
    size_t m = lh_hull_facet_count(h);
    const lh_index *f = lh_hull_facets(h);
    LH_EXPECT_GT_U64(m, (size_t)d);
    for (size_t i = 0; i < m && !LH_FAILED(); i++) {
        const double *pts[9];
        for (int k = 0; k < d; k++) pts[k] = x + (size_t)f[i * d + k] * d;
        int inner = 0;
        for (size_t s = 0; s < n && !LH_FAILED(); s++) {
            pts[d] = x + s * d;
            int o = lh_orient(p, d, pts);
            LH_EXPECT_LE_INT(o, 0);
            inner |= o < 0;
            if (LH_FAILED()) LH_NOTE("d=%d: site %zu outside facet %zu", d, s, i);
        }
        LH_EXPECT_TRUE(inner);
    }
    /* Ridges: (d-1)-subsets of each facet, counted by sorting. */
    size_t r = m * d, w = (size_t)d - 1;
    lh_index *ridge = malloc((r * w + 1) * sizeof *ridge);
    for (size_t i = 0; i < m; i++)
        for (int skip = 0; skip < d; skip++) {
            lh_index *o = ridge + (i * d + skip) * w;
            int q = 0;
            for (int k = 0; k < d; k++)
                if (k != skip) o[q++] = f[i * d + k];
            for (size_t a = 1; a < w; a++)
                for (size_t b = a; b > 0 && o[b] < o[b - 1]; b--) {
                    lh_index t = o[b];
                    o[b] = o[b - 1];
                    o[b - 1] = t;
                }
        }
    /* count occurrences of each ridge by brute force on small inputs */
    for (size_t a = 0; a < r && !LH_FAILED(); a++) {
        int same = 0;
        for (size_t b = 0; b < r; b++) same += memcmp(ridge + a * w, ridge + b * w, w * sizeof *ridge) == 0;
        LH_EXPECT_EQ_INT(same, 2);
    }
    free(ridge);
    lh_pred_free(p);
}

LH_TEST(hull_is_exactly_convex_and_closed)
{
    static const size_t sizes[9] = {0, 0, 400, 300, 120, 60, 35, 25, 20};
    for (int d = 2; d <= 8 && !LH_FAILED(); d++) {
        for (int grid = 0; grid <= 1 && !LH_FAILED(); grid++) {
            size_t n = sizes[d];
            double *x = malloc(n * d * sizeof *x);
            rng_state = (uint64_t)(d * 10 + grid);
            for (size_t i = 0; i < n * d; i++) x[i] = grid ? (double)(int)(3 * unif()) : unif();
            lh_hull *h;
            lh_status st = lh_convex_hull(d, n, x, NULL, &h);
            LH_EXPECT_EQ_INT(st, LH_OK);
            if (st == LH_OK) {
                check_hull(lh_t_, d, n, x, h);
                if (LH_FAILED()) LH_NOTE("d=%d %s", d, grid ? "grid {0,1,2}^d" : "uniform");
                lh_hull_free(h);
            }
            free(x);
        }
    }
}

LH_TEST(general_position_hull_equals_delaunay_hull)
{
    for (int d = 2; d <= 5 && !LH_FAILED(); d++) {
        size_t n = d == 2 ? 2000 : d == 3 ? 1000 : d == 4 ? 300 : 120;
        double *x = malloc(n * d * sizeof *x);
        rng_state = (uint64_t)(77 + d);
        for (size_t i = 0; i < n * d; i++) x[i] = unif();
        lh_hull *h;
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_convex_hull(d, n, x, NULL, &h), LH_OK);
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        LH_EXPECT_EQ_U64(lh_hull_facet_count(h), lh_tri_hull_count(t));
        LH_EXPECT_TRUE(memcmp(lh_hull_facets(h), lh_tri_hull_facets(t), lh_tri_hull_count(t) * d * 4) == 0);
        lh_hull_free(h);
        lh_tri_free(t);
        free(x);
    }
}

LH_TEST(unit_cube_and_bad_input)
{
    double cube[8 * 3 + 3 * 2];
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 3; j++) cube[i * 3 + j] = (i >> j) & 1;
    cube[24] = cube[25] = cube[26] = 0.5; /* an interior site */
    cube[27] = 0.5, cube[28] = 0, cube[29] = 0; /* a site on an edge */
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(3, 10, cube, NULL, &h), LH_OK);
    check_hull(lh_t_, 3, 10, cube, h);
    /* Every corner is a vertex, the interior site never; the edge site may be one
     * (then its facets are coplanar with their neighbours: 14 instead of 12). */
    size_t nv = lh_hull_vertex_count(h);
    const lh_index *v = lh_hull_vertices(h);
    LH_EXPECT_TRUE(nv == 8 || nv == 9);
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_INT(v[i], i);
    if (nv == 9) LH_EXPECT_EQ_INT(v[8], 9);
    LH_EXPECT_EQ_U64(lh_hull_facet_count(h), nv == 8 ? 12 : 14);
    lh_hull_free(h);
    double flat[4 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    LH_EXPECT_EQ_INT(lh_convex_hull(3, 4, flat, NULL, &h), LH_ERR_DEGENERATE);
    LH_EXPECT_EQ_INT(lh_convex_hull(1, 4, flat, NULL, &h), LH_ERR_DIMENSION);
    LH_EXPECT_EQ_INT(lh_convex_hull(9, 4, flat, NULL, &h), LH_ERR_DIMENSION);
    LH_EXPECT_EQ_INT(lh_convex_hull(3, 4, flat, NULL, NULL), LH_ERR_INVALID_ARGUMENT);
    lh_hull_free(NULL);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(hull_is_exactly_convex_and_closed),
                                         LH_CASE(general_position_hull_equals_delaunay_hull),
                                         LH_CASE(unit_cube_and_bad_input)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
