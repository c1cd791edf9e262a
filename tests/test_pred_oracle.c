/*
 * test_pred_oracle.c — the exact predicates against an exact rational oracle.
 *
 * For orient_k (k = 1..8) and insphere_d (d = 1..7) this test draws at least 10^5
 * cases per predicate and dimension (scaled by LH_TEST_SCALE, a number in (0,1],
 * but never fewer than 1000) and compares the library with the exact sign of the
 * homogeneous determinant as lifthull.h defines it:
 *
 *   orient_k   = sign det [ 1  p_i ]            rows i = 0..k
 *   insphere_d = sign det [ 1  p_i  |p_i|^2 ]   rows i = 0..d+1
 *
 * The oracle is GMP arithmetic: every double is split exactly into an odd integer
 * times a power of two, all coordinates are brought to integers by one common power
 * of two (a positive scaling of columns, so the sign is kept), |p|^2 is formed in
 * integers, row 0 is subtracted from the others (det [1 p] = det [p_i - p_0]) and the
 * sign comes from fraction-free (Bareiss) elimination with pivoting on nonzero. On a
 * regular subset of the cases that oracle is itself cross-checked against plain
 * rational Gaussian elimination on the full homogeneous matrix in mpq_t, with
 * mpq_set_d converting the doubles.
 *
 * Case families (interleaved; each case is regenerable from the seed and its number):
 *   uniform  uniform random points in [-1,1]^k;
 *   near     exactly degenerate configurations built in exact double arithmetic
 *            (points on a flat through dyadic base points with dyadic affine weights;
 *            for insphere also integer points on a sphere from the inverse
 *            stereographic projection of integer parameters, and points on a common
 *            hyperplane), or nearly degenerate by rounding (affine combinations and
 *            points on a sphere evaluated in floating point); then one coordinate of
 *            one point is moved by one ulp up, down, or not at all;
 *   1e9+     uniform or near points scaled by a small factor and offset by +-1e9;
 *   tiny     uniform or near points scaled by 1e-300 .. 1e-320 (subnormals included);
 *   mixed    every coordinate uniform * 10^u, u uniform in [-8, 8];
 *   degen    exactly degenerate: repeated points, points on a common flat with small
 *            integer coordinates, integer grids, cospherical integer points, and the
 *            same scaled by powers of two across the exponent range.
 *
 * Checks. Every case: lh_orient / lh_insphere equals the oracle; the _sos variant
 * returns +1 or -1 and equals the oracle when that is nonzero. When the oracle is
 * zero and the points are pairwise distinct, the _sos sign is compared with a
 * reference implementation of the perturbation lifthull.h defines (see
 * sos_reference_sign). On a subset of the cases with pairwise distinct points
 * (SoS assumes distinct points; with repeated points it breaks ties by position):
 * exchanging two arguments negates both predicates, an arbitrary permutation
 * multiplies them by its sign, scaling all coordinates by 2^e (exactly) changes
 * neither, nor (orient only) does an exact translation; and for one more point q
 * the SoS answers on the n+1 subsets of n points obey the identity
 * sum_i (-1)^i det(all but point i) = 0 (the expansion of a matrix with a repeated
 * column of ones): with one fixed perturbation of every point the n+1 signed
 * answers (-1)^i sos_i cannot all agree.
 *
 * Per family the test counts oracle zeros and the library's exact-stage exits on the
 * plain calls, and asserts that the degenerate family produced zeros, that the near
 * family straddles zero (zeros, positive and negative signs), and that the near,
 * 1e9+ and tiny families needed the exact stage. It also counts, for information,
 * how often a naive double-precision elimination gets the sign wrong. One summary
 * line per predicate goes to stdout: cases, oracle zeros, the exact-stage fraction
 * of all calls (lh_pred_counters), the time, then per family n (cases), z (oracle
 * zeros), x (exact-stage exits of the plain calls), w (naive double sign wrong),
 * s (permutation/scaling checks), r (subset-identity checks), e (SoS reference
 * checks).
 *
 * Files: the case families in pred_oracle_cases.c, the GMP oracle and the SoS
 * reference in pred_oracle_exact.c (pred_oracle.h), the checks and the driver here.
 *
 * Environment: LH_TEST_SCALE (default 1); LH_ORACLE_SEED (a 64-bit base seed) to
 * vary the cases; LH_ORACLE_CASE=N to rerun case N alone (a failure prints both).
 */
