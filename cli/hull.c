/* hull.c — `lifthull hull`: convex hull facets in qconvex's `i` format (a count line,
 * then one facet per line as d 0-based site indices, oriented outward), or a summary;
 * 3D hulls also as an OFF surface. */
#include "args.h"
#include "cli.h"
#include "outfile.h"
#include "progress.h"

#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: lifthull hull [-s] [-q] [-o FILE [-f]] [POINTS]\n"
    "\n"
    "The convex hull of the points (Qhull's point format, .node or columns; or standard\n"
    "input), exactly, in 2D to 8D: its vertices are the corners (a site on a flat face\n"
    "but not its corner is none), every facet a simplex of d corners oriented so that\n"
    "orient_d(facet, p) > 0 for points p outside; a flat face is split into simplices\n"
    "the same way whatever the input order, never\n"
    "merged. Output: the count, then one facet a line (0-based site indices; qconvex i\n"
    "lists the same facets with the last two exchanged: use lifthull qconvex for its\n"
    "exact formats); -s a summary; -o FILE.off an OFF surface (3D). A progress line\n"
    "shows on a terminal after 2 s of reading, building or writing (-q: none).\n"
    "\n"
    "examples:\n"
    "  rbox 1000 D4 | lifthull hull -s\n"
    "  lifthull points 500 -d 3 --sphere | lifthull hull -o hull.off -f\n"
    "\n"
    "exit codes: 0 done, 1 the computation failed, 2 usage, 3 bad input file.\n";

static void facets(FILE *f, const lh_hull *h)
{
    const int d = lh_hull_dim(h);
    const lh_index *v = lh_hull_facets(h);
    fprintf(f, "%zu\n", lh_hull_facet_count(h));
    for (size_t i = 0; i < lh_hull_facet_count(h); i++) {
        for (int k = 0; k < d; k++) fprintf(f, k ? " %" LH_INDEX_PRI : "%" LH_INDEX_PRI, v[i * d + k]);
        fputc('\n', f);
    }
}

static int off(FILE *f, const lh_hull *h, const lh_points *p)
{
    lh_mesh_view m = {p->d, p->n, p->xyz, 2, lh_hull_facet_count(h), lh_hull_facets(h), NULL, NULL, NULL};
    lh_status st = lh_off_write(f, &m);
    if (st == LH_ERR_DIMENSION) fprintf(stderr, "lifthull hull: an OFF surface needs a 3D hull\n");
    return st == LH_OK;
}

int lh_cli_hull(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "hull", "sqfo", 0, 1, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check("hull", a.output, a.force, a.file[0])) return LH_EXIT_FAIL;
    lh_cli_progress prog;
    lh_cli_progress_init(&prog, "hull", a.quiet);
    lh_points pts;
    const char *name;
    if (!lh_cli_load_progress(a.file[0], a.format, &pts, &name, &prog)) return LH_EXIT_INPUT;
    lh_options opt;
    lh_options_default(&opt);
    lh_cli_progress_attach(&prog, "hull", a.quiet, &opt);
    double t0 = lh_cli_seconds();
    lh_hull *h;
    lh_status st = lh_convex_hull(pts.d, pts.n, pts.xyz, &opt, &h);
    double t1 = lh_cli_seconds();
    lh_cli_progress_done(&prog);
    if (st != LH_OK) {
        lh_cli_report_failure(name, pts.d, pts.n, pts.xyz, st);
        lh_points_free(&pts);
        return LH_EXIT_FAIL;
    }
    lh_cli_out out;
    int status = LH_EXIT_FAIL;
    const char *dot = a.output ? strrchr(a.output, '.') : NULL;
    if (lh_cli_out_open(&out, "hull", a.output, a.force, a.file[0])) {
        int ok = 1;
        if (a.output) lh_cli_progress_file(&prog, "writing", a.output, out.f);
        if (a.summary)
            fprintf(out.f, "sites %zu\ndimension %d\nhull facets %zu\nhull vertices %zu\nseconds %.3f\n", pts.n,
                    pts.d, lh_hull_facet_count(h), lh_hull_vertex_count(h), t1 - t0);
        else if (dot && !strcmp(dot, ".off"))
            ok = off(out.f, h, &pts);
        else
            facets(out.f, h);
        lh_cli_progress_file_done(&prog);
        status = lh_cli_out_close(&out, "hull", ok);
    }
    lh_hull_free(h);
    lh_points_free(&pts);
    return status;
}
