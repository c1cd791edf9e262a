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
 * Environment: LH_TEST_SCALE (default 1); LH_ORACLE_SEED (a 64-bit base seed) to
 * vary the cases; LH_ORACLE_CASE=N to rerun case N alone (a failure prints both).
 */
#include "lifthull.h"
#include "lh_test.h"
#include "sites.h"

#include <gmp.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { MAXD = 8, MAXN = 11 }; /* up to 10 points of a call, plus one extra point */
enum { ORIENT = 0, INSPHERE = 1 };
enum { F_UNIFORM, F_NEAR, F_BIG, F_TINY, F_MIXED, F_DEGEN, F_COUNT };
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

/* ---- PRNG: xoshiro256** (tools/sites.h), the draws the cases need ------------- */

typedef lht_rng rng;

/* Uniform in 0..n-1 (n >= 1). */
static int rng_below(rng *r, int n)
{
    return (int)(((lht_rng_next(r) >> 32) * (uint64_t)n) >> 32);
}

/* Uniform in lo..hi inclusive. */
static int rng_int(rng *r, int lo, int hi) { return lo + rng_below(r, hi - lo + 1); }


/* Uniform in [-1,1), multiples of 2^-52. */
static double rng_sym(rng *r) { return (double)(lht_rng_next(r) >> 11) * 0x1p-52 - 1.0; }

/* ---- cases ---------------------------------------------------------------------- */

typedef struct pcase {
    int kind; /* ORIENT or INSPHERE */
    int D;    /* dimension of the points */
    int n;    /* points of one call: D+1 (orient) or D+2 (insphere) */
    int fam, var;
    double p[MAXN][MAXD];
} pcase;

static void shuffle_points(rng *r, pcase *c)
{
    for (int i = c->n - 1; i > 0; i--) {
        int j = rng_below(r, i + 1);
        for (int k = 0; k < c->D; k++) {
            double t = c->p[i][k];
            c->p[i][k] = c->p[j][k];
            c->p[j][k] = t;
        }
    }
}

/* Multiplies every coordinate by 2^e (exact for the generators that use it). */
static void scale_pow2(pcase *c, int e)
{
    for (int i = 0; i < c->n; i++)
        for (int j = 0; j < c->D; j++) c->p[i][j] = ldexp(c->p[i][j], e);
}

static void gen_uniform(rng *r, pcase *c)
{
    for (int i = 0; i < c->n; i++)
        for (int j = 0; j < c->D; j++) c->p[i][j] = rng_sym(r);
}

/* A small integer, or a dyadic k/2^e with |k| <= 64, e <= 6. */
static double small_coord(rng *r, int dyadic)
{
    if (dyadic) return ldexp((double)rng_int(r, -64, 64), -rng_int(r, 0, 6));
    return (double)rng_int(r, -20, 20);
}

/*
 * All n points on one affine flat of dimension <= m: m+1 base points with small
 * integer (dyadic) coordinates, the others affine combinations of them with integer
 * weights summing to 1 (dyadic weights a/4 summing to 1). Every product and partial
 * sum is a multiple of 2^-8 below 2^16 in magnitude, so the doubles are exact and the
 * configuration is exactly degenerate when m < n-1. Rows are then shuffled.
 */
static void gen_flat(rng *r, pcase *c, int m, int dyadic)
{
    int n = c->n, D = c->D;
    if (m > n - 1) m = n - 1;
    if (m < 0) m = 0;
    for (int l = 0; l <= m; l++)
        for (int j = 0; j < D; j++) c->p[l][j] = small_coord(r, dyadic);
    int total = dyadic ? 4 : 1, amp = dyadic ? 4 : 2;
    for (int i = m + 1; i < n; i++) {
        int a[MAXN], s = 0;
        for (int l = 0; l < m; l++) {
            a[l] = rng_int(r, -amp, amp);
            s += a[l];
        }
        a[m] = total - s;
        for (int j = 0; j < D; j++) {
            double acc = 0.0;
            for (int l = 0; l <= m; l++) acc += (double)a[l] * c->p[l][j];
            c->p[i][j] = acc / (double)total;
        }
    }
    shuffle_points(r, c);
}

/* Like gen_flat but with random base points and random real weights, evaluated in
 * floating point: degenerate up to rounding. */
static void gen_flat_rounded(rng *r, pcase *c, int m)
{
    int n = c->n, D = c->D;
    if (m > n - 1) m = n - 1;
    if (m < 0) m = 0;
    for (int l = 0; l <= m; l++)
        for (int j = 0; j < D; j++) c->p[l][j] = rng_sym(r);
    for (int i = m + 1; i < n; i++) {
        double w[MAXN], s = 0.0;
        for (int l = 0; l < m; l++) {
            w[l] = 2.0 * rng_sym(r);
            s += w[l];
        }
        w[m] = 1.0 - s;
        for (int j = 0; j < D; j++) {
            double acc = 0.0;
            for (int l = 0; l <= m; l++) acc += w[l] * c->p[l][j];
            c->p[i][j] = acc;
        }
    }
    shuffle_points(r, c);
}

