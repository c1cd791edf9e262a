/* delaunay.c — `lifthull delaunay [-s] [-u] [-a] [FILE]`: Delaunay simplices in
 * Qhull's `i` format (a count line, then one simplex per line as 0-based site
 * indices), or with -s a summary; -u the furthest-site triangulation; -a within the
 * sites' affine hull when they span less than R^d. Reads FILE or standard input. */
#include "cli.h"
#include "lifthull.h"
#include "points.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int lh_cli_delaunay(int argc, char **argv)
{
    int summary, furthest, affine;
    const char *file;
    if (lh_cli_parse_common("delaunay", argc, argv, &summary, &file, &furthest, &affine) != 0)
        return LH_EXIT_USAGE;
    lh_cli_points pts;
    const char *name;
    if (!lh_cli_load(file, &pts, &name)) return LH_EXIT_INPUT;
    double t0 = lh_cli_seconds();
    lh_tri *t;
    lh_options opt;
    lh_options_default(&opt);
    opt.furthest_site = furthest;
    opt.affine_hull = affine;
    lh_status st = lh_delaunay(pts.d, pts.n, pts.xyz, &opt, &t);
    double t1 = lh_cli_seconds();
    if (st != LH_OK) {
        lh_cli_report_failure(name, &pts, st);
        free(pts.xyz);
        return LH_EXIT_FAIL;
    }
    int nv = lh_tri_simplex_dim(t) + 1;
    if (summary) {
        printf("sites %zu\ndimension %d\n", pts.n, pts.d);
        if (nv - 1 < pts.d) printf("affine hull dimension %d\n", nv - 1);
        printf("simplices %zu\nhull facets %zu\nduplicates %zu\nseconds %.3f\n", lh_tri_count(t),
               lh_tri_hull_count(t), lh_tri_duplicate_count(t), t1 - t0);
    } else {
        const int32_t *s = lh_tri_simplices(t);
        printf("%zu\n", lh_tri_count(t));
        for (size_t i = 0; i < lh_tri_count(t); i++) {
            for (int k = 0; k < nv; k++) printf(k ? " %d" : "%d", (int)s[i * nv + k]);
            putchar('\n');
        }
    }
    lh_tri_free(t);
    free(pts.xyz);
    return lh_cli_finish_output("delaunay");
}
