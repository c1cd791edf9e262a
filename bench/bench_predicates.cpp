// bench_predicates — ns per call of lifthull's exact predicates next to CGAL's Epick
// predicates, measured in one run over the same pre-generated inputs.
//
// Predicates: orient_2, orient_3, insphere_2, insphere_3, insphere_4 (and orient_4 as
// an extra row, against Epick_d's Orientation_d). Input kinds:
//   random          every coordinate uniform in [0,1)
//   near-degenerate orient_k: k points uniform in [0,1)^k, the last one an affine
//                   combination of them rounded to double, then one of its coordinates
//                   moved by 1 ulp; insphere_d: d+2 points on the unit sphere computed
//                   with cos/sin (d = 2, 3) or a normalized Gaussian vector (d = 4) and
//                   rounded to double — so the determinant is tiny and filters mostly fail.
// For each (predicate, input) a pool of N tuples (2^16 by default) is generated once;
// CGAL points are built from the same doubles once, outside timing. Each side then
// runs R rounds (interleaved L,C / C,L, ...), each round a whole number of passes over
// the pool lasting at least --min-ms; the median round gives ns/call.
//
// Signs: before timing, one pass per side records every sign. lifthull and CGAL may
// use opposite sign conventions, so a global factor per predicate is determined from
// the first tuple where both signs are nonzero and printed; any tuple where
// lifthull != factor * CGAL is a disagreement and is printed with %a coordinates.
// The exact-path fraction is lh_pred_counters exact_exits / calls over that pass.
//
// CGAL's functors are inlined into the timed loop; lifthull is an out-of-line library
// call. For reference, the details table also times CGAL through a noinline wrapper
// (a third interleaved side; --no-ool skips it). The bars use the inlined CGAL time.
//
// Output: Markdown on stdout. Exit status 0, or 2 if any sign disagreement was found.

#include <lifthull.h>

#include "bench_machine.h"

#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/version.h>
#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <sys/utsname.h>
#include <unistd.h>

#define NOINLINE __attribute__((noinline))

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using KD4 = CGAL::Epick_d<CGAL::Dimension_tag<4>>;

enum class Pred { orient, insphere };
enum class Input { random, neardeg };

// ---- options ----------------------------------------------------------------------

struct Options {
    int log2n = 16;
    int rounds = 7;
    double min_ms = 60.0;
    uint64_t seed = 20240611;
    int max_print = 5; // disagreements printed per row
    bool ool = true;   // also time CGAL through an out-of-line call (details table)
    std::string only_pred, only_input; // empty: all (for profiling one row)
};
Options g_opt;

volatile long g_sink; // checksums end here so no call can be optimized away

// ---- CGAL adapters ----------------------------------------------------------------

template <int D> struct CgalPoint;
template <> struct CgalPoint<2> {
    using type = K::Point_2;
    static type make(const double *c) { return type(c[0], c[1]); }
};
template <> struct CgalPoint<3> {
    using type = K::Point_3;
    static type make(const double *c) { return type(c[0], c[1], c[2]); }
};
template <> struct CgalPoint<4> {
    using type = KD4::Point_d;
    static type make(const double *c) { return type(c, c + 4); }
};

