/*
 * insert_region.h — part of the insertion loop template (insert_impl.h): the
 * conflict region of e->q and its boundary.
 *
 * The region grows depth-first from the located cell through facets (Bowyer 1981;
 * Watson 1981): its cells are marked in, the tested neighbours out, so each cell is
 * tested once per insertion. Each boundary facet (c, k) (c in, its neighbour across
 * k out) later becomes the new cell c with vertex k replaced by q, which keeps c's
 * orientation. The region is connected and, for Delaunay, star-shaped from q.
 */

/* What the conflict search reads of cell c first: its visit mark (written: it is
 * set, and in a parallel worker taken by CAS) and its vertices. */
static LH__ALWAYS_INLINE void prefetch_cell(const lh__tds *t, int nv, lh_index c)
{
    LH__PREFETCH_W(t->stamp + c);
    LH__PREFETCH(t->vert + (size_t)c * nv);
}

/* The conflict tests of c's finite neighbours not yet visited, two cells at a time
 * (LH_T_FINITE_CONFLICT2), into x[k] for the neighbour across facet k; x[k] = -1
 * where grow_region tests it itself (visited, infinite, or the odd one left).
 * Same tests, same answers as one at a time: pairing only lets the two cells'
 * static filters share their evaluation (docs/bench-engine.md). Returns 0
 * when a neighbour is another worker's. */
static LH__ALWAYS_INLINE int pair_tests(lh__eng *e, lh_index c, uint32_t in, uint32_t out, int *x)
{
    const lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    const lh_index *nb = t->nbr + (size_t)c * nv;
    int wait = -1; /* a facet whose neighbour waits for a second one */
    for (int k = 0; k < nv; k++) {
        x[k] = -1;
        const lh_index n = nb[k];
        if (!HOLD(e, n)) return 0;
        const uint32_t st = MARK(t, n);
        const lh_index *v = t->vert + (size_t)n * nv;
        if (st == in || st == out || v[0] == LH__INF) continue;
        if (wait < 0) {
            wait = k;
            continue;
        }
        int two[2];
        LH_T_FINITE_CONFLICT2(e, t->vert + (size_t)nb[wait] * nv, v, e->q, two);
        x[wait] = two[0], x[k] = two[1];
        wait = -1;
    }
    return 1;
}

/* The conflict region from `start`: t->cells, and its boundary facets as pairs
 * (cell, k) in t->bound. Returns 1; 0 when memory runs out; -1 when a cell it
 * reaches is another worker's. */
static int grow_region(lh__eng *e, lh_index start, uint32_t in, uint32_t out)
{
    lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    t->ncells = t->nbound = 0;
    size_t nb2 = 0;
    SET_MARK(t, start, in);
    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, start)) return 0;
    for (size_t i = 0; i < t->ncells; i++) {
        lh_index c = t->cells[i];
        /* the misses of c's neighbours overlap; those of the cell two ahead in the
           queue are taken now, to arrive while c and the next are tested (two
           ahead hides more of the latency than one: docs/bench-engine.md) */
        for (int k = 0; k < nv; k++) prefetch_cell(t, nv, t->nbr[(size_t)c * nv + k]);
        if (i + 2 < t->ncells) {
            const lh_index *nn = t->nbr + (size_t)t->cells[i + 2] * nv;
            for (int k = 0; k < nv; k++) prefetch_cell(t, nv, nn[k]);
        }
        int paired[LH__TDS_MAX_NV];
        if (!pair_tests(e, c, in, out, paired)) return -1; /* holds every neighbour */
        for (int k = 0; k < nv; k++) {
            lh_index n = t->nbr[(size_t)c * nv + k];
            uint32_t st = MARK(t, n);
            if (st == in) continue;
            if (st != out) {
                int x = paired[k] >= 0 ? paired[k] : conflict(e, n);
                if (x < 0) return -1;
                if (x) {
                    SET_MARK(t, n, in);
                    LH__PREFETCH(t->nbr + (size_t)n * nv); /* read when n is expanded */
                    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, n)) return 0;
                    continue;
                }
                SET_MARK(t, n, out);
            }
            if (!push(t, &t->bound, &t->bound_cap, &nb2, c) || !push(t, &t->bound, &t->bound_cap, &nb2, k))
                return 0;
        }
    }
    t->nbound = nb2 / 2;
    return 1;
}
