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
//
// Files: this one (main), bench_delaunay.h (what the others share), _run.cpp (the `run`
// mode), _tools.cpp (the tool table, the dispatch and lifthull's runner), _cgal.cpp,
// _qhull.cpp, _tetgen.cpp (the other runners), _suite.cpp (the suite's options and
// rounds), _spawn.cpp (its child processes), _report.cpp (its Markdown report),
// _info.cpp (the machine and build facts); bench_sites.cpp (the site distributions).

#include "bench_delaunay.h"

#include <string>

int main(int argc, char **argv)
{
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
