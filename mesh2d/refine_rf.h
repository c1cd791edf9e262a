/*
 * refine_rf.h — the state of one Delaunay refinement (refine.c), shared with the
 * placement and removal of its points (refine_points.c). Internal to mesh2d/.
 */
#ifndef LH_MESH2D_REFINE_RF_H
#define LH_MESH2D_REFINE_RF_H

#include "m2.h"
#include "refine.h"

/* A bad triangle as queued: the angle-bad ones first, the one with the shortest
 * shortest edge (km * 2^ke, km in [1, 2): lh__g_norm) first among them; then those
 * only too large. */
typedef struct item {
    int area_only;
    long ke;
    double km;
    lh_index t, a, b, c;
} item;

typedef struct rf {
    lh__m2 *m;
    lh__m2_cavity *c;
    lh__m2_ins ins;
    const lh__refine_opts *o;
    double sin_bound;       /* bad when the smallest angle's sine is below this (0: none) */
    double off_h;           /* off-centre distance from the shortest edge, per unit length */
    double minlen_m;        /* the resolution floor, minlen_m * 2^minlen_e             */
    long minlen_e;
    item *heap;
    size_t heap_count, heap_cap;
    lh_index *segq;         /* 2 per entry: subsegment, forced */
    size_t segq_count, segq_cap;
    size_t steiner;
    size_t budget;          /* above the provable angle: at most this many (0: none) */
    unsigned char *stuck;   /* per subsegment: a split was refused or is too short */
    size_t stuck_count, stuck_cap;
    lh_index *gone;         /* free vertices to remove before a split (Chew's rule) */
    size_t gone_count, gone_cap;
} rf;

/* After an insertion: queue the new triangles that are bad and the subsegments on
 * their edges that are encroached (refine.c). */
lh_status lh__rf_after_insert(rf *r);

/* refine_points.c: where subsegment s is split (p); a new point's marker (from s, or
 * none when s < 0) and attributes (weights w of the points from[0..2], -1 ends);
 * Chew's rule before subsegment s is split. */
void lh__rf_split_point(const rf *r, lh_index s, double *p);
void lh__rf_point_data(rf *r, lh_index pi, lh_index s, const double *w, const lh_index *from);
lh_status lh__rf_remove_free(rf *r, lh_index s);

#endif
