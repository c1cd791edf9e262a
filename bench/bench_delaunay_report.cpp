// bench_delaunay_report.cpp — the suite's Markdown report on stdout: the machine and
// build facts, the time, two-thread and memory tables with their bars, every round's
// details, Qhull's hull-only times, what the times include, and the simplex-count check.
#include "bench_delaunay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace
{

double median(std::vector<double> v)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::string fmt_n(size_t n)
{
    // 1000000 -> 10^6, 20000 -> 2*10^4, 50000 -> 5*10^4, other -> plain
    size_t m = n;
    int e = 0;
    while (m >= 10 && m % 10 == 0) {
        m /= 10;
        ++e;
    }
    if (e >= 3 && m < 10) {
        return (m == 1 ? std::string() : std::to_string(m) + "·") + "10^" + std::to_string(e);
    }
    return std::to_string(n);
}

std::string fmt_s(double s)
{
    char b[32];
    if (std::isnan(s)) return "—";
    if (s >= 100)
        std::snprintf(b, sizeof b, "%.0f", s);
    else if (s >= 10)
        std::snprintf(b, sizeof b, "%.1f", s);
    else if (s >= 0.1)
        std::snprintf(b, sizeof b, "%.2f", s);
    else
        std::snprintf(b, sizeof b, "%.3f", s);
    return b;
}

std::string fmt_mib(double kb)
{
    char b[32];
    if (std::isnan(kb)) return "—";
    double m = kb / 1024.0;
    if (m >= 100)
        std::snprintf(b, sizeof b, "%.0f", m);
    else
        std::snprintf(b, sizeof b, "%.1f", m);
    return b;
}

std::string fmt_x(double x)
{
    char b[32];
    if (std::isnan(x)) return "—";
    std::snprintf(b, sizeof b, "%.2fx", x);
    return b;
}

// The report's sections over one suite's results; the bars' verdicts are counted as
// the tables print them.
struct Report {
    const SuiteOptions &o;
    const std::vector<Config> &configs;
    const std::vector<std::vector<std::string>> &cfg_tools;
    std::vector<std::map<std::string, std::vector<Sample>>> &results;
    int bar_fail = 0, bar_pass = 0;

    double med_wall(size_t ci, const std::string &t) const;
    double med_peak(size_t ci, const std::string &t) const;
    bool has(size_t ci, const std::string &t) const;
    std::string bar(bool applicable, bool pass);
    void header(const SuiteResults &res) const;
    void time_table();
    void two_threads();
    void two_thread_row(size_t ci);
    std::string speed_bars(size_t ci, double t2);
    void memory_table();
    void bars_line() const;
    void details();
    void qhull_hull_only();
};

double Report::med_wall(size_t ci, const std::string &t) const
{
    std::vector<double> v;
    auto it = results[ci].find(t);
    if (it != results[ci].end())
        for (auto &s : it->second)
            if (s.ok) v.push_back(s.wall);
    return median(v);
}

double Report::med_peak(size_t ci, const std::string &t) const
{
    std::vector<double> v;
    auto it = results[ci].find(t);
    if (it != results[ci].end())
        for (auto &s : it->second)
            if (s.ok) v.push_back(double(s.peak_kb));
    return median(v);
}

bool Report::has(size_t ci, const std::string &t) const
{
    return std::find(cfg_tools[ci].begin(), cfg_tools[ci].end(), t) != cfg_tools[ci].end();
}

std::string Report::bar(bool applicable, bool pass)
{
    if (!applicable) return "—";
    (pass ? bar_pass : bar_fail)++;
    return pass ? "PASS" : "**FAIL**";
}

void Report::header(const SuiteResults &res) const
{
    print_build_facts();
    for (auto &t : res.skipped)
        std::printf("- **%s: not built** (library not found at configure time)\n", t.c_str());
    std::printf("- sites uniform in [0,1)^D (xoshiro256** of tools/sites.h, 53-bit doubles); "
                "%d interleaved round(s), "
                "round r on seed %llu+r, every run a separate process; total %.0f s\n",
                o.rounds, (unsigned long long)o.seed, res.t_total);
    if (o.quick || o.scale != 1)
        std::printf("- **reduced sizes (N divided by %g): a smoke run, not the criterion's "
                    "sizes**\n",
                    o.scale);
    if (o.rounds < 3) std::printf("- **fewer than 3 rounds: not the criterion's protocol**\n");
    std::printf("\n");
}

void Report::time_table()
{
    std::printf(
        "### Time: median seconds (ratio tool / lifthull; above 1 means lifthull is faster)\n\n");
    std::printf("| D | N | lifthull | lifthull generic engine | CGAL dD | Qhull Qt | CGAL DT2/DT3 "
                "| TetGen | "
                "CGAL dD >= 2x | Qhull >= 3x | generic: CGAL dD >= 2x |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|\n");
    for (size_t ci = 0; ci < configs.size(); ++ci) {
        const Config &c = configs[ci];
        double lh = med_wall(ci, "lifthull");
        auto cell = [&](const std::string &t) -> std::string {
            if (!has(ci, t)) return "—";
            double s = med_wall(ci, t);
            if (std::isnan(s)) return "failed";
            return fmt_s(s) + " (" + fmt_x(s / lh) + ")";
        };
        std::string spec = c.d == 2 ? cell("cgal_2") : c.d == 3 ? cell("cgal_3") : "—";
        double rdd = med_wall(ci, "cgal_dd") / lh, rq = med_wall(ci, "qhull") / lh;
        double rg = med_wall(ci, "cgal_dd") / med_wall(ci, "lifthull_generic");
        std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.d,
                    fmt_n(c.n).c_str(), std::isnan(lh) ? "failed" : fmt_s(lh).c_str(),
                    cell("lifthull_generic").c_str(), cell("cgal_dd").c_str(),
                    cell("qhull").c_str(), spec.c_str(), cell("tetgen").c_str(),
                    bar(has(ci, "cgal_dd"), rdd >= 2.0).c_str(), // NaN (a failure): FAIL
                    bar(has(ci, "qhull"), rq >= 3.0).c_str(),
                    bar(has(ci, "cgal_dd") && has(ci, "lifthull_generic"), rg >= 2.0).c_str());
    }
}

