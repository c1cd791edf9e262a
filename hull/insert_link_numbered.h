/*
 * insert_link_numbered.h — part of the insertion loop template (insert_impl.h):
 * linking the new cells of a Delaunay insertion in 4D and up (and in 3D when
 * twin keys do not fit) by the cavity boundary's own numbering of its vertices,
 * for a boundary of at most 255 vertices (else insert_link_turning.h).
 */

/* The ridge keys of new cell b into keys[0..nv-2] (the ridge opposite the i-th old
 * vertex, in position order), from the numbers of its old vertices on the cavity's
 * boundary: t->vloc holds a vertex's number (1..255, 0: none yet), seen[0..*nid-1]
 * the vertices numbered. A key is the ridge's numbers, increasing, 8 bits each (56
 * bits at most in 8D): equal keys, equal ridges. Read from the dead cell of
 * boundary facet b, before the cone overwrites it. Returns 0 when the numbers run
 * out. */
static inline int number_ridges(lh__tds *t, size_t b, uint64_t *keys, lh_index *seen, int *nid)
{
    const int nv = LH_T_NV(t);
    const int M = nv - 1, k = (int)t->bound[2 * b + 1];
    const lh_index *v = t->vert + (size_t)t->bound[2 * b] * nv; /* the dead cell's */
    unsigned id[LH__ENGINE_MAX_DIM], rank[LH__ENGINE_MAX_DIM];
    for (int i = 0; i < M; i++) {
        const lh_index x = v[i + (i >= k)]; /* the i-th old vertex, without a branch on k */
        uint8_t *l = t->vloc + (x + 1);
        const unsigned had = *l;
        seen[*nid] = x;
        *nid += had == 0;
        id[i] = had ? had : (unsigned)*nid;
        *l = (uint8_t)id[i];
        rank[i] = 0;
    }
    if (*nid > 255) return 0;
    for (int a = 0; a < M; a++)
        for (int c = a + 1; c < M; c++) {
            const unsigned above = id[a] > id[c];
            rank[a] += above, rank[c] += !above;
        }
    uint64_t all = 0;
    for (int i = 0; i < M; i++) all |= (uint64_t)id[i] << (8 * rank[i]);
    for (int i = 0; i < M; i++) { /* all without its byte rank[i] */
        const uint64_t low = ((uint64_t)1 << (8 * rank[i])) - 1;
        keys[i] = (all & low) | (all >> 8 & ~low);
    }
    return 1;
}

/* Pairs the new cells of a Delaunay insertion in 4D and up (and in 3D beyond 2^32
 * sites, where link_twins's keys do not fit) by their ridges' keys
 * (number_ridges): the boundary's vertices are numbered as they are met, so a
 * ridge's key is its numbers in order, exact, in one word, with no sort of the
 * cell's vertices (link_new_cells) and no walk through the dead cells
 * (link_by_turning, whose chain of dependent loads is the slower).
 * number_boundary takes the keys, from the dead cells, before the cone;
 * link_numbered enters them in the ridge table (a prefix at most 1/8 full) in
 * order, each slot prefetched 16 keys ahead. The first of a pair to arrive claims
 * a slot; the second finds it, links both cells, and flags it paired: both
 * without a branch on which one arrives first (such a branch guesses wrong half
 * the time). Every ridge of the closed boundary is in exactly two new cells; the
 * count of pairs checks it. Keys go in t->sorted (LH__SORTED_ROOM). */

/* The keys of every boundary facet's ridges. Returns 1; 0, with t->vloc cleared
 * again, when the boundary has more than 255 vertices (link_by_turning then). */
static int number_boundary(lh__tds *t)
{
    const int nv = LH_T_NV(t);
    const int M = nv - 1;
    uint64_t *keys = (uint64_t *)t->sorted;
    lh_index seen[255 + LH__ENGINE_MAX_DIM];
    int nid = 0, ok = 1;
    for (size_t b = 0; b < t->nbound && ok; b++) ok = number_ridges(t, b, keys + b * M, seen, &nid);
    for (int i = 0; i < nid; i++) t->vloc[seen[i] + 1] = 0;
    return ok;
}

/* Links the new cells t->fresh[] by the keys of number_boundary. Returns 1; 0
 * when a ridge is not in exactly two cells (as link_twins). */
static int link_numbered(lh__tds *t)
{
    const int nv = LH_T_NV(t);
    const int M = nv - 1;
    const size_t nb = t->nbound, nk = nb * (size_t)M, ahead = 16;
    const uint64_t *keys = (const uint64_t *)t->sorted;
    lh_index sink[2];
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots(nk / 2) - 1; /* nk / 2 ridges */
    size_t paired = 0;
    for (size_t r = 0; r < nk && r < ahead; r++) LH__PREFETCH_W(t->ridge + (ridge_slot(keys[r]) & mask));
    for (size_t b = 0; b < nb; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index N = t->fresh[b];
        for (int i = 0; i < M; i++) {
            const size_t r = b * M + i;
            if (r + ahead < nk) LH__PREFETCH_W(t->ridge + (ridge_slot(keys[r + ahead]) & mask));
            const int j = i + (i >= k);
            const uint64_t key = keys[r];
            size_t h = ridge_slot(key) & mask;
            while ((t->ridge[h].round == round) & (t->ridge[h].key != key)) h = (h + 1) & mask;
            const lh__ridge met = t->ridge[h];
            const int second = met.round == round;
            paired += (size_t)second;
            t->ridge[h] = (lh__ridge){key | (uint64_t)second << 63, round, (uint32_t)b << 4 | (uint32_t)j};
            const lh_index O = t->fresh[second ? met.bd >> 4 : 0];
            *(second ? t->nbr + (size_t)N * nv + j : sink) = O;
            *(second ? t->nbr + (size_t)O * nv + (met.bd & 15) : sink + 1) = N;
        }
    }
    return 2 * paired == nk;
}
