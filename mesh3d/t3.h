/*
 * t3.h — the tetrahedral mesh handle (lh_tetmesh) and what mesh3d's stages share.
 */
#ifndef LH_T3_H
#define LH_T3_H

#include "lh_alloc.h"
#include "lh_error.h"
#include "lifthull.h"

/* The result of lh_tetrahedralize: flat arrays, each owned and freed with alloc. */
struct lh_tetmesh {
    lh_allocator alloc;
    size_t n;               /* points: the PLC's, then Steiner points, then the
                               second-order nodes                                */
    double *xyz;            /* 3n                                                */
    lh_index *point_marker; /* n                                                 */
    size_t tet_count;
    lh_index *tets;   /* 4 per tet, orient_3 > 0                           */
    lh_index *nbr;    /* 4 per tet, -1 none                                */
    double *tet_attr; /* tet_count, or NULL                                */
    size_t face_count;
    lh_index *faces; /* 3 per subface                                     */
    lh_index *face_marker, *face_parent;
    size_t edge_count;
    lh_index *edges; /* 2 per subsegment                                  */
    lh_index *edge_marker, *edge_parent;
    /* second order (second_order.c): the points before the edges' midpoints; per
       tet its 6 edges' midpoint nodes; per midpoint (sorted) its edge p < q */
    size_t n_corners;
    lh_index *tet_mid, *mid_edges;
    lh_tetmesh_leftover *left; /* leftover.c: the tets over their bounds */
    size_t left_count;
    lh_tetmesh_stats stats;
};

/* An empty handle with the allocator; NULL when out of memory. */
lh_tetmesh *lh__tetmesh_new(const lh_allocator *al);
/* quality.c: m's smallest dihedral angle and largest radius-edge ratio into its
 * statistics, and the tets over radius-edge bound max_ratio and under dihedral bound
 * min_dih (degrees; 0: none). */
void lh__tetmesh_quality(lh_tetmesh *m, double max_ratio, double min_dih);
/* second_order.c: the midpoint nodes of every tet edge appended to m's points. */
lh_status lh__tetmesh_second_order(lh_tetmesh *m);
/* Allocates count * size bytes with m's allocator into *arr (count 0: NULL). */
lh_status lh__tetmesh_array(lh_tetmesh *m, void **arr, size_t count, size_t size);

#endif