#include "lifthull.h"
#include "lh_test.h"
#include "pred_oracle.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char *const fam_name[F_COUNT] = {"uniform", "near", "1e9+",
                                              "tiny",    "mixed", "degen"};

/* Interleaving of the families over the cases: uniform 15 %, near 25 %, 1e9+ 15 %,
 * tiny 15 %, mixed 10 %, degen 20 %. */
static const unsigned char fam_schedule[20] = {
    F_UNIFORM, F_NEAR, F_BIG, F_TINY,  F_DEGEN, F_NEAR, F_MIXED, F_UNIFORM, F_NEAR, F_BIG,
    F_TINY,    F_DEGEN, F_NEAR, F_UNIFORM, F_NEAR, F_BIG, F_TINY, F_DEGEN,   F_MIXED, F_DEGEN};

/*
 * Which cases get which extra checks. Every case gets the plain predicate and the
 * SoS value. Each case then draws its own lots, so that no family is favoured by
 * the interleaving. "Generic" means a case of the uniform, 1e9+, tiny or mixed
 * family whose oracle sign is nonzero; the others (near, degen, every oracle zero)
 * are where SoS has work to do, and there the share thins out with the number n of
 * points per call (the exact stage's cost grows like n 2^n): 1 in THIN(n) cases,
 * THIN(n) = 2^max(0, n-6).
 */
enum {
    REF_EVERY = 50,           /* cross-check the oracle against plain mpq elimination */
    PERM_GENERIC_EVERY = 10,  /* exchange and permutation checks (4 more calls) */
    PERM_DEGEN_EVERY = 1,     /* ... times THIN(n) */
    RADON_GENERIC_EVERY = 50, /* the (n+1)-subset identity (n+1 more SoS calls) */
    RADON_DEGEN_EVERY = 4,    /* ... times THIN(n) */
    SOSREF_EVERY = 1,         /* oracle zeros compared with the SoS reference */
    MAX_BAD_CASES = 5         /* stop a test after this many failing cases */
};

static const uint64_t default_seed = 0x6c69667468756c6cu; /* "lifthull" */

/* ---- the library under test ------------------------------------------------------ */

static int lib_plain(lh_pred *ctx, int kind, int D, const double *const *pts)
{
    return kind == ORIENT ? lh_orient(ctx, D, pts) : lh_insphere(ctx, D, pts);
}

static int lib_sos(lh_pred *ctx, int kind, int D, const double *const *pts)
{
    return kind == ORIENT ? lh_orient_sos(ctx, D, pts) : lh_insphere_sos(ctx, D, pts);
}

/* ---- the driver ------------------------------------------------------------------ */

typedef struct fam_stats {
    long cases, zeros, pos, neg, naive_wrong, perm_checked, radon_checked, sosref_checked;
    uint64_t exact; /* exits of the plain calls by residues or the exact stage */
} fam_stats;

typedef struct run_info {
    const char *pred; /* "orient" / "insphere" */
    uint64_t base_seed, seed;
    long index;
} run_info;

static double test_scale(void)
{
    const char *s = getenv("LH_TEST_SCALE");
    if (!s || !*s) return 1.0;
    char *end;
    double v = strtod(s, &end);
    if (end == s || !(v > 0.0 && v <= 1.0)) {
        fprintf(stderr, "test_pred_oracle: ignoring LH_TEST_SCALE=%s (want (0,1])\n", s);
        return 1.0;
    }
    return v;
}

static uint64_t test_seed(void)
{
    const char *s = getenv("LH_ORACLE_SEED");
    if (!s || !*s) return default_seed;
    return (uint64_t)strtoull(s, NULL, 0);
}

static double now_seconds(void)
{
    struct timespec ts;
    if (timespec_get(&ts, TIME_UTC) != TIME_UTC) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void note_points(lh_test_state *lh_t_, const char *label, const double *const *pts,
                        int n, int D)
{
    for (int i = 0; i < n; i++) {
        char buf[MAXD * 32 + 8];
        size_t len = 0;
        for (int j = 0; j < D; j++)
            len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%a", j ? ", " : "",
                                    pts[i][j]);
        LH_NOTE("%s[%d] = (%s)", label, i, buf);
    }
}

