/*
 * test_voronoi.c — Voronoi vertices (lh_tri_circumcenters), the exact distance
 * comparison (lh_distance_compare), the nearest site (lh_tri_nearest) against brute
 * force, and linear / nearest interpolation (lh_tri_interpolate).
 */
#include "lh_api_test.h"
#include "lh_families.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static lh_tri *build(int d, size_t n, const double *x)
{
    lh_tri *t = NULL;
    return lh_delaunay(d, n, x, NULL, &t) == LH_OK ? t : NULL;
}

static double dist2(int d, const double *a, const double *b)
{
    double s = 0;
    for (int j = 0; j < d; j++) s += (a[j] - b[j]) * (a[j] - b[j]);
    return s;
}

/* Each centre is equidistant from its simplex's vertices (relative 1e-12 of the
 * radius) and no site is nearer to it than them (the empty sphere), up to the same
 * tolerance; d = 2..5, uniform and cospherical families. */
LH_TEST(circumcenters_are_empty_sphere_centres)
{
    static const int fams[] = {F_CUBE, F_SPHERE_EXACT, F_GRID};
    for (int d = 2; d <= 5; d++)
        for (size_t f = 0; f < LH_COUNT(fams) - (d == 5); f++) { /* 80 grid sites: flat in 5D */
            size_t n = d <= 3 ? 300 : 80;
            double *x = malloc(n * d * sizeof *x);
            lh_fam_seed(40 + d);
            n = lh_fam_make(fams[f], d, n, x);
            lh_tri *t = build(d, n, x);
            LH_ASSERT_TRUE(t);
            const double *c;
            LH_ASSERT_EQ_INT(lh_tri_circumcenters(t, &c), LH_OK);
            const lh_index *s = lh_tri_simplices(t);
            double worst = 0;
            for (size_t i = 0; i < lh_tri_count(t); i++) {
                const double *ci = c + i * d;
                double r2 = dist2(d, ci, x + (size_t)s[i * (d + 1)] * d);
                for (int k = 1; k <= d; k++) {
                    double e = fabs(dist2(d, ci, x + (size_t)s[i * (d + 1) + k] * d) - r2) / r2;
                    if (e > worst) worst = e;
                }
                for (size_t p = 0; p < n; p += 7) {
                    double e = (r2 - dist2(d, ci, x + p * d)) / r2;
                    if (e > worst) worst = e;
                }
            }
            LH_NOTE("d=%d family %s: worst relative error %.3g", d, lh_fam_name[fams[f]], worst);
            LH_EXPECT_LE_DBL(worst, 1e-12);
            const double *again;
            LH_EXPECT_EQ_INT(lh_tri_circumcenters(t, &again), LH_OK);
            LH_EXPECT_TRUE(again == c);
            lh_tri_free(t);
            free(x);
        }
}

/* lh_tri_circumcenter_exp: the triangle (2^1023, 0), (-2^1023, 0), (0, 2^1010) has
 * its circumcentre at (0, 2^1009 - 2^1035), past DBL_MAX: lh_tri_circumcenters gives
 * -inf there, c 2^e the centre itself (finite c); at unit scale both agree. */
