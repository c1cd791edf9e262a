/* test_tetmesh_check.c — lh_tetmesh_check (lifthull.h, "tetrahedral meshes of
 * PLCs"): valid meshes pass (boxes of unit cubes split into Kuhn's six tets with their
 * PLCs, Delaunay tetrahedralizations of random points), every kind of fault fails
 * with its exact message, rounded Steiner points are counted, bad arguments and
 * every allocation failure are survived. The meshes' boundaries, subsegments and
 * facet parents are found here by brute force, independently of the checker. */
#include "lh_test.h"
#include "lifthull.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXP 64
#define MAXT 64

typedef struct tm {
    size_t n, nt, nf, ne;
    double xyz[3 * MAXP];
    lh_index tets[4 * MAXT], faces[3 * 4 * MAXT], par[4 * MAXT], edges[2 * 6 * MAXT];
    /* the PLC */
    lh_plc g;
    lh_index facet_first[8], polygon_first[8], polygon_vertices[40], segs[4];
} tm;

static lh_pred *pred(void)
{
    static lh_pred *p; /* one per process; freed at exit by the OS */
    if (!p) lh_pred_create(NULL, &p);
    return p;
}

static int orient(const tm *m, const lh_index *v)
{
    const double *p[4] = {m->xyz + 3 * v[0], m->xyz + 3 * v[1], m->xyz + 3 * v[2], m->xyz + 3 * v[3]};
    return lh_orient(pred(), 3, p);
}

static void add_tet(tm *m, lh_index a, lh_index b, lh_index c, lh_index d)
{
    lh_index *v = m->tets + 4 * m->nt++;
    v[0] = a, v[1] = b, v[2] = c, v[3] = d;
    if (orient(m, v) < 0) v[2] = d, v[3] = c;
}

static int has(const lh_index *v, int k, lh_index x)
{
    for (int i = 0; i < k; i++)
        if (v[i] == x) return 1;
    return 0;
}

/* Faces in one tet become subfaces (brute force). */
static void boundary_faces(tm *m)
{
    m->nf = 0;
    for (size_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 4; k++) {
            lh_index f[3];
            for (int i = 0, j = 0; i < 4; i++)
                if (i != k) f[j++] = m->tets[4 * t + i];
            int shared = 0;
            for (size_t u = 0; u < m->nt; u++)
                shared |= u != t && has(m->tets + 4 * u, 4, f[0]) && has(m->tets + 4 * u, 4, f[1]) &&
                          has(m->tets + 4 * u, 4, f[2]);
            if (!shared) memcpy(m->faces + 3 * m->nf++, f, sizeof f);
        }
}

/* A box of k unit cubes along x, each split into Kuhn's six tets around its
 * diagonal; point (x, y, z) is x + (k+1)(y + 2z). */
static void box(tm *m, int k)
{
    memset(m, 0, sizeof *m);
    m->n = (size_t)(4 * (k + 1));
    for (int z = 0; z < 2; z++)
        for (int y = 0; y < 2; y++)
            for (int x = 0; x <= k; x++) {
                double *p = m->xyz + 3 * (x + (k + 1) * (y + 2 * z));
                p[0] = x, p[1] = y, p[2] = z;
            }
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int step[3] = {1, k + 1, 2 * (k + 1)};
    for (int c = 0; c < k; c++)
        for (int q = 0; q < 6; q++) {
            lh_index v[4] = {c};
            for (int i = 0; i < 3; i++) v[i + 1] = v[i] + step[perm[q][i]];
            add_tet(m, v[0], v[1], v[2], v[3]);
        }
    boundary_faces(m);
}

static const double *P(const tm *m, lh_index i) { return m->xyz + 3 * i; }

