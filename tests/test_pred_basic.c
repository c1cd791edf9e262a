/* test_pred_basic.c — predicates on configurations whose signs are known by
 * construction, in every dimension; invariance under exact translation and
 * power-of-two scaling (which moves the work between filter and exact stage);
 * counters, the residue stage's exact zeros; argument checks; allocation failure in lh_pred_create. */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAXP = LH_ORIENT_MAX_DIM + 2 };

typedef struct cfg {
    int dim, npts;
    double x[MAXP][LH_ORIENT_MAX_DIM];
    const double *p[MAXP];
} cfg;

/* p_0 = 0, p_i = e_i: orient_k = +1. */
static void unit_simplex(cfg *c, int dim, int npts)
{
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->npts = npts;
    for (int i = 1; i <= dim; i++) c->x[i][i - 1] = 1;
    for (int i = 0; i < npts; i++) c->p[i] = c->x[i];
}

static void set_query(cfg *c, double v)
{
    for (int j = 0; j < c->dim; j++) c->x[c->npts - 1][j] = v;
}

/* x -> x * 2^e + t, exact for the small dyadic coordinates used here. */
static void transform(cfg *c, int e, double t)
{
    for (int i = 0; i < c->npts; i++)
        for (int j = 0; j < c->dim; j++) c->x[i][j] = ldexp(c->x[i][j], e) + t;
}

static lh_pred *make(void)
{
    lh_pred *ctx = NULL;
    if (lh_pred_create(NULL, &ctx) != LH_OK) return NULL;
    return ctx;
}

LH_TEST(orient_of_unit_simplex_in_every_dimension)
{
    lh_pred *ctx = make();
    LH_ASSERT_TRUE(ctx != NULL);
    /* Exact transforms only: coordinates 0 and 1 become 2^e + t without rounding. */
    static const int scales[] = {0, -1000, 900, -60, 30};
    static const double shifts[] = {0, 0, 0, -0x1p-10, 0x1p70};
    for (int k = 1; k <= LH_ORIENT_MAX_DIM && !LH_FAILED(); k++) {
        for (int t = 0; t < 5; t++) {
            cfg c;
            unit_simplex(&c, k, k + 1);
            transform(&c, scales[t], shifts[t]);
            LH_EXPECT_EQ_INT(lh_orient(ctx, k, c.p), 1);
            const double *tmp = c.p[0]; /* one exchange flips the sign */
            c.p[0] = c.p[1];
            c.p[1] = tmp;
            LH_EXPECT_EQ_INT(lh_orient(ctx, k, c.p), -1);
            c.p[0] = c.p[1]; /* a repeated point: exactly zero */
            LH_EXPECT_EQ_INT(lh_orient(ctx, k, c.p), 0);
            if (LH_FAILED()) {
                LH_NOTE("k=%d scale 2^%d shift %g", k, scales[t], shifts[t]);
                break;
            }
        }
    }
    lh_pred_free(ctx);
}

LH_TEST(insphere_inside_on_outside_in_every_dimension)
{
    /* Circumsphere of 0, e_1..e_d: centre (1/2,...), radius^2 d/4. The query
     * (v,...,v) is inside for v = 1/2, on it for v = 1 and v = 0, outside for 2. */
    lh_pred *ctx = make();
    LH_ASSERT_TRUE(ctx != NULL);
    static const int scales[] = {0, -1000, 400, 30, 0};
    static const double shifts[] = {0, 0, 0, 0x1p70, 0x1p30};
    for (int d = 1; d <= LH_INSPHERE_MAX_DIM; d++) {
        for (int t = 0; t < 5; t++) {
            static const double v[] = {0.5, 1.0, 2.0, 0.0};
            static const int want[] = {-1, 0, 1, 0};
            for (int q = 0; q < 4; q++) {
                cfg c;
                unit_simplex(&c, d, d + 2);
                set_query(&c, v[q]);
                transform(&c, scales[t], shifts[t]);
                LH_EXPECT_EQ_INT(lh_insphere(ctx, d, c.p), want[q]);
                if (LH_FAILED()) {
                    LH_NOTE("d=%d scale 2^%d shift %g query %g", d, scales[t], shifts[t], v[q]);
                    lh_pred_free(ctx);
                    return;
                }
            }
        }
    }
    lh_pred_free(ctx);
}

