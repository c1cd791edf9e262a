// bench_delaunay.h — what the files of bench_delaunay share (bench_delaunay.cpp describes
// the program): the tools and their table, one timed run, the `run` and `suite` modes,
// the suite's options and results, and its Markdown report.
#ifndef LH_BENCH_DELAUNAY_H
#define LH_BENCH_DELAUNAY_H

#include <lifthull.h>

#include "bench_sites.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

// Qhull options: what qdelaunay runs for "qdelaunay Qt" ('d Qbb' are qdelaunay's own,
// 'Qc' is set by qdelaunay and implies 'Qi'; 'Qt' triangulates). With no output file,
// qh_new_qhull runs qh_prepare_output, which performs the Qt triangulation.
inline constexpr const char *kQhullCmd = "qhull d Qbb Qt Qc";
// For --dist sphere: Qhull refuses cospherical input under Qbb (QH6019) and advises 'Qz',
// a point at infinity, which qdelaunay users add for such input.
inline constexpr const char *kQhullCmdCospherical = "qhull d Qbb Qt Qc Qz";
// TetGen switches: Delaunay tetrahedralization of the points (no 'p': no PLC, no
// quality), quiet. Output goes to a tetgenio (library mode writes no files).
inline constexpr const char *kTetgenSwitches = "Q";

// ---- the tools (bench_delaunay_tools.cpp) --------------------------------------------

// One tool's run on one site set.
struct Timing {
    double wall = 0, cpu = 0;
    double hull_wall = -1; // Qhull only: the time before its Qt/output step
    size_t simplices = 0;
    bool have_counters = false; // lifthull only: its predicate counters
    lh_pred_counters counters{};
};

inline constexpr const char *kAllTools[] = {
    "lifthull", "lifthull_generic", "lifthull_t2", "cgal_dd",
    "qhull",    "cgal_2",           "cgal_3",      "tetgen"};

double now_s(); // a steady clock, seconds
double cpu_s(); // this process's user + system CPU seconds

// Times a tool: from construction (the sites in the tool's input form) to stop().
struct Stopwatch {
    double w0 = now_s(), c0 = cpu_s();
    void stop(Timing &t) const
    {
        t.wall = now_s() - w0;
        t.cpu = cpu_s() - c0;
    }
};

inline void release(std::vector<double> &v)
{
    std::vector<double>().swap(v);
}
[[noreturn]] void die(const char *what, const char *msg); // exit status 3

// The runners, one per library; each frees xyz once its input form is built (lifthull
// and Qhull read it in place).
Timing run_lifthull(int d, size_t n, std::vector<double> &xyz, bool generic, int threads = 1);
Timing run_cgal_dd(int d, size_t n, std::vector<double> &xyz); // bench_delaunay_cgal.cpp
Timing run_cgal_2(size_t n, std::vector<double> &xyz);
Timing run_cgal_3(size_t n, std::vector<double> &xyz);
#ifdef LH_BENCH_HAVE_QHULL
Timing run_qhull(int d, size_t n, std::vector<double> &xyz, const char *qhull_cmd);
const char *qhull_version(); // bench_delaunay_qhull.cpp
#endif
#ifdef LH_BENCH_HAVE_TETGEN
Timing run_tetgen(size_t n, std::vector<double> &xyz); // bench_delaunay_tetgen.cpp
#endif

bool tool_built(const std::string &tool); // its library was found at configure time
bool tool_fits(const std::string &tool, int d);
bool tool_exact(const std::string &tool); // its simplex count must equal lifthull's

// Runs TOOL (tool_fits and tool_built) on the n sites xyz, which it may free; "none"
// only reads them.
Timing tool_run(const std::string &tool, int d, size_t n, std::vector<double> &xyz, SiteDist dist);

// ---- the modes -------------------------------------------------------------------------

int cmd_run(int argc, char **argv);   // bench_delaunay_run.cpp
int cmd_suite(int argc, char **argv); // bench_delaunay_suite.cpp
void suite_usage();                   // bench_delaunay_suite.cpp
void print_build_facts();             // bench_delaunay_info.cpp

// ---- the suite (bench_delaunay_suite.cpp, _spawn.cpp, _report.cpp) -------------------

struct SuiteOptions {
    int rounds = 3;
    bool quick = false;
    double scale = 1; // divide every N by this
    uint64_t seed = 20240611;
    int timeout = 0; // per child, seconds; 0: default by mode
    std::vector<int> dims = {2, 3, 4, 5};
    std::vector<std::string> tools;
};

// One child run, parsed from its line.
struct Sample {
    bool ok = false;
    double wall = NAN, cpu = NAN, hull_wall = NAN;
    size_t simplices = 0;
    long peak_kb = 0;
};

struct Config {
    int d;
    size_t n;
};

// Everything the report reads.
struct SuiteResults {
    std::vector<Config> configs;
    std::vector<std::vector<std::string>> cfg_tools; // the tools run per config, "none" last
    // results[config][tool] = one Sample per round
    std::vector<std::map<std::string, std::vector<Sample>>> results;
    std::vector<std::string> skipped; // asked for but not built
    std::vector<std::string> failures, exact_mismatch, inexact_mismatch;
    double t_total = 0;
};

std::string self_exe(); // this executable's path; "" if /proc/self/exe is missing
// Runs `exe run tool d n seed --timeout T` and parses its line; on failure sets err.
Sample spawn_run(const std::string &exe, const std::string &tool, int d, size_t n, uint64_t seed,
                 int timeout, std::string &err);

// The Markdown report on stdout; returns the exit status (2 if a run failed or the
// exact tools disagree, else 0).
int suite_report(const SuiteOptions &o, SuiteResults &res);

#endif
