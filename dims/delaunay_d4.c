/* delaunay_d4.c — the Delaunay insertion loop compiled for d = 4 (insert_dims.h). */
#define LH_DIM 4
#define LH_T_NAME lh__dims_insert_4
#include "insert_dims.h"
