/* test_hostile.c — the API half of the hostile input catalogue (docs/hostile-inputs.md):
 * coordinates at the ends of the double range (2^±1000, subnormals, DBL_MAX, mixed
 * magnitudes) triangulated exactly and identically to their unit-scale copies; 10^6
 * identical sites rejected fast and small; duplicates only; collinear and coplanar
 * sites; exactly cocircular sites; sites on hull facets; queries on boundaries; what
 * the reader makes of extreme numbers and of megabyte lines. Each test names its rows
 * of the catalogue. Reader diagnostics proper are in test_io_read.c. */
#include "lh_api_test.h"
#include "lh_families.h"
#include "lh_test.h"
#include "lifthull.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TEXT(s) s, sizeof(s) - 1

/* ---- helpers ------------------------------------------------------------------------ */

/* An allocator that records the peak of live bytes and the largest block. */
typedef struct peak {
    size_t live, peak, largest;
} peak;

static void *peak_alloc(void *user, size_t size)
{
    peak *p = user;
    size_t *b = malloc(size + sizeof(max_align_t));
    if (!b) return NULL;
    *b = size;
    p->live += size;
    if (p->live > p->peak) p->peak = p->live;
    if (size > p->largest) p->largest = size;
    return (char *)b + sizeof(max_align_t);
}

static void peak_free(void *user, void *ptr)
{
    if (!ptr) return;
    size_t *b = (size_t *)(void *)((char *)ptr - sizeof(max_align_t));
    ((peak *)user)->live -= *b;
    free(b);
}


static lh_status read_text(const char *text, size_t len, lh_points *p, lh_error *err)
{
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_points_read(f, "h", LH_FORMAT_AUTO, NULL, p, err);
    fclose(f);
    return st;
}

/* A deterministic degenerate set: n small integer points in [0, 8)^d (many cospherical,
 * collinear and duplicate subsets), the first d+1 a corner simplex so they span R^d. */
static void integer_sites(int d, size_t n, double *x)
{
    uint64_t s = 0x9e3779b97f4a7c15u * (uint64_t)(d + 1);
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < d; j++) {
            s = s * 6364136223846793005u + 1442695040888963407u;
            x[i * (size_t)d + j] = i <= (size_t)d ? (double)(8 * (i == (size_t)j + 1)) : (double)((s >> 33) % 8);
        }
}

/* lh_delaunay and lh_convex_hull of x scaled by 2^e (exact: integer inputs) must give
 * the same arrays as the unscaled x, and pass the exact check. */
