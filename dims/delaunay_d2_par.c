/* delaunay_d2_par.c — delaunay_d2.c's loop as a worker of a parallel phase
 * (hull/parallel.c). */
#define LH_DIM 2
#define LH_T_NAME lh__dims_insert_2_par
#define LH_T_PARALLEL
#include "insert_dims.h"