template <int D, Pred P> struct CgalPred;
template <> struct CgalPred<2, Pred::orient> {
    static constexpr const char *name = "Epick Orientation_2";
    K::Orientation_2 f = K().orientation_2_object();
    int operator()(const K::Point_2 *a) const { return static_cast<int>(f(a[0], a[1], a[2])); }
};
template <> struct CgalPred<3, Pred::orient> {
    static constexpr const char *name = "Epick Orientation_3";
    K::Orientation_3 f = K().orientation_3_object();
    int operator()(const K::Point_3 *a) const {
        return static_cast<int>(f(a[0], a[1], a[2], a[3]));
    }
};
template <> struct CgalPred<4, Pred::orient> {
    static constexpr const char *name = "Epick_d<4> Orientation_d";
    KD4::Orientation_d f = KD4().orientation_d_object();
    int operator()(const KD4::Point_d *a) const { return static_cast<int>(f(a, a + 5)); }
};
template <> struct CgalPred<2, Pred::insphere> {
    static constexpr const char *name = "Epick Side_of_oriented_circle_2";
    K::Side_of_oriented_circle_2 f = K().side_of_oriented_circle_2_object();
    int operator()(const K::Point_2 *a) const {
        return static_cast<int>(f(a[0], a[1], a[2], a[3]));
    }
};
template <> struct CgalPred<3, Pred::insphere> {
    static constexpr const char *name = "Epick Side_of_oriented_sphere_3";
    K::Side_of_oriented_sphere_3 f = K().side_of_oriented_sphere_3_object();
    int operator()(const K::Point_3 *a) const {
        return static_cast<int>(f(a[0], a[1], a[2], a[3], a[4]));
    }
};
template <> struct CgalPred<4, Pred::insphere> {
    static constexpr const char *name = "Epick_d<4> Side_of_oriented_sphere_d";
    KD4::Side_of_oriented_sphere_d f = KD4().side_of_oriented_sphere_d_object();
    int operator()(const KD4::Point_d *a) const {
        return static_cast<int>(f(a, a + 5, a[5]));
    }
};

// ---- the timed loops ----------------------------------------------------------------

template <int D, Pred P> constexpr int npts() { return P == Pred::orient ? D + 1 : D + 2; }

template <int D, Pred P> inline int lh_call(lh_pred *ctx, const double *const *pts) {
    if constexpr (P == Pred::orient)
        return lh_orient(ctx, D, pts);
    else
        return lh_insphere(ctx, D, pts);
}

// One pass over the pool; returns the sum of signs (checksum).
template <int D, Pred P> NOINLINE long lh_pass(lh_pred *ctx, const double *c, size_t n) {
    constexpr int NP = npts<D, P>();
    const double *ptrs[NP];
    long acc = 0;
    for (size_t i = 0; i < n; ++i) {
        const double *b = c + i * (NP * D);
        for (int j = 0; j < NP; ++j) ptrs[j] = b + j * D;
        acc += lh_call<D, P>(ctx, ptrs);
    }
    return acc;
}

template <int D, Pred P>
NOINLINE long cgal_pass(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts,
                        size_t n) {
    constexpr int NP = npts<D, P>();
    long acc = 0;
    for (size_t i = 0; i < n; ++i) acc += f(pts + i * NP);
    return acc;
}

// The same CGAL pass, but every predicate call goes through an out-of-line function, as
// lifthull's calls do (informational: separates call overhead from predicate cost).
template <int D, Pred P>
NOINLINE int cgal_call_ool(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *a) {
    return f(a);
}
template <int D, Pred P>
NOINLINE long cgal_pass_ool(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts,
                            size_t n) {
    constexpr int NP = npts<D, P>();
    long acc = 0;
    for (size_t i = 0; i < n; ++i) acc += cgal_call_ool<D, P>(f, pts + i * NP);
    return acc;
}

// Sign-recording passes (untimed).
template <int D, Pred P>
void lh_signs(lh_pred *ctx, const double *c, size_t n, std::vector<signed char> &out) {
    constexpr int NP = npts<D, P>();
    const double *ptrs[NP];
    out.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double *b = c + i * (NP * D);
        for (int j = 0; j < NP; ++j) ptrs[j] = b + j * D;
        out[i] = static_cast<signed char>(lh_call<D, P>(ctx, ptrs));
    }
}
template <int D, Pred P>
void cgal_signs(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts, size_t n,
                std::vector<signed char> &out) {
    constexpr int NP = npts<D, P>();
    out.resize(n);
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<signed char>(f(pts + i * NP));
}