static void expect_scale_invariant(lh_test_state *lh_t_, int d, size_t n, const double *x, int e)
{
    double *y = malloc(n * (size_t)d * sizeof *y);
    LH_ASSERT_TRUE(y != NULL);
    for (size_t i = 0; i < n * (size_t)d; i++) {
        y[i] = ldexp(x[i], e);
        LH_ASSERT_TRUE(ldexp(y[i], -e) == x[i]); /* the scaling is exact */
    }
    lh_tri *a = NULL, *b = NULL;
    lh_hull *ha = NULL, *hb = NULL;
    LH_EXPECT_EQ_INT(lh_delaunay(d, n, x, NULL, &a), LH_OK);
    LH_EXPECT_EQ_INT(lh_delaunay(d, n, y, NULL, &b), LH_OK);
    LH_EXPECT_EQ_INT(lh_convex_hull(d, n, x, NULL, &ha), LH_OK);
    LH_EXPECT_EQ_INT(lh_convex_hull(d, n, y, NULL, &hb), LH_OK);
    if (a && b && ha && hb) {
        lh_error err;
        LH_EXPECT_EQ_INT(lh_tri_check(b, &err), LH_OK);
        if (LH_FAILED()) LH_NOTE("%s", err.message);
        LH_EXPECT_EQ_U64(lh_tri_count(b), lh_tri_count(a));
        LH_EXPECT_EQ_U64(lh_tri_duplicate_count(b), lh_tri_duplicate_count(a));
        if (lh_tri_count(a) == lh_tri_count(b))
            LH_EXPECT_TRUE(!memcmp(lh_tri_simplices(a), lh_tri_simplices(b),
                                   lh_tri_count(a) * (size_t)(d + 1) * sizeof(lh_index)));
        /* The hull: exactly convex at the new scale (no site strictly outside a facet),
         * its vertices the same corners as at the unit scale (before issue 30, which
         * boundary sites were vertices changed at 2^-1050 and below in 2D). */
        LH_EXPECT_EQ_U64(lh_hull_vertex_count(hb), lh_hull_vertex_count(ha));
        if (lh_hull_vertex_count(ha) == lh_hull_vertex_count(hb))
            LH_EXPECT_TRUE(!memcmp(lh_hull_vertices(ha), lh_hull_vertices(hb),
                                   lh_hull_vertex_count(ha) * sizeof(lh_index)));
        LH_EXPECT_EQ_U64(lh_hull_facet_count(hb), lh_hull_facet_count(ha));
        if (lh_hull_facet_count(ha) == lh_hull_facet_count(hb))
            LH_EXPECT_TRUE(!memcmp(lh_hull_facets(ha), lh_hull_facets(hb),
                                   lh_hull_facet_count(ha) * (size_t)d * sizeof(lh_index)));
        lh_pred *pred;
        LH_ASSERT_EQ_INT(lh_pred_create(NULL, &pred), LH_OK);
        for (size_t f = 0; f < lh_hull_facet_count(hb); f++)
            for (size_t i = 0; i < n; i++) {
                const double *p[9];
                for (int j = 0; j < d; j++) p[j] = y + (size_t)lh_hull_facets(hb)[f * (size_t)d + j] * (size_t)d;
                p[d] = y + i * (size_t)d;
                LH_EXPECT_LE_INT(lh_orient(pred, d, p), 0);
            }
        lh_pred_free(pred);
        /* point location decides inside/outside and the simplex exactly, at any scale */
        double q[8], qy[8];
        for (int k = 0; k < 20; k++) {
            for (int j = 0; j < d; j++) {
                q[j] = (double)((k * 7 + j * 3) % 11 - 1); /* on sites, edges; outside */
                qy[j] = ldexp(q[j], e);
            }
            lh_location la, lb;
            LH_EXPECT_EQ_INT(lh_tri_locate(a, q, -1, &la), LH_OK);
            LH_EXPECT_EQ_INT(lh_tri_locate(b, qy, -1, &lb), LH_OK);
            LH_EXPECT_EQ_INT(lb.simplex, la.simplex);
            lh_index na = -1, nb = -1;
            if (la.simplex >= 0) { /* outside at 2^1000: lh_tri_nearest is defect 1 */
                LH_EXPECT_EQ_INT(lh_tri_nearest(a, q, -1, &na), LH_OK);
                LH_EXPECT_EQ_INT(lh_tri_nearest(b, qy, -1, &nb), LH_OK);
                LH_EXPECT_EQ_INT(nb, na);
            }
        }
    }
    if (LH_FAILED()) LH_NOTE("d %d, n %zu, scale 2^%d", d, n, e);
    lh_tri_free(a);
    lh_tri_free(b);
    lh_hull_free(ha);
    lh_hull_free(hb);
    free(y);
}

/* ---- coordinate range ----------------------------------------------------------------- */

/* Rows "1e300 (squares overflow)", "1e-300", "subnormals": integers in [0, 8) scaled to
 * 2^1016 (|x|^2 far beyond DBL_MAX), 2^-1000 (|x|^2 far below the least subnormal)
 * and 2^-1074 (every coordinate a subnormal), in 2D to 4D. */
LH_TEST(extreme_scales_triangulate_as_the_unit_scale)
{
    static const int scales[] = {1016, 996, -1000, -1074, -1060};
    for (int d = 2; d <= 4 && !LH_FAILED(); d++) {
        size_t n = d == 2 ? 60 : 40;
        double x[60 * 4];
        integer_sites(d, n, x);
        for (size_t s = 0; s < LH_COUNT(scales) && !LH_FAILED(); s++)
            expect_scale_invariant(lh_t_, d, n, x, scales[s]);
    }
}

/* Rows "DBL_MAX" and "mixed 1e300 / 1e-300 / 5e-324": the triangulation is exactly
 * valid and has 2n - 2 - h triangles (every site a vertex, h of them on the hull). */
