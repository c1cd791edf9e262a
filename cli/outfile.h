/* outfile.h — output files written whole or not at all: a temporary file beside the
 * target, moved into place only after every byte was written and flushed. */
#ifndef LH_CLI_OUTFILE_H
#define LH_CLI_OUTFILE_H

#include <stdio.h>

typedef struct lh_cli_out {
    FILE *f;          /* write here                                   */
    const char *path; /* the target, NULL for standard output         */
    char *tmp;        /* the temporary file's name (malloc'ed), or NULL */
    int replace;      /* an existing target may be replaced           */
} lh_cli_out;

/* Opens standard output (path NULL or "-") or a temporary file in path's directory.
 * Refuses, with one line on standard error, a path naming the input file `input`
 * (NULL: none) — an input is never overwritten — and, unless `replace`, a path that
 * exists. Returns 1, or 0 after printing the problem. */
int lh_cli_out_open(lh_cli_out *o, const char *cmd, const char *path, int replace,
                    const char *input);

/* Finishes: flushes and checks every write; when ok, moves the temporary file to
 * the target (without replace, by link, so a file created meanwhile is never lost);
 * otherwise, or on any error, removes it. Returns 0 (LH_EXIT_OK) or LH_EXIT_FAIL
 * after printing the problem. */
int lh_cli_out_close(lh_cli_out *o, const char *cmd, int ok);

/* Whether a and b (either may be NULL) name one existing file (device and inode). */
int lh_cli_same_file(const char *a, const char *b);

#endif