/* Whether x lies on the closed segment a b (small integer coordinates: exact). */
static int on_seg(const double *a, const double *b, const double *x)
{
    for (int i = 0; i < 3; i++) {
        const double lo = a[i] < b[i] ? a[i] : b[i], hi = a[i] < b[i] ? b[i] : a[i];
        if (x[i] < lo || x[i] > hi) return 0;
    }
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                 w[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
    return u[1] * w[2] == u[2] * w[1] && u[2] * w[0] == u[0] * w[2] && u[0] * w[1] == u[1] * w[0];
}

static void add_facet(tm *m, const lh_index *v, int k)
{
    lh_plc *g = &m->g;
    const size_t f = g->facet_count++, first = (size_t)m->polygon_first[f];
    m->facet_first[f + 1] = (lh_index)(f + 1);
    memcpy(m->polygon_vertices + first, v, (size_t)k * sizeof *v);
    m->polygon_first[f + 1] = (lh_index)(first + (size_t)k);
    g->polygon_count = g->facet_count;
}

/* The box's PLC: for k = 1 its six quads; for k = 2 the bottom split at x = 1 into
 * facets 0 and 1, the front (y = 0) with its two points on edges as vertices. Then
 * subsegments (mesh edges on polygon edges) and parents (the facet in whose plane and
 * x range a subface lies), by brute force. */
static void box_plc(tm *m, int k)
{
    const lh_index K = k + 1;
    lh_plc *g = &m->g;
    g->n = m->n, g->xyz = m->xyz;
    g->facet_first = m->facet_first, g->polygon_first = m->polygon_first;
    g->polygon_vertices = m->polygon_vertices;
    if (k == 1) {
        const lh_index q[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
        for (int f = 0; f < 6; f++) add_facet(m, q[f], 4);
    } else {
        const lh_index a[4] = {0, 1, K + 1, K}, b[4] = {1, 2, K + 2, K + 1};
        const lh_index top[4] = {2 * K, 2 * K + 2, 3 * K + 2, 3 * K};
        const lh_index front[6] = {0, 1, 2, 2 * K + 2, 2 * K + 1, 2 * K};
        const lh_index back[4] = {K, K + 2, 3 * K + 2, 3 * K}, left[4] = {0, K, 3 * K, 2 * K},
                       right[4] = {2, K + 2, 3 * K + 2, 2 * K + 2};
        add_facet(m, a, 4), add_facet(m, b, 4), add_facet(m, top, 4), add_facet(m, front, 6);
        add_facet(m, back, 4), add_facet(m, left, 4), add_facet(m, right, 4);
    }
    m->ne = 0;
    for (size_t t = 0; t < m->nt; t++)
        for (int i = 0; i < 4; i++)
            for (int j = i + 1; j < 4; j++) {
                const lh_index u = m->tets[4 * t + i], v = m->tets[4 * t + j];
                int dup = 0, on = 0;
                for (size_t e = 0; e < m->ne; e++)
                    dup |= has(m->edges + 2 * e, 2, u) && has(m->edges + 2 * e, 2, v);
                for (size_t p = 0; p < g->polygon_count; p++) {
                    const lh_index *r = m->polygon_vertices + m->polygon_first[p];
                    const int len = (int)(m->polygon_first[p + 1] - m->polygon_first[p]);
                    for (int s = 0; s < len; s++)
                        on |= on_seg(P(m, r[s]), P(m, r[(s + 1) % len]), P(m, u)) &&
                              on_seg(P(m, r[s]), P(m, r[(s + 1) % len]), P(m, v));
                }
                if (!dup && on) m->edges[2 * m->ne] = u, m->edges[2 * m->ne++ + 1] = v;
            }
    for (size_t s = 0; s < m->nf; s++) {
        const double *a = P(m, m->faces[3 * s]), *b = P(m, m->faces[3 * s + 1]), *c = P(m, m->faces[3 * s + 2]);
        m->par[s] = -1;
        for (size_t f = 0; f < g->facet_count && m->par[s] < 0; f++) {
            const lh_index *r = m->polygon_vertices + m->polygon_first[f];
            const int len = (int)(m->polygon_first[f + 1] - m->polygon_first[f]);
            const double *p0 = P(m, r[0]);
            int axis = -1;
            double xmax = 0;
            for (int i = 0; i < 3; i++) {
                int same = 1;
                for (int j = 0; j < len; j++) same &= P(m, r[j])[i] == p0[i];
                if (same) axis = i;
            }
            for (int i = 0; i < len; i++) xmax = P(m, r[i])[0] > xmax ? P(m, r[i])[0] : xmax;
            const double fx = a[0] > b[0] ? a[0] : b[0], mx = fx > c[0] ? fx : c[0];
            if (a[axis] == p0[axis] && b[axis] == p0[axis] && c[axis] == p0[axis] && mx <= xmax &&
                (k == 1 || f != 1 || mx > 1))
                m->par[s] = (lh_index)f;
        }
    }
}

static lh_status run(const tm *m, const lh_index *par, int boundary_free, const lh_plc *g,
                     size_t *off, lh_error *err)
{
    return lh_tetmesh_check(m->n, m->xyz, m->nt, m->tets, m->nf, m->faces, par, m->ne, m->edges,
                            boundary_free, g, off, NULL, err);
}

static void expect_msg(lh_test_state *lh_t_, const tm *m, const lh_index *par, int bfree,
                       const lh_plc *g, const char *want)
{
    lh_error err;
    LH_EXPECT_EQ_INT(run(m, par, bfree, g, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, want);
}

static void expect_ok(lh_test_state *lh_t_, const tm *m, const lh_index *par, int bfree,
                      const lh_plc *g)
{
    lh_error err;
    size_t off = 99;
    LH_EXPECT_EQ_INT(run(m, par, bfree, g, &off, &err), LH_OK);
    LH_EXPECT_STREQ(err.message, "");
    LH_EXPECT_EQ_U64(off, 0);
}

LH_TEST(boxes_pass)
{
    for (int k = 1; k <= 2; k++) {
        tm m;
        box(&m, k);
        box_plc(&m, k);
        LH_EXPECT_EQ_U64(m.nt, 6 * (size_t)k);
        LH_EXPECT_EQ_U64(m.nf, 12 + 8 * (size_t)(k - 1));
        LH_EXPECT_EQ_U64(m.ne, k == 1 ? 12 : 17);
        for (size_t s = 0; s < m.nf; s++) LH_EXPECT_GE_INT(m.par[s], 0);
        expect_ok(lh_t_, &m, NULL, 0, NULL);
        expect_ok(lh_t_, &m, m.par, 0, &m.g);
        expect_ok(lh_t_, &m, NULL, 0, &m.g); /* parents by containment */
        expect_ok(lh_t_, &m, m.par, 1, &m.g);
    }
}

LH_TEST(tet_faults)
{
    tm m;
    char want[256];
    box(&m, 1);
    lh_index *v = m.tets;
    const lh_index t = v[2];
    v[2] = v[3], v[3] = t;
    snprintf(want, sizeof want, "tet 0 (%d %d %d %d) has orient_3 < 0 (inverted)", (int)v[0],
             (int)v[1], (int)v[2], (int)v[3]);
    expect_msg(lh_t_, &m, NULL, 0, NULL, want);
    box(&m, 1);
    m.tets[4 * 3 + 3] = 1, m.tets[4 * 3 + 2] = 0, m.tets[4 * 3 + 1] = 2, m.tets[4 * 3] = 3;
    expect_msg(lh_t_, &m, NULL, 0, NULL, "tet 3 (3 2 0 1) has orient_3 = 0 (flat)");
    box(&m, 1);
    m.tets[5] = 8;
    snprintf(want, sizeof want, "tet 1 (%d 8 %d %d) names point 8, not a point (0..7)",
             (int)m.tets[4], (int)m.tets[6], (int)m.tets[7]);
    expect_msg(lh_t_, &m, NULL, 0, NULL, want);
    box(&m, 1);
    memcpy(m.tets + 4 * m.nt++, m.tets + 8, 4 * sizeof *m.tets);
    snprintf(want, sizeof want, "tets 2 and 6 are the same tet (%d %d %d %d)", (int)m.tets[8],
             (int)m.tets[9], (int)m.tets[10], (int)m.tets[11]);
    expect_msg(lh_t_, &m, NULL, 1, NULL, want);
}

/* Two tets on one side of a face; a face in three tets. */
LH_TEST(overlapping_tets)
{
    tm m;
    memset(&m, 0, sizeof m);
    const double p[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 2}};
    memcpy(m.xyz, p, sizeof p);
    m.n = 5;
    add_tet(&m, 0, 1, 2, 3), add_tet(&m, 0, 1, 2, 4);
    expect_msg(lh_t_, &m, NULL, 1, NULL, "face (0 1 2): tets 0 and 1 lie on the same side");
    m.xyz[14] = -1;
    m.nt = 0;
    add_tet(&m, 0, 1, 2, 3), add_tet(&m, 0, 1, 2, 4);
    expect_ok(lh_t_, &m, NULL, 1, NULL);
    m.n = 6;
    m.xyz[15] = 0.1, m.xyz[16] = 0.1, m.xyz[17] = -2;
    add_tet(&m, 0, 1, 2, 5);
    expect_msg(lh_t_, &m, NULL, 1, NULL, "face (0 1 2) is in 3 tets: 0, 1, 2");
}

/* Tets around the edge 0 1 (the z axis) with apexes at 120 degree steps: once
 * around (3 tets) is right, twice around (6 tets, the second turn further out) is
 * not although every tet is positive and every face has its two sides. */
LH_TEST(edge_winding)
{
    tm m;
    memset(&m, 0, sizeof m);
    const double c[3][2] = {{1, 0}, {-0.5, 0.875}, {-0.5, -0.875}};
    m.n = 8;
    m.xyz[5] = 1;
    for (int i = 0; i < 6; i++) {
        const double r = i < 3 ? 1 : 2;
        double *p = m.xyz + 3 * (2 + i);
        p[0] = r * c[i % 3][0], p[1] = r * c[i % 3][1], p[2] = 0.5;
    }
    for (int i = 0; i < 3; i++) add_tet(&m, 0, 1, 2 + i, 2 + (i + 1) % 3);
    for (size_t t = 0; t < m.nt; t++) LH_EXPECT_EQ_INT(m.tets[4 * t + 2], 2 + (int)t);
    expect_ok(lh_t_, &m, NULL, 1, NULL);
    m.nt = 0;
    for (int i = 0; i < 6; i++) add_tet(&m, 0, 1, 2 + i, 2 + (i + 1) % 6);
    expect_msg(lh_t_, &m, NULL, 1, NULL,
               "edge (0 1): the tets around it turn 2 times, not once (tets 0, 1, ...)");
    /* a boundary edge's fan that overlaps itself: 5 of the 6 */
    m.nt = 5;
    expect_msg(lh_t_, &m, NULL, 1, NULL,
               "edge (0 1): the tets around it turn 2 times, not once (tets 0, 1, ...)");
}

LH_TEST(subface_and_subsegment_faults)
{
    tm m;
    char want[256];
    box(&m, 1);
    box_plc(&m, 1);
    const lh_index *f = m.faces + 3 * (m.nf - 1);
    lh_index key[3] = {f[0], f[1], f[2]};
    for (int i = 0; i < 3; i++) /* sorted, as the message names it */
        for (int j = i + 1; j < 3; j++)
            if (key[j] < key[i]) { const lh_index x = key[i]; key[i] = key[j], key[j] = x; }
    size_t owner = 0;
    for (size_t t = 0; t < m.nt; t++)
        if (has(m.tets + 4 * t, 4, key[0]) && has(m.tets + 4 * t, 4, key[1]) && has(m.tets + 4 * t, 4, key[2])) owner = t;
    m.nf--; /* a missing subface */
    snprintf(want, sizeof want, "boundary face (%d %d %d) of tet %zu is not a subface", (int)key[0],
             (int)key[1], (int)key[2], owner);
    expect_msg(lh_t_, &m, NULL, 0, NULL, want);
    /* ... and with boundary_free its facet is not covered */
    snprintf(want, sizeof want, "facet %d is not covered: its 1 subfaces' area is smaller than the facet's",
             (int)m.par[m.nf]);
    expect_msg(lh_t_, &m, m.par, 1, &m.g, want);
    m.nf++;
    /* a subface that is no face, a subsegment that is no edge */
    m.faces[3 * m.nf] = 0, m.faces[3 * m.nf + 1] = 1, m.faces[3 * m.nf + 2] = 6, m.par[m.nf] = -1;
    m.nf++;
    expect_msg(lh_t_, &m, NULL, 0, NULL, "subface 12 (0 1 6) is not a face of a tet");
    m.nf--;
    m.edges[2 * m.ne] = 1, m.edges[2 * m.ne + 1] = 6;
    m.ne++;
    expect_msg(lh_t_, &m, NULL, 0, NULL, "subsegment 12 (1 6) is not an edge of a tet");
    m.ne--;
    /* a boundary face that is no subface: a tet glued below the bottom */
    m.xyz[3 * 8] = 0.5, m.xyz[3 * 8 + 1] = 0.25, m.xyz[3 * 8 + 2] = -1;
    m.n = 9;
    const lh_index *b = NULL;
    for (size_t s = 0; s < m.nf && !b; s++)
        if (m.par[s] == 0) b = m.faces + 3 * s;
    add_tet(&m, b[0], b[1], b[2], 8);
    lh_index lo = b[0] < b[1] ? b[0] : b[1];
    lo = lo < b[2] ? lo : b[2];
    lh_index mid = b[0] + b[1] + b[2] - lo - (b[0] > b[1] ? (b[0] > b[2] ? b[0] : b[2]) : (b[1] > b[2] ? b[1] : b[2]));
    snprintf(want, sizeof want, "boundary face (%d %d 8) of tet 6 is not a subface", (int)lo, (int)mid);
    expect_msg(lh_t_, &m, NULL, 0, NULL, want);
}

LH_TEST(conformity_faults)
{
    tm m;
    char want[256];
    box(&m, 1);
    box_plc(&m, 1);
    /* a facet edge's subsegment missing: segment (0 1) is the first polygon edge */
    size_t e01 = 0;
    for (size_t e = 0; e < m.ne; e++)
        if (has(m.edges + 2 * e, 2, 0) && has(m.edges + 2 * e, 2, 1)) e01 = e;
    m.edges[2 * e01] = m.edges[2 * (m.ne - 1)], m.edges[2 * e01 + 1] = m.edges[2 * m.ne - 1];
    m.ne--;
    expect_msg(lh_t_, &m, m.par, 0, &m.g,
               "segment 0 (0 1) is not covered: its chain of subsegments from 0 stops at 0");
    box(&m, 1);
    box_plc(&m, 1);
    /* a free segment on no chain; the diagonal 0 7 is one edge of every Kuhn tet */
    m.g.segments = m.segs, m.g.segment_count = 1;
    m.segs[0] = 0, m.segs[1] = 7;
    m.edges[2 * m.ne] = 7, m.edges[2 * m.ne + 1] = 0;
    m.ne++;
    expect_ok(lh_t_, &m, m.par, 0, &m.g);
    m.segs[0] = 1, m.segs[1] = 6;
    expect_msg(lh_t_, &m, m.par, 0, &m.g,
               "segment 0 (1 6) is not covered: its chain of subsegments from 1 stops at 1");
    /* a subface given to the wrong facet: an input point off its plane */
    box(&m, 1);
    box_plc(&m, 1);
    const lh_index keep = m.par[0];
    m.par[0] = (keep + 1) % 6;
    snprintf(want, sizeof want, "facet %d is not covered: an input point off its plane (subface 0 (%d %d %d))",
             (int)m.par[0], (int)m.faces[0], (int)m.faces[1], (int)m.faces[2]);
    expect_msg(lh_t_, &m, m.par, 0, &m.g, want);
    m.par[0] = -7;
    expect_msg(lh_t_, &m, m.par, 0, &m.g, "subface 0 has parent -7, not a facet (0..5) or -1");
}

/* A facet outside the mesh (a fin on a closed surface, carved away with the region
 * around it) has no subface, and its polygon edges no subsegment: they pass. A free
 * segment may not be missing, nor a facet edge that enters the mesh at an end. Point
 * 8, (2 0 0), is in no tetrahedron. */
LH_TEST(carved_away_segment_passes)
{
    tm m;
    box(&m, 1);
    box_plc(&m, 1);
    m.xyz[24] = 2, m.xyz[25] = 0, m.xyz[26] = 0;
    m.n = m.g.n = 9;
    const lh_index fin[3] = {1, 8, 3}; /* in the bottom's plane, beside it */
    add_facet(&m, fin, 3);
    expect_ok(lh_t_, &m, m.par, 0, &m.g);
    m.g.segments = m.segs, m.g.segment_count = 1;
    m.segs[0] = 1, m.segs[1] = 8;
    expect_msg(lh_t_, &m, m.par, 0, &m.g,
               "segment 0 (1 8) is not covered: its chain of subsegments from 1 stops at 1");
    m.g.segment_count = 0;
    m.polygon_vertices[m.polygon_first[6]] = 6; /* the fin (6 8 3): edge 6 8 enters the cube */
    expect_msg(lh_t_, &m, m.par, 0, &m.g,
               "segment 12 (6 8) is not covered: its chain of subsegments from 6 stops at 6");
}

/* Two coplanar facets (the bottom halves of the 2-cube box) swap a triangle each:
 * the areas still agree, the subfaces' borders do not. */
LH_TEST(facet_border_fault)
{
    tm m;
    box(&m, 2);
    box_plc(&m, 2);
    size_t a = m.nf, b = m.nf;
    for (size_t s = 0; s < m.nf; s++) {
        if (m.par[s] == 0 && a == m.nf) a = s;
        if (m.par[s] == 1 && b == m.nf) b = s;
    }
    LH_ASSERT_TRUE(a < m.nf && b < m.nf);
    m.par[a] = 1, m.par[b] = 0;
    lh_error err;
    LH_EXPECT_EQ_INT(run(&m, m.par, 0, &m.g, NULL, &err), LH_ERR_INVALID_MESH);
    const char *want = "facet 0 is not covered: an edge on the subfaces' border lies on no "
                       "polygon edge of the facet (subface ";
    LH_EXPECT_TRUE(strncmp(err.message, want, strlen(want)) == 0);
    LH_NOTE("%s", err.message);
}

/* A segment 0 1 split at a rounded Steiner point 4 = (fl(1/3), 1, 0), not on the
 * line from (0 0 0) to (1 3 0): counted, not failed; as an input point it fails. */
LH_TEST(rounded_steiner_point_counted)
{
    tm m;
    memset(&m, 0, sizeof m);
    const double p[5][3] = {{0, 0, 0}, {1, 3, 0}, {0, 2, 1}, {1, 0, -1}, {1.0 / 3, 1, 0}};
    memcpy(m.xyz, p, sizeof p);
    m.n = 5;
    add_tet(&m, 0, 4, 2, 3), add_tet(&m, 4, 1, 2, 3);
    m.edges[0] = 0, m.edges[1] = 4, m.edges[2] = 4, m.edges[3] = 1;
    m.ne = 2;
    m.g.n = 4, m.g.xyz = m.xyz, m.g.segment_count = 1, m.g.segments = m.segs;
    m.segs[0] = 0, m.segs[1] = 1;
    size_t off = 0;
    lh_error err;
    LH_EXPECT_EQ_INT(run(&m, NULL, 1, &m.g, &off, &err), LH_OK);
    LH_EXPECT_EQ_U64(off, 1);
    m.g.n = 5;
    expect_msg(lh_t_, &m, NULL, 1, &m.g,
               "segment 0 (0 1) is not covered: its chain of subsegments from 0 stops at 0");
    /* a Steiner point 0.01 off the line is beyond rounding: a fault */
    m.g.n = 4;
    m.xyz[12] += 0.01;
    expect_msg(lh_t_, &m, NULL, 1, &m.g,
               "segment 0 (0 1) is not covered: its chain of subsegments from 0 stops at 0");
}

/* The square facet z = 0 split at a Steiner point 5 near its centre, under a
 * pyramid (apex 4): counted when the point is off the plane by rounding only, a
 * fault when further. */
LH_TEST(facet_steiner_point)
{
    for (int c = 0; c < 3; c++) {
        tm m;
        memset(&m, 0, sizeof m);
        const double z = c == 0 ? 0 : c == 1 ? 1e-17 : 1e-3;
        const double p[6][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}, {0.5, 0.5, z}};
        memcpy(m.xyz, p, sizeof p);
        m.n = 6;
        for (lh_index i = 0; i < 4; i++) {
            add_tet(&m, i, (i + 1) % 4, 5, 4);
            lh_index *f = m.faces + 3 * m.nf;
            f[0] = i, f[1] = (i + 1) % 4, f[2] = 5;
            m.par[m.nf++] = 0;
            m.edges[2 * m.ne] = i, m.edges[2 * m.ne++ + 1] = (i + 1) % 4;
        }
        const lh_index sq[4] = {0, 1, 2, 3};
        m.g.n = 4, m.g.xyz = m.xyz;
        m.g.facet_first = m.facet_first, m.g.polygon_first = m.polygon_first;
        m.g.polygon_vertices = m.polygon_vertices;
        add_facet(&m, sq, 4);
        size_t off = 9;
        lh_error err;
        for (int par = 0; par < (c == 0 ? 2 : 1); par++) { /* by containment: exact only */
            LH_EXPECT_EQ_INT(run(&m, par ? NULL : m.par, 1, &m.g, &off, &err),
                             c == 2 ? LH_ERR_INVALID_MESH : LH_OK);
            LH_EXPECT_EQ_U64(off, c == 1 ? 1 : 0);
        }
        if (c == 2)
            LH_EXPECT_STREQ(err.message, "facet 0 is not covered: a Steiner point off its plane "
                                         "beyond rounding (subface 0 (0 1 5))");
        /* a missing quarter */
        m.nf--;
        if (c == 0)
            expect_msg(lh_t_, &m, m.par, 1, &m.g,
                       "facet 0 is not covered: its 3 subfaces' area is smaller than the facet's");
    }
}

/* A square facet with a square hole (a hole point in it), its annulus in 8 subfaces
 * coned to an apex above the hole: the area is the annulus's; without the hole point
 * the inner square is a mere constraint and the annulus is short of the facet. */
LH_TEST(facet_with_hole)
{
    tm m;
    memset(&m, 0, sizeof m);
    const double p[9][3] = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {1, 1, 0},
                            {2, 1, 0}, {2, 2, 0}, {1, 2, 0}, {1.5, 1.5, 1}};
    memcpy(m.xyz, p, sizeof p);
    m.n = 9;
    for (lh_index k = 0; k < 4; k++) {
        const lh_index o0 = k, o1 = (k + 1) % 4, i0 = 4 + k, i1 = 4 + (k + 1) % 4;
        const lh_index tri[2][3] = {{o0, o1, i1}, {o0, i1, i0}};
        for (int j = 0; j < 2; j++) {
            add_tet(&m, tri[j][0], tri[j][1], tri[j][2], 8);
            memcpy(m.faces + 3 * m.nf, tri[j], sizeof tri[j]);
            m.par[m.nf++] = 0;
        }
        m.edges[2 * m.ne] = o0, m.edges[2 * m.ne++ + 1] = o1;
        m.edges[2 * m.ne] = i0, m.edges[2 * m.ne++ + 1] = i1;
    }
    for (lh_index i = 0; i < 8; i++) m.polygon_vertices[i] = i;
    m.facet_first[1] = 2, m.polygon_first[1] = 4, m.polygon_first[2] = 8;
    lh_index hole_first[2] = {0, 1};
    double hole[3] = {1.5, 1.5, 0};
    lh_plc *g = &m.g;
    g->n = 8, g->xyz = m.xyz, g->facet_count = 1, g->polygon_count = 2;
    g->facet_first = m.facet_first, g->polygon_first = m.polygon_first;
    g->polygon_vertices = m.polygon_vertices;
    g->facet_hole_first = hole_first, g->facet_holes = hole;
    expect_ok(lh_t_, &m, m.par, 1, g);
    expect_ok(lh_t_, &m, NULL, 1, g);
    g->facet_hole_first = NULL;
    expect_msg(lh_t_, &m, m.par, 1, g,
               "facet 0 is not covered: its 8 subfaces' area is smaller than the facet's");
}

