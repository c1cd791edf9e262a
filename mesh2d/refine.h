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
    const double *cover_area;  /* the old mesh's area bounds (m->cover), or NULL        */
    lh_trimesh_stats *out;     /* steiner_points, steiner_removed, steiner_limit_reached,
                                  segments_unsplit */
} lh__refine_opts;

lh_status lh__m2_refine(lh__m2 *m, lh__m2_cavity *c, const lh__refine_opts *o);
/* The resolution floor of m's points, fm * 2^*fe (an lh__g_cmp pair, m2_geom.h):
 * 2^-40 of the larger of their diameter and their largest |coordinate|. No
 * subsegment shorter than it is split (refine.c, cdt_split.c). */
void lh__m2_length_floor(const lh__m2 *m, double *fm, long *fe);
/* The live triangles still bad under o's bounds: *count, and their indices when bad
 * is not NULL. */
lh_status lh__m2_bad_triangles(lh__m2 *m, const lh__refine_opts *o, lh_index *bad,
                               size_t *count);

/* An existing mesh to refine (cdt_cover.c): its triangles, linked, and its boundary
 * edges (2 vertices each, the old interior on the left). */
typedef struct lh__cover { /* m2.h's struct lh__cover */
    lh__m2 mesh;
    lh_index *old;       /* per triangle of mesh: its index in lh_pslg.cover      */
    lh_index *bnd;
    size_t bnd_count;
    lh_index *claim;     /* pairs (subsegment of a boundary edge, input segment along
                            it), recorded by lh__cover_claim                       */
    size_t claim_count, claim_cap;
} lh__cover;
/* The subsegment parent of boundary edge i, and back (the map is an involution). */
#define LH__COVER_PARENT(i) (-(lh_index)(i) - 2)

lh_status lh__cover_build(lh__cover *cv, const lh_allocator *al, const lh_pslg *g,
                          const lh_index *dup);
void lh__cover_free(lh__cover *cv);
/* Inserts the boundary edges as segments (before the input's). */
lh_status lh__cover_segments(lh__m2 *m, lh__m2_cavity *c, const lh__cover *cv,
                             lh__m2_problem *pb);
/* After the domain is known (the boundary edges' parents have served
 * lh__cover_outside): each claimed subsegment takes the input segment along it as its
 * parent, so that it and the Steiner points put on it carry that segment's marker,
 * as Triangle's -rp gives them. */
void lh__cover_relabel(lh__m2 *m, const lh__cover *cv);
/* Marks with epoch e the triangles outside the old mesh. */
lh_status lh__cover_outside(lh__m2 *m, lh__m2_cavity *c, const lh__cover *cv, uint32_t e);
/* m->tarea[t] = area[old triangle holding t's centroid], for t / every live t. */
void lh__cover_area_of(lh__m2 *m, lh__cover *cv, const double *area, lh_index t);
lh_status lh__cover_areas(lh__m2 *m, lh__cover *cv, const double *area);

/* Laplacian smoothing of the free Steiner points, `passes` times at most, each
 * followed by Lawson's flips (smooth.c); *moved counts the moves. */
lh_status lh__m2_smooth(lh__m2 *m, lh__m2_cavity *c, int passes, double max_area, size_t *moved);

/* The subsegment on which point p lies (closed: an endpoint too), or -1 (cdt_domain.c);
 * at a vertex, of the subsegments ending there the one of the least input segment.
 * For the mesh before carving (a triangulation of the convex hull, where the
 * triangles around a vertex form one fan): point location, then that fan. A hole seed
 * on a subsegment would carve whichever side point location happens to find. */
lh_index lh__m2_subseg_at(lh__m2 *m, const double *p);

/* Triangle's -s (cdt_split.c): subsegments split at their midpoints until each is
 * locally Delaunay, at most max_steiner points (*added); *unsplit counts those left
 * not locally Delaunay (below the length floor, refused, or the budget spent). */
lh_status lh__m2_split_segments(lh__m2 *m, lh__m2_cavity *c, size_t max_steiner, size_t *added,
                                size_t *unsplit);

/* The domain (cdt_domain.c): Triangle's flood, the even-odd rule, or m->cover. */
lh_status lh__m2_domain(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, int convex_hull,
                        size_t *holes_ignored, size_t *regions_ignored);

#endif
