/*
 * insert_delaunay.h — hull/'s insertion loop (insert_impl.h) handed the lifted
 * conflict test inline (insert_lifted.h). The includer defines LH_T_NAME, and
 * LH_DIM for a fixed dimension (its loops see constant sizes and the filters for
 * that dimension are called directly) or leaves it undefined for the dimension a
 * run-time value, and LH_T_PARALLEL for a worker of a parallel phase
 * (hull/parallel.c). CMake stamps out one source per dimension 2..5 and the
 * run-time one, sequential and parallel (lift/CMakeLists.txt); every build makes
 * the same decisions, so the same output.
 */
#ifdef LH_DIM
#define LH_T_D LH_DIM
#endif
#include "insert_lifted.h"

#define LH_T_FINITE_CONFLICT(e, v, q) lifted_conflict(e, v, q)
#define LH_T_FINITE_CONFLICT2(e, v, w, q, x) lifted_conflict2(e, v, w, q, x)
#define LH_T_PLACING(e) 0
#define LH_T_ORIENT(e, pts) orient_inline(e, pts)
#define LH_T_PREPARE(e) prepare_lifted(e)
#include "insert_impl.h"
