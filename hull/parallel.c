/*
 * parallel.c — lh__eng_build's insertions with several threads (lh_options.threads).
 *
 * Each BRIO round with enough sites is a phase: its sites, in Hilbert order, are
 * cut into chunks of consecutive sites (regions of space), CHUNKS per worker, and
 * the chunks into one run per worker, which the workers insert at once into the one
 * cell store under cell locks (parallel.h; Batista, Devillers & Lévy 2010, §4). A
 * worker goes through its run from the front; one that has finished its own takes
 * chunks from the back of the run with the most left (work stealing), so that they
 * end together. Two workers so meet only where one's run ends and the other's began
 * long before, and where a thief's chunk meets its victim's. New cells come from
 * blocks above the store's top, taken by an atomic add (worker 0 also has the free
 * list), and a worker's scratch is allocated before: nothing is allocated while
 * they run (the store is frozen), and a worker out of blocks stops. A worker tries
 * the sites it deferred once more when its chunks are done; after the phase the
 * blocks' rests and the free lists are merged back, and the sites deferred twice
 * (another worker's cells, or cavities beyond a worker's scratch) are inserted
 * sequentially. The smaller rounds run sequentially.
 *
 * The triangulation is the sequential one: it is unique for the perturbed sites,
 * whoever inserts them in whatever order (parallel.h); vertex numbers are positions
 * in the insertion order, which does not change.
 */
#include "parallel.h"

#include "lh_exact.h"

#include <string.h>

/* Sites per worker below which a round stays sequential, and vertices before the
 * first phase (runs far apart), in 2D; a site costs about 4x more per dimension
 * (cells per vertex: 2, 6.7, 31, 160 in 2D..5D), so a phase pays for its threads at
 * 4x fewer sites. */
static size_t scaled(size_t n2, int d) { return d - 2 < 5 ? n2 >> (2 * (d - 2)) : n2 >> 10; }
enum {
    MIN_RUN = 4096,
    MIN_BUILT = 8192,
    CHUNKS = 64,         /* chunks of a phase per worker: the last ones balance the ends */
    MIN_CHUNK = 256,     /* sites in a chunk at least, in 2D (a stolen one starts with a long walk) */
    SCRATCH = 1 << 12,   /* boundary facets of the largest cavity a worker takes */
    BLOCK = 4 * SCRATCH, /* new cells a worker takes at a time */
    MAX_WORKERS = LH__MAX_THREADS
};

typedef struct worker {
    lh__eng e;        /* a copy of the engine: the shared store, its own scratch */
    lh__par par;
    lh__tds scratch;  /* its scratch arrays, kept between phases */
    lh_pred *pred;    /* its predicate context (worker 0: the engine's) */
    lh_index live0;   /* its store's live count at the start */
    lh_index hint;    /* where its last phase ended (-1: none) */
    lh_index *again;  /* the sites it deferred, tried again once its chunks are done */
    size_t again_cap;
    size_t sites;     /* sites of the chunks it took */
    lh_status st;
} worker;

typedef struct pctx {
    lh__eng *e;
    int nw;
    worker *w;
    void *from_block;           /* the workers' published rounds (sh.from), unaligned */
    lh__par_shared sh;          /* deferred: e->norder entries */
    size_t first, count, nchunks; /* the phase's sites, cut into chunks */
    _Atomic uint64_t run[MAX_WORKERS]; /* worker i's chunks not yet taken: lo | hi << 32 */
    size_t mark_sites;          /* vertices and cells at the end of the round     */
    lh_index mark_live;         /* before the last: the growth per site since     */
} pctx;

static void release(pctx *c)
{
    lh__eng *e = c->e;
    for (int i = 0; c->w && i < c->nw; i++) {
        worker *w = c->w + i;
        lh__tds_free_scratch(&w->scratch);
        lh__free(&e->alloc, w->again);
        if (i) lh_pred_free(w->pred);
    }
    lh__free(&e->alloc, c->w);
    lh__free(&e->alloc, c->from_block);
    lh__free(&e->alloc, c->sh.deferred);
}

