/*
 * pred_oracle_cases.c — test_pred_oracle's case families (uniform, near, 1e9+, tiny,
 * mixed, degen; test_pred_oracle.c describes them), each case regenerable from the
 * seed and its number.
 */
#include "pred_oracle.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* ---- cases ---------------------------------------------------------------------- */

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
 * Coordinates drawn from a pool of eight values of a few magnitude levels: small
 * integers times 2^997, 1, 2^-997 or 2^-1074 (subnormal), or 0, some with full 53-bit
 * mantissas. One call then mixes 1e+300 with 5e-324, and with values repeated across
 * points (as in the mixed-magnitude reproducers) its large terms often cancel exactly:
 * the sign sits 1000 bits or more below them, or is 0 (the exact stage's sparse path,
 * and the perturbation's minors on it).
 */
static void gen_levels(rng *r, pcase *c)
{
    static const int level[4] = {997, 0, -997, -1074};
    double pool[8];
    for (int v = 0; v < 8; v++) {
        int k = rng_below(r, 5);
        double m = (double)rng_int(r, -9, 9);
        if (k < 3 && rng_below(r, 3) == 0) m = 8.0 * rng_sym(r); /* 53 bits */
        pool[v] = k == 4 ? 0.0 : ldexp(m, level[k]);
    }
    for (int i = 0; i < c->n; i++)
        for (int j = 0; j < c->D; j++) c->p[i][j] = pool[rng_below(r, 8)];
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

void gen_case(rng *r, pcase *c, int fam)
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
        if (rng_below(r, 2)) { /* magnitude levels, as in the mixed-magnitude reproducers */
            gen_levels(r, c);
            c->var = 60;
            break;
        }
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

int all_distinct(const double *const *pts, int n, int D)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (points_equal(pts[i], pts[j], D)) return 0;
    return 1;
}
