/*
 * generate.c — `lifthull points`: test point sets in Qhull's point format, rbox's job
 * (uniform cube, ball, sphere, exactly cospherical integer points, integer grids,
 * Gaussian clusters, coordinates rounded to integers).
 *
 * References:
 *   - D. Blackman, S. Vigna, "Scrambled linear pseudorandom number generators",
 *     ACM TOMS 47(4), 2021: xoshiro256**, seeded through splitmix64.
 *   - G. Marsaglia, T. A. Bray, "A convenient method for generating normal random
 *     variables", SIAM Review 6(3), 1964: the polar method.
 *   - D. E. Knuth, TAOCP vol. 2, 3.4.2, Algorithm S: selection sampling.
 *   - G. H. Hardy, E. M. Wright, "An Introduction to the Theory of Numbers", ch. 16.9
 *     and 20: sums of two squares through Gaussian integers, r_2(n) = 4 prod (e_i + 1)
 *     when every prime factor of n is 1 mod 4; the average of r_d(n).
 *
 * Reproducibility: every coordinate is computed with +, -, *, / and sqrt, which IEEE 754
 * rounds correctly, and floor/frexp, which are exact; the polar method's logarithm is
 * our own series in those operations (libm's log may differ in the last bit between
 * systems). Contraction into fused multiply-adds is off (GCC in ISO C mode by default,
 * clang through the pragma), and "%.17g" prints every double exactly. So one command
 * line writes the same bytes on every IEEE-754 machine with double evaluation.
 */
#include "cli.h"
#include "outfile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

#define MAX_POINTS 1000000000u /* N <= 10^9 */
#define MAX_INTEGER_R 1000000000000000u /* --integer R <= 10^15 < 2^50: exact doubles */
#define DEFAULT_SEED 1u

typedef enum gen_kind { GEN_CUBE, GEN_BALL, GEN_SPHERE, GEN_EXACT_SPHERE, GEN_GRID, GEN_CLUSTERS } gen_kind;

static const char *const kind_flag[] = {"--cube", "--ball", "--sphere", "--exact-sphere", "--grid",
                                        "--clusters"};

/* The parsed command line. */
typedef struct gen_opts {
    uint64_t n;         /* points (for the grid: K^d)                          */
    int d;              /* 2..8                                               */
    gen_kind kind;
    uint64_t k;         /* --grid: the side K; --clusters: the count C        */
    uint64_t integer_r; /* 0, or round every coordinate to an integer in [-R, R] */
    uint64_t seed;
    const char *out;    /* -o FILE, or NULL for standard output               */
    int force;          /* -f: replace an existing FILE                       */
} gen_opts;

/* ---- random numbers ------------------------------------------------------------ */

