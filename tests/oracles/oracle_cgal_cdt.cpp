// oracle_cgal_cdt: the CGAL reference for lifthull's 2D meshing (issue #7).
//
//   oracle_cgal_cdt cdt  [--convex] [--time] [--write BASE] [--poly OUT] FILE
//   oracle_cgal_cdt mesh [--convex] [--size S] [--bound B] [--time] [--write BASE] FILE
//
// FILE is a Triangle .poly (its vertices, or FILE.node beside it when the .poly lists none;
// segments; holes), a JSON ring file in the earcut fixtures' format ([[[x,y],...], hole
// rings...]; each ring closed implicitly, a repeated first point dropped, a one-point ring an
// isolated vertex) or a CGAL .edg segment file (a count, then x1 y1 x2 y2 a line).
//
// cdt: CGAL::Constrained_Delaunay_triangulation_2<Epick, Default,
//      No_constraint_intersection_requiring_constructions_tag> of the vertices and segments,
//      restricted to the domain, printed one triangle a line as its three input vertex
//      indices (0-based, in the order the file lists the vertices; a duplicated point gets
//      its first index), each line sorted, the lines sorted: two runs compare with diff.
// mesh: CGAL::Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2(B, S) (B = 0.125 by
//      default: sin^2 of the smallest angle >= B, i.e. 20.7 degrees; S = 0 no size bound,
//      else an upper bound on the edge length) on that domain; prints
//        triangles N
//        vertices V
//        min_angle A      (degrees, over the triangles in the domain)
//
// The domain: for a .poly, Triangle's rule — triangles reachable from the outside of the
// convex hull or from a hole point without crossing a segment are removed (--convex, Triangle's
// -c, makes the convex hull's edges segments); for rings and .edg files, the even-odd rule
// (triangles whose nesting level, the number of constraints crossed from the outside, is odd).
//
// --write BASE writes the triangles of the domain as Triangle files BASE.node / BASE.ele
// (0-based, every input vertex in input order, then the mesher's new vertices).
// --poly OUT (cdt mode) writes the input as a Triangle .poly (1-based) whose hole points make
// Triangle's rule give this domain: one point (a triangle's centroid, checked to lie inside it)
// in each connected set of triangles outside the domain that the outside does not reach.
// --time prints the CGAL time (construction, domain, refinement; not the reading) to stderr.
//
// Exit status: 0 success, 1 usage or input error, 3 the segments cross (CGAL's
// Intersection_of_constraints_exception: the tag forbids constructing intersection points).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using Index = std::size_t;
constexpr Index kNone = static_cast<Index>(-1);

[[noreturn]] void die(const std::string &msg) {
  std::cerr << "oracle_cgal_cdt: " << msg << "\n";
  std::exit(1);
}

struct Pslg {
  std::vector<std::array<double, 2>> pts;
  std::vector<std::array<Index, 2>> segs;
  std::vector<std::array<double, 2>> holes;
  bool even_odd = false;  // rings / .edg: even-odd domain; .poly: Triangle's flood from outside + holes
};

