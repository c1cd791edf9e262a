// bench_delaunay_qhull.cpp — Qhull's runner (libqhull_r, as `qdelaunay Qt`), compiled in
// when CMake finds libqhull_r. Input form: the flat array itself (ismalloc False; Qhull
// lifts it into an array of its own).
#include "bench_delaunay.h"

#include <cstdio>
#include <cstring>
#include <vector>

// Qhull last: its headers define macros (True, False) that other headers must not see.
extern "C" {
#include <libqhull_r/qhull_ra.h>
}

const char *qhull_version()
{
    return qh_version;
}

namespace
{

// qh_new_qhull's steps (libqhull_r/user_r.c, Qhull 2020.2) with a clock read between the
// hull (qh_qhull) and qh_prepare_output, which performs the Qt triangulation: qdelaunay's
// 's' summary reports only the first part. Only POD locals here (setjmp/longjmp).
int qhull_steps(qhT *qh, int d, int n, coordT *pts, char *cmd, double *t_hull)
{
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

} // namespace

Timing run_qhull(int d, size_t n, std::vector<double> &xyz, const char *qhull_cmd)
{
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
    FORALLfacets
    {
        if (!facet->upperdelaunay && !facet->visible) ++count;
    }
    t.simplices = count;
    sw.stop(t);
    t.hull_wall = t_hull - sw.w0;
    if (!qh->hasTriangulation)
        std::fprintf(stderr, "qhull: warning: output was not triangulated\n");
    return t; // qh_freeqhull not called (not measured; the process exits)
}
