/* insert_generic.c — the insertion loop (insert_impl.h) with the dimension a
 * runtime value and the conflict test the caller's function (engine.h:
 * finite_conflict; NULL: no finite cell conflicts, a placing triangulation).
 * Loops with a conflict test inline are compiled where that test lives. */
#include "insert_orient.h"

static LH__ALWAYS_INLINE int finite_conflict(lh__eng *e, const lh_index *v, lh_index q)
{
    return e->finite_conflict && e->finite_conflict(e->user, v, q);
}

static LH__ALWAYS_INLINE void finite_conflict2(lh__eng *e, const lh_index *v, const lh_index *w, lh_index q,
                                               int *x)
{
    x[0] = finite_conflict(e, v, q);
    x[1] = finite_conflict(e, w, q);
}

#define LH_T_NAME lh__eng_insert_generic
#define LH_T_FINITE_CONFLICT(e, v, q) finite_conflict(e, v, q)
#define LH_T_FINITE_CONFLICT2(e, v, w, q, x) finite_conflict2(e, v, w, q, x)
#define LH_T_PLACING(e) (!(e)->finite_conflict)
#define LH_T_ORIENT(e, pts) orient_inline(e, pts)
#define LH_T_PREPARE(e) prepare_orient(e)
#include "insert_impl.h"
