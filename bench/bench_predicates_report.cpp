// bench_predicates_report.cpp — bench_predicates' Markdown report on stdout: the machine
// and build facts, the ns-per-call table with its bars, the details, the sign convention
// and the sign check.
#include "bench_predicates.h"

#include "bench_machine.h"

#include <CGAL/version.h>
#include <Eigen/Core>

#include <cstdio>
#include <string>
#include <vector>

#include <sys/utsname.h>
#include <unistd.h>

namespace
{

std::string fmt_frac(double x)
{
    char b[32];
    if (x > 0 && x < 1e-4)
        std::snprintf(b, sizeof b, "%.1e", x);
    else
        std::snprintf(b, sizeof b, "%.4f", x);
    return b;
}

void print_facts(const Session &s)
{
    struct utsname un;
    std::string kernel =
        uname(&un) == 0 ? std::string(un.sysname) + " " + un.release + " " + un.machine : "unknown";
    std::printf("- CPU: %s (%ld logical CPUs online)\n", cpu_model().c_str(),
                sysconf(_SC_NPROCESSORS_ONLN));
    std::printf("- OS: %s\n", kernel.c_str());
    std::printf("- lifthull %s, C compiler: %s, flags: `%s`\n", lh_version_string(),
                LH_BENCH_C_COMPILER, LH_BENCH_C_FLAGS);
    std::printf("- bench C++ compiler: %s (`__VERSION__` %s), flags: `%s`, build type %s\n",
                LH_BENCH_CXX_COMPILER, __VERSION__, LH_BENCH_CXX_FLAGS, LH_BENCH_BUILD_TYPE);
    std::printf("- CGAL %s (CGAL_VERSION_NR %lld), Eigen %d.%d.%d\n", CGAL_VERSION_STR,
                static_cast<long long>(CGAL_VERSION_NR), EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
                EIGEN_MINOR_VERSION);
    std::printf("- pool: 2^%d = %zu tuples per (predicate, input); %d interleaved rounds per "
                "side, each >= %.0f ms; seed %llu\n",
                s.opt.log2n, size_t(1) << s.opt.log2n, s.opt.rounds, s.opt.min_ms,
                static_cast<unsigned long long>(s.opt.seed));
    std::printf("\n");
}

// The main table and the bars' line.
void print_table(const std::vector<Row> &rows)
{
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
        std::printf("| %s | %s | %.1f | %.1f | %.2f | %s | %s |\n", r.pred.c_str(), r.input.c_str(),
                    r.lh_ns, r.cg_ns, ratio, fmt_frac(r.exact_frac).c_str(), bar.c_str());
    }
    std::printf("\nBars: random input, ratio <= 1.3 for orient_2, orient_3, insphere_2, "
                "insphere_3, insphere_4; near-degenerate insphere_3, ratio <= 3. "
                "%d bar(s) missed.\n",
                fails);
}

void print_details(const Session &s, const std::vector<Row> &rows)
{
    std::printf("\n### Details\n\n");
    std::printf("| predicate | input | CGAL functor | lifthull min..max ns | CGAL min..max ns | "
                "CGAL out-of-line ns | passes/round L, C | exact zeros | sign factor | "
                "disagreements | checksum L, C |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row &r : rows) {
        char ool[32] = "—";
        if (s.opt.ool) std::snprintf(ool, sizeof ool, "%.1f", r.ool_ns);
        std::printf("| %s | %s | %s | %.1f..%.1f | %.1f..%.1f | %s | %d, %d | %s | %+d | %zu | "
                    "%ld, %ld |\n",
                    r.pred.c_str(), r.input.c_str(), r.cgal_name.c_str(), r.lh_min, r.lh_max,
                    r.cg_min, r.cg_max, ool, r.lh_reps, r.cg_reps, fmt_frac(r.zero_frac).c_str(),
                    r.factor, r.disagreements, r.lh_sum, r.cg_sum);
    }

    std::printf("\nSign convention: lifthull sign = factor × CGAL sign, one factor per predicate, "
                "fixed from the first tuple where both signs are nonzero:");
    for (int d = 2; d <= 4; ++d) std::printf(" orient_%d %+d;", d, s.factor.orient[d]);
    for (int d = 2; d <= 4; ++d)
        std::printf(" insphere_%d %+d%s", d, s.factor.insphere[d], d < 4 ? ";" : ".\n");
}

} // namespace

int print_report(const Session &s, const std::vector<Row> &rows)
{
    print_facts(s);
    print_table(rows);
    print_details(s, rows);

    size_t total_dis = 0;
    for (const Row &r : rows) total_dis += r.disagreements;
    if (total_dis == 0) {
        std::printf("\nSign agreement: all %zu tuples agree (after the factor).\n",
                    rows.size() * (size_t(1) << s.opt.log2n));
    } else {
        std::printf("\n**Sign disagreements: %zu** (first %d per row shown):\n\n```\n", total_dis,
                    s.opt.max_print);
        for (const std::string &d : s.disagreement_log) std::printf("%s", d.c_str());
        std::printf("```\n");
    }
    for (const std::string &w : s.counter_warnings) std::printf("\nWarning: %s", w.c_str());
    std::printf("\n(checksum sink %ld)\n", static_cast<long>(s.sink));
    return total_dis ? 2 : 0;
}
