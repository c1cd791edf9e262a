/*
 * insert_link_turning.h — part of the insertion loop template (insert_impl.h):
 * linking the new cells of a Delaunay insertion by turning around each ridge
 * through the dead cells; the path for a cavity whose boundary has more than 255
 * vertices (beyond the numbering of insert_link_numbered.h), in 4D and up (3D
 * beyond 2^32 sites) and under the test knob hashed_ridges. Needs the dead cells intact: the cone is made
 * without reusing them (make_cone).
 */

/* Pairs the new cells by turning around their ridges through the dead cells, for a
 * Delaunay insertion (inside_conflicts): the conflict region is then a ball (it is
 * star-shaped from q), so the dead cells around a ridge R on its boundary form a
 * path from one boundary facet holding R to the other. Each dead cell's boundary
 * facet first points at its new cell; from boundary facet (c, k), the new cell's
 * facet opposite vertex j (R = c minus v_j and v_k) is crossed through c's facet
 * opposite j, R + x with x = v_k; a dead cell R + x + w entered there is left through
 * R + w, until the facet crossed is a boundary facet, whose new cell is the
 * neighbour (the way CGAL's 3D data structure builds a star, Boissonnat, Devillers,
 * Pion, Teillaud & Yvinec 2002, "Triangulations in CGAL", CGTA 22). Every step is in
 * cells just visited by grow_region, and nothing is hashed or sorted. Both cells of
 * a pair are linked at once. The dead cells' rows are overwritten (they are freed
 * next). */
static void link_by_turning(lh__eng *e)
{
    lh__tds *t = &e->tds;
    const int nv = LH_T_NV(t);
    /* a dead cell's boundary facet holds -2 - b (its new cell is fresh[b]): a
       neighbour >= 0 is then a dead cell, with no look at the stamps */
    for (size_t b = 0; b < t->nbound; b++) t->nbr[(size_t)t->bound[2 * b] * nv + t->bound[2 * b + 1]] = -2 - (lh_index)b;
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index N = t->fresh[b], c = t->bound[2 * b];
        const int k = (int)t->bound[2 * b + 1];
        for (int j = 0; j < nv; j++) {
            if (j == k || t->nbr[(size_t)N * nv + j] >= 0) continue;
            lh_index cur = c, x = t->vert[(size_t)c * nv + k], nx;
            int pos = j;
            while ((nx = t->nbr[(size_t)cur * nv + pos]) >= 0) {
                const lh_index *vv = t->vert + (size_t)nx * nv;
                const int m = row_pos(t->nbr + (size_t)nx * nv, nv, cur);
                pos = row_pos(vv, nv, x), x = vv[m], cur = nx;
            }
            const lh_index M = t->fresh[-2 - nx];
            t->nbr[(size_t)N * nv + j] = M;
            t->nbr[(size_t)M * nv + row_pos(t->vert + (size_t)cur * nv, nv, x)] = N;
        }
    }
}