typedef struct rng {
    uint64_t s[4]; /* xoshiro256** state, never all zero (splitmix64 outputs) */
} rng;

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static void rng_seed(rng *r, uint64_t seed)
{
    for (int i = 0; i < 4; i++) r->s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t rng_next(rng *r)
{
    uint64_t *s = r->s;
    uint64_t out = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return out;
}

/* Uniform in [0, 1), a multiple of 2^-53. */
static double rng_unit(rng *r) { return (double)(rng_next(r) >> 11) * 0x1.0p-53; }

/* Uniform in [0, n), n >= 1, without modulo bias: draws below 2^64 mod n are redrawn,
 * so the accepted range is a whole number of copies of [0, n). */
static uint64_t rng_below(rng *r, uint64_t n)
{
    uint64_t low = (0 - n) % n, x;
    do x = rng_next(r);
    while (x < low);
    return x % n;
}

/* log(x), x > 0 finite, in +, -, *, / only: x = m 2^e with m in [sqrt(1/2), sqrt(2)),
 * log x = e log 2 + 2 atanh(z), z = (m - 1)/(m + 1), |z| < 0.172; the series to z^41
 * leaves a remainder below 1e-33. */
static double det_log(double x)
{
    int e;
    double m = frexp(x, &e); /* exact, m in [0.5, 1) */
    if (m < 0.70710678118654752) {
        m *= 2;
        e--;
    }
    double z = (m - 1) / (m + 1), z2 = z * z, s = 1.0 / 41;
    for (int k = 39; k >= 1; k -= 2) s = s * z2 + 1.0 / k;
    return e * 0.69314718055994530942 + 2 * z * s;
}

/* A standard normal variate by the polar method (the second variate is dropped). */
static double rng_normal(rng *r)
{
    for (;;) {
        double u = 2 * rng_unit(r) - 1, v = 2 * rng_unit(r) - 1, s = u * u + v * v;
        if (s > 0 && s < 1) return u * sqrt(-2 * det_log(s) / s);
    }
}

/* ---- output -------------------------------------------------------------------- */

/* One point, "%.17g" (round-trips exactly); adding 0.0 turns -0 into 0. */
static void put_point(FILE *f, int d, const double *x)
{
    for (int j = 0; j < d; j++) fprintf(f, j ? " %.17g" : "%.17g", x[j] + 0.0);
    putc('\n', f);
}

/* The header: the dimension, the canonical command line (every effective option,
 * defaults included, -o and -f left out: they do not change the points) as a comment,
 * then the count. */
static void put_header(FILE *f, const gen_opts *o)
{
    fprintf(f, "%d lifthull points ", o->d);
    if (o->kind == GEN_GRID) {
        fprintf(f, "--grid %llu -d %d\n%llu\n", (unsigned long long)o->k, o->d, (unsigned long long)o->n);
        return;
    }
    fprintf(f, "%llu -d %d", (unsigned long long)o->n, o->d);
    if (o->kind == GEN_CLUSTERS) fprintf(f, " --clusters %llu", (unsigned long long)o->k);
    else if (o->kind != GEN_CUBE) fprintf(f, " %s", kind_flag[o->kind]);
    if (o->integer_r) fprintf(f, " --integer %llu", (unsigned long long)o->integer_r);
    fprintf(f, " --seed %llu\n%llu\n", (unsigned long long)o->seed, (unsigned long long)o->n);
}

/* ---- random distributions -------------------------------------------------------- */

static void point_cube(rng *r, int d, double *x)
{
    for (int j = 0; j < d; j++) x[j] = rng_unit(r) - 0.5; /* exact: [-0.5, 0.5) */
}

/* Uniform in the ball of radius 0.5 by rejection from the cube (acceptance 1.6% in 8D). */
static double point_ball(rng *r, int d, double *x)
{
    for (;;) {
        point_cube(r, d, x);
        double q = 0;
        for (int j = 0; j < d; j++) q += x[j] * x[j];
        if (q <= 0.25) return q;
    }
}

/* Uniform on the sphere of radius 0.5: a ball point's direction (radius at least 1/8,
 * so the scaling is well conditioned; the direction stays uniform). */
static void point_sphere(rng *r, int d, double *x)
{
    double q;
    do q = point_ball(r, d, x);
    while (q < 1.0 / 64);
    double s = 0.5 / sqrt(q);
    for (int j = 0; j < d; j++) x[j] *= s;
}

/* Scale [-0.5, 0.5] to [-R, R] and round to the nearest integer (halves up), clamped
 * to [-R, R] (cluster tails can leave the cube). */
static void round_point(double r_max, int d, double *x)
{
    for (int j = 0; j < d; j++) {
        double v = floor(x[j] * (2 * r_max) + 0.5);
        x[j] = v < -r_max ? -r_max : v > r_max ? r_max : v;
    }
}

/* Cube, ball, sphere and clusters: one point at a time. Cluster centres are uniform in
 * the cube; the blobs' standard deviation 0.1 / C^(1/d) shrinks as they get more. */
static int write_random(FILE *f, const gen_opts *o, rng *r)
{
    double *centres = NULL, sigma = 0, x[LH_DELAUNAY_MAX_DIM];
    if (o->kind == GEN_CLUSTERS) {
        centres = malloc((size_t)o->k * (size_t)o->d * sizeof *centres);
        if (!centres) return -1;
        for (uint64_t c = 0; c < o->k; c++) point_cube(r, o->d, centres + c * (size_t)o->d);
        double lo = 0, hi = 1; /* sigma = 0.1 / C^(1/d) by bisection: no pow() */
        for (int it = 0; it < 200; it++) {
            double mid = (lo + hi) / 2, p = 1;
            for (int j = 0; j < o->d; j++) p *= mid;
            if (p * (double)o->k < 1) lo = mid;
            else hi = mid;
        }
        sigma = 0.1 * lo;
    }
    for (uint64_t i = 0; i < o->n; i++) {
        switch (o->kind) {
        case GEN_BALL: point_ball(r, o->d, x); break;
        case GEN_SPHERE: point_sphere(r, o->d, x); break;
        case GEN_CLUSTERS: {
            const double *c = centres + rng_below(r, o->k) * (size_t)o->d;
            for (int j = 0; j < o->d; j++) x[j] = c[j] + sigma * rng_normal(r);
            break;
        }
        default: point_cube(r, o->d, x); break;
        }
        if (o->integer_r) round_point((double)o->integer_r, o->d, x);
        put_point(f, o->d, x);
    }
    free(centres);
    return 0;
}

/* The grid {0..K-1}^d, last coordinate fastest. */
static void write_grid(FILE *f, const gen_opts *o)
{
    uint64_t digit[LH_DELAUNAY_MAX_DIM] = {0};
    double x[LH_DELAUNAY_MAX_DIM];
    for (uint64_t i = 0; i < o->n; i++) {
        for (int j = 0; j < o->d; j++) x[j] = (double)digit[j];
        put_point(f, o->d, x);
        for (int j = o->d - 1; j >= 0 && ++digit[j] == o->k; j--) digit[j] = 0;
    }
}

/* ---- exactly cospherical integer points ------------------------------------------- */

/*
 * Design: choose a squared radius M with at least N integer points v, |v|^2 = M;
 * enumerate all of them in a fixed order and keep a uniformly random N of them by
 * selection sampling (keep the next candidate with probability still-needed /
 * still-left), streaming, so memory stays small.
 *   d = 2:  M = a product of primes p = 1 mod 4, chosen greedily (gain in points per
 *           factor of M) while M < 2^62; p = pi conj(pi) in the Gaussian integers and
 *           the points are the 4 unit multiples of the products that take
 *           pi^j conj(pi)^(e-j) from each p^e: all r_2(M) = 4 prod (e + 1) of them.
 *   d >= 3: from M0, where the average of r_d (pi^(d/2) / Gamma(d/2) M^(d/2-1)) reaches
 *           N, the first M whose points suffice, found by enumerating the sorted
 *           tuples 0 <= a_1 <= .. <= a_d with sum a_i^2 = M; each tuple stands for its
 *           distinct permutations times the signs of its nonzero entries.
 */
enum { N_GAUSS_PRIMES = 21, EXACT_SPHERE_MAX_3D = 200000 };
static const int64_t gauss_prime[N_GAUSS_PRIMES] = {5,  13,  17,  29,  37,  41,  53,
                                                    61, 73,  89,  97,  101, 109, 113,
                                                    137, 149, 157, 173, 181, 193, 197};

typedef struct sphere_plan {
    int d;
    uint64_t m;                 /* the squared radius                          */
    uint64_t total;             /* integer points with |v|^2 = m               */
    int exps[N_GAUSS_PRIMES];   /* d = 2: m = prod gauss_prime[i]^exps[i]       */
    int64_t *tuples;            /* d >= 3: tuple_count sorted tuples, d each    */
    size_t tuple_count, tuple_cap;
} sphere_plan;

/* d = 2: the greedy exponents; 0 when N points need M >= 2^62. */
static int plan_circle(sphere_plan *p, uint64_t n)
{
    uint64_t count = 1; /* prod (e + 1): the points are 4 * count */
    p->m = 1;
    while (4 * count < n) {
        int best = -1;
        double best_gain = 0;
        for (int i = 0; i < N_GAUSS_PRIMES; i++) {
            if (p->m > (UINT64_C(1) << 62) / (uint64_t)gauss_prime[i]) continue;
            double g = det_log((p->exps[i] + 2.0) / (p->exps[i] + 1.0)) / det_log((double)gauss_prime[i]);
            if (g > best_gain) best = i, best_gain = g;
        }
        if (best < 0) return 0;
        count = count / (uint64_t)(p->exps[best] + 1) * (uint64_t)(p->exps[best] + 2);
        p->exps[best]++;
        p->m *= (uint64_t)gauss_prime[best];
    }
    p->total = 4 * count;
    return 1;
}

static uint64_t isqrt_u64(uint64_t v) /* v < 2^53 */
{
    uint64_t s = (uint64_t)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    return s;
}

/* Distinct signed permutations of a sorted tuple: d! / prod(run length!) * 2^nonzeros. */
static uint64_t signed_perms(const int64_t *a, int d)
{
    uint64_t perms = 1; /* after step i: the multinomial of a[0..i], an integer */
    int run = 1;
    for (int i = 1; i < d; i++) {
        perms *= (uint64_t)(i + 1);
        if (a[i] == a[i - 1]) perms /= (uint64_t)++run;
        else run = 1;
    }
    for (int i = 0; i < d; i++)
        if (a[i]) perms *= 2;
    return perms;
}

static int push_tuple(sphere_plan *p, const int64_t *a)
{
    if (p->tuple_count == p->tuple_cap) {
        size_t cap = p->tuple_cap ? 2 * p->tuple_cap : 64;
        int64_t *t = realloc(p->tuples, cap * (size_t)p->d * sizeof *t);
        if (!t) return -1;
        p->tuples = t;
        p->tuple_cap = cap;
    }
    memcpy(p->tuples + p->tuple_count++ * (size_t)p->d, a, (size_t)p->d * sizeof *a);
    return 0;
}

/* Sorted tuples a[pos..d-1] >= lo with squares summing to rem; -1 out of memory. */
static int find_tuples(sphere_plan *p, int64_t *a, int pos, int64_t lo, uint64_t rem)
{
    if (pos == p->d - 1) {
        uint64_t s = isqrt_u64(rem);
        if (s * s != rem || (int64_t)s < lo) return 0;
        a[pos] = (int64_t)s;
        p->total += signed_perms(a, p->d);
        return push_tuple(p, a);
    }
    for (int64_t v = lo; (uint64_t)(p->d - pos) * (uint64_t)(v * v) <= rem; v++) {
        a[pos] = v;
        if (find_tuples(p, a, pos + 1, v, rem - (uint64_t)(v * v)) != 0) return -1;
    }
    return 0;
}

/* d >= 3: the first M from M0 on with at least n points. 1 found, 0 none below 2^50,
 * -1 out of memory. M0 by bisection on c_d^2 M^(d-2) >= n^2 (products only). */
static int plan_sphere(sphere_plan *p, uint64_t n)
{
    static const double c2[LH_DELAUNAY_MAX_DIM + 1] = {0, 0, 0, 39.47841760435743, 97.40909103400243,
        173.17171739378205, 240.34729839382604, 273.46181506141994, 263.5703060019603};
    uint64_t lo = 0, hi = UINT64_C(1) << 50;
    while (hi - lo > 1) {
        uint64_t mid = lo + (hi - lo) / 2;
        double v = c2[p->d];
        for (int i = 0; i < p->d - 2; i++) v *= (double)mid;
        if (v >= (double)n * (double)n) hi = mid;
        else lo = mid;
    }
    int64_t a[LH_DELAUNAY_MAX_DIM];
    for (uint64_t m = hi, tries = 0; m < (UINT64_C(1) << 50); m++) {
        if (p->d == 3 && (m % 8 == 7 || m % 4 == 0)) continue; /* none, or 2x those of m/4 */
        p->tuple_count = 0;
        p->total = 0;
        if (find_tuples(p, a, 0, 0, m) != 0) return -1;
        if (p->total >= n) {
            p->m = m;
            return 1;
        }
        if (++tries % 16 == 0) m += m / 8; /* unlucky stretch: move on faster */
    }
    return 0;
}

/* Selection sampling into the output: each candidate kept with probability need/left. */
typedef struct picker {
    FILE *f;
    rng *r;
    int d;
    uint64_t need, left;
} picker;

static void pick(picker *k, const int64_t *v)
{
    if (k->need && rng_below(k->r, k->left) < k->need) {
        double x[LH_DELAUNAY_MAX_DIM];
        for (int j = 0; j < k->d; j++) x[j] = (double)v[j];
        put_point(k->f, k->d, x);
        k->need--;
    }
    k->left--;
}

static void gauss_mul(int64_t *z, int64_t re, int64_t im)
{
    int64_t a = z[0];
    z[0] = a * re - z[1] * im;
    z[1] = a * im + z[1] * re;
}

/* d = 2: every point of the circle, choice by choice (a mixed-radix counter j[i] in
 * 0..exps[i]), through the picker. */
static void offer_circle(const sphere_plan *p, picker *k)
{
    int64_t root[N_GAUSS_PRIMES][2];
    int j[N_GAUSS_PRIMES] = {0};
    for (int i = 0; i < N_GAUSS_PRIMES; i++) /* p = a^2 + b^2, a > b > 0 */
        for (int64_t b = 1; b * b * 2 < gauss_prime[i]; b++) {
            int64_t a = (int64_t)isqrt_u64((uint64_t)(gauss_prime[i] - b * b));
            if (a * a + b * b == gauss_prime[i]) root[i][0] = a, root[i][1] = b;
        }
    for (;;) {
        int64_t z[2] = {1, 0};
        for (int i = 0; i < N_GAUSS_PRIMES; i++)
            for (int t = 0; t < p->exps[i]; t++) gauss_mul(z, root[i][0], t < j[i] ? root[i][1] : -root[i][1]);
        int64_t units[4][2] = {{z[0], z[1]}, {-z[1], z[0]}, {-z[0], -z[1]}, {z[1], -z[0]}};
        for (int u = 0; u < 4; u++) pick(k, units[u]);
        int i = 0;
        while (i < N_GAUSS_PRIMES && ++j[i] > p->exps[i]) j[i++] = 0;
        if (i == N_GAUSS_PRIMES) return;
    }
}

/* Lexicographic successor of a multiset permutation; 0 after the last. */
static int next_perm(int64_t *a, int d)
{
    int i = d - 2;
    while (i >= 0 && a[i] >= a[i + 1]) i--;
    if (i < 0) return 0;
    int j = d - 1;
    while (a[j] <= a[i]) j--;
    int64_t t = a[i];
    a[i] = a[j];
    a[j] = t;
    for (int lo = i + 1, hi = d - 1; lo < hi; lo++, hi--) t = a[lo], a[lo] = a[hi], a[hi] = t;
    return 1;
}

/* d >= 3: each tuple's permutations, each with every sign pattern of its nonzeros. */
static void offer_sphere(const sphere_plan *p, picker *k)
{
    int64_t a[LH_DELAUNAY_MAX_DIM], v[LH_DELAUNAY_MAX_DIM];
    for (size_t t = 0; t < p->tuple_count; t++) {
        memcpy(a, p->tuples + t * (size_t)p->d, (size_t)p->d * sizeof *a);
        do {
            int nz = 0;
            for (int j = 0; j < p->d; j++) nz += a[j] != 0;
            for (uint32_t mask = 0; mask < (UINT32_C(1) << nz); mask++) {
                for (int j = 0, b = 0; j < p->d; j++)
                    v[j] = a[j] && ((mask >> b++) & 1) ? -a[j] : a[j];
                pick(k, v);
            }
        } while (next_perm(a, p->d));
    }
}

/* ---- the command line ------------------------------------------------------------ */

static const char usage_text[] =
    "usage: lifthull points N [-d D] [DISTRIBUTION] [--integer R] [--seed S] [-o FILE [-f]]\n"
    "       lifthull points --grid K [-d D] [-o FILE [-f]]\n"
    "\n"
    "Writes N test points in Qhull's point format: the dimension followed by the\n"
    "canonical command line as a comment, the count, then one point per line with 17\n"
    "significant digits (they read back exactly). The same command line writes the same\n"
    "bytes on every machine; change --seed for another sample.\n"
    "\n"
    "options:\n"
    "  N               number of points, 1 to 1000000000\n"
    "  -d D            dimension, 2 to 8 (default 3)\n"
    "  --seed S        seed, 0 to 2^64-1 (default 1)\n"
    "  -o FILE         write FILE, complete or not at all (via FILE.tmpXXXXXX), instead\n"
    "                  of standard output; an existing FILE is an error...\n"
    "  -f              ...unless -f: replace it (a device, pipe or symbolic link is\n"
    "                  written through, not replaced)\n"
    "  -h, --help      this help\n"
    "  (long options also take their value as --seed=S)\n"
    "\n"
    "distributions (at most one):\n"
    "  --cube          uniform in the cube [-0.5, 0.5]^D (the default, as rbox)\n"
    "  --ball          uniform in the ball of diameter 1 about the origin\n"
    "  --sphere        uniform on the sphere of diameter 1 (rbox s)\n"
    "  --exact-sphere  N distinct points with integer coordinates and one squared norm\n"
    "                  M, so exactly cospherical: a random N of all integer points with\n"
    "                  |x|^2 = M, M the first that has enough (2D: at most %llu\n"
    "                  points; 3D: at most %d)\n"
    "  --grid K        the integer grid {0..K-1}^D, K >= 2: K^D exactly degenerate\n"
    "                  points (N may be left out; if given it must be K^D)\n"
    "  --clusters C    C Gaussian blobs, centres uniform in the cube, standard\n"
    "                  deviation 0.1 / C^(1/D); 1 <= C <= N\n"
    "  --integer R     scale the cube, ball, sphere or clusters to [-R, R]^D and round\n"
    "                  every coordinate to an integer, 1 <= R <= 10^15: exactly\n"
    "                  degenerate input (duplicates possible)\n"
    "\n"
    "examples:\n"
    "  lifthull points 1000 -d 3 --ball --seed 7\n"
    "  lifthull points 10000 -d 2 | lifthull delaunay -s\n"
    "  lifthull points 500 -d 2 --integer 10 | lifthull delaunay -s\n"
    "  lifthull points 2000 -d 4 --exact-sphere | lifthull delaunay -s\n"
    "  lifthull points --grid 5 -d 3 -o grid.txt -f\n"
    "  lifthull points 100000 -d 5 --clusters 20 --seed 3 -o clusters.txt -f\n";

/* The most points --exact-sphere gives in 2D (M < 2^62). */
static uint64_t circle_max(void)
{
    sphere_plan p = {.d = 2};
    plan_circle(&p, UINT64_MAX);
    uint64_t count = 4;
    for (int i = 0; i < N_GAUSS_PRIMES; i++) count *= (uint64_t)(p.exps[i] + 1);
    return count;
}

/* One line on standard error, "lifthull points: ..."; returns -1. */
static int usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("lifthull points: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return -1;
}

/* A decimal integer in [lo, hi], digits only (no sign, no blanks); 1 on success. */
static int parse_u64(const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    uint64_t v = 0;
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        unsigned digit = (unsigned)(*s - '0');
        if (v > (UINT64_MAX - digit) / 10) return 0;
        v = 10 * v + digit;
    }
    if (v < lo || v > hi) return 0;
    *out = v;
    return 1;
}

