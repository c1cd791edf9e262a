/* test_flat.c — lh_options.affine_hull: sites spanning a k-flat of R^d are
 * triangulated within it, exactly. A plane placed in R^3 by the similarity
 * (u, v) -> (3u, 4u, 5v) must give the 2D triangulation byte for byte, degenerate
 * families included; other flats pass the exact check; location, insertion and the
 * Delaunay complex work in the flat. */
#include "lh_families.h"
#include "lh_test.h"
#include "lh_api_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Coordinates rounded to multiples of 2^-40 (so that 3u, 4u, 5v are exact). */
static void quantise(double *x, size_t m)
{
    for (size_t i = 0; i < m; i++) x[i] = ldexp(floor(ldexp(x[i], 40)), -40);
}

static lh_tri *flat_delaunay(int d, size_t n, const double *x, lh_status *st)
{
    lh_options o;
    lh_options_default(&o);
    o.affine_hull = 1;
    lh_tri *t = NULL;
    *st = lh_delaunay(d, n, x, &o, &t);
    return t;
}

LH_TEST(a_plane_in_3d_gives_the_2d_triangulation)
{
    int fams[] = {F_CUBE, F_CLUSTERS, F_SPHERE_EXACT, F_GRID, F_DUPLICATES};
    for (int f = 0; f < 5 && !LH_FAILED(); f++) {
        size_t n = 500;
        double *uv = malloc(n * 2 * sizeof *uv), *x = malloc(n * 3 * sizeof *x);
        lh_fam_seed((uint64_t)(100 + f));
        n = lh_fam_make(fams[f], 2, n, uv);
        quantise(uv, n * 2);
        for (size_t i = 0; i < n; i++) {
            x[3 * i] = 3 * uv[2 * i];
            x[3 * i + 1] = 4 * uv[2 * i];
            x[3 * i + 2] = 5 * uv[2 * i + 1];
        }
        lh_tri *plain, *flat, *want;
        LH_EXPECT_EQ_INT(lh_delaunay(3, n, x, NULL, &plain), LH_ERR_DEGENERATE);
        lh_status st;
        flat = flat_delaunay(3, n, x, &st);
        LH_EXPECT_EQ_INT(st, LH_OK);
        LH_ASSERT_EQ_INT(lh_delaunay(2, n, uv, NULL, &want), LH_OK);
        if (st == LH_OK) {
            LH_EXPECT_EQ_INT(lh_tri_dim(flat), 3);
            LH_EXPECT_EQ_INT(lh_tri_simplex_dim(flat), 2);
            lh_error err;
            LH_EXPECT_EQ_INT(lh_tri_check(flat, &err), LH_OK);
            LH_EXPECT_TRUE(lh_test_same_tri(flat, want));
            size_t c1, c2;
            const lh_index *o1, *v1, *o2, *v2;
            LH_EXPECT_EQ_INT(lh_tri_complex(flat, &c1, &o1, &v1), LH_OK);
            LH_EXPECT_EQ_INT(lh_tri_complex(want, &c2, &o2, &v2), LH_OK);
            LH_EXPECT_EQ_U64(c1, c2);
            if (LH_FAILED()) LH_NOTE("%s: %s", lh_fam_name[fams[f]], err.message);
        }
        lh_tri_free(flat);
        lh_tri_free(want);
        free(uv);
        free(x);
    }
}

/* Sites of R^k placed in R^d by an integer matrix (a flat through the origin). */
static void embed(const double *u, size_t n, int k, int d, const int *A, double *x)
{
    for (size_t i = 0; i < n; i++)
        for (int r = 0; r < d; r++) {
            double s = 0;
            for (int c = 0; c < k; c++) s += A[r * k + c] * u[i * k + c];
            x[i * d + r] = s;
        }
}

