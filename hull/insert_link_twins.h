/*
 * insert_link_twins.h — part of the insertion loop template (insert_impl.h):
 * linking the new cells in 2D and 3D as twins. In 2D and 3D a ridge is a vertex or
 * an edge, oriented by each of its two new cells the opposite way: the two are
 * twins in a table of oriented ridges (link_twins). In 3D, while the boundary has
 * at most LH__EDGE_IDS vertices, that table is indexed by the boundary's own
 * numbering of its vertices, and the cone is built and linked in one pass with q
 * moved last in every new cell (cone_local).
 */

/* Pairing the new cells as twins, in 2D and 3D. The new cell made from boundary
 * facet (c, k) carries that facet; the facets tile the cavity's boundary, a closed
 * pseudo-manifold, and each is oriented by its cell (two cells oriented alike
 * induce opposite orientations on the facet they share: the boundary operator of
 * simplicial homology). In 3D the cell's facet opposite position j (j != k) holds q
 * and the boundary triangle's edge TWIN_EDGE[k][j] = (a, b), directed so that the
 * neighbour across that facet holds the same edge as (b, a); in 2D it holds q and
 * the boundary edge's end TWIN_VERTEX[k][j] = a, with a sign (a is the edge's first
 * or last vertex) that is the other one in the neighbour. Every new cell enters its
 * keys in the ridge table (a prefix at most 1/8 full: lh__ridge_slots), then finds
 * its neighbours under the reversed keys. No branch depends on which cell of a
 * pair comes first, unlike turning (link_by_turning, whose loop ends are
 * unpredictable) or link_new_cells. In 4D and up, where a
 * ridge's vertices must first be put in a canonical order, number_ridges does
 * that on small numbers. The 3D key needs 2 vbits <= 64. Returns 0 if a key has
 * no twin. */
static const int8_t TWIN_EDGE[4][4][2] = {
    /* positions {0..3} \ {k, j}, increasing, exchanged when j + (k, or k - 1 when
       j < k) is odd: the facet opposite j is (-1)^j times its vertices in order */
    {{0, 0}, {3, 2}, {1, 3}, {2, 1}},
    {{2, 3}, {0, 0}, {3, 0}, {0, 2}},
    {{3, 1}, {0, 3}, {0, 0}, {1, 0}},
    {{1, 2}, {2, 0}, {0, 1}, {0, 0}},
};
static const int8_t TWIN_VERTEX[3][3][2] = { /* position {0..2} \ {k, j}, parity */
    {{0, 0}, {2, 1}, {1, 0}},
    {{2, 0}, {0, 0}, {0, 1}},
    {{1, 1}, {0, 0}, {0, 0}},
};

/* The key of new cell v's ridge opposite position j (its new vertex at k), reversed
 * when `rev`, and its slot. nv: 3 or 4, a constant where link_twins is inlined. */
static inline size_t twin_slot(const lh__tds *t, const lh_index *v, int nv, int k, int j, int rev, uint64_t *key)
{
    if (nv == 3) {
        const int8_t *p = TWIN_VERTEX[k][j];
        *key = (uint64_t)(lh__uindex)(v[p[0]] + 1) << 1 | (uint64_t)(p[1] ^ rev);
    } else {
        const int8_t *e = TWIN_EDGE[k][j];
        *key = (uint64_t)(lh__uindex)(v[e[rev]] + 1) << t->vbits | (uint64_t)(lh__uindex)(v[e[!rev]] + 1);
    }
    return ridge_slot(*key);
}

static inline int link_twins(lh__tds *t, const int nv)
{
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots((size_t)(nv - 1) * t->nbound) - 1;
    for (size_t b = 0; b < t->nbound; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index *v = t->vert + (size_t)t->fresh[b] * nv;
        for (int i = 1; i < nv; i++) {
            const int j = k + i < nv ? k + i : k + i - nv;
            uint64_t key;
            size_t h = twin_slot(t, v, nv, k, j, 0, &key) & mask;
            while (t->ridge[h].round == round) h = (h + 1) & mask;
            t->ridge[h] = (lh__ridge){key, round, (uint32_t)b << 4 | (uint32_t)j};
        }
    }
    for (size_t b = 0; b < t->nbound; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index N = t->fresh[b], *v = t->vert + (size_t)N * nv;
        for (int i = 1; i < nv; i++) {
            const int j = k + i < nv ? k + i : k + i - nv;
            uint64_t key;
            size_t h = twin_slot(t, v, nv, k, j, 1, &key) & mask;
            for (;; h = (h + 1) & mask) {
                if (t->ridge[h].round != round) return 0;
                if (t->ridge[h].key == key) break;
            }
            t->nbr[(size_t)N * nv + j] = t->fresh[t->ridge[h].bd >> 4];
        }
    }
    return 1;
}

