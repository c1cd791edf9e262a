/* progress.c — the progress line (progress.h). */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno, lseek, fstat, pthread_sigmask */
#include "progress.h"

#include "cli.h"

#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>
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

void lh_cli_progress_init(lh_cli_progress *p, const char *cmd, int quiet)
{
    p->cmd = cmd;
    p->start = lh_cli_seconds();
    p->enabled = !quiet && isatty(fileno(stderr));
    p->shown = 0;
    p->ticker = NULL;
}

void lh_cli_progress_attach(lh_cli_progress *p, const char *cmd, int quiet, lh_options *opt)
{
    lh_cli_progress_init(p, cmd, quiet);
    opt->progress = report;
    opt->progress_user = p;
}

void lh_cli_progress_done(lh_cli_progress *p)
{
    if (p->shown) fputs("\r\033[K", stderr);
    p->shown = 0;
}

/* ---- reading and writing: a thread watching the file offset ----------------------- */

/* Invariant: the thread prints only while holding mu, and stops (and is joined)
 * before lh_cli_progress_file_done returns, so nothing is printed after it. */
typedef struct lh_cli_ticker {
    pthread_t thread;
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int stop;
    lh_cli_progress *p;
    const char *what, *name;
    int fd;
    double total; /* bytes of the file being read, 0 when unknown or writing */
} lh_cli_ticker;

static void show(lh_cli_ticker *k, double t)
{
    lh_cli_progress *p = k->p;
    off_t at = lseek(k->fd, 0, SEEK_CUR);
    fprintf(stderr, "\rlifthull %s: %s %s", p->cmd, k->what, k->name);
    if (at >= 0 && k->total > 0)
        fprintf(stderr, ": %.0f of %.0f MB (%.0f%%)", 1e-6 * (double)at, 1e-6 * k->total,
                100.0 * (double)at / k->total);
    else if (at >= 0)
        fprintf(stderr, ": %.0f MB", 1e-6 * (double)at);
    fprintf(stderr, ", %.0f s ", t);
    p->shown = 1;
}

static void *tick(void *arg)
{
    lh_cli_ticker *k = arg;
    pthread_mutex_lock(&k->mu);
    while (!k->stop) {
        struct timespec ts;
        timespec_get(&ts, TIME_UTC);
        ts.tv_nsec += 250000000L;
        if (ts.tv_nsec >= 1000000000L) ts.tv_sec++, ts.tv_nsec -= 1000000000L;
        pthread_cond_timedwait(&k->cv, &k->mu, &ts);
        const double t = lh_cli_seconds() - k->p->start;
        if (!k->stop && t >= 2) show(k, t);
    }
    pthread_mutex_unlock(&k->mu);
    return NULL;
}

void lh_cli_progress_file(lh_cli_progress *p, const char *what, const char *name, FILE *f)
{
    if (!p || !p->enabled || p->ticker) return;
    lh_cli_ticker *k = calloc(1, sizeof *k);
    if (!k) return; /* no progress line, nothing else lost */
    struct stat st;
    k->p = p;
    k->what = what;
    k->name = name;
    k->fd = fileno(f);
    k->total = what[0] == 'r' && fstat(k->fd, &st) == 0 && S_ISREG(st.st_mode) ? (double)st.st_size : 0;
    p->start = lh_cli_seconds();
    if (pthread_mutex_init(&k->mu, NULL) != 0) {
        free(k);
        return;
    }
    if (pthread_cond_init(&k->cv, NULL) != 0) {
        pthread_mutex_destroy(&k->mu);
        free(k);
        return;
    }
    /* the thread takes no signal: the output files' handler (outfile.c) runs in the
       main thread, whose table updates are the ones blocked against it */
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    int started = pthread_create(&k->thread, NULL, tick, k) == 0;
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (!started) {
        pthread_cond_destroy(&k->cv);
        pthread_mutex_destroy(&k->mu);
        free(k);
        return;
    }
    p->ticker = k;
}

void lh_cli_progress_file_done(lh_cli_progress *p)
{
    if (!p || !p->ticker) return;
    lh_cli_ticker *k = p->ticker;
    pthread_mutex_lock(&k->mu);
    k->stop = 1;
    pthread_cond_signal(&k->cv);
    pthread_mutex_unlock(&k->mu);
    pthread_join(k->thread, NULL);
    pthread_cond_destroy(&k->cv);
    pthread_mutex_destroy(&k->mu);
    free(k);
    p->ticker = NULL;
    lh_cli_progress_done(p);
}
