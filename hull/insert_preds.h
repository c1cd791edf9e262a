/*
 * insert_preds.h — the predicates of the insertion loop (insert_impl.h), inline:
 * the generated static filter (d <= 5, its bound from the sites' bounding box) and
 * dynamic filter of lh_filter.gen.h, then the library's exact and perturbed stages
 * only when neither decides. Same decisions as lh_orient_sos and lh_insphere_sos,
 * so the same output on every path. The dimension is the includer's constant
 * LH_T_D (dims/), or e->d at run time (insert_generic.c): a switch on it, which
 * folds away when it is a constant. Files that include this are compiled with
 * -ffp-contract=off, which the filters' error bounds assume.
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

/* The static filter of orient_d (lifted 0) or insphere_d (lifted 1): the sign, or 0
 * when it cannot decide or d has none. */
static inline int static_sign(int lifted, int d, const double *const *p, double eb)
{
    if (lifted) {
        switch (d) {
        case 2: return lh__insphere_static_2(p, eb);
        case 3: return lh__insphere_static_3(p, eb);
        case 4: return lh__insphere_static_4(p, eb);
        case 5: return lh__insphere_static_5(p, eb);
        default: return 0;
        }
    }
    switch (d) {
    case 2: return lh__orient_static_2(p, eb);
    case 3: return lh__orient_static_3(p, eb);
    case 4: return lh__orient_static_4(p, eb);
    case 5: return lh__orient_static_5(p, eb);
    default: return 0;
    }
}

/* The dynamic filter: 1 with *s the sign when it decides, else 0 with its value
 * and bound in *det, *err (pred.c's run_filter, inline here). */
static inline int dynamic_sign(int lifted, int d, const double *const *p, int *s, double *det, double *err)
{
    if (lifted) {
        switch (d) {
        case 1: return lh__insphere_filter_1(p, s, det, err);
        case 2: return lh__insphere_filter_2(p, s, det, err);
        case 3: return lh__insphere_filter_3(p, s, det, err);
        case 4: return lh__insphere_filter_4(p, s, det, err);
        case 5: return lh__insphere_filter_5(p, s, det, err);
        case 6: return lh__insphere_filter_6(p, s, det, err);
        case 7: return lh__insphere_filter_7(p, s, det, err);
        default: return lh__insphere_filter_8(p, s, det, err);
        }
    }
    switch (d) {
    case 1: return lh__orient_filter_1(p, s, det, err);
    case 2: return lh__orient_filter_2(p, s, det, err);
    case 3: return lh__orient_filter_3(p, s, det, err);
    case 4: return lh__orient_filter_4(p, s, det, err);
    case 5: return lh__orient_filter_5(p, s, det, err);
    case 6: return lh__orient_filter_6(p, s, det, err);
    case 7: return lh__orient_filter_7(p, s, det, err);
    default: return lh__orient_filter_8(p, s, det, err);
    }
}

/* The static filters' bounds for this computation's sites (+infinity: none); run
 * once per insertion call (LH_T_PREPARE). */
static void prepare_preds(lh__eng *e)
{
    e->static_eb[0] = lh__static_bound(0, LH_PD(e), e->span);
    e->static_eb[1] = lh__static_bound(1, LH_PD(e), e->span);
}

/* insphere_sos of finite cell v (positively oriented) and vertex q. */
static LH__ALWAYS_INLINE int lifted_sign(lh__eng *e, const lh_index *v, lh_index q)
{
    const int d = LH_PD(e);
    const double *p[LH__ENGINE_MAX_DIM + 2];
    for (int k = 0; k <= d; k++) p[k] = lh__eng_site(e, v[k]);
    p[d + 1] = lh__eng_site(e, q);
    int s = static_sign(1, d, p, e->static_eb[1]);
    if (s) {
        e->filtered++;
        return s;
    }
    double det = 0, err = -1; /* err stays -1 outside the filter's band */
    if (dynamic_sign(1, d, p, &s, &det, &err)) {
        if (s) {
            e->filtered++;
            return s;
        }
        return lh__insphere_sos_fast(e->pred, d, p); /* a zero column: perturbed */
    }
    return lh__insphere_sos_unfiltered(e->pred, d, p, det, err); /* exact, perturbed */
}

/* lh_orient of the d + 1 points p: exact, 0 when they are affinely dependent. */
static LH__ALWAYS_INLINE int orient_inline(lh__eng *e, const double *const *p)
{
    const int d = LH_PD(e);
    int s = static_sign(0, d, p, e->static_eb[0]);
    if (s) {
        e->filtered++;
        return s;
    }
    double det = 0, err = -1;
    if (dynamic_sign(0, d, p, &s, &det, &err)) {
        e->filtered++;
        return s;
    }
    return lh__orient_unfiltered(e->pred, d, p, det, err);
}

#endif
