/* check.c — `lifthull check POINTS SIMPLICES`: exactly verifies a Delaunay
 * triangulation made by any program (lh_delaunay_check). */
#include "args.h"
#include "cli.h"

#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: lifthull check POINTS SIMPLICES\n"
    "\n"
    "Verifies exactly that SIMPLICES is a Delaunay triangulation of POINTS: every\n"
    "simplex has positive volume (either orientation), every facet is shared by at most\n"
    "two simplices, every interior facet is locally Delaunay (no opposite vertex strictly\n"
    "inside a circumsphere), the boundary is convex so the simplices tile the convex\n"
    "hull, and every point is a vertex or a duplicate of one. Exact arithmetic: a\n"
    "triangulation of cospherical points passes whichever valid way it splits them.\n"
    "\n"
    "POINTS: Qhull's point format, .node or columns. SIMPLICES: Qhull's 'i' format (the\n"
    "count, then d+1 0-based indices a line: what qdelaunay Qt i and lifthull delaunay\n"
    "print) or a Triangle/TetGen .ele file (numbered from the .ele's first index).\n"
    "Prints one line, 'ok ...' or the first violation.\n"
    "\n"
    "examples:\n"
    "  rbox 1000 D3 > p.txt; qdelaunay Qt i < p.txt > s.txt; lifthull check p.txt s.txt\n"
    "  lifthull triangle -Q examples/dots.node    # examples/dots.1.node, dots.1.ele\n"
    "  lifthull check examples/dots.1.node examples/dots.1.ele\n"
    "\n"
    "exit codes: 0 valid, 1 not a Delaunay triangulation, 2 usage, 3 bad input file.\n";

static int read_cells(const char *file, size_t n, lh_cells *c)
{
    FILE *f = lh_cli_open_input(file);
    if (!f) return 0;
    lh_error err;
    lh_status st = lh_cells_read(f, file, n, NULL, c, &err);
    fclose(f);
    if (st != LH_OK) fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
    return st == LH_OK;
}

int lh_cli_check(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "check", "", 2, 2, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    lh_points p;
    const char *name;
    if (!lh_cli_load(a.file[0], a.format, &p, &name)) return LH_EXIT_INPUT;
    lh_cells c;
    if (!read_cells(a.file[1], p.n, &c)) {
        lh_points_free(&p);
        return LH_EXIT_INPUT;
    }
    int status = LH_EXIT_INPUT;
    if (c.nv != p.d + 1) {
        fprintf(stderr, "%s: cells of %d points; a triangulation of %d-dimensional points has %d\n",
                a.file[1], c.nv, p.d, p.d + 1);
    } else {
        lh_error err;
        lh_status st = lh_delaunay_check(p.d, p.n, p.xyz, c.count, c.v, NULL, &err);
        if (st == LH_OK)
            printf("ok: %zu %s, the Delaunay triangulation of the %zu point%s (exact check)\n", c.count,
                   c.count == 1 ? "simplex" : "simplices", p.n, p.n == 1 ? "" : "s");
        else
            printf("not Delaunay: %s\n",
                   st == LH_ERR_INVALID_MESH ? err.message : lh_status_message(st));
        status = st == LH_OK ? lh_cli_finish_output("check") : LH_EXIT_FAIL;
    }
    lh_cells_free(&c);
    lh_points_free(&p);
    return status;
}
