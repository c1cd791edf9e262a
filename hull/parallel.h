/*
 * parallel.h — what a worker of a parallel insertion phase (parallel.c) holds: the
 * cells it has taken, and the sites it left for a second try.
 *
 * Cells are locked, not regions: a worker inserts a site only once it holds every
 * cell its insertion reads or writes (the walk's cells, the conflict region, the
 * cells across its boundary, and the finite cell behind each infinite one tested),
 * taken by compare-and-swap as it reaches them. A cell held by another worker ends
 * the attempt before anything is written: the site is deferred and the cells are
 * let go (Batista, Devillers & Lévy, "Parallel geometric algorithms for multi-core
 * computers", CGTA 43(8), 2010, §4: the same optimistic scheme with retry). No
 * worker ever waits, so none can deadlock.
 *
 * The lock is the cell's visit mark (tds.h: 4 round + 0 in the region, 1 outside,
 * 2 taken), so that taking a cell touches nothing the conflict search does not
 * touch anyway. Each worker of a phase has its own range of rounds, and publishes
 * the first round of its current attempt, `from`: a cell is held by the worker
 * whose range its mark's round is in, while that round is not below the worker's
 * `from`. Publishing a later `from` (a release store) lets go of every cell at
 * once; no list of held cells is kept. A worker keeps one cell between attempts,
 * its next walk's start (the hint): it marks it with the new round before it
 * publishes that round, so that no other worker frees it meanwhile.
 *
 * Why holding a cell is enough: a worker reads a cell's rows only once it holds it,
 * and writes rows only of cells it holds or of new cells no other worker can reach
 * until the cells around them are let go (the `from` it reads with acquire when it
 * finds a mark in another worker's range orders those writes before its reads; the
 * compare-and-swap decides between two workers taking one free cell). A cell can
 * leave the triangulation only with its neighbours held (they are the conflict
 * region's boundary), so a neighbour index read from a held cell names a live cell
 * when it is taken next.
 *
 * The result does not depend on which worker inserted what, nor in which order: the
 * triangulation of the perturbed sites is unique (lifthull.h, predicates), and the
 * output is canonical.
 */
#ifndef LH_PARALLEL_H
#define LH_PARALLEL_H

#include "engine.h"

#include <stdatomic.h>

/* A worker's published first round, alone in its cache line. */
typedef struct lh__par_from {
    _Atomic uint32_t round;
    char pad[64 - sizeof(_Atomic uint32_t)];
} lh__par_from;

/* What the workers of a phase share besides the cells: new cells in blocks from
 * [cursor, end), the rounds, and the list of deferred sites. */
typedef struct lh__par_shared {
    _Atomic size_t cursor;   /* the next block's first cell */
    size_t end;              /* no block reaches past it (the store's capacity) */
    size_t block;            /* cells in a block */
    uint32_t base, span;     /* worker i's rounds: base + i span .. base + (i + 1) span - 1 */
    int nw;
    lh__par_from *from;      /* nw entries: a worker holds the marks of its rounds >= from */
    lh_index *deferred;      /* sites left for the sequential pass */
    _Atomic size_t ndeferred;
} lh__par_shared;

typedef struct lh__par {
    int me;                     /* this worker, 0.. */
    uint32_t from;              /* the first round of its current attempt */
    int stopped;                /* out of cells: every further site deferred */
    lh__par_shared *sh;
    lh_index live_shift;        /* the store's live count moved by refills, not cells */
    lh_index *again;            /* non-NULL: deferred sites kept here, to be tried */
    size_t nagain;              /* again once the worker's chunks are done */
} lh__par;

/* parallel.c: site q left for a second try (p->again) or the sequential pass. */
void lh__par_defer(lh__par *p, lh_index q);
/* parallel.c: after an insertion failed for want of cells (not of scratch), a new
 * block of cells for t, the rest of the old one on its free list; 0 when there was
 * room, or no block is left (then the worker stops). */
int lh__par_refill(lh__par *p, lh__tds *t);

/* The visit marks, which workers read and write at once. */
static inline _Atomic uint32_t *lh__par_marks(const lh__tds *t) { return (_Atomic uint32_t *)t->stamp; }

/* Takes cell c for this worker, whose current round is t->round (holding it already
 * counts); 0 when another worker holds it, or took it meanwhile. */
static inline int lh__par_lock(const lh__par *p, const lh__tds *t, lh_index c)
{
    _Atomic uint32_t *m = lh__par_marks(t) + c;
    uint32_t s = atomic_load_explicit(m, memory_order_relaxed);
    const uint32_t r = s >> 2, rel = r - p->sh->base;
    if (r >= p->from && r <= t->round) return 1; /* taken in this attempt */
    if (rel < p->sh->span * (uint32_t)p->sh->nw) {
        const uint32_t w = rel / p->sh->span;
        if ((int)w != p->me && r >= atomic_load_explicit(&p->sh->from[w].round, memory_order_acquire))
            return 0;
    }
    return atomic_compare_exchange_strong_explicit(m, &s, 4 * t->round + 2, memory_order_acquire,
                                                   memory_order_relaxed);
}

/* Marks c, which this worker holds or no other worker can reach yet (a new cell
 * linked only to held ones), as taken in round t->round: cannot fail. */
static inline void lh__par_keep(const lh__tds *t, lh_index c)
{
    atomic_store_explicit(lh__par_marks(t) + c, 4 * t->round + 2, memory_order_relaxed);
}

/* Starts an attempt: a new round for t (its range was checked to fit below
 * LH__TDS_MAX_ROUND when the phase began), the hint kept into it, every other cell
 * let go (the release publishes what the last attempt wrote). */
static inline void lh__par_begin(lh__par *p, lh__tds *t, lh_index hint)
{
    t->round++;
    lh__par_keep(t, hint);
    p->from = t->round;
    atomic_store_explicit(&p->sh->from[p->me].round, t->round, memory_order_release);
}

/* Lets go of every cell, the hint too. */
static inline void lh__par_release(lh__par *p)
{
    atomic_store_explicit(&p->sh->from[p->me].round, UINT32_MAX, memory_order_release);
}

#endif