LH_TEST(largest_and_mixed_magnitudes)
{
    const double M = DBL_MAX;
    const double big[] = {-M, -M, M, -M, -M, M, M, M, 0, 0, M / 2, -M / 3, 5e-324, 5e-324};
    const double mixed[] = {0, 0,        1e300,  0,     0,      1e-300, 1e300, 1e300,
                            5e-324, 5e-324, -1e-300, 1e300, 1e-300, -1e300, 3e-310, 2e-320,
                            -1e300, -5e-324, 1, 1};
    const struct {
        const double *x;
        size_t n;
    } sets[] = {{big, 7}, {mixed, 10}};
    for (size_t k = 0; k < LH_COUNT(sets); k++) {
        lh_tri *t;
        lh_error err;
        LH_ASSERT_EQ_INT(lh_delaunay(2, sets[k].n, sets[k].x, NULL, &t), LH_OK);
        LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
        LH_EXPECT_EQ_U64(lh_tri_count(t), 2 * sets[k].n - 2 - lh_tri_hull_count(t));
        for (size_t i = 0; i < sets[k].n; i++) LH_EXPECT_TRUE(lh_tri_vertex_simplex(t)[i] >= 0);
        lh_tri_free(t);
        lh_hull *h;
        LH_ASSERT_EQ_INT(lh_convex_hull(2, sets[k].n, sets[k].x, NULL, &h), LH_OK);
        LH_EXPECT_TRUE(lh_hull_facet_count(h) >= 3);
        lh_hull_free(h);
        if (LH_FAILED()) LH_NOTE("set %zu: %s", k, err.message);
    }
    /* 3D: the corners of the largest cube, its centre and a subnormal site. */
    double cube[10 * 3];
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 3; j++) cube[i * 3 + j] = (i >> j) & 1 ? M : -M;
    cube[24] = cube[25] = cube[26] = 0;
    cube[27] = 5e-324, cube[28] = -5e-324, cube[29] = 1e-310;
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, 10, cube, NULL, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_tri_free(t);
}

/* Rows "NaN", "+Inf", "-Inf": every entry point that takes coordinates refuses them;
 * a failed insertion leaves the triangulation as it was. */
LH_TEST(nonfinite_coordinates_everywhere)
{
    double x[] = {0, 0, 1, 0, 0, 1, 1, 1};
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t b = 0; b < LH_COUNT(bad); b++) {
        double y[8];
        memcpy(y, x, sizeof y);
        y[5] = bad[b];
        lh_tri *t = (lh_tri *)y;
        lh_hull *h = (lh_hull *)y;
        lh_error at;
        int k = 7;
        LH_EXPECT_EQ_INT(lh_coords_validate(2, 4, y, &at), LH_ERR_NONFINITE);
        LH_EXPECT_EQ_U64(at.index, 5);
        LH_EXPECT_EQ_INT(lh_delaunay(2, 4, y, NULL, &t), LH_ERR_NONFINITE);
        LH_EXPECT_TRUE(t == NULL);
        LH_EXPECT_EQ_INT(lh_convex_hull(2, 4, y, NULL, &h), LH_ERR_NONFINITE);
        LH_EXPECT_TRUE(h == NULL);
        LH_EXPECT_EQ_INT(lh_coords_affine_dim(2, 4, y, NULL, &k), LH_ERR_NONFINITE);
        LH_ASSERT_EQ_INT(lh_delaunay(2, 4, x, NULL, &t), LH_OK);
        lh_location loc;
        lh_index site;
        LH_EXPECT_EQ_INT(lh_tri_locate(t, y + 4, -1, &loc), LH_ERR_NONFINITE);
        LH_EXPECT_EQ_INT(lh_tri_nearest(t, y + 4, -1, &site), LH_ERR_NONFINITE);
        LH_EXPECT_EQ_INT(lh_tri_insert(t, 2, y + 2), LH_ERR_NONFINITE);
        LH_EXPECT_EQ_U64(lh_tri_site_count(t), 4);
        LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
        lh_tri_free(t);
    }
}

/* ---- duplicates ------------------------------------------------------------------------ */

