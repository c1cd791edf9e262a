/* delaunay_d3_par.c — delaunay_d3.c's loop as a worker of a parallel phase
 * (hull/parallel.c). */
#define LH_DIM 3
#define LH_T_NAME lh__dims_insert_3_par
#define LH_T_PARALLEL
#include "insert_dims.h"