LH_TEST(counters_record_the_stage_that_answered)
{
    lh_pred *ctx = make();
    LH_ASSERT_TRUE(ctx != NULL);
    cfg c;
    unit_simplex(&c, 3, 5);
    set_query(&c, 0.5);
    lh_pred_counters n;
    LH_EXPECT_EQ_INT(lh_insphere(ctx, 3, c.p), -1); /* easy: the filter */
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.calls, 1);
    LH_EXPECT_EQ_U64(n.filter_exits, 1);
    LH_EXPECT_EQ_U64(n.exact_exits, 0);
    set_query(&c, 1.0); /* cospherical, small integers: zero by the granularity rule */
    LH_EXPECT_EQ_INT(lh_insphere(ctx, 3, c.p), 0);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.calls, 2);
    LH_EXPECT_EQ_U64(n.grid_exits, 1);
    LH_EXPECT_EQ_U64(n.exact_exits, 0);
    LH_EXPECT_EQ_U64(n.zero_results, 1);
    /* The classroom example: collinear up to 2^-53, coordinates of mixed granularity:
     * beyond the double filter, decided by the double-word stage (pred_wide.c), which
     * counts as a filter exit. */
    const double a[2] = {0.5 + 0x1p-53, 0.5}, b[2] = {12, 12}, d[2] = {24, 24};
    const double *abd[3] = {a, b, d};
    LH_EXPECT_EQ_INT(lh_orient(ctx, 2, abd), -1);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.filter_exits, 2);
    LH_EXPECT_EQ_U64(n.exact_exits, 0);
    /* Off the line y = x by 2^-52 at 1, beside points at 2^-70 and 2^70: every
     * filter stage's bound exceeds the determinant there, so the exact stage decides. */
    const double e[2] = {1 + 0x1p-52, 1}, f[2] = {0x1p-70, 0x1p-70}, g[2] = {0x1p70, 0x1p70};
    const double *efg[3] = {e, f, g};
    LH_EXPECT_EQ_INT(lh_orient(ctx, 2, efg), -1);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.exact_exits, 1);
    LH_EXPECT_EQ_INT(lh_insphere_sos(ctx, 3, c.p) != 0, 1);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.sos_fast + n.sos_general, 1);
    LH_EXPECT_EQ_U64(n.calls, 5);
    lh_pred_counters_reset(ctx);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.calls, 0);
    LH_EXPECT_EQ_U64(n.sos_fast, 0);
    lh_pred_free(ctx);
}

/* Rows of cfg c from a flat list of npts points in R^dim, scaled by f (exact here). */
static void set_points(cfg *c, int dim, int npts, const double *xs, double f)
{
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->npts = npts;
    for (int i = 0; i < npts; i++) {
        for (int j = 0; j < dim; j++) c->x[i][j] = xs[i * dim + j] * f;
        c->p[i] = c->x[i];
    }
}

/* Exactly cospherical points too wide for the granularity rule: the residue stage
 * must prove the zero (no multi-limb arithmetic), and must not claim a zero when a
 * coordinate moves by one ulp. */
LH_TEST(residues_prove_exact_zeros_of_wide_coordinates)
{
    lh_pred *ctx = make();
    LH_ASSERT_TRUE(ctx != NULL);
    lh_pred_counters n;
    /* 3D: lattice points on the sphere of radius 7m (2^2 + 3^2 + 6^2 = 7^2). */
    static const double s3[] = {7, 0, 0, 0, 7, 0, 0, 0, 7, 2, 3, 6, 6, 2, 3};
    cfg c;
    set_points(&c, 3, 5, s3, 123457);
    LH_EXPECT_EQ_INT(lh_insphere(ctx, 3, c.p), 0);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.residue_exits, 1);
    LH_EXPECT_EQ_U64(n.exact_exits, 0);
    /* 4D: full 53-bit mantissas at 2^-60 (five moduli), the sphere of radius 2m. */
    static const double s4[] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2,
                                1, 1, 1, 1, 1, -1, 1, -1};
    set_points(&c, 4, 6, s4, ldexp(0x1p52 + 1, -60));
    LH_EXPECT_EQ_INT(lh_insphere(ctx, 4, c.p), 0);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.residue_exits, 2);
    LH_EXPECT_EQ_U64(n.exact_exits, 0);
    /* One ulp off the sphere, either way: nonzero, opposite, from the exact stage. */
    double keep = c.x[5][0];
    c.x[5][0] = nextafter(keep, INFINITY);
    int out = lh_insphere(ctx, 4, c.p);
    c.x[5][0] = nextafter(keep, 0);
    int in = lh_insphere(ctx, 4, c.p);
    LH_EXPECT_TRUE(out != 0 && in == -out);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.residue_exits, 2);
    LH_EXPECT_EQ_U64(n.exact_exits, 2);
    /* orient_3: four points of the plane z = x + y with 41-bit integer coordinates. */
    static const double s3p[] = {1, 2, 3, 5, -7, -2, -11, 13, 2, 17, 19, 36};
    set_points(&c, 3, 4, s3p, 0x1p40 + 1);
    LH_EXPECT_EQ_INT(lh_orient(ctx, 3, c.p), 0);
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.residue_exits, 3);
    LH_EXPECT_EQ_U64(n.exact_exits, 2);
    lh_pred_free(ctx);
}