bool ends_with(const std::string &s, const std::string &suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die("cannot open " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---- Triangle's .node / .poly: numbers on non-blank lines, '#' starts a comment ------------

struct Lines {
  std::string name;
  std::vector<std::vector<std::string>> rows;
  std::size_t next = 0;
  explicit Lines(const std::string &path) : name(path) {
    std::istringstream in(slurp(path));
    std::string line;
    while (std::getline(in, line)) {
      std::size_t h = line.find('#');
      if (h != std::string::npos) line.resize(h);
      std::istringstream ls(line);
      std::vector<std::string> toks;
      std::string t;
      while (ls >> t) toks.push_back(t);
      if (!toks.empty()) rows.push_back(toks);
    }
  }
  const std::vector<std::string> &row() {
    if (next >= rows.size()) die(name + ": unexpected end of file");
    return rows[next++];
  }
  bool done() const { return next >= rows.size(); }
};

double num(const std::vector<std::string> &r, std::size_t k, const std::string &what) {
  if (k >= r.size()) die("missing " + what);
  char *end = nullptr;
  double v = std::strtod(r[k].c_str(), &end);
  if (end == r[k].c_str()) die("not a number: " + r[k] + " (" + what + ")");
  return v;
}
long inum(const std::vector<std::string> &r, std::size_t k, const std::string &what, long dflt) {
  if (k >= r.size()) return dflt;
  char *end = nullptr;
  long v = std::strtol(r[k].c_str(), &end, 0);
  if (end == r[k].c_str()) die("not an integer: " + r[k] + " (" + what + ")");
  return v;
}

// Reads the vertex block whose header row was just read; returns the numbering base.
long read_vertices(Lines &L, const std::vector<std::string> &hdr, Pslg &g) {
  long n = inum(hdr, 0, "vertex count", 0);
  long dim = inum(hdr, 1, "dimension", 2);
  long nattr = inum(hdr, 2, "attribute count", 0);
  if (dim != 2) die(L.name + ": dimension must be 2");
  (void)nattr;
  long base = 1;
  for (long i = 0; i < n; ++i) {
    const auto &r = L.row();
    if (i == 0) {
      long first = inum(r, 0, "vertex number", 1);
      if (first == 0 || first == 1) base = first;
    }
    g.pts.push_back({num(r, 1, "x"), num(r, 2, "y")});
  }
  return base;
}

Pslg read_poly(const std::string &path) {
  Pslg g;
  Lines L(path);
  auto hdr = L.row();
  long base;
  if (inum(hdr, 0, "vertex count", 0) > 0) {
    base = read_vertices(L, hdr, g);
  } else {
    Lines N(path.substr(0, path.size() - 5) + ".node");
    auto nh = N.row();
    base = read_vertices(N, nh, g);
  }
  const auto &sh = L.row();
  long ns = inum(sh, 0, "segment count", 0);
  for (long i = 0; i < ns; ++i) {
    const auto &r = L.row();
    long a = inum(r, 1, "segment endpoint", -1) - base, b = inum(r, 2, "segment endpoint", -1) - base;
    long n = static_cast<long>(g.pts.size());
    if (a < 0 || b < 0 || a >= n || b >= n) die(path + ": segment " + std::to_string(i + base) + " has an endpoint out of range");
    if (a != b) g.segs.push_back({static_cast<Index>(a), static_cast<Index>(b)});
  }
  if (!L.done()) {
    long nh = inum(L.row(), 0, "hole count", 0);
    for (long i = 0; i < nh; ++i) {
      const auto &r = L.row();
      g.holes.push_back({num(r, 1, "hole x"), num(r, 2, "hole y")});
    }
  }
  return g;
}

// ---- JSON rings: [[[x,y],...],...] ------------------------------------------------------

struct Json {
  const std::string &s;
  std::size_t i = 0;
  explicit Json(const std::string &t) : s(t) {}
  void ws() { while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i; }
  bool eat(char c) { ws(); if (i < s.size() && s[i] == c) { ++i; return true; } return false; }
  void need(char c) { if (!eat(c)) die(std::string("JSON: expected '") + c + "' at byte " + std::to_string(i)); }
  double number() {
    ws();
    const char *p = s.c_str() + i;
    char *end = nullptr;
    double v = std::strtod(p, &end);
    if (end == p) die("JSON: expected a number at byte " + std::to_string(i));
    i += static_cast<std::size_t>(end - p);
    return v;
  }
};

Pslg read_rings(const std::string &path) {
  std::string text = slurp(path);
  Json j(text);
  Pslg g;
  g.even_odd = true;
  j.need('[');
  if (!j.eat(']')) {
    do {
      j.need('[');
      std::vector<std::array<double, 2>> ring;
      if (!j.eat(']')) {
        do {
          j.need('[');
          double x = j.number();
          j.need(',');
          double y = j.number();
          while (j.eat(',')) j.number();  // ignore any further coordinates
          j.need(']');
          ring.push_back({x, y});
        } while (j.eat(','));
        j.need(']');
      }
      if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      Index first = g.pts.size();
      for (const auto &p : ring) g.pts.push_back(p);
      Index m = ring.size();
      if (m >= 2) {
        for (Index k = 0; k < m; ++k) {
          Index a = first + k, b = first + (k + 1) % m;
          if (m == 2 && k == 1) break;  // a two-point ring is one segment
          if (g.pts[a] != g.pts[b]) g.segs.push_back({a, b});
        }
      }
    } while (j.eat(','));
    j.need(']');
  }
  return g;
}

// ---- CGAL .edg: count, then x1 y1 x2 y2 per segment ---------------------------------------

Pslg read_edg(const std::string &path) {
  std::istringstream in(slurp(path));
  Pslg g;
  g.even_odd = true;
  long n;
  if (!(in >> n) || n < 0) die(path + ": expected the segment count");
  std::map<std::array<double, 2>, Index> seen;
  auto vid = [&](double x, double y) {
    std::array<double, 2> p{x, y};
    auto it = seen.find(p);
    if (it != seen.end()) return it->second;
    g.pts.push_back(p);
    seen.emplace(p, g.pts.size() - 1);
    return g.pts.size() - 1;
  };
  for (long i = 0; i < n; ++i) {
    double x1, y1, x2, y2;
    if (!(in >> x1 >> y1 >> x2 >> y2)) die(path + ": segment " + std::to_string(i + 1) + " is incomplete");
    Index a = vid(x1, y1), b = vid(x2, y2);
    if (a != b) g.segs.push_back({a, b});
  }
  return g;
}

// ---- the triangulation ----------------------------------------------------------------------

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K, CGAL::Delaunay_mesh_vertex_base_2<K>>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Itag = CGAL::No_constraint_intersection_requiring_constructions_tag;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, Itag>;
using Vh = CDT::Vertex_handle;
using Fh = CDT::Face_handle;

// Builds the CDT; vh[i] is input vertex i's vertex (duplicates share one, info = first index).
void build(const Pslg &g, CDT &cdt, std::vector<Vh> &vh, bool convex) {
  std::vector<Index> order(g.pts.size());
  std::vector<K::Point_2> pts;
  pts.reserve(g.pts.size());
  for (Index i = 0; i < g.pts.size(); ++i) {
    order[i] = i;
    pts.emplace_back(g.pts[i][0], g.pts[i][1]);
  }
  // as CGAL's range insertion: spatial sort, then each point with the previous one as the hint
  using Pmap = CGAL::Pointer_property_map<K::Point_2>::type;
  using SortTraits = CGAL::Spatial_sort_traits_adapter_2<K, Pmap>;
  CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(pts)));
  vh.assign(g.pts.size(), Vh());
  Fh hint;
  for (Index i : order) {
    std::size_t before = cdt.number_of_vertices();
    Vh v = cdt.insert(pts[i], hint);
    if (cdt.number_of_vertices() != before) v->info() = i;
    vh[i] = v;
    hint = v->face();
  }
  // a duplicate inserted before its first occurrence (spatial order) carries the later index
  for (Index i = 0; i < g.pts.size(); ++i)
    if (vh[i]->info() > i) vh[i]->info() = i;
  for (const auto &s : g.segs) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  if (convex && cdt.dimension() == 2) {
    // Triangle's -c: the convex hull's edges become segments
    std::vector<std::pair<Vh, Vh>> hull;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
      if (!cdt.is_infinite(f)) continue;
      int i = f->index(cdt.infinite_vertex());
      hull.emplace_back(f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i)));
    }
    for (const auto &e : hull) cdt.insert_constraint(e.first, e.second);
  }
}

