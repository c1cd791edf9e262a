/*
 * dt.h — Delaunay triangulation as the lower hull of the lifted sites (Brown 1979;
 * Edelsbrunner & Seidel 1986), built by lift/ on hull/'s cell store.
 *
 * Cells have d+1 vertices: site indices (input numbering) or LH__INF, the symbolic
 * vertex straight up the lifted axis. A finite cell is a Delaunay simplex, stored
 * positively oriented (orient_d > 0). An infinite cell pairs a convex hull facet
 * with LH__INF and is "positively oriented" in the sense that putting a point beyond
 * that facet in LH__INF's place gives orient_d > 0. Together they triangulate the
 * d-sphere R^d + {infinity}: every cell has d+1 neighbours.
 */
#ifndef LH_DT_H
#define LH_DT_H

#include "lh_alloc.h"
#include "lifthull.h"
#include "tds.h"

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
};

/* The builder: one per lh_delaunay call. */
typedef struct lh__dt {
    lh_tri *t;
    int d, nv;
    lh_pred *pred;
    lh__tds tds;
    int32_t *order; /* distinct sites in insertion order */
    size_t norder;
    int32_t *v2c;   /* n: a cell incident to each inserted site */
    int32_t q;      /* the site being inserted */
    int32_t hint;   /* where the next walk starts */
    uint64_t rng;
    const double *pts[LH_DELAUNAY_MAX_DIM + 2];
} lh__dt;

static inline const double *lh__dt_site(const lh__dt *b, int32_t v)
{
    return b->t->xyz + (size_t)v * (size_t)b->d;
}

static inline uint64_t lh__rng_next(uint64_t *s) /* xorshift64* (Vigna 2016) */
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * UINT64_C(2685821657736338717);
}

/* order.c */
/* Merges exact duplicates (t->dup, t->ndup) and puts the distinct sites in
 * insertion order in b->order. */
lh_status lh__dt_order_sites(lh__dt *b);
int lh__dt_initial_simplex(lh__dt *b);
int lh__affine_independent(lh_pred *pred, int d, const double *const *pts, int k);
/* output.c */
lh_status lh__dt_extract(lh__dt *b);

#endif
