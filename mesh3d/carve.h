/* carve.h — the domain after recovery: walls, labels, and the mesh written from them. */
#ifndef LH_CARVE_H
#define LH_CARVE_H

#include "recover.h"

#define T3_FREE ((lh_index)-1) /* a tetrahedron in the domain, in no region          */
#define T3_OUT ((lh_index)-2)  /* outside the domain or in a hole                    */

typedef struct t3_domain {
    lh_index *wall;  /* 4 per tet: the facet of its face opposite corner j, or -1 */
    lh_index *label; /* per tet: T3_OUT, T3_FREE or the region's index           */
    lh_index *stack; /* flood scratch                                             */
    size_t kept;     /* tets not T3_OUT                                           */
    size_t holes_ignored, regions_ignored;
} t3_domain;

lh_status lh__t3_walls(t3_ctx *c, t3_domain *d);
/* The facet of tet t's face opposite corner j, or -1 when that face is no wall. */
lh_index lh__t3_wall_of(const t3_domain *d, size_t t, int j);
lh_status lh__t3_carve(t3_ctx *c, t3_domain *d);
/* LH_ERR_DEGENERATE when a facet's recovered faces are partly beside a kept tet and
 * partly not: a facet that is not planar folded out of the domain, whose recovered
 * surface the input does not fix (docs/meshing3d.md). */
lh_status lh__t3_partly_carved(t3_ctx *c, const t3_domain *d);
void lh__t3_domain_free(t3_ctx *c, t3_domain *d);
/* mesh_out.c: the lh_tetmesh of the kept tets. */
lh_status lh__t3_output(t3_ctx *c, const t3_domain *d, lh_tetmesh *m);

#endif
