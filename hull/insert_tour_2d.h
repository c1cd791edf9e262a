/*
 * insert_tour_2d.h — part of the insertion loop template (insert_impl.h), in the
 * builds whose dimension is 2 or a runtime value: the 2D cavity of a Delaunay
 * insertion as an Euler tour of its cells, linked as it is walked.
 *
 * A Delaunay insertion (inside_conflicts) never removes a vertex, so no vertex
 * lies inside the conflict region, a triangulated disk whose cells' dual graph is
 * therefore a tree. An Euler tour of that tree from
 * the located cell, taking each cell's edges in order (k, k+1, k+2 cyclically) from
 * the one after its entry edge, meets the boundary edges in order around the disk:
 * edge i = (v[k+1], v[k+2]) of its dead cell ends where edge i+1 starts. The new
 * cell (q, a_i, b_i) on edge i meets the new cells of edges i+1 and i-1 across its
 * other two edges, so the cells are linked without visit stamps or the ridge table.
 * A disk of m triangles has m + 2 boundary edges: the dead cells are reused in
 * place and two more are taken. Same cavity as cavity_insert (the same conflict
 * test on the same cells), so the same triangulation. The runtime-dimension build
 * takes it too when d = 2 (a choice made per insertion on t->nv, like the twins'),
 * except under hashed_ridges, which test_ridges sets to check cavity_insert's
 * 2D linking against it.
 */

/* Cell N := (q, a, b) in this cyclic order with neighbours (o, next, prev) opposite
 * them, rotated so that LH__INF, when present, comes first. */
static inline void set_fan_cell(lh__tds *t, lh_index N, const lh_index v3[3], const lh_index n3[3])
{
    int r = v3[1] == LH__INF ? 1 : v3[2] == LH__INF ? 2 : 0;
    lh_index *v = t->vert + (size_t)N * 3, *n = t->nbr + (size_t)N * 3;
    for (int j = 0; j < 3; j++) {
        int s = j + r < 3 ? j + r : j + r - 3;
        v[j] = v3[s];
        n[j] = n3[s];
    }
}

static const int8_t NEXT_3[3] = {1, 2, 0}; /* the next position, cyclically: a load, not a branch */

/* The tour from `start` (in conflict with q): dead cells in t->cells, boundary
 * edges in t->bound as (a, b, outside cell, index of the dead cell in its row).
 * Returns LH_OK, LH_ERR_NOMEM, LH__RETRY (a cell is another worker's), or
 * LH_ERR_INTERNAL should the region not be a tree. */
static lh_status tour_cavity_2(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
    size_t nb4 = 0, depth = 0;
    t->ncells = 0;
    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, start)) return LH_ERR_NOMEM;
    if (!push(t, &t->fresh, &t->fresh_cap, &depth, start) || !push(t, &t->fresh, &t->fresh_cap, &depth, 3))
        return LH_ERR_NOMEM; /* frames: cell, then next edge << 2 | edges left */
    while (depth) {
        lh_index c = t->fresh[depth - 2], f = t->fresh[depth - 1];
        int k = (int)(f >> 2), left = (int)(f & 3);
        if (!left) {
            depth -= 2;
            continue;
        }
        t->fresh[depth - 1] = (lh_index)(NEXT_3[k] << 2 | (left - 1));
        lh_index n = t->nbr[(size_t)c * 3 + k];
        LH__PREFETCH(t->nbr + (size_t)n * 3);
        int cf = HOLD(e, n) ? conflict(e, n) : -1;
        if (cf < 0) return LH__RETRY;
        if (cf) {
            if (t->ncells >= (size_t)t->live) return LH_ERR_INTERNAL; /* not a tree */
            int j = row_pos(t->nbr + (size_t)n * 3, 3, c);
            if (!push(t, &t->cells, &t->cells_cap, &t->ncells, n) ||
                !push(t, &t->fresh, &t->fresh_cap, &depth, n) ||
                !push(t, &t->fresh, &t->fresh_cap, &depth, (lh_index)(NEXT_3[j] << 2 | 2)))
                return LH_ERR_NOMEM;
            continue;
        }
        const lh_index *cv = t->vert + (size_t)c * 3;
        lh_index rec[4] = {cv[NEXT_3[k]], cv[NEXT_3[NEXT_3[k]]], n, row_pos(t->nbr + (size_t)n * 3, 3, c)};
        for (int x = 0; x < 4; x++)
            if (!push(t, &t->bound, &t->bound_cap, &nb4, rec[x])) return LH_ERR_NOMEM;
    }
    t->nbound = nb4 / 4;
    return t->nbound == t->ncells + 2 ? LH_OK : LH_ERR_INTERNAL;
}

static lh_status cavity_insert_2(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
    lh_status st = tour_cavity_2(e, start);
    if (st == LH_OK) st = lh__tds_room(t);
    if (st != LH_OK) return st;
    const size_t nb = t->nbound;
    for (size_t i = 0; i < nb; i++) t->fresh[i] = i < t->ncells ? t->cells[i] : lh__tds_new_cell(t);
    for (size_t i = 0; i < nb; i++) {
        const lh_index *r = t->bound + 4 * i;
        lh_index v3[3] = {e->q, r[0], r[1]};
        lh_index n3[3] = {r[2], t->fresh[i + 1 < nb ? i + 1 : 0], t->fresh[i ? i - 1 : nb - 1]};
        set_fan_cell(t, t->fresh[i], v3, n3);
        t->nbr[(size_t)r[2] * 3 + r[3]] = t->fresh[i];
    }
    return LH_OK;
}