// Marks the domain in the faces' in_domain flags.
void mark_domain(const Pslg &g, CDT &cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(true);
  if (cdt.dimension() < 2) return;
  if (g.even_odd) {
    // nesting levels: breadth first from the outside, +1 across each constraint
    std::map<Fh, int> level;
    std::deque<Fh> border{cdt.infinite_face()};
    level[cdt.infinite_face()] = 0;
    for (int lev = 0; !border.empty(); ++lev) {
      std::deque<Fh> next;
      std::deque<Fh> q(border.begin(), border.end());
      while (!q.empty()) {
        Fh f = q.front();
        q.pop_front();
        for (int i = 0; i < 3; ++i) {
          Fh n = f->neighbor(i);
          if (level.count(n)) continue;
          if (cdt.is_constrained(CDT::Edge(f, i))) {
            next.push_back(n);
          } else {
            level[n] = lev;
            q.push_back(n);
          }
        }
      }
      border.clear();
      for (Fh f : next)
        if (!level.count(f)) { level[f] = lev + 1; border.push_back(f); }
    }
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
      auto it = level.find(f);
      f->set_in_domain(!cdt.is_infinite(f) && it != level.end() && (it->second % 2) == 1);
    }
    return;
  }
  // Triangle's rule: remove what is reachable from outside and from each hole point
  auto eat = [&](Fh start) {
    if (!start->is_in_domain()) return;
    std::deque<Fh> q{start};
    start->set_in_domain(false);
    while (!q.empty()) {
      Fh f = q.front();
      q.pop_front();
      for (int i = 0; i < 3; ++i) {
        Fh n = f->neighbor(i);
        if (n->is_in_domain() && !cdt.is_constrained(CDT::Edge(f, i))) {
          n->set_in_domain(false);
          q.push_back(n);
        }
      }
    }
  };
  eat(cdt.infinite_face());  // with --convex the hull edges are constraints: only the infinite faces go
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    if (cdt.is_infinite(f)) f->set_in_domain(false);
  for (const auto &h : g.holes) {
    Fh f = cdt.locate(K::Point_2(h[0], h[1]));
    if (f != Fh() && !cdt.is_infinite(f)) eat(f);
  }
}

