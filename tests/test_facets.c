/* test_facets.c — facets triangulated in their planes (mesh3d/facets.h): a triangle
 * passes through; quads, a non-convex pentagon, a hole ring with and without its hole
 * point, a slit, a non-planar quad and vertical facets are triangulated with no new
 * point, each triangle turning as the facet's first ring; each refusal's message;
 * every allocation failure survived. */
#include "facets.h"
#include "lh_test.h"
#include "plc_build_test.h"

#include <math.h>

static void cross(const double *a, const double *b, const double *c, double n[3])
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
}

/* Facet f of t has `count` triangles of total area `area` (to 1e-12), each with a
 * normal on the side of `dir`. */
static void expect_facet(lh_test_state *lh_t_, const lh_plc *g, const lh__facet_tris *t, lh_index f,
                         size_t count, double area, const double dir[3])
{
    size_t c = 0;
    double sum = 0;
    for (size_t i = 0; i < t->count; i++) {
        if (t->facet[i] != f) continue;
        const lh_index *v = t->tri + 3 * i;
        double n[3];
        cross(g->xyz + 3 * v[0], g->xyz + 3 * v[1], g->xyz + 3 * v[2], n);
        sum += sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
        LH_EXPECT_TRUE(n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2] > 0);
        c++;
    }
    LH_EXPECT_EQ_U64(c, count);
    LH_EXPECT_TRUE(fabs(sum - area) < 1e-12);
}

static lh_status run(const tplc *b, lh__facet_tris *t, lh_error *err)
{
    return lh__facets_triangulate(&b->g, NULL, t, err);
}

static const double up[3] = {0, 0, 1}, down[3] = {0, 0, -1};

/* A square 0..s in z = 0, counterclockwise seen from +z: points 0..3 of b. */
static void square(tplc *b, double s)
{
    tplc_point(b, 0, 0, 0), tplc_point(b, s, 0, 0), tplc_point(b, s, s, 0), tplc_point(b, 0, s, 0);
}

LH_TEST(triangle_passes_through)
{
    tplc b;
    tplc_init(&b);
    square(&b, 1);
    tplc_face(&b, 3, (lh_index[]){2, 0, 1});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    LH_ASSERT_EQ_U64(t.count, 1);
    LH_EXPECT_EQ_INT(t.tri[0], 2), LH_EXPECT_EQ_INT(t.tri[1], 0), LH_EXPECT_EQ_INT(t.tri[2], 1);
    LH_EXPECT_EQ_INT(t.facet[0], 0);
    LH_EXPECT_EQ_U64(t.nonplanar, 0);
    lh__facet_tris_free(NULL, &t);
}

LH_TEST(quads_follow_their_rings)
{
    tplc b;
    tplc_init(&b);
    square(&b, 1);
    tplc_face(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_face(&b, 4, (lh_index[]){3, 2, 1, 0});
    lh__facet_tris t;
    lh_error err;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, &err), LH_OK);
    LH_EXPECT_EQ_U64(t.count, 4);
    expect_facet(lh_t_, &b.g, &t, 0, 2, 1, up);
    expect_facet(lh_t_, &b.g, &t, 1, 2, 1, down);
    lh__facet_tris_free(NULL, &t);
}

/* The sorted corners of facet f's triangles, for comparing triangulations. */
static void tri_set(const lh__facet_tris *t, lh_index f, lh_index out[6])
{
    size_t n = 0;
    for (size_t i = 0; i < t->count; i++) {
        if (t->facet[i] != f || n == 2) continue;
        lh_index *v = out + 3 * n++;
        for (int k = 0; k < 3; k++) v[k] = t->tri[3 * i + k];
        for (int a = 0; a < 3; a++) /* three elements: bubble */
            for (int b = 0; b + 1 < 3; b++)
                if (v[b] > v[b + 1]) {
                    const lh_index x = v[b];
                    v[b] = v[b + 1], v[b + 1] = x;
                }
    }
    if (n == 2 && (out[0] > out[3] || (out[0] == out[3] && out[1] > out[4])))
        for (int k = 0; k < 3; k++) {
            const lh_index x = out[k];
            out[k] = out[k + 3], out[k + 3] = x;
        }
}

/* Quads: the only valid diagonal of a dart, the Delaunay one of a convex quad; for a
 * square (both on one circle) the same one wherever the ring starts; a quad with
 * two corners at one place goes the general way (its duplicate merged). */
