/* test_tetmesh_measure.c — lh_tetmesh_measure (lifthull.h): the figures of shapes
 * whose figures are known in closed form (the regular tetrahedron, the six Kuhn
 * tetrahedra of a cube), every face counted once, the same figures at 2^±200, a flat
 * tetrahedron in the histograms' last bins, bad arguments and every allocation
 * failure survived. */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <string.h>

#define DEG(x) ((x) * (180 / 3.14159265358979323846))

/* A regular tetrahedron of edge 2*sqrt(2): alternate corners of the cube [-1, 1]^3. */
static const double REGULAR[12] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
static const lh_index ONE_TET[4] = {0, 1, 2, 3};

/* The unit cube split into Kuhn's six tetrahedra around its diagonal 0-7 (point i at
 * (i & 1, i >> 1 & 1, i >> 2)): each the path 0 -> 7 along the axes in one order. */
static void kuhn(double xyz[24], lh_index tets[24])
{
    static const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++) xyz[3 * i + k] = (i >> k) & 1;
    for (int t = 0; t < 6; t++) {
        int v = 0;
        tets[4 * t] = 0;
        for (int s = 0; s < 3; s++) tets[4 * t + s + 1] = v |= 1 << order[t][s];
    }
}

static size_t total(const lh_histogram *h)
{
    size_t s = 0;
    for (int k = 0; k < h->bins; k++) s += h->count[k];
    return s;
}

/* The bin x falls in. */
static int bin_of(const lh_histogram *h, double x)
{
    int k = h->bins - 1;
    while (k > 0 && x < h->lower[k]) k--;
    return k;
}

LH_TEST(regular_tetrahedron)
{
    lh_tetmesh_quality q;
    lh_error err;
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(4, REGULAR, 1, ONE_TET, NULL, &q, &err), LH_OK);
    const double edge = 2 * sqrt(2), dih = DEG(acos(1.0 / 3));
    LH_EXPECT_EQ_U64(q.tets, 1);
    LH_EXPECT_EQ_U64(q.faces, 4);
    LH_EXPECT_TRUE(fabs(q.min_volume - 8.0 / 3) < 1e-14 && q.min_volume == q.max_volume);
    LH_EXPECT_TRUE(fabs(q.min_edge - edge) < 1e-14 && fabs(q.max_edge - edge) < 1e-14);
    LH_EXPECT_TRUE(fabs(q.min_dihedral - dih) < 1e-12 && fabs(q.max_dihedral - dih) < 1e-12);
    LH_EXPECT_TRUE(fabs(q.min_face_angle - 60) < 1e-12 && fabs(q.max_face_angle - 60) < 1e-12);
    LH_EXPECT_TRUE(fabs(q.max_radius_edge - sqrt(6) / 4) < 1e-14);
    LH_EXPECT_TRUE(fabs(q.max_aspect - sqrt(1.5)) < 1e-14); /* edge / height sqrt(2/3) edge */
    LH_EXPECT_EQ_U64(q.dihedral.count[bin_of(&q.dihedral, dih)], 6);
    LH_EXPECT_EQ_U64(q.face_angle.count[5] + q.face_angle.count[6], 12); /* 60 up to rounding */
    LH_EXPECT_EQ_U64(q.radius_edge.count[0], 1);
    LH_EXPECT_EQ_U64(q.aspect.count[0], 1);
    LH_EXPECT_EQ_U64(total(&q.dihedral), 6);
    LH_EXPECT_EQ_U64(total(&q.face_angle), 12);
}

/* Each Kuhn tet: volume 1/6, edges 1, sqrt(2), sqrt(3); dihedrals 45 (2), 60 (2),
 * 90 (2); faces right triangles; 18 faces in all (12 on the cube's sides, 6 inside). */
LH_TEST(kuhn_cube)
{
    double xyz[24];
    lh_index tets[24];
    kuhn(xyz, tets);
    lh_tetmesh_quality q;
    lh_error err;
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(8, xyz, 6, tets, NULL, &q, &err), LH_OK);
    LH_EXPECT_EQ_U64(q.faces, 18);
    LH_EXPECT_EQ_U64(total(&q.face_angle), 54);
    LH_EXPECT_TRUE(fabs(q.min_volume - 1.0 / 6) < 1e-15 && fabs(q.max_volume - 1.0 / 6) < 1e-15);
    LH_EXPECT_TRUE(fabs(q.min_edge - 1) < 1e-15 && fabs(q.max_edge - sqrt(3)) < 1e-15);
    LH_EXPECT_TRUE(fabs(q.min_dihedral - 45) < 1e-12 && fabs(q.max_dihedral - 90) < 1e-12);
    LH_EXPECT_TRUE(fabs(q.max_face_angle - 90) < 1e-12);
    LH_EXPECT_TRUE(fabs(q.max_radius_edge - sqrt(3) / 2) < 1e-14);   /* circumsphere: the cube's */
    LH_EXPECT_EQ_U64(q.dihedral.count[bin_of(&q.dihedral, 47)], 12); /* 40 - 50 */
    LH_EXPECT_EQ_U64(total(&q.dihedral), 36);
}

