/* insert_generic.c — the insertion loop (insert_impl.h) with the dimension a
 * runtime value: every d, every mode. Its loops run over d + 1 entries at run time
 * and its predicates switch on d (insert_preds.h). In Delaunay mode (conflict_sign
 * set by lift/) the lifted conflict test is inline; in the other modes the
 * caller's finite_conflict decides. insert_generic_par.c includes this file with
 * LH_T_PARALLEL defined for the parallel phases' workers (parallel.c). */
#include "insert_preds.h"

static LH__ALWAYS_INLINE int finite_conflict_generic(lh__eng *e, const lh_index *v, lh_index q)
{
    if (e->conflict_sign) return lifted_sign(e, v, q) == e->conflict_sign;
    return e->finite_conflict && e->finite_conflict(e->user, v, q);
}

static LH__ALWAYS_INLINE void finite_conflict2_generic(lh__eng *e, const lh_index *v, const lh_index *w,
                                                       lh_index q, int *x)
{
    if (!e->conflict_sign) {
        x[0] = finite_conflict_generic(e, v, q);
        x[1] = finite_conflict_generic(e, w, q);
        return;
    }
    lifted_conflict2(e, v, w, q, x);
}

#ifdef LH_T_PARALLEL
#define LH_T_NAME lh__eng_insert_generic_par
#else
#define LH_T_NAME lh__eng_insert_generic
#endif
#define LH_T_FINITE_CONFLICT(e, v, q) finite_conflict_generic(e, v, q)
#define LH_T_FINITE_CONFLICT2(e, v, w, q, x) finite_conflict2_generic(e, v, w, q, x)
#define LH_T_ORIENT(e, pts) orient_inline(e, pts)
#define LH_T_PREPARE(e) prepare_preds(e)
#include "insert_impl.h"