// The speed issue's bars, for lifthull on two threads (lifthull_t2), the machine's
// cores: wall time, as every other tool's.
void Report::two_threads()
{
    bool any_t2 = false;
    for (size_t ci = 0; ci < configs.size(); ++ci) any_t2 |= has(ci, "lifthull_t2");
    if (!any_t2) return;
    std::printf(
        "\n### Two threads: lifthull_t2 (lh_options.threads = 2) against every tool, median "
        "wall seconds (ratio tool / lifthull_t2), and the speed issue's bars\n\n");
    std::printf(
        "| D | N | lifthull 1 thread | lifthull 2 threads | its CPU s | CGAL dD | Qhull Qt | "
        "CGAL DT2/DT3 | TetGen | speed issue's bars |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (size_t ci = 0; ci < configs.size(); ++ci) two_thread_row(ci);
    std::printf("\n(The lifthull 1 thread column's ratio is its time over lifthull_t2's: the "
                "speed-up of the second thread. A bar's verdict reads the ratio of the medians; "
                "beside it, the lowest and highest of the ratios within one round (both tools on "
                "that round's sites): a bar inside that range is within this machine's "
                "noise.)\n");
}

void Report::two_thread_row(size_t ci)
{
    const Config &c = configs[ci];
    if (!has(ci, "lifthull_t2")) return;
    double t2 = med_wall(ci, "lifthull_t2");
    std::vector<double> cpu;
    for (auto &x : results[ci]["lifthull_t2"])
        if (x.ok) cpu.push_back(x.cpu);
    auto cell = [&](const std::string &t) -> std::string {
        if (!has(ci, t)) return "—";
        double v = med_wall(ci, t);
        return std::isnan(v) ? "failed" : fmt_s(v) + " (" + fmt_x(v / t2) + ")";
    };
    const std::string bars = speed_bars(ci, t2);
    std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.d, fmt_n(c.n).c_str(),
                cell("lifthull").c_str(), std::isnan(t2) ? "failed" : fmt_s(t2).c_str(),
                fmt_s(median(cpu)).c_str(), cell("cgal_dd").c_str(), cell("qhull").c_str(),
                (c.d == 2   ? cell("cgal_2")
                 : c.d == 3 ? cell("cgal_3")
                            : std::string("—"))
                    .c_str(),
                cell("tetgen").c_str(), bars.empty() ? "—" : bars.c_str());
}