LH_TEST(invalid_arguments_answer_zero_and_count_nothing)
{
    lh_pred *ctx = make();
    LH_ASSERT_TRUE(ctx != NULL);
    cfg c;
    unit_simplex(&c, 3, 5);
    LH_EXPECT_EQ_INT(lh_orient(ctx, 0, c.p), 0);
    LH_EXPECT_EQ_INT(lh_orient(ctx, LH_ORIENT_MAX_DIM + 1, c.p), 0);
    LH_EXPECT_EQ_INT(lh_orient_sos(ctx, LH_ORIENT_MAX_DIM + 1, c.p), 0);
    LH_EXPECT_EQ_INT(lh_insphere(ctx, LH_INSPHERE_MAX_DIM + 1, c.p), 0);
    LH_EXPECT_EQ_INT(lh_insphere_sos(ctx, 0, c.p), 0);
    LH_EXPECT_EQ_INT(lh_orient(NULL, 3, c.p), 0);
    LH_EXPECT_EQ_INT(lh_orient(ctx, 3, NULL), 0);
    lh_pred_counters n;
    lh_pred_counters_get(ctx, &n);
    LH_EXPECT_EQ_U64(n.calls, 0);
    lh_pred_counters_get(NULL, &n);
    LH_EXPECT_EQ_U64(n.calls, 0);
    lh_pred_free(ctx);
    lh_pred_free(NULL);
}


LH_TEST(create_fails_cleanly_at_every_allocation)
{
    /* the context, the dense arena, the sparse accumulator's coefficients and flags */
    for (int k = 1; k <= 5; k++) {
        lh_test_counter c = {0, k, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh_pred *ctx = (lh_pred *)&c; /* must be overwritten */
        lh_status st = lh_pred_create(&a, &ctx);
        if (k <= 4) {
            LH_EXPECT_EQ_INT(st, LH_ERR_NOMEM);
            LH_EXPECT_TRUE(ctx == NULL);
        } else {
            LH_EXPECT_EQ_INT(st, LH_OK);
            lh_pred_free(ctx);
        }
        LH_EXPECT_EQ_INT(c.live, 0);
    }
    lh_allocator half = {lh_test_counting_alloc, NULL, NULL};
    lh_pred *ctx;
    LH_EXPECT_EQ_INT(lh_pred_create(&half, &ctx), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_pred_create(NULL, NULL), LH_ERR_INVALID_ARGUMENT);
}

/* lh_hyperplane: unit normal, the points on the plane, the orientation of orient_d,
 * and accuracy on thin simplices where floating-point cofactors fail: points at
 * 2^-20 from a common line through large offsets. */
LH_TEST(hyperplanes_through_points)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    uint64_t r = 99;
    for (int d = 2; d <= 8; d++)
        for (int t = 0; t < 50; t++) {
            double x[9][8], n[8], off, q[8];
            const double *p[9];
            for (int i = 0; i < d; i++) {
                for (int j = 0; j < d; j++) {
                    r = r * 6364136223846793005u + 1442695040888963407u;
                    double u = (double)(r >> 11) * 0x1p-53;
                    /* t odd: thin, the points within 2^-20 of the line 1e6 * (1, 2, ...) */
                    x[i][j] = t % 2 ? 1e6 * (j + 1) * (1 + i) + ldexp(u, -20) : u;
                }
                p[i] = x[i];
            }
            LH_ASSERT_EQ_INT(lh_hyperplane(ctx, d, p, n, &off), 1);
            double len = 0, scale = 0;
            for (int j = 0; j < d; j++) len += n[j] * n[j];
            LH_EXPECT_LE_DBL(fabs(len - 1), 1e-15);
            for (int i = 0; i < d; i++) {
                double v = off;
                for (int j = 0; j < d; j++) {
                    v += n[j] * x[i][j];
                    scale += fabs(n[j] * x[i][j]);
                }
                LH_EXPECT_LE_DBL(fabs(v), 1e-14 * (scale + fabs(off)));
            }
            for (int j = 0; j < d; j++) q[j] = x[0][j] + n[j]; /* one unit along n */
            p[d] = q;
            LH_EXPECT_EQ_INT(lh_orient(ctx, d, p), 1);
        }
    const double a[2] = {1, 1}, *dup[2] = {a, a};
    double n[2], off;
    LH_EXPECT_EQ_INT(lh_hyperplane(ctx, 2, dup, n, &off), 0);
    LH_EXPECT_EQ_INT(lh_hyperplane(NULL, 2, dup, n, &off), 0);
    lh_pred_free(ctx);
}

