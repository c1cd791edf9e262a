/* test_pred_sos.c — the perturbed predicates against their definition.
 *
 * The brute force below evaluates the definition in pred_sos.c literally: among all
 * partial matchings S of perturbable entries, in increasing binary order of their
 * code sets, the first whose term det(H with rows r replaced by e_c, (r,c) in S) is
 * nonzero gives the sign. It shares only lh__minor_sign (checked against GMP in
 * test_pred_oracle) with the library's greedy search and fast path. Inputs are tiny
 * integer coordinates, a quarter of them in a common hyperplane, so degeneracies of
 * every kind are frequent. (orient_1 and insphere_1 of distinct points are never
 * zero: their perturbation only shows for equal points.) */
#include "lh_families.h"
#include "lh_test.h"
#include "pred_internal.h"

#include <string.h>


static int more_significant(const double *const *p, int dim, int a, int b)
{
    for (int c = 0; c < dim; c++)
        if (p[a][c] != p[b][c]) return p[a][c] > p[b][c];
    return a > b;
}

static int term_sign(lh_pred *ctx, const double *const *p, int dim, int n,
                     const int *frow, const int *fcol, int nf)
{
    int rows[LH__MAXN], cols[LH__MAXN], nr = n, sign = 1;
    for (int i = 0; i < n; i++) rows[i] = cols[i] = i;
    for (int f = 0; f < nf; f++) {
        int ri = 0, ci = 0;
        while (rows[ri] != frow[f]) ri++;
        while (cols[ci] != fcol[f]) ci++;
        if ((ri + ci) & 1) sign = -sign;
        memmove(rows + ri, rows + ri + 1, (size_t)(nr - ri - 1) * sizeof *rows);
        memmove(cols + ci, cols + ci + 1, (size_t)(nr - ci - 1) * sizeof *cols);
        nr--;
    }
    return sign * lh__minor_sign(ctx, p, dim, nr, rows, cols);
}

static int brute_sos(lh_pred *ctx, const double *const *p, int dim, int lifted)
{
    int n = dim + 1 + lifted, per = dim + lifted;
    int rank[LH__MAXN]; /* 0 = most significant */
    for (int i = 0; i < n; i++) {
        rank[i] = 0;
        for (int j = 0; j < n; j++) rank[i] += j != i && more_significant(p, dim, j, i);
    }
    int cell_row[32], cell_col[32], ncells = n * per;
    for (int i = 0; i < n; i++)
        for (int w = 0; w < per; w++) {
            int code = rank[i] * per + w;
            cell_row[code] = i;
            cell_col[code] = lifted ? (w == 0 ? dim + 1 : w) : w + 1;
        }
    for (uint32_t set = 0; set < (UINT32_C(1) << ncells); set++) {
        int frow[LH__MAXN], fcol[LH__MAXN], nf = 0, rused = 0, cused = 0, ok = 1;
        for (int code = 0; code < ncells && ok; code++) {
            if (!(set & (UINT32_C(1) << code))) continue;
            int r = cell_row[code], c = cell_col[code];
            ok = !(rused & (1 << r)) && !(cused & (1 << c));
            rused |= 1 << r;
            cused |= 1 << c;
            frow[nf] = r;
            fcol[nf++] = c;
        }
        if (!ok) continue;
        int s = term_sign(ctx, p, dim, n, frow, fcol, nf);
        if (s) return s;
    }
    return 0;
}

/* n distinct points with coordinates drawn from {0, .., span-1} (span is raised
 * until span^dim >= n, so that n distinct points exist). */
static void random_points(double x[][8], int n, int dim, int span)
{
    for (;;) {
        long cells = 1;
        for (int j = 0; j < dim && cells < n; j++) cells *= span;
        if (cells >= n) break;
        span++;
    }
    for (int i = 0; i < n; i++) {
        int fresh;
        do {
            for (int j = 0; j < dim; j++) x[i][j] = (double)(lh_fam_rnd() % (uint64_t)span);
            fresh = 1;
            for (int k = 0; k < i && fresh; k++) fresh = memcmp(x[i], x[k], sizeof(double) * (size_t)dim) != 0;
        } while (!fresh);
    }
}

static int perturbed(lh_pred *ctx, int lifted, int dim, const double *const *p)
{
    return lifted ? lh_insphere_sos(ctx, dim, p) : lh_orient_sos(ctx, dim, p);
}

static void check_against_definition(lh_test_state *lh_t_, int lifted, int dim, int cases)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    int n = dim + 1 + lifted, degenerate = 0;
    for (int t = 0; t < cases && !LH_FAILED(); t++) {
        double x[LH__MAXN][8];
        const double *p[LH__MAXN];
        if (t % 4 == 3) { /* all points in the hyperplane x_0 = 1: the general search */
            double y[LH__MAXN][8];
            random_points(y, n, dim - 1, 3);
            for (int i = 0; i < n; i++) {
                x[i][0] = 1;
                memcpy(x[i] + 1, y[i], sizeof(double) * (size_t)(dim - 1));
            }
        } else {
            random_points(x, n, dim, t % 2 ? 2 : 3);
        }
        for (int i = 0; i < n; i++) p[i] = x[i];
        int exact = lifted ? lh_insphere(ctx, dim, p) : lh_orient(ctx, dim, p);
        int s = perturbed(ctx, lifted, dim, p);
        LH_EXPECT_TRUE(s == 1 || s == -1);
        if (exact) {
            LH_EXPECT_EQ_INT(s, exact);
            continue;
        }
        degenerate++;
        LH_EXPECT_EQ_INT(s, brute_sos(ctx, p, dim, lifted));
        if (LH_FAILED()) {
            for (int i = 0; i < n; i++) LH_NOTE("p%d = (%g %g %g)", i, x[i][0], dim > 1 ? x[i][1] : 0.0, dim > 2 ? x[i][2] : 0.0);
        }
    }
    lh_pred_counters c;
    lh_pred_counters_get(ctx, &c);
    printf("%s_%d: %d cases, %d exactly degenerate, fast path %llu, general search %llu\n",
           lifted ? "insphere" : "orient", dim, cases, degenerate,
           (unsigned long long)c.sos_fast, (unsigned long long)c.sos_general);
    LH_EXPECT_GT_INT(degenerate, cases / 25);
    LH_EXPECT_GT_U64(c.sos_general, 0); /* both paths are exercised */
    LH_EXPECT_GT_U64(c.sos_fast, 0);
    lh_pred_free(ctx);
}

