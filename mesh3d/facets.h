/* facets.h — every facet of a PLC triangulated in its plane (temporary declaration;
 * the facet triangulator replaces it). */
#ifndef LH_FACETS_H
#define LH_FACETS_H

#include "lh_alloc.h"
#include "lh_error.h"
#include "lifthull.h"

typedef struct lh__facet_tris {
    size_t count;
    lh_index *tri;   /* 3 per triangle, point indices into the PLC */
    lh_index *facet; /* 1 per triangle */
    size_t nonplanar;
} lh__facet_tris;

lh_status lh__facets_triangulate(const lh_plc *g, const lh_allocator *al, lh__facet_tris *out,
                                 lh_error *err);
void lh__facet_tris_free(const lh_allocator *al, lh__facet_tris *t);

#endif