// 2D: 2.5x CGAL DT2; 3D: 2.5x DT3 and 4x TetGen; 4D, 5D: 5x CGAL dD, 10x Qhull.
std::string Report::speed_bars(size_t ci, double t2)
{
    const Config &c = configs[ci];
    std::string bars;
    auto add = [&](const char *name, const std::string &t, double want) {
        if (!has(ci, t)) return;
        double r = med_wall(ci, t) / t2;
        bool pass = r >= want;
        (pass ? bar_pass : bar_fail)++;
        // The ratio within each round (both tools on that round's sites): its
        // spread shows how much of a verdict this machine's noise can turn.
        double lo = INFINITY, hi = -INFINITY;
        const std::vector<Sample> &a = results[ci][t], &l = results[ci]["lifthull_t2"];
        for (size_t k = 0; k < a.size() && k < l.size(); ++k)
            if (a[k].ok && l[k].ok) {
                const double x = a[k].wall / l[k].wall;
                lo = std::min(lo, x), hi = std::max(hi, x);
            }
        char b[160];
        std::snprintf(b, sizeof b, "%s%s >= %.1fx: %s", bars.empty() ? "" : "; ", name, want,
                      pass ? "PASS" : "**FAIL**");
        bars += b;
        if (lo <= hi) {
            std::snprintf(b, sizeof b, " (rounds %.2f..%.2fx)", lo, hi);
            bars += b;
        }
    };
    if (c.d == 2) add("DT2", "cgal_2", 2.5);
    if (c.d == 3) add("DT3", "cgal_3", 2.5), add("TetGen", "tetgen", 4.0);
    if (c.d >= 4) add("CGAL dD", "cgal_dd", 5.0), add("Qhull", "qhull", 10.0);
    return bars;
}

void Report::memory_table()
{
    std::printf(
        "\n### Peak memory: median MiB of the process's maximum RSS (ratio tool / lifthull)\n\n");
    std::printf("| D | N | input only | lifthull | CGAL dD | Qhull Qt | CGAL DT2/DT3 | TetGen | "
                "below CGAL dD | below Qhull | speed issue: <= 0.7x every CGAL |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---|\n");
    for (size_t ci = 0; ci < configs.size(); ++ci) {
        const Config &c = configs[ci];
        double lh = med_peak(ci, "lifthull");
        auto cell = [&](const std::string &t) -> std::string {
            if (!has(ci, t)) return "—";
            double k = med_peak(ci, t);
            if (std::isnan(k)) return "failed";
            return fmt_mib(k) + " (" + fmt_x(k / lh) + ")";
        };
        std::string spec = c.d == 2 ? cell("cgal_2") : c.d == 3 ? cell("cgal_3") : "—";
        // The speed issue's bar (not counted above): at least 30% below each CGAL run here.
        const char *cgal_spec = c.d == 2 ? "cgal_2" : c.d == 3 ? "cgal_3" : nullptr;
        bool cgal_any = has(ci, "cgal_dd") || (cgal_spec && has(ci, cgal_spec));
        bool below = (!has(ci, "cgal_dd") || lh <= 0.7 * med_peak(ci, "cgal_dd")) &&
                     (!cgal_spec || !has(ci, cgal_spec) || lh <= 0.7 * med_peak(ci, cgal_spec));
        std::string speed_bar = !cgal_any ? "—" : below ? "PASS" : "**FAIL**";
        std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.d,
                    fmt_n(c.n).c_str(), fmt_mib(med_peak(ci, "none")).c_str(),
                    std::isnan(lh) ? "failed" : fmt_mib(lh).c_str(), cell("cgal_dd").c_str(),
                    cell("qhull").c_str(), spec.c_str(), cell("tetgen").c_str(),
                    bar(has(ci, "cgal_dd"), lh < med_peak(ci, "cgal_dd")).c_str(),
                    bar(has(ci, "qhull"), lh < med_peak(ci, "qhull")).c_str(), speed_bar.c_str());
    }
}

void Report::bars_line() const
{
    std::printf("\nBars (engine issue): lifthull >= 2x faster than CGAL dD and >= 3x faster than "
                "Qhull Qt at every size, peak memory below both; and the generic engine alone "
                "(lh_options.generic_engine: the dimension a runtime value) >= 2x faster than "
                "CGAL dD. With lifthull_t2, also the speed issue's time bars (the table above). "
                "%d passed, %d failed%s.\n",
                bar_pass, bar_fail,
                (o.quick || o.scale != 1) ? " (reduced sizes: not the criterion)" : "");
}