/* One case under check: its points, the oracle's and the library's answers, and
 * whether (and where) a comparison failed. */
typedef struct case_check {
    lh_pred *ctx;
    oracle_ws *o;
    rng *r;
    int kind, D, n;
    const double *pts[MAXN];
    int oracle, sos, distinct;
    int bad;          /* a comparison failed */
    const char *what; /* the first failing check ("" while none) */
} case_check;

/* Which extra checks a case gets (drawn in this order from the case's generator). */
typedef struct case_lots {
    int ref, perm, radon, sosref;
} case_lots;

/* A failed comparison inside one case: report it (the harness prints both sides). */
#define CASE_EQ(k, a, b)                                                               \
    do {                                                                               \
        if ((a) != (b)) {                                                              \
            LH_EXPECT_EQ_INT(a, b);                                                    \
            (k)->bad = 1;                                                              \
        }                                                                              \
    } while (0)

static case_lots draw_lots(case_check *k, const pcase *c)
{
    const int generic = c->fam != F_NEAR && c->fam != F_DEGEN && k->oracle != 0;
    const int thin = k->n > 6 ? 1 << (k->n - 6) : 1;
    case_lots l;
    l.ref = rng_below(k->r, REF_EVERY) == 0;
    l.perm = rng_below(k->r, generic ? PERM_GENERIC_EVERY : PERM_DEGEN_EVERY * thin) == 0;
    l.radon = rng_below(k->r, generic ? RADON_GENERIC_EVERY : RADON_DEGEN_EVERY * thin) == 0;
    l.sosref = rng_below(k->r, SOSREF_EVERY) == 0;
    return l;
}

/* The test's own two oracles must agree. */
static void check_oracle_ref(lh_test_state *lh_t_, case_check *k)
{
    const int oracle = k->oracle, oracle_mpq = oracle_ref_sign(k->o, k->kind, k->D, k->n, k->pts);
    CASE_EQ(k, oracle, oracle_mpq);
    if (k->bad) k->what = "mpq cross-check of the oracle";
}

/* The plain predicate equals the oracle; counts its exact-stage exits. */
static void check_plain(lh_test_state *lh_t_, case_check *k, fam_stats *fs)
{
    lh_pred_counters before, after;
    lh_pred_counters_get(k->ctx, &before);
    const int oracle = k->oracle, lib = lib_plain(k->ctx, k->kind, k->D, k->pts);
    lh_pred_counters_get(k->ctx, &after);
    fs->exact += after.exact_exits - before.exact_exits + after.residue_exits -
                 before.residue_exits;
    CASE_EQ(k, lib, oracle);
    if (k->bad && !*k->what) k->what = "plain sign";
}

/* The SoS variant answers +1 or -1, and the oracle's sign when that is nonzero. */
static void check_sos_value(lh_test_state *lh_t_, case_check *k)
{
    const int oracle = k->oracle, sos = lib_sos(k->ctx, k->kind, k->D, k->pts);
    k->sos = sos;
    int sos_is_unit = sos == 1 || sos == -1;
    CASE_EQ(k, sos_is_unit, 1);
    if (oracle != 0) CASE_EQ(k, sos, oracle);
    if (k->bad) k->what = "sos value";
}

/* An oracle zero among distinct points: SoS equals the reference perturbation. */
static void check_sos_reference(lh_test_state *lh_t_, case_check *k, fam_stats *fs)
{
    /* o->X still holds this case's points (oracle_sign in check_case) */
    fs->sosref_checked++;
    const int sos = k->sos;
    int sos_reference = sos_reference_sign(k->o, k->r, k->kind, k->D, k->n, k->pts);
    CASE_EQ(k, sos, sos_reference);
    if (k->bad) k->what = "SoS sign against the reference perturbation";
}

