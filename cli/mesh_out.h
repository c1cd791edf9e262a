/* mesh_out.h — a triangulation written in the format its file name asks for. */
#ifndef LH_CLI_MESH_OUT_H
#define LH_CLI_MESH_OUT_H

#include "args.h"
#include "lifthull.h"
#include "progress.h"

/* Whether path's extension names a mesh format: .vtu .msh .off .svg .node .ele. */
int lh_cli_is_mesh_path(const char *path);

/* Writes t (sites xyz) to a->output, whole or not at all: .vtu (VTK XML), .msh (Gmsh
 * 4.1), .off, .svg (2D: sites and Delaunay edges; with `voronoi` the Voronoi diagram
 * too; a->circles adds circumcircles), .node/.ele (Triangle/TetGen: BASE.node,
 * BASE.ele and BASE.neigh, numbered from 1 as Triangle does: all three or none).
 * Returns an exit code (message printed on failure). prog (or NULL) shows the
 * writing. */
int lh_cli_write_mesh(const char *cmd, const lh_cli_args *a, const char *input, lh_tri *t,
                      const double *xyz, int voronoi, lh_cli_progress *prog);

/* Checks every file lh_cli_write_mesh would write for a->output (for .node/.ele all
 * three; also the other names), before the input is read. Returns 1, or 0 after
 * printing the problem. */
int lh_cli_mesh_out_check(const char *cmd, const lh_cli_args *a, const char *input);

#endif