LH_TEST(delaunay_meshes_pass)
{
    uint64_t s = 0x9e3779b97f4a7c15u;
    for (size_t n = 5; n <= 400; n *= 3) {
        double *xyz = malloc(3 * n * sizeof *xyz);
        LH_ASSERT_TRUE(xyz != NULL);
        for (size_t i = 0; i < 3 * n; i++) xyz[i] = (double)(lh_test_xorshift(&s) >> 11) * 0x1p-53;
        lh_plc g;
        memset(&g, 0, sizeof g);
        g.n = n, g.xyz = xyz;
        lh_tetmesh *out = NULL;
        lh_error err;
        LH_ASSERT_EQ_INT(lh_tetrahedralize(&g, NULL, &out, &err), LH_OK);
        size_t off = 9;
        LH_EXPECT_EQ_INT(lh_tetmesh_check(lh_tetmesh_point_count(out), lh_tetmesh_points(out),
                                          lh_tetmesh_tet_count(out), lh_tetmesh_tets(out),
                                          lh_tetmesh_face_count(out), lh_tetmesh_faces(out),
                                          lh_tetmesh_face_parents(out), lh_tetmesh_edge_count(out),
                                          lh_tetmesh_edges(out), 0, &g, &off, NULL, &err),
                         LH_OK);
        LH_EXPECT_STREQ(err.message, "");
        LH_EXPECT_EQ_U64(off, 0);
        /* one hull face fewer: the boundary is no longer all subfaces */
        LH_EXPECT_EQ_INT(lh_tetmesh_check(lh_tetmesh_point_count(out), lh_tetmesh_points(out),
                                          lh_tetmesh_tet_count(out), lh_tetmesh_tets(out),
                                          lh_tetmesh_face_count(out) - 1, lh_tetmesh_faces(out),
                                          NULL, 0, NULL, 0, NULL, NULL, NULL, &err),
                         LH_ERR_INVALID_MESH);
        LH_EXPECT_TRUE(strstr(err.message, "is not a subface") != NULL);
        lh_tetmesh_free(out);
        free(xyz);
    }
}