/* Row "10^6 identical points": LH_ERR_DEGENERATE (affine dimension 0) from lh_delaunay
 * with and without affine_hull and from lh_convex_hull, in well under a second each,
 * with at most 8d + 20 bytes per site allocated and three indices' width more: 8d + 32
 * (measured 8d + 29: a copy of the coordinates, two Hilbert keys and three indices);
 * 8d + 44 with 64-bit indices (measured 8d + 41). */
LH_TEST(a_million_identical_sites)
{
    const size_t n = 1000000;
    for (int d = 2; d <= 3; d++) {
        double *x = malloc(n * (size_t)d * sizeof *x);
        LH_ASSERT_TRUE(x != NULL);
        for (size_t i = 0; i < n * (size_t)d; i++) x[i] = i % (size_t)d ? -5e-324 : 1e300;
        peak p = {0, 0, 0};
        lh_allocator a = {peak_alloc, peak_free, &p};
        lh_options opt;
        lh_options_default(&opt);
        opt.alloc = &a;
        clock_t c0 = clock();
        lh_tri *t = (lh_tri *)x;
        LH_EXPECT_EQ_INT(lh_delaunay(d, n, x, &opt, &t), LH_ERR_DEGENERATE);
        LH_EXPECT_TRUE(t == NULL);
        opt.affine_hull = 1;
        LH_EXPECT_EQ_INT(lh_delaunay(d, n, x, &opt, &t), LH_ERR_DEGENERATE);
        opt.affine_hull = 0;
        lh_hull *h = (lh_hull *)x;
        LH_EXPECT_EQ_INT(lh_convex_hull(d, n, x, &opt, &h), LH_ERR_DEGENERATE);
        LH_EXPECT_TRUE(h == NULL);
        int k = 7;
        LH_EXPECT_EQ_INT(lh_coords_affine_dim(d, n, x, NULL, &k), LH_OK);
        LH_EXPECT_EQ_INT(k, 0);
        double secs = (double)(clock() - c0) / CLOCKS_PER_SEC;
        LH_EXPECT_LE_DBL(secs, 10.0); /* measured 0.5 s (2D), 0.7 s (3D) for the four calls, Release */
        LH_EXPECT_EQ_U64(p.live, 0);
        LH_EXPECT_LE_U64(p.peak, n * ((size_t)d * 8 + 20 + 3 * sizeof(lh_index)));
        if (LH_FAILED()) LH_NOTE("d %d: %.2f s, peak %zu bytes, largest block %zu", d, secs, p.peak, p.largest);
        free(x);
    }
}

/* Row "all points duplicates of one": any count, any dimension: dimension 0. */
LH_TEST(all_duplicates_of_one_site)
{
    for (int d = 2; d <= 8; d++) {
        double x[5 * 8];
        for (int i = 0; i < 5 * d; i++) x[i] = 0.1 * (i % d);
        lh_tri *t;
        lh_options opt;
        lh_options_default(&opt);
        opt.affine_hull = 1;
        int k = 7;
        LH_EXPECT_EQ_INT(lh_delaunay(d, 5, x, &opt, &t), LH_ERR_DEGENERATE);
        LH_EXPECT_EQ_INT(lh_coords_affine_dim(d, 5, x, NULL, &k), LH_OK);
        LH_EXPECT_EQ_INT(k, 0);
    }
}

/* ---- lower-dimensional input -------------------------------------------------------------- */

/* Rows "collinear 2D/3D", "coplanar 3D": LH_ERR_DEGENERATE with the affine dimension;
 * with affine_hull the chain of n-1 segments, or the triangles within the plane;
 * lh_convex_hull always LH_ERR_DEGENERATE. */
