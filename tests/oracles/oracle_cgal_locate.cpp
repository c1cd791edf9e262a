// oracle_cgal_locate: the CGAL reference for lifthull's `locate` command.
//
//   oracle_cgal_locate SITES QUERIES
//
// Reads SITES and QUERIES in Qhull's input format (as oracle_cgal_delaunay does: the dimension
// and the count in either order, then the coordinates; '#' or the first non-numeric token of a
// line starts a comment), d = 2 or 3 for both. Builds CGAL::Delaunay_triangulation_2<Epick>
// (d = 2) or _3 (d = 3) by range insertion with the input index as vertex info, then for each
// query writes one line
//
//   TYPE cell I... sub J... nearest N
//
//   TYPE     CGAL's locate type: VERTEX, EDGE, FACE (2D), FACET (3D), CELL (3D),
//            OUTSIDE_CONVEX_HULL or OUTSIDE_AFFINE_HULL
//   cell I   the sorted input indices of the finite vertices of the face (2D) / cell (3D)
//            that locate returned (fewer than d+1 when it is an infinite one)
//   sub J    the sorted input indices of the sub-face named by li (and lj): the vertex for
//            VERTEX, the two endpoints for EDGE, the three vertices of the facet for FACET,
//            the whole face/cell for FACE/CELL; empty when outside
//   nearest  the input index of nearest_vertex(q) (any one of exactly equally near sites)
//
// Exit status: 0 success, 1 usage or input error. Duplicate sites keep one vertex; which of the
// duplicate indices it carries is unspecified (do not compare on input with duplicates).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
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
  std::cerr << "oracle_cgal_locate: " << msg << "\n";
  std::exit(1);
}

bool parse_number(const std::string &tok, double &out) {
  if (tok.empty()) return false;
  const char *s = tok.c_str();
  char *end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0';
}

// Qhull input format, read as oracle_cgal_delaunay reads it.
PointSet read_points(const char *file) {
  std::ifstream in(file);
  if (!in) die(std::string("cannot open ") + file);
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
  if (nums.size() < 2) die(std::string(file) + ": no dimension/count header");
  double a = nums[0], b = nums[1];
  if (a != static_cast<double>(static_cast<long long>(a)) ||
      b != static_cast<double>(static_cast<long long>(b)) || a < 1 || b < 0)
    die(std::string(file) + ": the first two numbers must be the dimension and the count");
  if (a > b) std::swap(a, b);
  PointSet ps;
  ps.dim = static_cast<int>(a);
  ps.count = static_cast<Index>(b);
  if (ps.dim < 2 || ps.dim > 3) die(std::string(file) + ": dimension must be 2 or 3");
  std::size_t need = ps.count * static_cast<std::size_t>(ps.dim);
  if (nums.size() - 2 != need)
    die(std::string(file) + ": expected " + std::to_string(need) + " coordinates, found " +
        std::to_string(nums.size() - 2));
  ps.coords.assign(nums.begin() + 2, nums.end());
  return ps;
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

void emit(std::string &out, const char *type, std::vector<Index> cell, std::vector<Index> sub,
          Index nearest) {
  std::sort(cell.begin(), cell.end());
  std::sort(sub.begin(), sub.end());
  out += type;
  out += " cell";
  for (Index i : cell) { out += ' '; out += std::to_string(i); }
  out += " sub";
  for (Index i : sub) { out += ' '; out += std::to_string(i); }
  out += " nearest ";
  out += std::to_string(nearest);
  out += '\n';
}

void run_2d(const PointSet &s, const PointSet &q, std::string &out) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
  std::vector<std::pair<K::Point_2, Index>> pts;
  pts.reserve(s.count);
  for (Index i = 0; i < s.count; ++i)
    pts.emplace_back(K::Point_2(s.coords[2 * i], s.coords[2 * i + 1]), i);
  DT dt;
  dt.insert(pts.begin(), pts.end());
  for (Index k = 0; k < q.count; ++k) {
    K::Point_2 p(q.coords[2 * k], q.coords[2 * k + 1]);
    DT::Locate_type lt;
    int li = -1;
    DT::Face_handle f = dt.locate(p, lt, li);
    Index nearest = dt.nearest_vertex(p)->info();
    std::vector<Index> cell, sub;
    if (f != DT::Face_handle())
      for (int i = 0; i < 3; ++i)
        if (f->vertex(i) != DT::Vertex_handle() && !dt.is_infinite(f->vertex(i)))
          cell.push_back(f->vertex(i)->info());
    const char *type = "?";
    switch (lt) {
      case DT::VERTEX:
        type = "VERTEX";
        sub.push_back(f->vertex(li)->info());
        break;
      case DT::EDGE:
        type = "EDGE";
        sub.push_back(f->vertex(DT::ccw(li))->info());
        sub.push_back(f->vertex(DT::cw(li))->info());
        break;
      case DT::FACE:
        type = "FACE";
        sub = cell;
        break;
      case DT::OUTSIDE_CONVEX_HULL: type = "OUTSIDE_CONVEX_HULL"; break;
      case DT::OUTSIDE_AFFINE_HULL: type = "OUTSIDE_AFFINE_HULL"; break;
    }
    emit(out, type, cell, sub, nearest);
  }
}