static uint64_t gcd_u64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/*
 * n integer points on the sphere |x| = L centred at the origin, from the inverse
 * stereographic projection of integer parameters (a in Z^(D-1), b >= 1):
 *     x = (2ab, |a|^2 - b^2) * L / (|a|^2 + b^2),
 * or the pole (0,..,0,L), with L the lcm of the denominators (kept below 2^36, so every
 * coordinate is an exact double). Then a random signed permutation of the axes and a
 * translation by an integer vector, both exact.
 */
static void gen_sphere_int(rng *r, pcase *c)
{
    static const int amax[MAXD + 1] = {0, 0, 12, 5, 3, 2, 2, 2, 2};
    int n = c->n, D = c->D;
    int64_t num[MAXN][MAXD], den[MAXN];
    uint64_t L = 1;
    for (int attempt = 0;; attempt++) {
        int A = attempt < 20 ? amax[D] : 1, B = A;
        int ok = 1;
        L = 1;
        for (int i = 0; i < n && ok; i++) {
            int pole = D == 1 ? rng_below(r, 2) : rng_below(r, 4 * n) == 0;
            if (pole) {
                for (int j = 0; j < D - 1; j++) num[i][j] = 0;
                num[i][D - 1] = 1;
                den[i] = 1;
            } else {
                int64_t b = rng_int(r, 1, B), aa = 0;
                for (int j = 0; j < D - 1; j++) {
                    int64_t a = rng_int(r, -A, A);
                    aa += a * a;
                    num[i][j] = 2 * a * b;
                }
                num[i][D - 1] = aa - b * b;
                den[i] = aa + b * b;
            }
            L = L / gcd_u64(L, (uint64_t)den[i]) * (uint64_t)den[i];
            if (L > ((uint64_t)1 << 36)) ok = 0;
        }
        if (ok) break;
    }
    int perm[MAXD];
    for (int j = 0; j < D; j++) perm[j] = j;
    for (int j = D - 1; j > 0; j--) {
        int t = rng_below(r, j + 1), s = perm[j];
        perm[j] = perm[t];
        perm[t] = s;
    }
    double sgn[MAXD], ctr[MAXD];
    for (int j = 0; j < D; j++) {
        sgn[j] = rng_below(r, 2) ? 1.0 : -1.0;
        ctr[j] = rng_below(r, 2) ? (double)rng_int(r, -(1 << 20), 1 << 20) : 0.0;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < D; j++)
            c->p[i][perm[j]] =
                ctr[j] + sgn[j] * (double)(num[i][j] * (int64_t)(L / (uint64_t)den[i]));
}

/* n points on a sphere, evaluated in floating point: cospherical up to rounding. */
static void gen_sphere_float(rng *r, pcase *c)
{
    int n = c->n, D = c->D;
    double ctr[MAXD], rad = 0.5 + lht_rng_unit(r);
    for (int j = 0; j < D; j++) ctr[j] = rng_sym(r);
    for (int i = 0; i < n; i++) {
        double v[MAXD], q;
        do {
            q = 0.0;
            for (int j = 0; j < D; j++) {
                v[j] = rng_sym(r);
                q += v[j] * v[j];
            }
        } while (q < 1e-3);
        q = sqrt(q);
        for (int j = 0; j < D; j++) c->p[i][j] = ctr[j] + rad * (v[j] / q);
    }
}

/* Points that are the same vector of small integers up to signs and order of the
 * coordinates, plus a common integer centre: cospherical integer points. */
static void gen_signed_perms(rng *r, pcase *c)
{
    int n = c->n, D = c->D;
    int v[MAXD];
    double ctr[MAXD];
    for (int j = 0; j < D; j++) {
        v[j] = rng_int(r, 0, 5);
        ctr[j] = (double)rng_int(r, -100, 100);
    }
    for (int i = 0; i < n; i++) {
        int w[MAXD];
        memcpy(w, v, sizeof w);
        for (int j = D - 1; j > 0; j--) {
            int t = rng_below(r, j + 1), s = w[j];
            w[j] = w[t];
            w[t] = s;
        }
        for (int j = 0; j < D; j++)
            c->p[i][j] = ctr[j] + (double)(rng_below(r, 2) ? w[j] : -w[j]);
    }
}

/* Moves one coordinate of one point by one ulp up or down, or leaves all alone. */
static void move_ulp(rng *r, pcase *c)
{
    int dir = rng_int(r, -1, 1);
    if (!dir) return;
    int i = rng_below(r, c->n), j = rng_below(r, c->D);
    c->p[i][j] = nextafter(c->p[i][j], dir > 0 ? INFINITY : -INFINITY);
}

/* The "near" family before the one-ulp move. var: 0 exact flat, 1 rounded flat,
 * 2 exact integer sphere, 3 exact hyperplane (insphere), 4 rounded sphere. */