LH_TEST(collinear_and_coplanar_sites)
{
    const double line2[] = {0, 0, 3, 3, 1, 1, 2, 2, 1e300, 1e300};
    const double line3[] = {0, 0, 0, 3, 3, 3, 1, 1, 1, 2, 2, 2};
    const double plane[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0};
    const struct {
        int d;
        size_t n;
        const double *x;
        int k;
        size_t count;
    } cases[] = {{2, 5, line2, 1, 4}, {3, 4, line3, 1, 3}, {3, 5, plane, 2, 4}};
    for (size_t c = 0; c < LH_COUNT(cases); c++) {
        lh_tri *t;
        lh_hull *h;
        int k = 7;
        LH_EXPECT_EQ_INT(lh_delaunay(cases[c].d, cases[c].n, cases[c].x, NULL, &t), LH_ERR_DEGENERATE);
        LH_EXPECT_EQ_INT(lh_convex_hull(cases[c].d, cases[c].n, cases[c].x, NULL, &h), LH_ERR_DEGENERATE);
        LH_EXPECT_EQ_INT(lh_coords_affine_dim(cases[c].d, cases[c].n, cases[c].x, NULL, &k), LH_OK);
        LH_EXPECT_EQ_INT(k, cases[c].k);
        lh_options opt;
        lh_options_default(&opt);
        opt.affine_hull = 1;
        LH_ASSERT_EQ_INT(lh_delaunay(cases[c].d, cases[c].n, cases[c].x, &opt, &t), LH_OK);
        LH_EXPECT_EQ_INT(lh_tri_simplex_dim(t), cases[c].k);
        LH_EXPECT_EQ_U64(lh_tri_count(t), cases[c].count);
        LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
        lh_tri_free(t);
        if (LH_FAILED()) LH_NOTE("case %zu", c);
    }
}

/* ---- exact degeneracies: cocircular sites, sites on facets ------------------------------- */

static void expect_count(lh_test_state *lh_t_, int d, size_t n, const double *x, size_t count,
                         size_t complex_cells)
{
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), count);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    size_t cells = 0;
    const lh_index *off, *v;
    LH_EXPECT_EQ_INT(lh_tri_complex(t, &cells, &off, &v), LH_OK);
    LH_EXPECT_EQ_U64(cells, complex_cells);
    lh_tri_free(t);
}

/* Rows "cocircular square + centre", "12 sites on one circle", "grids": the
 * perturbation picks one triangulation; the Delaunay complex merges the cospherical
 * cells back. */
LH_TEST(sites_on_a_common_circumsphere)
{
    const double sqc[] = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5};
    expect_count(lh_t_, 2, 4, sqc, 2, 1);
    expect_count(lh_t_, 2, 5, sqc, 4, 4);
    /* x^2 + y^2 = 25 at 12 integer points: one cell of 12 sites, 10 triangles. */
    const double circle[] = {5, 0, 4, 3, 3, 4, 0, 5, -3, 4, -4, 3, -5, 0, -4, -3, -3, -4, 0, -5, 3, -4, 4, -3};
    expect_count(lh_t_, 2, 12, circle, 10, 1);
    double grid2[100 * 2], grid3[125 * 3];
    for (int i = 0; i < 100; i++) grid2[2 * i] = i / 10, grid2[2 * i + 1] = i % 10;
    for (int i = 0; i < 125; i++)
        for (int j = 0; j < 3; j++) grid3[3 * i + j] = (i / (j == 0 ? 1 : j == 1 ? 5 : 25)) % 5;
    expect_count(lh_t_, 2, 100, grid2, 162, 81);
    expect_count(lh_t_, 3, 125, grid3, 384, 64);
    /* the same grid far out of the filter's band: the same answer */
    for (int i = 0; i < 125 * 3; i++) grid3[i] = ldexp(grid3[i], -1070);
    expect_count(lh_t_, 3, 125, grid3, 384, 64);
}

/* Row "lattice points on a sphere ... scaled": exactly cospherical lattice points in
 * 2D-5D (every insphere among them a perturbed zero) scaled by odd integers, whose
 * spans run from within the range where the engine's static filters are exact on
 * integer sites (lift/insert_lifted.h: 2D up to about 5000, 3D 650, 4D 160, 5D 59)
 * to far past it, where products round: the triangulation of the unscaled points,
 * and exactly valid. */
