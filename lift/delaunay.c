/*
 * delaunay.c — lh_delaunay: the sites copied, hull/'s engine run with the lifted
 * conflict test (dt.h), the output put in canonical form (output.c).
 */
#include "dt.h"
#include "lh_exact.h"

#include <string.h>

_Static_assert(LH_DELAUNAY_MAX_DIM <= LH_INSPHERE_MAX_DIM, "Delaunay in R^d needs insphere_d");
_Static_assert(LH_DELAUNAY_MAX_DIM <= LH__ENGINE_MAX_DIM, "the engine's dimensions");

void lh_options_default(lh_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    opt->seed = LH__DEFAULT_SEED;
    opt->threads = 1;
}

/* The insertion loops with the lifted test inline (insert_delaunay.h), stamped out
 * by lift/CMakeLists.txt: d = 2..5 with the dimension a constant, and any d. */
#define LH__DT_LOOPS(X) X(2) X(3) X(4) X(5) X(any)
#define LH__DT_DECLARE(D)                                                                      \
    lh_status lh__dt_insert_##D(lh__eng *e, size_t first, size_t count, const lh_index *list); \
    lh_status lh__dt_insert_##D##_par(lh__eng *e, size_t first, size_t count, const lh_index *list);
LH__DT_LOOPS(LH__DT_DECLARE)

/* The loop for d, or its worker of a parallel phase: the fixed-dimension one
 * unless `generic` (lh_options.generic_engine; the output is identical). */
static lh__insert_fn loop_for(int d, int generic, int parallel)
{
    switch (generic ? 0 : d) {
    case 2: return parallel ? lh__dt_insert_2_par : lh__dt_insert_2;
    case 3: return parallel ? lh__dt_insert_3_par : lh__dt_insert_3;
    case 4: return parallel ? lh__dt_insert_4_par : lh__dt_insert_4;
    case 5: return parallel ? lh__dt_insert_5_par : lh__dt_insert_5;
    default: return parallel ? lh__dt_insert_any_par : lh__dt_insert_any;
    }
}

/* The lifted visibility of a finite cell from q, tested inline by the insertion
 * loops (insert_lifted.h): q strictly inside the circumsphere (Delaunay), or
 * strictly outside (furthest-site: the upper hull, no parallel phases). */
void lh__dt_conflicts(lh__eng *e, int furthest, int generic)
{
    e->inside_conflicts = !furthest;
    e->conflict_sign = furthest ? 1 : -1;
    e->insert = loop_for(e->d, generic, 0);
    e->insert_par = furthest ? NULL : loop_for(e->d, generic, 1);
}

/* Cells (finite and infinite) expected for n uniform sites: the mean counts, about
 * 2n, 6.75n, 31n, 161n in 2D..5D, with a little room; higher dimensions start smaller
 * and grow. */
lh_index lh__dt_expected_cells(int d, size_t n)
{
    static const double per_site[LH_DELAUNAY_MAX_DIM + 1] = {0, 0, 2.1, 7.0, 33, 170, 400, 400, 400};
    double c = per_site[d] * (double)n + 256;
    return c > (double)(LH_INDEX_MAX / 2) ? LH_INDEX_MAX / 2 : (lh_index)c;
}

void lh_tri_free(lh_tri *t)
{
    if (!t) return;
    lh_allocator a = t->alloc;
    lh__free(&a, t->xyz);
    lh__free(&a, t->dup);
    lh__free(&a, t->simp);
    lh__free(&a, t->nbr);
    lh__free(&a, t->hull);
    lh__free(&a, t->vsimp);
    lh_pred_free(t->pred);
    lh__free(&a, t->cell_off);
    lh__free(&a, t->cell_vert);
    lh__free(&a, t->simp_cell);
    lh__free(&a, t->edges);
    lh__free(&a, t->centers);
    lh__free(&a, t);
}

/* The handle, its duplicate map allocated; its copy of the sites comes after the
 * build (copy_sites), which reads the caller's array: the two copies, the handle's
 * and the engine's insertion-order one, never coexist. */