/* Exchanging two arguments negates both predicates. */
static void check_exchange(lh_test_state *lh_t_, case_check *k)
{
    const int n = k->n;
    const double *sw[MAXN];
    memcpy(sw, k->pts, sizeof k->pts);
    int a = rng_below(k->r, n), b = rng_below(k->r, n - 1);
    if (b >= a) b++;
    sw[a] = k->pts[b];
    sw[b] = k->pts[a];
    int sos_swapped = lib_sos(k->ctx, k->kind, k->D, sw);
    int lib_swapped = lib_plain(k->ctx, k->kind, k->D, sw);
    int minus_sos = -k->sos, minus_oracle = -k->oracle;
    CASE_EQ(k, sos_swapped, minus_sos);
    CASE_EQ(k, lib_swapped, minus_oracle);
    if (k->bad) {
        k->what = "exchange of two arguments";
        LH_NOTE("exchanged arguments %d and %d", a, b);
    }
}

/* An arbitrary permutation multiplies both predicates by its sign. */
static void check_permutation(lh_test_state *lh_t_, case_check *k)
{
    const int n = k->n;
    const double *pm[MAXN];
    int perm[MAXN], psign = 1;
    for (int i = 0; i < n; i++) perm[i] = i;
    for (int i = n - 1; i > 0; i--) {
        int j = rng_below(k->r, i + 1);
        if (j != i) {
            int t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
            psign = -psign;
        }
    }
    for (int i = 0; i < n; i++) pm[i] = k->pts[perm[i]];
    int sos_permuted = lib_sos(k->ctx, k->kind, k->D, pm);
    int lib_permuted = lib_plain(k->ctx, k->kind, k->D, pm);
    int psign_sos = psign * k->sos, psign_oracle = psign * k->oracle;
    CASE_EQ(k, sos_permuted, psign_sos);
    CASE_EQ(k, lib_permuted, psign_oracle);
    if (k->bad && !*k->what) {
        k->what = "permutation of the arguments";
        char buf[MAXN * 4 + 4];
        size_t len = 0;
        for (int i = 0; i < n; i++)
            len += (size_t)snprintf(buf + len, sizeof buf - len, " %d", perm[i]);
        LH_NOTE("permutation:%s (sign %d)", buf, psign);
    }
}

/* Scaling every coordinate by 2^e (exactly) multiplies each column of the perturbed
 * matrix by a positive constant and keeps the lexicographic order: the SoS sign must
 * not change. The exponent is drawn even when an earlier check failed. */
static void check_scaling(lh_test_state *lh_t_, case_check *k)
{
    double moved[MAXN][MAXD];
    const double *mv[MAXN];
    int e = rng_below(k->r, 2) ? rng_int(k->r, 1, 40) : -rng_int(k->r, 1, 40), exact = 1;
    for (int i = 0; i < k->n; i++) {
        mv[i] = moved[i];
        for (int j = 0; j < k->D && exact; j++) {
            moved[i][j] = ldexp(k->pts[i][j], e);
            exact = isfinite(moved[i][j]) && ldexp(moved[i][j], -e) == k->pts[i][j];
        }
    }
    if (k->bad || !exact) return;
    int sos_scaled = lib_sos(k->ctx, k->kind, k->D, mv);
    int lib_scaled = lib_plain(k->ctx, k->kind, k->D, mv);
    const int sos = k->sos, oracle = k->oracle;
    CASE_EQ(k, sos_scaled, sos);
    CASE_EQ(k, lib_scaled, oracle);
    if (k->bad) {
        k->what = "scaling by a power of two";
        LH_NOTE("scaled by 2^%d", e);
    }
}

/* orient only: an exact translation is a column operation with the column of ones and
 * changes neither sign. */
static void check_translation(lh_test_state *lh_t_, case_check *k)
{
    const int D = k->D;
    double moved[MAXN][MAXD], t[MAXD];
    const double *mv[MAXN];
    int from = rng_below(k->r, k->n), exact = 1;
    for (int j = 0; j < D; j++)
        t[j] = rng_below(k->r, 2) ? -k->pts[from][j] : (double)rng_int(k->r, -1000, 1000);
    for (int i = 0; i < k->n; i++) {
        mv[i] = moved[i];
        for (int j = 0; j < D && exact; j++) {
            /* Knuth's two-sum: the rounding error of x + t, exactly. */
            double x = k->pts[i][j], y = x + t[j], tv = y - x;
            double err = (x - (y - tv)) + (t[j] - tv);
            moved[i][j] = y + 0.0;
            exact = isfinite(y) && err == 0.0;
        }
    }
    if (!exact) return;
    int sos_translated = lib_sos(k->ctx, k->kind, D, mv);
    int lib_translated = lib_plain(k->ctx, k->kind, D, mv);
    const int sos = k->sos, oracle = k->oracle;
    CASE_EQ(k, sos_translated, sos);
    CASE_EQ(k, lib_translated, oracle);
    if (k->bad) {
        k->what = "exact translation";
        char buf[MAXD * 32 + 8];
        size_t len = 0;
        for (int j = 0; j < D; j++)
            len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%a", j ? ", " : "", t[j]);
        LH_NOTE("translated by (%s)", buf);
    }
}

