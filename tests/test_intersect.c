/* test_intersect.c — lh_plc_intersections (TetGen's -d) on PLCs built in C: crossing
 * triangles; contact only in shared corners (a vertex, an edge folded, an edge with
 * the triangles on opposite sides in one plane) is no intersection; overlap in a
 * plane, a vertex inside the other triangle or on its edge is; two cubes sharing an
 * edge and Schönhardt's prism have none; facet pairs unique and sorted, cap and
 * count; refusals; allocation failures; the grid against all pairs on random
 * lattice triangles, and the triangle test's symmetry. */
#include "intersect.h"
#include "lh_test.h"
#include "plc_build_test.h"

#include <math.h>
#include <stdlib.h>

/* The facet pairs of b: count, and the first pairs (up to 8) in got. */
static size_t pairs_of(lh_test_state *lh_t_, const tplc *b, lh_index got[16])
{
    size_t count = 99;
    lh_error err;
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b->g, NULL, 8, got, &count, &err), LH_OK);
    LH_EXPECT_STREQ(err.message, "");
    return count;
}

static void tri(tplc *b, const double p[9])
{
    const lh_index v0 = tplc_point(b, p[0], p[1], p[2]), v1 = tplc_point(b, p[3], p[4], p[5]);
    const lh_index v2 = tplc_point(b, p[6], p[7], p[8]);
    tplc_face(b, 3, (lh_index[]){v0, v1, v2});
}

/* Whether the two triangles p and q (each its own facet and its own points, so
 * shared corners are found by coordinates) intersect. */
static size_t two(lh_test_state *lh_t_, const double p[9], const double q[9])
{
    tplc b;
    tplc_init(&b);
    tri(&b, p);
    tri(&b, q);
    lh_index got[16];
    return pairs_of(lh_t_, &b, got);
}

static const double base[9] = {0, 0, 0, 4, 0, 0, 0, 4, 0};

LH_TEST(crossing_and_disjoint)
{
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){1, 1, -1, 1, 1, 1, 3, -1, 0}), 1);
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){1, 1, 1, 2, 1, 1, 1, 2, 3}), 0);
    /* the same, reaching down to touch the plane outside the triangle */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){3, 3, 0, 3, 4, 1, 4, 3, 1}), 0);
}

LH_TEST(shared_corners_only)
{
    /* a shared vertex, the other triangle above: no */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){0, 0, 0, -1, 1, 1, -1, -1, 2}), 0);
    /* a shared vertex, coplanar, on the other side: no */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){0, 0, 0, -1, 0, 0, 0, -1, 0}), 0);
    /* a shared edge, folded: no */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){4, 0, 0, 0, 4, 0, 1, 1, 3}), 0);
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){4, 0, 0, 0, 4, 0, 1, 1, -3}), 0);
    /* a shared edge, coplanar on the other side (a square's two halves): no */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){4, 0, 0, 0, 4, 0, 4, 4, 0}), 0);
    /* a shared edge, folded onto the same side in one plane: overlap, yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){4, 0, 0, 0, 4, 0, 1, 1, 0}), 1);
    /* a shared vertex, coplanar, overlapping: yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){0, 0, 0, 3, 2, 0, 2, 3, 0}), 1);
    /* a shared vertex and an edge lying along the other's edge: yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){0, 0, 0, 2, 0, 0, 1, -1, 3}), 1);
    /* a shared vertex, the opposite edge piercing the other: yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){0, 0, 0, 1, 1, -1, 1, 1, 1}), 1);
    /* the same triangle twice (two facets): yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, base), 1);
}

LH_TEST(vertex_inside_or_on_edge)
{
    /* a vertex in the other's interior, the rest above: yes (TetGen counts it) */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){1, 1, 0, 1, 2, 2, 2, 1, 2}), 1);
    /* a vertex inside an edge of the other (a T-junction): yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){2, 0, 0, 2, -1, 2, 3, -1, 2}), 1);
    /* coplanar, a vertex on the other's edge and the rest outside: yes */
    LH_EXPECT_EQ_U64(two(lh_t_, base, (double[]){2, 0, 0, 2, -1, 0, 3, -1, 0}), 1);
}

/* Unit cubes [0,1]^3 and [1,2] x [1,2] x [0,1] share the edge x = y = 1: a valid
 * non-manifold PLC, no intersection; quads triangulated as facets. */
static void cube(tplc *b, double x, double y)
{
    lh_index v[8];
    for (int i = 0; i < 8; i++) v[i] = tplc_point(b, x + (i & 1), y + (i >> 1 & 1), i >> 2 & 1);
    static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; f++)
        tplc_face(b, 4, (lh_index[]){v[q[f][0]], v[q[f][1]], v[q[f][2]], v[q[f][3]]});
}

