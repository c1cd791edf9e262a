/* pslg_io.h — 2D meshing input and output for the `triangle` and `mesh` commands:
 * loading (pslg_load.c) and Triangle's output files (trimesh_write.c). */
#ifndef LH_CLI_PSLG_IO_H
#define LH_CLI_PSLG_IO_H

#include <stdio.h>

#include "lifthull.h"

enum { LH_CLI_NODE, LH_CLI_POLY, LH_CLI_RINGS };

typedef struct lh_cli_pslg {
    lh_pslg g;          /* the graph (for a .node: pointing into pts)  */
    lh_points pts;      /* a .node's points                            */
    const char *path;   /* the file read                               */
    char *node_path;    /* BASE.node when the .poly had no vertices (read
                           too, so never written), or NULL              */
    int kind;           /* LH_CLI_*                                    */
    lh_cells ele;       /* -r: the mesh to refine (BASE.ele), in g.cover */
    double *area;       /* -ra: its triangles' area bounds (BASE.area)   */
} lh_cli_pslg;

/* Reads path as kind; a .poly without vertices takes base.node's. Returns 1, or 0
 * after printing the problem (FILE:LINE:COL: ...). */
int lh_cli_pslg_load(lh_cli_pslg *in, const char *path, const char *base, int kind);
void lh_cli_pslg_free(lh_cli_pslg *in);
/* Triangle's -r: BASE.ele (triangles of the points read) becomes in->g.cover and,
 * with area, BASE.area its cover_area. Returns 1, or 0 after printing the problem
 * (FILE:LINE:COL: ...). */
int lh_cli_pslg_load_mesh(lh_cli_pslg *in, const char *base, int area);
/* Triangle's .area (bound_read.c): count area bounds, one per triangle of the .ele,
 * from f into area. Returns 1, or 0 after printing the problem (FILE:LINE:COL: ...). */
int lh_cli_area_read(FILE *f, const char *path, size_t count, double *area);
/* Prints lh_pslg_triangulate's failure as "FILE:LINE: ..." or "FILE: ...". */
void lh_cli_pslg_report(const lh_cli_pslg *in, const lh_error *err);

/* Triangle's output files and what goes in them (its switches in brackets). */
typedef struct lh_cli_tri_files {
    int node, ele, poly;  /* write BASE.node, .ele, .poly (not N, E, P)         */
    int edge, neigh, off; /* BASE.edge (e), .neigh (n), .off (g)                */
    int markers;          /* boundary markers in the files (not B)              */
    int base;             /* first number, 0 (z) or 1                           */
    int jettison;         /* leave out points in no triangle, renumbering (j)   */
    int no_replace;       /* refuse to replace existing files (mesh without -f;
                             Triangle replaces its outputs)                    */
    int voronoi;          /* BASE.v.node, BASE.v.edge: the Voronoi diagram (v)  */
    int order2;           /* quadratic elements: midpoint nodes (o2)            */
} lh_cli_tri_files;

/* Writes the files BASE.node etc. whole or not at all (each to a temporary file,
 * renamed together at the end when all were written; none left behind on failure:
 * outfile.h); in supplies the holes and
 * regions for .poly. Never replaces an input file (in->path, in->node_path).
 * Returns 0 (LH_EXIT_OK) or LH_EXIT_FAIL after printing the problem. */
int lh_cli_trimesh_write(const lh_trimesh *m, const lh_cli_pslg *in, const char *base,
                         const lh_cli_tri_files *w, const char *cmd);
/* Checks every file lh_cli_trimesh_write would write (lh_cli_out_check), before the
 * input is read. Returns 1, or 0 after printing the problem. */
int lh_cli_trimesh_check(const char *base, const lh_cli_tri_files *w, const char *input, const char *cmd);

/* The mesh's edges as Triangle's .edge file numbers them (trimesh_edges.c): triangle
 * by triangle, the edges opposite corners 0, 1, 2, each at the first triangle holding
 * it. id: 3 per triangle, the number of its edge opposite each corner; end: 2 per edge
 * (counterclockwise in tri[0]); mark: its subsegment's marker, else 0; tri: 2 per edge,
 * the triangle holding it first and the one across (-1 on the boundary). */
typedef struct lh_cli_edges {
    size_t n;
    lh_index *id, *end, *mark, *tri;
} lh_cli_edges;
/* Returns 1, or 0 out of memory (e freed). */
int lh_cli_edges_build(lh_cli_edges *e, const lh_trimesh *m);
void lh_cli_edges_free(lh_cli_edges *e);
/* Triangle's -v files: FILE.v.node, one Voronoi vertex per triangle (its circumcentre,
 * the vertex attributes interpolated linearly, no markers); FILE.v.edge, one Voronoi
 * edge per mesh edge in the .edge order: the two triangles' vertices, or on the
 * boundary "t -1 dx dy", a ray from t's circumcentre outward across the edge (dx dy
 * the edge turned clockwise; halved where its length overflows). */
void lh_cli_write_vnode(FILE *f, const lh_trimesh *m, int base);
void lh_cli_write_vedge(FILE *f, const lh_trimesh *m, const lh_cli_edges *e, int base);

/* The quality report: counts, angle and area ranges, an angle histogram, the
 * triangles below the bounds numbered from first (as the files written: 1, or 0 with
 * Triangle's -z, VTU and OFF). */
void lh_cli_trimesh_report(FILE *out, const lh_trimesh *m, double min_angle, int first);
/* Triangle p[0..2]'s angles in degrees (ang[k] at p[k]), radius-edge ratio (circumradius
 * over shortest edge; infinity when flat) and edge lengths (len[k] opposite p[k];
 * infinity beyond DBL_MAX), scale-free: the edge vectors are computed at half scale
 * when a difference overflows, then scaled by the power of two of their largest
 * component, so points near +-DBL_MAX, near 1e-300 or both give no NaN. */
void lh_cli_triangle_shape(const double *const p[3], double ang[3], double *ratio, double len[3]);
/* The line that says refinement left subsegments unsplit (stats.segments_unsplit). */
void lh_cli_trimesh_unsplit(FILE *out, const lh_trimesh_stats *s);
/* The line saying refinement stopped at its Steiner budget (s->steiner_budget_reached). */
void lh_cli_trimesh_budget(FILE *out, const lh_trimesh_stats *s, double min_angle);

/* An SVG picture of m (mesh_svg.c): triangles shaded by their smallest angle, red
 * below min_angle (0: no bound), the subsegments thick, the bad triangles outlined
 * red, a legend headed by title. Returns 0, or -1 on a write error or out of memory. */
int lh_cli_trimesh_svg(FILE *f, const lh_trimesh *m, double min_angle, const char *title);

#endif
