/* progress.h — a progress line on standard error for long runs: shown after about 2 s
 * of a phase, only when standard error is a terminal and -q was not given. Phases:
 * reading the input and writing the output (a thread looks at the file's offset four
 * times a second: the library reports nothing while it reads or writes), and the
 * insertion of the sites (the library's progress callback). */
#ifndef LH_CLI_PROGRESS_H
#define LH_CLI_PROGRESS_H

#include "lifthull.h"

#include <stdio.h>

struct lh_cli_ticker;

typedef struct lh_cli_progress {
    const char *cmd;
    double start; /* the current phase's start (lh_cli_seconds) */
    int enabled, shown;
    struct lh_cli_ticker *ticker; /* the reading or writing phase's thread, or NULL */
} lh_cli_progress;

/* Enabled when standard error is a terminal and not quiet. */
void lh_cli_progress_init(lh_cli_progress *p, const char *cmd, int quiet);
/* lh_cli_progress_init, and sets opt->progress to report the insertion through p. */
void lh_cli_progress_attach(lh_cli_progress *p, const char *cmd, int quiet, lh_options *opt);
/* Erases the line if one was shown. */
void lh_cli_progress_done(lh_cli_progress *p);

/* Starts showing `what` ("reading", "writing") of the file `name`, open as f: the
 * bytes so far (f's file offset) and, when f is a regular file being read, the share
 * of its size. Without effect when p is NULL or disabled, or when the offset cannot
 * be read (a pipe shows the seconds only). */
void lh_cli_progress_file(lh_cli_progress *p, const char *what, const char *name, FILE *f);
/* Ends that phase and erases its line. NULL: nothing. */
void lh_cli_progress_file_done(lh_cli_progress *p);

#endif
