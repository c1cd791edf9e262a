// bench_delaunay_tools.cpp — the tool table (which tool serves which dimension, which
// are exact, which were built), the clocks, lifthull's runner and the dispatch of
// `run TOOL` to the runner of each library.
#include "bench_delaunay.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>
#include <sys/time.h>

double now_s()
{
    using clk = std::chrono::steady_clock;
    return std::chrono::duration<double>(clk::now().time_since_epoch()).count();
}

double cpu_s()
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec) +
           double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
}

[[noreturn]] void die(const char *what, const char *msg)
{
    std::fprintf(stderr, "bench_delaunay: %s: %s\n", what, msg);
    std::exit(3);
}

Timing run_lifthull(int d, size_t n, std::vector<double> &xyz, bool generic, int threads)
{
    lh_options opt;
    lh_options_default(&opt);
    opt.generic_engine = generic; // the runtime-d engine (same output, for comparison)
    opt.threads = threads;        // lifthull_t2: two threads (same output)
    lh_tri *tri = nullptr;
    Timing t;
    Stopwatch sw;
    lh_status st = lh_delaunay(d, n, xyz.data(), &opt, &tri);
    if (st != LH_OK) die("lh_delaunay", lh_status_message(st));
    t.simplices = lh_tri_count(tri);
    sw.stop(t);
    lh_tri_pred_counters_get(tri, &t.counters);
    t.have_counters = true;
    lh_tri_free(tri);
    return t;
}

bool tool_built(const std::string &tool)
{
#ifndef LH_BENCH_HAVE_QHULL
    if (tool == "qhull") return false;
#endif
#ifndef LH_BENCH_HAVE_TETGEN
    if (tool == "tetgen") return false;
#endif
    (void)tool;
    return true;
}

bool tool_fits(const std::string &tool, int d)
{
    if (tool == "lifthull" || tool == "lifthull_generic" || tool == "lifthull_t2")
        return d >= LH_DELAUNAY_MIN_DIM && d <= LH_DELAUNAY_MAX_DIM;
    if (tool == "cgal_dd") return d >= 2 && d <= 6;
    if (tool == "cgal_2") return d == 2;
    if (tool == "cgal_3" || tool == "tetgen") return d == 3;
    if (tool == "qhull") return d >= 2 && d <= 8;
    if (tool == "none") return d >= 1;
    return false;
}

bool tool_exact(const std::string &tool)
{
    return tool != "qhull" && tool != "none";
}

Timing tool_run(const std::string &tool, int d, size_t n, std::vector<double> &xyz, SiteDist dist)
{
    Timing t;
    if (tool == "lifthull")
        t = run_lifthull(d, n, xyz, false);
    else if (tool == "lifthull_generic")
        t = run_lifthull(d, n, xyz, true);
    else if (tool == "lifthull_t2")
        t = run_lifthull(d, n, xyz, false, 2);
    else if (tool == "cgal_dd")
        t = run_cgal_dd(d, n, xyz);
    else if (tool == "cgal_2")
        t = run_cgal_2(n, xyz);
    else if (tool == "cgal_3")
        t = run_cgal_3(n, xyz);
#ifdef LH_BENCH_HAVE_QHULL
    else if (tool == "qhull")
        t = run_qhull(d, n, xyz, dist == SiteDist::sphere ? kQhullCmdCospherical : kQhullCmd);
#endif
#ifdef LH_BENCH_HAVE_TETGEN
    else if (tool == "tetgen")
        t = run_tetgen(n, xyz);
#endif
    else if (tool == "none") {
        volatile double sink = xyz.empty() ? 0.0 : xyz.back();
        (void)sink;
    }
    (void)dist;
    return t;
}
