/*
 * insert_lifted.h — the conflict test lift/ hands to hull/'s insertion loop
 * (insert_impl.h), inline: insphere_sos of a finite cell and the new site, the sign
 * of orient_(d+1) of their points lifted to the paraboloid (dt.h). The generated
 * static filter (d <= 5) and dynamic filter of lh_filter.gen.h first, then the
 * library's exact and perturbed stages only when neither decides: the same
 * decisions as lh_insphere_sos, so the same output on every path. The dimension is
 * the includer's constant LH_T_D, or e->d at run time (insert_orient.h).
 */
#ifndef LH_INSERT_LIFTED_H
#define LH_INSERT_LIFTED_H

#include "insert_orient.h"

/* The static filters' bounds for this computation's sites, orient_d's and
 * insphere_d's (+infinity: none; 0 where the filter is exact): insphere's lifted
 * column holds integers of at most d S^2, so its values are at most
 * (d + 1) d S^2 times orient's (insert_orient.h). Run once per insertion call. */
static void prepare_lifted(lh__eng *e)
{
    const int d = LH_PD(e);
    prepare_orient(e);
    double s = 0;
    for (int j = 0; j < d; j++) s = e->span[j] > s ? e->span[j] : s;
    e->conflict_exact = orient_integer_bound(e) * (d + 1) * d * s * s < 0x1p53;
    e->conflict_eb = e->conflict_exact ? 0 : lh__static_bound(1, d, e->span);
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
    if (e->conflict_exact) return lh__insphere_sos_zero(e->pred, d, p);
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

/* Whether finite cell v (positively oriented) conflicts with vertex q: its
 * insphere_sos equals e->conflict_sign. */
static LH__ALWAYS_INLINE int lifted_conflict(lh__eng *e, const lh_index *v, lh_index q)
{
    const double *p[LH__ENGINE_MAX_DIM + 2];
    lifted_points(e, v, q, p);
    int s = lh__static_d(1, LH_PD(e), p, e->conflict_eb);
    if (s) e->filtered++;
    else s = lifted_undecided(e, p);
    return s == e->conflict_sign;
}

/* Whether finite cells v and w each conflict with q, into x[0] and x[1]: their
 * static filters in one paired evaluation (lh__static2_d), the later stages for a
 * cell it leaves undecided. */
static LH__ALWAYS_INLINE void lifted_conflict2(lh__eng *e, const lh_index *v, const lh_index *w, lh_index q, int *x)
{
    const double *p[2][LH__ENGINE_MAX_DIM + 2];
    lifted_points(e, v, q, p[0]);
    lifted_points(e, w, q, p[1]);
    lh__static2_d(LH_PD(e), p[0], p[1], e->conflict_eb, x);
    for (int i = 0; i < 2; i++) {
        e->filtered += x[i] != 0;
        x[i] = (x[i] ? x[i] : lifted_undecided(e, p[i])) == e->conflict_sign;
    }
}

#endif
