/* tetgen_items.c — every face or every edge of a tetrahedral mesh once, as TetGen's
 * -f and -e list them (tetgen_io.h): tetrahedron by tetrahedron, each item where it
 * is first met, with the marker of the subface or subsegment it is (0 if none).
 * Faces: the one opposite corner j of tetrahedron t is listed at t when the
 * neighbour across it is none or comes later; edges: the six of each tetrahedron,
 * duplicates found by sorting (ordered pair, first appearance). */
#include "tetgen_io.h"

#include <stdlib.h>
#include <string.h>

/* An item's sorted vertices (k+1 used, k <= 2), its marker or its first appearance. */
typedef struct key {
    lh_index v[3];
    size_t tag;
} key;

static int cmp_key(const void *pa, const void *pb)
{
    const key *a = pa, *b = pb;
    for (int j = 0; j < 3; j++)
        if (a->v[j] != b->v[j]) return a->v[j] < b->v[j] ? -1 : 1;
    return a->tag < b->tag ? -1 : a->tag > b->tag;
}

static key make_key(const lh_index *v, int per, size_t tag)
{
    key k = {{v[0], per > 1 ? v[1] : -1, per > 2 ? v[2] : -1}, tag};
    for (int i = 1; i < per; i++) /* insertion sort of at most 3 */
        for (int j = i; j > 0 && k.v[j - 1] > k.v[j]; j--) {
            lh_index t = k.v[j];
            k.v[j] = k.v[j - 1];
            k.v[j - 1] = t;
        }
    return k;
}

/* The marked items (subfaces or subsegments), sorted, tag = marker; NULL when out
 * of memory. */
static key *marked(const lh_index *v, const lh_index *mark, size_t n, int per)
{
    key *k = malloc((n ? n : 1) * sizeof *k);
    if (!k) return NULL;
    for (size_t i = 0; i < n; i++) k[i] = make_key(v + (size_t)per * i, per, (size_t)mark[i]);
    qsort(k, n, sizeof *k, cmp_key);
    return k;
}

static lh_index marker_of(const key *sorted, size_t n, const lh_index *v, int per)
{
    key q = make_key(v, per, 0);
    size_t lo = 0, hi = n; /* first element >= q (tag 0 sorts first among equals) */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cmp_key(&sorted[mid], &q) < 0) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && !memcmp(sorted[lo].v, q.v, sizeof q.v) ? (lh_index)sorted[lo].tag : 0;
}

/* Corners of the face opposite corner j, ordered so that its normal points out of
 * the (positively oriented) tetrahedron. */
static const int face_corner[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
static const int edge_corner[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

static int faces(lh_cli_items *it, const lh_tetmesh *m)
{
    const size_t nt = lh_tetmesh_tet_count(m), ns = lh_tetmesh_face_count(m);
    const lh_index *t = lh_tetmesh_tets(m), *nb = lh_tetmesh_neighbors(m);
    key *sub = marked(lh_tetmesh_faces(m), lh_tetmesh_face_markers(m), ns, 3);
    it->v = malloc((4 * nt + 1) * 3 * sizeof *it->v);
    it->mark = malloc((4 * nt + 1) * sizeof *it->mark);
    if (!sub || !it->v || !it->mark) {
        free(sub);
        return 0;
    }
    for (size_t i = 0; i < nt; i++)
        for (int j = 0; j < 4; j++) {
            if (nb[4 * i + j] >= 0 && (size_t)nb[4 * i + j] < i) continue;
            lh_index *v = it->v + 3 * it->n;
            for (int c = 0; c < 3; c++) v[c] = t[4 * i + face_corner[j][c]];
            it->mark[it->n++] = marker_of(sub, ns, v, 3);
        }
    free(sub);
    return 1;
}

static int cmp_tag(const void *pa, const void *pb)
{
    const key *a = pa, *b = pb;
    return a->tag < b->tag ? -1 : a->tag > b->tag;
}

static int edges(lh_cli_items *it, const lh_tetmesh *m)
{
    const size_t nt = lh_tetmesh_tet_count(m), ns = lh_tetmesh_edge_count(m);
    const lh_index *t = lh_tetmesh_tets(m);
    key *sub = marked(lh_tetmesh_edges(m), lh_tetmesh_edge_markers(m), ns, 2);
    key *all = malloc((6 * nt + 1) * sizeof *all);
    it->v = malloc((6 * nt + 1) * 2 * sizeof *it->v);
    it->mark = malloc((6 * nt + 1) * sizeof *it->mark);
    if (!sub || !all || !it->v || !it->mark) {
        free(sub);
        free(all);
        return 0;
    }
    for (size_t i = 0; i < nt; i++)
        for (int j = 0; j < 6; j++) {
            const lh_index v[2] = {t[4 * i + edge_corner[j][0]], t[4 * i + edge_corner[j][1]]};
            all[6 * i + (size_t)j] = make_key(v, 2, 6 * i + (size_t)j);
        }
    qsort(all, 6 * nt, sizeof *all, cmp_key);
    size_t u = 0;
    for (size_t i = 0; i < 6 * nt; i++)
        if (i == 0 || all[i].v[0] != all[i - 1].v[0] || all[i].v[1] != all[i - 1].v[1]) all[u++] = all[i];
    qsort(all, u, sizeof *all, cmp_tag); /* back to the order of first appearance */
    for (size_t i = 0; i < u; i++) {
        const size_t at = all[i].tag;
        lh_index *v = it->v + 2 * i;
        v[0] = t[4 * (at / 6) + edge_corner[at % 6][0]];
        v[1] = t[4 * (at / 6) + edge_corner[at % 6][1]];
        it->mark[i] = marker_of(sub, ns, v, 2);
    }
    it->n = u;
    free(sub);
    free(all);
    return 1;
}

int lh_cli_items_build(lh_cli_items *it, const lh_tetmesh *m, int k)
{
    memset(it, 0, sizeof *it);
    const int ok = k == 2 ? faces(it, m) : edges(it, m);
    if (!ok) lh_cli_items_free(it);
    return ok;
}

void lh_cli_items_free(lh_cli_items *it)
{
    free(it->v);
    free(it->mark);
    memset(it, 0, sizeof *it);
}
