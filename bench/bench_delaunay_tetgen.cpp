// bench_delaunay_tetgen.cpp — TetGen's runner (libtet, tetrahedralize with the switches
// kTetgenSwitches), compiled in when CMake finds tetgen.h and libtet. Input form:
// tetgenio::pointlist copied from the flat array, which is then freed.
#include "bench_delaunay.h"

#include <algorithm>
#include <cstring>
#include <vector>

// TetGen last: its header defines REAL.
#include <tetgen.h>

Timing run_tetgen(size_t n, std::vector<double> &xyz)
{
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