static void gen_near_base(rng *r, pcase *c)
{
    int D = c->D;
    if (c->kind == ORIENT) {
        int m = D == 1 ? 0 : (rng_below(r, 2) ? D - 1 : rng_int(r, 1, D - 1));
        if (rng_below(r, 4) == 0) {
            c->var = 1;
            gen_flat_rounded(r, c, m);
        } else {
            c->var = 0;
            gen_flat(r, c, m, 1);
            if (rng_below(r, 2)) scale_pow2(c, rng_int(r, -20, 20));
        }
    } else {
        int v = rng_below(r, 10);
        if (v < 5) {
            c->var = 2;
            gen_sphere_int(r, c);
            if (rng_below(r, 2)) scale_pow2(c, rng_int(r, -30, 10));
        } else if (v < 7) {
            c->var = 3;
            gen_flat(r, c, D - 1, 1);
        } else {
            c->var = 4;
            gen_sphere_float(r, c);
        }
    }
}

/* Exactly degenerate configurations. var: 10 repeated points, 11 integer flat,
 * 12 integer grid, 13 dyadic flat scaled by 2^e, 14 integer sphere, 15 signed
 * permutations, 16 integer sphere scaled by 2^e. */
static void gen_degen(rng *r, pcase *c)
{
    int D = c->D, n = c->n;
    int v = rng_below(r, 20);
    int repeated = c->kind == ORIENT ? (v < 5 || D == 1) : (v < 4 || (D == 1 && v < 8));
    if (repeated) {
        c->var = 10;
        if (rng_below(r, 2)) {
            gen_uniform(r, c);
        } else {
            for (int i = 0; i < n; i++)
                for (int j = 0; j < D; j++) c->p[i][j] = small_coord(r, 0);
        }
        int copies = 1 + rng_below(r, 2);
        for (int t = 0; t < copies; t++) {
            int a = rng_below(r, n), b = rng_below(r, n - 1);
            if (b >= a) b++;
            memcpy(c->p[b], c->p[a], sizeof c->p[a]);
        }
        return;
    }
    if (c->kind == ORIENT) {
        if (v < 13) {
            c->var = 11;
            gen_flat(r, c, rng_int(r, 1, D - 1), 0);
        } else if (v < 17) {
            c->var = 12;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < D; j++) c->p[i][j] = (double)rng_int(r, -1, 1);
        } else {
            c->var = 13;
            gen_flat(r, c, rng_int(r, 0, D - 1), 1);
            scale_pow2(c, rng_int(r, -1060, 900));
        }
    } else {
        if (v < 11) {
            c->var = 14;
            gen_sphere_int(r, c);
        } else if (v < 14) {
            c->var = 15;
            gen_signed_perms(r, c);
        } else if (v < 17) {
            c->var = 11;
            gen_flat(r, c, rng_int(r, 0, D - 1), 0);
        } else if (v < 19) {
            c->var = 12;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < D; j++) c->p[i][j] = (double)rng_int(r, 0, 2);
        } else {
            c->var = 16;
            gen_sphere_int(r, c);
            scale_pow2(c, rng_int(r, -1030, 900));
        }
    }
}

static void gen_case(rng *r, pcase *c, int fam)
{
    int n = c->n, D = c->D;
    c->fam = fam;
    c->var = 0;
    switch (fam) {
    case F_UNIFORM:
        gen_uniform(r, c);
        break;
    case F_NEAR:
        gen_near_base(r, c);
        move_ulp(r, c);
        break;
    case F_BIG: {
        static const double smalls[5] = {1.0, 0x1p-10, 1e-3, 1e-6, 0x1p-24};
        int near = rng_below(r, 2), si = rng_below(r, 5), common = rng_below(r, 2);
        if (near) gen_near_base(r, c);
        else gen_uniform(r, c);
        double off[MAXD];
        for (int j = 0; j < D; j++) off[j] = common || rng_below(r, 2) ? 1e9 : -1e9;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < D; j++) c->p[i][j] = off[j] + smalls[si] * c->p[i][j];
        if (near) move_ulp(r, c);
        c->var = 20 + 10 * near + si;
        break;
    }
    case F_TINY: {
        static const double tinies[5] = {1e-300, 0x1p-1000, 1e-310, 0x1p-1040, 1e-320};
        int near = rng_below(r, 2), si = rng_below(r, 5);
        if (near) gen_near_base(r, c);
        else gen_uniform(r, c);
        for (int i = 0; i < n; i++)
            for (int j = 0; j < D; j++) c->p[i][j] *= tinies[si];
        if (near) move_ulp(r, c);
        c->var = 40 + 10 * near + si;
        break;
    }
    case F_MIXED:
        for (int i = 0; i < n; i++)
            for (int j = 0; j < D; j++)
                c->p[i][j] = rng_sym(r) * pow(10.0, 16.0 * lht_rng_unit(r) - 8.0);
        break;
    default:
        gen_degen(r, c);
        break;
    }
    /* -0.0 becomes +0.0: the same point, one representation. */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < D; j++) c->p[i][j] += 0.0;
}

static int points_equal(const double *a, const double *b, int D)
{
    for (int j = 0; j < D; j++)
        if (a[j] != b[j]) return 0;
    return 1;
}

