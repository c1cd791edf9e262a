/*
 * flat.c — the Delaunay triangulation of sites that span only a k-flat F of R^d
 * (1 <= k < d), within F (lh_options.affine_hull; CGAL's dD triangulation does the
 * same, Qhull stops with QH6154). k = 1 is chain.c's.
 *
 * Choose k coordinates J on which k+1 independent sites project to a nonzero
 * orient_k: the projection to J is then an affine bijection of F, exact (a copy of
 * coordinates). The engine runs in R^k on the projections — orientation, walks and
 * the hull are affine notions, so they are the same there — with the lifted test
 * replaced by the insphere test within F in the metric of R^d (lh__insphere_flat:
 * det [1, p_J, |p|^2], the lifted coordinate over all d coordinates), perturbed as
 * lh_insphere_sos. Exact throughout; the in-flat test has no floating-point filter
 * yet, so this path is slower than the full-dimensional one.
 */
#include "dt.h"

#include <string.h>

typedef struct flat_ctx {
    lh__eng *e;
    const double *xyz; /* the caller's sites, d coordinates each */
    lh__frame f;
    int furthest;
} flat_ctx;

static int flat_sign(flat_ctx *x, const lh_index *v, lh_index q)
{
    const double *p[LH_DELAUNAY_MAX_DIM + 2];
    const int nv = x->f.k + 1;
    for (int i = 0; i < nv; i++) p[i] = x->xyz + (size_t)x->e->order[v[i]] * x->f.d;
    p[nv] = x->xyz + (size_t)x->e->order[q] * x->f.d;
    return lh__insphere_flat_sos(x->e->pred, x->f.d, x->f.k, x->f.J, p);
}

static int flat_conflict(void *user, const lh_index *v, lh_index q)
{
    flat_ctx *x = user;
    int s = flat_sign(x, v, q);
    return x->furthest ? s > 0 : s < 0;
}

/* J: coordinates on which the sites order[0..k] of the ordered engine o project to a
 * simplex of nonzero volume. */
static int choose_coordinates(lh__eng *o, int k, int *J)
{
    const double *pts[LH_DELAUNAY_MAX_DIM + 1];
    for (int i = 0; i <= k; i++) pts[i] = lh__eng_input(o, (size_t)o->order[i]);
    return lh__independent_coords(o->pred, o->d, pts, k, J);
}

/* t->frame for the sites of t. */
static lh_status find_frame(lh_tri *t, int k)
{
    lh__eng o;
    lh_status st = lh__eng_init(&o, &t->alloc, t->d, t->n, t->xyz, t->dup, NULL);
    if (st == LH_OK) st = lh__eng_order(&o);
    if (st == LH_OK && lh__eng_initial_simplex(&o) != k) st = LH_ERR_INTERNAL;
    if (st == LH_OK && !choose_coordinates(&o, k, t->frame.J)) st = LH_ERR_INTERNAL;
    t->frame.d = t->d;
    t->frame.k = k;
    lh__eng_release(&o);
    return st;
}

lh_status lh__dt_flat(lh_tri *t, const lh_options *opt, int k)
{
    lh_status st = find_frame(t, k);
    if (st != LH_OK) return st;
    if (k == 1) return lh__dt_chain(t);
    double *proj = lh__alloc(&t->alloc, (t->n * (size_t)k + 1) * sizeof *proj);
    if (!proj) return LH_ERR_NOMEM;
    for (size_t i = 0; i < t->n; i++)
        for (int j = 0; j < k; j++) proj[i * k + j] = t->xyz[i * t->d + t->frame.J[j]];
    lh__eng e;
    st = lh__eng_init(&e, &t->alloc, k, t->n, proj, t->dup, opt);
    flat_ctx x = {&e, t->xyz, t->frame, t->furthest};
    e.finite_conflict = flat_conflict;
    e.inside_conflicts = !t->furthest;
    e.user = &x;
    int affdim = -1;
    if (st == LH_OK) st = lh__eng_build(&e, lh__dt_expected_cells(k, t->n), &affdim);
    if (st == LH_OK) st = lh__dt_extract(&e, t);
    if (st == LH_OK) {
        t->pred = e.pred;
        e.pred = NULL;
    }
    t->ndup = e.ndup;
    lh__eng_release(&e);
    lh__free(&t->alloc, proj);
    return st;
}
