/* progress.h — a progress line on standard error for long computations: shown after
 * about 2 s, only when standard error is a terminal and -q was not given. */
#ifndef LH_CLI_PROGRESS_H
#define LH_CLI_PROGRESS_H

#include "lifthull.h"

typedef struct lh_cli_progress {
    const char *cmd;
    double start;
    int enabled, shown;
} lh_cli_progress;

/* Sets opt->progress to report through p. */
void lh_cli_progress_attach(lh_cli_progress *p, const char *cmd, int quiet, lh_options *opt);
/* Erases the line if one was shown. */
void lh_cli_progress_done(lh_cli_progress *p);

#endif
