/*
 * threads.c — loops shared among POSIX threads (threads.h): fork-join over a
 * fixed count of workers, each given a share of the iterations; no pool, no queue.
 * The engine's ordering, canonical output and parallel insertion phases use them.
 */
#include "threads.h"

#include <pthread.h>
#include <unistd.h>

typedef struct for_arg {
    void (*fn)(void *ctx, int w, int nw);
    void *ctx;
    int w, nw;
} for_arg;

static void *for_body(void *arg)
{
    const for_arg *a = arg;
    a->fn(a->ctx, a->w, a->nw);
    return NULL;
}

void lh__par_for(int nw, void (*fn)(void *ctx, int w, int nw), void *ctx)
{
    nw = nw < 1 ? 1 : nw < LH__MAX_THREADS ? nw : LH__MAX_THREADS;
    pthread_t th[LH__MAX_THREADS];
    for_arg arg[LH__MAX_THREADS];
    int started[LH__MAX_THREADS] = {0};
    for (int w = 0; w < nw; w++) arg[w] = (for_arg){fn, ctx, w, nw}; /* nw = 1: no thread */
    for (int w = 1; w < nw; w++) started[w] = !pthread_create(th + w, NULL, for_body, arg + w);
    fn(ctx, 0, nw);
    for (int w = 1; w < nw; w++) {
        if (started[w])
            pthread_join(th[w], NULL);
        else
            fn(ctx, w, nw); /* no thread: its share runs here */
    }
}

typedef struct range_arg {
    void (*fn)(void *ctx, size_t lo, size_t hi);
    void *ctx;
    size_t n;
} range_arg;

static void range_body(void *arg, int w, int nw)
{
    const range_arg *a = arg;
    a->fn(a->ctx, lh__share(a->n, w, nw), lh__share(a->n, w + 1, nw));
}

int lh__par_width(int nw, size_t n)
{
    enum { MIN_SHARE = 1 << 14 }; /* items a thread must get to be worth starting */
    if (nw > 1 && n / MIN_SHARE < (size_t)nw) nw = (int)(n / MIN_SHARE);
    return nw < 1 ? 1 : nw < LH__MAX_THREADS ? nw : LH__MAX_THREADS;
}

void lh__par_range(int nw, size_t n, void (*fn)(void *ctx, size_t lo, size_t hi), void *ctx)
{
    range_arg a = {fn, ctx, n};
    lh__par_for(lh__par_width(nw, n), range_body, &a);
}

int lh__threads(int requested)
{
    if (requested > 0) return requested < LH__MAX_THREADS ? requested : LH__MAX_THREADS;
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online < 1 ? 1 : online < LH__MAX_THREADS ? (int)online : LH__MAX_THREADS;
}

