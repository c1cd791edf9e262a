/* insert_generic_par.c — insert_generic.c's loop as a worker of a parallel phase
 * (parallel.c): Delaunay only, the dimension a runtime value. */
#include "insert_preds.h"

#define LH_T_NAME lh__eng_insert_generic_par
#define LH_T_FINITE_CONFLICT(e, v, q) (lifted_sign(e, v, q) == (e)->conflict_sign)
#define LH_T_ORIENT(e, pts) orient_inline(e, pts)
#define LH_T_PREPARE(e) prepare_preds(e)
#define LH_T_PARALLEL
#include "insert_impl.h"
