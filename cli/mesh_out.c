/* mesh_out.c — a triangulation written as VTK, Gmsh, OFF, SVG or Triangle files. */
#include "mesh_out.h"

#include "cli.h"
#include "outfile.h"
#include "svg.h"

#include <stdlib.h>
#include <string.h>

static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot : "";
}

int lh_cli_is_mesh_path(const char *path)
{
    static const char *const exts[] = {".vtu", ".msh", ".off", ".svg", ".node", ".ele"};
    const char *e = path ? extension(path) : "";
    for (size_t i = 0; i < sizeof exts / sizeof exts[0]; i++)
        if (!strcmp(e, exts[i])) return 1;
    return 0;
}

typedef lh_status (*writer)(FILE *f, const lh_mesh_view *m, int first_index);

static lh_status vtu(FILE *f, const lh_mesh_view *m, int first)
{
    (void)first;
    return lh_vtu_write(f, m, NULL);
}
static lh_status vtu_ascii(FILE *f, const lh_mesh_view *m, int first)
{
    (void)first;
    const lh_vtu_options ascii = {1, NULL, NULL};
    return lh_vtu_write(f, m, &ascii);
}
static lh_status msh(FILE *f, const lh_mesh_view *m, int first) { (void)first; return lh_msh_write(f, m); }
static lh_status off(FILE *f, const lh_mesh_view *m, int first) { (void)first; return lh_off_write(f, m); }

/* One file through the whole-or-nothing mechanism. */
static int one_file(const char *cmd, const lh_cli_args *a, const char *input, const char *path,
                    writer w, const lh_mesh_view *m, lh_cli_progress *prog)
{
    lh_cli_out out;
    if (!lh_cli_out_open(&out, cmd, path, a->force, input)) return LH_EXIT_FAIL;
    lh_cli_progress_file(prog, "writing", path, out.f);
    lh_status st = w(out.f, m, 1);
    lh_cli_progress_file_done(prog);
    if (st != LH_OK && st != LH_ERR_IO)
        fprintf(stderr, "lifthull %s: %s: %s\n", cmd, path,
                st == LH_ERR_DIMENSION ? "the format cannot hold this dimension" : lh_status_message(st));
    return lh_cli_out_close(&out, cmd, st == LH_OK);
}

/* The three Triangle/TetGen files of a .node or .ele output name: BASE.node, BASE.ele,
 * BASE.neigh (into path[3]: lh_cli_paths); 0 when out of memory. */
static const char *const tri_ext[3] = {".node", ".ele", ".neigh"};

static int tri_paths(const char *output, char *path[3])
{
    return lh_cli_paths(output, (size_t)(extension(output) - output), tri_ext, NULL, 3, path);
}

static int is_tri_path(const char *path)
{
    const char *e = extension(path);
    return !strcmp(e, ".node") || !strcmp(e, ".ele");
}

int lh_cli_mesh_out_check(const char *cmd, const lh_cli_args *a, const char *input)
{
    if (!a->output || !is_tri_path(a->output)) return lh_cli_out_check(cmd, a->output, a->force, input);
    char *path[3];
    int ok = tri_paths(a->output, path);
    if (!ok) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    for (int i = 0; i < 3 && ok; i++) ok = lh_cli_out_check(cmd, path[i], a->force, input);
    lh_cli_paths_free(path, 3);
    return ok;
}

/* BASE.node, BASE.ele, BASE.neigh: one output set, all three or none. */
static int triangle_files(const char *cmd, const lh_cli_args *a, const char *input, const lh_mesh_view *m,
                          lh_cli_progress *prog)
{
    static const writer ws[3] = {lh_node_write, lh_ele_write, lh_neigh_write};
    char *path[3];
    FILE *f[3] = {0};
    int ok = tri_paths(a->output, path);
    if (!ok) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    lh_cli_outset set;
    lh_cli_outset_init(&set, cmd, a->force, input);
    for (int i = 0; i < 3 && ok; i++) ok = (f[i] = lh_cli_outset_add(&set, path[i])) != NULL;
    for (int i = 0; i < 3 && ok; i++) {
        lh_cli_progress_file(prog, "writing", path[i], f[i]);
        lh_status st = ws[i](f[i], m, 1);
        lh_cli_progress_file_done(prog);
        if (st != LH_OK && st != LH_ERR_IO)
            fprintf(stderr, "lifthull %s: %s: %s\n", cmd, path[i], lh_status_message(st));
        ok = st == LH_OK;
    }
    const int rc = lh_cli_outset_close(&set, ok);
    lh_cli_paths_free(path, 3);
    return rc;
}

static int svg(const char *cmd, const lh_cli_args *a, const char *input, lh_tri *t, const double *xyz,
               int voronoi, lh_cli_progress *prog)
{
    if (lh_tri_dim(t) != 2 || lh_tri_simplex_dim(t) != 2) {
        fprintf(stderr, "lifthull %s: %s: SVG pictures are of 2D triangulations\n", cmd, a->output);
        return LH_EXIT_FAIL;
    }
    lh_cli_svg s = {lh_tri_site_count(t), xyz, lh_tri_count(t), lh_tri_simplices(t),
                    lh_tri_neighbors(t), 1, voronoi, a->circles, 1,
                    voronoi ? "lifthull voronoi" : "lifthull delaunay"};
    lh_cli_out out;
    if (!lh_cli_out_open(&out, cmd, a->output, a->force, input)) return LH_EXIT_FAIL;
    lh_cli_progress_file(prog, "writing", a->output, out.f);
    const int ok = lh_cli_svg_write(out.f, &s) == 0;
    lh_cli_progress_file_done(prog);
    return lh_cli_out_close(&out, cmd, ok);
}

int lh_cli_write_mesh(const char *cmd, const lh_cli_args *a, const char *input, lh_tri *t,
                      const double *xyz, int voronoi, lh_cli_progress *prog)
{
    lh_mesh_view m = {lh_tri_dim(t), lh_tri_site_count(t), xyz, lh_tri_simplex_dim(t), lh_tri_count(t),
                      lh_tri_simplices(t), lh_tri_neighbors(t), NULL, NULL};
    const char *e = extension(a->output);
    if (!strcmp(e, ".svg")) return svg(cmd, a, input, t, xyz, voronoi, prog);
    if (is_tri_path(a->output)) return triangle_files(cmd, a, input, &m, prog);
    const writer w = !strcmp(e, ".vtu") ? (a->ascii ? vtu_ascii : vtu) : !strcmp(e, ".msh") ? msh : off;
    return one_file(cmd, a, input, a->output, w, &m, prog);
}
