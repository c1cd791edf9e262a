/*
 * lh_families.h — the site families the engine issue names (uniform cube and ball,
 * Gaussian clusters, exactly cospherical, integer grids, grids moved by 1e-12, near a
 * hyperplane, 5% duplicates, offset 1e9, spread 1e-9, mixed magnitudes), from a
 * seeded generator (tools/sites.h: its xoshiro256** and its exact spheres), for the
 * tests that need them.
 */
#ifndef LH_FAMILIES_H
#define LH_FAMILIES_H

#include <stddef.h>
#include <stdint.h>

enum family {
    F_CUBE, F_BALL, F_CLUSTERS, F_SPHERE_EXACT, F_GRID, F_GRID_JITTER, F_NEAR_PLANE,
    F_DUPLICATES, F_OFFSET_1E9, F_SPREAD_1E9, F_MIXED, F_COUNT
};
extern const char *const lh_fam_name[F_COUNT];

void lh_fam_seed(uint64_t seed);
uint64_t lh_fam_rnd(void);  /* xoshiro256** (lht_rng_next) */
double lh_fam_unif(void);   /* [0,1), 53 bits */
/* n sites of family fam in R^d into x (n*d doubles); returns the count made (the
 * exactly cospherical family, d = 2..8, makes at most lht_circle_max() in 2D, and
 * none when no sphere of tools/sites.h has n lattice points). */
size_t lh_fam_make(int fam, int d, size_t n, double *x);

#endif
