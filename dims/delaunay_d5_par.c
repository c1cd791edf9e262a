/* delaunay_d5_par.c — delaunay_d5.c's loop as a worker of a parallel phase
 * (hull/parallel.c). */
#define LH_DIM 5
#define LH_T_NAME lh__dims_insert_5_par
#define LH_T_PARALLEL
#include "insert_dims.h"