static int parse_value(const char *name, const char *s, uint64_t lo, uint64_t hi, uint64_t *out)
{
    if (parse_u64(s, lo, hi, out)) return 0;
    return usage_error("%s must be an integer from %llu to %llu, not '%s'", name, (unsigned long long)lo,
                       (unsigned long long)hi, s);
}

static int set_kind(gen_opts *o, const char **kind_opt, const char *name, gen_kind kind)
{
    if (*kind_opt && strcmp(*kind_opt, name))
        return usage_error("%s and %s exclude each other (one distribution at most)", *kind_opt, name);
    *kind_opt = name;
    o->kind = kind;
    return 0;
}

/* Whether argument a (its name part being len characters) is option name. */
static int is_opt(const char *a, size_t len, const char *name)
{
    return strlen(name) == len && !strncmp(a, name, len);
}

/* One argument at argv[*i] (advancing *i past a separate value). 0 or -1. */
static int parse_one(int argc, char **argv, int *i, gen_opts *o, const char **kind_opt, int *have_n)
{
    const char *a = argv[*i], *eq = a[0] == '-' && a[1] == '-' ? strchr(a, '=') : NULL;
    size_t len = eq ? (size_t)(eq - a) : strlen(a);
    static const char *const flags[] = {"--cube", "--ball", "--sphere", "--exact-sphere", "-f"};
    for (int k = 0; k < 5; k++) {
        if (!is_opt(a, len, flags[k])) continue;
        if (eq) return usage_error("%s takes no value", flags[k]);
        if (k == 4) return o->force = 1, 0;
        return set_kind(o, kind_opt, flags[k], (gen_kind)k);
    }
    static const char *const valued[] = {"-d", "--dim", "--seed", "--grid", "--clusters", "--integer", "-o"};
    for (int k = 0; k < 7; k++) {
        if (!is_opt(a, len, valued[k])) continue;
        const char *v = eq ? eq + 1 : *i + 1 < argc ? argv[++*i] : NULL;
        if (!v) return usage_error("%s needs a value (try lifthull points --help)", valued[k]);
        uint64_t x = 0;
        switch (k) {
        case 0:
        case 1:
            if (parse_value(valued[k], v, LH_DELAUNAY_MIN_DIM, LH_DELAUNAY_MAX_DIM, &x)) return -1;
            o->d = (int)x;
            return 0;
        case 2: return parse_value("--seed", v, 0, UINT64_MAX, &o->seed);
        case 3:
            if (set_kind(o, kind_opt, "--grid", GEN_GRID)) return -1;
            return parse_value("--grid", v, 2, MAX_POINTS, &o->k);
        case 4:
            if (set_kind(o, kind_opt, "--clusters", GEN_CLUSTERS)) return -1;
            return parse_value("--clusters", v, 1, 1000000, &o->k);
        case 5: return parse_value("--integer", v, 1, MAX_INTEGER_R, &o->integer_r);
        default:
            if (!*v) return usage_error("-o needs a file name");
            o->out = v;
            return 0;
        }
    }
    if (a[0] == '-' && !(a[1] >= '0' && a[1] <= '9'))
        return usage_error("unknown option '%s' (try lifthull points --help)", a);
    if (*have_n) return usage_error("unexpected argument '%s': N is already %llu", a, (unsigned long long)o->n);
    *have_n = 1;
    if (parse_u64(a, 1, MAX_POINTS, &o->n)) return 0;
    return usage_error("the number of points N must be an integer from 1 to %u, not '%s'", MAX_POINTS, a);
}

