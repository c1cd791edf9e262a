/* refine.h — Delaunay refinement of the 2D mesh (refine.c). */
#ifndef LH_REFINE_H
#define LH_REFINE_H

#include "m2.h"

typedef struct lh__refine_opts {
    double min_angle;          /* degrees, 0: none                                     */
    double max_area;           /* <= 0: none                                           */
    int region_areas;          /* the triangles' region bounds (m->tarea) apply        */
    int conforming;            /* diametral circles always (no lenses): every subsegment's
                                  circle empty of its triangles' apexes at the end, so
                                  every edge is locally Delaunay (lh_trimesh_options)   */
    int boundary_steiner;      /* lh_trimesh_options.boundary_steiner                  */
    size_t max_steiner;
    const lh_index *segments;  /* the input segments (2 each) and the duplicate map:   */
    const lh_index *dup;       /* for the small-angle rule                             */
    lh_trimesh_stats *out;     /* steiner_points, steiner_limit_reached                */
} lh__refine_opts;

lh_status lh__m2_refine(lh__m2 *m, lh__m2_cavity *c, const lh__refine_opts *o);
/* The live triangles still bad under o's bounds: *count, and their indices when bad
 * is not NULL. */
lh_status lh__m2_bad_triangles(lh__m2 *m, const lh__refine_opts *o, lh_index *bad,
                               size_t *count);

lh_status lh__m2_domain(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, int convex_hull,
                        size_t *holes_ignored, size_t *regions_ignored);

#endif
