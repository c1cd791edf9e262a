// oracle_cgal_tritri: lh_plc_intersections on two-triangle PLCs against CGAL's exact
// triangle-triangle intersection (Exact_predicates_exact_constructions_kernel).
//
//   oracle_cgal_tritri [CASES]     (default 30000 a lattice, times LH_TEST_SCALE)
//
// Triangles get corners on the lattices {0..M-1}^3 (M = 3, 4, 6), so corners, edges and
// planes coincide often; the second triangle copies 0, 1 or 2 of the first's corners.
// Each triangle is a facet with points of its own: lifthull finds the shared corners by
// coordinates. The expected answer (lh_plc_intersections' contract): the triangles
// intersect when CGAL's intersection is nonempty and is not exactly what they share (the
// common corner, or the common edge as a segment). Prints the counts; exit 1 on a
// mismatch, printing the first few.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "lifthull.h"

typedef CGAL::Exact_predicates_exact_constructions_kernel K;

static uint64_t state = 88172645463325252ull;
static uint64_t next()
{
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state;
}

static K::Point_3 pt(const double *p)
{
    return K::Point_3(p[0], p[1], p[2]);
}

// CGAL's verdict: the intersection is more than the s corners shared (sh).
static int expected(const double A[3][3], const double B[3][3], int s, const double *sh[2])
{
    const K::Triangle_3 ta(pt(A[0]), pt(A[1]), pt(A[2])), tb(pt(B[0]), pt(B[1]), pt(B[2]));
    const auto r = CGAL::intersection(ta, tb);
    if (!r) return 0;
    if (s == 0 || s == 3) return 1;
    if (const K::Point_3 *p = boost::get<K::Point_3>(&*r)) return !(s == 1 && *p == pt(sh[0]));
    if (const K::Segment_3 *g = boost::get<K::Segment_3>(&*r))
        return !(s == 2 && ((g->source() == pt(sh[0]) && g->target() == pt(sh[1])) ||
                            (g->source() == pt(sh[1]) && g->target() == pt(sh[0]))));
    return 1;
}

static int lifthull(const double A[3][3], const double B[3][3])
{
    double xyz[18];
    std::memcpy(xyz, A, sizeof(double) * 9), std::memcpy(xyz + 9, B, sizeof(double) * 9);
    lh_index ff[3] = {0, 1, 2}, pf[3] = {0, 3, 6}, pv[6] = {0, 1, 2, 3, 4, 5};
    lh_plc g;
    std::memset(&g, 0, sizeof g);
    g.n = 6, g.xyz = xyz, g.facet_count = 2, g.facet_first = ff, g.polygon_count = 2;
    g.polygon_first = pf, g.polygon_vertices = pv;
    size_t count = 0;
    lh_error err;
    if (lh_plc_intersections(&g, NULL, 0, NULL, &count, &err) != LH_OK) {
        std::printf("lh_plc_intersections: %s\n", err.message);
        std::exit(1);
    }
    return (int)count;
}

int main(int argc, char **argv)
{
    // LH_TEST_SCALE (the sanitizer stage's 0.2) scales the default count
    const char *scale = std::getenv("LH_TEST_SCALE");
    const double f = scale && std::atof(scale) > 0 ? std::atof(scale) : 1;
    const long cases = argc > 1 ? std::atol(argv[1]) : (long)(30000 * f) + 1;
    long bad = 0;
    for (int M : {3, 4, 6}) {
        long n[4] = {0, 0, 0, 0}, yes[4] = {0, 0, 0, 0};
        for (long it = 0; it < cases; it++) {
            double A[3][3], B[3][3];
            for (int i = 0; i < 3; i++)
                for (int k = 0; k < 3; k++)
                    A[i][k] = (double)(next() % M), B[i][k] = (double)(next() % M);
            const int copy = (int)(next() % 3);
            for (int i = 0; i < copy; i++) std::memcpy(B[i], A[i], sizeof A[i]);
            if (CGAL::collinear(pt(A[0]), pt(A[1]), pt(A[2])) ||
                CGAL::collinear(pt(B[0]), pt(B[1]), pt(B[2])))
                continue;
            int s = 0, ua[3] = {0, 0, 0}, ub[3] = {0, 0, 0};
            const double *sh[3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    if (!ua[i] && !ub[j] && !std::memcmp(A[i], B[j], sizeof A[i]))
                        sh[s++] = A[i], ua[i] = ub[j] = 1;
            const int want = expected(A, B, s, sh), got = lifthull(A, B);
            n[s]++, yes[s] += want;
            if (got != want && bad++ < 5)
                std::printf("mismatch (shared %d): lifthull %d, CGAL %d; A %g %g %g, %g %g %g, "
                            "%g %g %g; B %g %g %g, %g %g %g, %g %g %g\n",
                            s, got, want, A[0][0], A[0][1], A[0][2], A[1][0], A[1][1], A[1][2],
                            A[2][0], A[2][1], A[2][2], B[0][0], B[0][1], B[0][2], B[1][0], B[1][1],
                            B[1][2], B[2][0], B[2][1], B[2][2]);
        }
        std::printf("lattice %d: shared 0: %ld pairs (%ld intersect), 1: %ld (%ld), 2: %ld (%ld), "
                    "3: %ld\n",
                    M, n[0], yes[0], n[1], yes[1], n[2], yes[2], n[3]);
    }
    std::printf("%ld mismatches\n", bad);
    return bad != 0;
}