/* The exchange, permutation, scaling and (orient) translation checks, in that order;
 * the permutation runs even after a failed exchange. */
static void check_symmetries(lh_test_state *lh_t_, case_check *k, fam_stats *fs)
{
    fs->perm_checked++;
    check_exchange(lh_t_, k);
    check_permutation(lh_t_, k);
    check_scaling(lh_t_, k);
    if (!k->bad && k->kind == ORIENT) check_translation(lh_t_, k);
}

/* The (n+1)-subset identity with one more point q (a midpoint, a reflection or a
 * one-ulp neighbour of the case's points). */
static void check_radon(lh_test_state *lh_t_, case_check *k, fam_stats *fs)
{
    const int D = k->D, n = k->n;
    double q[MAXD];
    int qa = rng_below(k->r, n), qb = rng_below(k->r, n - 1), how = rng_below(k->r, 3);
    if (qb >= qa) qb++;
    for (int j = 0; j < D; j++) {
        if (how == 0) q[j] = 0.5 * k->pts[qa][j] + 0.5 * k->pts[qb][j];
        else if (how == 1) q[j] = 2.0 * k->pts[qa][j] - k->pts[qb][j];
        else q[j] = k->pts[qa][j];
        q[j] += 0.0;
    }
    if (how == 2) {
        int j = rng_below(k->r, D);
        q[j] = nextafter(q[j], rng_below(k->r, 2) ? INFINITY : -INFINITY);
    }
    const double *all[MAXN];
    memcpy(all, k->pts, sizeof k->pts);
    all[n] = q;
    int finite = 1;
    for (int j = 0; j < D; j++) finite &= isfinite(q[j]) != 0;
    if (!finite || !all_distinct(all, n + 1, D)) return;
    fs->radon_checked++;
    int seen_pos = 0, seen_neg = 0;
    for (int i = 0; i <= n; i++) {
        const double *sub[MAXN];
        for (int l = 0, t = 0; l <= n; l++)
            if (l != i) sub[t++] = all[l];
        int s = lib_sos(k->ctx, k->kind, D, sub) * (i % 2 ? -1 : 1);
        seen_pos |= s > 0;
        seen_neg |= s < 0;
    }
    int mixed_signs = seen_pos && seen_neg;
    CASE_EQ(k, mixed_signs, 1);
    if (k->bad) {
        k->what = "(n+1)-subset identity: all (-1)^i sos_i agree";
        note_points(lh_t_, "q", (const double *const *)all + n, 1, D);
    }
}

/* Runs every check on one case; returns 1 when all passed. */
static int check_case(lh_test_state *lh_t_, lh_pred *ctx, oracle_ws *o, rng *r,
                      const pcase *c, const run_info *ri, fam_stats *fs)
{
    case_check k = {.ctx = ctx, .o = o, .r = r, .kind = c->kind, .D = c->D,
                    .n = c->n, .what = ""};
    for (int i = 0; i < k.n; i++) k.pts[i] = c->p[i];
    k.oracle = oracle_sign(o, k.kind, k.D, k.n, k.pts);
    const case_lots lots = draw_lots(&k, c);
    if (lots.ref) check_oracle_ref(lh_t_, &k);
    fs->cases++;
    fs->zeros += k.oracle == 0;
    fs->pos += k.oracle > 0;
    fs->neg += k.oracle < 0;
    if (naive_sign(k.kind, k.D, k.n, k.pts) != k.oracle) fs->naive_wrong++;
    check_plain(lh_t_, &k, fs);
    k.distinct = all_distinct(k.pts, k.n, k.D);
    if (!k.bad) check_sos_value(lh_t_, &k);
    if (!k.bad && k.oracle == 0 && k.distinct && lots.sosref) check_sos_reference(lh_t_, &k, fs);
    if (!k.bad && k.distinct && lots.perm) check_symmetries(lh_t_, &k, fs);
    if (!k.bad && k.distinct && lots.radon) check_radon(lh_t_, &k, fs);
    if (k.bad) {
        LH_NOTE("%s_%d failed (%s): test seed %#llx, case %ld, family %s, variant %d, "
                "oracle %d; rerun with LH_ORACLE_SEED=%#llx LH_ORACLE_CASE=%ld",
                ri->pred, k.D, k.what, (unsigned long long)ri->seed, ri->index,
                fam_name[c->fam], c->var, k.oracle, (unsigned long long)ri->base_seed,
                ri->index);
        note_points(lh_t_, "p", k.pts, k.n, k.D);
    }
    return !k.bad;
}