/* QLAST[k]: the positions in old cell c of new cell N's vertices when q, which
 * takes c's position k, is moved last (cone_local): an even permutation, so N keeps
 * c's orientation, that fixes position 0 (LH__INF's) unless k = 0. */
static const int8_t QLAST[4][4] = {{2, 1, 3, 0}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 1, 2, 3}};

/* The cone and its links in 3D without hashing. Each new cell has q at position 3
 * (QLAST), so its boundary triangle (0, 1, 2) is directed by TWIN_EDGE[3]: 1 -> 2,
 * 2 -> 0 and 0 -> 1, opposite positions 0, 1 and 2. The boundary's vertices are
 * numbered 1..LH__EDGE_IDS as they are met (t->vloc), and the directed edge (a, b)
 * is the slot a << LH__EDGE_BITS | b of t->edge, which holds b + 1 for the new cell
 * of boundary facet b until its twin (b, a) reads it. Both arrays are zero between
 * insertions: every number is cleared at the end, and every slot written is
 * cleared by its one reader (3 nbound reads, each clearing a nonzero slot, clear
 * 3 nbound distinct slots: all those written). A closed boundary of V vertices has
 * 2V - 4 triangles, so the numbers suffice for up to 122 new cells.
 * First every boundary facet is read and numbered, and what its new cell needs is
 * kept in t->sorted's room (its three old vertices, the outside cell, the dead
 * cell's position there and the numbers); then the dead cells are reused in place
 * for the first new cells, as many as there are (no free list walked, nothing
 * killed but the rest), and the twins are read. Returns 1; 0 when there are more
 * vertices (nothing changed: the general cone then); -1 when an edge has no twin. */
static int cone_local(lh__eng *e)
{
    lh__tds *t = &e->tds;
    uint8_t *loc = t->vloc;
    uint32_t *edge = t->edge;
    lh_index seen[LH__EDGE_IDS + 3];
    int nid = 0, ok = 1;
    const size_t nb = t->nbound, reuse = t->ncells < nb ? t->ncells : nb;
    for (size_t b = 0; b < nb; b++) {
        const lh_index c = t->bound[2 * b], *cv = t->vert + (size_t)c * 4;
        const int k = (int)t->bound[2 * b + 1];
        lh_index *keep = t->sorted + 5 * b;
        unsigned id[3];
        for (int j = 0; j < 3; j++) {
            const lh_index v = cv[QLAST[k][j]];
            uint8_t *x = loc + (v + 1);
            const uint8_t had = *x;
            seen[nid] = keep[j] = v;
            nid += had == 0;
            id[j] = *x = had ? had : (uint8_t)nid;
        }
        ok = nid <= LH__EDGE_IDS;
        if (!ok) break;
        edge[id[1] << LH__EDGE_BITS | id[2]] = (uint32_t)b + 1;
        edge[id[2] << LH__EDGE_BITS | id[0]] = (uint32_t)b + 1;
        edge[id[0] << LH__EDGE_BITS | id[1]] = (uint32_t)b + 1;
        const lh_index out = t->nbr[(size_t)c * 4 + k];
        keep[3] = out;
        keep[4] = (lh_index)((unsigned)row_pos(t->nbr + (size_t)out * 4, 4, c) | id[0] << 2 | id[1] << 10 | id[2] << 18);
    }
    for (size_t b = 0; b < nb && ok; b++) {
        const lh_index *keep = t->sorted + 5 * b;
        const lh_index N = b < reuse ? t->cells[b] : lh__tds_new_cell(t); /* room: lh__tds_room */
        lh_index *nw = t->vert + (size_t)N * 4, *nn = t->nbr + (size_t)N * 4;
        nw[0] = keep[0], nw[1] = keep[1], nw[2] = keep[2], nw[3] = e->q;
        nn[3] = keep[3];
        t->nbr[(size_t)keep[3] * 4 + (keep[4] & 3)] = N;
        t->fresh[b] = N;
    }
    for (size_t b = 0; b < nb && ok; b++) {
        const unsigned w = (unsigned)t->sorted[5 * b + 4], id0 = w >> 2 & 255, id1 = w >> 10 & 255, id2 = w >> 18;
        lh_index *nn = t->nbr + (size_t)t->fresh[b] * 4;
        uint32_t *slot[3] = {edge + (id2 << LH__EDGE_BITS | id1), edge + (id0 << LH__EDGE_BITS | id2),
                             edge + (id1 << LH__EDGE_BITS | id0)};
        for (int j = 0; j < 3; j++) {
            const uint32_t m = *slot[j];
            *slot[j] = 0;
            if (!m) ok = -1;
            else nn[j] = t->fresh[m - 1];
        }
    }
    for (int s = 0; s < nid; s++) loc[seen[s] + 1] = 0; /* nid < LH__EDGE_IDS + 3 */
    if (ok <= 0) memset(edge, 0, LH__EDGE_SLOTS * sizeof *edge);
    if (ok > 0)
        for (size_t i = reuse; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return ok;
}
