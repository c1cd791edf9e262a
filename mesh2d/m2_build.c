/*
 * m2_build.c — the 2D mesh (m2.h) started from the Delaunay triangulation of the
 * input vertices, computed by the fixed-dimension engine (lh_delaunay): its
 * triangles are positively oriented and its neighbour k is opposite vertex k, the
 * mesh's own encoding, so the arrays are taken over as they are.
 */
#include <string.h>

#include "dt.h"
#include "m2.h"

lh_status lh__m2_from_delaunay(lh__m2 *m, lh_tri *dt)
{
    /* the handle's triangle and neighbour arrays are taken over (allocated with the
       same hooks); the incident-triangle map copied */
    const size_t nt = dt->count;
    m->sg = lh__alloc(&m->al, (nt ? 3 * nt : 1) * sizeof *m->sg);
    m->mark = lh__alloc(&m->al, (nt ? nt : 1) * sizeof *m->mark);
    if (!m->sg || !m->mark) return LH_ERR_NOMEM;
    m->v = dt->simp, dt->simp = NULL;
    m->nb = dt->nbr, dt->nbr = NULL;
    m->cap_t = nt;
    for (size_t i = 0; i < 3 * nt; i++) m->sg[i] = -1;
    memset(m->mark, 0, nt * sizeof *m->mark);
    m->nt = m->live = nt;
    memcpy(m->vt, dt->vsimp, dt->n * sizeof *m->vt); /* -1 for merged duplicates */
    m->walk_hint = nt ? 0 : -1;
    return LH_OK;
}