LH_TEST(other_flats_pass_the_exact_check)
{
    /* 3-space in R^4 by orthogonal columns of equal norm (a similarity), 2-planes
     * in R^4 and R^5 by skew integer maps, plus an offset. */
    static const int A34[12] = {1, 1, 1, 1, -1, 1, 1, 1, -1, 1, -1, -1};
    static const int A24[8] = {1, 2, 3, -1, 1, 0, 0, 2};
    static const int A25[10] = {2, 1, 0, 1, 1, -3, 1, 1, 5, 2};
    struct { int k, d; const int *A; } cases[3] = {{3, 4, A34}, {2, 4, A24}, {2, 5, A25}};
    for (int c = 0; c < 3 && !LH_FAILED(); c++) {
        int k = cases[c].k, d = cases[c].d;
        for (int f = 0; f < 3 && !LH_FAILED(); f++) {
            int fam = f == 0 ? F_CUBE : f == 1 ? F_GRID : F_SPHERE_EXACT;
            size_t n = 200;
            double *u = malloc(n * k * sizeof *u), *x = malloc(n * d * sizeof *x);
            lh_fam_seed((uint64_t)(10 * c + f));
            n = lh_fam_make(fam, k, n, u);
            quantise(u, n * k);
            embed(u, n, k, d, cases[c].A, x);
            for (size_t i = 0; i < n * d; i++) x[i] += 1000.0 * (double)(i % d + 1);
            lh_status st;
            lh_tri *t = flat_delaunay(d, n, x, &st);
            LH_EXPECT_EQ_INT(st, LH_OK);
            if (st == LH_OK) {
                lh_error err;
                LH_EXPECT_EQ_INT(lh_tri_simplex_dim(t), k);
                LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
                if (fam == F_CUBE && c == 0) { /* a similarity: 3D's simplex count */
                    lh_tri *w;
                    LH_ASSERT_EQ_INT(lh_delaunay(3, n, u, NULL, &w), LH_OK);
                    LH_EXPECT_EQ_U64(lh_tri_count(t), lh_tri_count(w));
                    lh_tri_free(w);
                }
                if (LH_FAILED()) LH_NOTE("k=%d d=%d %s: %s", k, d, lh_fam_name[fam], err.message);
            }
            lh_tri_free(t);
            free(u);
            free(x);
        }
    }
}

LH_TEST(location_and_insertion_in_the_flat)
{
    enum { N = 300 };
    double uv[N * 2], x[N * 3];
    lh_fam_seed(3);
    lh_fam_make(F_CUBE, 2, N, uv);
    quantise(uv, N * 2);
    for (int i = 0; i < N; i++) {
        x[3 * i] = 3 * uv[2 * i];
        x[3 * i + 1] = 4 * uv[2 * i];
        x[3 * i + 2] = 5 * uv[2 * i + 1];
    }
    lh_status st;
    lh_tri *t = flat_delaunay(3, N - 50, x, &st);
    LH_ASSERT_EQ_INT(st, LH_OK);
    /* A point of the flat inside: found, barycentric coordinates reproduce it. */
    double q[3] = {3 * 0.5, 4 * 0.5, 5 * 0.5}, off[3] = {1.5, 2.5, 2.5};
    lh_location loc;
    LH_ASSERT_EQ_INT(lh_tri_locate(t, q, -1, &loc), LH_OK);
    LH_ASSERT_TRUE(loc.simplex >= 0);
    double r[3] = {0, 0, 0};
    for (int j = 0; j < 3; j++) {
        const double *p = x + 3 * lh_tri_simplices(t)[3 * loc.simplex + j];
        LH_EXPECT_TRUE(loc.bary[j] >= -1e-12);
        for (int c = 0; c < 3; c++) r[c] += loc.bary[j] * p[c];
    }
    for (int c = 0; c < 3; c++) LH_EXPECT_TRUE(fabs(r[c] - q[c]) < 1e-9);
    double far[3] = {3 * 2.0, 4 * 2.0, 5 * 0.5}; /* in the flat, outside the hull */
    LH_ASSERT_EQ_INT(lh_tri_locate(t, far, -1, &loc), LH_OK);
    LH_EXPECT_EQ_INT(loc.simplex, -1);
    LH_EXPECT_TRUE(loc.hull_facet >= 0 && loc.distance > 0);
    LH_EXPECT_EQ_INT(lh_tri_locate(t, off, -1, &loc), LH_ERR_INVALID_ARGUMENT);
    /* Insertion within the flat: lh_delaunay of all; then a site off the flat. */
    LH_ASSERT_EQ_INT(lh_tri_insert(t, 50, x + 3 * (N - 50)), LH_OK);
    lh_tri *all = flat_delaunay(3, N, x, &st);
    LH_ASSERT_EQ_INT(st, LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(t, all));
    LH_ASSERT_EQ_INT(lh_tri_insert(t, 1, off), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_simplex_dim(t), 3);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_tri_free(all);
    lh_tri_free(t);
}