static lh_status setup(pctx *c, lh__eng *e, int nw)
{
    memset(c, 0, sizeof *c);
    c->e = e;
    c->w = lh__alloc(&e->alloc, (size_t)nw * sizeof *c->w);
    c->sh.deferred = lh__alloc(&e->alloc, (e->norder + 1) * sizeof *c->sh.deferred);
    c->from_block = lh__alloc(&e->alloc, (size_t)(nw + 1) * sizeof(lh__par_from));
    if (!c->w || !c->sh.deferred || !c->from_block) return LH_ERR_NOMEM;
    memset(c->w, 0, (size_t)nw * sizeof *c->w);
    c->nw = nw;
    c->sh.block = BLOCK;
    c->sh.nw = nw;
    const uintptr_t line = sizeof(lh__par_from); /* 64: each worker's own cache line */
    c->sh.from = (lh__par_from *)(((uintptr_t)c->from_block + line - 1) / line * line);
    for (int i = 0; i < nw; i++) atomic_init(&c->sh.from[i].round, UINT32_MAX);
    for (int i = 0; i < nw; i++) {
        worker *w = c->w + i;
        w->hint = -1;
        w->scratch.alloc = e->alloc;
        w->scratch.nv = e->nv;
        w->scratch.vlimit = e->tds.vlimit;
        w->par.me = i;
        w->par.sh = &c->sh;
        lh_status st = lh__tds_scratch(&w->scratch, e->dbg.par_scratch ? e->dbg.par_scratch : SCRATCH);
        if (st == LH_OK && i) st = lh_pred_create(&e->alloc, &w->pred);
        if (i == 0) w->pred = e->pred;
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

/* Each worker's list of sites to try again holds `sites` (a phase's) at most. */
static lh_status cover_again(pctx *c, size_t sites)
{
    for (int i = 0; i < c->nw; i++) {
        worker *w = c->w + i;
        if (w->again_cap >= sites) continue;
        lh__free(&c->e->alloc, w->again);
        w->again = lh__alloc(&c->e->alloc, sites * sizeof *w->again);
        w->again_cap = w->again ? sites : 0;
        if (!w->again) return LH_ERR_NOMEM;
    }
    return LH_OK;
}

static int live_cell(const lh__tds *t, lh_index c) { return c >= 0 && c < t->top && !lh__tds_dead(t, c); }

/* A live cell that workers 0..upto-1 of this phase do not start from, trying `want`
 * first, then the cells from the top down; -1 if none. */
static lh_index free_start(const pctx *c, int upto, lh_index want)
{
    const lh__tds *t = &c->e->tds;
    for (lh_index x = want, scan = t->top;; x = --scan) {
        int taken = !live_cell(t, x);
        for (int i = 0; i < upto && !taken; i++) taken = c->w[i].e.hint == x;
        if (!taken) return x;
        if (scan <= 0) return -1;
    }
}

static uint32_t run_lo(uint64_t r) { return (uint32_t)r; }
static uint32_t run_hi(uint64_t r) { return (uint32_t)(r >> 32); }

/* The phase's sites first..first+count-1 cut into chunks, CHUNKS per worker but
 * at least MIN_CHUNK sites each (scaled) and one per worker, and the chunks into
 * one run per worker. */
static void cut_runs(pctx *c, size_t first, size_t count)
{
    const size_t least = scaled(MIN_CHUNK, c->e->d), fit = count / (least ? least : 1);
    const size_t most = (size_t)c->nw * CHUNKS, chunks = fit < most ? fit : most;
    c->first = first, c->count = count;
    c->nchunks = chunks > (size_t)c->nw ? chunks : (size_t)c->nw;
    for (int i = 0; i < c->nw; i++) {
        const uint64_t lo = lh__share(c->nchunks, i, c->nw), hi = lh__share(c->nchunks, i + 1, c->nw);
        atomic_store(&c->run[i], lo | hi << 32);
    }
}

/* The first site of chunk k (k = nchunks: the end of the phase). */
static size_t chunk_first(const pctx *c, uint32_t k)
{
    return c->first + lh__share(c->count, (int)k, (int)c->nchunks);
}

/* A cell near vertex q, from cell c (returned as it is if not live): a visibility
 * walk (Devillers, Pion & Teillaud 2002) that ends in the closed simplex holding q,
 * at an infinite cell, or after `limit` steps. A worker starts from it, not from
 * the last insertion's cells, where every worker would start at once: their first
 * walks would cross, and a worker descheduled there would hold them, each one
 * deferring every site it tries meanwhile. Not insert_locate.h's locate, which is
 * static to each compiled insertion loop and takes the workers' locks: this runs a
 * few times a phase, on the calling thread before any worker, so plain exact
 * orientations do. */
static lh_index walk_toward(lh__eng *e, lh_index c, lh_index q)
{
    const lh__tds *t = &e->tds;
    const int nv = t->nv;
    const double *p[LH__ENGINE_MAX_DIM + 2];
    lh_index prev = -1;
    if (!live_cell(t, c)) return c; /* free_start finds another */
    for (size_t step = 0, limit = 64 + 8 * (size_t)t->live; step < limit; step++) {
        const lh_index *v = t->vert + (size_t)c * nv;
        if (v[0] == LH__INF) return c;
        int moved = 0;
        for (int i = 0; i < nv && !moved; i++) {
            const int k = (int)((step + (size_t)i) % (size_t)nv); /* the first facet rotates */
            const lh_index n = t->nbr[(size_t)c * nv + k];
            if (n == prev) continue;
            for (int j = 0; j < nv; j++) p[j] = lh__eng_site(e, j == k ? q : v[j]);
            if (lh_orient(e->pred, e->d, p) < 0) prev = c, c = n, moved = 1;
        }
        if (!moved) break;
    }
    return c;
}

/* Worker i's engine for a phase: the shared store, no block of new cells yet
 * (worker 0 has the free list), its scratch, predicates, random stream, visit rounds
 * after `round`, and a start cell it holds. */
static void prepare(pctx *c, int i, uint32_t round)
{
    lh__eng *e = c->e;
    worker *w = c->w + i;
    lh__tds *t = &w->e.tds;
    w->e = *e;
    w->e.pred = w->pred;
    w->e.par = &w->par;
    w->e.rng = (e->rng ^ (UINT64_C(0x9e3779b97f4a7c15) * (uint64_t)(i + 1))) | 1;
    const lh__tds *s = &w->scratch;
    t->cells = s->cells, t->bound = s->bound, t->fresh = s->fresh;
    t->cells_cap = s->cells_cap, t->bound_cap = s->bound_cap, t->fresh_cap = s->fresh_cap;
    t->ridge = s->ridge, t->ridge_cap = s->ridge_cap;
    t->sorted = s->sorted, t->spos = s->spos, t->sorted_cap = s->sorted_cap;
    t->vloc = s->vloc, t->edge = s->edge;
    t->frozen = 1;
    t->cap = t->top; /* no block yet (lh__par_refill) */
    /* top - live counts the free cells (lh__tds_reserve) */
    t->free_head = i ? -1 : e->tds.free_head;
    t->live = i ? t->top : t->top - (e->tds.top - e->tds.live);
    w->live0 = t->live;
    w->sites = 0;
    w->par.stopped = 0;
    w->par.live_shift = 0;
    const lh_index from = live_cell(&e->tds, w->hint) ? w->hint : e->hint;
    const size_t head = chunk_first(c, run_lo(atomic_load(&c->run[i]))); /* its first site */
    w->e.hint = free_start(c, i, walk_toward(e, from, (lh_index)head));
    t->round = round + 1; /* the hint held from the first round on (lh__par_begin) */
    if (w->e.hint >= 0) lh__par_keep(t, w->e.hint);
    else w->par.stopped = 1; /* no cell to start from: the sequential pass does it all */
    atomic_store(&c->sh.from[i].round, t->round);
    t->round = round; /* lh__par_begin steps to round + 1 */
}

/* Takes the first chunk of run j (front) or its last (!front); -1 if it is empty. */
static long take_chunk(pctx *c, int j, int front)
{
    uint64_t r = atomic_load_explicit(&c->run[j], memory_order_relaxed);
    for (;;) {
        const uint32_t lo = run_lo(r), hi = run_hi(r);
        if (lo >= hi) return -1;
        const uint64_t to = front ? r + 1 : r - ((uint64_t)1 << 32);
        if (atomic_compare_exchange_weak_explicit(&c->run[j], &r, to, memory_order_relaxed, memory_order_relaxed))
            return front ? (long)lo : (long)hi - 1;
    }
}

/* Worker i's next chunk: the front of its run, else the back of the run with the
 * most chunks left (far from where its owner works); -1 when none is left. */
static long next_chunk(pctx *c, int i)
{
    long k = take_chunk(c, i, 1);
    while (k < 0) {
        int most = -1;
        uint32_t left = 0;
        for (int j = 0; j < c->nw; j++) {
            const uint64_t r = atomic_load_explicit(&c->run[j], memory_order_relaxed);
            if (run_hi(r) > run_lo(r) && run_hi(r) - run_lo(r) > left) left = run_hi(r) - run_lo(r), most = j;
        }
        if (most < 0) return -1;
        k = take_chunk(c, most, 0);
    }
    return k;
}

/* Worker i's phase: chunks until none is left or it is out of cells. */
static void work(void *ctx, int i, int nw)
{
    pctx *c = ctx;
    worker *w = c->w + i;
    (void)nw;
    w->st = LH_OK;
    w->par.again = w->again, w->par.nagain = 0;
    while (w->st == LH_OK && !w->par.stopped) {
        const long k = next_chunk(c, i);
        if (k < 0) break;
        const size_t f = chunk_first(c, (uint32_t)k), to = chunk_first(c, (uint32_t)k + 1);
        w->st = w->e.insert_par(&w->e, f, to - f, NULL);
        w->sites += to - f;
    }
    w->par.again = NULL; /* deferred again: for the sequential pass */
    if (w->st == LH_OK && w->par.nagain) w->st = w->e.insert_par(&w->e, 0, w->par.nagain, w->again);
    lh__par_release(&w->par);
}

void lh__par_defer(lh__par *p, lh_index q)
{
    if (p->again) {
        p->again[p->nagain++] = q;
        return;
    }
    size_t i = atomic_fetch_add_explicit(&p->sh->ndeferred, 1, memory_order_relaxed);
    p->sh->deferred[i] = q;
}

/* The unused rest of t's block, top..cap-1, onto its free list (top stays). */
static void free_rest(lh__tds *t)
{
    for (lh_index x = t->top; x < t->cap; x++) {
        t->vert[(size_t)x * t->nv] = LH__DEAD;
        t->nbr[(size_t)x * t->nv] = t->free_head;
        t->free_head = x;
    }
}

int lh__par_refill(lh__par *p, lh__tds *t)
{
    if ((size_t)(t->cap - t->live) >= t->nbound) return 0; /* the scratch failed */
    lh__par_shared *sh = p->sh;
    size_t b = atomic_fetch_add_explicit(&sh->cursor, sh->block, memory_order_relaxed);
    if (b + sh->block > sh->end) {
        p->stopped = 1;
        return 0;
    }
    const lh_index freed = (t->top - t->live) + (t->cap - t->top);
    free_rest(t);
    p->live_shift += ((lh_index)b - freed) - t->live; /* top - live: still the free cells */
    t->live = (lh_index)b - freed;
    t->top = (lh_index)b;
    t->cap = (lh_index)(b + sh->block);
    return 1;
}

/* Appends the free list from `head` to the store's. */
static void splice_free(lh__tds *t, lh_index head)
{
    if (head < 0) return;
    lh_index tail = head;
    while (t->nbr[(size_t)tail * t->nv] >= 0) tail = t->nbr[(size_t)tail * t->nv];
    t->nbr[(size_t)tail * t->nv] = t->free_head;
    t->free_head = head;
}

/* The workers' store changes taken into e's: live counts, free lists with the rest
 * of each worker's last block, the blocks' top, rounds, counters. */
static lh_status merge(pctx *c, lh_index start)
{
    lh__eng *e = c->e;
    lh__tds *t = &e->tds;
    lh_status st = LH_OK;
    const size_t given = atomic_load(&c->sh.cursor) - (size_t)start, whole = (c->sh.end - (size_t)start) / BLOCK * BLOCK;
    t->top = start + (lh_index)(given < whole ? given : whole);
    t->free_head = -1;
    for (int i = 0; i < c->nw; i++) {
        worker *w = c->w + i;
        lh__tds *wt = &w->e.tds;
        t->live += wt->live - w->live0 - w->par.live_shift;
        t->round = wt->round > t->round ? wt->round : t->round;
        free_rest(wt);
        splice_free(t, wt->free_head);
        if (i) lh__pred_move_counters(e->pred, w->pred);
        w->hint = w->e.hint;
        e->par_sites += w->sites;
        e->par_stopped += (size_t)w->par.stopped;
        if (w->st != LH_OK && st == LH_OK) st = w->st;
    }
    e->par_deferred += atomic_load(&c->sh.ndeferred);
    e->rng = c->w[0].e.rng;
    e->hint = free_start(c, 0, c->w[0].e.hint); /* another worker may have freed it */
    return st;
}

/* The sites first..first+count-1 by c->nw workers, then those they deferred or did
 * not reach. */
static lh_status phase(pctx *c, size_t first, size_t count)
{
    lh__eng *e = c->e;
    lh__tds *t = &e->tds;
    const int nw = c->nw;
    /* new cells a site makes, as in the last round (more than the average so far:
       sites near the hull make fewer), with a margin; a worker out of blocks stops */
    const double per_site = (double)(t->live - c->mark_live) / (double)(first - c->mark_sites);
    const size_t need = (size_t)(per_site * (double)count * 1.04) + 2 * (size_t)nw * BLOCK;
    const uint32_t rounds = (uint32_t)(4 * count + 2); /* each worker's, at most: a site is
                                                           tried twice (lh__par_defer), a try
                                                           takes 2 rounds when it refills */
    lh_status st = lh__tds_reserve_top(t, need);
    if (st != LH_OK) return st;
    if ((uint64_t)t->round + (uint64_t)nw * rounds + 2 >= LH__TDS_MAX_ROUND) {
        lh__tds_reset_rounds(t);
        for (int i = 0; i < nw; i++)
            if (c->w[i].scratch.ridge) memset(c->w[i].scratch.ridge, 0, c->w[i].scratch.ridge_cap * sizeof(lh__ridge));
    }
    const lh_index start = t->top;
    atomic_store(&c->sh.cursor, (size_t)start);
    c->sh.end = (size_t)t->cap;
    if (e->dbg.par_blocks && c->sh.end - (size_t)start > e->dbg.par_blocks * BLOCK)
        c->sh.end = (size_t)start + e->dbg.par_blocks * BLOCK;
    atomic_store(&c->sh.ndeferred, 0);
    cut_runs(c, first, count);
    st = cover_again(c, count);
    if (st != LH_OK) return st;
    c->sh.base = t->round + 1, c->sh.span = rounds;
    for (int i = 0; i < nw; i++) prepare(c, i, t->round + (uint32_t)i * rounds);
    lh__par_for(nw, work, c); /* a worker whose thread does not start runs after */
    st = merge(c, start);
    const lh__insert_fn seq = e->insert ? e->insert : lh__eng_insert_generic;
    const size_t nd = atomic_load(&c->sh.ndeferred);
    if (st == LH_OK && nd) st = seq(e, 0, nd, c->sh.deferred);
    for (int i = 0; i < nw && st == LH_OK; i++) { /* the chunks no worker took (out of cells) */
        const uint64_t r = atomic_load(&c->run[i]);
        const size_t from = chunk_first(c, run_lo(r)), to = chunk_first(c, run_hi(r));
        if (from < to) st = seq(e, from, to - from, NULL);
    }
    return st;
}

lh_status lh__eng_insert_parallel(lh__eng *e, size_t at)
{
    const lh__insert_fn seq = e->insert ? e->insert : lh__eng_insert_generic;
    const int nw = e->threads;
    /* a phase's workers take disjoint ranges of 4 count + 2 visit rounds each */
    const size_t most = LH__TDS_MAX_ROUND / (8 * (size_t)nw) - 2;
    pctx c;
    lh_status st = setup(&c, e, nw);
    for (int r = 0; r < LH__BRIO_ROUNDS && st == LH_OK;) {
        size_t end = r == LH__BRIO_ROUNDS - 1 || e->round_end[r] > e->norder ? e->norder : e->round_end[r];
        if (end <= at) {
            r++;
            continue;
        }
        if (end - at > most) end = at + most; /* the rest of the round comes next */
        const size_t sites = at;
        const lh_index live = e->tds.live;
        if (at >= scaled(MIN_BUILT, e->d) && end - at >= (size_t)nw * scaled(MIN_RUN, e->d))
            st = phase(&c, at, end - at);
        else
            st = seq(e, at, end - at, NULL);
        at = end;
        c.mark_sites = sites, c.mark_live = live;
        if (st == LH_OK && e->progress) e->progress(e->progress_user, at, e->norder);
    }
    release(&c);
    return st;
}
