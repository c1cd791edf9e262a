/*
 * insert_locate.h — part of the insertion loop template (insert_impl.h): the walk
 * to a cell in conflict with the new site e->q.
 *
 * A remembering stochastic visibility walk (Devillers, Pion & Teillaud, "Walking in
 * a triangulation", IJFCS 13(2), 2002) from the last new cell: it crosses a facet
 * whose hyperplane strictly separates the cell from q, trying the facets from a
 * random one, never back across the facet it came through. It stops in the closed simplex containing q,
 * or in an infinite cell whose facet q strictly sees. A bound on its length falls
 * back to scanning every cell, so it always ends.
 */

/* Whether cell c (held) conflicts with e->q (engine.h: the rule for infinite
 * cells); -1 when a cell it needs is another worker's. */
static LH__ALWAYS_INLINE int conflict(lh__eng *e, lh_index c)
{
    const lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    const lh_index *v = t->vert + (size_t)c * nv;
    if (v[0] != LH__INF) return LH_T_FINITE_CONFLICT(e, v, e->q);
    e->pts[0] = lh__eng_site(e, e->q);
    for (int k = 1; k < nv; k++) e->pts[k] = lh__eng_site(e, v[k]);
    int o = LH_T_ORIENT(e, e->pts);
    if (o || LH_T_PLACING(e)) return o > 0;
    lh_index f = t->nbr[(size_t)c * nv];
    if (!HOLD(e, f)) return -1;
    return LH_T_FINITE_CONFLICT(e, t->vert + (size_t)f * nv, e->q);
}

/* orient_d of finite cell v with its vertex k replaced by q. */
static inline int orient_replaced(lh__eng *e, const lh_index *v, int k)
{
    const int nv = LH_T_NV(&e->tds);
    for (int j = 0; j < nv; j++) e->pts[j] = lh__eng_site(e, v[j]);
    e->pts[k] = lh__eng_site(e, e->q); /* after the loop: no branch on j == k in it */
    return LH_T_ORIENT(e, e->pts);
}

#ifndef LH_T_PARALLEL
static lh_index scan_for_conflict(lh__eng *e)
{
    for (lh_index c = 0; c < e->tds.top; c++)
        if (!lh__tds_dead(&e->tds, c) && conflict(e, c)) return c;
    return -1;
}
#endif

/* A cell in conflict with q, or -1 when q is inside the current hull and no finite
 * cell can conflict (placing mode), or -2 when a cell on the way is another
 * worker's. Starts from the hint (held). */
static lh_index locate(lh__eng *e)
{
    const lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    lh_index c = e->hint, prev = -1;
    size_t limit = 64 + 8 * (size_t)t->live;
    for (size_t step = 0; step < limit; step++) {
        const lh_index *v = t->vert + (size_t)c * nv;
        if (v[0] == LH__INF) {
            if (prev >= 0) return c; /* entered across its facet */
            int x = conflict(e, c);
            if (x) return x > 0 ? c : -2;
            prev = c;
            c = t->nbr[(size_t)c * nv];
            if (!HOLD(e, c)) return -2;
            continue;
        }
        /* the first facet tried: the high half of a random word times nv, over 2^32
           (a multiply, not a division by the runtime nv of the generic build) */
        int s = (int)((lh__rng_next(&e->rng) >> 32) * (uint64_t)nv >> 32), moved = 0;
        for (int i = 0; i < nv && !moved; i++) {
            int k = s + i < nv ? s + i : s + i - nv;
            lh_index n = t->nbr[(size_t)c * nv + k];
            if (n == prev || orient_replaced(e, v, k) >= 0) continue;
            if (!HOLD(e, n)) return -2;
            prev = c;
            c = n;
            moved = 1;
        }
        if (!moved) return e->inside_conflicts ? c : -1; /* q in the closed simplex c */
    }
#ifdef LH_T_PARALLEL
    return -2; /* the cells are shared: left to the sequential pass */
#else
    return scan_for_conflict(e); /* not reached in practice */
#endif
}