LH_TEST(scaled_lattice_spheres_triangulate_alike)
{
    static const double scales[] = {3, 13, 29, 41, 71, 101, 10007, 1000003, 0x1p40 + 1};
    /* 2D: the 48 points of the circle |v|^2 = 5525 (coordinates up to 74), so that the
     * small scales stay inside the filters' exact range and every scaling is exact */
    static const size_t count[6] = {0, 0, 48, 300, 300, 300};
    for (int d = 2; d <= 5 && !LH_FAILED(); d++) {
        double x[300 * 5], y[300 * 5];
        lh_fam_seed((uint64_t)(31 * d));
        const size_t n = lh_fam_make(F_SPHERE_EXACT, d, count[d], x);
        LH_ASSERT_EQ_U64(n, count[d]);
        lh_tri *a = NULL;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &a), LH_OK);
        for (size_t s = 0; s < LH_COUNT(scales) && !LH_FAILED(); s++) {
            for (size_t i = 0; i < n * (size_t)d; i++) {
                y[i] = x[i] * scales[s];
                LH_ASSERT_TRUE(fma(x[i], scales[s], -y[i]) == 0); /* the lattice, scaled */
            }
            lh_tri *b = NULL;
            LH_EXPECT_EQ_INT(lh_delaunay(d, n, y, NULL, &b), LH_OK);
            LH_EXPECT_TRUE(b && lh_test_same_tri(a, b));
            if (b) LH_EXPECT_EQ_INT(lh_tri_check(b, NULL), LH_OK);
            if (LH_FAILED()) LH_NOTE("d %d, %zu sites, scale %.17g", d, n, scales[s]);
            lh_tri_free(b);
        }
        lh_tri_free(a);
    }
}

/* Rows "site exactly on a hull facet": Delaunay makes it a vertex (every site is one);
 * the convex hull may (coplanar facets, never flat ones). A query exactly on the
 * hull's boundary is inside (distance 0), in the smallest simplex holding it. */
LH_TEST(sites_and_queries_on_hull_facets)
{
    const double edge[] = {0, 0, 2, 0, 0, 2, 1, 0};
    const double face[] = {0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0, 3, 1, 1, 0};
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 4, edge, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 2);
    LH_EXPECT_EQ_U64(lh_tri_hull_count(t), 4);
    LH_EXPECT_TRUE(lh_tri_vertex_simplex(t)[3] >= 0);
    const double on_hull[2] = {0.5, 0}, at_site[2] = {1, 0};
    lh_location loc;
    LH_EXPECT_EQ_INT(lh_tri_locate(t, on_hull, -1, &loc), LH_OK);
    LH_EXPECT_TRUE(loc.simplex >= 0 && loc.hull_facet == -1 && loc.distance == 0);
    LH_EXPECT_EQ_INT(lh_tri_locate(t, at_site, 1, &loc), LH_OK);
    LH_EXPECT_EQ_INT(loc.simplex, 0); /* site 3 is in both triangles: the smaller */
    lh_tri_free(t);
    LH_ASSERT_EQ_INT(lh_delaunay(3, 5, face, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 3);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_tri_free(t);
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(3, 5, face, NULL, &h), LH_OK);
    size_t nv = lh_hull_vertex_count(h);
    LH_EXPECT_TRUE(nv == 4 || nv == 5);
    LH_EXPECT_EQ_U64(lh_hull_facet_count(h), nv == 4 ? 4 : 6);
    lh_hull_free(h);
}

/* ---- the reader at the extremes ------------------------------------------------------------ */

/* Rows "subnormal 5e-324", "1e-999 underflows", "-0", "hex floats": strtod's correctly
 * rounded value is kept (an underflow to 0 or to a subnormal is not an error; an
 * overflow is, see test_io_read). */
LH_TEST(reader_keeps_extreme_doubles)
{
    lh_points p;
    lh_error err;
    LH_ASSERT_EQ_INT(read_text(TEXT("2 4\n5e-324 -1e-999\n1.7976931348623157e308 0x1p-1074\n"
                                    "-0 2.4703282292062328e-324\n1e300 1e-300\n"),
                               &p, &err),
                     LH_OK);
    LH_ASSERT_EQ_U64(p.n, 4);
    const double want[] = {4.9406564584124654e-324, -0.0, DBL_MAX, 4.9406564584124654e-324, -0.0,
                           4.9406564584124654e-324, 1e300, 1e-300};
    for (int i = 0; i < 8; i++) LH_EXPECT_EQ_DBL(p.xyz[i], want[i]);
    LH_EXPECT_TRUE(signbit(p.xyz[1]) && signbit(p.xyz[4]));
    lh_points_free(&p);
}

/* Rows "a 1 MB line of numbers", "a 1 MB comment", "1 MB of blanks": lines have no
 * length limit, only tokens (LH_READ_MAX_TOKEN). */
