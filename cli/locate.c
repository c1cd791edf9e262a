/* locate.c — `lifthull locate SITES QUERIES`: for each query point, the Delaunay
 * simplex containing it with barycentric coordinates, or outside with its distance
 * to the hull; and its nearest site. */
#include "args.h"
#include "cli.h"
#include "outfile.h"

#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: lifthull locate [-o FILE [-f]] SITES QUERIES\n"
    "\n"
    "Locates each point of QUERIES in the Delaunay triangulation of SITES (both in\n"
    "Qhull's point format, .node or columns, of one dimension). One line a query:\n"
    "  in S v_0 .. v_d b_0 .. b_d nearest N\n"
    "      inside simplex S (its index in `lifthull delaunay SITES` output) with sites\n"
    "      v_i, barycentric coordinates b_i (summing to 1), and the nearest site N;\n"
    "  out f_1 .. f_d distance D nearest N\n"
    "      outside the convex hull: the nearest hull facet's sites, the distance to\n"
    "      the hull, and the nearest site.\n"
    "Inside or outside is decided exactly (a query on the hull is inside). A query on\n"
    "a facet shared by several simplices, or at a site, is reported in the one with\n"
    "the smallest index; the nearest site is the smallest index among exact ties. Site\n"
    "indices are 0-based input positions (a duplicate site maps to its first copy).\n"
    "\n"
    "example:\n"
    "  lifthull points 1000 -d 2 > s.txt; lifthull points 5 -d 2 --seed 2 > q.txt\n"
    "  lifthull locate s.txt q.txt\n"
    "\n"
    "exit codes: 0 done, 1 the computation failed, 2 usage, 3 bad input file.\n";

static void line(FILE *f, lh_tri *t, const lh_location *loc, lh_index nearest)
{
    const int k = lh_tri_simplex_dim(t);
    if (loc->simplex >= 0) {
        fprintf(f, "in %" LH_INDEX_PRI, loc->simplex);
        for (int j = 0; j <= k; j++)
            fprintf(f, " %" LH_INDEX_PRI, lh_tri_simplices(t)[(size_t)loc->simplex * (k + 1) + j]);
        for (int j = 0; j <= k; j++) fprintf(f, " %.17g", loc->bary[j] + 0.0); /* no -0 */
    } else {
        fputs("out", f);
        for (int j = 0; j < k; j++)
            fprintf(f, " %" LH_INDEX_PRI, lh_tri_hull_facets(t)[(size_t)loc->hull_facet * k + j]);
        fprintf(f, " distance %.17g", loc->distance);
    }
    fprintf(f, " nearest %" LH_INDEX_PRI "\n", nearest);
}

static lh_status run(FILE *f, lh_tri *t, const lh_points *q)
{
    for (size_t i = 0; i < q->n; i++) {
        const double *p = q->xyz + i * q->d;
        lh_location loc;
        lh_index near;
        lh_status st = lh_tri_locate(t, p, -1, &loc);
        if (st == LH_OK) st = lh_tri_nearest(t, p, loc.simplex, &near);
        if (st != LH_OK) return st;
        line(f, t, &loc, near);
    }
    return LH_OK;
}

int lh_cli_locate(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "locate", "qfo", 2, 2, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check("locate", a.output, a.force, a.file[1]) ||
        !lh_cli_out_check("locate", a.output, a.force, a.file[0]))
        return LH_EXIT_FAIL;
    lh_points s, q;
    const char *names[2];
    if (!lh_cli_load_pair(a.file[0], a.file[1], a.format, &s, &q, names)) return LH_EXIT_INPUT;
    int status = LH_EXIT_FAIL;
    lh_tri *t = NULL;
    lh_status st = LH_OK;
    lh_options opt;
    lh_options_default(&opt);
    opt.threads = a.threads;
    if (q.d != s.d) {
        fprintf(stderr, "%s: the queries have dimension %d, the sites (%s) %d\n", names[1], q.d, names[0], s.d);
        status = LH_EXIT_INPUT;
    } else if ((st = lh_delaunay(s.d, s.n, s.xyz, &opt, &t)) != LH_OK) {
        lh_cli_report_failure(names[0], s.d, s.n, s.xyz, st);
    } else {
        lh_cli_out out;
        if (lh_cli_out_open(&out, "locate", a.output, a.force, a.file[1])) {
            st = run(out.f, t, &q);
            if (st != LH_OK) fprintf(stderr, "lifthull locate: %s\n", lh_status_message(st));
            status = lh_cli_out_close(&out, "locate", st == LH_OK);
        }
    }
    lh_tri_free(t);
    lh_points_free(&s);
    lh_points_free(&q);
    return status;
}
