/*
 * insert_dims.h — hull/'s insertion loop (insert_impl.h) for the Delaunay
 * triangulation in a fixed dimension LH_DIM (defined by the includer, with
 * LH_T_NAME): the lifted conflict test and orient_d call the generated filters
 * for that dimension inline (lh_filter.gen.h) and fall back to the library's exact
 * and perturbed stages only when a filter cannot decide. Same decisions as the
 * generic path, so the same output.
 */
#include "engine.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"

#define LH_CAT_(a, b) a##b
#define LH_CAT(a, b) LH_CAT_(a, b)

/* The static filters' bounds for this computation's sites (lh_filter.gen.h). */
static void prepare_fixed(lh__eng *e)
{
    e->static_eb[0] = lh__static_bound(0, LH_DIM, e->span);
    e->static_eb[1] = lh__static_bound(1, LH_DIM, e->span);
}

/* insphere_sos of finite cell v (positively oriented) and vertex q. */
static inline int lifted_sign_fixed(lh__eng *e, const lh_index *v, lh_index q)
{
    const double *p[LH_DIM + 2];
    for (int k = 0; k <= LH_DIM; k++) p[k] = lh__eng_site(e, v[k]);
    p[LH_DIM + 1] = lh__eng_site(e, q);
    int s = LH_CAT(lh__insphere_static_, LH_DIM)(p, e->static_eb[1]);
    if (s) {
        e->filtered++;
        return s;
    }
    double det = 0, err = -1; /* err stays -1 outside the filter's band */
    if (LH_CAT(lh__insphere_filter_, LH_DIM)(p, &s, &det, &err)) {
        if (s) {
            e->filtered++;
            return s;
        }
        return lh__insphere_sos_fast(e->pred, LH_DIM, p); /* a zero column: perturbed */
    }
    return lh__insphere_sos_unfiltered(e->pred, LH_DIM, p, det, err); /* exact, perturbed */
}

static inline int orient_fixed(lh__eng *e, const double *const *p)
{
    int s = LH_CAT(lh__orient_static_, LH_DIM)(p, e->static_eb[0]);
    if (s) {
        e->filtered++;
        return s;
    }
    double det = 0, err = -1; /* err stays -1 outside the filter's band */
    if (LH_CAT(lh__orient_filter_, LH_DIM)(p, &s, &det, &err)) {
        e->filtered++;
        return s;
    }
    return lh__orient_unfiltered(e->pred, LH_DIM, p, det, err);
}

#define LH_T_D LH_DIM
#define LH_T_FINITE_CONFLICT(e, v, q) (lifted_sign_fixed(e, v, q) == (e)->conflict_sign)
#define LH_T_ORIENT(e, pts) orient_fixed(e, pts)
#define LH_T_PREPARE(e) prepare_fixed(e)
#include "insert_impl.h"
