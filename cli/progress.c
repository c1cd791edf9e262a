/* progress.c — the progress line (progress.h). */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno */
#include "progress.h"

#include "cli.h"

#include <stdio.h>
#include <unistd.h>

static void report(void *user, size_t done, size_t total)
{
    lh_cli_progress *p = user;
    double t = lh_cli_seconds() - p->start;
    if (!p->enabled || t < 2) return;
    fprintf(stderr, "\rlifthull %s: %zu of %zu sites inserted (%.0f%%), %.0f s ", p->cmd, done, total,
            100.0 * (double)done / (double)(total ? total : 1), t);
    p->shown = 1;
}

void lh_cli_progress_attach(lh_cli_progress *p, const char *cmd, int quiet, lh_options *opt)
{
    p->cmd = cmd;
    p->start = lh_cli_seconds();
    p->enabled = !quiet && isatty(fileno(stderr));
    p->shown = 0;
    opt->progress = report;
    opt->progress_user = p;
}

void lh_cli_progress_done(lh_cli_progress *p)
{
    if (p->shown) fputs("\r\033[K", stderr);
    p->shown = 0;
}
