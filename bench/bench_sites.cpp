// bench_sites.cpp — the site distributions declared in bench_sites.h: uniform random
// sites, integer grids, exactly cospherical integer points, and two near-degenerate
// families: Gaussian clusters of very different widths and perturbed grids.
#include "bench_sites.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace {

using i64 = long long;
using i128 = __int128;

// Largest integer magnitude a double holds exactly (every coordinate must stay below).
constexpr double kExactLimit = 9007199254740992.0; // 2^53

i64 isqrt(i64 v) {
    if (v < 0) return -1;
    i64 r = i64(std::sqrt(double(v)));
    while (r > 0 && r * r > v) --r;
    while ((r + 1) * (r + 1) <= v) ++r;
    return r;
}

// Moves a uniform random choice of `keep` rows (d values each), in random order, to the
// front, and drops the rest: partial Fisher-Yates. The stream is seeded apart from the
// uniform sites' so that the two never share draws.
void shuffle_rows(std::vector<double> &xyz, int d, size_t keep, uint64_t seed) {
    const size_t m = xyz.size() / size_t(d);
    std::mt19937_64 g(seed ^ 0x9e3779b97f4a7c15ULL);
    for (size_t i = 0; i < keep && i + 1 < m; ++i) {
        size_t j = i + size_t(g() % uint64_t(m - i));
        if (j != i)
            std::swap_ranges(xyz.begin() + ptrdiff_t(i * d), xyz.begin() + ptrdiff_t((i + 1) * d),
                             xyz.begin() + ptrdiff_t(j * d));
    }
    xyz.resize(std::min(keep, m) * size_t(d));
    xyz.shrink_to_fit(); // the caller holds exactly its sites while the tool runs
}

std::vector<double> uniform_sites(int d, size_t n, uint64_t seed) {
    std::mt19937_64 g(seed);
    std::vector<double> xyz(n * size_t(d));
    for (double &x : xyz) x = double(g() >> 11) * 0x1p-53;
    return xyz;
}

bool grid_sites(int d, size_t n, uint64_t seed, std::vector<double> *out, std::string *err) {
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
        for (int j = 0; j < d; ++j, v /= size_t(k)) xyz[i * size_t(d) + size_t(j)] = double(v % size_t(k));
    }
    shuffle_rows(xyz, d, m, seed); // every point kept, in a seeded order
    return true;
}

// ---- 2D: lattice points on the circle x^2 + y^2 = N --------------------------------------
// N = prod p_i^e_i over primes p_i = 1 mod 4, p_i = pi_i * conj(pi_i) in the Gaussian
// integers; the points of norm N are exactly u * prod pi_i^j * conj(pi_i)^(e_i - j),
// j = 0..e_i, u a unit: 4 * prod (e_i + 1) distinct points.

struct Gauss {
    i128 re, im;
};

