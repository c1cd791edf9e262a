/* delaunay.c — `lifthull delaunay [-s] [FILE]`: Delaunay simplices in Qhull's `i`
 * format (a count line, then one simplex per line as 0-based site indices), or with
 * -s a summary. Reads FILE or standard input. Also the pieces the point-reading
 * commands share (lh_cli_load and friends, cli.h). */
#include "cli.h"
#include "lifthull.h"
#include "points.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

double lh_cli_seconds(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int lh_cli_parse_common(const char *cmd, int argc, char **argv, int *summary, const char **file,
                        int *furthest)
{
    *summary = 0;
    *file = NULL;
    if (furthest) *furthest = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "-s")) {
            *summary = 1;
        } else if (furthest && !strcmp(argv[i], "-u")) {
            *furthest = 1;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "lifthull %s: unknown option '%s' (usage: lifthull %s [-s]%s [FILE])\n", cmd,
                    argv[i], cmd, furthest ? " [-u]" : "");
            return -1;
        } else if (*file) {
            fprintf(stderr, "lifthull %s: more than one input file\n", cmd);
            return -1;
        } else {
            *file = argv[i];
        }
    }
    return 0;
}

int lh_cli_load(const char *file, lh_cli_points *pts, const char **name)
{
    FILE *f = stdin;
    *name = "<stdin>";
    if (file && strcmp(file, "-")) {
        f = fopen(file, "r");
        *name = file;
        if (!f) {
            perror(file);
            return 0;
        }
    }
    int ok = lh_cli_read_points(f, *name, pts);
    if (f != stdin) fclose(f);
    return ok;
}

void lh_cli_report_failure(const char *name, const lh_cli_points *pts, lh_status st)
{
    if (st == LH_ERR_DEGENERATE) {
        int k = -1;
        lh_affine_dim(pts->d, pts->n, pts->xyz, &k);
        fprintf(stderr, "%s: the %zu sites span an affine subspace of dimension %d, not %d: "
                "nothing %d-dimensional to compute\n", name, pts->n, k, pts->d, pts->d);
    } else {
        fprintf(stderr, "%s: %s\n", name, lh_status_message(st));
    }
}

int lh_cli_finish_output(const char *cmd)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "lifthull %s: error writing the output\n", cmd);
        return LH_EXIT_FAIL;
    }
    return LH_EXIT_OK;
}

int lh_cli_delaunay(int argc, char **argv)
{
    int summary, furthest;
    const char *file;
    if (lh_cli_parse_common("delaunay", argc, argv, &summary, &file, &furthest) != 0) return LH_EXIT_USAGE;
    lh_cli_points pts;
    const char *name;
    if (!lh_cli_load(file, &pts, &name)) return LH_EXIT_INPUT;
    double t0 = lh_cli_seconds();
    lh_tri *t;
    lh_options opt;
    lh_options_default(&opt);
    opt.furthest_site = furthest;
    lh_status st = lh_delaunay(pts.d, pts.n, pts.xyz, &opt, &t);
    double t1 = lh_cli_seconds();
    if (st != LH_OK) {
        lh_cli_report_failure(name, &pts, st);
        free(pts.xyz);
        return LH_EXIT_FAIL;
    }
    int nv = pts.d + 1;
    if (summary) {
        printf("sites %zu\ndimension %d\nsimplices %zu\nhull facets %zu\nduplicates %zu\nseconds %.3f\n",
               pts.n, pts.d, lh_tri_count(t), lh_tri_hull_count(t), lh_tri_duplicate_count(t), t1 - t0);
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
