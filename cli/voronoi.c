/* voronoi.c — `lifthull voronoi`: the Voronoi diagram, in qvoronoi's 'o' format or as
 * an SVG picture (2D). */
#include "args.h"
#include "cli.h"
#include "mesh_out.h"
#include "outfile.h"
#include "progress.h"
#include "qhull.h"

#include <string.h>

static const char help[] =
    "usage: lifthull voronoi [-q] [--circles] [-o FILE [-f]] [POINTS]\n"
    "\n"
    "The Voronoi diagram of the points (Qhull's point format, .node, or columns; or\n"
    "standard input), the dual of the exact Delaunay triangulation: Voronoi vertex v\n"
    "is the circumcentre of Delaunay simplex v-1.\n"
    "\n"
    "Output: qvoronoi's 'o' format — the dimension; the number of Voronoi vertices\n"
    "(with the vertex at infinity, 0, printed as -10.101), of regions, and 1; the\n"
    "vertices; then one region a site: its vertex count and vertices (0 when the region\n"
    "is unbounded; in 2D in cyclic order). With -o FILE.svg: a picture of the sites,\n"
    "the Delaunay triangulation and the Voronoi diagram (2D; --circles adds the\n"
    "circumcircles). Other -o names get the 'o' format.\n"
    "\n"
    "examples:\n"
    "  rbox 100 D2 | lifthull voronoi\n"
    "  lifthull voronoi examples/ukraine.txt -o voronoi.svg -f\n"
    "\n"
    "exit codes: 0 done, 1 the computation failed, 2 usage, 3 bad input file.\n";

static int svg(const lh_cli_args *a, const lh_points *pts, const char *name)
{
    lh_options opt;
    lh_options_default(&opt);
    opt.threads = a->threads;
    lh_cli_progress prog;
    lh_cli_progress_attach(&prog, "voronoi", a->quiet, &opt);
    lh_tri *t;
    lh_status st = lh_delaunay(pts->d, pts->n, pts->xyz, &opt, &t);
    lh_cli_progress_done(&prog);
    if (st != LH_OK) {
        lh_cli_report_failure(name, pts->d, pts->n, pts->xyz, st);
        return LH_EXIT_FAIL;
    }
    int status = lh_cli_write_mesh("voronoi", a, a->file[0], t, pts->xyz, 1, &prog);
    lh_tri_free(t);
    return status;
}

static int text(const lh_cli_args *a, const lh_points *pts, const char *name)
{
    char *argv[1] = {"o"};
    lh_cli_qopts o;
    lh_cli_qparse(&o, LH_QPROG_VORONOI, 1, argv);
    o.name = "voronoi";
    lh_cli_qmodel mo;
    if (!lh_cli_qmodel_build(&mo, &o, pts->d, pts->n, pts->xyz, name)) return LH_EXIT_FAIL;
    lh_cli_out out;
    int status = LH_EXIT_FAIL;
    if (lh_cli_out_open(&out, "voronoi", a->output, a->force, a->file[0])) {
        int ok = lh_cli_qprint(out.f, &o, &mo, "o");
        if (!ok) fprintf(stderr, "lifthull voronoi: out of memory\n");
        status = lh_cli_out_close(&out, "voronoi", ok);
    }
    lh_cli_qmodel_free(&mo);
    return status;
}

int lh_cli_voronoi(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "voronoi", "qfoc", 0, 1, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check("voronoi", a.output, a.force, a.file[0])) return LH_EXIT_FAIL;
    lh_cli_progress prog;
    lh_cli_progress_init(&prog, "voronoi", a.quiet);
    lh_points pts;
    const char *name;
    if (!lh_cli_load_progress(a.file[0], a.format, &pts, &name, &prog)) return LH_EXIT_INPUT;
    const char *dot = a.output ? strrchr(a.output, '.') : NULL;
    int status = dot && !strcmp(dot, ".svg") ? svg(&a, &pts, name) : text(&a, &pts, name);
    lh_points_free(&pts);
    return status;
}
