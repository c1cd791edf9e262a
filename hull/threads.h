/*
 * threads.h — loops shared among threads (threads.c): lh__par_for runs a function
 * once per worker at once, lh__par_range splits an index range among them. The
 * callers' iterations must touch disjoint data. Used by every layer that has a
 * thread count (lh_options.threads).
 */
#ifndef LH_THREADS_H
#define LH_THREADS_H

#include <stddef.h>

#define LH__MAX_THREADS 64 /* workers of one computation, at most */

/* The workers lh_options.threads asks for (0: one per online CPU). */
int lh__threads(int requested);
/* fn(ctx, w, nw) for w = 0..nw-1 at once, w = 0 on the calling thread,
 * the others on threads of their own (or here, after, should one not start); a
 * share is the range [lh__share(count, w, nw), lh__share(count, w + 1, nw)). */
void lh__par_for(int nw, void (*fn)(void *ctx, int w, int nw), void *ctx);
static inline size_t lh__share(size_t count, int w, int nw)
{
    return count / (size_t)nw * (size_t)w + count % (size_t)nw * (size_t)w / (size_t)nw;
}
/* The threads, at most nw (and LH__MAX_THREADS), worth starting for n items: each
 * must get enough (one thread for small n). */
int lh__par_width(int nw, size_t n);
/* fn(ctx, lo, hi) over the shares of 0..n-1 among lh__par_width(nw, n) threads, for
 * loops whose iterations touch disjoint data. */
void lh__par_range(int nw, size_t n, void (*fn)(void *ctx, size_t lo, size_t hi), void *ctx);

#endif