/* The number of cases to run, [*first, return): LH_TEST_SCALE * 10^5 (at least 1000),
 * or the one case LH_ORACLE_CASE names. */
static long case_range(long *first)
{
    long cases = (long)(100000.0 * test_scale() + 0.5);
    if (cases < 1000) cases = 1000;
    *first = 0;
    const char *only = getenv("LH_ORACLE_CASE"); /* rerun one case */
    if (only && *only) {
        *first = strtol(only, NULL, 10);
        cases = *first + 1;
    }
    return cases;
}

/* One summary line on stdout: the counts of the run and of each family. */
static void print_summary(lh_pred *ctx, const char *pred, int D, long done, uint64_t seed,
                          double t0, const fam_stats *fs)
{
    lh_pred_counters cnt;
    lh_pred_counters_get(ctx, &cnt);
    long zeros = 0;
    for (int f = 0; f < F_COUNT; f++) zeros += fs[f].zeros;
    uint64_t answered = cnt.filter_exits + cnt.residue_exits + cnt.exact_exits;
    double exact_fraction = answered ? (double)cnt.exact_exits / (double)answered : 0.0;
    char fam_buf[F_COUNT * 96];
    size_t len = 0;
    for (int f = 0; f < F_COUNT; f++)
        len += (size_t)snprintf(fam_buf + len, sizeof fam_buf - len,
                                " | %s n=%ld z=%ld x=%llu w=%ld s=%ld r=%ld e=%ld", fam_name[f],
                                fs[f].cases, fs[f].zeros, (unsigned long long)fs[f].exact,
                                fs[f].naive_wrong, fs[f].perm_checked, fs[f].radon_checked,
                                fs[f].sosref_checked);
    printf("oracle %s_%d: cases=%ld oracle_zeros=%ld exact_fraction=%.4f (calls=%llu "
           "filter=%llu residue=%llu exact=%llu zero=%llu sos_fast=%llu sos_general=%llu) time=%.2fs "
           "seed=%#llx%s\n",
           pred, D, done, zeros, exact_fraction, (unsigned long long)cnt.calls,
           (unsigned long long)cnt.filter_exits, (unsigned long long)cnt.residue_exits,
           (unsigned long long)cnt.exact_exits, (unsigned long long)cnt.zero_results, (unsigned long long)cnt.sos_fast,
           (unsigned long long)cnt.sos_general, now_seconds() - t0,
           (unsigned long long)seed, fam_buf);
    fflush(stdout);
}

/* The families hit the regimes they are meant to hit. */
static void check_coverage(lh_test_state *lh_t_, int kind, int D, const fam_stats *fs)
{
    LH_EXPECT_GT_INT(fs[F_DEGEN].zeros, 0);
    LH_EXPECT_GT_INT(fs[F_NEAR].zeros, 0);
    LH_EXPECT_GT_INT(fs[F_NEAR].pos, 0);
    LH_EXPECT_GT_INT(fs[F_NEAR].neg, 0);
    /* ...and needed exact arithmetic (residues or the exact stage). orient_1 is exempt: the sign of p_1 - p_0 is
     * a comparison of two doubles, which floating point gets right every time. */
    if (!(kind == ORIENT && D == 1)) {
        LH_EXPECT_GT_U64(fs[F_NEAR].exact, 0);
        LH_EXPECT_GT_U64(fs[F_BIG].exact, 0);
        LH_EXPECT_GT_U64(fs[F_TINY].exact, 0);
    }
    LH_EXPECT_GT_INT(fs[F_DEGEN].perm_checked + fs[F_NEAR].perm_checked, 0);
    LH_EXPECT_GT_INT(fs[F_DEGEN].radon_checked + fs[F_NEAR].radon_checked, 0);
    /* In R^1 exact zeros need repeated points, outside the SoS precondition. */
    if (D > 1) LH_EXPECT_GT_INT(fs[F_DEGEN].sosref_checked + fs[F_NEAR].sosref_checked, 0);
}