void run_3d(const PointSet &s, const PointSet &q, std::string &out) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, Index>> pts;
  pts.reserve(s.count);
  for (Index i = 0; i < s.count; ++i)
    pts.emplace_back(K::Point_3(s.coords[3 * i], s.coords[3 * i + 1], s.coords[3 * i + 2]), i);
  DT dt;
  dt.insert(pts.begin(), pts.end());
  for (Index k = 0; k < q.count; ++k) {
    K::Point_3 p(q.coords[3 * k], q.coords[3 * k + 1], q.coords[3 * k + 2]);
    DT::Locate_type lt;
    int li = -1, lj = -1;
    DT::Cell_handle c = dt.locate(p, lt, li, lj);
    Index nearest = dt.nearest_vertex(p)->info();
    std::vector<Index> cell, sub;
    if (c != DT::Cell_handle())
      for (int i = 0; i < 4; ++i)
        if (c->vertex(i) != DT::Vertex_handle() && !dt.is_infinite(c->vertex(i)))
          cell.push_back(c->vertex(i)->info());
    const char *type = "?";
    switch (lt) {
      case DT::VERTEX:
        type = "VERTEX";
        sub.push_back(c->vertex(li)->info());
        break;
      case DT::EDGE:
        type = "EDGE";
        sub.push_back(c->vertex(li)->info());
        sub.push_back(c->vertex(lj)->info());
        break;
      case DT::FACET:
        type = "FACET";
        for (int i = 0; i < 4; ++i)
          if (i != li) sub.push_back(c->vertex(i)->info());
        break;
      case DT::CELL:
        type = "CELL";
        sub = cell;
        break;
      case DT::OUTSIDE_CONVEX_HULL: type = "OUTSIDE_CONVEX_HULL"; break;
      case DT::OUTSIDE_AFFINE_HULL: type = "OUTSIDE_AFFINE_HULL"; break;
    }
    emit(out, type, cell, sub, nearest);
  }
}

}  // namespace

int main(int argc, char **argv) {
  if (argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::cerr << "usage: oracle_cgal_locate SITES QUERIES   (Qhull-format points, d = 2 or 3)\n";
    return 0;
  }
  if (argc != 3) {
    std::cerr << "usage: oracle_cgal_locate SITES QUERIES   (Qhull-format points, d = 2 or 3)\n";
    return 1;
  }
  PointSet s = read_points(argv[1]);
  PointSet q = read_points(argv[2]);
  if (s.dim != q.dim) die("SITES and QUERIES differ in dimension");
  if (s.count == 0) die("no sites");
  std::string out;
  if (s.dim == 2) run_2d(s, q, out);
  else run_3d(s, q, out);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}
