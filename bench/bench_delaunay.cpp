// bench_delaunay — whole Delaunay triangulations: lifthull next to CGAL (dD, DT2, DT3),
// Qhull (libqhull_r, as qdelaunay Qt) and TetGen, on the same sites.
//
// Three modes:
//
//   bench_delaunay run TOOL D N SEED [--timeout S] [--dist uniform|grid|sphere|clusters|pgrid]
//       Generates the sites (seeded; identical for every tool): by default N sites uniform
//       in [0,1)^D; --dist grid or sphere: an integer grid of about N points or N integer
//       points on one sphere (bench_sites.h). Computes one triangulation in this process
//       and prints one line:
//         TOOL D N seconds=<wall> cpu=<user+sys> simplices=<finite simplices> peak_kb=<peak RSS, KiB>
//           sites=<sites generated>
//       (one line), and for lifthull also the predicate counters of the build
//       (lh_pred_counters): pred_calls= pred_filter= pred_grid= pred_exact= pred_zero=
//       pred_sos_general=.
//       TOOL: lifthull | lifthull_generic | lifthull_t2 (lh_options.threads = 2) | cgal_dd |
//             cgal_2 | cgal_3 | qhull | tetgen | none
//       ("none" only generates the sites: the memory of the input alone). With --dist
//       sphere, Qhull runs with 'Qz' added (it refuses cospherical input without it).
//       The timer starts when the sites are in the tool's input form and stops when the
//       tool has returned its triangulation and its simplex count is known; destruction
//       is not timed. peak_kb is the whole process's peak resident set (libraries, the
//       input, the tool), read after the computation: VmHWM of /proc/self/status, which
//       starts afresh at exec (getrusage's ru_maxrss keeps the spawning parent's peak
//       across fork+exec: a Python driver's 25 MB would hide a small run's own), or
//       ru_maxrss where /proc is missing.
//
//   bench_delaunay suite [--quick] [--rounds R] [--dims 2,3,..] [--tools a,b,..]
//                        [--scale K] [--seed S] [--timeout S]
//       For each (D, N) in (2, 10^6), (3, 10^6), (4, 10^5), (5, 2*10^4) runs every
//       applicable tool R times (default 3; --quick: N/20 and 2 rounds, a smoke run of
//       about 15 s, unless --rounds is given), each run a separate child process
//       ("run" mode of this same executable) so that peak memory belongs to that tool
//       alone. Rounds are interleaved: round r runs every tool once, in an order rotated
//       by r, on the sites of seed S+r. Reports medians, ratios tool/lifthull (so "2.3x"
//       means lifthull took 2.3 times less time), bars, and checks that every tool counted
//       the same number of simplices. Markdown on stdout, progress on stderr.
//
//   bench_delaunay info
//       Prints the machine and build facts the suite's report starts with (Markdown list).
//
// Input forms (what each tool's caller holds while the tool runs, so part of its peak):
//   lifthull  the flat array of n*d doubles (lh_delaunay copies it internally).
//   cgal_*    a std::vector of CGAL points built from the flat array, which is then freed
//             (range insert copies the points again to sort them spatially).
//   qhull     the flat array (ismalloc False; Qhull lifts it into an array of its own).
//   tetgen    tetgenio::pointlist copied from the flat array, which is then freed.
// Qhull runs qh_new_qhull's steps itself, to also report hull_seconds=, its time before the
// Qt triangulation (which qdelaunay's 's' summary leaves out).
//
// Exit status: 0; 1 for usage errors; 2 if a child failed or the exact tools (lifthull,
// CGAL, TetGen) disagree on a simplex count. Qhull's count differing is a warning only
// (it is not exact). Missed bars do not change the exit status: read the report.

#include <lifthull.h>

#include "bench_machine.h"
#include "bench_sites.h"

#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
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
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

// Qhull and TetGen last: their headers define macros (True, False, REAL) that CGAL and
// Eigen must not see.
#ifdef LH_BENCH_HAVE_QHULL
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#endif
#ifdef LH_BENCH_HAVE_TETGEN
#include <tetgen.h>
#endif

extern char **environ;

namespace {

// Qhull options: what qdelaunay runs for "qdelaunay Qt" ('d Qbb' are qdelaunay's own,
// 'Qc' is set by qdelaunay and implies 'Qi'; 'Qt' triangulates). With no output file,
// qh_new_qhull runs qh_prepare_output, which performs the Qt triangulation.
const char *const kQhullCmd = "qhull d Qbb Qt Qc";
// For --dist sphere: Qhull refuses cospherical input under Qbb (QH6019) and advises 'Qz',
// a point at infinity, which qdelaunay users add for such input.
const char *const kQhullCmdCospherical = "qhull d Qbb Qt Qc Qz";
// TetGen switches: Delaunay tetrahedralization of the points (no 'p': no PLC, no
// quality), quiet. Output goes to a tetgenio (library mode writes no files).
const char *const kTetgenSwitches = "Q";

// ---- small utilities ----------------------------------------------------------------

double now_s() {
    using clk = std::chrono::steady_clock;
    return std::chrono::duration<double>(clk::now().time_since_epoch()).count();
}

double cpu_s() {
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec) +
           double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
}

