/* delaunay_d4_par.c — delaunay_d4.c's loop as a worker of a parallel phase
 * (hull/parallel.c). */
#define LH_DIM 4
#define LH_T_NAME lh__dims_insert_4_par
#define LH_T_PARALLEL
#include "insert_dims.h"
