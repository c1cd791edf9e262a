// oracle_cgal_delaunay: the CGAL reference for lifthull's `delaunay` command.
//
//   oracle_cgal_delaunay [--dd] [--validate] [--time] FILE|-
//
// Reads points in Qhull's input format (the dimension, the count, then the coordinates;
// comments start at '#' or at the first non-numeric token of a line, so rbox output is read as
// it is; like Qhull, dimension and count may come in either order) and writes the finite
// simplices of the Delaunay triangulation in Qhull's `i` format: a line with the number of
// simplices, then one simplex per line as d+1 space-separated 0-based input indices.
//
//   d = 2: CGAL::Delaunay_triangulation_2<Epick>, vertex info = input index
//   d = 3: CGAL::Delaunay_triangulation_3<Epick>, vertex info = input index
//   --dd (any d in 2..8): CGAL::Delaunay_triangulation<Epick_d<Dynamic_dimension_tag>>,
//          vertex data = input index
//
// All three insert the whole set at once after a spatial sort (Hilbert order), as CGAL's own
// range insertion does. Duplicate points keep one vertex; which of the duplicate indices it
// carries is unspecified (do not compare on input with duplicates).
//
// Exit status: 0 success, 1 usage or input error, 2 triangulation failed validation.
// If the points span less than d dimensions, the output is "0" (no full-dimensional simplex)
// and a warning goes to stderr.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Epick_d.h>
#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Triangulation_data_structure.h>
#include <CGAL/Triangulation_vertex.h>
#include <CGAL/Triangulation_full_cell.h>
#include <CGAL/Spatial_sort_traits_adapter_d.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using Index = std::size_t;

struct PointSet {
  int dim = 0;
  Index count = 0;
  std::vector<double> coords;  // count * dim, row-major
};

[[noreturn]] void die(const std::string &msg) {
  std::cerr << "oracle_cgal_delaunay: " << msg << "\n";
  std::exit(1);
}

// A token is numeric if strtod consumes all of it.
bool parse_number(const std::string &tok, double &out) {
  if (tok.empty()) return false;
  const char *s = tok.c_str();
  char *end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0';
}

// Qhull input format: numbers are read in order; on every line, a '#' or the first token that
// is not a number starts a comment running to the end of the line.
PointSet read_points(std::istream &in) {
  std::vector<double> nums;
  std::string line;
  while (std::getline(in, line)) {
    std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    std::string tok;
    double v;
    while (ls >> tok) {
      if (!parse_number(tok, v)) break;
      nums.push_back(v);
    }
  }
  if (nums.size() < 2) die("input has no dimension/count header");
  double a = nums[0], b = nums[1];
  if (a != static_cast<double>(static_cast<long long>(a)) ||
      b != static_cast<double>(static_cast<long long>(b)) || a < 1 || b < 0)
    die("the first two numbers must be the dimension and the point count");
  // Qhull accepts the two header numbers in either order; a triangulation needs n > d.
  if (a > b) std::swap(a, b);
  PointSet ps;
  ps.dim = static_cast<int>(a);
  ps.count = static_cast<Index>(b);
  if (ps.dim < 2 || ps.dim > 8) die("dimension must be in 2..8, got " + std::to_string(ps.dim));
  std::size_t need = ps.count * static_cast<std::size_t>(ps.dim);
  if (nums.size() - 2 != need)
    die("expected " + std::to_string(need) + " coordinates (" + std::to_string(ps.count) +
        " points of dimension " + std::to_string(ps.dim) + "), found " +
        std::to_string(nums.size() - 2));
  ps.coords.assign(nums.begin() + 2, nums.end());
  return ps;
}

struct Simplices {
  int width = 0;             // d + 1
  std::vector<Index> flat;   // width indices per simplex
};