double min_angle_deg(const K::Point_2 &a, const K::Point_2 &b, const K::Point_2 &c) {
  auto ang = [](const K::Point_2 &p, const K::Point_2 &q, const K::Point_2 &r) {
    double ux = q.x() - p.x(), uy = q.y() - p.y(), vx = r.x() - p.x(), vy = r.y() - p.y();
    return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  double m = std::min({ang(a, b, c), ang(b, c, a), ang(c, a, b)});
  return m * 180.0 / M_PI;
}

std::string g17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void write_triangle_files(const std::string &base, const Pslg &g, CDT &cdt) {
  // input vertices keep their indices; the mesher's new vertices follow
  Index next = g.pts.size();
  std::vector<std::array<double, 2>> extra;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info() == kNone || v->info() >= g.pts.size()) {
      v->info() = next++;
      extra.push_back({v->point().x(), v->point().y()});
    }
  }
  std::string out = std::to_string(next) + "  2  0  0\n";
  for (Index i = 0; i < g.pts.size(); ++i)
    out += std::to_string(i) + "  " + g17(g.pts[i][0]) + "  " + g17(g.pts[i][1]) + "\n";
  for (Index i = 0; i < extra.size(); ++i)
    out += std::to_string(g.pts.size() + i) + "  " + g17(extra[i][0]) + "  " + g17(extra[i][1]) + "\n";
  std::ofstream(base + ".node") << out;
  std::size_t m = 0;
  std::string body;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    body += std::to_string(m++) + "  " + std::to_string(f->vertex(0)->info()) + "  " +
            std::to_string(f->vertex(1)->info()) + "  " + std::to_string(f->vertex(2)->info()) + "\n";
  }
  std::ofstream(base + ".ele") << std::to_string(m) + "  3  0\n" + body;
}