/* The options' combinations, once all are read; fills in the grid's N. 0 or -1. */
static int check_opts(gen_opts *o, int have_n)
{
    if (o->force && !o->out) return usage_error("-f only makes sense with -o FILE");
    if (o->integer_r && (o->kind == GEN_GRID || o->kind == GEN_EXACT_SPHERE))
        return usage_error("--integer does not apply to %s (its coordinates are integers already)",
                           kind_flag[o->kind]);
    if (o->kind == GEN_GRID) {
        uint64_t size = 1;
        for (int j = 0; j < o->d; j++) {
            if (size > MAX_POINTS / o->k)
                return usage_error("--grid %llu in %dD makes more than %u points", (unsigned long long)o->k,
                                   o->d, MAX_POINTS);
            size *= o->k;
        }
        if (have_n && o->n != size)
            return usage_error("--grid %llu in %dD makes %llu points, not %llu (leave N out)",
                               (unsigned long long)o->k, o->d, (unsigned long long)size,
                               (unsigned long long)o->n);
        o->n = size;
        return 0;
    }
    if (!have_n) return usage_error("the number of points N is missing (e.g. lifthull points 1000)");
    if (o->kind == GEN_CLUSTERS && o->k > o->n)
        return usage_error("--clusters %llu: more clusters than the %llu points", (unsigned long long)o->k,
                           (unsigned long long)o->n);
    if (o->kind == GEN_EXACT_SPHERE && o->d == 2 && o->n > circle_max())
        return usage_error("--exact-sphere in 2D gives at most %llu points, not %llu",
                           (unsigned long long)circle_max(), (unsigned long long)o->n);
    if (o->kind == GEN_EXACT_SPHERE && o->d == 3 && o->n > EXACT_SPHERE_MAX_3D)
        return usage_error("--exact-sphere in 3D gives at most %d points, not %llu", EXACT_SPHERE_MAX_3D,
                           (unsigned long long)o->n);
    return 0;
}

