// bench_delaunay_info.cpp — `bench_delaunay info`: the machine and build facts every
// suite report starts with.
#include "bench_delaunay.h"

#include "bench_machine.h"

#include <CGAL/version.h>
#include <Eigen/Core>

#include <cstdio>
#include <string>

#include <sys/utsname.h>
#include <unistd.h>

// The machine and build facts every report starts with: a Markdown list on stdout.
void print_build_facts()
{
    struct utsname un;
    std::string kernel =
        uname(&un) == 0 ? std::string(un.sysname) + " " + un.release + " " + un.machine : "unknown";
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
    std::printf(", Qhull %s (libqhull_r, `%s`)", qhull_version(), kQhullCmd);
#endif
#ifdef LH_BENCH_HAVE_TETGEN
    std::printf(", TetGen 1.5 (libtet, switches `%s`)", kTetgenSwitches);
#endif
    std::printf("\n");
}
