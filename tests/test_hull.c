/* test_hull.c — lh_convex_hull: every site inside or on every facet (exactly), the
 * facets close up (every ridge in exactly two), no facet flat; in general position
 * the facets are exactly the Delaunay triangulation's hull facets; on degenerate
 * input the vertices are exactly the corners and the facets do not depend on the
 * input order or the seed; bad inputs. */
#include "lh_families.h"
#include "lh_test.h"
#include "lifthull.h"

#include <stdlib.h>
#include <string.h>


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
            lh_fam_seed((uint64_t)(d * 10 + grid));
            for (size_t i = 0; i < n * d; i++) x[i] = grid ? (double)(int)(3 * lh_fam_unif()) : lh_fam_unif();
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
        lh_fam_seed((uint64_t)(77 + d));
        for (size_t i = 0; i < n * d; i++) x[i] = lh_fam_unif();
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

/* Whether site v is a corner of the hull of the n sites: outside the hull of the
 * sites other than v (and its duplicates), or needed for them to span R^d. */
static int is_corner(lh_pred *p, int d, size_t n, const double *x, size_t v)
{
    double *y = malloc((n * d + 1) * sizeof *y);
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (memcmp(x + i * d, x + v * d, d * sizeof *x)) memcpy(y + m++ * d, x + i * d, d * sizeof *y);
    lh_hull *h;
    int corner = 1;
    if (lh_convex_hull(d, m, y, NULL, &h) == LH_OK) {
        const lh_index *f = lh_hull_facets(h);
        corner = 0;
        for (size_t i = 0; i < lh_hull_facet_count(h) && !corner; i++) {
            const double *pts[9];
            for (int k = 0; k < d; k++) pts[k] = y + (size_t)f[i * d + k] * d;
            pts[d] = x + v * d;
            corner = lh_orient(p, d, pts) > 0;
        }
        lh_hull_free(h);
    }
    free(y);
    return corner;
}

/* The facets as site-index tuples through map (NULL: as they are), each in
 * canonical order (increasing, the last two exchanged on an odd sort), sorted. */
