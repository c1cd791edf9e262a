/* lh_families.c — the site families of the tests (lh_families.h). */
#include "lh_families.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sites.h"

/* Test programs are single-threaded. Unseeded, the generator starts as seed 0 does
 * (xoshiro's all-zero state would give zeros forever). */
static lht_rng rng;
static int seeded;

void lh_fam_seed(uint64_t seed)
{
    lht_rng_seed(&rng, seed);
    seeded = 1;
}

static lht_rng *gen(void)
{
    if (!seeded) lh_fam_seed(0);
    return &rng;
}

uint64_t lh_fam_rnd(void) { return lht_rng_next(gen()); }
double lh_fam_unif(void) { return lht_rng_unit(gen()); }

const char *const lh_fam_name[F_COUNT] = {
    "uniform cube", "uniform ball", "gaussian clusters", "exactly cospherical",
    "integer grid", "grid + 1e-12", "within 1e-10 of a hyperplane", "5% duplicates",
    "offset 1e9, unit spread", "spread 1e-9", "mixed 1e-8..1e8"};

typedef struct sink {
    double *x;
    size_t count;
} sink;

static void take_site(void *ctx, int d, const double *p)
{
    sink *k = ctx;
    memcpy(k->x + k->count++ * (size_t)d, p, (size_t)d * sizeof *p);
}

/* Exactly cospherical: n integer points of one sphere centred at the origin, a random
 * subset of all its lattice points (tools/sites.h). In 2D at most lht_circle_max()
 * points (the whole of that circle); 0 when no sphere of sites.h has n. */
static size_t sphere_points(int d, size_t n, double *x)
{
    if (d == 2 && n > lht_circle_max()) n = (size_t)lht_circle_max();
    lht_sphere plan;
    const int ok = lht_sphere_plan(&plan, d, n);
    if (ok < 0) {
        fprintf(stderr, "lh_families: out of memory planning %zu sphere points\n", n);
        abort();
    }
    sink k = {x, 0};
    if (ok) lht_sphere_pick(&plan, gen(), n, take_site, &k);
    lht_sphere_free(&plan);
    return k.count;
}

size_t lh_fam_make(int fam, int d, size_t n, double *x)
{
    int side = (int)ceil(pow((double)n, 1.0 / d));
    for (size_t i = 0; i < n; i++) {
        double *p = x + i * d;
        switch (fam) {
        case F_BALL: {
            double r2;
            do {
                r2 = 0;
                for (int j = 0; j < d; j++) {
                    p[j] = 2 * lh_fam_unif() - 1;
                    r2 += p[j] * p[j];
                }
            } while (r2 > 1);
            break;
        }
        case F_CLUSTERS:
            for (int j = 0; j < d; j++) p[j] = (double)(i % 5) * 10 + lht_rng_normal(gen());
            break;
        case F_GRID:
        case F_GRID_JITTER: {
            size_t k = i;
            for (int j = 0; j < d; j++) {
                p[j] = (double)(k % (size_t)side);
                k /= (size_t)side;
                if (fam == F_GRID_JITTER) p[j] += 1e-12 * (2 * lh_fam_unif() - 1);
            }
            break;
        }
        case F_NEAR_PLANE:
            for (int j = 0; j < d; j++) p[j] = lh_fam_unif();
            p[d - 1] = 1e-10 * (2 * lh_fam_unif() - 1);
            break;
        case F_OFFSET_1E9:
            for (int j = 0; j < d; j++) p[j] = 1e9 + lh_fam_unif();
            break;
        case F_SPREAD_1E9:
            for (int j = 0; j < d; j++) p[j] = 1e-9 * lh_fam_unif();
            break;
        case F_MIXED:
            for (int j = 0; j < d; j++) p[j] = (2 * lh_fam_unif() - 1) * pow(10.0, -8 + 16 * lh_fam_unif());
            break;
        default: /* F_CUBE, F_DUPLICATES */
            for (int j = 0; j < d; j++) p[j] = lh_fam_unif();
        }
    }
    if (fam == F_DUPLICATES)
        for (size_t i = 0; i < n / 20; i++) {
            size_t a = lh_fam_rnd() % n, b = lh_fam_rnd() % n;
            memcpy(x + a * d, x + b * d, (size_t)d * sizeof *x);
        }
    if (fam == F_SPHERE_EXACT) n = sphere_points(d, n, x);
    return n;
}