/* The figures at 2^+-200 are the same (volumes and edges scaled exactly). */
LH_TEST(same_at_every_scale)
{
    double xyz[24], big[24], small[24];
    lh_index tets[24];
    kuhn(xyz, tets);
    xyz[3 * 5] = 1.25, xyz[3 * 6 + 2] = 0.875; /* not all right angles */
    for (int i = 0; i < 24; i++) big[i] = ldexp(xyz[i], 200), small[i] = ldexp(xyz[i], -200);
    lh_tetmesh_quality q, qb, qs;
    lh_error err;
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(8, xyz, 6, tets, NULL, &q, &err), LH_OK);
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(8, big, 6, tets, NULL, &qb, &err), LH_OK);
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(8, small, 6, tets, NULL, &qs, &err), LH_OK);
    LH_EXPECT_EQ_DBL(qb.min_volume, ldexp(q.min_volume, 600));
    LH_EXPECT_EQ_DBL(qs.max_volume, ldexp(q.max_volume, -600));
    LH_EXPECT_EQ_DBL(qb.min_edge, ldexp(q.min_edge, 200));
    LH_EXPECT_EQ_DBL(qs.max_edge, ldexp(q.max_edge, -200));
    for (const lh_tetmesh_quality *o = &qb; o; o = o == &qb ? &qs : NULL) {
        LH_EXPECT_EQ_DBL(o->min_dihedral, q.min_dihedral);
        LH_EXPECT_EQ_DBL(o->max_radius_edge, q.max_radius_edge);
        LH_EXPECT_EQ_DBL(o->max_aspect, q.max_aspect);
        LH_EXPECT_EQ_DBL(o->min_face_angle, q.min_face_angle);
        LH_EXPECT_TRUE(!memcmp(o->dihedral.count, q.dihedral.count, sizeof q.dihedral.count));
        LH_EXPECT_TRUE(!memcmp(o->face_angle.count, q.face_angle.count, sizeof q.face_angle.count));
    }
}

LH_TEST(flat_tetrahedron)
{
    const double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    lh_tetmesh_quality q;
    lh_error err;
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(4, xyz, 1, ONE_TET, NULL, &q, &err), LH_OK);
    LH_EXPECT_EQ_DBL(q.min_volume, 0);
    LH_EXPECT_TRUE(isinf(q.max_radius_edge) && isinf(q.max_aspect));
    LH_EXPECT_EQ_U64(q.radius_edge.count[q.radius_edge.bins - 1], 1);
    LH_EXPECT_EQ_U64(q.aspect.count[q.aspect.bins - 1], 1);
    LH_EXPECT_EQ_DBL(q.min_dihedral, 0);
    LH_EXPECT_EQ_DBL(q.max_dihedral, 180);
}

LH_TEST(arguments)
{
    lh_tetmesh_quality q;
    lh_error err;
    const lh_index bad[4] = {0, 1, 2, 4};
    const double nan[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN};
    LH_EXPECT_EQ_INT(lh_tetmesh_measure(4, REGULAR, 1, ONE_TET, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tetmesh_measure(4, NULL, 1, ONE_TET, NULL, &q, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tetmesh_measure(4, REGULAR, 1, NULL, NULL, &q, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tetmesh_measure(4, REGULAR, 1, bad, NULL, &q, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "tetrahedron 0 has point 4, not one of the 4 points");
    LH_EXPECT_EQ_INT(lh_tetmesh_measure(4, nan, 1, ONE_TET, NULL, &q, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "point 3 has a NaN or infinite coordinate");
    LH_ASSERT_EQ_INT(lh_tetmesh_measure(0, NULL, 0, NULL, NULL, &q, &err), LH_OK);
    LH_EXPECT_EQ_U64(q.tets + q.faces, 0);
    LH_EXPECT_EQ_DBL(q.min_dihedral, 0);
    LH_EXPECT_EQ_INT(q.dihedral.bins, 18);
}

LH_TEST(allocation_failures)
{
    double xyz[24];
    lh_index tets[24];
    kuhn(xyz, tets);
    lh_status st = LH_ERR_NOMEM;
    long k;
    for (k = 1; st == LH_ERR_NOMEM && k < 50; k++) {
        lh_test_counter c = {0};
        c.fail_at = k;
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh_tetmesh_quality q;
        lh_error err;
        st = lh_tetmesh_measure(8, xyz, 6, tets, &a, &q, &err);
        LH_EXPECT_EQ_INT(c.live, 0);
    }
    LH_EXPECT_EQ_INT(st, LH_OK);
    LH_EXPECT_GT_INT(k, 2);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(regular_tetrahedron), LH_CASE(kuhn_cube), LH_CASE(same_at_every_scale),
        LH_CASE(flat_tetrahedron),    LH_CASE(arguments), LH_CASE(allocation_failures)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