double now_s() {
    using clk = std::chrono::steady_clock;
    return std::chrono::duration<double>(clk::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// ---- input generation ----------------------------------------------------------------

struct Rng {
    std::mt19937_64 g;
    explicit Rng(uint64_t s) : g(s) {}
    double u01() { return static_cast<double>(g() >> 11) * 0x1p-53; } // [0,1)
    double gauss() { return nd(g); }
    uint64_t bits() { return g(); }
    std::normal_distribution<double> nd{0.0, 1.0};
};

const double kTwoPi = 6.283185307179586476925286766559;

// Writes one tuple of np points of dimension d into out.
void gen_tuple(Rng &r, Pred p, Input in, int d, double *out) {
    const int np = p == Pred::orient ? d + 1 : d + 2;
    if (in == Input::random) {
        for (int i = 0; i < np * d; ++i) out[i] = r.u01();
        return;
    }
    if (p == Pred::orient) {
        // d points uniform; the last an affine combination of them, rounded, then one
        // coordinate moved by 1 ulp up or down.
        for (int i = 0; i < d * d; ++i) out[i] = r.u01();
        double t[8];
        for (int j = 1; j < d; ++j) t[j] = r.u01();
        double *q = out + d * d;
        for (int c = 0; c < d; ++c) {
            double v = out[c];
            for (int j = 1; j < d; ++j) v += t[j] * (out[j * d + c] - out[c]);
            q[c] = v;
        }
        uint64_t b = r.bits();
        int c = static_cast<int>(b % static_cast<uint64_t>(d));
        q[c] = std::nextafter(q[c], (b >> 32) & 1 ? 2.0 : -2.0);
        return;
    }
    // insphere: d+2 points on the unit sphere, rounded.
    for (int i = 0; i < np; ++i) {
        double *q = out + i * d;
        if (d == 2) {
            double th = kTwoPi * r.u01();
            q[0] = std::cos(th);
            q[1] = std::sin(th);
        } else if (d == 3) {
            double z = 2.0 * r.u01() - 1.0, th = kTwoPi * r.u01();
            double s = std::sqrt(1.0 - z * z);
            q[0] = s * std::cos(th);
            q[1] = s * std::sin(th);
            q[2] = z;
        } else {
            double n2 = 0;
            do {
                n2 = 0;
                for (int c = 0; c < d; ++c) {
                    q[c] = r.gauss();
                    n2 += q[c] * q[c];
                }
            } while (n2 < 1e-6);
            double inv = 1.0 / std::sqrt(n2);
            for (int c = 0; c < d; ++c) q[c] *= inv;
        }
    }
}

// ---- one row ---------------------------------------------------------------------------

struct Row {
    std::string pred, input, cgal_name;
    double lh_ns = 0, cg_ns = 0;
    double lh_min = 0, lh_max = 0, cg_min = 0, cg_max = 0;
    double ool_ns = 0; // CGAL through an out-of-line call
    int ool_reps = 0;
    double exact_frac = 0, zero_frac = 0, lh_zero_sign_frac = 0;
    double bar = 0; // 0: no bar for this row
    bool extra = false;
    int factor = 0;
    size_t n = 0, disagreements = 0;
    int lh_reps = 0, cg_reps = 0;
    long lh_sum = 0, cg_sum = 0;
    uint64_t calls = 0;
};

struct SignFactor {
    int orient[9] = {0};
    int insphere[9] = {0};
    int &get(Pred p, int d) { return p == Pred::orient ? orient[d] : insphere[d]; }
};
SignFactor g_factor;
std::vector<std::string> g_disagreement_log;
std::vector<std::string> g_counter_warnings;

template <int D, Pred P> Row run_row(lh_pred *ctx, Input in, double bar, bool extra) {
    constexpr int NP = npts<D, P>();
    using CP = CgalPoint<D>;
    using Pt = typename CP::type;
    const size_t n = size_t(1) << g_opt.log2n;

    Row row;
    row.pred = std::string(P == Pred::orient ? "orient_" : "insphere_") + std::to_string(D);
    row.input = in == Input::random ? "random" : "near-degenerate";
    row.cgal_name = CgalPred<D, P>::name;
    row.bar = bar;
    row.extra = extra;
    row.n = n;

    // Generate (seed depends on the row, so rows are independent of each other's order).
    Rng rng(g_opt.seed * 1000003u + static_cast<uint64_t>(D) * 17u +
            (P == Pred::insphere ? 5u : 0u) + (in == Input::neardeg ? 101u : 0u));
    std::vector<double> coords(n * NP * D);
    for (size_t i = 0; i < n; ++i) gen_tuple(rng, P, in, D, &coords[i * NP * D]);
    std::vector<Pt> pts;
    pts.reserve(n * NP);
    for (size_t i = 0; i < n * NP; ++i) pts.push_back(CP::make(&coords[i * D]));
    CgalPred<D, P> cg;

    // Sign pass + counters.
    std::vector<signed char> sl, sc;
    lh_pred_counters_reset(ctx);
    lh_signs<D, P>(ctx, coords.data(), n, sl);
    lh_pred_counters cnt;
    lh_pred_counters_get(ctx, &cnt);
    row.calls = cnt.calls;
    row.exact_frac = cnt.calls ? double(cnt.exact_exits) / double(cnt.calls) : 0.0;
    row.zero_frac = cnt.calls ? double(cnt.zero_results) / double(cnt.calls) : 0.0;
    if (cnt.calls != n || cnt.filter_exits + cnt.exact_exits != cnt.calls) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "%s %s: counters inconsistent after %zu calls: calls %llu, filter_exits "
                      "%llu, exact_exits %llu\n",
                      row.pred.c_str(), row.input.c_str(), n, (unsigned long long)cnt.calls,
                      (unsigned long long)cnt.filter_exits, (unsigned long long)cnt.exact_exits);
        g_counter_warnings.push_back(buf);
        std::fprintf(stderr, "warning: %s", buf);
    }
    cgal_signs<D, P>(cg, pts.data(), n, sc);

    int &fac = g_factor.get(P, D);
    if (fac == 0)
        for (size_t i = 0; i < n; ++i)
            if (sl[i] != 0 && sc[i] != 0) {
                fac = sl[i] * sc[i];
                break;
            }
    row.factor = fac;
    size_t zl = 0;
    for (size_t i = 0; i < n; ++i) {
        zl += sl[i] == 0;
        int expect = (fac ? fac : 1) * sc[i];
        if (sl[i] != expect) {
            if (row.disagreements < static_cast<size_t>(g_opt.max_print)) {
                std::string s;
                char buf[128];
                std::snprintf(buf, sizeof buf, "%s %s tuple %zu: lifthull %+d, CGAL %+d (factor %+d)\n",
                              row.pred.c_str(), row.input.c_str(), i, int(sl[i]), int(sc[i]), fac);
                s += buf;
                for (int j = 0; j < NP; ++j) {
                    s += "    p" + std::to_string(j) + " = (";
                    for (int c = 0; c < D; ++c) {
                        std::snprintf(buf, sizeof buf, "%s%a", c ? ", " : "",
                                      coords[i * NP * D + j * D + c]);
                        s += buf;
                    }
                    s += ")\n";
                }
                g_disagreement_log.push_back(s);
            }
            ++row.disagreements;
        }
    }
    row.lh_zero_sign_frac = double(zl) / double(n);

    // Calibrate: one warm pass each, passes per round so a round lasts >= min_ms.
    auto passes_for = [&](double t_pass) {
        double want = g_opt.min_ms * 1e-3;
        int r = static_cast<int>(std::ceil(want / std::max(t_pass, 1e-9)));
        return std::max(1, r);
    };
    double t0 = now_s();
    g_sink = g_sink + lh_pass<D, P>(ctx, coords.data(), n);
    double t1 = now_s();
    g_sink = g_sink + cgal_pass<D, P>(cg, pts.data(), n);
    double t2 = now_s();
    g_sink = g_sink + cgal_pass_ool<D, P>(cg, pts.data(), n);
    double t3 = now_s();
    row.lh_reps = passes_for(t1 - t0);
    row.cg_reps = passes_for(t2 - t1);
    row.ool_reps = passes_for(t3 - t2);

    std::vector<double> lh_t, cg_t, ool_t;
    auto round_lh = [&] {
        long acc = 0;
        double a = now_s();
        for (int r = 0; r < row.lh_reps; ++r) acc += lh_pass<D, P>(ctx, coords.data(), n);
        double b = now_s();
        g_sink = g_sink + acc;
        row.lh_sum = acc / row.lh_reps;
        lh_t.push_back((b - a) * 1e9 / (double(n) * row.lh_reps));
    };
    auto round_cg = [&] {
        long acc = 0;
        double a = now_s();
        for (int r = 0; r < row.cg_reps; ++r) acc += cgal_pass<D, P>(cg, pts.data(), n);
        double b = now_s();
        g_sink = g_sink + acc;
        row.cg_sum = acc / row.cg_reps;
        cg_t.push_back((b - a) * 1e9 / (double(n) * row.cg_reps));
    };
    auto round_ool = [&] {
        long acc = 0;
        double a = now_s();
        for (int r = 0; r < row.ool_reps; ++r) acc += cgal_pass_ool<D, P>(cg, pts.data(), n);
        double b = now_s();
        g_sink = g_sink + acc;
        ool_t.push_back((b - a) * 1e9 / (double(n) * row.ool_reps));
    };
    for (int r = 0; r < g_opt.rounds; ++r) {
        if (r % 2 == 0) {
            round_lh();
            round_cg();
        } else {
            round_cg();
            round_lh();
        }
        if (g_opt.ool) round_ool();
    }
    if (g_opt.ool) row.ool_ns = median(ool_t);
    row.lh_ns = median(lh_t);
    row.cg_ns = median(cg_t);
    row.lh_min = *std::min_element(lh_t.begin(), lh_t.end());
    row.lh_max = *std::max_element(lh_t.begin(), lh_t.end());
    row.cg_min = *std::min_element(cg_t.begin(), cg_t.end());
    row.cg_max = *std::max_element(cg_t.begin(), cg_t.end());
    std::fprintf(stderr, "  %-11s %-15s lifthull %9.1f ns  CGAL %9.1f ns  exact %.4f\n",
                 row.pred.c_str(), row.input.c_str(), row.lh_ns, row.cg_ns, row.exact_frac);
    return row;
}

