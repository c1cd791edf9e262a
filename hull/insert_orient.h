/*
 * insert_orient.h — orient_d for the insertion loop (insert_impl.h), inline: the
 * generated static filter (d <= 5, its bound from the sites' bounding box) and
 * dynamic filter of lh_filter.gen.h (lh__static_d, lh__filter_d), then the
 * library's exact stage only when neither decides. Same decisions as lh_orient, so
 * the same output on every path. The dimension is the includer's constant LH_T_D,
 * or e->d at run time: the filters' switch on it folds away when it is a constant.
 * The conflict test is the includer's (engine.h). Files that include this are
 * compiled with -ffp-contract=off, which the filters' error bounds assume.
 */
#ifndef LH_INSERT_ORIENT_H
#define LH_INSERT_ORIENT_H

#include "engine.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"

#ifdef LH_T_D
#define LH_PD(e) ((void)(e), LH_T_D)
#else
#define LH_PD(e) ((e)->d)
#endif

/* A bound on every value the static filter of orient_d computes on the sites,
 * when they are integers whose spans are at most S: it takes the differences
 * p_i - p_0 (integers of at most S), then minors by Laplace expansion, each value a
 * sum of products of entries, one per column; so every value is an integer of at
 * most d! S^d. +infinity when the sites are not integers or d is past the static
 * filters (5D). A predicate over extra columns multiplies in their bounds; below
 * 2^53 nothing is rounded and the filter is exact. */
static double orient_integer_bound(const lh__eng *e)
{
    const int d = LH_PD(e);
    if (!e->integer || d < 2 || d > 5) return INFINITY;
    double s = 0, bound = 1;
    for (int j = 0; j < d; j++) s = e->span[j] > s ? e->span[j] : s;
    for (int k = 1; k <= d; k++) bound *= k * s;
    return bound;
}

/* orient_d's static filter bound for this computation's sites (+infinity: none;
 * 0 where the filter is exact); run once per insertion call. */
static void prepare_orient(lh__eng *e)
{
    e->orient_exact = orient_integer_bound(e) < 0x1p53;
    e->orient_eb = e->orient_exact ? 0 : lh__static_bound(0, LH_PD(e), e->span);
}

/* lh_orient of the d + 1 points p: exact, 0 when they are affinely dependent. */
static LH__ALWAYS_INLINE int orient_inline(lh__eng *e, const double *const *p)
{
    const int d = LH_PD(e);
    int s = lh__static_d(0, d, p, e->orient_eb);
    if (s) {
        e->filtered++;
        return s;
    }
    if (e->orient_exact) {
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