Gauss gmul(Gauss a, Gauss b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

struct PrimeSq {
    i64 p, u, v; // p = u^2 + v^2
};

std::vector<PrimeSq> primes_1_mod_4(size_t count) {
    std::vector<PrimeSq> out;
    for (i64 p = 5; out.size() < count; p += 4) {
        bool prime = true;
        for (i64 q = 2; q * q <= p && prime; ++q) prime = p % q != 0;
        if (!prime) continue;
        for (i64 u = 1; u * u < p; ++u) {
            i64 v = isqrt(p - u * u);
            if (v * v == p - u * u) {
                out.push_back({p, u, v});
                break;
            }
        }
    }
    return out;
}

// Exponents (non-increasing along the primes) with prod(e_i + 1) >= target and the least
// log2 N: a depth-first search as for "the smallest number with many divisors".
struct ExpSearch {
    ExpSearch(const std::vector<PrimeSq> &primes, i64 t) : ps(primes), target(t) {}
    const std::vector<PrimeSq> &ps;
    i64 target;
    double best_log = INFINITY;
    std::vector<int> best, cur;
    void dfs(size_t i, i64 prod, double log2n, int emax) {
        if (prod >= target) {
            if (log2n < best_log) {
                best_log = log2n;
                best = cur;
            }
            return;
        }
        if (i >= ps.size()) return;
        for (int e = 1; e <= emax; ++e) {
            double l = log2n + e * std::log2(double(ps[i].p));
            if (l >= best_log) break;
            cur.push_back(e);
            dfs(i + 1, prod * (e + 1), l, e);
            cur.pop_back();
        }
    }
};

bool circle_sites(size_t n, std::vector<double> *out, std::string *err) {
    const std::vector<PrimeSq> ps = primes_1_mod_4(24);
    ExpSearch s(ps, i64((n + 3) / 4));
    s.dfs(0, 1, 0.0, 8);
    if (s.best.empty() || s.best_log / 2 >= 52.5) {
        *err = "2D sphere: too many sites for a circle with exact double coordinates";
        return false;
    }
    i128 norm = 1;
    std::vector<Gauss> pts = {{1, 0}};
    for (size_t i = 0; i < s.best.size(); ++i) {
        const int e = s.best[i];
        const Gauss pi = {ps[i].u, ps[i].v}, pibar = {ps[i].u, -ps[i].v};
        std::vector<Gauss> factors; // pi^j * conj(pi)^(e-j), j = 0..e
        for (int j = 0; j <= e; ++j) {
            Gauss f = {1, 0};
            for (int t = 0; t < j; ++t) f = gmul(f, pi);
            for (int t = j; t < e; ++t) f = gmul(f, pibar);
            factors.push_back(f);
        }
        for (int t = 0; t < e; ++t) norm *= ps[i].p;
        std::vector<Gauss> next;
        next.reserve(pts.size() * factors.size());
        for (const Gauss &g : pts)
            for (const Gauss &f : factors) next.push_back(gmul(g, f));
        pts.swap(next);
    }
    std::vector<double> &xyz = *out;
    xyz.clear();
    xyz.reserve(4 * pts.size() * 2);
    for (const Gauss &g : pts) {
        const Gauss units[4] = {{g.re, g.im}, {-g.im, g.re}, {-g.re, -g.im}, {g.im, -g.re}};
        for (const Gauss &u : units) {
            if (u.re * u.re + u.im * u.im != norm) {
                *err = "2D sphere: internal error (point off the circle)";
                return false;
            }
            xyz.push_back(double(i64(u.re)));
            xyz.push_back(double(i64(u.im)));
        }
    }
    return true;
}

// ---- 3D: lattice points on the sphere |x|^2 = R^2 ------------------------------------------
// An integer quaternion q = a + bi + cj + ek of norm R rotates (0,0,1) to a point of
// |x| = 1 scaled by R: (2(be + ac), 2(ce - ab), a^2 - b^2 - c^2 + e^2), an integer point
// with |x|^2 = R^2. For odd R they give about 3R distinct points. q, -q, qk and -qk give
// the same point, and when a and e are both nonzero exactly one of them has a > 0 and
// e > 0: only that one is kept (the rest, and rarer coincidences, are sorted out).

using P3 = std::array<int32_t, 3>; // |coordinates| <= R < 2^30: a small transient array

std::vector<P3> quaternion_sphere(i64 R) {
    std::vector<P3> pts;
    for (i64 a = 0; a * a <= R; ++a)
        for (i64 b = 0; a * a + b * b <= R; ++b)
            for (i64 c = 0; a * a + b * b + c * c <= R; ++c) {
                const i64 r = R - a * a - b * b - c * c, e = isqrt(r);
                if (e * e != r) continue;
                for (int sb = 1; sb >= (b ? -1 : 1); sb -= 2)
                    for (int sc = 1; sc >= (c ? -1 : 1); sc -= 2)
                        for (int se = 1; se >= (e && !a ? -1 : 1); se -= 2) {
                            const i64 B = sb * b, C = sc * c, E = se * e;
                            pts.push_back({int32_t(2 * (B * E + a * C)), int32_t(2 * (C * E - a * B)),
                                           int32_t(a * a - B * B - C * C + E * E)});
                        }
            }
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    return pts;
}

bool sphere3_sites(size_t n, std::vector<double> *out, std::string *err) {
    if (n > 100000000) {
        *err = "3D sphere: too many sites";
        return false;
    }
    i64 R = std::max<i64>(3, i64(double(n) / 2.4)) | 1;
    std::vector<P3> pts;
    for (;;) {
        pts = quaternion_sphere(R);
        if (pts.size() >= n) break;
        R = (R + R / 4 + 2) | 1; // 25% larger, odd
    }
    std::vector<double> &xyz = *out;
    xyz.clear();
    xyz.reserve(pts.size() * 3);
    for (const P3 &p : pts) {
        if (i64(p[0]) * p[0] + i64(p[1]) * p[1] + i64(p[2]) * p[2] != R * R) {
            *err = "3D sphere: internal error (point off the sphere)";
            return false;
        }
        for (int32_t x : p) xyz.push_back(double(x));
    }
    return true;
}

// ---- d >= 4: every lattice point of |x|^2 = N --------------------------------------------

void enumerate_sphere(int d, int k, i64 rem, std::vector<i64> &cur, std::vector<double> &out) {
    if (k == d - 1) {
        const i64 t = isqrt(rem);
        if (t * t != rem) return;
        for (int s = 1; s >= (t ? -1 : 1); s -= 2) {
            cur[size_t(k)] = s * t;
            for (i64 x : cur) out.push_back(double(x));
        }
        return;
    }
    const i64 s = isqrt(rem);
    for (i64 x = -s; x <= s; ++x) {
        cur[size_t(k)] = x;
        enumerate_sphere(d, k + 1, rem - x * x, cur, out);
    }
}

bool sphere_high_sites(int d, size_t n, std::vector<double> *out, std::string *err) {
    // The number of lattice points on |x|^2 = N is about pi^(d/2) / Gamma(d/2) N^(d/2-1);
    // start just below that estimate and grow N by 10% until there are n. In 4D N is odd
    // (r_4(N) = 8 sigma(N) then, never small).
    const double c = std::pow(M_PI, d / 2.0) / std::tgamma(d / 2.0);
    i64 N = std::max<i64>(1, i64(0.8 * std::pow(double(n) / c, 2.0 / (d - 2))));
    if (d == 4) N |= 1;
    std::vector<i64> cur(size_t(d), 0);
    for (;;) {
        if (double(N) >= kExactLimit) {
            *err = "sphere: radius too large";
            return false;
        }
        out->clear();
        enumerate_sphere(d, 0, N, cur, *out);
        if (out->size() / size_t(d) >= n) break;
        N = std::max(N + 1, i64(double(N) * 1.1));
        if (d == 4) N |= 1;
    }
    for (size_t i = 0; i < out->size(); i += size_t(d)) {
        i128 s = 0;
        for (int j = 0; j < d; ++j) s += i128(i64((*out)[i + size_t(j)])) * i64((*out)[i + size_t(j)]);
        if (s != N) {
            *err = "sphere: internal error (point off the sphere)";
            return false;
        }
    }
    return true;
}

// 10 Gaussian clusters with standard deviations 10^-6 .. 10^-2 (cluster c: 10^(-6+4c/9))
// about centres uniform in [0,1)^d; site i belongs to cluster i mod 10.
std::vector<double> cluster_sites(int d, size_t n, uint64_t seed) {
    std::mt19937_64 g(seed);
    std::vector<double> centre(10 * size_t(d));
    for (double &x : centre) x = double(g() >> 11) * 0x1p-53;
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> xyz(n * size_t(d));
    for (size_t i = 0; i < n; ++i) {
        size_t c = i % 10;
        double sigma = std::pow(10.0, -6.0 + 4.0 * double(c) / 9.0);
        for (int j = 0; j < d; ++j)
            xyz[i * size_t(d) + size_t(j)] = centre[c * size_t(d) + size_t(j)] + sigma * normal(g);
    }
    return xyz;
}

// The grid of grid_sites, every coordinate x replaced by x (1 + 10^-12 u), u uniform in
// [-1, 1) (0 by 10^-12 u): near-degenerate, no longer exactly so.
bool perturbed_grid_sites(int d, size_t n, uint64_t seed, std::vector<double> *out,
                          std::string *err) {
    if (!grid_sites(d, n, seed, out, err)) return false;
    std::mt19937_64 g(seed ^ 0x51ed270b27a1e2b5ULL);
    for (double &x : *out) {
        double u = double(g() >> 11) * 0x1p-52 - 1.0;
        x = x != 0 ? x * (1.0 + 1e-12 * u) : 1e-12 * u;
    }
    return true;
}
} // namespace