std::string fmt_frac(double x) {
    char b[32];
    if (x > 0 && x < 1e-4)
        std::snprintf(b, sizeof b, "%.1e", x);
    else
        std::snprintf(b, sizeof b, "%.4f", x);
    return b;
}

void usage(const char *argv0) {
    std::fprintf(stderr,
                 "usage: %s [--log2n L] [--rounds R] [--min-ms M] [--seed S] [--quick]\n"
                 "  --log2n L   pool of 2^L tuples per (predicate, input) (default 16)\n"
                 "  --rounds R  timed rounds per side, interleaved (default 7, min 5)\n"
                 "  --min-ms M  minimum duration of one round in ms (default 60)\n"
                 "  --seed S    RNG seed (default 20240611)\n"
                 "  --only P    run only predicate P (e.g. insphere_3)\n"
                 "  --input I   run only input kind I (random or near-degenerate)\n"
                 "  --no-ool    skip timing CGAL through an out-of-line call\n"
                 "  --quick     smoke test: --log2n 12 --rounds 5 --min-ms 5\n",
                 argv0);
}

} // namespace

int main(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> const char * {
            if (i + 1 >= argc) {
                usage(argv[0]);
                std::exit(1);
            }
            return argv[++i];
        };
        if (a == "--log2n")
            g_opt.log2n = std::atoi(next());
        else if (a == "--rounds")
            g_opt.rounds = std::atoi(next());
        else if (a == "--min-ms")
            g_opt.min_ms = std::atof(next());
        else if (a == "--seed")
            g_opt.seed = std::strtoull(next(), nullptr, 0);
        else if (a == "--only")
            g_opt.only_pred = next();
        else if (a == "--input")
            g_opt.only_input = next();
        else if (a == "--no-ool")
            g_opt.ool = false;
        else if (a == "--quick") {
            g_opt.log2n = 12;
            g_opt.rounds = 5;
            g_opt.min_ms = 5;
        } else {
            usage(argv[0]);
            return 1;
        }
    }
    if (g_opt.log2n < 4 || g_opt.log2n > 24 || g_opt.rounds < 1 || g_opt.min_ms <= 0) {
        usage(argv[0]);
        return 1;
    }

    lh_pred *ctx = nullptr;
    if (lh_pred_create(nullptr, &ctx) != LH_OK) {
        std::fprintf(stderr, "lh_pred_create failed\n");
        return 1;
    }

    std::vector<Row> rows;
    std::fprintf(stderr, "bench_predicates: 2^%d tuples, %d rounds, >= %.0f ms per round\n",
                 g_opt.log2n, g_opt.rounds, g_opt.min_ms);
    for (Input in : {Input::random, Input::neardeg}) {
        const bool rnd = in == Input::random;
        if (!g_opt.only_input.empty() && g_opt.only_input != (rnd ? "random" : "near-degenerate"))
            continue;
        auto want = [&](const char *name) {
            return g_opt.only_pred.empty() || g_opt.only_pred == name;
        };
        if (want("orient_2")) rows.push_back(run_row<2, Pred::orient>(ctx, in, rnd ? 1.3 : 0, false));
        if (want("orient_3")) rows.push_back(run_row<3, Pred::orient>(ctx, in, rnd ? 1.3 : 0, false));
        if (want("orient_4")) rows.push_back(run_row<4, Pred::orient>(ctx, in, 0, true));
        if (want("insphere_2"))
            rows.push_back(run_row<2, Pred::insphere>(ctx, in, rnd ? 1.3 : 0, false));
        if (want("insphere_3"))
            rows.push_back(run_row<3, Pred::insphere>(ctx, in, rnd ? 1.3 : 3.0, false));
        if (want("insphere_4"))
            rows.push_back(run_row<4, Pred::insphere>(ctx, in, rnd ? 1.3 : 0, false));
    }
    if (rows.empty()) {
        std::fprintf(stderr, "no row matches --only/--input\n");
        return 1;
    }
    lh_pred_free(ctx);

    // ---- report ----
    struct utsname un;
    std::string kernel = uname(&un) == 0 ? std::string(un.sysname) + " " + un.release + " " +
                                               un.machine
                                         : "unknown";
    std::printf("- CPU: %s (%ld logical CPUs online)\n", cpu_model().c_str(),
                sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("- OS: %s\n", kernel.c_str());
    std::printf("- lifthull %s, C compiler: %s, flags: `%s`\n", lh_version_string(),
                LH_BENCH_C_COMPILER, LH_BENCH_C_FLAGS);
    std::printf("- bench C++ compiler: %s (`__VERSION__` %s), flags: `%s`, build type %s\n",
                LH_BENCH_CXX_COMPILER, __VERSION__, LH_BENCH_CXX_FLAGS, LH_BENCH_BUILD_TYPE);
    std::printf("- CGAL %s (CGAL_VERSION_NR %lld), Eigen %d.%d.%d\n", CGAL_VERSION_STR,
                static_cast<long long>(CGAL_VERSION_NR), EIGEN_WORLD_VERSION,
                EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
    std::printf("- pool: 2^%d = %zu tuples per (predicate, input); %d interleaved rounds per "
                "side, each >= %.0f ms; seed %llu\n",
                g_opt.log2n, size_t(1) << g_opt.log2n, g_opt.rounds, g_opt.min_ms,
                static_cast<unsigned long long>(g_opt.seed));
    std::printf("\n");

    std::printf("| predicate | input | lifthull ns/call | CGAL ns/call | ratio | "
                "lifthull exact-path fraction | bar |\n");
    std::printf("|---|---|---:|---:|---:|---:|---|\n");
    int fails = 0;
    for (const Row &r : rows) {
        double ratio = r.lh_ns / r.cg_ns;
        std::string bar;
        if (r.bar > 0) {
            bool pass = ratio <= r.bar;
            fails += !pass;
            char b[48];
            std::snprintf(b, sizeof b, "<= %.1fx: %s", r.bar, pass ? "PASS" : "FAIL");
            bar = b;
        } else {
            bar = r.extra ? "— (extra row)" : "—";
        }
        std::printf("| %s | %s | %.1f | %.1f | %.2f | %s | %s |\n", r.pred.c_str(),
                    r.input.c_str(), r.lh_ns, r.cg_ns, ratio, fmt_frac(r.exact_frac).c_str(),
                    bar.c_str());
    }
    std::printf("\nBars: random input, ratio <= 1.3 for orient_2, orient_3, insphere_2, "
                "insphere_3, insphere_4; near-degenerate insphere_3, ratio <= 3. "
                "%d bar(s) missed.\n",
                fails);

    std::printf("\n### Details\n\n");
    std::printf("| predicate | input | CGAL functor | lifthull min..max ns | CGAL min..max ns | "
                "CGAL out-of-line ns | passes/round L, C | exact zeros | sign factor | disagreements | checksum L, C |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row &r : rows) {
        char ool[32] = "—";
        if (g_opt.ool) std::snprintf(ool, sizeof ool, "%.1f", r.ool_ns);
        std::printf("| %s | %s | %s | %.1f..%.1f | %.1f..%.1f | %s | %d, %d | %s | %+d | %zu | %ld, %ld |\n",
                    r.pred.c_str(), r.input.c_str(), r.cgal_name.c_str(), r.lh_min, r.lh_max,
                    r.cg_min, r.cg_max, ool, r.lh_reps, r.cg_reps, fmt_frac(r.zero_frac).c_str(),
                    r.factor, r.disagreements, r.lh_sum, r.cg_sum);
    }

    std::printf("\nSign convention: lifthull sign = factor × CGAL sign, one factor per predicate, "
                "fixed from the first tuple where both signs are nonzero:");
    for (int d = 2; d <= 4; ++d) std::printf(" orient_%d %+d;", d, g_factor.orient[d]);
    for (int d = 2; d <= 4; ++d)
        std::printf(" insphere_%d %+d%s", d, g_factor.insphere[d], d < 4 ? ";" : ".\n");

    size_t total_dis = 0;
    for (const Row &r : rows) total_dis += r.disagreements;
    if (total_dis == 0) {
        std::printf("\nSign agreement: all %zu tuples agree (after the factor).\n",
                    rows.size() * (size_t(1) << g_opt.log2n));
    } else {
        std::printf("\n**Sign disagreements: %zu** (first %d per row shown):\n\n```\n", total_dis,
                    g_opt.max_print);
        for (const std::string &s : g_disagreement_log) std::printf("%s", s.c_str());
        std::printf("```\n");
    }
    for (const std::string &w : g_counter_warnings) std::printf("\nWarning: %s", w.c_str());
    std::printf("\n(checksum sink %ld)\n", static_cast<long>(g_sink));
    return total_dis ? 2 : 0;
}
