/*
 * facets.h — every facet of a PLC triangulated in its plane, without Steiner points:
 * what the intersection test (lh_plc_intersections) and boundary recovery share.
 */
#ifndef LH_FACETS_H
#define LH_FACETS_H

#include "lifthull.h"

/* The triangles of all facets, facet by facet in facet order. */
typedef struct lh__facet_tris {
    size_t count;     /* triangles                                                   */
    lh_index *tri;    /* 3 per triangle: point indices into the PLC, ordered as the
                         facet's first ring (see lh__facets_triangulate)             */
    lh_index *facet;  /* 1 per triangle: its facet                                   */
    signed char *axis; /* 1 per facet: the axis it was projected along (lh__facet_axis),
                          -1 for a facet of one triangle, which is not projected      */
    size_t nonplanar; /* facets whose points are not exactly coplanar                */
} lh__facet_tris;

/*
 * Triangulates every facet of g: a facet that is one triangle passes through; a
 * quad takes its valid diagonal (the Delaunay one when both are); any other is
 * projected to the coordinate plane that drops the largest component of its
 * first ring's Newell normal and triangulated there by lh_pslg_triangulate (ring and
 * slit edges as segments, the facet's hole points carving holes, no Steiner point),
 * each triangle oriented as the first ring turns in that projection — so a closed
 * surface given with consistently oriented rings gets consistently oriented
 * triangles. A facet whose points are not exactly coplanar is triangulated the same
 * way, in its projection (its triangles then are not in one plane), and counted in
 * out->nonplanar. Points of equal coordinates are one point (the triangles name one
 * of them).
 * Errors, err->message naming the facet (0-based) and its line when g->facet_line is
 * set, err->index the facet: LH_ERR_INVALID_ARGUMENT (g's arrays inconsistent, an
 * index out of range), LH_ERR_NONFINITE, LH_ERR_DEGENERATE (a facet without a polygon
 * of 3 or more vertices; with all its points collinear; whose projection merges two
 * distinct points; a hole point on an edge or one carving the whole facet),
 * LH_ERR_CROSSING_SEGMENTS (edges that cross in the projection), LH_ERR_TOO_LARGE,
 * LH_ERR_NOMEM. On failure *out is zeroed and nothing is leaked.
 */
/* al: NULL for malloc/free. */
lh_status lh__facets_triangulate(const lh_plc *g, const lh_allocator *al, lh__facet_tris *out,
                                 lh_error *err);
/* orient_2 of points a, b, c of R^3 projected along axis k (0..2) to the plane of
 * the other two axes, taken in cyclic order (k+1, k+2): > 0 when a, b, c turn
 * positively about +k. */
int lh__orient2_along(lh_pred *pred, int k, const double *a, const double *b, const double *c);

/* The axis (0..2) along which lh__facets_triangulate projects facet f of g (its
 * points' coordinates in xyz, 3 each, which may be g->xyz): the
 * largest component of the Newell normal of its first polygon of 3 or more vertices,
 * returned in nrm (zero when it has none), unless the projection along it flattens
 * a, b, c — the facet's first three non-collinear points in polygon order, points of
 * equal coordinates counted once; then the largest that does not. A checker that
 * projects a non-planar facet along it sees the triangulation that was made. */
int lh__facet_axis(lh_pred *pred, const lh_plc *g, const double *xyz, size_t f, const double *a,
                   const double *b, const double *c, double nrm[3]);

/* Frees out's arrays (allocated with al) and zeroes it; a zeroed out is a no-op. */
void lh__facet_tris_free(const lh_allocator *al, lh__facet_tris *out);

#endif
