// bench_delaunay_cgal.cpp — CGAL's runners: the dD Delaunay_triangulation on Epick_d
// (dimension a compile-time tag), and the specialised Delaunay_triangulation_2 and _3 on
// Epick. Input form: a std::vector of CGAL points built from the flat array, which is then
// freed (range insert copies the points again to sort them spatially).
#include "bench_delaunay.h"

#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace
{

template <int D> Timing run_cgal_dd_t(size_t n, std::vector<double> &xyz)
{
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

} // namespace

Timing run_cgal_dd(int d, size_t n, std::vector<double> &xyz)
{
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

Timing run_cgal_2(size_t n, std::vector<double> &xyz)
{
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

Timing run_cgal_3(size_t n, std::vector<double> &xyz)
{
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