// Peak resident set of this program image, in KiB (see the header comment).
long peak_kb() {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6); // "VmHWM: 1234 kB"
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss; // kilobytes on Linux
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void release(std::vector<double> &v) { std::vector<double>().swap(v); }

struct Timing {
    double wall = 0, cpu = 0;
    double hull_wall = -1; // Qhull only: the time before its Qt/output step
    size_t simplices = 0;
    bool have_counters = false; // lifthull only: its predicate counters
    lh_pred_counters counters{};
};

struct Stopwatch {
    double w0 = now_s(), c0 = cpu_s();
    void stop(Timing &t) const {
        t.wall = now_s() - w0;
        t.cpu = cpu_s() - c0;
    }
};

[[noreturn]] void die(const char *what, const char *msg) {
    std::fprintf(stderr, "bench_delaunay: %s: %s\n", what, msg);
    std::exit(3);
}

// ---- the tools ----------------------------------------------------------------------

Timing run_lifthull(int d, size_t n, std::vector<double> &xyz, bool generic, int threads = 1) {
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

template <int D> Timing run_cgal_dd_t(size_t n, std::vector<double> &xyz) {
    using K = CGAL::Epick_d<CGAL::Dimension_tag<D>>;
    using DT = CGAL::Delaunay_triangulation<K>;
    using P = typename DT::Point;
    std::vector<P> pts;
    pts.reserve(n);
    for (size_t i = 0; i < n; ++i) pts.emplace_back(&xyz[i * D], &xyz[i * D] + D);
    release(xyz);
    Timing t;
    Stopwatch sw;
    auto *dt = new DT(D);
    dt->insert(pts.begin(), pts.end());
    t.simplices = dt->number_of_finite_full_cells();
    sw.stop(t);
    if (dt->current_dimension() != D) die("cgal_dd", "triangulation is not full-dimensional");
    return t; // dt deliberately not destroyed (not measured; the process exits)
}

Timing run_cgal_dd(int d, size_t n, std::vector<double> &xyz) {
    switch (d) {
    case 2: return run_cgal_dd_t<2>(n, xyz);
    case 3: return run_cgal_dd_t<3>(n, xyz);
    case 4: return run_cgal_dd_t<4>(n, xyz);
    case 5: return run_cgal_dd_t<5>(n, xyz);
    case 6: return run_cgal_dd_t<6>(n, xyz);
    default: die("cgal_dd", "dimension must be 2..6");
    }
}

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

Timing run_cgal_2(size_t n, std::vector<double> &xyz) {
    using DT = CGAL::Delaunay_triangulation_2<Epick>;
    std::vector<Epick::Point_2> pts;
    pts.reserve(n);
    for (size_t i = 0; i < n; ++i) pts.emplace_back(xyz[2 * i], xyz[2 * i + 1]);
    release(xyz);
    Timing t;
    Stopwatch sw;
    auto *dt = new DT;
    dt->insert(pts.begin(), pts.end());
    t.simplices = dt->number_of_faces();
    sw.stop(t);
    if (dt->dimension() != 2) die("cgal_2", "triangulation is not 2-dimensional");
    return t; // dt deliberately not destroyed (not measured; the process exits)
}

Timing run_cgal_3(size_t n, std::vector<double> &xyz) {
    using DT = CGAL::Delaunay_triangulation_3<Epick>;
    std::vector<Epick::Point_3> pts;
    pts.reserve(n);
    for (size_t i = 0; i < n; ++i) pts.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    release(xyz);
    Timing t;
    Stopwatch sw;
    auto *dt = new DT;
    dt->insert(pts.begin(), pts.end());
    t.simplices = dt->number_of_finite_cells();
    sw.stop(t);
    if (dt->dimension() != 3) die("cgal_3", "triangulation is not 3-dimensional");
    return t;
}

#ifdef LH_BENCH_HAVE_QHULL
// qh_new_qhull's steps (libqhull_r/user_r.c, Qhull 2020.2) with a clock read between the
// hull (qh_qhull) and qh_prepare_output, which performs the Qt triangulation: qdelaunay's
// 's' summary reports only the first part. Only POD locals here (setjmp/longjmp).
int qhull_steps(qhT *qh, int d, int n, coordT *pts, char *cmd, double *t_hull) {
    qh_zero(qh, stderr);
    qh_meminit(qh, stderr);
    qh_initqhull_start(qh, nullptr, nullptr, stderr);
    int code = setjmp(qh->errexit);
    if (!code) {
        qh->NOerrexit = False;
        qh_initflags(qh, cmd);
        if (qh->DELAUNAY) qh->PROJECTdelaunay = True;
        qh_init_B(qh, pts, n, d, False);
        qh_qhull(qh);
        *t_hull = now_s();
        qh_check_output(qh);
        qh_prepare_output(qh);
    }
    qh->NOerrexit = True;
    return code;
}

Timing run_qhull(int d, size_t n, std::vector<double> &xyz, const char *qhull_cmd) {
    static qhT qh_qh;
    qhT *qh = &qh_qh;
    QHULL_LIB_CHECK
    std::vector<char> cmd(qhull_cmd, qhull_cmd + std::strlen(qhull_cmd) + 1);
    Timing t;
    double t_hull = 0;
    Stopwatch sw;
    if (qhull_steps(qh, d, int(n), xyz.data(), cmd.data(), &t_hull) != 0)
        die("qhull", "Qhull failed");
    size_t count = 0;
    facetT *facet;
    FORALLfacets {
        if (!facet->upperdelaunay && !facet->visible) ++count;
    }
    t.simplices = count;
    sw.stop(t);
    t.hull_wall = t_hull - sw.w0;
    if (!qh->hasTriangulation) std::fprintf(stderr, "qhull: warning: output was not triangulated\n");
    return t; // qh_freeqhull not called (not measured; the process exits)
}
#endif

#ifdef LH_BENCH_HAVE_TETGEN
Timing run_tetgen(size_t n, std::vector<double> &xyz) {
    auto *in = new tetgenio;
    auto *out = new tetgenio;
    in->firstnumber = 0;
    in->numberofpoints = int(n);
    in->pointlist = new REAL[3 * n];
    std::copy(xyz.begin(), xyz.end(), in->pointlist);
    release(xyz);
    std::vector<char> sw_str(kTetgenSwitches, kTetgenSwitches + std::strlen(kTetgenSwitches) + 1);
    Timing t;
    Stopwatch sw;
    tetrahedralize(sw_str.data(), in, out);
    t.simplices = size_t(out->numberoftetrahedra);
    sw.stop(t);
    return t; // in/out deliberately not destroyed
}
#endif

const char *const kAllTools[] = {"lifthull", "lifthull_generic", "lifthull_t2", "cgal_dd", "qhull", "cgal_2", "cgal_3", "tetgen"};

bool tool_built(const std::string &tool) {
#ifndef LH_BENCH_HAVE_QHULL
    if (tool == "qhull") return false;
#endif
#ifndef LH_BENCH_HAVE_TETGEN
    if (tool == "tetgen") return false;
#endif
    (void)tool;
    return true;
}

bool tool_fits(const std::string &tool, int d) {
    if (tool == "lifthull" || tool == "lifthull_generic" || tool == "lifthull_t2")
        return d >= LH_DELAUNAY_MIN_DIM && d <= LH_DELAUNAY_MAX_DIM;
    if (tool == "cgal_dd") return d >= 2 && d <= 6;
    if (tool == "cgal_2") return d == 2;
    if (tool == "cgal_3" || tool == "tetgen") return d == 3;
    if (tool == "qhull") return d >= 2 && d <= 8;
    if (tool == "none") return d >= 1;
    return false;
}

bool tool_exact(const std::string &tool) { return tool != "qhull" && tool != "none"; }

size_t parse_count(const char *s) {
    char *end = nullptr;
    double v = std::strtod(s, &end);
    if (!end || *end || !(v >= 1) || v > 1e10) return 0;
    return size_t(std::llround(v));
}

int cmd_run(int argc, char **argv) {
    // argv: run TOOL D N SEED [--timeout S] [--dist uniform|grid|sphere|clusters|pgrid]
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_delaunay run TOOL D N SEED [--timeout S] "
                             "[--dist uniform|grid|sphere|clusters|pgrid]\n");
        return 1;
    }
    std::string tool = argv[1];
    int d = std::atoi(argv[2]);
    size_t n = parse_count(argv[3]);
    uint64_t seed = std::strtoull(argv[4], nullptr, 0);
    SiteDist dist = SiteDist::uniform;
    for (int i = 5; i < argc; ++i) {
        if (std::string(argv[i]) == "--timeout" && i + 1 < argc) {
            alarm(unsigned(std::max(1, std::atoi(argv[++i])))); // SIGALRM ends the process
        } else if (std::string(argv[i]) == "--dist" && i + 1 < argc) {
            if (!site_dist_parse(argv[++i], &dist)) {
                std::fprintf(stderr, "bench_delaunay run: unknown distribution %s\n", argv[i]);
                return 1;
            }
        } else {
            std::fprintf(stderr, "bench_delaunay run: unknown argument %s\n", argv[i]);
            return 1;
        }
    }
    if (n == 0 || !tool_fits(tool, d)) {
        std::fprintf(stderr, "bench_delaunay run: tool %s does not serve D=%d (or bad N %s)\n",
                     tool.c_str(), d, argv[3]);
        return 1;
    }
    if (!tool_built(tool)) {
        std::fprintf(stderr, "bench_delaunay run: %s was not built in\n", tool.c_str());
        return 1;
    }
    std::vector<double> xyz;
    std::string gen_err;
    if (!site_make(dist, d, n, seed, &xyz, &gen_err)) {
        std::fprintf(stderr, "bench_delaunay run: %s sites: %s\n", site_dist_name(dist),
                     gen_err.c_str());
        return 1;
    }
    const size_t requested = n, sites = xyz.size() / size_t(d); // grid: k^D, not N
    n = sites;
    Timing t;
    if (tool == "lifthull") t = run_lifthull(d, n, xyz, false);
    else if (tool == "lifthull_generic") t = run_lifthull(d, n, xyz, true);
    else if (tool == "lifthull_t2") t = run_lifthull(d, n, xyz, false, 2);
    else if (tool == "cgal_dd") t = run_cgal_dd(d, n, xyz);
    else if (tool == "cgal_2") t = run_cgal_2(n, xyz);
    else if (tool == "cgal_3") t = run_cgal_3(n, xyz);
