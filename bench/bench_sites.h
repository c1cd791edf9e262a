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

// Row-major sites (count*d doubles) of the distribution, the same for every tool:
//   uniform  n sites uniform in [0,1)^d: multiples of 2^-53 from mt19937_64(seed).
//   grid     all k^d points of {0,..,k-1}^d, k = max(2, round(n^(1/d))), so the count
//            differs from n (10^6 in 2D and 3D exactly); shuffled by seed.
//   sphere   n distinct points of Z^d on the sphere |x|^2 = N about the origin, a random
//            subset (seed) of all the lattice points on a sphere chosen per (d, n) to hold
//            at least n of them: in 2D the Gaussian-integer products of norm N (N a
//            product of primes 1 mod 4), in 3D the rotations of (0,0,R) by integer
//            quaternions of norm R (N = R^2), from 4D on every lattice point of |x|^2 = N.
//            Every coordinate is an integer below 2^53, so exact in a double, and every
//            site is checked on the sphere in integer arithmetic.
//   clusters n sites from 10 Gaussian clusters, standard deviations 10^-6 .. 10^-2, about
//            centres uniform in [0,1)^d (near-degenerate at every scale between).
//   pgrid    the grid above with every coordinate x moved to x (1 + 10^-12 u), u uniform in
//            [-1, 1): near-degenerate, no longer exactly.
// On failure (sizes the construction cannot reach with exact doubles) returns false and
// sets *err.
bool site_make(SiteDist dist, int d, size_t n, uint64_t seed, std::vector<double> *xyz,
               std::string *err);

#endif