/* 1 for --help (printed), 0 parsed, -1 usage error (printed). */
static int parse_args(int argc, char **argv, gen_opts *o)
{
    memset(o, 0, sizeof *o);
    o->d = 3;
    o->seed = DEFAULT_SEED;
    o->kind = GEN_CUBE;
    for (int i = 0; i < argc; i++)
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            printf(usage_text, (unsigned long long)circle_max(), EXACT_SPHERE_MAX_3D);
            return 1;
        }
    const char *kind_opt = NULL;
    int have_n = 0;
    for (int i = 0; i < argc; i++)
        if (parse_one(argc, argv, &i, o, &kind_opt, &have_n)) return -1;
    return check_opts(o, have_n);
}

/* ---- writing ---------------------------------------------------------------------- */

/* The header and the points; -1 out of memory (write errors are found at the end). */
static int write_points(FILE *f, const gen_opts *o, const sphere_plan *plan)
{
    rng r;
    rng_seed(&r, o->seed);
    put_header(f, o);
    if (o->kind == GEN_GRID) {
        write_grid(f, o);
        return 0;
    }
    if (o->kind != GEN_EXACT_SPHERE) return write_random(f, o, &r);
    picker k = {f, &r, o->d, o->n, plan->total};
    if (o->d == 2) offer_circle(plan, &k);
    else offer_sphere(plan, &k);
    return 0;
}

int lh_cli_generate(int argc, char **argv)
{
    gen_opts o;
    int r = parse_args(argc, argv, &o);
    if (r != 0) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check("points", o.out, o.force, NULL)) return LH_EXIT_FAIL;
    sphere_plan plan = {.d = o.d};
    if (o.kind == GEN_EXACT_SPHERE) {
        r = o.d == 2 ? plan_circle(&plan, o.n) : plan_sphere(&plan, o.n);
        if (r <= 0) {
            free(plan.tuples);
            fprintf(stderr, "lifthull points: %s\n", r < 0 ? "out of memory" : "no sphere found");
            return LH_EXIT_FAIL;
        }
    }
    lh_cli_out out;
    if (!lh_cli_out_open(&out, "points", o.out, o.force, NULL)) {
        free(plan.tuples);
        return LH_EXIT_FAIL;
    }
    int status = write_points(out.f, &o, &plan);
    free(plan.tuples);
    if (status != 0) fprintf(stderr, "lifthull points: out of memory\n");
    return lh_cli_out_close(&out, "points", status == 0);
}