void Report::details()
{
    std::printf("\n### Details (per tool: every round)\n\n");
    std::printf("| D | N | tool | median s | min..max s | median CPU s | peak MiB min..max | "
                "simplices (round 0) | rounds ok |\n");
    std::printf("|---:|---:|---|---:|---:|---:|---:|---:|---:|\n");
    for (size_t ci = 0; ci < configs.size(); ++ci) {
        const Config &c = configs[ci];
        for (const std::string &t : cfg_tools[ci]) {
            const auto &v = results[ci][t];
            std::vector<double> w, cpu;
            double wmin = INFINITY, wmax = -INFINITY, pmin = INFINITY, pmax = -INFINITY;
            int ok = 0;
            size_t simp = 0;
            bool have_simp = false;
            for (size_t r = 0; r < v.size(); ++r) {
                const Sample &s = v[r];
                if (!s.ok) continue;
                ++ok;
                w.push_back(s.wall);
                cpu.push_back(s.cpu);
                wmin = std::min(wmin, s.wall);
                wmax = std::max(wmax, s.wall);
                pmin = std::min(pmin, double(s.peak_kb));
                pmax = std::max(pmax, double(s.peak_kb));
                if (r == 0) {
                    simp = s.simplices;
                    have_simp = true;
                }
            }
            std::string range = ok ? fmt_s(wmin) + ".." + fmt_s(wmax) : "—";
            std::string prange = ok ? fmt_mib(pmin) + ".." + fmt_mib(pmax) : "—";
            std::string sx = t == "none" ? "—" : have_simp ? std::to_string(simp) : "—";
            std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %d/%zu |\n", c.d,
                        fmt_n(c.n).c_str(), t == "none" ? "(input only)" : t.c_str(),
                        t == "none" ? "—" : fmt_s(median(w)).c_str(),
                        t == "none" ? "—" : range.c_str(),
                        t == "none" ? "—" : fmt_s(median(cpu)).c_str(), prange.c_str(), sx.c_str(),
                        ok, v.size());
        }
    }
}

void Report::qhull_hull_only()
{
    bool any = false;
    for (size_t ci = 0; ci < configs.size(); ++ci) {
        std::vector<double> v;
        for (auto &x : results[ci]["qhull"])
            if (x.ok && !std::isnan(x.hull_wall)) v.push_back(x.hull_wall);
        if (v.empty()) continue;
        if (!any) {
            std::printf("\nQhull without its Qt step: the time up to the end of qh_qhull (the "
                        "part qdelaunay's `s` summary reports as CPU seconds), leaving out "
                        "qh_prepare_output, which performs the Qt triangulation. For "
                        "reference only: the bars use the total.\n\n");
            std::printf("| D | N | Qhull total s | hull only s | hull only / lifthull |\n");
            std::printf("|---:|---:|---:|---:|---:|\n");
            any = true;
        }
        double h = median(v);
        std::printf("| %d | %s | %s | %s | %s |\n", configs[ci].d, fmt_n(configs[ci].n).c_str(),
                    fmt_s(med_wall(ci, "qhull")).c_str(), fmt_s(h).c_str(),
                    fmt_x(h / med_wall(ci, "lifthull")).c_str());
    }
}

// What the times include, the simplex-count check and the failed runs.
int report_footer(const SuiteResults &res)
{
    std::printf("\nWhat the times include: the timer starts when the sites are in the tool's "
                "input form and stops when the triangulation is built and its finite simplices "
                "are counted. lifthull: lh_delaunay (its copy of the input, the triangulation, "
                "neighbours, hull facets, canonical sorted output). CGAL: range insert (spatial "
                "sort + incremental insertion); building the vector of CGAL points is not "
                "timed. Qhull: the steps of qh_new_qhull with `%s` "
                "(lifting, Qbb scaling, hull, Qt triangulation; no output); counted facets are the "
                "lower-Delaunay ones. "
                "TetGen: tetrahedralize(\"%s\") into a tetgenio (tetrahedra, hull faces and "
                "the point list copied out); filling the input tetgenio is not timed. No "
                "destructor is timed. Peak memory: whole-process maximum RSS, including the "
                "program and libraries, and the input in the form the tool's caller must hold "
                "(lifthull and Qhull: the flat double array; CGAL: its point vector; TetGen: "
                "its tetgenio); \"input only\" is a run that just generates the sites.\n",
#ifdef LH_BENCH_HAVE_QHULL
                kQhullCmd,
#else
                "(not built)",
#endif
                kTetgenSwitches);

    std::printf("\nSimplex counts (every round, every tool against lifthull): ");
    if (res.exact_mismatch.empty() && res.inexact_mismatch.empty()) {
        std::printf("all agree.\n");
    } else {
        std::printf("**%zu disagreement(s)**\n\n",
                    res.exact_mismatch.size() + res.inexact_mismatch.size());
        for (auto &s : res.exact_mismatch) std::printf("- exact tool: %s\n", s.c_str());
        for (auto &s : res.inexact_mismatch)
            std::printf("- warning (Qhull is not exact): %s\n", s.c_str());
    }
    if (!res.failures.empty()) {
        std::printf("\n**%zu failed run(s):**\n\n", res.failures.size());
        for (auto &s : res.failures) std::printf("- %s\n", s.c_str());
    }
    return (!res.failures.empty() || !res.exact_mismatch.empty()) ? 2 : 0;
}

} // namespace

int suite_report(const SuiteOptions &o, SuiteResults &res)
{
    Report r{o, res.configs, res.cfg_tools, res.results};
    r.header(res);
    r.time_table();
    r.two_threads();
    r.memory_table();
    r.bars_line();
    r.details();
    r.qhull_hull_only();
    return report_footer(res);
}