static int all_distinct(const double *const *pts, int n, int D)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (points_equal(pts[i], pts[j], D)) return 0;
    return 1;
}

/* ---- the oracle ----------------------------------------------------------------- */

typedef struct oracle_ws {
    mpz_t X[MAXN][MAXD]; /* coordinates as integers (common power of two removed) */
    mpz_t lift[MAXN];    /* |X_i|^2 */
    mpz_t A[MAXN][MAXN]; /* the matrix being eliminated */
    mpz_t t;
    mpq_t Q[MAXN][MAXN]; /* the homogeneous matrix, for the mpq cross-check */
    mpq_t qt;
} oracle_ws;

static oracle_ws *oracle_new(void)
{
    oracle_ws *o = malloc(sizeof *o);
    if (!o) return NULL;
    for (int i = 0; i < MAXN; i++) {
        for (int j = 0; j < MAXD; j++) mpz_init(o->X[i][j]);
        mpz_init(o->lift[i]);
        for (int j = 0; j < MAXN; j++) mpq_init(o->Q[i][j]);
    }
    for (int i = 0; i < MAXN; i++)
        for (int j = 0; j < MAXN; j++) mpz_init(o->A[i][j]);
    mpz_init(o->t);
    mpq_init(o->qt);
    return o;
}

static void oracle_free(oracle_ws *o)
{
    if (!o) return;
    for (int i = 0; i < MAXN; i++) {
        for (int j = 0; j < MAXD; j++) mpz_clear(o->X[i][j]);
        mpz_clear(o->lift[i]);
        for (int j = 0; j < MAXN; j++) mpq_clear(o->Q[i][j]);
    }
    for (int i = 0; i < MAXN; i++)
        for (int j = 0; j < MAXN; j++) mpz_clear(o->A[i][j]);
    mpz_clear(o->t);
    mpq_clear(o->qt);
    free(o);
}

/* x = mant * 2^ex exactly, mant an odd integer below 2^53 in magnitude (x != 0),
 * read off the IEEE 754 binary64 encoding (subnormals included). */
static void split_double(double x, int64_t *mant, int *ex)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int biased = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
    int e = -1074;
    if (biased != 0) {
        m |= UINT64_C(1) << 52;
        e = biased - 1075;
    }
    while (!(m & 0xff)) {
        m >>= 8;
        e += 8;
    }
    while (!(m & 1)) {
        m >>= 1;
        e++;
    }
    *mant = bits >> 63 ? -(int64_t)m : (int64_t)m;
    *ex = e;
}

/* z = v, |v| < 2^53. */
static void set_mpz_i53(mpz_t z, int64_t v)
{
#if LONG_MAX >= 9007199254740992L
    mpz_set_si(z, (long)v);
#else
    mpz_set_d(z, (double)v);
#endif
}

/* Sign of the determinant of the m x m integer matrix o->A (destroyed), by
 * fraction-free elimination with a row exchange whenever the pivot is zero. */
static int bareiss_sign(oracle_ws *o, int m)
{
    int sign = 1;
    for (int k = 0; k < m - 1; k++) {
        if (mpz_sgn(o->A[k][k]) == 0) {
            int r = k + 1;
            while (r < m && mpz_sgn(o->A[r][k]) == 0) r++;
            if (r == m) return 0;
            for (int j = k; j < m; j++) mpz_swap(o->A[k][j], o->A[r][j]);
            sign = -sign;
        }
        for (int i = k + 1; i < m; i++) {
            for (int j = k + 1; j < m; j++) {
                mpz_mul(o->t, o->A[i][j], o->A[k][k]);
                mpz_submul(o->t, o->A[i][k], o->A[k][j]);
                if (k > 0) mpz_divexact(o->A[i][j], o->t, o->A[k - 1][k - 1]);
                else mpz_swap(o->A[i][j], o->t);
            }
        }
    }
    return sign * mpz_sgn(o->A[m - 1][m - 1]);
}

/* The exact sign of orient_D / insphere_D of the n points pts[0..n-1]. */
static int oracle_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts)
{
    int64_t mant[MAXN][MAXD];
    int ex[MAXN][MAXD], emin = INT_MAX;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < D; j++) {
            if (pts[i][j] == 0.0) {
                mant[i][j] = 0;
                continue;
            }
            split_double(pts[i][j], &mant[i][j], &ex[i][j]);
            if (ex[i][j] < emin) emin = ex[i][j];
        }
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < D; j++) {
            set_mpz_i53(o->X[i][j], mant[i][j]);
            if (mant[i][j] != 0 && ex[i][j] != emin)
                mpz_mul_2exp(o->X[i][j], o->X[i][j], (mp_bitcnt_t)(ex[i][j] - emin));
        }
        if (kind == INSPHERE) {
            mpz_set_ui(o->lift[i], 0);
            for (int j = 0; j < D; j++) mpz_addmul(o->lift[i], o->X[i][j], o->X[i][j]);
        }
    }
    int m = n - 1; /* = D (orient) or D+1 (insphere) */
    for (int i = 1; i < n; i++) {
        for (int j = 0; j < D; j++) mpz_sub(o->A[i - 1][j], o->X[i][j], o->X[0][j]);
        if (kind == INSPHERE) mpz_sub(o->A[i - 1][D], o->lift[i], o->lift[0]);
    }
    return bareiss_sign(o, m);
}

