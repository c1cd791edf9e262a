/* delaunay.c — `lifthull delaunay [-s] [FILE]`: Delaunay simplices in Qhull's `i`
 * format (a count line, then one simplex per line as 0-based site indices), or with
 * -s a summary. Reads FILE or standard input. */
#include "cli.h"
#include "lifthull.h"
#include "points.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double seconds(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int lh_cli_delaunay(int argc, char **argv)
{
    int summary = 0;
    const char *file = NULL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "-s"))
            summary = 1;
        else if (argv[i][0] == '-' && argv[i][1]) {
            fprintf(stderr, "lifthull delaunay: unknown option '%s' (usage: lifthull delaunay [-s] [FILE])\n", argv[i]);
            return LH_EXIT_USAGE;
        } else if (file) {
            fprintf(stderr, "lifthull delaunay: more than one input file\n");
            return LH_EXIT_USAGE;
        } else
            file = argv[i];
    }
    FILE *f = stdin;
    const char *name = "<stdin>";
    if (file && strcmp(file, "-")) {
        f = fopen(file, "r");
        name = file;
        if (!f) {
            perror(file);
            return LH_EXIT_INPUT;
        }
    }
    lh_cli_points pts;
    int ok = lh_cli_read_points(f, name, &pts);
    if (f != stdin) fclose(f);
    if (!ok) return LH_EXIT_INPUT;

    double t0 = seconds();
    lh_tri *t;
    lh_status st = lh_delaunay(pts.d, pts.n, pts.xyz, NULL, &t);
    double t1 = seconds();
    if (st != LH_OK) {
        if (st == LH_ERR_DEGENERATE) {
            int k = -1;
            lh_affine_dim(pts.d, pts.n, pts.xyz, &k);
            fprintf(stderr, "%s: the %zu sites span an affine subspace of dimension %d, not %d: "
                    "no %d-dimensional triangulation exists\n", name, pts.n, k, pts.d, pts.d);
        } else {
            fprintf(stderr, "%s: %s\n", name, lh_status_message(st));
        }
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
    if (fflush(stdout) != 0 || ferror(stdout)) {
        perror("lifthull delaunay: writing the output");
        return LH_EXIT_FAIL;
    }
    return LH_EXIT_OK;
}