#ifdef LH_BENCH_HAVE_QHULL
    else if (tool == "qhull")
        t = run_qhull(d, n, xyz, dist == SiteDist::sphere ? kQhullCmdCospherical : kQhullCmd);
#endif
#ifdef LH_BENCH_HAVE_TETGEN
    else if (tool == "tetgen") t = run_tetgen(n, xyz);
#endif
    else if (tool == "none") {
        volatile double sink = xyz.empty() ? 0.0 : xyz.back();
        (void)sink;
    }
    std::printf("%s %d %zu seconds=%.6f cpu=%.6f simplices=%zu peak_kb=%ld sites=%zu", tool.c_str(),
                d, requested, t.wall, t.cpu, t.simplices, peak_kb(), sites);
    if (t.hull_wall >= 0) std::printf(" hull_seconds=%.6f", t.hull_wall);
    if (t.have_counters) {
        const lh_pred_counters &k = t.counters;
        std::printf(" pred_calls=%llu pred_filter=%llu pred_grid=%llu pred_residue=%llu"
                    " pred_exact=%llu pred_zero=%llu pred_sos_general=%llu",
                    (unsigned long long)k.calls, (unsigned long long)k.filter_exits,
                    (unsigned long long)k.grid_exits, (unsigned long long)k.residue_exits,
                    (unsigned long long)k.exact_exits,
                    (unsigned long long)k.zero_results, (unsigned long long)k.sos_general);
    }
    std::printf("\n");
    std::fflush(stdout);
    // Skip destructors: tearing down a million-cell triangulation is not measured and
    // would only lengthen the suite.
    std::_Exit(0);
}

