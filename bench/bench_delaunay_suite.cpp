// bench_delaunay_suite.cpp — `bench_delaunay suite`: its options, the (D, N)
// configurations, and the interleaved rounds, every run a child process
// (bench_delaunay_spawn.cpp), each round's simplex counts checked against lifthull's.
// The report is bench_delaunay_report.cpp's.
#include "bench_delaunay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{

std::vector<std::string> split(const std::string &s)
{
    std::vector<std::string> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) v.push_back(item);
    return v;
}

// Reads the options into *o; false (after the usage or a message) if they are not
// usable. Exits with status 1 if an option lacks its value.
bool parse_suite_options(int argc, char **argv, SuiteOptions *out)
{
    SuiteOptions &o = *out;
    bool rounds_given = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> const char * {
            if (i + 1 >= argc) {
                suite_usage();
                std::exit(1);
            }
            return argv[++i];
        };
        if (a == "--quick")
            o.quick = true;
        else if (a == "--rounds") {
            o.rounds = std::atoi(next());
            rounds_given = true;
        } else if (a == "--scale")
            o.scale = std::atof(next());
        else if (a == "--seed")
            o.seed = std::strtoull(next(), nullptr, 0);
        else if (a == "--timeout")
            o.timeout = std::atoi(next());
        else if (a == "--dims") {
            o.dims.clear();
            for (auto &s : split(next())) o.dims.push_back(std::atoi(s.c_str()));
        } else if (a == "--tools")
            o.tools = split(next());
        else {
            suite_usage();
            return false;
        }
    }
    if (o.rounds < 1 || !(o.scale >= 1)) {
        suite_usage();
        return false;
    }
    if (o.quick && o.scale == 1) o.scale = 20;
    if (o.quick && !rounds_given) o.rounds = 2; // a smoke run: < 20 s on the 2-core machines
    if (o.timeout <= 0) o.timeout = o.quick ? 120 : 1800;
    return true;
}

// o.tools: every tool by default; unknown names refused, tools not built moved to
// *skipped; lifthull required (ratios are relative to it). False after a message.
bool select_tools(SuiteOptions &o, std::vector<std::string> *skipped)
{
    if (o.tools.empty())
        for (const char *t : kAllTools) o.tools.push_back(t);
    for (auto &t : o.tools) {
        bool known = false;
        for (const char *k : kAllTools) known |= t == k;
        if (!known) {
            std::fprintf(stderr, "unknown tool %s\n", t.c_str());
            return false;
        }
    }
    std::vector<std::string> kept;
    for (auto &t : o.tools)
        if (tool_built(t))
            kept.push_back(t);
        else
            skipped->push_back(t);
    o.tools = kept;
    if (std::find(o.tools.begin(), o.tools.end(), "lifthull") == o.tools.end()) {
        std::fprintf(stderr, "--tools must include lifthull (ratios are relative to it)\n");
        return false;
    }
    return true;
}

// The criterion's sizes in the dimensions asked for, N divided by the scale.
std::vector<Config> make_configs(const SuiteOptions &o)
{
    const Config base[] = {{2, 1000000}, {3, 1000000}, {4, 100000}, {5, 20000}};
    std::vector<Config> configs;
    for (const Config &c : base)
        if (std::find(o.dims.begin(), o.dims.end(), c.d) != o.dims.end())
            configs.push_back({c.d, size_t(std::llround(double(c.n) / o.scale))});
    return configs;
}

