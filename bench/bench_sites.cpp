// bench_sites.cpp — the site distributions declared in bench_sites.h: uniform random
// sites, integer grids, exactly cospherical integer points, and two near-degenerate
// families: Gaussian clusters of very different widths and perturbed grids. Random
// numbers and the cospherical points come from tools/sites.h, shared with the tool and
// the tests.
#include "bench_sites.h"

#include "sites.h"

#include <algorithm>
#include <cmath>

namespace
{

using i64 = long long;

lht_rng seeded(uint64_t seed)
{
    lht_rng r;
    lht_rng_seed(&r, seed);
    return r;
}

// Moves a uniform random choice of `keep` rows (d values each), in random order, to the
// front, and drops the rest: partial Fisher-Yates. The stream is seeded apart from the
// uniform sites' so that the two never share draws.
void shuffle_rows(std::vector<double> &xyz, int d, size_t keep, uint64_t seed)
{
    const size_t m = xyz.size() / size_t(d);
    lht_rng g = seeded(seed ^ 0x9e3779b97f4a7c15ULL);
    for (size_t i = 0; i < keep && i + 1 < m; ++i) {
        size_t j = i + size_t(lht_rng_below(&g, uint64_t(m - i)));
        if (j != i)
            std::swap_ranges(xyz.begin() + ptrdiff_t(i * d), xyz.begin() + ptrdiff_t((i + 1) * d),
                             xyz.begin() + ptrdiff_t(j * d));
    }
    xyz.resize(std::min(keep, m) * size_t(d));
    xyz.shrink_to_fit(); // the caller holds exactly its sites while the tool runs
}

std::vector<double> uniform_sites(int d, size_t n, uint64_t seed)
{
    lht_rng g = seeded(seed);
    std::vector<double> xyz(n * size_t(d));
    for (double &x : xyz) x = lht_rng_unit(&g);
    return xyz;
}

bool grid_sites(int d, size_t n, uint64_t seed, std::vector<double> *out, std::string *err)
{
    i64 k = std::max<i64>(2, std::llround(std::pow(double(n), 1.0 / d)));
    double total = std::pow(double(k), d);
    if (total > 2e8) {
        *err = "grid too large";
        return false;
    }
    const size_t m = size_t(total);
    std::vector<double> &xyz = *out;
    xyz.assign(m * size_t(d), 0.0);
    for (size_t i = 0; i < m; ++i) {
        size_t v = i;
        for (int j = 0; j < d; ++j, v /= size_t(k))
            xyz[i * size_t(d) + size_t(j)] = double(v % size_t(k));
    }
    shuffle_rows(xyz, d, m, seed); // every point kept, in a seeded order
    return true;
}

// n of the integer points on one sphere about the origin, from tools/sites.h: a random
// subset (by selection sampling, in the generator's fixed order) drawn from seed; the
// caller shuffles them.
void put_site(void *ctx, int d, const double *x)
{
    auto *xyz = static_cast<std::vector<double> *>(ctx);
    xyz->insert(xyz->end(), x, x + d);
}

bool sphere_sites(int d, size_t n, uint64_t seed, std::vector<double> *out, std::string *err)
{
    if (d > LHT_MAX_DIM) {
        *err = "sphere: dimension above " + std::to_string(LHT_MAX_DIM);
        return false;
    }
    if (d == 3 && n > LHT_EXACT_SPHERE_MAX_3D) {
        *err = "3D sphere: at most " + std::to_string(LHT_EXACT_SPHERE_MAX_3D) + " sites";
        return false;
    }
    lht_sphere plan;
    const int planned = lht_sphere_plan(&plan, d, n);
    if (planned != 1) {
        lht_sphere_free(&plan);
        *err = planned < 0 ? "sphere: out of memory"
               : d == 2    ? "2D sphere: at most " + std::to_string(lht_circle_max()) + " sites"
                           : "sphere: too many sites for a sphere with exact double coordinates";
        return false;
    }
    lht_rng rng;
    lht_rng_seed(&rng, seed);
    out->clear();
    out->reserve(n * size_t(d));
    lht_sphere_pick(&plan, &rng, n, put_site, out);
    lht_sphere_free(&plan);
    return true;
}

// 10 Gaussian clusters with standard deviations 10^-6 .. 10^-2 (cluster c: 10^(-6+4c/9))
// about centres uniform in [0,1)^d; site i belongs to cluster i mod 10.
std::vector<double> cluster_sites(int d, size_t n, uint64_t seed)
{
    lht_rng g = seeded(seed);
    std::vector<double> centre(10 * size_t(d));
    for (double &x : centre) x = lht_rng_unit(&g);
    std::vector<double> xyz(n * size_t(d));
    for (size_t i = 0; i < n; ++i) {
        size_t c = i % 10;
        double sigma = std::pow(10.0, -6.0 + 4.0 * double(c) / 9.0);
        for (int j = 0; j < d; ++j)
            xyz[i * size_t(d) + size_t(j)] =
                centre[c * size_t(d) + size_t(j)] + sigma * lht_rng_normal(&g);
    }
    return xyz;
}

// The grid of grid_sites, every coordinate x replaced by x (1 + 10^-12 u), u uniform in
// [-1, 1) (0 by 10^-12 u): near-degenerate, no longer exactly so.
bool perturbed_grid_sites(int d, size_t n, uint64_t seed, std::vector<double> *out,
                          std::string *err)
{
    if (!grid_sites(d, n, seed, out, err)) return false;
    lht_rng g = seeded(seed ^ 0x51ed270b27a1e2b5ULL);
    for (double &x : *out) {
        double u = 2.0 * lht_rng_unit(&g) - 1.0;
        x = x != 0 ? x * (1.0 + 1e-12 * u) : 1e-12 * u;
    }
    return true;
}
} // namespace

bool site_dist_parse(const std::string &name, SiteDist *out)
{
    if (name == "uniform")
        *out = SiteDist::uniform;
    else if (name == "grid")
        *out = SiteDist::grid;
    else if (name == "sphere")
        *out = SiteDist::sphere;
    else if (name == "clusters")
        *out = SiteDist::clusters;
    else if (name == "pgrid")
        *out = SiteDist::pgrid;
    else
        return false;
    return true;
}

const char *site_dist_name(SiteDist dist)
{
    switch (dist) {
    case SiteDist::grid: return "grid";
    case SiteDist::sphere: return "sphere";
    case SiteDist::clusters: return "clusters";
    case SiteDist::pgrid: return "pgrid";
    default: return "uniform";
    }
}

bool site_make(SiteDist dist, int d, size_t n, uint64_t seed, std::vector<double> *xyz,
               std::string *err)
{
    if (d < 2) {
        *err = "dimension below 2";
        return false;
    }
    switch (dist) {
    case SiteDist::uniform: *xyz = uniform_sites(d, n, seed); return true;
    case SiteDist::grid: return grid_sites(d, n, seed, xyz, err);
    case SiteDist::clusters: *xyz = cluster_sites(d, n, seed); return true;
    case SiteDist::pgrid: return perturbed_grid_sites(d, n, seed, xyz, err);
    case SiteDist::sphere:
        if (!sphere_sites(d, n, seed, xyz, err)) return false;
        shuffle_rows(*xyz, d, n, seed); // in random order
        return true;
    }
    return false;
}