// ---- suite --------------------------------------------------------------------------

struct SuiteOptions {
    int rounds = 3;
    bool quick = false;
    double scale = 1; // divide every N by this
    uint64_t seed = 20240611;
    int timeout = 0; // per child, seconds; 0: default by mode
    std::vector<int> dims = {2, 3, 4, 5};
    std::vector<std::string> tools;
};

struct Sample {
    bool ok = false;
    double wall = NAN, cpu = NAN, hull_wall = NAN;
    size_t simplices = 0;
    long peak_kb = 0;
};

std::string self_exe() {
    char buf[4096];
    ssize_t k = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (k <= 0) return "";
    buf[k] = 0;
    return buf;
}

// Runs `exe run tool d n seed --timeout T` and parses its line.
Sample spawn_run(const std::string &exe, const std::string &tool, int d, size_t n,
                 uint64_t seed, int timeout, std::string &err) {
    Sample s;
    int fd[2];
    if (pipe(fd) != 0) {
        err = "pipe failed";
        return s;
    }
    std::vector<std::string> args = {exe, "run", tool, std::to_string(d), std::to_string(n),
                                     std::to_string(seed), "--timeout", std::to_string(timeout)};
    std::vector<char *> av;
    for (auto &a : args) av.push_back(a.data());
    av.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addclose(&fa, fd[0]);
    posix_spawn_file_actions_adddup2(&fa, fd[1], 1);
    posix_spawn_file_actions_addclose(&fa, fd[1]);
    pid_t pid;
    int rc = posix_spawn(&pid, exe.c_str(), &fa, nullptr, av.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fd[1]);
    if (rc != 0) {
        close(fd[0]);
        err = std::string("posix_spawn: ") + std::strerror(rc);
        return s;
    }
    std::string out;
    char buf[4096];
    for (;;) {
        ssize_t k = read(fd[0], buf, sizeof buf);
        if (k > 0) out.append(buf, size_t(k));
        else if (k == 0 || errno != EINTR) break;
    }
    close(fd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) {
        err = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) +
              (WTERMSIG(status) == SIGALRM ? " (timeout)" : "");
        return s;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        err = "exit status " + std::to_string(WEXITSTATUS(status));
        return s;
    }
    auto field = [&](const char *key, std::string &val) {
        std::string k = std::string(" ") + key + "=";
        size_t p = out.find(k);
        if (p == std::string::npos) return false;
        p += k.size();
        size_t e = out.find_first_of(" \n", p);
        val = out.substr(p, e == std::string::npos ? std::string::npos : e - p);
        return true;
    };
    std::string w, c, sx, pk;
    if (!field("seconds", w) || !field("cpu", c) || !field("simplices", sx) ||
        !field("peak_kb", pk)) {
        err = "unparsable output: " + out;
        return s;
    }
    s.wall = std::atof(w.c_str());
    s.cpu = std::atof(c.c_str());
    s.simplices = size_t(std::strtoull(sx.c_str(), nullptr, 10));
    s.peak_kb = std::atol(pk.c_str());
    std::string hw;
    if (field("hull_seconds", hw)) s.hull_wall = std::atof(hw.c_str());
    s.ok = true;
    return s;
}