LH_TEST(collinear_sites_give_the_chain)
{
    /* Sites t * (1, 2, 3) + (5, 0, -1) for t in a shuffled 0..29, three repeated. */
    enum { N = 33 };
    double x[N * 3];
    int tt[N];
    for (int i = 0; i < 30; i++) tt[i] = (i * 7) % 30;
    tt[30] = 4, tt[31] = 0, tt[32] = 29;
    for (int i = 0; i < N; i++) {
        x[3 * i] = tt[i] + 5;
        x[3 * i + 1] = 2 * tt[i];
        x[3 * i + 2] = 3 * tt[i] - 1;
    }
    for (int furthest = 0; furthest < 2; furthest++) {
        lh_options o;
        lh_options_default(&o);
        o.affine_hull = 1;
        o.furthest_site = furthest;
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(3, N, x, &o, &t), LH_OK);
        LH_EXPECT_EQ_INT(lh_tri_simplex_dim(t), 1);
        LH_EXPECT_EQ_U64(lh_tri_count(t), furthest ? 1 : 29);
        LH_EXPECT_EQ_U64(lh_tri_duplicate_count(t), 3);
        LH_EXPECT_EQ_U64(lh_tri_hull_count(t), 2);
        lh_error err;
        LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
        const lh_index *s = lh_tri_simplices(t), *dup = lh_tri_duplicate_of(t);
        for (size_t i = 0; i < lh_tri_count(t); i++) /* oriented along the line */
            LH_EXPECT_EQ_INT(tt[s[2 * i + 1]] - tt[s[2 * i]], furthest ? 29 : 1);
        LH_EXPECT_EQ_INT(dup[30], 22); /* t = 4 first appears as site 22 (7 * 22 % 30) */
        LH_EXPECT_EQ_INT(dup[31], 0);  /* t = 0: site 0 */
        LH_EXPECT_EQ_INT(dup[32], 17); /* t = 29: site 17 */
        if (LH_FAILED()) LH_NOTE("furthest=%d: %s", furthest, err.message);
        lh_tri_free(t);
    }
    lh_tri *t;
    lh_options o;
    lh_options_default(&o);
    o.affine_hull = 1;
    LH_ASSERT_EQ_INT(lh_delaunay(3, N, x, &o, &t), LH_OK);
    lh_location loc;
    double in[3] = {5 + 2.5, 5, 6.5}, out[3] = {5 - 2, -4, -7}, off[3] = {6, 2, 3};
    LH_ASSERT_EQ_INT(lh_tri_locate(t, in, -1, &loc), LH_OK);
    LH_ASSERT_TRUE(loc.simplex >= 0);
    const lh_index *s = lh_tri_simplices(t) + 2 * loc.simplex;
    LH_EXPECT_TRUE((tt[s[0]] == 2 && tt[s[1]] == 3));
    LH_ASSERT_EQ_INT(lh_tri_locate(t, out, -1, &loc), LH_OK);
    LH_EXPECT_EQ_INT(loc.simplex, -1);
    LH_EXPECT_TRUE(loc.hull_facet >= 0 && tt[lh_tri_hull_facets(t)[loc.hull_facet]] == 0);
    LH_EXPECT_TRUE(fabs(loc.distance - sqrt(56.0)) < 1e-12); /* 2 units of (1, 2, 3) */
    LH_EXPECT_EQ_INT(lh_tri_locate(t, off, -1, &loc), LH_ERR_INVALID_ARGUMENT);
    lh_tri_free(t);
    double one[6] = {1, 2, 3, 1, 2, 3}; /* a single distinct site: nothing to triangulate */
    LH_EXPECT_EQ_INT(lh_delaunay(3, 2, one, &o, &t), LH_ERR_DEGENERATE);
}

/* lh_delaunay with the affine-hull option on sites (n of them) in R^3. */
typedef struct flat_input {
    size_t n;
    const double *x;
} flat_input;

static lh_status flat_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const flat_input *in = user;
    (void)lh_t_;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    o.affine_hull = 1;
    lh_tri *t;
    lh_status st = lh_delaunay(3, in->n, in->x, &o, &t);
    if (st == LH_OK) { /* the check allocates through the handle's hooks too */
        st = lh_tri_check(t, NULL);
        lh_tri_free(t);
    }
    return st;
}

/* Every allocation of the flat and line paths failing in turn: LH_ERR_NOMEM and
 * nothing left allocated, until a run succeeds. */
LH_TEST(every_allocation_failure_is_survived)
{
    double plane[60 * 3], line[20 * 3];
    lh_fam_seed(8);
    for (int i = 0; i < 60; i++) {
        double u = (double)(lh_fam_rnd() % 1000), v = (double)(lh_fam_rnd() % 1000);
        plane[3 * i] = u + v, plane[3 * i + 1] = u - v, plane[3 * i + 2] = 2 * u;
    }
    for (int i = 0; i < 20; i++) line[3 * i] = i % 7, line[3 * i + 1] = 2 * (i % 7), line[3 * i + 2] = 1;
    flat_input in_plane = {60, plane}, in_line = {20, line};
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, flat_run, &in_plane), 5);
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, flat_run, &in_line), 5);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(a_plane_in_3d_gives_the_2d_triangulation),
        LH_CASE(other_flats_pass_the_exact_check),
        LH_CASE(location_and_insertion_in_the_flat),
        LH_CASE(collinear_sites_give_the_chain),
        LH_CASE(every_allocation_failure_is_survived),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
