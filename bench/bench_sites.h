// bench_sites.h — the site distributions of bench_delaunay's `run --dist`: uniform random
// sites, and two degenerate families whose degeneracy is exact in doubles (the point of
// an exact triangulation): integer grids and integer points on one sphere.
#ifndef LH_BENCH_SITES_H
#define LH_BENCH_SITES_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

enum class SiteDist { uniform, grid, sphere, clusters, pgrid };

// "uniform" | "grid" | "sphere" | "clusters" | "pgrid" -> *out; false for any other name.
bool site_dist_parse(const std::string &name, SiteDist *out);
const char *site_dist_name(SiteDist dist);

// Row-major sites (count*d doubles) of the distribution, the same for every tool; the
// random numbers are tools/sites.h's (xoshiro256**, seeded through splitmix64):
//   uniform  n sites uniform in [0,1)^d: multiples of 2^-53 (lht_rng_unit, seed).
//   grid     all k^d points of {0,..,k-1}^d, k = max(2, round(n^(1/d))), so the count
//            differs from n (10^6 in 2D and 3D exactly); shuffled by seed.
//   sphere   n distinct points of Z^d on one sphere |x|^2 = M about the origin, chosen
//            per (d, n) to hold at least n lattice points, a random subset (seed) of
//            them in random order: tools/sites.h's exactly cospherical sites
//            (lht_sphere_plan, lht_sphere_pick), as `lifthull points --exact-sphere`
//            makes them. d <= 8; at most lht_circle_max() sites in 2D and
//            LHT_EXACT_SPHERE_MAX_3D in 3D. Every coordinate is an integer, exact in a
//            double.
//   clusters n sites from 10 Gaussian clusters, standard deviations 10^-6 .. 10^-2, about
//            centres uniform in [0,1)^d (near-degenerate at every scale between).
//   pgrid    the grid above with every coordinate x moved to x (1 + 10^-12 u), u uniform in
//            [-1, 1): near-degenerate, no longer exactly.
// On failure (sizes the construction cannot reach with exact doubles) returns false and
// sets *err.
bool site_make(SiteDist dist, int d, size_t n, uint64_t seed, std::vector<double> *xyz,
               std::string *err);

#endif