static void run_oracle(lh_test_state *lh_t_, int kind, int D)
{
    const char *pred = kind == ORIENT ? "orient" : "insphere";
    double t0 = now_seconds();
    long first;
    const long cases = case_range(&first);
    const uint64_t base_seed = test_seed();
    const uint64_t seed = base_seed ^ ((uint64_t)(kind * 16 + D) * 0x2545f4914f6cdd1du);

    lh_pred *ctx = NULL;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &ctx), LH_OK);
    oracle_ws *o = oracle_new();
    if (!o) {
        lh_pred_free(ctx);
        LH_ASSERT_TRUE(o != NULL);
    }

    fam_stats fs[F_COUNT];
    memset(fs, 0, sizeof fs);
    run_info ri = {pred, base_seed, seed, 0};
    long bad_cases = 0, done = 0;
    for (long ci = first; ci < cases; ci++) {
        rng r;
        lht_rng_seed(&r, seed + (uint64_t)ci * 0xd1b54a32d192ed03u);
        pcase c;
        c.kind = kind;
        c.D = D;
        c.n = kind == ORIENT ? D + 1 : D + 2;
        gen_case(&r, &c, fam_schedule[ci % 20]);
        ri.index = ci;
        done++;
        if (!check_case(lh_t_, ctx, o, &r, &c, &ri, &fs[c.fam]) &&
            ++bad_cases >= MAX_BAD_CASES) {
            LH_NOTE("%s_%d: stopped after %ld failing cases", pred, D, bad_cases);
            break;
        }
    }
    print_summary(ctx, pred, D, done, seed, t0, fs);
    if (bad_cases == 0 && first == 0) check_coverage(lh_t_, kind, D, fs);
    oracle_free(o);
    lh_pred_free(ctx);
}

#define ORACLE_TEST(kind, name, D) \
    LH_TEST(oracle_##name##_##D) { run_oracle(lh_t_, kind, D); }

ORACLE_TEST(ORIENT, orient, 1)
ORACLE_TEST(ORIENT, orient, 2)
ORACLE_TEST(ORIENT, orient, 3)
ORACLE_TEST(ORIENT, orient, 4)
ORACLE_TEST(ORIENT, orient, 5)
ORACLE_TEST(ORIENT, orient, 6)
ORACLE_TEST(ORIENT, orient, 7)
ORACLE_TEST(ORIENT, orient, 8)
ORACLE_TEST(INSPHERE, insphere, 1)
ORACLE_TEST(INSPHERE, insphere, 2)
ORACLE_TEST(INSPHERE, insphere, 3)
ORACLE_TEST(INSPHERE, insphere, 4)
ORACLE_TEST(INSPHERE, insphere, 5)
ORACLE_TEST(INSPHERE, insphere, 6)
ORACLE_TEST(INSPHERE, insphere, 7)
ORACLE_TEST(INSPHERE, insphere, 8)

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(oracle_orient_1),   LH_CASE(oracle_orient_2),   LH_CASE(oracle_orient_3),
        LH_CASE(oracle_orient_4),   LH_CASE(oracle_orient_5),   LH_CASE(oracle_orient_6),
        LH_CASE(oracle_orient_7),   LH_CASE(oracle_orient_8),   LH_CASE(oracle_insphere_1),
        LH_CASE(oracle_insphere_2), LH_CASE(oracle_insphere_3), LH_CASE(oracle_insphere_4),
        LH_CASE(oracle_insphere_5), LH_CASE(oracle_insphere_6), LH_CASE(oracle_insphere_7), LH_CASE(oracle_insphere_8),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
