/*
 * second_order.c — second-order nodes (TetGen's -o2): a node at the midpoint of every
 * edge of the mesh's tetrahedra, appended to its points, for the ten-node
 * (quadratic) tetrahedra of finite elements. The edges are numbered in the order of
 * their endpoints (p < q, lexicographic), so the nodes depend on the mesh alone. A
 * node's marker: its subsegment's, else the first subface's it lies in, else 0.
 */
#include "lh_sort.h"
#include "t3.h"

#include <stddef.h>
#include <string.h>

/* Tet corners of edge k: VTK's quadratic tetrahedron order. */
static const int EDGE[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

typedef struct edge_rec {
    lh_index p, q; /* p < q */
    lh_index at;   /* 6 tet + k */
} edge_rec;

static edge_rec edge_of(lh_index a, lh_index b, lh_index at)
{
    edge_rec e = {a < b ? a : b, a < b ? b : a, at};
    return e;
}

/* The mesh's edges in order: *rec (6 per tet, sorted), equal edges together. */
static lh_status sorted_edges(lh_tetmesh *m, size_t n, edge_rec **rec)
{
    const size_t count = 6 * m->tet_count;
    lh_status st = lh__tetmesh_array(m, (void **)rec, count, sizeof **rec);
    for (size_t t = 0; st == LH_OK && t < m->tet_count; t++)
        for (int k = 0; k < 6; k++)
            (*rec)[6 * t + (size_t)k] =
                edge_of(m->tets[4 * t + (size_t)EDGE[k][0]], m->tets[4 * t + (size_t)EDGE[k][1]],
                        (lh_index)(6 * t + (size_t)k));
    if (st == LH_OK)
        st = lh__sort_by_index(&m->alloc, *rec, count, sizeof **rec, offsetof(edge_rec, q), n);
    if (st == LH_OK)
        st = lh__sort_by_index(&m->alloc, *rec, count, sizeof **rec, offsetof(edge_rec, p), n);
    return st;
}

/* Room for the added nodes: xyz and markers grown to n + added. */
static lh_status grow_points(lh_tetmesh *m, size_t added)
{
    double *xyz = NULL;
    lh_index *mk = NULL;
    lh_status st = lh__tetmesh_array(m, (void **)&xyz, 3 * (m->n + added), sizeof *xyz);
    if (st == LH_OK) st = lh__tetmesh_array(m, (void **)&mk, m->n + added, sizeof *mk);
    if (st != LH_OK) {
        lh__free(&m->alloc, xyz);
        return st;
    }
    if (m->n)
        memcpy(xyz, m->xyz, 3 * m->n * sizeof *xyz), memcpy(mk, m->point_marker, m->n * sizeof *mk);
    lh__free(&m->alloc, m->xyz), lh__free(&m->alloc, m->point_marker);
    m->xyz = xyz, m->point_marker = mk;
    return LH_OK;
}

/* Marks the midpoint of edge a b with mark unless it has one (or always, `over`). */
static void mark(lh_tetmesh *m, lh_index a, lh_index b, lh_index mk, int over)
{
    const lh_index x = lh_tetmesh_midpoint(m, a, b);
    if (x >= 0 && (over || m->point_marker[x] == 0)) m->point_marker[x] = mk;
}

lh_status lh__tetmesh_second_order(lh_tetmesh *m)
{
    const size_t n = m->n, count = 6 * m->tet_count;
    edge_rec *rec = NULL;
    lh_status st = sorted_edges(m, n, &rec);
    size_t edges = 0;
    for (size_t i = 0; st == LH_OK && i < count; i++)
        edges += i == 0 || rec[i].p != rec[i - 1].p || rec[i].q != rec[i - 1].q;
    if (st == LH_OK && edges > (size_t)LH_INDEX_MAX - n) st = LH_ERR_TOO_LARGE;
    if (st == LH_OK) st = lh__tetmesh_array(m, (void **)&m->tet_mid, count, sizeof *m->tet_mid);
    if (st == LH_OK)
        st = lh__tetmesh_array(m, (void **)&m->mid_edges, 2 * edges, sizeof *m->mid_edges);
    if (st == LH_OK) st = grow_points(m, edges);
    for (size_t i = 0, e = 0; st == LH_OK && i < count; i++) {
        if (i && (rec[i].p != rec[i - 1].p || rec[i].q != rec[i - 1].q)) e++;
        m->tet_mid[rec[i].at] = (lh_index)(n + e);
        m->mid_edges[2 * e] = rec[i].p, m->mid_edges[2 * e + 1] = rec[i].q;
        const double *a = m->xyz + 3 * (size_t)rec[i].p, *b = m->xyz + 3 * (size_t)rec[i].q;
        for (int k = 0; k < 3; k++) m->xyz[3 * (n + e) + (size_t)k] = 0.5 * a[k] + 0.5 * b[k];
        m->point_marker[n + e] = 0;
    }
    lh__free(&m->alloc, rec);
    if (st != LH_OK) return st;
    m->n_corners = n, m->n = n + edges;
    for (size_t f = 0; f < m->face_count; f++)
        for (int k = 0; k < 3; k++)
            mark(m, m->faces[3 * f + (size_t)k], m->faces[3 * f + (size_t)(k + 1) % 3],
                 m->face_marker[f], 0);
    for (size_t s = 0; s < m->edge_count; s++)
        mark(m, m->edges[2 * s], m->edges[2 * s + 1], m->edge_marker[s], 1);
    return LH_OK;
}

/* The midpoint node of edge a b: binary search in the sorted edges. */
lh_index lh_tetmesh_midpoint(const lh_tetmesh *m, lh_index a, lh_index b)
{
    if (!m || !m->mid_edges) return -1;
    const lh_index p = a < b ? a : b, q = a < b ? b : a;
    size_t lo = 0, hi = m->n - m->n_corners;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        const lh_index *e = m->mid_edges + 2 * mid;
        if (e[0] < p || (e[0] == p && e[1] < q))
            lo = mid + 1;
        else
            hi = mid;
    }
    const lh_index *e = m->mid_edges + 2 * lo;
    return lo < m->n - m->n_corners && e[0] == p && e[1] == q ? (lh_index)(m->n_corners + lo) : -1;
}

const lh_index *lh_tetmesh_tet_midpoints(const lh_tetmesh *m)
{
    return m ? m->tet_mid : NULL;
}
