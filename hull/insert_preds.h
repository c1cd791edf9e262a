/*
 * insert_preds.h — the predicates of the insertion loop (insert_impl.h), inline:
 * the generated static filter (d <= 5, its bound from the sites' bounding box) and
 * dynamic filter of lh_filter.gen.h (lh__static_d, lh__filter_d), then the
 * library's exact and perturbed stages only when neither decides. Same decisions
 * as lh_orient and lh_insphere_sos, so the same output on every path. The
 * dimension is the includer's constant LH_T_D (dims/), or e->d at run time
 * (insert_generic.c): the filters' switch on it folds away when it is a constant.
 * Files that include this are compiled with -ffp-contract=off, which the filters'
 * error bounds assume.
 */
#ifndef LH_INSERT_PREDS_H
#define LH_INSERT_PREDS_H

#include "engine.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"

#ifdef LH_T_D
#define LH_PD(e) ((void)(e), LH_T_D)
#else
#define LH_PD(e) ((e)->d)
#endif

/* Whether the static filter of orient_d (lifted 0) or insphere_d (lifted 1)
 * evaluates exactly on the sites: integers whose spans are at most S. It takes the
 * differences p_i - p_0 (integers of at most S), the lifted entries (at most d S^2)
 * and then minors by Laplace expansion, each value a sum of products of entries, one
 * per column; so every value is an integer of at most n! times the columns' largest
 * entries (n = d, or d + 1 with the lifted column), and below 2^53 none is rounded.
 * Grids of 10^6 sites: S = 999 in 2D, 99 in 3D. */
static int static_exact(const lh__eng *e, int lifted)
{
    const int d = LH_PD(e);
    if (!e->integer || d < 2 || d > 5) return 0; /* no static filter past 5D */
    double s = 0, bound = 1;
    for (int j = 0; j < d; j++) s = e->span[j] > s ? e->span[j] : s;
    for (int k = 1; k <= d; k++) bound *= k * s;
    if (lifted) bound *= (d + 1) * d * s * s;
    return bound < 0x1p53;
}

/* The static filters' bounds for this computation's sites (+infinity: none; 0
 * where the filter is exact); run once per insertion call (LH_T_PREPARE). */
static void prepare_preds(lh__eng *e)
{
    for (int lifted = 0; lifted < 2; lifted++) {
        e->static_exact[lifted] = static_exact(e, lifted);
        e->static_eb[lifted] = e->static_exact[lifted] ? 0 : lh__static_bound(lifted, LH_PD(e), e->span);
    }
}

/* The points of finite cell v and vertex q, in the order of insphere_d. */
static LH__ALWAYS_INLINE void lifted_points(const lh__eng *e, const lh_index *v, lh_index q, const double **p)
{
    const int d = LH_PD(e);
    for (int k = 0; k <= d; k++) p[k] = lh__eng_site(e, v[k]);
    p[d + 1] = lh__eng_site(e, q);
}

/* insphere_sos of the points p once the static filter has not decided: the exact
 * zero of integer sites, or the dynamic filter, then the exact perturbed stages. */
static inline int lifted_undecided(lh__eng *e, const double *const *p)
{
    const int d = LH_PD(e);
    if (e->static_exact[1]) return lh__insphere_sos_zero(e->pred, d, p);
    int s;
    double det = 0, err = -1; /* err stays -1 outside the filter's band */
    if (lh__filter_d(1, d, p, &s, &det, &err)) {
        if (s) {
            e->filtered++;
            return s;
        }
        return lh__insphere_sos_fast(e->pred, d, p); /* a zero column: perturbed */
    }
    return lh__insphere_sos_unfiltered(e->pred, d, p, det, err); /* exact, perturbed */
}

/* insphere_sos of finite cell v (positively oriented) and vertex q. */
static LH__ALWAYS_INLINE int lifted_sign(lh__eng *e, const lh_index *v, lh_index q)
{
    const double *p[LH__ENGINE_MAX_DIM + 2];
    lifted_points(e, v, q, p);
    int s = lh__static_d(1, LH_PD(e), p, e->static_eb[1]);
    if (s) {
        e->filtered++;
        return s;
    }
    return lifted_undecided(e, p);
}

/* Whether finite cells v and w each conflict with q (lifted_sign equal to
 * e->conflict_sign), into x[0] and x[1]: their static filters in one paired
 * evaluation (lh__static2_d), the later stages for a cell it leaves undecided. */
static LH__ALWAYS_INLINE void lifted_conflict2(lh__eng *e, const lh_index *v, const lh_index *w, lh_index q, int *x)
{
    const double *p[2][LH__ENGINE_MAX_DIM + 2];
    lifted_points(e, v, q, p[0]);
    lifted_points(e, w, q, p[1]);
    lh__static2_d(LH_PD(e), p[0], p[1], e->static_eb[1], x);
    for (int i = 0; i < 2; i++) {
        e->filtered += x[i] != 0;
        x[i] = (x[i] ? x[i] : lifted_undecided(e, p[i])) == e->conflict_sign;
    }
}

/* lh_orient of the d + 1 points p: exact, 0 when they are affinely dependent. */
static LH__ALWAYS_INLINE int orient_inline(lh__eng *e, const double *const *p)
{
    const int d = LH_PD(e);
    int s = lh__static_d(0, d, p, e->static_eb[0]);
    if (s) {
        e->filtered++;
        return s;
    }
    if (e->static_exact[0]) {
        lh__pred_count_zero(e->pred);
        return 0;
    }
    double det = 0, err = -1;
    if (lh__filter_d(0, d, p, &s, &det, &err)) {
        e->filtered++;
        return s;
    }
    return lh__orient_unfiltered(e->pred, d, p, det, err);
}

#endif
