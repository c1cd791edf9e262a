// bench_delaunay_run.cpp — `bench_delaunay run TOOL D N SEED [--timeout S] [--dist ...]`:
// generates the sites, runs one tool on them in this process and prints one line
// (bench_delaunay.cpp describes it), which the suite's parent process parses.
#include "bench_delaunay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace
{

// Peak resident set of this program image, in KiB (see bench_delaunay.cpp).
long peak_kb()
{
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6); // "VmHWM: 1234 kB"
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss; // kilobytes on Linux
}

size_t parse_count(const char *s)
{
    char *end = nullptr;
    double v = std::strtod(s, &end);
    if (!end || *end || !(v >= 1) || v > 1e10) return 0;
    return size_t(std::llround(v));
}

struct RunArgs {
    std::string tool;
    int d = 0;
    size_t n = 0;
    uint64_t seed = 0;
    SiteDist dist = SiteDist::uniform;
};

// argv: run TOOL D N SEED [--timeout S] [--dist uniform|grid|sphere|clusters|pgrid].
// --timeout arms the alarm at once (SIGALRM ends the process). False after a message.
bool parse_run_args(int argc, char **argv, RunArgs *a)
{
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_delaunay run TOOL D N SEED [--timeout S] "
                             "[--dist uniform|grid|sphere|clusters|pgrid]\n");
        return false;
    }
    a->tool = argv[1];
    a->d = std::atoi(argv[2]);
    a->n = parse_count(argv[3]);
    a->seed = std::strtoull(argv[4], nullptr, 0);
    for (int i = 5; i < argc; ++i) {
        if (std::string(argv[i]) == "--timeout" && i + 1 < argc) {
            alarm(unsigned(std::max(1, std::atoi(argv[++i])))); // SIGALRM ends the process
        } else if (std::string(argv[i]) == "--dist" && i + 1 < argc) {
            if (!site_dist_parse(argv[++i], &a->dist)) {
                std::fprintf(stderr, "bench_delaunay run: unknown distribution %s\n", argv[i]);
                return false;
            }
        } else {
            std::fprintf(stderr, "bench_delaunay run: unknown argument %s\n", argv[i]);
            return false;
        }
    }
    if (a->n == 0 || !tool_fits(a->tool, a->d)) {
        std::fprintf(stderr, "bench_delaunay run: tool %s does not serve D=%d (or bad N %s)\n",
                     a->tool.c_str(), a->d, argv[3]);
        return false;
    }
    if (!tool_built(a->tool)) {
        std::fprintf(stderr, "bench_delaunay run: %s was not built in\n", a->tool.c_str());
        return false;
    }
    return true;
}

void print_run_line(const RunArgs &a, const Timing &t, size_t sites)
{
    std::printf("%s %d %zu seconds=%.6f cpu=%.6f simplices=%zu peak_kb=%ld sites=%zu",
                a.tool.c_str(), a.d, a.n, t.wall, t.cpu, t.simplices, peak_kb(), sites);
    if (t.hull_wall >= 0) std::printf(" hull_seconds=%.6f", t.hull_wall);
    if (t.have_counters) {
        const lh_pred_counters &k = t.counters;
        std::printf(" pred_calls=%llu pred_filter=%llu pred_grid=%llu pred_residue=%llu"
                    " pred_exact=%llu pred_zero=%llu pred_sos_general=%llu",
                    (unsigned long long)k.calls, (unsigned long long)k.filter_exits,
                    (unsigned long long)k.grid_exits, (unsigned long long)k.residue_exits,
                    (unsigned long long)k.exact_exits, (unsigned long long)k.zero_results,
                    (unsigned long long)k.sos_general);
    }
    std::printf("\n");
}

} // namespace

int cmd_run(int argc, char **argv)
{
    RunArgs a;
    if (!parse_run_args(argc, argv, &a)) return 1;
    std::vector<double> xyz;
    std::string gen_err;
    if (!site_make(a.dist, a.d, a.n, a.seed, &xyz, &gen_err)) {
        std::fprintf(stderr, "bench_delaunay run: %s sites: %s\n", site_dist_name(a.dist),
                     gen_err.c_str());
        return 1;
    }
    const size_t sites = xyz.size() / size_t(a.d); // grid: k^D, not N
    const Timing t = tool_run(a.tool, a.d, sites, xyz, a.dist);
    print_run_line(a, t, sites); // N as requested, sites as generated
    std::fflush(stdout);
    // Skip destructors: tearing down a million-cell triangulation is not measured and
    // would only lengthen the suite.
    std::_Exit(0);
}
