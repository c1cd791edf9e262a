/* outfile.h — output files written whole, together or not at all.
 *
 * Every command that writes files goes through an output set:
 *   1. lh_cli_out_check on every target, right after the arguments are parsed and
 *      before any input is read (an empty name, a directory, an existing file without
 *      -f, a missing or unwritable directory, the input file itself);
 *   2. lh_cli_outset_add per file: checks again and opens a temporary file
 *      TARGET.tmpXXXXXX in the target's directory (so the final rename never crosses
 *      file systems), with the mode the target will keep;
 *   3. lh_cli_outset_close: flushes, fsyncs and closes every temporary; only when all
 *      of them succeeded (and the caller says ok) does it rename them onto the
 *      targets, one after another; otherwise it removes every temporary and every
 *      old file stays untouched.
 * Renames of several files cannot be atomic as a group: when the system fails a
 * rename in step 3 (it needs no space, so that is rare) the files renamed before it
 * are new and the others old; the message says which.
 *
 * Signals: while temporaries exist, SIGHUP, SIGINT, SIGPIPE, SIGTERM and SIGXFSZ
 * remove them and then end the process with the signal's default action (a signal
 * that was ignored when the program started stays ignored). The handler needs the
 * temporaries' names, so the CLI keeps one process-wide table of them — the only
 * global state of the tool: a signal handler receives no context pointer, and the
 * table lives here, never in the library.
 *
 * An existing target replaced with -f keeps its permission bits (as `sed -i` and
 * editors do); a read-only file stays read-only. A target that exists and is neither
 * a regular file nor a directory (a device such as /dev/null, a pipe, a symbolic
 * link) is written through, never replaced — outside the all-or-nothing promise. */
#ifndef LH_CLI_OUTFILE_H
#define LH_CLI_OUTFILE_H

#include <stdio.h>

enum { LH_CLI_OUTSET_MAX = 8 };

typedef struct lh_cli_outfile {
    const char *path; /* the target                                         */
    char *tmp;        /* its temporary file (malloc'ed), NULL when direct    */
    FILE *f;          /* write here                                         */
} lh_cli_outfile;

typedef struct lh_cli_outset {
    const char *cmd;   /* for messages: "lifthull CMD: ..."                  */
    const char *input; /* the input file (never overwritten), or NULL         */
    int replace;       /* an existing target may be replaced (-f)            */
    int n;             /* files added                                        */
    int to_stdout;     /* standard output was "added"                        */
    lh_cli_outfile file[LH_CLI_OUTSET_MAX];
} lh_cli_outset;

/* Whether path can be written by the command: NULL and "-" (standard output) can.
 * Refuses, with one line on standard error: an empty name; a directory; the input
 * file `input` (NULL: none); unless `replace`, an existing file; a name whose
 * directory is missing or not writable. Creates nothing. Returns 1, or 0. */
int lh_cli_out_check(const char *cmd, const char *path, int replace, const char *input);

void lh_cli_outset_init(lh_cli_outset *s, const char *cmd, int replace, const char *input);
/* Checks path (lh_cli_out_check) and opens its temporary file (standard output for
 * NULL or "-"). Returns the stream to write, or NULL after printing the problem;
 * the set must be closed either way. At most LH_CLI_OUTSET_MAX files. */
FILE *lh_cli_outset_add(lh_cli_outset *s, const char *path);
/* Finishes the set as described above: with ok, every file is committed or none;
 * without ok (the caller failed and printed why), none. Returns 0 (LH_EXIT_OK) or
 * LH_EXIT_FAIL after printing the problem. */
int lh_cli_outset_close(lh_cli_outset *s, int ok);

/* A set of one file, for the commands that write one. */
typedef struct lh_cli_out {
    FILE *f; /* write here */
    lh_cli_outset set;
} lh_cli_out;

/* lh_cli_outset_add of one path. Returns 1, or 0 after printing the problem (then
 * nothing needs closing). */
int lh_cli_out_open(lh_cli_out *o, const char *cmd, const char *path, int replace,
                    const char *input);
int lh_cli_out_close(lh_cli_out *o, const char *cmd, int ok);

/* base[0..len) followed by ext (malloc'ed): BASE.node from BASE; NULL when out of
 * memory. */
char *lh_cli_path_ext(const char *base, size_t len, const char *ext);
/* path[i] = lh_cli_path_ext(base, len, ext[i]) for each i < n where want is NULL or
 * want[i] is nonzero, NULL elsewhere. Returns 1, or 0 when out of memory; either
 * way lh_cli_paths_free(path, n) frees them. */
int lh_cli_paths(const char *base, size_t len, const char *const *ext, const int *want, int n,
                 char **path);
void lh_cli_paths_free(char **path, int n);

/* Whether a and b (either may be NULL) name one existing file (device and inode). */
int lh_cli_same_file(const char *a, const char *b);

#endif
