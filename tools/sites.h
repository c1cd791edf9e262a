/*
 * sites.h — seeded random numbers and exactly cospherical integer sites for the tool
 * (`lifthull points`), the tests (their harness) and the benchmarks (bench_sites.cpp);
 * not part of the library (libc and libm only, compiled into each program that uses
 * it). C, callable from C++.
 */
#ifndef LH_TOOLS_SITES_H
#define LH_TOOLS_SITES_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { LHT_MAX_DIM = 8, LHT_GAUSS_PRIMES = 21, LHT_EXACT_SPHERE_MAX_3D = 10000000 };

/* xoshiro256**: the state is never all zero (splitmix64 outputs). */
typedef struct lht_rng {
    uint64_t s[4];
} lht_rng;

void lht_rng_seed(lht_rng *r, uint64_t seed); /* the state from splitmix64(seed) */
uint64_t lht_rng_next(lht_rng *r);            /* 64 random bits */
double lht_rng_unit(lht_rng *r);              /* uniform in [0, 1), a multiple of 2^-53 */
uint64_t lht_rng_below(lht_rng *r, uint64_t n); /* uniform in [0, n), n >= 1, unbiased */
double lht_rng_normal(lht_rng *r);            /* standard normal (polar method) */

/* The plan of exactly cospherical integer points in dimension d (2..8): a squared
 * radius m with total >= n integer points v, |v|^2 = m. */
typedef struct lht_sphere {
    int d;
    uint64_t m;                 /* d >= 3: the squared radius                  */
    uint64_t total;             /* integer points with |v|^2 = m               */
    int exps[LHT_GAUSS_PRIMES]; /* d = 2: m = prod gauss_prime[i]^exps[i], below
                                   2^104 (not stored in m)                     */
    int64_t *tuples;            /* d >= 3: tuple_count sorted tuples, d each    */
    size_t tuple_count, tuple_cap;
} lht_sphere;

/* 1 planned, 0 no such sphere (2D: n > lht_circle_max(); d >= 3: m would pass 2^50),
 * -1 out of memory; lht_sphere_free releases it in every case. */
int lht_sphere_plan(lht_sphere *p, int d, uint64_t n);
/* The most points a 2D plan gives (M < 2^104: 1105920). */
uint64_t lht_circle_max(void);
/* n of the plan's points, a uniformly random subset drawn from r, each passed to emit in
 * a fixed order (coordinates are integers, exact in doubles). */
typedef void (*lht_site_fn)(void *ctx, int d, const double *x);
void lht_sphere_pick(const lht_sphere *p, lht_rng *r, uint64_t n, lht_site_fn emit, void *ctx);
void lht_sphere_free(lht_sphere *p);

#ifdef __cplusplus
}
#endif

#endif