/* The same sign by rational Gaussian elimination on the full homogeneous matrix
 * [1 p_i (|p_i|^2)] in mpq_t: slower, used to cross-check oracle_sign. */
static int oracle_ref_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts)
{
    for (int i = 0; i < n; i++) {
        mpq_set_ui(o->Q[i][0], 1, 1);
        for (int j = 0; j < D; j++) mpq_set_d(o->Q[i][1 + j], pts[i][j]);
        if (kind == INSPHERE) {
            mpq_set_ui(o->Q[i][D + 1], 0, 1);
            for (int j = 0; j < D; j++) {
                mpq_mul(o->qt, o->Q[i][1 + j], o->Q[i][1 + j]);
                mpq_add(o->Q[i][D + 1], o->Q[i][D + 1], o->qt);
            }
        }
    }
    int sign = 1;
    for (int k = 0; k < n; k++) {
        int r = k;
        while (r < n && mpq_sgn(o->Q[r][k]) == 0) r++;
        if (r == n) return 0;
        if (r != k) {
            for (int j = k; j < n; j++) mpq_swap(o->Q[k][j], o->Q[r][j]);
            sign = -sign;
        }
        if (mpq_sgn(o->Q[k][k]) < 0) sign = -sign;
        for (int i = k + 1; i < n; i++) {
            if (mpq_sgn(o->Q[i][k]) == 0) continue;
            mpq_div(o->Q[i][k], o->Q[i][k], o->Q[k][k]); /* the multiplier */
            for (int j = k + 1; j < n; j++) {
                mpq_mul(o->qt, o->Q[i][k], o->Q[k][j]);
                mpq_sub(o->Q[i][j], o->Q[i][j], o->qt);
            }
        }
    }
    return sign;
}

/*
 * A reference for the SoS sign, from the definition in lifthull.h (Edelsbrunner &
 * Muecke): entry (r, c) of the homogeneous matrix H, for every perturbed column c,
 * becomes H[r][c] + eps^(2^code(r, c)), codes numbering the entries by significance:
 * the lexicographically largest point first, within a point the lifted column first
 * and then x_0, x_1, ... The perturbed determinant is the sum over sets S of entries
 * (at most one per row and per column) of eps^(sum of 2^code) times det(H with the
 * rows of S replaced by the unit vectors of their columns); its sign for small eps
 * is that of the nonzero term whose code set is least in binary order, i.e. whose
 * largest code is least, then the next largest, and so on. So: find the least K
 * such that det(H + symbols at codes 0..K) is not identically zero; K is in that
 * set; replace its row by its unit vector and repeat below K until the determinant
 * itself is nonzero. "Not identically zero" is decided by evaluation at random
 * points modulo two primes near 2^32 (Schwartz-Zippel: a false "zero" has
 * probability below 2^-54 per decision); the final sign is exact (Bareiss).
 *
 * Uses o->X and o->lift as left by oracle_sign on the same points, which must be
 * pairwise distinct.
 */
enum { NPRIMES = 2 };
static const uint64_t sz_primes[NPRIMES] = {4294967291u, 4294967279u};

/* Is det W != 0 modulo the prime p (W destroyed)? Division-free elimination: row i
 * becomes W[k][k] * row i - W[i][k] * row k, which multiplies the determinant by the
 * nonzero pivot and so keeps it zero or nonzero. */
static int det_mod_nonzero(uint64_t W[MAXN][MAXN], int n, uint64_t p)
{
    for (int k = 0; k < n; k++) {
        int r = k;
        while (r < n && W[r][k] == 0) r++;
        if (r == n) return 0;
        if (r != k)
            for (int j = k; j < n; j++) {
                uint64_t t = W[k][j];
                W[k][j] = W[r][j];
                W[r][j] = t;
            }
        uint64_t piv = W[k][k];
        for (int i = k + 1; i < n; i++) {
            uint64_t f = W[i][k];
            if (f == 0) continue;
            for (int j = k + 1; j < n; j++)
                W[i][j] = (W[i][j] * piv % p + (p - f) * W[k][j] % p) % p;
        }
    }
    return 1;
}

typedef struct sos_ref {
    int n, P;              /* points, perturbed columns per row */
    int row_at[MAXN];      /* row_at[t]: the row of significance rank t (0 = most) */
    int col_of[MAXD + 1];  /* column of the q-th perturbed entry of a row */
    int repl[MAXN];        /* column of the unit vector replacing a row, or -1 */
    uint64_t Hm[NPRIMES][MAXN][MAXN];
} sos_ref;