LH_TEST(quad_diagonals)
{
    tplc b;
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 4, 0, 0), tplc_point(&b, 1, 1, 0),
        tplc_point(&b, 0, 4, 0);
    tplc_point(&b, 0, 0, 1), tplc_point(&b, 10, 1, 1), tplc_point(&b, 11, 2, 1),
        tplc_point(&b, 1, 10, 1);
    tplc_point(&b, 0, 0, 2), tplc_point(&b, 1, 0, 2), tplc_point(&b, 1, 1, 2),
        tplc_point(&b, 0, 1, 2);
    tplc_point(&b, 1, 0, 2);
    tplc_face(&b, 4, (lh_index[]){1, 2, 3, 0}); /* a dart: reflex at 2 */
    tplc_face(&b, 4, (lh_index[]){4, 5, 6, 7}); /* at 5 and 7: 141 + 57 > 180 degrees, so 5-7 */
    for (int r = 0; r < 4; r++)
        tplc_face(&b, 4,
                  (lh_index[]){8 + r % 4, 8 + (r + 1) % 4, 8 + (r + 2) % 4, 8 + (r + 3) % 4});
    tplc_face(&b, 4, (lh_index[]){8, 9, 12, 10}); /* 9 and 12 coincide */
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    lh_index s[6], r[6];
    tri_set(&t, 0, s);
    static const lh_index dart[6] = {0, 1, 2, 0, 2, 3}, convex[6] = {4, 5, 7, 5, 6, 7};
    for (int k = 0; k < 6; k++) LH_EXPECT_EQ_INT(s[k], dart[k]);
    tri_set(&t, 1, s);
    for (int k = 0; k < 6; k++) LH_EXPECT_EQ_INT(s[k], convex[k]);
    tri_set(&t, 2, s);
    for (lh_index f = 3; f < 6; f++) {
        tri_set(&t, f, r);
        for (int k = 0; k < 6; k++) LH_EXPECT_EQ_INT(r[k], s[k]);
    }
    expect_facet(lh_t_, &b.g, &t, 6, 1, 0.5, up);
    lh__facet_tris_free(NULL, &t);
}

LH_TEST(nonconvex_pentagon)
{
    tplc b;
    tplc_init(&b);
    tplc_point(&b, 0, 0, 5), tplc_point(&b, 4, 0, 5), tplc_point(&b, 4, 4, 5);
    tplc_point(&b, 2, 1, 5), tplc_point(&b, 0, 4, 5); /* a notch at (2, 1) */
    tplc_face(&b, 5, (lh_index[]){0, 1, 2, 3, 4});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    expect_facet(lh_t_, &b.g, &t, 0, 3, 16 - 6, up);
    lh__facet_tris_free(NULL, &t);
}

