/* tetgen_io.h — 3D meshing input and output for the `tetgen` and `mesh` commands:
 * loading a PLC (tetgen_load.c), the mesh's faces and edges as TetGen numbers them
 * (tetgen_items.c), and the SVG picture of the boundary (mesh_svg3.c). */
#ifndef LH_CLI_TETGEN_IO_H
#define LH_CLI_TETGEN_IO_H

#include "lifthull.h"

#include <stdio.h>

/* A 3D meshing input. */
typedef struct lh_cli_plc {
    lh_plc g;          /* the PLC (for a .node: pointing into pts)              */
    lh_points pts;     /* a .node's points                                      */
    int read;          /* g was filled by lh_plc_read (lh_plc_free releases it) */
    const char *path;  /* the file read                                         */
    char *node_path;   /* BASE.node when the .poly had no points (read too, so
                          never written), or NULL                               */
    int binary;        /* a binary PLY or STL: item places are record numbers   */
} lh_cli_plc;

/* The input extensions 3D meshing reads, by lh_plc_read (".node" by lh_points_read):
 * whether path ends in one (its length into *stem). */
int lh_cli_plc_path(const char *path, size_t *stem);

/* Reads path (a .node with lh_points_read: a point set; anything else with
 * lh_plc_read, a .poly without points taking BASE.node's, BASE = path without its
 * extension). Returns 1, or 0 after printing "lifthull CMD: FILE:LINE:COL: ..." on
 * standard error. */
int lh_cli_plc_load(lh_cli_plc *in, const char *cmd, const char *path);
/* A tetrahedral mesh to refine (-r): BASE.node's points (BASE = node_path's first
 * stem bytes) and BASE.ele's tets, as the PLC they bound (lh_plc_from_tetmesh). 1, or
 * 0 after printing the problem as lifthull CMD. */
int lh_cli_mesh_load(lh_cli_plc *in, const char *cmd, const char *node_path, size_t stem);
void lh_cli_plc_free(lh_cli_plc *in);
/* Whether the input is points only (no facet, no segment): its mesh is the
 * Delaunay tetrahedralization of their convex hull. */
int lh_cli_plc_is_points(const lh_cli_plc *in);
/* Leaves only the points (TetGen without -p: a Delaunay tetrahedralization). */
void lh_cli_plc_points_only(lh_cli_plc *in);
/* Prints lh_tetrahedralize's (or another call's) failure: "lifthull CMD: FILE:..." */
void lh_cli_plc_report(const lh_cli_plc *in, const char *cmd, const lh_error *err);
/* Exit code for a failed meshing call: 1 out of memory or internal, 3 the input. */
int lh_cli_plc_exit(lh_status st);

/* -d: lists the pairs of facets that intersect (the first `limit`, 0: all) on out,
 * facets numbered from `first`. Returns 0 none, 1 some, -1 after printing a
 * failure. */
int lh_cli_plc_intersections(FILE *out, const lh_cli_plc *in, const char *cmd, size_t limit, int first);

/* -C: lh_tetmesh_check of m against the input; prints the verdict on out. Returns
 * 1 valid, 0 not (or the check failed; printed). */
int lh_cli_tetmesh_verify(FILE *out, const lh_tetmesh *m, const lh_cli_plc *in, const char *cmd);

/* The mesh's faces or edges, every one once, in TetGen's order (tetrahedron by
 * tetrahedron): v (k+1 per item), mark (the subface's or subsegment's marker, 0 for
 * others). */
typedef struct lh_cli_items {
    size_t n;
    lh_index *v, *mark;
} lh_cli_items;
/* k = 2: every face; k = 1: every edge. Returns 1, or 0 out of memory (it freed). */
int lh_cli_items_build(lh_cli_items *it, const lh_tetmesh *m, int k);
void lh_cli_items_free(lh_cli_items *it);

/* The one-line summary and -V's statistics of a mesh. */
void lh_cli_tetmesh_summary(FILE *out, const char *name, const lh_tetmesh *m, double secs);
int lh_cli_tetmesh_stats(FILE *out, const lh_cli_plc *in, const lh_tetmesh *m, const char *cmd);
/* tetmesh_report.c: m's quality figures and histograms (lh_tetmesh_measure) as TetGen's
 * -V prints them; 0 (after saying why on stderr, as lifthull CMD) when they could not
 * be computed. */