void write_simplices(const Simplices &s) {
  std::string out;
  std::size_t m = s.width ? s.flat.size() / s.width : 0;
  out.reserve(16 + s.flat.size() * 8);
  out += std::to_string(m);
  out += '\n';
  for (std::size_t i = 0; i < m; ++i) {
    for (int k = 0; k < s.width; ++k) {
      if (k) out += ' ';
      out += std::to_string(s.flat[i * s.width + k]);
    }
    out += '\n';
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

bool run_2d(const PointSet &ps, bool validate, Simplices &out) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
  std::vector<std::pair<K::Point_2, Index>> pts;
  pts.reserve(ps.count);
  for (Index i = 0; i < ps.count; ++i)
    pts.emplace_back(K::Point_2(ps.coords[2 * i], ps.coords[2 * i + 1]), i);
  DT dt;
  dt.insert(pts.begin(), pts.end());  // spatially sorted inside
  if (validate && !dt.is_valid()) return false;
  out.width = 3;
  if (dt.dimension() < 2) return true;
  out.flat.reserve(3 * dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for (int k = 0; k < 3; ++k) out.flat.push_back(f->vertex(k)->info());
  return true;
}

bool run_3d(const PointSet &ps, bool validate, Simplices &out) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, Index>> pts;
  pts.reserve(ps.count);
  for (Index i = 0; i < ps.count; ++i)
    pts.emplace_back(K::Point_3(ps.coords[3 * i], ps.coords[3 * i + 1], ps.coords[3 * i + 2]), i);
  DT dt;
  dt.insert(pts.begin(), pts.end());  // spatially sorted inside
  if (validate && !dt.is_valid()) return false;
  out.width = 4;
  if (dt.dimension() < 3) return true;
  out.flat.reserve(4 * dt.number_of_finite_cells());
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for (int k = 0; k < 4; ++k) out.flat.push_back(c->vertex(k)->info());
  return true;
}

template <class DimTag>
bool run_dd(const PointSet &ps, bool validate, Simplices &out) {
  using Kd = CGAL::Epick_d<DimTag>;
  using Vertex = CGAL::Triangulation_vertex<Kd, Index>;
  using Cell = CGAL::Triangulation_full_cell<Kd>;
  using Tds = CGAL::Triangulation_data_structure<typename Kd::Dimension, Vertex, Cell>;
  using DT = CGAL::Delaunay_triangulation<Kd, Tds>;
  using Point = typename Kd::Point_d;
  const int d = ps.dim;
  std::vector<Point> pts;
  pts.reserve(ps.count);
  for (Index i = 0; i < ps.count; ++i) {
    const double *c = &ps.coords[i * d];
    pts.emplace_back(c, c + d);
  }
  DT dt(d);
  // Same as DT::insert(range): spatial sort, then insert with the previous cell as the hint;
  // sorting indices instead of points lets each new vertex record its input index.
  std::vector<Index> order(ps.count);
  for (Index i = 0; i < ps.count; ++i) order[i] = i;
  using Pmap = typename CGAL::Pointer_property_map<Point>::type;
  using SortTraits = CGAL::Spatial_sort_traits_adapter_d<Kd, Pmap>;
  CGAL::spatial_sort(order.begin(), order.end(),
                     SortTraits(CGAL::make_property_map(pts), dt.geom_traits()));
  typename DT::Full_cell_handle hint;
  for (Index idx : order) {
    std::size_t before = dt.number_of_vertices();
    typename DT::Vertex_handle v = dt.insert(pts[idx], hint);
    if (dt.number_of_vertices() != before) v->data() = idx;  // a duplicate keeps its first index
    hint = v->full_cell();
  }
  if (validate && !dt.is_valid()) return false;
  out.width = d + 1;
  if (dt.current_dimension() < d) return true;
  out.flat.reserve(static_cast<std::size_t>(d + 1) * dt.number_of_finite_full_cells());
  for (auto c = dt.full_cells_begin(); c != dt.full_cells_end(); ++c) {
    if (dt.is_infinite(c)) continue;
    for (int k = 0; k <= d; ++k) out.flat.push_back(c->vertex(k)->data());
  }
  return true;
}

void usage() {
  std::cerr << "usage: oracle_cgal_delaunay [--dd] [--validate] [--time] FILE|-\n"
               "  reads Qhull-format points, prints the Delaunay simplices in Qhull 'i' format\n"
               "  --dd        use the dD Delaunay_triangulation (Epick_d) for any d in 2..8\n"
               "              (default: Delaunay_triangulation_2/_3; d >= 4 requires --dd)\n"
               "  --validate  run CGAL's is_valid() on the result (exit 2 if it fails)\n"
               "  --time      print the construction time to stderr\n";
}

}  // namespace

int main(int argc, char **argv) {
  bool dd = false, validate = false, timing = false;
  const char *file = nullptr;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--dd") dd = true;
    else if (a == "--validate") validate = true;
    else if (a == "--time") timing = true;
    else if (a == "-h" || a == "--help") { usage(); return 0; }
    else if (a.size() > 1 && a[0] == '-') { usage(); return 1; }
    else if (!file) file = argv[i];
    else { usage(); return 1; }
  }
  if (!file) { usage(); return 1; }

  PointSet ps;
  if (std::strcmp(file, "-") == 0) {
    ps = read_points(std::cin);
  } else {
    std::ifstream in(file);
    if (!in) die(std::string("cannot open ") + file);
    ps = read_points(in);
  }
  if (!dd && ps.dim > 3) die("d = " + std::to_string(ps.dim) + " needs --dd");

  Simplices s;
  auto t0 = std::chrono::steady_clock::now();
  bool ok;
  if (dd) ok = run_dd<CGAL::Dynamic_dimension_tag>(ps, validate, s);
  else if (ps.dim == 2) ok = run_2d(ps, validate, s);
  else ok = run_3d(ps, validate, s);
  auto t1 = std::chrono::steady_clock::now();
  if (!ok) {
    std::cerr << "oracle_cgal_delaunay: CGAL triangulation failed is_valid()\n";
    return 2;
  }
  if (s.flat.empty() && ps.count > 0)
    std::cerr << "oracle_cgal_delaunay: warning: the points do not span " << ps.dim
              << " dimensions; no full-dimensional simplex\n";
  if (timing)
    std::cerr << "oracle_cgal_delaunay: " << (dd ? "dD" : (ps.dim == 2 ? "DT2" : "DT3"))
              << " d=" << ps.dim << " n=" << ps.count << " simplices="
              << (s.width ? s.flat.size() / s.width : 0) << " time="
              << std::chrono::duration<double>(t1 - t0).count() << " s\n";
  write_simplices(s);
  return 0;
}
