/*
 * parallel.h — what a worker of a parallel insertion phase (parallel.c) holds: the
 * cells it has locked, and the sites it left for the sequential pass.
 *
 * Cells are locked, not regions: a worker inserts a site only once it holds every
 * cell its insertion reads or writes (the walk's cells, the conflict region, the
 * cells across its boundary, and the finite cell behind each infinite one tested),
 * taken by compare-and-swap on the cell's owner byte as it reaches them. A cell
 * held by another worker ends the attempt before anything is written: the site is
 * deferred, the locks are dropped (Batista, Devillers & Lévy, "Parallel geometric
 * algorithms for multi-core computers", CGTA 43(8), 2010, §4: the same optimistic
 * scheme with retry; here the retry is the sequential pass). No worker ever waits,
 * so none can deadlock. A worker keeps one cell between insertions, its next walk's
 * start (the hint), so that no other worker frees it meanwhile.
 *
 * Why holding a cell is enough: a worker reads a cell's rows only once it holds it,
 * and writes rows only of cells it holds or of new cells no other worker can reach
 * until the locks around them are released (release stores, acquire CAS: the rows
 * are published with the release). A cell can leave the triangulation only with its
 * neighbours held (they are the conflict region's boundary), so a neighbour index
 * read from a held cell names a live cell when it is locked next.
 *
 * The result does not depend on which worker inserted what, nor in which order: the
 * triangulation of the perturbed sites is unique (lifthull.h, predicates), and the
 * output is canonical.
 */
#ifndef LH_PARALLEL_H
#define LH_PARALLEL_H

#include "engine.h"

#include <stdatomic.h>

/* What the workers of a phase share besides the cells: new cells in blocks from
 * [cursor, end), and the list of deferred sites. */
typedef struct lh__par_shared {
    _Atomic size_t cursor;   /* the next block's first cell */
    size_t end;              /* no block reaches past it (the store's capacity) */
    size_t block;            /* cells in a block */
    lh_index *deferred;      /* sites left for the sequential pass */
    _Atomic size_t ndeferred;
} lh__par_shared;

typedef struct lh__par {
    _Atomic unsigned char *own; /* per cell: 0 free, else the worker holding it */
    unsigned char me;           /* this worker's mark, 1.. */
    int stopped;                /* out of cells: every further site deferred */
    lh_index *log;              /* the cells this worker holds */
    size_t nlog, log_cap;
    lh__par_shared *sh;
    lh_index live_shift;        /* the store's live count moved by refills, not cells */
    lh_index *again;            /* non-NULL: deferred sites kept here, to be tried */
    size_t nagain;              /* again once the chunk is done */
} lh__par;

/* parallel.c: site q left for a second try (p->again) or the sequential pass. */
void lh__par_defer(lh__par *p, lh_index q);
/* parallel.c: after an insertion failed for want of cells (not of scratch), a new
 * block of cells for t, the rest of the old one on its free list; 0 when there was
 * room, or no block is left (then the worker stops). */
int lh__par_refill(lh__par *p, lh__tds *t);

/* Takes cell c for this worker (holding it already counts); 0 when another worker
 * holds it, or when the log is full but for the slot kept for the next hint. */
static inline int lh__par_lock(lh__par *p, lh_index c)
{
    unsigned char cur = atomic_load_explicit(&p->own[c], memory_order_relaxed);
    if (cur == p->me) return 1;
    if (cur || p->nlog + 1 >= p->log_cap) return 0;
    if (!atomic_compare_exchange_strong_explicit(&p->own[c], &cur, p->me, memory_order_acquire,
                                                 memory_order_relaxed))
        return 0;
    p->log[p->nlog++] = c;
    return 1;
}

/* Takes the next hint c, a cell that no other worker can reach yet (a new cell
 * linked only to held ones) or that this worker holds: cannot fail. */
static inline void lh__par_keep(lh__par *p, lh_index c)
{
    if (atomic_load_explicit(&p->own[c], memory_order_relaxed) == p->me) return;
    atomic_store_explicit(&p->own[c], p->me, memory_order_relaxed);
    p->log[p->nlog++] = c;
}

/* Releases every held cell but `keep` (-1: all), publishing what was written. */
static inline void lh__par_release(lh__par *p, lh_index keep)
{
    int kept = 0;
    for (size_t i = 0; i < p->nlog; i++) {
        if (p->log[i] == keep)
            kept = 1;
        else
            atomic_store_explicit(&p->own[p->log[i]], 0, memory_order_release);
    }
    p->nlog = 0;
    if (kept) p->log[p->nlog++] = keep;
}

#endif
