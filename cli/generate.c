/*
 * generate.c — `lifthull points`: test point sets in Qhull's point format, rbox's job
 * (uniform cube, ball, sphere, exactly cospherical integer points, integer grids,
 * Gaussian clusters, coordinates rounded to integers).
 *
 * The random numbers (xoshiro256**, the polar method) and the exactly cospherical points
 * come from tools/sites.c, shared with the tests; its header cites the papers.
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
#include "sites.h"

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

/* ---- output -------------------------------------------------------------------- */

/* One point, "%.17g" (round-trips exactly); adding 0.0 turns -0 into 0. */
static void put_point(FILE *f, int d, const double *x)
{
    for (int j = 0; j < d; j++) fprintf(f, j ? " %.17g" : "%.17g", x[j] + 0.0);
    putc('\n', f);
}

/* lht_sphere_pick's callback: one point to the file ctx. */
static void put_site(void *ctx, int d, const double *x) { put_point(ctx, d, x); }

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

static void point_cube(lht_rng *r, int d, double *x)
{
    for (int j = 0; j < d; j++) x[j] = lht_rng_unit(r) - 0.5; /* exact: [-0.5, 0.5) */
}

/* Uniform in the ball of radius 0.5 by rejection from the cube (acceptance 1.6% in 8D). */
static double point_ball(lht_rng *r, int d, double *x)
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
static void point_sphere(lht_rng *r, int d, double *x)
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
static int write_random(FILE *f, const gen_opts *o, lht_rng *r)
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
            const double *c = centres + lht_rng_below(r, o->k) * (size_t)o->d;
            for (int j = 0; j < o->d; j++) x[j] = c[j] + sigma * lht_rng_normal(r);
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
    if (o->kind == GEN_EXACT_SPHERE && o->d == 2 && o->n > lht_circle_max())
        return usage_error("--exact-sphere in 2D gives at most %llu points, not %llu",
                           (unsigned long long)lht_circle_max(), (unsigned long long)o->n);
    if (o->kind == GEN_EXACT_SPHERE && o->d == 3 && o->n > LHT_EXACT_SPHERE_MAX_3D)
        return usage_error("--exact-sphere in 3D gives at most %d points, not %llu", LHT_EXACT_SPHERE_MAX_3D,
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
            printf(usage_text, (unsigned long long)lht_circle_max(), LHT_EXACT_SPHERE_MAX_3D);
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
static int write_points(FILE *f, const gen_opts *o, const lht_sphere *plan)
{
    lht_rng r;
    lht_rng_seed(&r, o->seed);
    put_header(f, o);
    if (o->kind == GEN_GRID) {
        write_grid(f, o);
        return 0;
    }
    if (o->kind != GEN_EXACT_SPHERE) return write_random(f, o, &r);
    lht_sphere_pick(plan, &r, o->n, put_site, f);
    return 0;
}

int lh_cli_generate(int argc, char **argv)
{
    gen_opts o;
    int r = parse_args(argc, argv, &o);
    if (r != 0) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check("points", o.out, o.force, NULL)) return LH_EXIT_FAIL;
    lht_sphere plan = {.d = o.d};
    if (o.kind == GEN_EXACT_SPHERE) {
        r = lht_sphere_plan(&plan, o.d, o.n);
        if (r <= 0) {
            lht_sphere_free(&plan);
            fprintf(stderr, "lifthull points: %s\n", r < 0 ? "out of memory" : "no sphere found");
            return LH_EXIT_FAIL;
        }
    }
    lh_cli_out out;
    if (!lh_cli_out_open(&out, "points", o.out, o.force, NULL)) {
        lht_sphere_free(&plan);
        return LH_EXIT_FAIL;
    }
    int status = write_points(out.f, &o, &plan);
    lht_sphere_free(&plan);
    if (status != 0) fprintf(stderr, "lifthull points: out of memory\n");
    return lh_cli_out_close(&out, "points", status == 0);
}