void write_poly(const std::string &path, const Pslg &g, CDT &cdt) {
  // seeds: one per connected set of out-of-domain finite faces not reached from the outside
  std::map<Fh, bool> seen;
  std::vector<std::array<double, 2>> seeds;
  auto flood = [&](Fh start) {
    std::deque<Fh> q{start};
    seen[start] = true;
    std::vector<Fh> comp;
    bool outside = false;
    while (!q.empty()) {
      Fh f = q.front();
      q.pop_front();
      comp.push_back(f);
      if (cdt.is_infinite(f)) outside = true;
      for (int i = 0; i < 3; ++i) {
        Fh n = f->neighbor(i);
        if (!seen.count(n) && !n->is_in_domain() && !cdt.is_constrained(CDT::Edge(f, i))) {
          seen[n] = true;
          q.push_back(n);
        }
      }
    }
    return std::make_pair(outside, comp);
  };
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    if (f->is_in_domain() || seen.count(f)) continue;
    auto [outside, comp] = flood(f);
    if (outside) continue;
    bool placed = false;
    for (Fh c : comp) {
      K::Triangle_2 t = cdt.triangle(c);
      K::Point_2 m = CGAL::centroid(t);
      if (t.has_on_bounded_side(m)) {
        seeds.push_back({m.x(), m.y()});
        placed = true;
        break;
      }
    }
    if (!placed) die("no hole point found for a region outside the domain");
  }
  std::string out = std::to_string(g.pts.size()) + "  2  0  0\n";
  for (Index i = 0; i < g.pts.size(); ++i)
    out += std::to_string(i + 1) + "  " + g17(g.pts[i][0]) + "  " + g17(g.pts[i][1]) + "\n";
  out += std::to_string(g.segs.size()) + "  0\n";
  for (Index i = 0; i < g.segs.size(); ++i)
    out += std::to_string(i + 1) + "  " + std::to_string(g.segs[i][0] + 1) + "  " +
           std::to_string(g.segs[i][1] + 1) + "\n";
  out += std::to_string(seeds.size()) + "\n";
  for (Index i = 0; i < seeds.size(); ++i)
    out += std::to_string(i + 1) + "  " + g17(seeds[i][0]) + "  " + g17(seeds[i][1]) + "\n";
  std::ofstream(path) << out;
}

void usage() {
  std::cerr << "usage: oracle_cgal_cdt cdt  [--convex] [--time] [--write BASE] [--poly OUT] FILE\n"
               "       oracle_cgal_cdt mesh [--convex] [--size S] [--bound B] [--time] [--write BASE] FILE\n"
               "  FILE: Triangle .poly, JSON rings (.json) or CGAL segments (.edg)\n"
               "  cdt   the constrained Delaunay triangles of the domain, sorted input indices\n"
               "  mesh  Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2(B = 0.125, S = 0):\n"
               "        prints the triangle and vertex counts and the smallest angle\n";
}

// The command line: the mode, its options and the input file.
struct Args {
  std::string mode;
  bool convex = false, timing = false;
  double size = 0, bound = 0.125;
  std::string write_base, poly_out, file;
};

// Parses argv into a; returns -1 to go on, else the exit status (usage printed).
int parse_args(int argc, char **argv, Args &a) {
  if (argc < 2) { usage(); return 1; }
  a.mode = argv[1];
  if (a.mode == "-h" || a.mode == "--help") { usage(); return 0; }
  if (a.mode != "cdt" && a.mode != "mesh") { usage(); return 1; }
  for (int i = 2; i < argc; ++i) {
    std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) { usage(); std::exit(1); }
      return argv[++i];
    };
    if (arg == "--convex") a.convex = true;
    else if (arg == "--time") a.timing = true;
    else if (arg == "--write") a.write_base = value();
    else if (arg == "--poly") a.poly_out = value();
    else if (arg == "--size") a.size = std::atof(value().c_str());
    else if (arg == "--bound") a.bound = std::atof(value().c_str());
    else if (arg.size() > 1 && arg[0] == '-') { usage(); return 1; }
    else if (a.file.empty()) a.file = arg;
    else { usage(); return 1; }
  }
  if (a.file.empty()) { usage(); return 1; }
  return -1;
}

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }
struct Times { Clock::time_point t0, t1, t2; };  // before and after the construction, the domain