LH_TEST(reader_takes_megabyte_lines)
{
    const size_t n = 100000; /* 2n numbers on one line: ~1.2 MB */
    size_t cap = 64 + n * 16 + (1u << 20) * 2;
    char *s = malloc(cap), *w = s;
    LH_ASSERT_TRUE(s != NULL);
    w += sprintf(w, "#");
    memset(w, 'x', 1u << 20), w += 1u << 20;
    w += sprintf(w, "\n2 %zu\n", n);
    memset(w, ' ', 1u << 20), w += 1u << 20;
    for (size_t i = 0; i < n; i++) w += sprintf(w, "%zu %zu ", i % 1000, i / 1000);
    w += sprintf(w, "\r\n");
    lh_points p;
    lh_error err;
    lh_status st = read_text(s, (size_t)(w - s), &p, &err);
    free(s);
    LH_ASSERT_EQ_INT(st, LH_OK);
    LH_EXPECT_EQ_INT(p.format, LH_FORMAT_QHULL);
    LH_EXPECT_EQ_U64(p.n, n);
    LH_EXPECT_EQ_DBL(p.xyz[2 * n - 2], 999);
    LH_EXPECT_EQ_DBL(p.xyz[2 * n - 1], 99);
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, p.n, p.xyz, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 2 * 999 * 99); /* a 1000 x 100 grid */
    lh_tri_free(t);
    lh_points_free(&p);
}

/* Constructions at every scale: the unit square + centre scaled by 2^e for e from
 * -1070 to +1020 gives the same barycentric coordinates, circumcentres (scaled),
 * interpolated values, nearest sites and outside distances (scaled) as at e = 0, to
 * a few units in the last place: computed on coordinates scaled by a power of two. */
LH_TEST(constructions_at_extreme_scales)
{
    static const int exps[] = {-1070, -1060, -1000, -300, 0, 300, 1000, 1020};
    const double unit[10] = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5};
    const double q[2] = {0.25, 0.5}, out_q[2] = {3, 0.5};
    for (size_t i = 0; i < LH_COUNT(exps); i++) {
        int e = exps[i];
        double x[10], v[5], qs[2] = {ldexp(q[0], e), ldexp(q[1], e)}, os[2] = {ldexp(out_q[0], e), ldexp(out_q[1], e)};
        for (int k = 0; k < 10; k++) x[k] = ldexp(unit[k], e);
        for (int k = 0; k < 5; k++) v[k] = 1 + unit[2 * k] + 2 * unit[2 * k + 1]; /* 1 + x + 2y, unscaled */
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(2, 5, x, NULL, &t), LH_OK);
        lh_location loc;
        LH_ASSERT_EQ_INT(lh_tri_locate(t, qs, -1, &loc), LH_OK);
        LH_ASSERT_TRUE(loc.simplex >= 0);
        double sum = 0;
        for (int k = 0; k < 3; k++) sum += loc.bary[k] * unit[2 * lh_tri_simplices(t)[loc.simplex * 3 + k]];
        LH_EXPECT_LE_DBL(fabs(sum - q[0]), 1e-15);
        double out[3];
        for (int m = 0; m < 3; m++) {
            LH_ASSERT_EQ_INT(lh_tri_interpolate(t, (lh_interp_method)m, 1, qs, 1, v, &out[m]), LH_OK);
        }
        LH_EXPECT_LE_DBL(fabs(out[0] - 2.25), 1e-14); /* linear: 1 + 0.25 + 1 */
        LH_EXPECT_LE_DBL(fabs(out[1] - 2.25), 1e-13); /* natural */
        LH_EXPECT_EQ_DBL(out[2], v[4]);               /* nearest: the centre */
        const double *c;
        LH_ASSERT_EQ_INT(lh_tri_circumcenters(t, &c), LH_OK);
        for (size_t s = 0; s < lh_tri_count(t) * 2; s++) {
            double cu = ldexp(c[s], -e); /* each centre of the unit case is 0, 0.5 or 1 */
            LH_EXPECT_LE_DBL(fabs(cu - round(2 * cu) / 2), 1e-15);
        }
        LH_ASSERT_EQ_INT(lh_tri_locate(t, os, -1, &loc), LH_OK);
        LH_EXPECT_EQ_INT(loc.simplex, -1);
        LH_EXPECT_TRUE(loc.hull_facet >= 0);
        LH_EXPECT_LE_DBL(fabs(ldexp(loc.distance, -e) - 2), 1e-15);
        lh_index near;
        LH_EXPECT_EQ_INT(lh_tri_nearest(t, os, -1, &near), LH_OK);
        LH_EXPECT_EQ_INT(near, 1); /* (1,0) and (1,1) tie: the smaller index */
        if (LH_FAILED()) LH_NOTE("scale 2^%d", e);
        lh_tri_free(t);
    }
}