/* Is det(H, rows replaced, + random symbols at codes 0..K) nonzero? */
static int sz_nonzero(const sos_ref *s, rng *r, int K)
{
    for (int k = 0; k < NPRIMES; k++) {
        uint64_t p = sz_primes[k], W[MAXN][MAXN];
        for (int i = 0; i < s->n; i++)
            for (int j = 0; j < s->n; j++)
                W[i][j] = s->repl[i] < 0 ? s->Hm[k][i][j] : (uint64_t)(j == s->repl[i]);
        for (int code = 0; code <= K; code++) {
            int row = s->row_at[code / s->P], col = s->col_of[code % s->P];
            if (s->repl[row] < 0) W[row][col] = (W[row][col] + lht_rng_next(r) % p) % p;
        }
        if (det_mod_nonzero(W, s->n, p)) return 1;
    }
    return 0;
}

/* o->A = H with the replaced rows; returns its exact sign. */
static int exact_replaced_sign(oracle_ws *o, const sos_ref *s, int kind, int D)
{
    for (int i = 0; i < s->n; i++) {
        if (s->repl[i] >= 0) {
            for (int j = 0; j < s->n; j++) mpz_set_ui(o->A[i][j], j == s->repl[i]);
            continue;
        }
        mpz_set_ui(o->A[i][0], 1);
        for (int j = 0; j < D; j++) mpz_set(o->A[i][1 + j], o->X[i][j]);
        if (kind == INSPHERE) mpz_set(o->A[i][D + 1], o->lift[i]);
    }
    return bareiss_sign(o, s->n);
}

static int lex_greater(const double *a, const double *b, int D)
{
    for (int j = 0; j < D; j++)
        if (a[j] != b[j]) return a[j] > b[j];
    return 0;
}

static int sos_reference_sign(oracle_ws *o, rng *r, int kind, int D, int n,
                              const double *const *pts)
{
    sos_ref s;
    s.n = n;
    s.P = D + (kind == INSPHERE);
    for (int i = 0; i < n; i++) {
        int t = 0;
        for (int j = 0; j < n; j++) t += lex_greater(pts[j], pts[i], D);
        s.row_at[t] = i;
        s.repl[i] = -1;
    }
    for (int q = 0; q < s.P; q++)
        s.col_of[q] = kind == INSPHERE ? (q == 0 ? D + 1 : q) : q + 1;
    for (int k = 0; k < NPRIMES; k++)
        for (int i = 0; i < n; i++) {
            s.Hm[k][i][0] = 1;
            for (int j = 0; j < D; j++)
                s.Hm[k][i][1 + j] = mpz_fdiv_ui(o->X[i][j], (unsigned long)sz_primes[k]);
            if (kind == INSPHERE)
                s.Hm[k][i][D + 1] = mpz_fdiv_ui(o->lift[i], (unsigned long)sz_primes[k]);
        }
    int limit = n * s.P;
    for (int level = 0; level <= n; level++) {
        int sign = exact_replaced_sign(o, &s, kind, D);
        if (sign) return sign;
        if (limit == 0 || !sz_nonzero(&s, r, limit - 1)) return 0; /* cannot happen */
        int lo = 0, hi = limit - 1;
        while (lo < hi) {
            int mid = lo + (hi - lo) / 2;
            if (sz_nonzero(&s, r, mid)) hi = mid;
            else lo = mid + 1;
        }
        s.repl[s.row_at[lo / s.P]] = s.col_of[lo % s.P];
        limit = lo;
    }
    return 0;
}

/* What a naive double-precision evaluation (Gaussian elimination with partial
 * pivoting on the homogeneous matrix, |p|^2 rounded) says: for information only. */
static int naive_sign(int kind, int D, int n, const double *const *pts)
{
    double M[MAXN][MAXN];
    for (int i = 0; i < n; i++) {
        double l = 0.0;
        M[i][0] = 1.0;
        for (int j = 0; j < D; j++) {
            M[i][1 + j] = pts[i][j];
            l += pts[i][j] * pts[i][j];
        }
        if (kind == INSPHERE) M[i][D + 1] = l;
    }
    int sign = 1;
    for (int k = 0; k < n; k++) {
        int r = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(M[i][k]) > fabs(M[r][k])) r = i;
        if (M[r][k] == 0.0) return 0;
        if (r != k) {
            for (int j = 0; j < n; j++) {
                double t = M[k][j];
                M[k][j] = M[r][j];
                M[r][j] = t;
            }
            sign = -sign;
        }
        if (M[k][k] < 0.0) sign = -sign;
        for (int i = k + 1; i < n; i++) {
            double f = M[i][k] / M[k][k];
            for (int j = k + 1; j < n; j++) M[i][j] -= f * M[k][j];
        }
    }
    return sign;
}

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

/* A failed comparison inside one case: report it (the harness prints both sides). */
#define CASE_EQ(a, b)                                                                  \
    do {                                                                               \
        if ((a) != (b)) {                                                              \
            LH_EXPECT_EQ_INT(a, b);                                                    \
            bad = 1;                                                                   \
        }                                                                              \
    } while (0)

