/*
 * insert_cone.h — part of the insertion loop template (insert_impl.h): the cone of
 * new cells over the conflict region's boundary (Bowyer 1981; Watson 1981), and
 * the choice of how its cells are linked (docs/engine.md, "Paths of the insertion
 * loop").
 */

/* The cone: the new cell t->fresh[b] is boundary facet b's dead cell c with vertex
 * k replaced by q, linked to the outside cell across k and to nothing else yet.
 * grow_region lists the boundary facets cell by cell in the order of t->cells, so
 * once facet b of cells[i] is reached, cells[0..i-1] have been read for the last
 * time: with `reuse`, they are overwritten in place as the next new cells (no free
 * list walked: its pops are a chain of dependent loads), and only the rest come
 * from lh__tds_new_cell. The last dead cell with a boundary facet is never reused
 * (it is still being read when the last new cell is made). Without `reuse`, the
 * dead cells stay as they are (turning walks through them). Returns the number of
 * dead cells reused, the first of t->cells; the caller kills the others. */
static size_t make_cone(lh__eng *e, int reuse)
{
    lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    size_t done = 0, used = 0;
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index c = t->bound[2 * b], k = t->bound[2 * b + 1];
        while (reuse && t->cells[done] != c) done++;
        /* cannot fail after lh__tds_room */
        const lh_index N = used < done ? t->cells[used++] : lh__tds_new_cell(t);
        lh_index *nvert = t->vert + (size_t)N * nv, *nnbr = t->nbr + (size_t)N * nv;
        const lh_index *cv = t->vert + (size_t)c * nv, outside = t->nbr[(size_t)c * nv + k];
        for (int j = 0; j < nv; j++) nvert[j] = cv[j], nnbr[j] = -1;
        nvert[k] = e->q;
        nnbr[k] = outside;
        lh_index *on = t->nbr + (size_t)outside * nv;
        on[row_pos(on, nv, c)] = N;
        t->fresh[b] = N;
    }
    return used;
}

/* Inserts e->q from `start`, a cell in conflict with it. The new cells are
 * t->fresh[0..nbound-1]. On LH_ERR_NOMEM and LH__RETRY the store is unchanged
 * (but for visit marks). */
static lh_status cavity_insert(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
#ifndef LH_T_PARALLEL
    lh__tds_next_round(t); /* a worker's attempt starts its rounds (lh__par_begin) */
#endif
    uint32_t in = 4 * t->round, out = in + 1;
    int g = grow_region(e, start, in, out);
    if (g <= 0) return g ? LH__RETRY : LH_ERR_NOMEM;
    lh_status st = lh__tds_room(t);
    if (st != LH_OK) return st;
    for (size_t b = 0; b < t->nbound; b++) /* the outside cells' neighbour rows */
        LH__PREFETCH(t->nbr + (size_t)t->nbr[(size_t)t->bound[2 * b] * nv + t->bound[2 * b + 1]] * nv);
    /* the linking (docs/engine.md): twins in 2D and 3D while keys fit, cone and
       links at once in 3D while the boundary has few vertices, numbered ridges for
       a Delaunay boundary of at most 255 vertices, else turning; hashed ridges when
       the region need not be a ball (placing, furthest-site) */
    const int twins = (nv == 3 || (nv == 4 && 2 * t->vbits <= 64)) && !e->dbg.hashed_ridges;
    const int local = nv == 4 && twins && t->vloc ? cone_local(e) : 0;
    if (local) return local > 0 ? LH_OK : LH_ERR_INTERNAL;
    const int numbered = !twins && e->inside_conflicts && t->vloc ? number_boundary(t) : 0;
    const size_t reused = make_cone(e, numbered);
    if (numbered) {
        if (!link_numbered(t)) return LH_ERR_INTERNAL;
    } else if (twins) {
        if (!(nv == 3 ? link_twins(t, 3) : link_twins(t, 4))) return LH_ERR_INTERNAL;
    } else if (e->inside_conflicts) {
        link_by_turning(e);
#ifndef LH_T_PARALLEL
        e->dbg.turned++;
#endif
    } else
        link_new_cells(t);
    for (size_t i = reused; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return LH_OK;
}
