/*
 * m2_build.c — the 2D mesh (m2.h) started from the Delaunay triangulation of the
 * input vertices, computed by the fixed-dimension engine (lh_delaunay): its
 * triangles are positively oriented and its neighbour k is opposite vertex k, the
 * mesh's own encoding, so the arrays are copied as they are.
 */
#include <string.h>

#include "m2.h"

lh_status lh__m2_from_delaunay(lh__m2 *m, const lh_tri *dt)
{
    const size_t nt = lh_tri_count(dt);
    lh_status st = lh__m2_reserve_tris(m, nt + nt / 2 + 16);
    if (st != LH_OK) return st;
    memcpy(m->v, lh_tri_simplices(dt), 3 * nt * sizeof(lh_index));
    memcpy(m->nb, lh_tri_neighbors(dt), 3 * nt * sizeof(lh_index));
    for (size_t i = 0; i < 3 * nt; i++) m->sg[i] = -1;
    memset(m->mark, 0, nt * sizeof *m->mark);
    m->nt = m->live = nt;
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) m->vt[m->v[3 * t + k]] = (lh_index)t;
    m->walk_hint = nt ? 0 : -1;
    return LH_OK;
}