LH_TEST(orient_2_matches_definition) { check_against_definition(lh_t_, 0, 2, 3000); }
LH_TEST(orient_3_matches_definition) { check_against_definition(lh_t_, 0, 3, 3000); }
LH_TEST(insphere_2_matches_definition) { check_against_definition(lh_t_, 1, 2, 3000); }
LH_TEST(insphere_3_matches_definition) { check_against_definition(lh_t_, 1, 3, 400); }

/* In every dimension: never zero, antisymmetric under an exchange of arguments,
 * multiplied by the permutation's sign under a reordering (the answer belongs to the
 * point set, not to the argument order). */
static void check_antisymmetry(lh_test_state *lh_t_, int lifted, int maxdim)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    for (int dim = 1; dim <= maxdim && !LH_FAILED(); dim++) {
        int n = dim + 1 + lifted;
        for (int t = 0; t < 300 && !LH_FAILED(); t++) {
            double x[LH__MAXN][8];
            const double *p[LH__MAXN], *q[LH__MAXN];
            random_points(x, n, dim, 2 + (int)(lh_fam_rnd() % 2));
            for (int i = 0; i < n; i++) p[i] = x[i];
            int s = perturbed(ctx, lifted, dim, p);
            LH_EXPECT_TRUE(s == 1 || s == -1);
            int perm[LH__MAXN], sign = 1;
            for (int i = 0; i < n; i++) perm[i] = i;
            for (int i = n - 1; i > 0; i--) { /* Fisher-Yates, counting exchanges */
                int j = (int)(lh_fam_rnd() % (uint64_t)(i + 1));
                if (j != i) {
                    int tmp = perm[i];
                    perm[i] = perm[j];
                    perm[j] = tmp;
                    sign = -sign;
                }
            }
            for (int i = 0; i < n; i++) q[i] = p[perm[i]];
            LH_EXPECT_EQ_INT(perturbed(ctx, lifted, dim, q), sign * s);
            if (LH_FAILED()) LH_NOTE("dim %d case %d", dim, t);
        }
    }
    lh_pred_free(ctx);
}

LH_TEST(orient_sos_follows_argument_permutations) { check_antisymmetry(lh_t_, 0, LH_ORIENT_MAX_DIM); }
LH_TEST(insphere_sos_follows_argument_permutations) { check_antisymmetry(lh_t_, 1, LH_INSPHERE_MAX_DIM); }

/* The in-flat insphere (lh_exact.h) against lh_insphere_sos, exactly degenerate
 * cases included: with J all the coordinates (k = d) the matrix is the same; for
 * points (u, v) of R^2 placed in R^3 as (3u, 4u, 5v), a similarity, with J = {0, 2}
 * its columns are H's times 1, 3, 5, 25 and the rows keep their order. */
LH_TEST(in_flat_insphere_matches_the_full_one)
{
    lh_pred *ctx;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    int same = 0, embedded = 0;
    for (int t = 0; t < 4000 && !LH_FAILED(); t++) {
        int dim = 2 + t % 3, n = dim + 2;
        double x[LH__MAXN][8], e[LH__MAXN][8];
        const double *p[LH__MAXN], *q[LH__MAXN];
        random_points(x, n, dim, t % 2 ? 2 : 3);
        for (int i = 0; i < n; i++) p[i] = x[i];
        int J[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        int want = lh_insphere_sos(ctx, dim, p);
        LH_EXPECT_EQ_INT(lh__insphere_flat_sos(ctx, dim, dim, J, p), want);
        same++;
        if (dim != 2) continue;
        for (int i = 0; i < n; i++) {
            e[i][0] = 3 * x[i][0];
            e[i][1] = 4 * x[i][0];
            e[i][2] = 5 * x[i][1];
            q[i] = e[i];
        }
        int J2[2] = {0, 2};
        LH_EXPECT_EQ_INT(lh__insphere_flat_sos(ctx, 3, 2, J2, q), want);
        LH_EXPECT_EQ_INT(lh__insphere_flat(ctx, 3, 2, J2, q), lh_insphere(ctx, 2, p));
        embedded++;
        if (LH_FAILED()) LH_NOTE("case %d", t);
    }
    lh_pred_counters c;
    lh_pred_counters_get(ctx, &c);
    LH_EXPECT_GT_U64(c.sos_general, 0);
    LH_EXPECT_GT_INT(embedded, 1000);
    lh_pred_free(ctx);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(orient_2_matches_definition),
        LH_CASE(orient_3_matches_definition),
        LH_CASE(insphere_2_matches_definition), LH_CASE(insphere_3_matches_definition),
        LH_CASE(orient_sos_follows_argument_permutations),
        LH_CASE(insphere_sos_follows_argument_permutations),
        LH_CASE(in_flat_insphere_matches_the_full_one)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