LH_TEST(circumcentres_past_dbl_max_as_mantissa_and_exponent)
{
    const double x[6] = {0x1p1023, 0, -0x1p1023, 0, 0, 0x1p1010};
    lh_tri *t = build(2, 3, x);
    LH_ASSERT_TRUE(t);
    LH_ASSERT_EQ_INT(lh_tri_count(t), 1);
    const double *all;
    LH_ASSERT_EQ_INT(lh_tri_circumcenters(t, &all), LH_OK);
    LH_EXPECT_TRUE(isinf(all[1]) && all[1] < 0);
    double c[2];
    int e;
    LH_ASSERT_EQ_INT(lh_tri_circumcenter_exp(t, 0, c, &e), LH_OK);
    LH_EXPECT_TRUE(isfinite(c[0]) && isfinite(c[1]));
    double y = ldexp(c[1], e - 1035), want = -1 + 0x1p-26; /* the centre's y 2^-1035 */
    LH_NOTE("centre (%.17g, %.17g) 2^%d", c[0], c[1], e);
    LH_EXPECT_LE_DBL(fabs(y - want), 1e-15);
    LH_EXPECT_LE_DBL(fabs(ldexp(c[0], e - 1035)), 1e-15);
    LH_EXPECT_EQ_INT(lh_tri_circumcenter_exp(t, 1, c, &e), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_circumcenter_exp(t, 0, c, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_circumcenter_exp(NULL, 0, c, &e), LH_ERR_INVALID_ARGUMENT);
    lh_tri_free(t);
    const double unit[6] = {0, 0, 4, 0, 0, 2};
    t = build(2, 3, unit);
    LH_ASSERT_TRUE(t);
    LH_ASSERT_EQ_INT(lh_tri_circumcenters(t, &all), LH_OK);
    LH_ASSERT_EQ_INT(lh_tri_circumcenter_exp(t, 0, c, &e), LH_OK);
    LH_EXPECT_TRUE(ldexp(c[0], e) == all[0] && ldexp(c[1], e) == all[1]);
    LH_EXPECT_TRUE(all[0] == 2 && all[1] == 1);
    lh_tri_free(t);
}

/* Ties and near ties that double arithmetic gets wrong, and the sign convention. */
LH_TEST(compare_distance_is_exact)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    const double q[2] = {0, 0}, a[2] = {3, 4}, b[2] = {5, 0}, c[2] = {0, 5.000000000000001};
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 2, q, a, b), 0);
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 2, q, a, c), -1);
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 2, q, c, a), 1);
    /* 1 + 2^-52 against 1 at an offset: |q-a|^2 - |q-b|^2 = 2^-52 (2 + 2^-52) - 0,
     * rounding would see 2^-51 exactly; a second coordinate of 2^-60 decides it. */
    const double q1[2] = {1e9, 0}, a1[2] = {1e9 + 1, 0x1p-60}, b1[2] = {1e9 - 1, 0};
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 2, q1, a1, b1), 1);
    /* subnormal magnitudes: the filter must hand over to the exact stage */
    const double q2[3] = {0, 0, 0}, a2[3] = {0x1p-1074, 0x1p-1074, 0}, b2[3] = {0, 0, 0x1p-1073};
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 3, q2, a2, b2), -1);
    const double a3[3] = {0x1p-1073, 0x1p-1073, 0}, b3[3] = {0, 0x1p-1073, 0x1p-1073};
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 3, q2, a3, b3), 0);
    /* huge magnitudes whose squares overflow */
    const double q4[2] = {-1e300, 1e300}, a4[2] = {1e300, 1e300}, b4[2] = {-1e300, -1e300};
    LH_EXPECT_EQ_INT(lh_distance_compare(ctx, 2, q4, a4, b4), 0);
    LH_EXPECT_EQ_INT(lh_distance_compare(NULL, 2, q, a, b), 0);
    lh_pred_free(ctx);
}

/* The nearest site against a brute-force scan with the exact comparison (the
 * smallest index among exact ties), on uniform sites and on grids where queries at
 * grid points and cell centres tie. */
LH_TEST(nearest_matches_brute_force)
{
    static const int fams[] = {F_CUBE, F_GRID, F_DUPLICATES, F_SPHERE_EXACT};
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    for (int d = 2; d <= 4; d++)
        for (size_t f = 0; f < LH_COUNT(fams); f++) {
            size_t n = d == 4 ? 100 : 400;
            double *x = malloc(n * d * sizeof *x);
            lh_fam_seed(70 + d);
            n = lh_fam_make(fams[f], d, n, x);
            lh_tri *t = build(d, n, x);
            LH_ASSERT_TRUE(t);
            for (int i = 0; i < 300 && !LH_FAILED(); i++) {
                double q[8];
                const double *p = x + (lh_fam_rnd() % n) * d, *r = x + (lh_fam_rnd() % n) * d;
                int kind = i % 3; /* a site, a midpoint (ties), a random point */
                for (int j = 0; j < d; j++)
                    q[j] = kind == 0 ? p[j] : kind == 1 ? 0.5 * (p[j] + r[j]) : 2.5 * lh_fam_unif() - 1.25;
                lh_index best = -1, got = -2;
                for (size_t s = 0; s < n; s++)
                    if (best < 0 || lh_distance_compare(ctx, d, q, x + s * d, x + (size_t)best * d) < 0)
                        best = (lh_index)s;
                LH_EXPECT_EQ_INT(lh_tri_nearest(t, q, i % 2 ? -1 : 3, &got), LH_OK);
                if (got != best) LH_NOTE("d=%d %s query %d", d, lh_fam_name[fams[f]], i);
                LH_EXPECT_EQ_INT(got, best);
            }
            lh_tri_free(t);
            free(x);
        }
    lh_pred_free(ctx);
}

/* Linear interpolation reproduces an affine function inside the hull and gives NaN
 * outside; NEAREST gives the nearest site's value; duplicates use their
 * representative's value. */
