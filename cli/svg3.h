/* svg3.h — drawing a tetrahedral mesh's triangles in an SVG picture (svg3.c): a fixed
 * oblique parallel view (azimuth 35 degrees, elevation 25), the triangles painted far
 * to near by their centroids' depth (the painter's algorithm: exact for a convex
 * surface, a picture and not a proof otherwise), shaded by a fixed light. Canvas as
 * svg.c's: the projection's bounding box plus a 5% margin, its longer side 10^4
 * units, y down, integer coordinates, computed on the points multiplied by a power of
 * two (lh_cli_svg_shift) so that no coordinate overflows. */
#ifndef LH_CLI_SVG3_H
#define LH_CLI_SVG3_H

#include "lifthull.h"

#include <stddef.h>
#include <stdio.h>

#define LH_SVG3_CANVAS 10000.0

typedef struct lh_cli_camera {
    int shift; /* points drawn multiplied by 2^-shift */
    double right[3], up[3], dir[3];
    double u0, v1, scale, width, height; /* canvas: (u - u0) scale, (v1 - v) scale */
} lh_cli_camera;

/* The view framing the corners of the count triangles tri (3 point indices each), or
 * every point of xyz (np) when count is 0. */
lh_cli_camera lh_cli_camera_aim(const double *xyz, size_t np, const lh_index *tri, size_t count);
/* p's depth along the view (larger: farther). */
double lh_cli_camera_depth(const lh_cli_camera *c, const double *p);
/* The count triangles' indices, farthest first (ties by index), malloc'ed; NULL when
 * out of memory. */
size_t *lh_cli_camera_order(const lh_cli_camera *c, const double *xyz, const lh_index *tri,
                            size_t count);
/* The light's cosine with triangle t's normal, from 0.55 (edge on) to 1 (facing it). */
double lh_cli_camera_shade(const lh_cli_camera *c, const double *xyz, const lh_index *t);
/* "<path d=\"M..L..L..Z\"" of triangle t, for its fill and the closing "/>". */
void lh_cli_camera_path(FILE *f, const lh_cli_camera *c, const double *xyz, const lh_index *t);

#endif
