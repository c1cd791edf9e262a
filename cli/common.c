/* common.c — what the commands that read points share: options, loading, failure
 * messages, timing, flushing the output (cli.h). */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include "cli.h"
#include "progress.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

double lh_cli_seconds(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

FILE *lh_cli_open_input(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) { /* fopen opens one; reading it fails */
        fprintf(stderr, "%s: is a directory, not an input file\n", path);
        fclose(f);
        return NULL;
    }
    return f;
}

int lh_cli_load(const char *file, lh_format fmt, lh_points *pts, const char **name)
{
    return lh_cli_load_progress(file, fmt, pts, name, NULL);
}

int lh_cli_load_progress(const char *file, lh_format fmt, lh_points *pts, const char **name,
                         struct lh_cli_progress *prog)
{
    FILE *f = stdin;
    *name = "<stdin>";
    if (file && strcmp(file, "-")) {
        *name = file;
        if (!(f = lh_cli_open_input(file))) return 0;
    }
    lh_error err;
    lh_cli_progress_file(prog, "reading", *name, f);
    lh_status st = lh_points_read(f, *name, fmt, NULL, pts, &err);
    lh_cli_progress_file_done(prog);
    if (f != stdin) fclose(f);
    if (st != LH_OK) fprintf(stderr, "%s\n", err.message[0] ? err.message : lh_status_message(st));
    return st == LH_OK;
}

int lh_cli_load_pair(const char *f1, const char *f2, lh_format fmt, lh_points *a, lh_points *b,
                     const char **names)
{
    if (!lh_cli_load(f1, fmt, a, &names[0])) return 0;
    if (!lh_cli_load(f2, fmt, b, &names[1])) {
        lh_points_free(a);
        return 0;
    }
    return 1;
}

void lh_cli_report_failure(const char *name, int d, size_t n, const double *xyz, lh_status st)
{
    if (st == LH_ERR_DEGENERATE) {
        int k = -1;
        lh_coords_affine_dim(d, n, xyz, NULL, &k);
        fprintf(stderr, "%s: the %zu site%s span%s an affine subspace of dimension %d, not %d: "
                "nothing %d-dimensional to compute%s\n", name, n, n == 1 ? "" : "s", n == 1 ? "s" : "", k, d, d,
                k >= 1 ? " (lifthull delaunay -a triangulates within that subspace)" : "");
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
