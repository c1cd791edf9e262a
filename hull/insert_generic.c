/* insert_generic.c — the insertion loop (insert_impl.h) with the dimension a
 * runtime value: every d, every mode. Its loops run over d + 1 entries at run time;
 * the predicates are the per-dimension kernels of lh_filter.gen.h (the static
 * filter where d <= 5, then the dynamic filter), chosen by a switch on d and inlined
 * as the exact arithmetic of lh_orient and lh_insphere chooses them, the exact and
 * perturbed stages called only when the filters cannot decide. In Delaunay mode
 * (conflict_sign set by lift/) the lifted conflict test is inline too; in the other
 * modes the caller's finite_conflict decides. Same decisions, so the same output,
 * as either path through pred.c. */
#include "engine.h"
#include "lh_exact.h"
#include "lh_filter.gen.h"

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

/* The static filters' bounds for this computation's sites (+infinity: none). */
static void prepare_generic(lh__eng *e)
{
    e->static_eb[0] = lh__static_bound(0, e->d, e->span);
    e->static_eb[1] = lh__static_bound(1, e->d, e->span);
}

/* insphere_sos of finite cell v (positively oriented) and vertex q. */
static LH__ALWAYS_INLINE int lifted_sign_generic(lh__eng *e, const lh_index *v, lh_index q)
{
    const int d = e->d;
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

static LH__ALWAYS_INLINE int orient_generic(lh__eng *e, const double *const *p)
{
    int s = static_sign(0, e->d, p, e->static_eb[0]);
    if (s) {
        e->filtered++;
        return s;
    }
    double det = 0, err = -1;
    if (dynamic_sign(0, e->d, p, &s, &det, &err)) {
        e->filtered++;
        return s;
    }
    return lh__orient_unfiltered(e->pred, e->d, p, det, err);
}

static LH__ALWAYS_INLINE int finite_conflict_generic(lh__eng *e, const lh_index *v, lh_index q)
{
    if (e->conflict_sign) return lifted_sign_generic(e, v, q) == e->conflict_sign;
    return e->finite_conflict && e->finite_conflict(e->user, v, q);
}

#define LH_T_NAME lh__eng_insert_generic
#define LH_T_FINITE_CONFLICT(e, v, q) finite_conflict_generic(e, v, q)
#define LH_T_ORIENT(e, pts) orient_generic(e, pts)
#define LH_T_PREPARE(e) prepare_generic(e)
#include "insert_impl.h"
