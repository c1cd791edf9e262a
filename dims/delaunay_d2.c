/* delaunay_d2.c — the Delaunay insertion loop compiled for d = 2 (insert_dims.h). */
#define LH_DIM 2
#define LH_T_NAME lh__dims_insert_2
#include "insert_dims.h"
