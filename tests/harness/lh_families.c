/* lh_families.c — the site families of the tests (lh_families.h). */
#include "lh_families.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_state; /* test programs are single-threaded */

void lh_fam_seed(uint64_t seed) { rng_state = seed; }

uint64_t lh_fam_rnd(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}
double lh_fam_unif(void) { return (double)(lh_fam_rnd() >> 11) * 0x1p-53; } /* [0,1) */

static double gauss(void)
{
    double u = lh_fam_unif() + 0x1p-60, v = lh_fam_unif();
    return sqrt(-2 * log(u)) * cos(6.283185307179586 * v);
}

const char *const lh_fam_name[F_COUNT] = {
    "uniform cube", "uniform ball", "gaussian clusters", "exactly cospherical",
    "integer grid", "grid + 1e-12", "within 1e-10 of a hyperplane", "5% duplicates",
    "offset 1e9, unit spread", "spread 1e-9", "mixed 1e-8..1e8"};

/* Exactly cospherical: n points drawn at random from the points of Z^d with
 * |x|^2 = r2 (r2 chosen so that there are many). */
static size_t sphere_points(int d, size_t n, double *x)
{
    static const int r2_for_dim[9] = {0, 0, 5525, 425, 50, 18, 12, 10, 8};
    int r2 = r2_for_dim[d], r = (int)sqrt((double)r2);
    size_t m = 0, cap = 50000;
    double *all = malloc(cap * d * sizeof *all);
    int c[8];
    for (int j = 0; j < d; j++) c[j] = -r;
    for (;;) {
        int s = 0;
        for (int j = 0; j < d; j++) s += c[j] * c[j];
        if (s == r2 && m < cap) {
            for (int j = 0; j < d; j++) all[m * d + j] = c[j];
            m++;
        }
        int j = 0;
        while (j < d && c[j] == r) c[j++] = -r;
        if (j == d) break;
        c[j]++;
    }
    size_t take = m < n ? m : n;
    for (size_t i = 0; i < take; i++) { /* partial Fisher-Yates */
        size_t k = i + lh_fam_rnd() % (m - i);
        for (int j = 0; j < d; j++) {
            double t = all[k * d + j];
            all[k * d + j] = all[i * d + j];
            all[i * d + j] = t;
        }
    }
    memcpy(x, all, take * d * sizeof *x);
    free(all);
    return take;
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
            for (int j = 0; j < d; j++) p[j] = (double)(i % 5) * 10 + gauss();
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