static int facet_d;
static int cmp_tuple(const void *a, const void *b)
{
    const lh_index *x = a, *y = b;
    for (int k = 0; k < facet_d; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}
static lh_index *canonical_facets(const lh_hull *h, const lh_index *map)
{
    const int d = lh_hull_dim(h);
    size_t m = lh_hull_facet_count(h);
    lh_index *f = malloc((m * d + 1) * sizeof *f);
    for (size_t i = 0; i < m; i++) {
        lh_index *t = f + i * d;
        int odd = 0;
        for (int k = 0; k < d; k++) t[k] = map ? map[lh_hull_facets(h)[i * d + k]] : lh_hull_facets(h)[i * d + k];
        for (int a = 1; a < d; a++)
            for (int b = a; b > 0 && t[b] < t[b - 1]; b--) {
                lh_index x = t[b];
                t[b] = t[b - 1];
                t[b - 1] = x;
                odd ^= 1;
            }
        if (odd) {
            lh_index x = t[d - 1];
            t[d - 1] = t[d - 2];
            t[d - 2] = x;
        }
    }
    facet_d = d;
    qsort(f, m, d * sizeof *f, cmp_tuple);
    return f;
}

/* On degenerate sets (grids, points on the faces of a cube, on a square's sides):
 * the vertices are exactly the corners (each checked against the hull of the other
 * sites), and reversing or shuffling the input or changing the seed gives the same
 * facets up to the renumbering. */
LH_TEST(vertices_are_corners_whatever_the_order)
{
    lh_pred *p;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &p), LH_OK);
    for (int d = 2; d <= 5 && !LH_FAILED(); d++)
        for (int kind = 0; kind < 3 && !LH_FAILED(); kind++) {
            size_t n = d == 2 ? 120 : d == 3 ? 90 : d == 4 ? 60 : 40;
            double *x = malloc(n * d * sizeof *x);
            lh_fam_seed((uint64_t)(1000 + 10 * d + kind));
            for (size_t i = 0; i < n; i++)
                for (int j = 0; j < d; j++) {
                    double *c = x + i * d + j;
                    if (kind == 0) *c = (double)(int)(3 * lh_fam_unif()); /* {0,1,2}^d */
                    else *c = (double)(int)(64 * lh_fam_unif()) / 64; /* dyadic, in [0, 1) */
                    if (kind == 1 && j == (int)(i % d)) *c = (double)(i / d % 2); /* on a face of the unit cube */
                    if (kind == 2 && j == (int)(i % d) && i % 5) *c = 1; /* on a face through (1,..,1) */
                }
            lh_hull *h;
            LH_ASSERT_EQ_INT(lh_convex_hull(d, n, x, NULL, &h), LH_OK);
            check_hull(lh_t_, d, n, x, h);
            const lh_index *v = lh_hull_vertices(h), *dup = lh_hull_duplicate_of(h);
            size_t k = 0, corners = 0;
            for (size_t i = 0; i < n && !LH_FAILED(); i++) {
                if (dup[i] != (lh_index)i) continue;
                int corner = is_corner(p, d, n, x, i);
                int vertex = k < lh_hull_vertex_count(h) && v[k] == (lh_index)i;
                k += vertex;
                corners += corner;
                LH_EXPECT_EQ_INT(vertex, corner);
                if (LH_FAILED()) LH_NOTE("d=%d kind %d: site %zu corner %d vertex %d", d, kind, i, corner, vertex);
            }
            LH_EXPECT_EQ_U64(lh_hull_vertex_count(h), corners);
            lh_index *want = canonical_facets(h, NULL);
            for (int how = 0; how < 3 && !LH_FAILED(); how++) {
                /* y[i] = x[perm[i]]: reversed, or shuffled; or the seed changed */
                double *y = malloc(n * d * sizeof *y);
                lh_index *perm = malloc(n * sizeof *perm);
                for (size_t i = 0; i < n; i++) perm[i] = how == 0 ? (lh_index)(n - 1 - i) : (lh_index)i;
                for (size_t i = n; how == 1 && i > 1; i--) {
                    size_t j = (size_t)(lh_fam_unif() * (double)i);
                    lh_index t = perm[i - 1];
                    perm[i - 1] = perm[j];
                    perm[j] = t;
                }
                for (size_t i = 0; i < n; i++) memcpy(y + i * d, x + (size_t)perm[i] * d, d * sizeof *y);
                lh_options o;
                lh_options_default(&o);
                o.seed = how == 2 ? 0x9e3779b97f4a7c15u : o.seed;
                lh_hull *g;
                LH_ASSERT_EQ_INT(lh_convex_hull(d, n, y, &o, &g), LH_OK);
                /* duplicates: compare through each one's representative */
                lh_index *map = malloc(n * sizeof *map);
                for (size_t i = 0; i < n; i++) map[i] = dup[perm[i]];
                lh_index *got = canonical_facets(g, map);
                LH_EXPECT_EQ_U64(lh_hull_facet_count(g), lh_hull_facet_count(h));
                if (lh_hull_facet_count(g) == lh_hull_facet_count(h))
                    LH_EXPECT_TRUE(!memcmp(got, want, lh_hull_facet_count(h) * d * sizeof *got));
                if (LH_FAILED()) LH_NOTE("d=%d kind %d: %s", d, kind, how == 0 ? "reversed" : how == 1 ? "shuffled" : "seed");
                free(got);
                free(map);
                lh_hull_free(g);
                free(perm);
                free(y);
            }
            free(want);
            lh_hull_free(h);
            free(x);
        }
    lh_pred_free(p);
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
    /* The corners are the vertices, the interior site and the one on an edge not. */
    LH_ASSERT_EQ_U64(lh_hull_vertex_count(h), 8);
    const lh_index *v = lh_hull_vertices(h);
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_INT(v[i], i);
    LH_EXPECT_EQ_U64(lh_hull_facet_count(h), 12);
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
                                         LH_CASE(vertices_are_corners_whatever_the_order),
                                         LH_CASE(unit_cube_and_bad_input)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
