/* insert_generic_par.c — insert_generic.c's loop as a worker of a parallel phase
 * (parallel.c): the same source with LH_T_PARALLEL. */
#define LH_T_PARALLEL
#include "insert_generic.c"