/* lh_hyperplane_exp: the offset of the plane x + y + z = 2M through (M,M,0), (M,0,M),
 * (0,M,M) is 2M/sqrt(3) > DBL_MAX for M = 0x1.fp1023: finite as off 2^e there, where
 * lh_hyperplane's is +-inf (never nan) with the same normal; and a lattice triangle
 * has bit for bit the same normal and offset mantissa at 2^-1070 (subnormal), 2^0
 * and 2^1000, its offset exponent shifted by the scale. */
LH_TEST(hyperplane_offsets_past_dbl_max_and_scale_free_normals)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    const double M = 0x1.fp1023;
    const double a[3] = {M, M, 0}, b[3] = {M, 0, M}, c[3] = {0, M, M}, *p[3] = {a, b, c};
    double n[3], n2[3], off, m;
    int e;
    LH_ASSERT_EQ_INT(lh_hyperplane_exp(ctx, 3, p, n, &m, &e), 1);
    LH_ASSERT_EQ_INT(lh_hyperplane(ctx, 3, p, n2, &off), 1);
    LH_EXPECT_TRUE(memcmp(n, n2, sizeof n) == 0);
    LH_EXPECT_TRUE(isinf(off) && (off > 0) == (m > 0));
    LH_EXPECT_TRUE(fabs(m) >= 0.5 && fabs(m) < 1);
    for (int j = 0; j < 3; j++) LH_EXPECT_LE_DBL(fabs(fabs(n[j]) - 1 / sqrt(3.0)), 3e-16);
    /* n.a + off = 0: off 2^-1024 = -2 n_0 M 2^-1024, to a few ulps */
    double want = -2 * n[0] * ldexp(M, -1024), got = ldexp(m, e - 1024);
    LH_EXPECT_LE_DBL(fabs(got - want), 1e-15 * fabs(want));
    LH_EXPECT_TRUE(isfinite(got));

    static const double tri[3][3] = {{1, 2, 0}, {0, 1, 3}, {2, 0, 1}};
    double base_n[3], base_m = 0;
    int base_e = 0;
    static const int scales[] = {0, -1070, 1000};
    for (size_t k = 0; k < LH_COUNT(scales); k++) {
        double x[3][3];
        const double *q[3] = {x[0], x[1], x[2]};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) x[i][j] = ldexp(tri[i][j], scales[k]); /* exact */
        LH_ASSERT_EQ_INT(lh_hyperplane_exp(ctx, 3, q, n, &m, &e), 1);
        if (k == 0) {
            memcpy(base_n, n, sizeof n);
            base_m = m;
            base_e = e;
            LH_EXPECT_TRUE(m != 0);
            continue;
        }
        LH_NOTE("scale 2^%d: offset %.17g 2^%d", scales[k], m, e);
        LH_EXPECT_TRUE(memcmp(n, base_n, sizeof n) == 0);
        LH_EXPECT_TRUE(m == base_m);
        LH_EXPECT_EQ_INT(e, base_e + scales[k]);
    }
    const double o[2] = {0, 0}, u[2] = {1, 1}, *through[2] = {o, u};
    LH_EXPECT_EQ_INT(lh_hyperplane_exp(ctx, 2, through, n, &m, &e), 1);
    LH_EXPECT_TRUE(m == 0 && e == 0); /* the line y = x through the origin */
    const double *dup[2] = {u, u};
    LH_EXPECT_EQ_INT(lh_hyperplane_exp(ctx, 2, dup, n, &m, &e), 0);
    LH_EXPECT_EQ_INT(lh_hyperplane_exp(ctx, 2, dup, n, &m, NULL), 0);
    LH_EXPECT_EQ_INT(lh_hyperplane_exp(NULL, 2, dup, n, &m, &e), 0);
    lh_pred_free(ctx);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(hyperplanes_through_points),
        LH_CASE(hyperplane_offsets_past_dbl_max_and_scale_free_normals),
        LH_CASE(orient_of_unit_simplex_in_every_dimension),
        LH_CASE(insphere_inside_on_outside_in_every_dimension),
        LH_CASE(counters_record_the_stage_that_answered),
        LH_CASE(residues_prove_exact_zeros_of_wide_coordinates),
        LH_CASE(invalid_arguments_answer_zero_and_count_nothing),
        LH_CASE(create_fails_cleanly_at_every_allocation)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