std::string fmt_n(size_t n) {
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

std::string fmt_s(double s) {
    char b[32];
    if (std::isnan(s)) return "—";
    if (s >= 100) std::snprintf(b, sizeof b, "%.0f", s);
    else if (s >= 10) std::snprintf(b, sizeof b, "%.1f", s);
    else if (s >= 0.1) std::snprintf(b, sizeof b, "%.2f", s);
    else std::snprintf(b, sizeof b, "%.3f", s);
    return b;
}

std::string fmt_mib(double kb) {
    char b[32];
    if (std::isnan(kb)) return "—";
    double m = kb / 1024.0;
    if (m >= 100) std::snprintf(b, sizeof b, "%.0f", m);
    else std::snprintf(b, sizeof b, "%.1f", m);
    return b;
}

std::string fmt_x(double x) {
    char b[32];
    if (std::isnan(x)) return "—";
    std::snprintf(b, sizeof b, "%.2fx", x);
    return b;
}

std::vector<std::string> split(const std::string &s) {
    std::vector<std::string> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) v.push_back(item);
    return v;
}

void suite_usage() {
    std::fprintf(stderr,
                 "usage: bench_delaunay suite [--quick] [--rounds R] [--dims 2,3,4,5]\n"
                 "                            [--tools lifthull,cgal_dd,...] [--scale K]\n"
                 "                            [--seed S] [--timeout S]\n"
                 "       bench_delaunay run TOOL D N SEED [--timeout S] [--dist uniform|grid|sphere|clusters|pgrid]\n"
                 "       bench_delaunay info   (machine and build facts)\n"
                 "  sizes: (2,10^6) (3,10^6) (4,10^5) (5,2*10^4); --quick divides N by 20 and\n"
                 "  runs 2 rounds (--scale K divides by K); R interleaved rounds (default 3;\n"
                 "  the criterion needs >= 3)\n"
                 "  tools: lifthull lifthull_generic lifthull_t2 cgal_dd qhull cgal_2 cgal_3\n"
                 "  tetgen (none: input only,\n"
                 "  always run); --timeout: per child process (default 1800 s, quick 120 s)\n");
}