int lh_cli_tetmesh_quality(FILE *out, const lh_tetmesh *m, const char *cmd);
/* tetmesh_report.c: the tets refinement left over its bounds, counted by why, the worst
 * `limit` listed (lh_tetmesh_leftovers), numbered from first; nothing when none. */
void lh_cli_tetmesh_leftovers(FILE *out, const lh_tetmesh *m, size_t limit, int first);
/* tetgen_order2.c: TetGen's -o2 .ele (10 nodes a row, attrs NULL or one per tet) and
 * .face/.edge (count simplices v of `corners` 3 or 2 points, then their midpoints,
 * markers NULL or one each), numbered from first; LH_ERR_IO on a write error,
 * LH_ERR_INVALID_ARGUMENT when m has no second-order nodes. */
/* bound_read.c: TetGen's .mtr, count sizes (one per input point, each positive) into
 * size; 0 after printing "FILE:LINE:COL: ..." on stderr. */
int lh_cli_mtr_read(FILE *f, const char *path, size_t count, double *size);
/* tetgen_sizing.c: -m's sizing function, the .mtr's sizes at g's points interpolated
 * linearly in their Delaunay tetrahedralization (outside its hull: the nearest
 * point's). lh_cli_sizing_load: 1, or 0 after printing the problem as lifthull CMD;
 * lh_cli_sizing_at: an lh_sizing_fn of a loaded lh_cli_sizing. */
typedef struct lh_cli_sizing {
    lh_tri *t;
    double *size;
} lh_cli_sizing;
int lh_cli_sizing_load(lh_cli_sizing *s, const char *path, const lh_plc *g, const char *cmd);
double lh_cli_sizing_at(void *user, const double xyz[3]);
void lh_cli_sizing_free(lh_cli_sizing *s);
lh_status lh_cli_ele_order2_write(FILE *f, const lh_tetmesh *m, const double *attrs, int first);
lh_status lh_cli_simplex_order2_write(FILE *f, const lh_tetmesh *m, size_t count, int corners,
                                      const lh_index *v, const lh_index *markers, int first);

/* The Medit .mesh of m (lh_medit_write): point and face markers as references
 * (with markers), the region attributes as the tetrahedra's (with attrs; whole
 * numbers only, else LH_ERR_INVALID_ARGUMENT after a message). */
lh_status lh_cli_tetmesh_medit(FILE *f, const lh_tetmesh *m, int markers, int attrs, const char *cmd);

/* `lifthull mesh` with a 3D input (mesh3.c), its options parsed by mesh.c. */
typedef struct lh_cli_mesh3_args {
    const char *file, *output;
    int force, quiet, ascii, check, report;
    int clip; /* the .svg: the quality picture (lh_cli_tetmesh_svg_clip) */
    lh_tetmesh_options opt;
} lh_cli_mesh3_args;
int lh_cli_mesh3(const lh_cli_mesh3_args *a);
/* For `mesh -o OUTPUT` (mesh.c): the np point markers pm as doubles (a point field),
 * malloc'ed; NULL after a message when out of memory or when OUTPUT is node_path,
 * an input. */
double *lh_cli_mesh_markers(const char *output, const char *node_path, const lh_index *pm, size_t np);
/* Whether FILE is a 3D meshing input: a .poly or .node whose header says 3
 * coordinates (a .poly without points: BASE.node's), or another extension
 * lh_cli_plc_path knows. */
int lh_cli_plc_is_3d(const char *path);

/* An SVG picture of m's boundary faces (mesh_svg3.c), coloured by facet marker,
 * seen along a fixed oblique direction, far faces painted first; a legend headed by
 * title. Returns 0, or -1 on a write error or out of memory. */
int lh_cli_tetmesh_svg(FILE *f, const lh_tetmesh *m, const char *title);
/* The SVG picture of m's quality (mesh_svg3_clip.c): the mesh cut through the middle,
 * facing the same view, each face drawn in the colour of its tetrahedron's smallest
 * dihedral angle, and the dihedral angles' histogram below. Returns as
 * lh_cli_tetmesh_svg. */
int lh_cli_tetmesh_svg_clip(FILE *f, const lh_tetmesh *m, const char *title);

#endif
