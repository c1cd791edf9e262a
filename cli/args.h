/* args.h — the options the native commands share, parsed one way for all. */
#ifndef LH_CLI_ARGS_H
#define LH_CLI_ARGS_H

#include "lifthull.h"

#include <stddef.h>

typedef struct lh_cli_args {
    int summary;        /* -s                                   */
    int furthest;       /* -u                                   */
    int affine;         /* -a                                   */
    int quiet;          /* -q: no progress line                 */
    int force;          /* -f: -o may replace a file             */
    int circles;        /* --circles (SVG)                      */
    int ascii;          /* --ascii: a .vtu as text, not binary   */
    const char *output; /* -o FILE                              */
    const char *method; /* -m NAME                              */
    int values;         /* --values K                           */
    lh_format format;   /* --format qhull|node|columns (auto)   */
    int threads;        /* --threads N: lh_options.threads (1)   */
    const char *file[3];
    int nfile;
} lh_cli_args;

/* Parses argv for command `cmd` accepting the options named in `accepted` (letters
 * s u a q f o m, and 'c' for --circles, 'A' for --ascii, 'v' for --values; every point command takes
 * --threads N, the threads of its Delaunay triangulation (0: one per CPU), and --format
 * F to read the input files as Qhull points, .node or columns) and up to max_files
 * operands (at least min_files). `help` is printed on --help or -h. Returns 0; 1 after
 * --help; -1 after printing a usage error. */
int lh_cli_args_parse(lh_cli_args *a, const char *cmd, const char *accepted, int min_files,
                      int max_files, int argc, char **argv, const char *help);

#endif