/* A facet: the square 0..4 with a square hole ring 1..3 and a hole point in it. */
static void annulus(tplc *b)
{
    tplc_init(b);
    square(b, 4);
    tplc_point(b, 1, 1, 0), tplc_point(b, 3, 1, 0), tplc_point(b, 3, 3, 0), tplc_point(b, 1, 3, 0);
    tplc_facet(b);
    tplc_polygon(b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_polygon(b, 4, (lh_index[]){7, 6, 5, 4});
    tplc_hole(b, 2, 2, 0);
}

/* The hole ring is carved by a hole point, else it is a polygon inside the facet
 * (TetGen's rule: only hole points carve). */
LH_TEST(hole_ring_and_hole_point)
{
    tplc b;
    annulus(&b);
    tplc_facet(&b);
    tplc_polygon(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_polygon(&b, 4, (lh_index[]){4, 5, 6, 7});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    expect_facet(lh_t_, &b.g, &t, 0, 8, 12, up);
    expect_facet(lh_t_, &b.g, &t, 1, 10, 16, up);
    lh__facet_tris_free(NULL, &t);
}

/* A slit (2 vertices) and a lone point (1 vertex) inside a square: both are
 * vertices of the triangulation and the slit an edge of two triangles. */
LH_TEST(slit_and_lone_point)
{
    tplc b;
    tplc_init(&b);
    square(&b, 4);
    tplc_point(&b, 1, 1, 0), tplc_point(&b, 3, 2, 0), tplc_point(&b, 1, 3, 0);
    tplc_facet(&b);
    tplc_polygon(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_polygon(&b, 2, (lh_index[]){4, 5});
    tplc_polygon(&b, 1, (lh_index[]){6});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    expect_facet(lh_t_, &b.g, &t, 0, 2 * 7 - 4 - 2, 16, up);
    int slit = 0, lone = 0;
    for (size_t i = 0; i < t.count; i++)
        for (int k = 0; k < 3; k++) {
            const lh_index u = t.tri[3 * i + k], v = t.tri[3 * i + (k + 1) % 3];
            slit += (u == 4 && v == 5) || (u == 5 && v == 4);
            lone += u == 6;
        }
    LH_EXPECT_EQ_INT(slit, 2);
    LH_EXPECT_GT_INT(lone, 0);
    lh__facet_tris_free(NULL, &t);
}

/* One corner 10^-3 above the plane of the other three: counted, triangulated in
 * the projection to z = 0 (its triangles are not coplanar), oriented as the ring. */
LH_TEST(nonplanar_quad)
{
    tplc b;
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 1, 0, 0), tplc_point(&b, 1, 1, 1e-3),
        tplc_point(&b, 0, 1, 0);
    tplc_face(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_face(&b, 4, (lh_index[]){1, 0, 3, 2});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    LH_EXPECT_EQ_U64(t.nonplanar, 2);
    LH_EXPECT_EQ_U64(t.count, 4);
    for (size_t i = 0; i < t.count; i++) {
        double n[3];
        cross(b.xyz + 3 * t.tri[3 * i], b.xyz + 3 * t.tri[3 * i + 1], b.xyz + 3 * t.tri[3 * i + 2],
              n);
        LH_EXPECT_TRUE(t.facet[i] == 0 ? n[2] > 0 : n[2] < 0);
    }
    lh__facet_tris_free(NULL, &t);
}

/* Facets in x = 1 and y = 2 (dropped axes x and y), a pentagon each with a notch,
 * both turning ways. */
LH_TEST(vertical_facets)
{
    tplc b;
    tplc_init(&b);
    tplc_point(&b, 1, 0, 0), tplc_point(&b, 1, 4, 0), tplc_point(&b, 1, 4, 4);
    tplc_point(&b, 1, 2, 1), tplc_point(&b, 1, 0, 4);
    tplc_point(&b, 0, 2, 0), tplc_point(&b, 4, 2, 0), tplc_point(&b, 4, 2, 4);
    tplc_point(&b, 2, 2, 1), tplc_point(&b, 0, 2, 4);
    tplc_face(&b, 5, (lh_index[]){0, 1, 2, 3, 4});
    tplc_face(&b, 5, (lh_index[]){4, 3, 2, 1, 0});
    tplc_face(&b, 5, (lh_index[]){5, 6, 7, 8, 9});
    tplc_face(&b, 5, (lh_index[]){9, 8, 7, 6, 5});
    lh__facet_tris t;
    LH_ASSERT_EQ_INT(lh__facets_triangulate(&b.g, NULL, &t, NULL), LH_OK);
    expect_facet(lh_t_, &b.g, &t, 0, 3, 10, (double[]){1, 0, 0});
    expect_facet(lh_t_, &b.g, &t, 1, 3, 10, (double[]){-1, 0, 0});
    expect_facet(lh_t_, &b.g, &t, 2, 3, 10, (double[]){0, -1, 0});
    expect_facet(lh_t_, &b.g, &t, 3, 3, 10, (double[]){0, 1, 0});
    LH_EXPECT_EQ_U64(t.nonplanar, 0);
    lh__facet_tris_free(NULL, &t);
}

/* b's facet 0 is refused with status st and message msg (also with a line). */
static void expect_refusal(lh_test_state *lh_t_, tplc *b, lh_status st, const char *msg,
                           const char *with_line)
{
    lh__facet_tris t;
    lh_error err;
    LH_EXPECT_EQ_INT(run(b, &t, &err), st);
    LH_EXPECT_STREQ(err.message, msg);
    LH_EXPECT_EQ_U64(err.index, 0);
    LH_EXPECT_EQ_U64(t.count, 0);
    LH_EXPECT_TRUE(t.tri == NULL);
    size_t lines[4] = {7, 8, 9, 10};
    b->g.facet_line = lines;
    LH_EXPECT_EQ_INT(run(b, &t, &err), st);
    LH_EXPECT_STREQ(err.message, with_line);
    LH_EXPECT_EQ_U64(err.line, 7);
    b->g.facet_line = NULL;
    lh__facet_tris_free(NULL, &t);
}

LH_TEST(refusals)
{
    tplc b;
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 1, 1, 1), tplc_point(&b, 2, 2, 2),
        tplc_point(&b, 3, 3, 3);
    tplc_face(&b, 3, (lh_index[]){0, 1, 2});
    expect_refusal(lh_t_, &b, LH_ERR_DEGENERATE,
                   "facet 0: its points are all collinear (zero area)",
                   "facet 0 (line 7): its points are all collinear (zero area)");
    tplc_init(&b);
    tplc_point(&b, 0, 0, 0), tplc_point(&b, 1, 1, 1), tplc_point(&b, 2, 2, 2),
        tplc_point(&b, 3, 3, 3);
    tplc_face(&b, 4, (lh_index[]){0, 1, 3, 2});
    expect_refusal(lh_t_, &b, LH_ERR_DEGENERATE,
                   "facet 0: its points are all collinear (zero area)",
                   "facet 0 (line 7): its points are all collinear (zero area)");
    tplc_init(&b);
    square(&b, 1);
    tplc_face(&b, 4, (lh_index[]){0, 2, 1, 3}); /* a bow tie */
    expect_refusal(lh_t_, &b, LH_ERR_CROSSING_SEGMENTS,
                   "facet 0: edges 0-2 and 1-3 cross in the facet's plane",
                   "facet 0 (line 7): edges 0-2 and 1-3 cross in the facet's plane");
    tplc_init(&b);
    square(&b, 1);
    tplc_facet(&b);
    tplc_polygon(&b, 2, (lh_index[]){0, 1});
    tplc_polygon(&b, 2, (lh_index[]){2, 3});
    expect_refusal(lh_t_, &b, LH_ERR_DEGENERATE, "facet 0: no polygon of 3 or more vertices",
                   "facet 0 (line 7): no polygon of 3 or more vertices");
    tplc_init(&b); /* no polygon at all */
    square(&b, 1);
    tplc_facet(&b);
    expect_refusal(lh_t_, &b, LH_ERR_DEGENERATE, "facet 0: no polygon of 3 or more vertices",
                   "facet 0 (line 7): no polygon of 3 or more vertices");
    tplc_init(&b); /* a slit standing up from the square: not planar, merged along z */
    square(&b, 2);
    tplc_point(&b, 1, 1, 0), tplc_point(&b, 1, 1, 1);
    tplc_facet(&b);
    tplc_polygon(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_polygon(&b, 2, (lh_index[]){4, 5});
    expect_refusal(lh_t_, &b, LH_ERR_DEGENERATE,
                   "facet 0: not planar, and its projection to a coordinate plane merges "
                   "points 4 and 5",
                   "facet 0 (line 7): not planar, and its projection to a coordinate plane "
                   "merges points 4 and 5");
    tplc_init(&b); /* a hole point carving everything: no boundary around it */
    square(&b, 2);
    tplc_facet(&b);
    tplc_polygon(&b, 4, (lh_index[]){0, 1, 2, 3});
    tplc_hole(&b, 1, 1, 0);
    lh__facet_tris t;
    lh_error err;
    LH_EXPECT_EQ_INT(run(&b, &t, &err), LH_ERR_DEGENERATE);
    LH_EXPECT_TRUE(strncmp(err.message, "facet 0: in the facet's plane: the domain is empty", 50) ==
                   0);
    b.pv[1] = 4; /* out of range */
    LH_EXPECT_EQ_INT(run(&b, &t, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "polygon vertex 1: point 4 is not a point (0..3)");
    b.pv[1] = 1;
    b.xyz[4] = NAN;
    LH_EXPECT_EQ_INT(run(&b, &t, &err), LH_ERR_NONFINITE);
}

/* Every allocation failure returns LH_ERR_NOMEM and leaks nothing. */
LH_TEST(allocation_failures)
{
    tplc b;
    annulus(&b);
    tplc_face(&b, 3, (lh_index[]){0, 1, 2});
    lh_status st = LH_ERR_NOMEM;
    long k;
    for (k = 1; st == LH_ERR_NOMEM && k < 1000; k++) {
        lh_test_counter c = {0, k, 0};
        lh_allocator al = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh__facet_tris t;
        st = lh__facets_triangulate(&b.g, &al, &t, NULL);
        if (st == LH_OK) LH_EXPECT_EQ_U64(t.count, 9);
        lh__facet_tris_free(&al, &t);
        LH_EXPECT_EQ_INT(c.live, 0);
    }
    LH_EXPECT_EQ_INT(st, LH_OK);
    LH_EXPECT_GT_INT(k, 3);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(triangle_passes_through),
        LH_CASE(quads_follow_their_rings),
        LH_CASE(quad_diagonals),
        LH_CASE(nonconvex_pentagon),
        LH_CASE(hole_ring_and_hole_point),
        LH_CASE(slit_and_lone_point),
        LH_CASE(nonplanar_quad),
        LH_CASE(vertical_facets),
        LH_CASE(refusals),
        LH_CASE(allocation_failures),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