// Round r of configuration ci: every tool once, in an order rotated by r, on the sites of
// seed o.seed + r; then every tool's simplex count against lifthull's.
void run_round(const std::string &exe, const SuiteOptions &o, size_t ci, int r, SuiteResults &res)
{
    const Config &c = res.configs[ci];
    const uint64_t seed = o.seed + uint64_t(r);
    std::vector<std::string> order = res.cfg_tools[ci];
    std::rotate(order.begin(), order.begin() + (size_t(r) % order.size()), order.end());
    std::map<std::string, size_t> counts;
    for (const std::string &t : order) {
        std::string err;
        Sample s = spawn_run(exe, t, c.d, c.n, seed, o.timeout, err);
        res.results[ci][t].push_back(s);
        if (!s.ok) {
            char b[512];
            std::snprintf(b, sizeof b, "D=%d N=%zu round %d %s: %s", c.d, c.n, r, t.c_str(),
                          err.c_str());
            res.failures.push_back(b);
            std::fprintf(stderr, "  FAILED %s\n", b);
            continue;
        }
        std::fprintf(stderr, "  D=%d N=%-8zu round %d %-9s %8.3f s  %9zu simplices  %8.1f MiB\n",
                     c.d, c.n, r, t.c_str(), s.wall, s.simplices, s.peak_kb / 1024.0);
        if (t != "none") counts[t] = s.simplices;
    }
    // Simplex counts of this round: every tool against lifthull.
    auto ref = counts.find("lifthull");
    if (ref != counts.end())
        for (auto &[t, k] : counts) {
            if (k == ref->second) continue;
            char b[256];
            std::snprintf(b, sizeof b,
                          "D=%d N=%zu seed %llu: %s counted %zu simplices, lifthull %zu", c.d, c.n,
                          (unsigned long long)seed, t.c_str(), k, ref->second);
            (tool_exact(t) ? res.exact_mismatch : res.inexact_mismatch).push_back(b);
            std::fprintf(stderr, "  warning: %s\n", b);
        }
}

} // namespace

void suite_usage()
{
    std::fprintf(stderr,
                 "usage: bench_delaunay suite [--quick] [--rounds R] [--dims 2,3,4,5]\n"
                 "                            [--tools lifthull,cgal_dd,...] [--scale K]\n"
                 "                            [--seed S] [--timeout S]\n"
                 "       bench_delaunay run TOOL D N SEED [--timeout S] [--dist "
                 "uniform|grid|sphere|clusters|pgrid]\n"
                 "       bench_delaunay info   (machine and build facts)\n"
                 "  sizes: (2,10^6) (3,10^6) (4,10^5) (5,2*10^4); --quick divides N by 20 and\n"
                 "  runs 2 rounds (--scale K divides by K); R interleaved rounds (default 3;\n"
                 "  the criterion needs >= 3)\n"
                 "  tools: lifthull lifthull_generic lifthull_t2 cgal_dd qhull cgal_2 cgal_3\n"
                 "  tetgen (none: input only,\n"
                 "  always run); --timeout: per child process (default 1800 s, quick 120 s)\n");
}

int cmd_suite(int argc, char **argv)
{
    SuiteOptions o;
    SuiteResults res;
    if (!parse_suite_options(argc, argv, &o) || !select_tools(o, &res.skipped)) return 1;
    res.configs = make_configs(o);
    if (res.configs.empty()) {
        std::fprintf(stderr, "no configuration left (--dims takes 2,3,4,5)\n");
        return 1;
    }
    const std::string exe = self_exe();
    if (exe.empty()) {
        std::fprintf(stderr, "cannot find /proc/self/exe\n");
        return 1;
    }
    res.results.resize(res.configs.size());
    res.cfg_tools.resize(res.configs.size());
    const double t_start = now_s();
    std::fprintf(stderr, "bench_delaunay suite: %d round(s), N scaled by 1/%g, timeout %d s\n",
                 o.rounds, o.scale, o.timeout);
    for (size_t ci = 0; ci < res.configs.size(); ++ci) {
        for (auto &t : o.tools)
            if (tool_fits(t, res.configs[ci].d)) res.cfg_tools[ci].push_back(t);
        res.cfg_tools[ci].push_back("none");
        for (int r = 0; r < o.rounds; ++r) run_round(exe, o, ci, r, res);
    }
    res.t_total = now_s() - t_start;
    return suite_report(o, res);
}
