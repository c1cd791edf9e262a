/* qhull.c — `lifthull qdelaunay | qvoronoi | qconvex OPTIONS` (qhull.h). */
#include "cli.h"
#include "outfile.h"
#include "qhull.h"

#include <stdlib.h>
#include <string.h>

static int run(lh_cli_qprog prog, int argc, char **argv)
{
    lh_cli_qopts o;
    int r = lh_cli_qparse(&o, prog, argc, argv);
    if (r != 0) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check(o.name, o.output, 1, o.input)) return LH_EXIT_FAIL;
    lh_points pts;
    const char *name;
    if (!lh_cli_load(o.input, LH_FORMAT_AUTO, &pts, &name)) return LH_EXIT_INPUT;
    if (!lh_cli_qcheck_outputs(&o, pts.d, pts.n)) {
        lh_points_free(&pts);
        return LH_EXIT_USAGE;
    }
    if (o.show_options) fprintf(stderr, "Options selected for %s\n", o.command);
    /* qvoronoi with print filters: the Voronoi formats need every Delaunay simplex
     * (regions, ridges) and which are good; the others print the good ones */
    const int two = prog == LH_QPROG_VORONOI && lh_cli_qselecting(&o);
    lh_cli_qmodel mo, all;
    memset(&all, 0, sizeof all);
    if (!lh_cli_qmodel_build(&mo, &o, pts.d, pts.n, pts.xyz, name)) {
        lh_points_free(&pts);
        return LH_EXIT_FAIL;
    }
    lh_cli_qopts quiet = o;
    quiet.verify = 0; /* Tv checks the first build */
    if (two && !lh_cli_qmodel_build(&all, &quiet, pts.d, pts.n, pts.xyz, name)) {
        lh_cli_qmodel_free(&mo);
        lh_points_free(&pts);
        return LH_EXIT_FAIL;
    }
    r = lh_cli_qselect(&mo, &o, two ? &all : NULL);
    if (r <= 0) {
        lh_cli_qmodel_free(&mo);
        lh_cli_qmodel_free(&all);
        lh_points_free(&pts);
        return r < 0 ? LH_EXIT_USAGE : LH_EXIT_FAIL;
    }
    lh_cli_out out;
    int ok = lh_cli_out_open(&out, o.name, o.output, 1, o.input);
    for (int i = 0; ok && i < o.nout; i++) {
        /* an 's' asked for goes to standard error, the default one to the output
         * (Qhull 2020.2) */
        FILE *f = !strcmp(o.out[i], "s") && !o.summary_default ? stderr : out.f;
        ok = lh_cli_qprint(f, &o, &mo, o.out[i]);
        if (!ok) fprintf(stderr, "lifthull %s: out of memory\n", o.name);
    }
    if (ok && o.stats) lh_cli_qstats(stderr, &o, &mo);
    int status = out.f ? lh_cli_out_close(&out, o.name, ok) : LH_EXIT_FAIL;
    lh_cli_qmodel_free(&mo);
    lh_cli_qmodel_free(&all);
    lh_points_free(&pts);
    return status;
}

int lh_cli_qdelaunay(int argc, char **argv) { return run(LH_QPROG_DELAUNAY, argc, argv); }
int lh_cli_qvoronoi(int argc, char **argv) { return run(LH_QPROG_VORONOI, argc, argv); }
int lh_cli_qconvex(int argc, char **argv) { return run(LH_QPROG_CONVEX, argc, argv); }
