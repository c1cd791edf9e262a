/* lh_tri_same.h — whether two Delaunay handles hold the same output, byte for byte:
 * the same simplex dimension k, counts, simplices, neighbours, hull facets, incident
 * simplices and duplicate map (the ambient dimension may differ: a triangulation
 * within a plane of R^3 against the same one in R^2). */
#ifndef LH_TRI_SAME_H
#define LH_TRI_SAME_H

#include "lifthull.h"

int lh_test_same_tri(const lh_tri *a, const lh_tri *b);

#endif
