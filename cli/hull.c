/* hull.c — `lifthull hull [-s] [FILE]`: convex hull facets in qconvex's `i` format
 * (a count line, then one facet per line as d 0-based site indices, oriented
 * outward), or with -s a summary. Reads FILE or standard input. */
#include "cli.h"
#include "lifthull.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int lh_cli_hull(int argc, char **argv)
{
    int summary = 0;
    const char *file = NULL;
    if (lh_cli_parse_common("hull", argc, argv, &summary, &file, NULL, NULL) != 0) return LH_EXIT_USAGE;
    lh_points pts;
    const char *name;
    if (!lh_cli_load(file, &pts, &name)) return LH_EXIT_INPUT;
    double t0 = lh_cli_seconds();
    lh_hull *h;
    lh_status st = lh_convex_hull(pts.d, pts.n, pts.xyz, NULL, &h);
    double t1 = lh_cli_seconds();
    if (st != LH_OK) {
        lh_cli_report_failure(name, pts.d, pts.n, pts.xyz, st);
        lh_points_free(&pts);
        return LH_EXIT_FAIL;
    }
    if (summary) {
        printf("sites %zu\ndimension %d\nhull facets %zu\nhull vertices %zu\nseconds %.3f\n",
               pts.n, pts.d, lh_hull_facet_count(h), lh_hull_vertex_count(h), t1 - t0);
    } else {
        const int32_t *f = lh_hull_facets(h);
        printf("%zu\n", lh_hull_facet_count(h));
        for (size_t i = 0; i < lh_hull_facet_count(h); i++) {
            for (int k = 0; k < pts.d; k++) printf(k ? " %d" : "%d", (int)f[i * pts.d + k]);
            putchar('\n');
        }
    }
    lh_hull_free(h);
    lh_points_free(&pts);
    return lh_cli_finish_output("hull");
}
