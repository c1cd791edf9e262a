/*
 * insert_dims.h — hull/'s insertion loop (insert_impl.h) for the Delaunay
 * triangulation in a fixed dimension LH_DIM (defined by the includer, with
 * LH_T_NAME): its loops see constant sizes, and the lifted conflict test and
 * orient_d call the generated filters for that dimension inline (insert_preds.h).
 * Same decisions as the generic path, so the same output.
 */
#define LH_T_D LH_DIM
#include "insert_preds.h"

#define LH_T_FINITE_CONFLICT(e, v, q) (lifted_sign(e, v, q) == (e)->conflict_sign)
#define LH_T_FINITE_CONFLICT2(e, v, w, q, x) lifted_conflict2(e, v, w, q, x)
#define LH_T_ORIENT(e, pts) orient_inline(e, pts)
#define LH_T_PREPARE(e) prepare_preds(e)
#include "insert_impl.h"
