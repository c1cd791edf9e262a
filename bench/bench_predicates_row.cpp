// bench_predicates_row.cpp — one (predicate, input) row: the pool of tuples and its CGAL
// points, one untimed pass per side that records every sign (and lifthull's counters),
// the comparison of the signs, then the calibrated, interleaved timed rounds.
#include "bench_predicates_cgal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{

double now_s()
{
    using clk = std::chrono::steady_clock;
    return std::chrono::duration<double>(clk::now().time_since_epoch()).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// n tuples as doubles and as CGAL points, built once, outside timing.
template <int D, Pred P> struct Pool {
    static constexpr int NP = npts<D, P>();
    size_t n;
    std::vector<double> coords;
    std::vector<typename CgalPoint<D>::type> pts;
    CgalPred<D, P> cg;
};

// The seed depends on the row, so rows are independent of each other's order.
template <int D, Pred P> void make_pool(const Session &s, Input in, Pool<D, P> &pool)
{
    constexpr int NP = Pool<D, P>::NP;
    const size_t n = pool.n;
    Rng rng(s.opt.seed * 1000003u + static_cast<uint64_t>(D) * 17u +
            (P == Pred::insphere ? 5u : 0u) + (in == Input::neardeg ? 101u : 0u));
    pool.coords.resize(n * NP * D);
    for (size_t i = 0; i < n; ++i) gen_tuple(rng, P, in, D, &pool.coords[i * NP * D]);
    pool.pts.reserve(n * NP);
    for (size_t i = 0; i < n * NP; ++i) pool.pts.push_back(CgalPoint<D>::make(&pool.coords[i * D]));
}

// lifthull's sign pass, with its predicate counters checked against the call count.
template <int D, Pred P>
void lh_sign_pass(Session &s, lh_pred *ctx, const Pool<D, P> &pool, Row &row,
                  std::vector<signed char> &sl)
{
    const size_t n = pool.n;
    lh_pred_counters_reset(ctx);
    lh_signs<D, P>(ctx, pool.coords.data(), n, sl);
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
        s.counter_warnings.push_back(buf);
        std::fprintf(stderr, "warning: %s", buf);
    }
}

// The disagreement on tuple i, with its points in %a, for the report.
template <int D, Pred P>
std::string describe_disagreement(const Pool<D, P> &pool, const Row &row, size_t i, int sl, int sc,
                                  int fac)
{
    constexpr int NP = Pool<D, P>::NP;
    std::string s;
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s %s tuple %zu: lifthull %+d, CGAL %+d (factor %+d)\n",
                  row.pred.c_str(), row.input.c_str(), i, sl, sc, fac);
    s += buf;
    for (int j = 0; j < NP; ++j) {
        s += "    p" + std::to_string(j) + " = (";
        for (int c = 0; c < D; ++c) {
            std::snprintf(buf, sizeof buf, "%s%a", c ? ", " : "",
                          pool.coords[i * NP * D + j * D + c]);
            s += buf;
        }
        s += ")\n";
    }
    return s;
}

// Both sign passes, the predicate's sign factor (fixed by its first row) and every
// tuple's signs compared under it.
template <int D, Pred P>
void check_signs(Session &s, lh_pred *ctx, const Pool<D, P> &pool, Row &row)
{
    const size_t n = pool.n;
    std::vector<signed char> sl, sc;
    lh_sign_pass<D, P>(s, ctx, pool, row, sl);
    cgal_signs<D, P>(pool.cg, pool.pts.data(), n, sc);
    int &fac = s.factor.get(P, D);
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
            if (row.disagreements < static_cast<size_t>(s.opt.max_print))
                s.disagreement_log.push_back(
                    describe_disagreement<D, P>(pool, row, i, int(sl[i]), int(sc[i]), fac));
            ++row.disagreements;
        }
    }
    row.lh_zero_sign_frac = double(zl) / double(n);
}

