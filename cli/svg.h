/* svg.h — an SVG picture of a 2D Delaunay triangulation, its Voronoi diagram, the
 * circumcircles and the sites (for the CLI; drawing only, in plain doubles). */
#ifndef LH_CLI_SVG_H
#define LH_CLI_SVG_H

#include "lifthull.h" /* lh_index */

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* What to draw, as flat arrays the caller owns (nothing is copied or kept). */
typedef struct lh_cli_svg {
    size_t site_count;        /* n                                                   */
    const double *sites;      /* 2n doubles: x, y of each site (y up, as in the input) */
    size_t tri_count;         /* triangles, may be 0 (then only sites are drawn)     */
    const lh_index *tris;     /* 3 * tri_count site indices, either orientation      */
    const lh_index *neighbors; /* 3 * tri_count, or NULL (then computed here): the
                                 neighbour across the edge opposite vertex k, -1
                                 across the convex hull (lh_tri_neighbors' layout)   */
    int draw_delaunay;        /* nonzero: the triangles' edges                       */
    int draw_voronoi;         /* nonzero: the Voronoi diagram, the dual: an edge
                                 between the circumcentres of neighbouring triangles,
                                 a ray outward across each hull edge                 */
    int draw_circles;         /* nonzero: each triangle's circumcircle               */
    int draw_sites;           /* nonzero: a dot per site                             */
    const char *title;        /* the legend's first words, or NULL for "lifthull"   */
} lh_cli_svg;

/* Writes the picture to f: the viewBox is the sites' bounding box plus a margin (y
 * pointing up), with a legend line above it; everything outside it is clipped. All
 * edges of one kind go into a few <path> elements (a dot per site too), coordinates
 * are integers on a 10^4-unit scale, so 10^4 sites make about 1.5 MB. Returns 0, or
 * -1 on a write error (ferror(f) or a failed fflush) or when out of memory. f stays
 * open. */
int lh_cli_svg_write(FILE *f, const lh_cli_svg *s);

/* The exponent e that brings the largest magnitude of the box lo..hi into [1/2, 1)
 * when every coordinate is multiplied by 2^-e (0 for an empty or all-zero box). A
 * picture drawn from coordinates scaled so has a finite, nonzero side, margin and
 * canvas scale for any finite points, subnormals, +-DBL_MAX or both: the scaling is
 * exact but where a coordinate far below the largest underflows, far below a canvas
 * unit (svg.c, mesh_svg.c). */
int lh_cli_svg_shift(const double lo[2], const double hi[2]);

/* For the mesh pictures (mesh_svg.c, mesh_svg3.c): s as XML text (& < > escaped,
 * control bytes left out); the document's start: the viewBox 0 -legend .. width x
 * height + legend (a tenth of it in pixels), the title, a white background. */
void lh_cli_svg_escaped(FILE *f, const char *s);
void lh_cli_svg_begin(FILE *f, double width, double height, double legend, const char *title);

#endif