// cdt mode: the domain's triangles as sorted input indices, sorted.
int run_cdt(const Args &a, const Pslg &g, CDT &cdt, const Times &tm) {
  std::vector<std::array<Index, 3>> tris;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<Index, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(t.begin(), t.end());
    tris.push_back(t);
  }
  std::sort(tris.begin(), tris.end());
  std::string out;
  out.reserve(tris.size() * 24);
  for (const auto &t : tris)
    out += std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  if (a.timing)
    std::cerr << "oracle_cgal_cdt: cdt vertices=" << g.pts.size() << " segments=" << g.segs.size()
              << " triangles=" << tris.size() << " time_cdt=" << seconds(tm.t0, tm.t1)
              << " s time_domain=" << seconds(tm.t1, tm.t2) << " s\n";
  if (!a.poly_out.empty()) write_poly(a.poly_out, g, cdt);
  if (!a.write_base.empty()) write_triangle_files(a.write_base, g, cdt);
  return 0;
}

// mesh mode: Delaunay_mesher_2 on the marked domain, then its counts and smallest angle.
int run_mesh(const Args &a, const Pslg &g, CDT &cdt, const std::vector<Vh> &vh, const Times &tm) {
  using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
  CGAL::Delaunay_mesher_2<CDT, Criteria> mesher(cdt, Criteria(a.bound, a.size));
  mesher.init(true);  // the domain as marked above
  mesher.refine_mesh();
  auto t3 = Clock::now();
  std::size_t n = 0;
  double amin = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    ++n;
    amin = std::min(amin, min_angle_deg(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
  }
  std::printf("triangles %zu\nvertices %zu\nmin_angle %.6f\n", n,
              static_cast<std::size_t>(cdt.number_of_vertices()), n ? amin : 0.0);
  if (a.timing)
    std::cerr << "oracle_cgal_cdt: mesh B=" << a.bound << " S=" << a.size << " triangles=" << n
              << " time_cdt=" << seconds(tm.t0, tm.t1) << " s time_refine=" << seconds(tm.t2, t3)
              << " s time_total=" << seconds(tm.t0, t3) << " s\n";
  if (!a.write_base.empty()) {
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
      // the mesher's new vertices carry default (or copied) info: mark them unnumbered
      Index i = v->info();
      if (i >= g.pts.size() || vh[i] != Vh(v)) v->info() = kNone;
    }
    write_triangle_files(a.write_base, g, cdt);
  }
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  Args a;
  const int status = parse_args(argc, argv, a);
  if (status >= 0) return status;
  Pslg g;
  if (ends_with(a.file, ".poly")) g = read_poly(a.file);
  else if (ends_with(a.file, ".json")) g = read_rings(a.file);
  else if (ends_with(a.file, ".edg")) g = read_edg(a.file);
  else die("FILE must end in .poly, .json or .edg: " + a.file);

  CDT cdt;
  std::vector<Vh> vh;
  Times tm{Clock::now(), {}, {}};
  try {
    build(g, cdt, vh, a.convex);
  } catch (const CDT::Intersection_of_constraints_exception &) {
    std::cerr << "oracle_cgal_cdt: two segments cross (CGAL Intersection_of_constraints_exception)\n";
    return 3;
  }
  tm.t1 = Clock::now();
  mark_domain(g, cdt);
  tm.t2 = Clock::now();
  return a.mode == "cdt" ? run_cdt(a, g, cdt, tm) : run_mesh(a, g, cdt, vh, tm);
}