// Calibrates (one warm pass each: passes per round so a round lasts >= min_ms), then
// runs the interleaved rounds; the medians give ns per call.
template <int D, Pred P>
void time_rounds(Session &s, lh_pred *ctx, const Pool<D, P> &pool, Row &row)
{
    const size_t n = pool.n;
    const double *coords = pool.coords.data();
    const auto *pts = pool.pts.data();
    const CgalPred<D, P> &cg = pool.cg;
    auto passes_for = [&](double t_pass) {
        double want = s.opt.min_ms * 1e-3;
        int r = static_cast<int>(std::ceil(want / std::max(t_pass, 1e-9)));
        return std::max(1, r);
    };
    double t0 = now_s();
    s.sink = s.sink + lh_pass<D, P>(ctx, coords, n);
    double t1 = now_s();
    s.sink = s.sink + cgal_pass<D, P>(cg, pts, n);
    double t2 = now_s();
    s.sink = s.sink + cgal_pass_ool<D, P>(cg, pts, n);
    double t3 = now_s();
    row.lh_reps = passes_for(t1 - t0);
    row.cg_reps = passes_for(t2 - t1);
    row.ool_reps = passes_for(t3 - t2);

    std::vector<double> lh_t, cg_t, ool_t;
    // One round of reps passes of one side: ns per call into times, the checksum of one
    // pass into *sum (if given).
    auto round = [&](int reps, auto pass, std::vector<double> &times, long *sum) {
        long acc = 0;
        double a = now_s();
        for (int r = 0; r < reps; ++r) acc += pass();
        double b = now_s();
        s.sink = s.sink + acc;
        if (sum) *sum = acc / reps;
        times.push_back((b - a) * 1e9 / (double(n) * reps));
    };
    auto round_lh = [&] {
        round(
            row.lh_reps, [&] { return lh_pass<D, P>(ctx, coords, n); }, lh_t, &row.lh_sum);
    };
    auto round_cg = [&] {
        round(
            row.cg_reps, [&] { return cgal_pass<D, P>(cg, pts, n); }, cg_t, &row.cg_sum);
    };
    auto round_ool = [&] {
        round(
            row.ool_reps, [&] { return cgal_pass_ool<D, P>(cg, pts, n); }, ool_t, nullptr);
    };
    for (int r = 0; r < s.opt.rounds; ++r) {
        if (r % 2 == 0) {
            round_lh();
            round_cg();
        } else {
            round_cg();
            round_lh();
        }
        if (s.opt.ool) round_ool();
    }
    if (s.opt.ool) row.ool_ns = median(ool_t);
    row.lh_ns = median(lh_t);
    row.cg_ns = median(cg_t);
    row.lh_min = *std::min_element(lh_t.begin(), lh_t.end());
    row.lh_max = *std::max_element(lh_t.begin(), lh_t.end());
    row.cg_min = *std::min_element(cg_t.begin(), cg_t.end());
    row.cg_max = *std::max_element(cg_t.begin(), cg_t.end());
}

template <int D, Pred P> Row run_row_t(Session &s, lh_pred *ctx, Input in, double bar, bool extra)
{
    Row row;
    row.pred = std::string(P == Pred::orient ? "orient_" : "insphere_") + std::to_string(D);
    row.input = in == Input::random ? "random" : "near-degenerate";
    row.cgal_name = CgalPred<D, P>::name;
    row.bar = bar;
    row.extra = extra;
    row.n = size_t(1) << s.opt.log2n;

    Pool<D, P> pool;
    pool.n = row.n;
    make_pool<D, P>(s, in, pool);
    check_signs<D, P>(s, ctx, pool, row);
    time_rounds<D, P>(s, ctx, pool, row);
    std::fprintf(stderr, "  %-11s %-15s lifthull %9.1f ns  CGAL %9.1f ns  exact %.4f\n",
                 row.pred.c_str(), row.input.c_str(), row.lh_ns, row.cg_ns, row.exact_frac);
    return row;
}

} // namespace

Row run_row(Session &s, lh_pred *ctx, int d, Pred p, Input in, double bar, bool extra)
{
    const bool o = p == Pred::orient;
    switch (d) {
    case 2:
        return o ? run_row_t<2, Pred::orient>(s, ctx, in, bar, extra)
                 : run_row_t<2, Pred::insphere>(s, ctx, in, bar, extra);
    case 3:
        return o ? run_row_t<3, Pred::orient>(s, ctx, in, bar, extra)
                 : run_row_t<3, Pred::insphere>(s, ctx, in, bar, extra);
    default:
        return o ? run_row_t<4, Pred::orient>(s, ctx, in, bar, extra)
                 : run_row_t<4, Pred::insphere>(s, ctx, in, bar, extra);
    }
}
