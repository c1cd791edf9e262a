/*
 * check.h — what the two halves of lh_tetmesh_check share: the mesh's topology and
 * orientation (check.c) and its conformity to a PLC (check_plc.c).
 */
#ifndef LH_CHECK3_H
#define LH_CHECK3_H

#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_exact.h"
#include "lifthull.h"

typedef struct lh__tchk {
    lh_allocator al;
    lh_pred *pr;
    lh_error *err;
    size_t n;
    const double *xyz;
    size_t nt, nf, ne;
    const lh_index *tets, *faces, *parents, *edges;
    int boundary_free;
    const lh_plc *g;
    unsigned char *off; /* n flags: point counted in off_exact                       */
    size_t off_count;
} lh__tchk;

/* The mesh's point i. */
static inline const double *lh__tchk_pt(const lh__tchk *c, lh_index i)
{
    return c->xyz + 3 * (size_t)i;
}

/* Conformity to c->g (not NULL): every facet the union of its subfaces, every segment
 * a chain of subsegments (check_plc.c). LH_OK, LH_ERR_INVALID_MESH,
 * LH_ERR_INVALID_ARGUMENT (g malformed), LH_ERR_NOMEM. */
lh_status lh__tchk_plc(lh__tchk *c);

#endif