// The machine and build facts every report starts with: a Markdown list on stdout.
void print_build_facts() {
    struct utsname un;
    std::string kernel = uname(&un) == 0 ? std::string(un.sysname) + " " + un.release + " " +
                                               un.machine
                                         : "unknown";
    std::printf("- CPU: %s (%ld logical CPUs online), memory %s\n", cpu_model().c_str(),
                sysconf(_SC_NPROCESSORS_ONLN), mem_total().c_str());
    std::printf("- OS: %s\n", kernel.c_str());
    std::printf("- lifthull %s, C compiler: %s, flags: `%s`\n", lh_version_string(),
                LH_BENCH_C_COMPILER, LH_BENCH_C_FLAGS);
    std::printf("- bench C++ compiler: %s, flags: `%s`, build type %s\n", LH_BENCH_CXX_COMPILER,
                LH_BENCH_CXX_FLAGS, LH_BENCH_BUILD_TYPE);
    std::printf("- CGAL %s (Epick, Epick_d<Dimension_tag<D>>), Eigen %d.%d.%d", CGAL_VERSION_STR,
                EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
#ifdef LH_BENCH_HAVE_QHULL
    std::printf(", Qhull %s (libqhull_r, `%s`)", qh_version, kQhullCmd);
#endif
#ifdef LH_BENCH_HAVE_TETGEN
    std::printf(", TetGen 1.5 (libtet, switches `%s`)", kTetgenSwitches);
#endif
    std::printf("\n");
}

struct Config {
    int d;
    size_t n;
};

int cmd_suite(int argc, char **argv) {
    SuiteOptions o;
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
        if (a == "--quick") o.quick = true;
        else if (a == "--rounds") {
            o.rounds = std::atoi(next());
            rounds_given = true;
        }
        else if (a == "--scale") o.scale = std::atof(next());
        else if (a == "--seed") o.seed = std::strtoull(next(), nullptr, 0);
        else if (a == "--timeout") o.timeout = std::atoi(next());
        else if (a == "--dims") {
            o.dims.clear();
            for (auto &s : split(next())) o.dims.push_back(std::atoi(s.c_str()));
        } else if (a == "--tools") o.tools = split(next());
        else {
            suite_usage();
            return 1;
        }
    }
    if (o.rounds < 1 || !(o.scale >= 1)) {
        suite_usage();
        return 1;
    }
    if (o.quick && o.scale == 1) o.scale = 20;
    if (o.quick && !rounds_given) o.rounds = 2; // a smoke run: < 20 s on the 2-core machines
    if (o.timeout <= 0) o.timeout = o.quick ? 120 : 1800;
    if (o.tools.empty())
        for (const char *t : kAllTools) o.tools.push_back(t);
    for (auto &t : o.tools) {
        bool known = false;
        for (const char *k : kAllTools) known |= t == k;
        if (!known) {
            std::fprintf(stderr, "unknown tool %s\n", t.c_str());
            return 1;
        }
    }
    std::vector<std::string> skipped;
    {
        std::vector<std::string> kept;
        for (auto &t : o.tools)
            if (tool_built(t)) kept.push_back(t);
            else skipped.push_back(t);
        o.tools = kept;
    }
    if (std::find(o.tools.begin(), o.tools.end(), "lifthull") == o.tools.end()) {
        std::fprintf(stderr, "--tools must include lifthull (ratios are relative to it)\n");
        return 1;
    }

    const Config base[] = {{2, 1000000}, {3, 1000000}, {4, 100000}, {5, 20000}};
    std::vector<Config> configs;
    for (const Config &c : base)
        if (std::find(o.dims.begin(), o.dims.end(), c.d) != o.dims.end())
            configs.push_back({c.d, size_t(std::llround(double(c.n) / o.scale))});
    if (configs.empty()) {
        std::fprintf(stderr, "no configuration left (--dims takes 2,3,4,5)\n");
        return 1;
    }

    const std::string exe = self_exe();
    if (exe.empty()) {
        std::fprintf(stderr, "cannot find /proc/self/exe\n");
        return 1;
    }

    // results[config][tool] = one Sample per round
    std::vector<std::map<std::string, std::vector<Sample>>> results(configs.size());
    std::vector<std::vector<std::string>> cfg_tools(configs.size());
    std::vector<std::string> failures, exact_mismatch, inexact_mismatch;
    const double t_start = now_s();

    std::fprintf(stderr, "bench_delaunay suite: %d round(s), N scaled by 1/%g, timeout %d s\n",
                 o.rounds, o.scale, o.timeout);
    for (size_t ci = 0; ci < configs.size(); ++ci) {
        const Config &c = configs[ci];
        std::vector<std::string> tools;
        for (auto &t : o.tools)
            if (tool_fits(t, c.d)) tools.push_back(t);
        tools.push_back("none");
        cfg_tools[ci] = tools;
        for (int r = 0; r < o.rounds; ++r) {
            const uint64_t seed = o.seed + uint64_t(r);
            std::vector<std::string> order = tools;
            std::rotate(order.begin(), order.begin() + (size_t(r) % order.size()), order.end());
            std::map<std::string, size_t> counts;
            for (const std::string &t : order) {
                std::string err;
                Sample s = spawn_run(exe, t, c.d, c.n, seed, o.timeout, err);
                results[ci][t].push_back(s);
                if (!s.ok) {
                    char b[512];
                    std::snprintf(b, sizeof b, "D=%d N=%zu round %d %s: %s", c.d, c.n, r,
                                  t.c_str(), err.c_str());
                    failures.push_back(b);
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
                    std::snprintf(b, sizeof b, "D=%d N=%zu seed %llu: %s counted %zu simplices, lifthull %zu",
                                  c.d, c.n, (unsigned long long)seed, t.c_str(), k, ref->second);
                    (tool_exact(t) ? exact_mismatch : inexact_mismatch).push_back(b);
                    std::fprintf(stderr, "  warning: %s\n", b);
                }
        }
    }
    const double t_total = now_s() - t_start;

    // ---- report ----
    print_build_facts();
    for (auto &t : skipped) std::printf("- **%s: not built** (library not found at configure time)\n", t.c_str());
    std::printf("- sites uniform in [0,1)^D (mt19937_64, 53-bit doubles); %d interleaved round(s), "
                "round r on seed %llu+r, every run a separate process; total %.0f s\n",
                o.rounds, (unsigned long long)o.seed, t_total);
    if (o.quick || o.scale != 1)
        std::printf("- **reduced sizes (N divided by %g): a smoke run, not the criterion's "
                    "sizes**\n", o.scale);
    if (o.rounds < 3)
        std::printf("- **fewer than 3 rounds: not the criterion's protocol**\n");
    std::printf("\n");

    auto med_wall = [&](size_t ci, const std::string &t) {
        std::vector<double> v;
        auto it = results[ci].find(t);
        if (it != results[ci].end())
            for (auto &s : it->second)
                if (s.ok) v.push_back(s.wall);
        return median(v);
    };
    auto med_peak = [&](size_t ci, const std::string &t) {
        std::vector<double> v;
        auto it = results[ci].find(t);
        if (it != results[ci].end())
            for (auto &s : it->second)
                if (s.ok) v.push_back(double(s.peak_kb));
        return median(v);
    };
    auto has = [&](size_t ci, const std::string &t) {
        return std::find(cfg_tools[ci].begin(), cfg_tools[ci].end(), t) != cfg_tools[ci].end();
    };

    int bar_fail = 0, bar_pass = 0;
    auto bar = [&](bool applicable, bool pass) -> std::string {
        if (!applicable) return "—";
        (pass ? bar_pass : bar_fail)++;
        return pass ? "PASS" : "**FAIL**";
    };

    std::printf("### Time: median seconds (ratio tool / lifthull; above 1 means lifthull is faster)\n\n");
    std::printf("| D | N | lifthull | lifthull generic engine | CGAL dD | Qhull Qt | CGAL DT2/DT3 | TetGen | "
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
        std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.d, fmt_n(c.n).c_str(),
                    std::isnan(lh) ? "failed" : fmt_s(lh).c_str(), cell("lifthull_generic").c_str(),
                    cell("cgal_dd").c_str(), cell("qhull").c_str(),
                    spec.c_str(), cell("tetgen").c_str(),
                    bar(has(ci, "cgal_dd"), rdd >= 2.0).c_str(), // NaN (a failure): FAIL
                    bar(has(ci, "qhull"), rq >= 3.0).c_str(),
                    bar(has(ci, "cgal_dd") && has(ci, "lifthull_generic"), rg >= 2.0).c_str());
    }

    // The speed issue's bars, for lifthull on two threads (lifthull_t2), the machine's
    // cores: wall time, as every other tool's.
    bool any_t2 = false;
    for (size_t ci = 0; ci < configs.size(); ++ci) any_t2 |= has(ci, "lifthull_t2");
    if (any_t2) {
        std::printf("\n### Two threads: lifthull_t2 (lh_options.threads = 2) against every tool, median "
                    "wall seconds (ratio tool / lifthull_t2), and the speed issue's bars\n\n");
        std::printf("| D | N | lifthull 1 thread | lifthull 2 threads | its CPU s | CGAL dD | Qhull Qt | "
                    "CGAL DT2/DT3 | TetGen | speed issue's bars |\n");
        std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
        for (size_t ci = 0; ci < configs.size(); ++ci) {
            const Config &c = configs[ci];
            if (!has(ci, "lifthull_t2")) continue;
            double t2 = med_wall(ci, "lifthull_t2");
            std::vector<double> cpu;
            for (auto &x : results[ci]["lifthull_t2"])
                if (x.ok) cpu.push_back(x.cpu);
            auto cell = [&](const std::string &t) -> std::string {
                if (!has(ci, t)) return "—";
                double v = med_wall(ci, t);
                return std::isnan(v) ? "failed" : fmt_s(v) + " (" + fmt_x(v / t2) + ")";
            };
            // 2D: 2.5x CGAL DT2; 3D: 2.5x DT3 and 4x TetGen; 4D, 5D: 5x CGAL dD, 10x Qhull.
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
            std::printf("| %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.d, fmt_n(c.n).c_str(),
                        cell("lifthull").c_str(), std::isnan(t2) ? "failed" : fmt_s(t2).c_str(),
                        fmt_s(median(cpu)).c_str(), cell("cgal_dd").c_str(), cell("qhull").c_str(),
                        (c.d == 2 ? cell("cgal_2") : c.d == 3 ? cell("cgal_3") : std::string("—")).c_str(),
                        cell("tetgen").c_str(), bars.empty() ? "—" : bars.c_str());
        }
        std::printf("\n(The lifthull 1 thread column's ratio is its time over lifthull_t2's: the "
                    "speed-up of the second thread. A bar's verdict reads the ratio of the medians; "
                    "beside it, the lowest and highest of the ratios within one round (both tools on "
                    "that round's sites): a bar inside that range is within this machine's "
                    "noise.)\n");
    }

    std::printf("\n### Peak memory: median MiB of the process's maximum RSS (ratio tool / lifthull)\n\n");
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
                    std::isnan(lh) ? "failed" : fmt_mib(lh).c_str(), cell("cgal_dd").c_str(), cell("qhull").c_str(),
                    spec.c_str(), cell("tetgen").c_str(),
                    bar(has(ci, "cgal_dd"), lh < med_peak(ci, "cgal_dd")).c_str(),
                    bar(has(ci, "qhull"), lh < med_peak(ci, "qhull")).c_str(), speed_bar.c_str());
    }

    std::printf("\nBars (engine issue): lifthull >= 2x faster than CGAL dD and >= 3x faster than "
                "Qhull Qt at every size, peak memory below both; and the generic engine alone "
                "(lh_options.generic_engine: the dimension a runtime value) >= 2x faster than "
                "CGAL dD. With lifthull_t2, also the speed issue's time bars (the table above). "
                "%d passed, %d failed%s.\n",
                bar_pass, bar_fail,
                (o.quick || o.scale != 1) ? " (reduced sizes: not the criterion)" : "");

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
                        t == "none" ? "—" : fmt_s(median(cpu)).c_str(), prange.c_str(),
                        sx.c_str(), ok, v.size());
        }
    }

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
            std::printf("| %d | %s | %s | %s | %s |\n", configs[ci].d,
                        fmt_n(configs[ci].n).c_str(), fmt_s(med_wall(ci, "qhull")).c_str(),
                        fmt_s(h).c_str(), fmt_x(h / med_wall(ci, "lifthull")).c_str());
        }
    }

    std::printf("\nWhat the times include: the timer starts when the sites are in the tool's "
                "input form and stops when the triangulation is built and its finite simplices "
                "are counted. lifthull: lh_delaunay (its copy of the input, the triangulation, "
                "neighbours, hull facets, canonical sorted output). CGAL: range insert (spatial "
                "sort + incremental insertion); building the vector of CGAL points is not "
                "timed. Qhull: the steps of qh_new_qhull with `%s` "
                "(lifting, Qbb scaling, hull, Qt triangulation; no output); counted facets are the lower-Delaunay ones. "
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
    if (exact_mismatch.empty() && inexact_mismatch.empty()) {
        std::printf("all agree.\n");
    } else {
        std::printf("**%zu disagreement(s)**\n\n", exact_mismatch.size() + inexact_mismatch.size());
        for (auto &s : exact_mismatch) std::printf("- exact tool: %s\n", s.c_str());
        for (auto &s : inexact_mismatch) std::printf("- warning (Qhull is not exact): %s\n", s.c_str());
    }
    if (!failures.empty()) {
        std::printf("\n**%zu failed run(s):**\n\n", failures.size());
        for (auto &s : failures) std::printf("- %s\n", s.c_str());
    }
    return (!failures.empty() || !exact_mismatch.empty()) ? 2 : 0;
}

} // namespace

int main(int argc, char **argv) {
    if (argc >= 2 && std::string(argv[1]) == "run") return cmd_run(argc - 1, argv + 1);
    if (argc >= 2 && std::string(argv[1]) == "suite") return cmd_suite(argc - 1, argv + 1);
    if (argc == 2 && std::string(argv[1]) == "info") {
        print_build_facts();
        return 0;
    }
    if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
        suite_usage();
        return 0;
    }
    // Bare options (e.g. `bench_delaunay --quick`) mean `suite ...`.
    if (argc == 1 || argv[1][0] == '-') return cmd_suite(argc, argv);
    suite_usage();
    return 1;
}
