/*
 * dt.h — the Delaunay triangulation as the lower hull of the lifted sites (Brown
 * 1979; Edelsbrunner & Seidel 1986): hull/'s engine with the lifted conflict test
 * (a finite cell conflicts with q when q is strictly inside its circumsphere,
 * insphere_sos < 0 — its lifted facet is visible from q's lifted point). The
 * perturbation acts on the lifted coordinates first (lifthull.h), so cospherical
 * sites are split consistently and no flat simplex can appear.
 */
#ifndef LH_DT_H
#define LH_DT_H

#include "engine.h"

struct lh_tri {
    lh_allocator alloc;
    int d;
    size_t n;
    double *xyz;      /* n*d, a copy of the caller's sites */
    int32_t *dup;     /* n: the site each one was merged into (itself for a vertex) */
    size_t ndup;
    size_t count;     /* finite simplices */
    int32_t *simp;    /* (d+1)*count, canonical */
    int32_t *nbr;     /* (d+1)*count, -1 across the hull */
    size_t hull_count;
    int32_t *hull;    /* d*hull_count, outward */
    int32_t *vsimp;   /* n */
    lh_pred *pred;    /* for queries (lh_tri_locate) */
    int furthest;     /* the furthest-site triangulation (lh_options) */
    size_t ncells;    /* the Delaunay complex, built on demand (complex.c) */
    int32_t *cell_off, *cell_vert;
};

/* delaunay.c: sets e's conflict test: lifted (Delaunay) or reversed (furthest). */
void lh__dt_conflicts(lh__eng *e, int furthest);

/* output.c: the handle's arrays from a built engine. */
lh_status lh__dt_extract(lh__eng *e, lh_tri *t);

#endif