static lh_status new_handle(int d, size_t n, const lh_options *opt, lh_tri **out)
{
    lh_allocator a;
    lh__allocator_init(&a, opt ? opt->alloc : NULL);
    lh_tri *t = lh__alloc(&a, sizeof *t);
    if (!t) return LH_ERR_NOMEM;
    memset(t, 0, sizeof *t);
    t->alloc = a;
    t->d = d;
    t->frame.d = t->frame.k = d;
    for (int j = 0; j < d; j++) t->frame.J[j] = j;
    t->n = n;
    t->dup = lh__alloc(&a, (n + 1) * sizeof *t->dup);
    if (!t->dup) {
        lh_tri_free(t);
        return LH_ERR_NOMEM;
    }
    *out = t;
    return LH_OK;
}

static lh_status copy_sites(lh_tri *t, const double *xyz)
{
    t->xyz = lh__alloc(&t->alloc, (t->n * (size_t)t->d + 1) * sizeof *t->xyz);
    if (!t->xyz) return LH_ERR_NOMEM;
    if (t->n) memcpy(t->xyz, xyz, t->n * (size_t)t->d * sizeof *t->xyz);
    return LH_OK;
}

lh_status lh_delaunay(int d, size_t n, const double *xyz, const lh_options *opt, lh_tri **out)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    *out = NULL;
    lh_status st = lh__eng_check_args(d, LH_DELAUNAY_MIN_DIM, LH_DELAUNAY_MAX_DIM, n, xyz, opt);
    if (st != LH_OK) return st;
    lh_tri *t;
    if ((st = new_handle(d, n, opt, &t)) != LH_OK) return st;
    lh__eng e;
    st = lh__eng_init(&e, &t->alloc, d, n, xyz, t->dup, opt);
    int furthest = opt && opt->furthest_site;
    t->generic = opt && opt->generic_engine;
    lh__dt_conflicts(&e, furthest, t->generic);
    t->furthest = furthest;
    t->affine_hull = opt && opt->affine_hull;
    int affdim = -1;
    if (st == LH_OK) st = lh__eng_build(&e, lh__dt_expected_cells(d, n), &affdim);
    if (st == LH_OK) st = lh__dt_extract(&e, t);
    if (st == LH_OK) { /* the handle's queries reuse the engine's predicate context */
        t->pred = e.pred;
        e.pred = NULL;
    }
    t->ndup = e.ndup;
    lh__eng_release(&e);
    const int flat = st == LH_ERR_DEGENERATE && t->affine_hull && affdim >= 1;
    if (st == LH_OK || flat) { /* the handle is kept: it needs its sites */
        lh_status cs = copy_sites(t, xyz);
        st = cs != LH_OK ? cs : flat ? lh__dt_flat(t, opt, affdim) : LH_OK;
    }
    if (st != LH_OK) {
        lh_tri_free(t);
        return st;
    }
    *out = t;
    return LH_OK;
}

lh_status lh_coords_affine_dim(int d, size_t n, const double *xyz, const lh_options *opt,
                               int *dim)
{
    if (!dim) return LH_ERR_INVALID_ARGUMENT;
    lh_status st = lh__eng_check_args(d, 1, LH__ENGINE_MAX_DIM, n, xyz, opt);
    if (st != LH_OK) return st;
    lh_allocator a;
    lh__allocator_init(&a, opt ? opt->alloc : NULL);
    lh_index *dup = lh__alloc(&a, (n + 1) * sizeof *dup);
    if (!dup) return LH_ERR_NOMEM;
    lh__eng e;
    st = lh__eng_init(&e, &a, d, n, xyz, dup, opt);
    if (st == LH_OK) st = lh__eng_order(&e);
    if (st == LH_OK) *dim = lh__eng_initial_simplex(&e);
    lh__eng_release(&e);
    lh__free(&a, dup);
    return st;
}
