/*
 * intersect.h — the exact triangle-triangle test behind lh_plc_intersections.
 */
#ifndef LH_INTERSECT_H
#define LH_INTERSECT_H

#include "lifthull.h"

/*
 * Whether closed triangles a and b (each of three non-collinear points) meet other
 * than in what they share. Their first `shared` vertices are the same points, in the
 * same order (a[i] and b[i] equal for i < shared); the others are distinct from
 * every vertex of the other triangle. Precisely:
 *   shared 0: a and b intersect;
 *   shared 1 (vertex v): a and b meet in a point other than v;
 *   shared 2 (edge e): a and b meet outside e — they are coplanar and lie on the same
 *            side of e (they overlap);
 *   shared 3: always (the same triangle).
 * Exact: orient_3 signs, and orient_2 signs in a coordinate projection for coplanar
 * configurations.
 */
int lh__tri_tri_meet(lh_pred *pred, const double *const a[3], const double *const b[3], int shared);

#endif