/* Runs every check on one case; returns 1 when all passed. */
static int check_case(lh_test_state *lh_t_, lh_pred *ctx, oracle_ws *o, rng *r,
                      const pcase *c, const run_info *ri, fam_stats *fs)
{
    const int kind = c->kind, D = c->D, n = c->n;
    const double *pts[MAXN];
    for (int i = 0; i < n; i++) pts[i] = c->p[i];
    int bad = 0;
    const char *what = "";

    int oracle = oracle_sign(o, kind, D, n, pts);
    int generic = c->fam != F_NEAR && c->fam != F_DEGEN && oracle != 0;
    int do_ref = rng_below(r, REF_EVERY) == 0;
    int thin = n > 6 ? 1 << (n - 6) : 1;
    int do_perm = rng_below(r, generic ? PERM_GENERIC_EVERY : PERM_DEGEN_EVERY * thin) == 0;
    int do_radon =
        rng_below(r, generic ? RADON_GENERIC_EVERY : RADON_DEGEN_EVERY * thin) == 0;
    int do_sosref = rng_below(r, SOSREF_EVERY) == 0;
    if (do_ref) {
        int oracle_mpq = oracle_ref_sign(o, kind, D, n, pts);
        CASE_EQ(oracle, oracle_mpq); /* the test's own two oracles must agree */
        if (bad) what = "mpq cross-check of the oracle";
    }
    fs->cases++;
    fs->zeros += oracle == 0;
    fs->pos += oracle > 0;
    fs->neg += oracle < 0;
    if (naive_sign(kind, D, n, pts) != oracle) fs->naive_wrong++;

    lh_pred_counters before, after;
    lh_pred_counters_get(ctx, &before);
    int lib = lib_plain(ctx, kind, D, pts);
    lh_pred_counters_get(ctx, &after);
    fs->exact += after.exact_exits - before.exact_exits + after.residue_exits -
                 before.residue_exits;
    CASE_EQ(lib, oracle);
    if (bad && !*what) what = "plain sign";

    int sos = 0, distinct = all_distinct(pts, n, D);
    if (!bad) {
        sos = lib_sos(ctx, kind, D, pts);
        int sos_is_unit = sos == 1 || sos == -1;
        CASE_EQ(sos_is_unit, 1);
        if (oracle != 0) CASE_EQ(sos, oracle);
        if (bad) what = "sos value";
    }
    if (!bad && oracle == 0 && distinct && do_sosref) {
        /* o->X still holds this case's points (oracle_sign above) */
        fs->sosref_checked++;
        int sos_reference = sos_reference_sign(o, r, kind, D, n, pts);
        CASE_EQ(sos, sos_reference);
        if (bad) what = "SoS sign against the reference perturbation";
    }

    /* Exchange of two arguments, then an arbitrary permutation: both predicates
     * follow the permutation's sign. */
    if (!bad && distinct && do_perm) {
        fs->perm_checked++;
        const double *sw[MAXN];
        memcpy(sw, pts, sizeof pts);
        int a = rng_below(r, n), b = rng_below(r, n - 1);
        if (b >= a) b++;
        sw[a] = pts[b];
        sw[b] = pts[a];
        int sos_swapped = lib_sos(ctx, kind, D, sw);
        int lib_swapped = lib_plain(ctx, kind, D, sw);
        int minus_sos = -sos, minus_oracle = -oracle;
        CASE_EQ(sos_swapped, minus_sos);
        CASE_EQ(lib_swapped, minus_oracle);
        if (bad) {
            what = "exchange of two arguments";
            LH_NOTE("exchanged arguments %d and %d", a, b);
        }

        const double *pm[MAXN];
        int perm[MAXN], psign = 1;
        for (int i = 0; i < n; i++) perm[i] = i;
        for (int i = n - 1; i > 0; i--) {
            int j = rng_below(r, i + 1);
            if (j != i) {
                int t = perm[i];
                perm[i] = perm[j];
                perm[j] = t;
                psign = -psign;
            }
        }
        for (int i = 0; i < n; i++) pm[i] = pts[perm[i]];
        int sos_permuted = lib_sos(ctx, kind, D, pm);
        int lib_permuted = lib_plain(ctx, kind, D, pm);
        int psign_sos = psign * sos, psign_oracle = psign * oracle;
        CASE_EQ(sos_permuted, psign_sos);
        CASE_EQ(lib_permuted, psign_oracle);
        if (bad && !*what) {
            what = "permutation of the arguments";
            char buf[MAXN * 4 + 4];
            size_t len = 0;
            for (int i = 0; i < n; i++)
                len += (size_t)snprintf(buf + len, sizeof buf - len, " %d", perm[i]);
            LH_NOTE("permutation:%s (sign %d)", buf, psign);
        }

        /* Scaling every coordinate by 2^e (exactly) multiplies each column of the
         * perturbed matrix by a positive constant and keeps the lexicographic order:
         * the SoS sign must not change. For orient, so must an exact translation,
         * a column operation with the column of ones. */
        double moved[MAXN][MAXD];
        const double *mv[MAXN];
        int e = rng_below(r, 2) ? rng_int(r, 1, 40) : -rng_int(r, 1, 40), exact = 1;
        for (int i = 0; i < n; i++) {
            mv[i] = moved[i];
            for (int j = 0; j < D && exact; j++) {
                moved[i][j] = ldexp(pts[i][j], e);
                exact = isfinite(moved[i][j]) && ldexp(moved[i][j], -e) == pts[i][j];
            }
        }
        if (!bad && exact) {
            int sos_scaled = lib_sos(ctx, kind, D, mv);
            int lib_scaled = lib_plain(ctx, kind, D, mv);
            CASE_EQ(sos_scaled, sos);
            CASE_EQ(lib_scaled, oracle);
            if (bad) {
                what = "scaling by a power of two";
                LH_NOTE("scaled by 2^%d", e);
            }
        }
        if (!bad && kind == ORIENT) {
            double t[MAXD];
            int from = rng_below(r, n);
            for (int j = 0; j < D; j++)
                t[j] = rng_below(r, 2) ? -pts[from][j] : (double)rng_int(r, -1000, 1000);
            exact = 1;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < D && exact; j++) {
                    /* Knuth's two-sum: the rounding error of x + t, exactly. */
                    double x = pts[i][j], y = x + t[j], tv = y - x;
                    double err = (x - (y - tv)) + (t[j] - tv);
                    moved[i][j] = y + 0.0;
                    exact = isfinite(y) && err == 0.0;
                }
            if (exact) {
                int sos_translated = lib_sos(ctx, kind, D, mv);
                int lib_translated = lib_plain(ctx, kind, D, mv);
                CASE_EQ(sos_translated, sos);
                CASE_EQ(lib_translated, oracle);
                if (bad) {
                    what = "exact translation";
                    char buf[MAXD * 32 + 8];
                    size_t len = 0;
                    for (int j = 0; j < D; j++)
                        len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%a",
                                                j ? ", " : "", t[j]);
                    LH_NOTE("translated by (%s)", buf);
                }
            }
        }
    }

    /* The (n+1)-subset identity with one more point q (a midpoint, a reflection or a
     * one-ulp neighbour of the case's points). */
    if (!bad && distinct && do_radon) {
        double q[MAXD];
        int qa = rng_below(r, n), qb = rng_below(r, n - 1), how = rng_below(r, 3);
        if (qb >= qa) qb++;
        for (int j = 0; j < D; j++) {
            if (how == 0) q[j] = 0.5 * pts[qa][j] + 0.5 * pts[qb][j];
            else if (how == 1) q[j] = 2.0 * pts[qa][j] - pts[qb][j];
            else q[j] = pts[qa][j];
            q[j] += 0.0;
        }
        if (how == 2) {
            int j = rng_below(r, D);
            q[j] = nextafter(q[j], rng_below(r, 2) ? INFINITY : -INFINITY);
        }
        const double *all[MAXN];
        memcpy(all, pts, sizeof pts);
        all[n] = q;
        int finite = 1;
        for (int j = 0; j < D; j++) finite &= isfinite(q[j]) != 0;
        if (finite && all_distinct(all, n + 1, D)) {
            fs->radon_checked++;
            int seen_pos = 0, seen_neg = 0;
            for (int i = 0; i <= n; i++) {
                const double *sub[MAXN];
                for (int l = 0, t = 0; l <= n; l++)
                    if (l != i) sub[t++] = all[l];
                int s = lib_sos(ctx, kind, D, sub) * (i % 2 ? -1 : 1);
                seen_pos |= s > 0;
                seen_neg |= s < 0;
            }
            int mixed_signs = seen_pos && seen_neg;
            CASE_EQ(mixed_signs, 1);
            if (bad) {
                what = "(n+1)-subset identity: all (-1)^i sos_i agree";
                note_points(lh_t_, "q", (const double *const *)all + n, 1, D);
            }
        }
    }
    if (bad) {
        LH_NOTE("%s_%d failed (%s): test seed %#llx, case %ld, family %s, variant %d, "
                "oracle %d; rerun with LH_ORACLE_SEED=%#llx LH_ORACLE_CASE=%ld",
                ri->pred, D, what, (unsigned long long)ri->seed, ri->index,
                fam_name[c->fam], c->var, oracle, (unsigned long long)ri->base_seed,
                ri->index);
        note_points(lh_t_, "p", pts, n, D);
    }
    return !bad;
}

static void run_oracle(lh_test_state *lh_t_, int kind, int D)
{
    const char *pred = kind == ORIENT ? "orient" : "insphere";
    double t0 = now_seconds();
    long cases = (long)(100000.0 * test_scale() + 0.5);
    if (cases < 1000) cases = 1000;
    const uint64_t base_seed = test_seed();
    const uint64_t seed = base_seed ^ ((uint64_t)(kind * 16 + D) * 0x2545f4914f6cdd1du);
    long first = 0;
    const char *only = getenv("LH_ORACLE_CASE"); /* rerun one case */
    if (only && *only) {
        first = strtol(only, NULL, 10);
        cases = first + 1;
    }

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

    if (bad_cases == 0 && first == 0) {
        /* The families hit the regimes they are meant to hit. */
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