bool site_dist_parse(const std::string &name, SiteDist *out) {
    if (name == "uniform") *out = SiteDist::uniform;
    else if (name == "grid") *out = SiteDist::grid;
    else if (name == "sphere") *out = SiteDist::sphere;
    else if (name == "clusters") *out = SiteDist::clusters;
    else if (name == "pgrid") *out = SiteDist::pgrid;
    else return false;
    return true;
}

const char *site_dist_name(SiteDist dist) {
    switch (dist) {
    case SiteDist::grid: return "grid";
    case SiteDist::sphere: return "sphere";
    case SiteDist::clusters: return "clusters";
    case SiteDist::pgrid: return "pgrid";
    default: return "uniform";
    }
}

bool site_make(SiteDist dist, int d, size_t n, uint64_t seed, std::vector<double> *xyz,
               std::string *err) {
    if (d < 2) {
        *err = "dimension below 2";
        return false;
    }
    switch (dist) {
    case SiteDist::uniform: *xyz = uniform_sites(d, n, seed); return true;
    case SiteDist::grid: return grid_sites(d, n, seed, xyz, err);
    case SiteDist::clusters: *xyz = cluster_sites(d, n, seed); return true;
    case SiteDist::pgrid: return perturbed_grid_sites(d, n, seed, xyz, err);
    case SiteDist::sphere: {
        bool ok = d == 2 ? circle_sites(n, xyz, err)
                : d == 3 ? sphere3_sites(n, xyz, err)
                         : sphere_high_sites(d, n, xyz, err);
        if (!ok) return false;
        shuffle_rows(*xyz, d, n, seed); // a random n of them, in random order
        return true;
    }
    }
    return false;
}
