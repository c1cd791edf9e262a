/* delaunay.c — `lifthull delaunay`: the Delaunay triangulation of a point file, as
 * Qhull's `i` format, a summary, or a mesh file (VTK, Gmsh, OFF, SVG, Triangle). */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno */
#include "args.h"
#include "cli.h"
#include "mesh_out.h"
#include "outfile.h"
#include "progress.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const char help[] =
    "usage: lifthull delaunay [-s] [-u] [-a] [-q] [-o FILE [-f]] [--ascii] [POINTS]\n"
    "\n"
    "The Delaunay triangulation of the points in POINTS (or standard input): Qhull's\n"
    "point format (rbox output as it is), Triangle/TetGen .node, or columns (blank- or\n"
    "comma-separated, one point a line). Exact: cospherical and duplicate sites are\n"
    "fine; every simplex has positive volume.\n"
    "\n"
    "Output: Qhull's 'i' format (the count, then one simplex a line as 0-based site\n"
    "indices, positively oriented), or with -o FILE the format its name asks for:\n"
    "  .vtu  VTK (ParaView; binary, --ascii: text)   .msh  Gmsh 4.1   .off  OFF (2D)\n"
    "  .node / .ele  Triangle/TetGen BASE.node, BASE.ele, BASE.neigh (numbered from 1)\n"
    "  .svg  a picture (2D; --circles adds the circumcircles)\n"
    "  other names: the 'i' format.\n"
    "\n"
    "options:\n"
    "  -s         a summary instead of the simplices\n"
    "  -u         the furthest-site triangulation (Qhull's Qu)\n"
    "  -a         points spanning only a k-flat (1 <= k < d) are triangulated within\n"
    "             it (k+1 indices a simplex) instead of failing\n"
    "  -q         no progress line (shown on a terminal after 2 s of reading,\n"
    "             inserting or writing)\n"
    "  -o FILE    write FILE, whole or not at all; an existing FILE needs -f\n"
    "  --ascii    a .vtu as text (default: binary, base64 inline)\n"
    "  --threads N  insert with N threads (default 0: one per CPU); the output\n"
    "             is the same, byte for byte\n"
    "\n"
    "examples:\n"
    "  rbox 1000 D3 | lifthull delaunay\n"
    "  lifthull points 10000 -d 2 | lifthull delaunay -o mesh2d.vtu\n"
    "  lifthull points 100000 -d 3 | lifthull delaunay --threads 0 -o mesh3d.vtu -f\n"
    "  lifthull delaunay -s examples/ukraine.txt\n"
    "\n"
    "exit codes: 0 done, 1 the computation failed (e.g. all points on a plane: the\n"
    "message names the affine dimension), 2 usage, 3 bad input file.\n";

static void summary(FILE *f, const lh_points *p, lh_tri *t, double seconds)
{
    int k = lh_tri_simplex_dim(t);
    fprintf(f, "sites %zu\ndimension %d\n", p->n, p->d);
    if (k < p->d) fprintf(f, "affine hull dimension %d\n", k);
    fprintf(f, "simplices %zu\nhull facets %zu\nduplicates %zu\nseconds %.3f\n", lh_tri_count(t),
            lh_tri_hull_count(t), lh_tri_duplicate_count(t), seconds);
}

static void simplices(FILE *f, lh_tri *t)
{
    const int nv = lh_tri_simplex_dim(t) + 1;
    const lh_index *s = lh_tri_simplices(t);
    fprintf(f, "%zu\n", lh_tri_count(t));
    for (size_t i = 0; i < lh_tri_count(t); i++) {
        for (int k = 0; k < nv; k++) fprintf(f, k ? " %" LH_INDEX_PRI : "%" LH_INDEX_PRI, s[i * nv + k]);
        fputc('\n', f);
    }
}

int lh_cli_delaunay(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "delaunay", "suaqfocA", 0, 1, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    /* every output target is checked before the input is read */
    if (!(a.summary ? lh_cli_out_check("delaunay", a.output, a.force, a.file[0])
                    : lh_cli_mesh_out_check("delaunay", &a, a.file[0])))
        return LH_EXIT_FAIL;
    lh_cli_progress prog;
    lh_cli_progress_init(&prog, "delaunay", a.quiet);
    lh_points pts;
    const char *name;
    if (!lh_cli_load_progress(a.file[0], a.format, &pts, &name, &prog)) return LH_EXIT_INPUT;
    lh_options opt;
    lh_options_default(&opt);
    opt.furthest_site = a.furthest;
    opt.affine_hull = a.affine;
    opt.threads = a.threads;
    lh_cli_progress_attach(&prog, "delaunay", a.quiet, &opt);
    lh_tri *t;
    lh_status st = lh_delaunay(pts.d, pts.n, pts.xyz, &opt, &t);
    double seconds = lh_cli_seconds() - prog.start;
    lh_cli_progress_done(&prog);
    if (st != LH_OK) {
        lh_cli_report_failure(name, pts.d, pts.n, pts.xyz, st);
        lh_points_free(&pts);
        return LH_EXIT_FAIL;
    }
    int status;
    if (!a.summary && lh_cli_is_mesh_path(a.output)) {
        status = lh_cli_write_mesh("delaunay", &a, a.file[0], t, pts.xyz, 0, &prog);
    } else {
        lh_cli_out out;
        status = LH_EXIT_FAIL;
        if (lh_cli_out_open(&out, "delaunay", a.output, a.force, a.file[0])) {
            /* a terminal shows the output itself */
            if (!isatty(fileno(out.f)))
                lh_cli_progress_file(&prog, "writing", a.output ? a.output : "<stdout>", out.f);
            if (a.summary) summary(out.f, &pts, t, seconds);
            else simplices(out.f, t);
            lh_cli_progress_file_done(&prog);
            status = lh_cli_out_close(&out, "delaunay", 1);
        }
    }
    lh_tri_free(t);
    lh_points_free(&pts);
    return status;
}