LH_TEST(cubes_sharing_an_edge)
{
    tplc b;
    tplc_init(&b);
    cube(&b, 0, 0);
    cube(&b, 1, 1);
    lh_index got[16];
    LH_EXPECT_EQ_U64(pairs_of(lh_t_, &b, got), 0);
    /* moved by 1/2 along y the second cube's faces cut the first's: x = 1 faces
     * overlap in their plane, the others cross */
    tplc_init(&b);
    cube(&b, 0, 0);
    cube(&b, 1, 0.5);
    const size_t n = pairs_of(lh_t_, &b, got);
    LH_EXPECT_GT_U64(n, 0);
    for (size_t i = 0; i < n && i < 8; i++) {
        LH_EXPECT_TRUE(got[2 * i] < 6 && got[2 * i + 1] >= 6);
        if (i)
            LH_EXPECT_TRUE(got[2 * i - 2] < got[2 * i] ||
                           (got[2 * i - 2] == got[2 * i] && got[2 * i - 1] < got[2 * i + 1]));
    }
    LH_EXPECT_EQ_INT(got[0], 0);
}

/* Schönhardt's twisted prism: a closed polyhedron whose reflex side diagonals admit
 * no tetrahedralization without Steiner points; its faces meet only in edges. */
LH_TEST(schonhardt_prism)
{
    tplc b;
    tplc_init(&b);
    const double pi = 3.14159265358979323846, twist = pi / 6;
    lh_index bot[3], top[3];
    for (int i = 0; i < 3; i++) {
        const double a = 2 * pi * i / 3;
        bot[i] = tplc_point(&b, cos(a), sin(a), 0);
        top[i] = tplc_point(&b, cos(a + twist), sin(a + twist), 1);
    }
    tplc_face(&b, 3, (lh_index[]){bot[0], bot[2], bot[1]});
    tplc_face(&b, 3, top);
    for (int i = 0; i < 3; i++) {
        const int j = (i + 1) % 3;
        tplc_face(&b, 3, (lh_index[]){bot[i], bot[j], top[j]});
        tplc_face(&b, 3, (lh_index[]){bot[i], top[j], top[i]});
    }
    lh_index got[16];
    LH_EXPECT_EQ_U64(pairs_of(lh_t_, &b, got), 0);
}

/* Four quads through one vertical line's neighbourhood: facets 0 and 3 cross
 * facets 1 and 2 (several triangle pairs each), reported once, sorted; cap. */
LH_TEST(pairs_unique_sorted_and_capped)
{
    tplc b;
    tplc_init(&b);
    const double q[4][12] = {{0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0},     /* z = 0      */
                             {2, -1, -1, 2, 5, -1, 2, 5, 1, 2, -1, 1}, /* x = 2      */
                             {-1, 2, -1, 5, 2, -1, 5, 2, 1, -1, 2, 1}, /* y = 2      */
                             {0, 0, 0.5, 4, 0, 0.5, 4, 4, 0.5, 0, 4, 0.5}};
    for (int f = 3; f >= 0; f--) { /* facet 0 is q[3] */
        lh_index v[4];
        for (int i = 0; i < 4; i++)
            v[i] = tplc_point(&b, q[f][3 * i], q[f][3 * i + 1], q[f][3 * i + 2]);
        tplc_face(&b, 4, v);
    }
    lh_index got[16];
    static const lh_index want[10] = {0, 1, 0, 2, 1, 2, 1, 3, 2, 3};
    LH_ASSERT_EQ_U64(pairs_of(lh_t_, &b, got), 5);
    for (int i = 0; i < 10; i++) LH_EXPECT_EQ_INT(got[i], want[i]);
    size_t count = 0;
    lh_index two_pairs[4] = {-7, -7, -7, -7};
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 1, two_pairs, &count, NULL), LH_OK);
    LH_EXPECT_EQ_U64(count, 5);
    LH_EXPECT_EQ_INT(two_pairs[0], 0), LH_EXPECT_EQ_INT(two_pairs[1], 1);
    LH_EXPECT_EQ_INT(two_pairs[2], -7); /* nothing past the cap */
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 0, NULL, &count, NULL), LH_OK);
    LH_EXPECT_EQ_U64(count, 5);
}

/* 1000 copies of one triangle (facets 0..999) and one triangle crossing it: every
 * pair intersects, counted without testing each; the first pairs listed. */