/* The index limit: at most LH_INDEX_MAX - 1 sites; LH_INDEX_MAX of them is
 * LH_ERR_TOO_LARGE before any coordinate is read (x holds two: ASan would see a read).
 * With 64-bit indices n*d doubles would not fit in size_t either: both checks say so. */
LH_TEST(the_site_count_limit)
{
    const double x[2] = {0, 0};
    const size_t n = (size_t)LH_INDEX_MAX;
    lh_tri *t = (lh_tri *)x;
    lh_hull *h = (lh_hull *)x;
    int k;
    LH_EXPECT_EQ_INT(lh_delaunay(2, n, x, NULL, &t), LH_ERR_TOO_LARGE);
    LH_EXPECT_TRUE(t == NULL);
    LH_EXPECT_EQ_INT(lh_convex_hull(2, n, x, NULL, &h), LH_ERR_TOO_LARGE);
    LH_EXPECT_TRUE(h == NULL);
    LH_EXPECT_EQ_INT(lh_coords_affine_dim(2, n, x, NULL, &k), LH_ERR_TOO_LARGE);
    const double three[6] = {0, 0, 1, 0, 0, 1};
    LH_ASSERT_EQ_INT(lh_delaunay(2, 3, three, NULL, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_insert(t, n - 3, x), LH_ERR_TOO_LARGE); /* n - 3 + 3 = LH_INDEX_MAX */
    LH_EXPECT_EQ_U64(lh_tri_site_count(t), 3);
    lh_tri_free(t);
}

/* lh_delaunay_check with counts no array can have: 2^60 simplices in 3D made a
 * 4-byte block ((2^62 + 1) * 4 wraps around) and then wrote past it; now
 * LH_ERR_TOO_LARGE before any allocation. */
LH_TEST(check_delaunay_refuses_counts_that_wrap)
{
    const double tet[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const lh_index simp[4] = {0, 1, 2, 3};
    peak p = {0, 0, 0};
    lh_allocator a = {peak_alloc, peak_free, &p};
    lh_options o;
    lh_options_default(&o);
    o.alloc = &a;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_delaunay_check(3, 4, tet, (size_t)1 << 60, simp, &o, &err), LH_ERR_TOO_LARGE);
    LH_EXPECT_STREQ(err.message, "4 sites and 1152921504606846976 simplices: more than an lh_index or a size_t can count");
    LH_EXPECT_EQ_INT(lh_delaunay_check(3, SIZE_MAX / 2, tet, 1, simp, &o, &err), LH_ERR_TOO_LARGE);
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, 3, tet, SIZE_MAX, simp, &o, &err), LH_ERR_TOO_LARGE);
    LH_EXPECT_EQ_U64(p.peak, 0);
    LH_EXPECT_EQ_INT(lh_delaunay_check(3, 4, tet, 1, simp, &o, &err), LH_OK);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(extreme_scales_triangulate_as_the_unit_scale),
        LH_CASE(largest_and_mixed_magnitudes),
        LH_CASE(nonfinite_coordinates_everywhere),
        LH_CASE(a_million_identical_sites),
        LH_CASE(all_duplicates_of_one_site),
        LH_CASE(collinear_and_coplanar_sites),
        LH_CASE(sites_on_a_common_circumsphere),
        LH_CASE(scaled_lattice_spheres_triangulate_alike),
        LH_CASE(sites_and_queries_on_hull_facets),
        LH_CASE(reader_keeps_extreme_doubles),
        LH_CASE(reader_takes_megabyte_lines),
        LH_CASE(constructions_at_extreme_scales),
        LH_CASE(the_site_count_limit),
        LH_CASE(check_delaunay_refuses_counts_that_wrap),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