LH_TEST(arguments)
{
    lh_error err;
    LH_EXPECT_EQ_INT(lh_tetmesh_check(0, NULL, 0, NULL, 0, NULL, NULL, 0, NULL, 0, NULL, NULL, NULL, &err),
                     LH_OK);
    LH_EXPECT_EQ_INT(lh_tetmesh_check(3, NULL, 0, NULL, 0, NULL, NULL, 0, NULL, 0, NULL, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "xyz is NULL with a count above 0");
    const double xyz[6] = {0, 0, 0, 1, 0, 0};
    LH_EXPECT_EQ_INT(lh_tetmesh_check(2, xyz, 1, NULL, 0, NULL, NULL, 0, NULL, 0, NULL, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "tets is NULL with a count above 0");
    LH_EXPECT_EQ_INT(lh_tetmesh_check(2, xyz, 0, NULL, 0, NULL, NULL, 1, NULL, 0, NULL, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "edges is NULL with a count above 0");
    const lh_index e[2] = {0, 2};
    LH_EXPECT_EQ_INT(lh_tetmesh_check(2, xyz, 0, NULL, 0, NULL, NULL, 1, e, 0, NULL, NULL, NULL, &err),
                     LH_ERR_INVALID_MESH);
    LH_EXPECT_STREQ(err.message, "subsegment 0 (0 2) names point 2, not a point (0..1)");
    const double bad[3] = {0, 0, 1.0 / 0.0};
    LH_EXPECT_EQ_INT(lh_tetmesh_check(1, bad, 0, NULL, 0, NULL, NULL, 0, NULL, 0, NULL, NULL, NULL, &err),
                     LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "point 0 has a NaN or infinite coordinate");
    tm m;
    box(&m, 1);
    box_plc(&m, 1);
    m.polygon_vertices[3] = 9;
    LH_EXPECT_EQ_INT(run(&m, m.par, 0, &m.g, NULL, &err), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_STREQ(err.message, "the PLC is malformed: polygon vertex out of range at 3");
}

/* Every allocation failing in turn: LH_ERR_NOMEM, nothing leaked, then LH_OK. */
LH_TEST(allocation_failures)
{
    tm m;
    box(&m, 2);
    box_plc(&m, 2);
    for (int with_parents = 0; with_parents < 2; with_parents++) {
        lh_status st = LH_ERR_NOMEM;
        long k;
        for (k = 1; st == LH_ERR_NOMEM && k < 200; k++) {
            lh_test_counter c = {0};
            c.fail_at = k;
            lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
            lh_error err;
            st = lh_tetmesh_check(m.n, m.xyz, m.nt, m.tets, m.nf, m.faces, with_parents ? m.par : NULL,
                                  m.ne, m.edges, 0, &m.g, NULL, &a, &err);
            LH_EXPECT_EQ_INT(c.live, 0);
        }
        LH_EXPECT_EQ_INT(st, LH_OK);
        LH_EXPECT_GT_INT(k, 10);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(boxes_pass), LH_CASE(tet_faults), LH_CASE(overlapping_tets),
        LH_CASE(edge_winding), LH_CASE(subface_and_subsegment_faults), LH_CASE(conformity_faults),
        LH_CASE(carved_away_segment_passes), LH_CASE(facet_border_fault),
        LH_CASE(rounded_steiner_point_counted), LH_CASE(facet_steiner_point),
        LH_CASE(facet_with_hole),
        LH_CASE(delaunay_meshes_pass), LH_CASE(arguments), LH_CASE(allocation_failures)};
    int rc = lh_test_main(cases, LH_COUNT(cases), argc, argv);
    lh_pred_free(pred());
    return rc;
}