LH_TEST(identical_copies)
{
    static tplc b;
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 4, 0, 0), tplc_point(&b, 0, 4, 0);
    for (int i = 0; i < 1000; i++) tplc_face(&b, 3, (lh_index[]){i % 3, (i + 1) % 3, (i + 2) % 3});
    tri(&b, (double[]){1, 1, -1, 1, 1, 1, 3, -1, 0});
    lh_index got[16];
    LH_EXPECT_EQ_U64(pairs_of(lh_t_, &b, got), 1000 * 999 / 2 + 1000);
    for (int i = 0; i < 8; i++)
        LH_EXPECT_EQ_INT(got[2 * i], 0), LH_EXPECT_EQ_INT(got[2 * i + 1], i + 1);
    size_t count = 0;
    lh_index last[2 * 1001];
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 1001, last, &count, NULL), LH_OK);
    LH_EXPECT_EQ_INT(last[2 * 999], 0), LH_EXPECT_EQ_INT(last[2 * 999 + 1], 1000);
    LH_EXPECT_EQ_INT(last[2 * 1000], 1), LH_EXPECT_EQ_INT(last[2 * 1000 + 1], 2);
    /* 30 copies of a quad facet (two triangles each): each pair once */
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 4, 0, 0), tplc_point(&b, 4, 4, 0),
        tplc_point(&b, 0, 4, 0);
    for (int i = 0; i < 30; i++) tplc_face(&b, 4, (lh_index[]){0, 1, 2, 3});
    LH_EXPECT_EQ_U64(pairs_of(lh_t_, &b, got), 30 * 29 / 2);
    for (int i = 0; i < 8; i++)
        LH_EXPECT_EQ_INT(got[2 * i], 0), LH_EXPECT_EQ_INT(got[2 * i + 1], i + 1);
}

LH_TEST(refusals)
{
    tplc b;
    tplc_init(&b);
    tri(&b, base);
    tri(&b, (double[]){0, 0, 1, 1, 1, 1, 2, 2, 1}); /* collinear */
    size_t count = 7;
    lh_index p[2];
    lh_error err;
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 1, p, &count, &err), LH_ERR_DEGENERATE);
    LH_EXPECT_STREQ(err.message, "facet 1: its points are all collinear (zero area)");
    LH_EXPECT_EQ_U64(count, 0);
    LH_EXPECT_EQ_INT(lh_plc_intersections(NULL, NULL, 0, NULL, &count, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 0, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 1, NULL, &count, &err),
                     LH_ERR_INVALID_ARGUMENT);
    lh_allocator bad = {NULL, NULL, NULL};
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, &bad, 0, NULL, &count, &err),
                     LH_ERR_INVALID_ARGUMENT);
    b.xyz[0] = INFINITY;
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 0, NULL, &count, &err), LH_ERR_NONFINITE);
    tplc_init(&b); /* no facet, or one: nothing to intersect */
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 0, NULL, &count, &err), LH_OK);
    LH_EXPECT_EQ_U64(count, 0);
    tri(&b, base);
    LH_EXPECT_EQ_INT(lh_plc_intersections(&b.g, NULL, 0, NULL, &count, &err), LH_OK);
    LH_EXPECT_EQ_U64(count, 0);
}

/* Corners with small integer coordinates lie on one line: the cross product is
 * exact. */
static int collinear(const double *const p[3])
{
    double u[3], v[3];
    for (int k = 0; k < 3; k++) u[k] = p[1][k] - p[0][k], v[k] = p[2][k] - p[0][k];
    return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 &&
           u[0] * v[1] - u[1] * v[0] == 0;
}

/* n (at most 85) random triangles with corners on the lattice {0..3}^3 (corners,
 * edges and planes shared often), each its own facet with its own points. */
static void lattice_triangles(tplc *b, size_t n, uint64_t *seed)
{
    tplc_init(b);
    while (b->g.facet_count < n) {
        double p[9];
        for (int i = 0; i < 9; i++) p[i] = (double)(lh_test_xorshift(seed) % 4);
        const double *c[3] = {p, p + 3, p + 6};
        if (!collinear(c)) tri(b, p);
    }
}

/* Facet pairs by testing every pair, shared corners found by coordinates. */
static size_t brute_force(lh_pred *pr, const tplc *b, lh_index *out)
{
    size_t m = 0;
    for (size_t f = 0; f < b->g.facet_count; f++)
        for (size_t h = f + 1; h < b->g.facet_count; h++) {
            const double *a[3], *c[3], *x[3], *y[3];
            for (int i = 0; i < 3; i++) {
                a[i] = b->xyz + 3 * b->pv[3 * f + i];
                c[i] = b->xyz + 3 * b->pv[3 * h + i];
            }
            int shared = 0, na, nc, used[3] = {0, 0, 0}, ua[3] = {0, 0, 0};
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    if (!used[j] && !ua[i] && !memcmp(a[i], c[j], 3 * sizeof(double))) {
                        x[shared] = a[i], y[shared] = c[j], used[j] = ua[i] = 1, shared++;
                    }
            na = nc = shared;
            for (int i = 0; i < 3; i++) {
                if (!ua[i]) x[na++] = a[i];
                if (!used[i]) y[nc++] = c[i];
            }
            if (lh__tri_tri_meet(pr, x, y, shared))
                out[2 * m] = (lh_index)f, out[2 * m + 1] = (lh_index)h, m++;
        }
    return m;
}