LH_TEST(interpolation_reproduces_affine_functions)
{
    for (int d = 2; d <= 5; d++) {
        size_t n = d <= 3 ? 500 : 120, m = 400;
        double *x = malloc(n * d * sizeof *x), *v = malloc(n * 2 * sizeof *v);
        double *q = malloc(m * d * sizeof *q), *out = malloc(m * 2 * sizeof *out);
        lh_fam_seed(90 + d);
        n = lh_fam_make(F_BALL, d, n, x);
        for (size_t i = 0; i < n; i++) {
            v[2 * i] = 1.5, v[2 * i + 1] = -1;
            for (int j = 0; j < d; j++) v[2 * i] += (j + 1) * x[i * d + j], v[2 * i + 1] += x[i * d + j] * (j % 2 ? -3 : 2);
        }
        for (size_t i = 0; i < m * d; i++) q[i] = 1.4 * lh_fam_unif() - 0.7;
        lh_tri *t = build(d, n, x);
        LH_ASSERT_TRUE(t);
        LH_ASSERT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_LINEAR, m, q, 2, v, out), LH_OK);
        size_t inside = 0;
        for (size_t i = 0; i < m; i++) {
            lh_location loc;
            LH_ASSERT_EQ_INT(lh_tri_locate(t, q + i * d, -1, &loc), LH_OK);
            double e0 = 1.5, e1 = -1;
            for (int j = 0; j < d; j++) e0 += (j + 1) * q[i * d + j], e1 += q[i * d + j] * (j % 2 ? -3 : 2);
            if (loc.simplex < 0) {
                LH_EXPECT_TRUE(isnan(out[2 * i]) && isnan(out[2 * i + 1]));
                continue;
            }
            inside++;
            LH_EXPECT_LE_DBL(fabs(out[2 * i] - e0), 1e-12 * (1 + fabs(e0)));
            LH_EXPECT_LE_DBL(fabs(out[2 * i + 1] - e1), 1e-12 * (1 + fabs(e1)));
        }
        LH_EXPECT_GT_U64(inside, m / 8);
        LH_ASSERT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_NEAREST, m, q, 2, v, out), LH_OK);
        for (size_t i = 0; i < m; i++) {
            lh_index s;
            LH_ASSERT_EQ_INT(lh_tri_nearest(t, q + i * d, -1, &s), LH_OK);
            LH_EXPECT_EQ_DBL(out[2 * i], v[2 * s]);
        }
        LH_ASSERT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_NATURAL, m, q, 2, v, out), d <= 3 ? LH_OK : LH_ERR_DIMENSION);
        for (size_t i = 0; i < m && d <= 3; i++) {
            lh_location loc;
            LH_ASSERT_EQ_INT(lh_tri_locate(t, q + i * d, -1, &loc), LH_OK);
            double e0 = 1.5;
            for (int j = 0; j < d; j++) e0 += (j + 1) * q[i * d + j];
            if (loc.simplex < 0) LH_EXPECT_TRUE(isnan(out[2 * i]));
            else LH_EXPECT_LE_DBL(fabs(out[2 * i] - e0), 1e-11 * (1 + fabs(e0)));
        }
        lh_tri_free(t);
        free(x), free(v), free(q), free(out);
    }
}

LH_TEST(bad_arguments)
{
    const double x[8] = {0, 0, 1, 0, 0, 1, 1, 1}, q[2] = {0.5, NAN}, v[4] = {1, 2, 3, 4};
    double out[2];
    lh_index s;
    lh_tri *t = build(2, 4, x);
    LH_ASSERT_TRUE(t);
    LH_EXPECT_EQ_INT(lh_tri_nearest(t, q, -1, &s), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(lh_tri_nearest(t, NULL, -1, &s), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_LINEAR, 1, q, 1, v, out), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_LINEAR, 1, x, 0, v, out), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_interpolate(t, (lh_interp_method)7, 1, x, 1, v, out), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_circumcenters(t, NULL), LH_ERR_INVALID_ARGUMENT);
    lh_tri_free(t);
    lh_options o;
    lh_options_default(&o);
    o.furthest_site = 1;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 4, x, &o, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_nearest(t, x, -1, &s), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_NEAREST, 1, x, 1, v, out), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_interpolate(t, LH_INTERP_LINEAR, 1, x, 1, v, out), LH_OK);
    lh_tri_free(t);
}

typedef struct query_input {
    int method;
} query_input;

static lh_status query_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const query_input *in = user;
    double x[200 * 3], v[200], q[30 * 3], out[30];
    lh_fam_seed(5);
    size_t n = lh_fam_make(F_GRID, 3, 200, x);
    for (size_t i = 0; i < n; i++) v[i] = x[3 * i];
    for (int i = 0; i < 90; i++) q[i] = 3 * lh_fam_unif();
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    lh_tri *t;
    lh_status st = lh_delaunay(3, n, x, &o, &t);
    if (st != LH_OK) return st;
    if (in->method < 0) {
        const double *c;
        st = lh_tri_circumcenters(t, &c);
    } else {
        st = lh_tri_interpolate(t, (lh_interp_method)in->method, 30, q, 1, v, out);
    }
    LH_EXPECT_TRUE(st == LH_OK || st == LH_ERR_NOMEM);
    lh_tri_free(t);
    return st;
}

LH_TEST(every_allocation_failure_is_survived)
{
    static const query_input in[] = {{-1}, {LH_INTERP_LINEAR}, {LH_INTERP_NEAREST}, {LH_INTERP_NATURAL}};
    for (size_t i = 0; i < LH_COUNT(in); i++) LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, query_run, &in[i]), 3);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(circumcenters_are_empty_sphere_centres),
        LH_CASE(circumcentres_past_dbl_max_as_mantissa_and_exponent),
        LH_CASE(compare_distance_is_exact),
        LH_CASE(nearest_matches_brute_force), LH_CASE(interpolation_reproduces_affine_functions),
        LH_CASE(bad_arguments), LH_CASE(every_allocation_failure_is_survived)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
