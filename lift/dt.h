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
#include "lh_exact.h"

/* Where the simplices live: R^d (k == d), or a k-flat of R^d (the affine hull of
 * lower-dimensional sites, lh_options.affine_hull), on which the projection to the
 * coordinates J is one to one; orientation is then orient_k of the projections and
 * the insphere test lh__insphere_flat (lh_exact.h). */
typedef struct lh__frame {
    int d, k;
    int J[LH_DELAUNAY_MAX_DIM];
} lh__frame;

/* orient_k of k+1 sites (coordinates in R^d) in the frame. */
static inline int lh__frame_orient(lh_pred *pred, const lh__frame *f, const double *const *p)
{
    if (f->k == f->d) return lh_orient(pred, f->d, p);
    double proj[LH_DELAUNAY_MAX_DIM + 1][LH_DELAUNAY_MAX_DIM];
    const double *pp[LH_DELAUNAY_MAX_DIM + 1];
    for (int i = 0; i <= f->k; i++) {
        for (int j = 0; j < f->k; j++) proj[i][j] = p[i][f->J[j]];
        pp[i] = proj[i];
    }
    return lh_orient(pred, f->k, pp);
}

/* The (unperturbed) insphere sign of k+2 sites in the frame. */
static inline int lh__frame_insphere(lh_pred *pred, const lh__frame *f, const double *const *p)
{
    return f->k == f->d ? lh_insphere(pred, f->d, p) : lh__insphere_flat(pred, f->d, f->k, f->J, p);
}

struct lh_tri {
    lh_allocator alloc;
    int d;
    lh__frame frame;  /* k = d unless triangulated in the sites' affine hull */
    size_t n;
    double *xyz;      /* n*d, a copy of the caller's sites */
    lh_index *dup;    /* n: the site each one was merged into (itself for a vertex) */
    size_t ndup;
    size_t count;     /* finite simplices */
    lh_index *simp;   /* (k+1)*count, canonical (with `unordered`: oriented only) */
    int unordered;    /* lh_tri_insert_unordered: simplices in no particular order */
    lh_index *nbr;    /* (k+1)*count, -1 across the hull */
    size_t hull_count;
    lh_index *hull;   /* k*hull_count, outward */
    lh_index *vsimp;  /* n */
    lh_pred *pred;    /* for queries (lh_tri_locate) */
    int furthest;     /* the furthest-site triangulation (lh_options) */
    int affine_hull;  /* lh_options.affine_hull, for lh_tri_insert */
    int generic;      /* lh_options.generic_engine, for lh_tri_insert */
    size_t ncells;    /* the Delaunay complex, built on demand (complex.c) */
    lh_index *cell_off, *cell_vert;
    lh_index *simp_cell; /* count: the cell of each simplex */
    size_t nedges;       /* the complex's edges, built on demand (complex.c) */
    lh_index *edges;     /* 2 per edge */
    double *centers;  /* d per simplex, the circumcentres, built on demand (voronoi.c) */
};

/* delaunay.c: a capacity hint, the cells expected for n uniform sites in R^d. */
lh_index lh__dt_expected_cells(int d, size_t n);
/* delaunay.c: sets e's conflict test, lifted (Delaunay) or reversed (furthest),
 * and its insertion loops: for e->d, or with d a runtime value when `generic`. */
void lh__dt_conflicts(lh__eng *e, int furthest, int generic);

/* flat.c: t (sites copied, dup allocated) triangulated in the k-flat spanned by
 * its sites, 1 <= k < d. */
lh_status lh__dt_flat(lh_tri *t, const lh_options *opt, int k);
/* chain.c: the same for k = 1, t->frame set: segments along the line. */
lh_status lh__dt_chain(lh_tri *t);

/* output.c: the handle's arrays from a built engine; _as with sorted 0: the
 * simplices in no particular order, each positively oriented but its vertices in no
 * particular order either (lh__tds_compact_cells). */
lh_status lh__dt_extract(lh__eng *e, lh_tri *t);
lh_status lh__dt_extract_as(lh__eng *e, lh_tri *t, int sorted);

#endif