LH_TEST(grid_agrees_with_all_pairs)
{
    lh_pred *pr;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &pr), LH_OK);
    uint64_t seed = 0x9e3779b97f4a7c15u;
    static tplc b;
    static lh_index want[2 * 80 * 79 / 2], got[2 * 80 * 79 / 2];
    for (int round = 0; round < 20 && !LH_FAILED(); round++) {
        lattice_triangles(&b, 80, &seed);
        const size_t m = brute_force(pr, &b, want);
        size_t count = 0;
        LH_ASSERT_EQ_INT(lh_plc_intersections(&b.g, NULL, 80 * 79 / 2, got, &count, NULL), LH_OK);
        LH_EXPECT_EQ_U64(count, m);
        for (size_t i = 0; i < 2 * m && i < 2 * count; i++) LH_EXPECT_EQ_INT(got[i], want[i]);
        if (LH_FAILED()) LH_NOTE("round %d", round);
    }
    lh_pred_free(pr);
}

/* The answer does not depend on the triangles' order, nor on where each starts
 * or which way it turns (with the shared corners first, in the same order). */
LH_TEST(triangle_test_symmetric)
{
    lh_pred *pr;
    LH_ASSERT_EQ_INT(lh_pred_create(NULL, &pr), LH_OK);
    uint64_t seed = 12345;
    static tplc b;
    long meets = 0;
    for (size_t f = 0; f < 1000 && !LH_FAILED(); f += 2) {
        if (f % 80 == 0) lattice_triangles(&b, 80, &seed);
        const double *a[3], *c[3];
        for (int i = 0; i < 3; i++)
            a[i] = b.xyz + 9 * (f % 80) + 3 * i, c[i] = b.xyz + 9 * (f % 80 + 1) + 3 * i;
        const int r = lh__tri_tri_meet(pr, a, c, 0);
        meets += r;
        LH_EXPECT_EQ_INT(lh__tri_tri_meet(pr, c, a, 0), r);
        const double *a2[3] = {a[1], a[2], a[0]}, *a3[3] = {a[0], a[2], a[1]};
        LH_EXPECT_EQ_INT(lh__tri_tri_meet(pr, a2, c, 0), r);
        LH_EXPECT_EQ_INT(lh__tri_tri_meet(pr, a3, c, 0), r);
        /* sharing a's first corner: c moved so that its first corner is a's */
        const double *c1[3] = {a[0], c[1], c[2]}, *a1[3] = {a[0], a[2], a[1]};
        if (!memcmp(c[1], a[0], 24) || !memcmp(c[2], a[0], 24) || !memcmp(c[1], a[1], 24) ||
            !memcmp(c[1], a[2], 24) || !memcmp(c[2], a[1], 24) || !memcmp(c[2], a[2], 24) ||
            collinear(c1))
            continue;
        const int s = lh__tri_tri_meet(pr, a, c1, 1);
        LH_EXPECT_EQ_INT(lh__tri_tri_meet(pr, c1, a, 1), s);

        LH_EXPECT_EQ_INT(lh__tri_tri_meet(pr, a1, c1, 1), s);
    }
    LH_EXPECT_GT_INT(meets, 10);
    lh_pred_free(pr);
}

/* Every allocation failure returns LH_ERR_NOMEM and leaks nothing. */
LH_TEST(allocation_failures)
{
    tplc b;
    tplc_init(&b);
    cube(&b, 0, 0);
    cube(&b, 1, 0.5);
    lh_status st = LH_ERR_NOMEM;
    long k;
    size_t count = 0;
    lh_index got[4];
    for (k = 1; st == LH_ERR_NOMEM && k < 1000; k++) {
        lh_test_counter c = {0, k, 0};
        lh_allocator al = {lh_test_counting_alloc, lh_test_counting_free, &c};
        st = lh_plc_intersections(&b.g, &al, 2, got, &count, NULL);
        LH_EXPECT_EQ_INT(c.live, 0);
    }
    LH_EXPECT_EQ_INT(st, LH_OK);
    LH_EXPECT_GT_INT(k, 5);
    LH_EXPECT_GT_U64(count, 0);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(crossing_and_disjoint),      LH_CASE(shared_corners_only),
        LH_CASE(vertex_inside_or_on_edge),   LH_CASE(cubes_sharing_an_edge),
        LH_CASE(schonhardt_prism),           LH_CASE(pairs_unique_sorted_and_capped),
        LH_CASE(identical_copies),           LH_CASE(refusals),
        LH_CASE(grid_agrees_with_all_pairs), LH_CASE(triangle_test_symmetric),
        LH_CASE(allocation_failures),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
