/* delaunay_d3.c — the Delaunay insertion loop compiled for d = 3 (insert_dims.h). */
#define LH_DIM 3
#define LH_T_NAME lh__dims_insert_3
#include "insert_dims.h"
