// bench_whole_cgal — CGAL's whole program for `lifthull delaunay -s`: reads a Qhull
// point file (dimension and a title, count, then the coordinates, as `lifthull points`
// writes it; '#' comments skipped) with a plain strtod loop, triangulates with
// Delaunay_triangulation_2 or _3 (Epick, spatial sort inside insert), and prints the
// number of finite simplices. bench/run_whole.sh times it beside lifthull.
//   bench_whole_cgal FILE
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

static std::vector<char> slurp(const char *path)
{
    std::vector<char> text;
    FILE *f = std::fopen(path, "rb");
    if (!f) return text;
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.insert(text.end(), buf, buf + n);
    std::fclose(f);
    text.push_back(0);
    return text;
}

// The numbers of the text after removing '#' comments, parsed with strtod; the rest of
// the first number's line is a title (Qhull's format: "2 lifthull points ...").
static std::vector<double> numbers(std::vector<char> &text)
{
    for (size_t i = 0; i < text.size(); i++)
        if (text[i] == '#')
            while (i < text.size() && text[i] != '\n' && text[i]) text[i++] = ' ';
    std::vector<double> v;
    char *p = text.data(), *end;
    double d = std::strtod(p, &end);
    if (end == p) return v;
    v.push_back(d);
    for (p = end; *p && *p != '\n'; p++) {
    }
    for (;;) {
        double x = std::strtod(p, &end);
        if (end == p) break;
        v.push_back(x);
        p = end;
    }
    return v;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: bench_whole_cgal FILE\n");
        return 2;
    }
    std::vector<char> text = slurp(argv[1]);
    std::vector<double> v = numbers(text);
    if (v.size() < 2) return 1;
    int d = (int)v[0];
    size_t n = (size_t)v[1];
    if ((d != 2 && d != 3) || v.size() < 2 + n * (size_t)d) return 1;
    const double *x = v.data() + 2;
    size_t simplices;
    if (d == 2) {
        std::vector<K::Point_2> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; i++) pts.emplace_back(x[2 * i], x[2 * i + 1]);
        CGAL::Delaunay_triangulation_2<K> t(pts.begin(), pts.end());
        simplices = t.number_of_faces();
    } else {
        std::vector<K::Point_3> pts;
        pts.reserve(n);
        for (size_t i = 0; i < n; i++) pts.emplace_back(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        CGAL::Delaunay_triangulation_3<K> t(pts.begin(), pts.end());
        simplices = t.number_of_finite_cells();
    }
    std::printf("simplices %zu\n", simplices);
    return 0;
}
