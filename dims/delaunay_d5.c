/* delaunay_d5.c — the Delaunay insertion loop compiled for d = 5 (insert_dims.h). */
#define LH_DIM 5
#define LH_T_NAME lh__dims_insert_5
#include "insert_dims.h"
