/* points.h — reading points in Qhull's input format for the CLI. */
#ifndef LH_CLI_POINTS_H
#define LH_CLI_POINTS_H

#include <stddef.h>
#include <stdio.h>

typedef struct lh_cli_points {
    int d;
    size_t n;
    double *xyz; /* n*d, malloc'ed */
} lh_cli_points;

/* Reads Qhull's point format: the dimension, the count (on one line or two), then
 * n*d coordinates; '#' starts a comment anywhere. On error prints
 * "NAME:LINE:COL: expected ..." to stderr and returns 0. */
int lh_cli_read_points(FILE *f, const char *name, lh_cli_points *out);

#endif
