/* test_parallel.c — lh_options.threads: the parallel insertion phases
 * (hull/parallel.c) and the shared output sort give exactly the one-thread output,
 * byte for byte, on every family in 2D..6D (fixed and generic engines); the
 * workers really insert sites, and the sites they defer (cells another worker
 * holds, cavities beyond their scratch) are inserted afterwards. */
#include "lh_api_test.h"
#include "lh_eng_test.h"
#include "lh_families.h"
#include "lh_test.h"
#include "lifthull.h"

#include <stdlib.h>
#include <string.h>

/* lift/delaunay.c (lift/dt.h): the lifted conflict test and its insertion loops. */
void lh__dt_conflicts(lh__eng *e, int furthest, int generic);

/* Sizes that give every dimension at least two parallel phases with 2 threads. */
static const size_t SIZE[7] = {0, 0, 40000, 12000, 2400, 640, 300};

static void same_as_one_thread(lh_test_state *lh_t_, int d, int fam, int generic)
{
    double *x = malloc(SIZE[d] * d * sizeof *x);
    lh_fam_seed((uint64_t)(91 * d + fam));
    size_t n = lh_fam_make(fam, d, SIZE[d], x);
    lh_options o;
    lh_options_default(&o);
    o.generic_engine = generic;
    lh_tri *one = NULL;
    lh_status s1 = lh_delaunay(d, n, x, &o, &one);
    const int threads[2] = {2, 3};
    for (int i = 0; i < 2 && !LH_FAILED(); i++) {
        o.threads = threads[i];
        lh_tri *many = NULL;
        LH_EXPECT_EQ_INT(lh_delaunay(d, n, x, &o, &many), s1);
        if (s1 == LH_OK && many) LH_EXPECT_TRUE(lh_test_same_tri(one, many));
        if (LH_FAILED()) LH_NOTE("d=%d %s%s threads=%d", d, lh_fam_name[fam], generic ? " generic" : "", threads[i]);
        lh_tri_free(many);
    }
    if (s1 == LH_OK) LH_EXPECT_EQ_INT(lh_tri_check(one, NULL), LH_OK);
    lh_tri_free(one);
    free(x);
}

LH_TEST(threads_give_the_one_thread_output)
{
    for (int d = 2; d <= 5 && !LH_FAILED(); d++)
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++)
            if (fam != F_GRID_JITTER || d < 4) /* seconds there: test_dims has it */
                same_as_one_thread(lh_t_, d, fam, 0);
    const int fams[3] = {F_CUBE, F_SPHERE_EXACT, F_GRID};
    for (int d = 2; d <= 6 && !LH_FAILED(); d++)
        for (int f = 0; f < 3 && !LH_FAILED(); f++) same_as_one_thread(lh_t_, d, fams[f], 1);
}

/* The engine run directly (the generic worker loop) with `threads`, a worker
 * cavity bound of `scratch` facets and `blocks` blocks of new cells a phase (0: the
 * defaults), against one thread; returns the sites the workers deferred, and in
 * *stopped (if not NULL) the workers that stopped. */
static size_t engine_run(lh_test_state *lh_t_, int d, int fam, int threads, size_t scratch, size_t blocks,
                         size_t *stopped)
{
    double *x = malloc(SIZE[d] * d * sizeof *x);
    lh_index *dup = malloc(SIZE[d] * sizeof *dup);
    lh_fam_seed((uint64_t)(7 * d + fam));
    size_t n = lh_fam_make(fam, d, SIZE[d], x), count[2] = {0, 0}, deferred = 0;
    lh_index *cells[2] = {NULL, NULL};
    for (int run = 0; run < 2; run++) {
        lh_options o;
        lh_options_default(&o);
        o.threads = run ? threads : 1;
        lh__eng e;
        if (lh__eng_init(&e, NULL, d, n, x, dup, &o) != LH_OK) {
            LH_EXPECT_TRUE(0); /* no memory for the predicates */
            lh__eng_release(&e);
            continue;
        }
        lh__dt_conflicts(&e, 0, 1); /* Delaunay, the loops with d a runtime value */
        e.dbg.par_scratch = scratch;
        e.dbg.par_blocks = blocks;
        int affdim;
        LH_EXPECT_EQ_INT(lh__eng_build(&e, 1024, &affdim), LH_OK);
        if (run) {
            LH_EXPECT_TRUE(blocks || e.par_sites > n / 3); /* the last round at least */
            deferred = e.par_deferred;
            if (stopped) *stopped = e.par_stopped;
        }
        cells[run] = lh_test_engine_cells(&e, count + run);
        lh__eng_release(&e);
    }
    LH_EXPECT_TRUE(count[0] > 0 && count[0] == count[1]);
    if (count[0] == count[1]) LH_EXPECT_TRUE(!memcmp(cells[0], cells[1], count[0] * (d + 1) * sizeof(lh_index)));
    if (LH_FAILED()) LH_NOTE("d=%d %s threads=%d scratch=%zu blocks=%zu", d, lh_fam_name[fam], threads, scratch, blocks);
    free(cells[0]);
    free(cells[1]);
    free(dup);
    free(x);
    return deferred;
}

LH_TEST(workers_insert_sites)
{
    for (int d = 2; d <= 4 && !LH_FAILED(); d++)
        for (int threads = 2; threads <= 4 && !LH_FAILED(); threads += 2) {
            engine_run(lh_t_, d, F_CUBE, threads, 0, 0, NULL);
            engine_run(lh_t_, d, F_GRID, threads, 0, 0, NULL);
            engine_run(lh_t_, d, F_CLUSTERS, threads, 0, 0, NULL);
        }
}

/* A cavity beyond a worker's scratch defers its site, whatever the timing: with a
 * bound of 8 boundary facets most 3D sites are deferred, some 2D ones. */
LH_TEST(deferred_sites_are_inserted_afterwards)
{
    for (int d = 2; d <= 3 && !LH_FAILED(); d++) {
        size_t deferred = engine_run(lh_t_, d, F_CUBE, 2, 8, 0, NULL);
        LH_EXPECT_TRUE(deferred > SIZE[d] / 100);
        LH_NOTE("d=%d: %zu sites deferred", d, deferred);
    }
}

/* Workers that run out of new cells stop; their sites and the chunks nobody took
 * are inserted afterwards: with one block of cells a phase, workers stop, and the
 * triangulation is still the one-thread one. Whether a given run stops one depends
 * on the threads' timing (under ASan, on 2 cores, a 2D run with 3 threads once
 * stopped none), so the stops are counted over all six runs (3 or 4 a run
 * otherwise). */
LH_TEST(sites_of_stopped_workers_are_inserted_afterwards)
{
    size_t total = 0;
    for (int d = 2; d <= 4 && !LH_FAILED(); d++)
        for (int threads = 2; threads <= 3 && !LH_FAILED(); threads++) {
            size_t stopped = 0, deferred = engine_run(lh_t_, d, F_CUBE, threads, 0, 1, &stopped);
            total += stopped;
            LH_NOTE("d=%d threads=%d: %zu workers stopped, %zu sites left to the sequential pass", d, threads,
                    stopped, deferred);
        }
    LH_EXPECT_GT_U64(total, 0);
}

/* lh_delaunay with 2 threads and the k-th allocation failing (all on the calling
 * thread: workers allocate nothing): LH_ERR_NOMEM, nothing leaked. */
enum { ALLOC_N = 6000 }; /* 3D: one parallel phase */
static lh_status threads_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const double *x = user;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    o.threads = 2;
    lh_tri *t = (lh_tri *)x;
    lh_status st = lh_delaunay(3, ALLOC_N, x, &o, &t);
    if (st != LH_OK) {
        LH_EXPECT_TRUE(t == NULL);
        return st;
    }
    LH_EXPECT_GT_U64(lh_tri_count(t), ALLOC_N);
    lh_tri_free(t);
    return st;
}

LH_TEST(every_allocation_failure_is_survived_with_threads)
{
    double *x = malloc(ALLOC_N * 3 * sizeof *x);
    lh_fam_seed(11);
    for (int i = 0; i < ALLOC_N * 3; i++) x[i] = lh_fam_unif();
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, threads_run, x), 10);
    free(x);
}

/* Duplicates merged by threads (order.c shares the runs of equal Hilbert keys): 500
 * distinct sites, each 1 to 200 times over in a random order, so that runs are
 * long (sorted exactly) and cross the threads' shares. Same output as one thread,
 * and every copy points at the smallest index of its site. */
LH_TEST(duplicates_are_merged_alike_by_threads)
{
    enum { DISTINCT = 500, N = 50000 };
    double *x = malloc(N * 2 * sizeof *x), base[DISTINCT][2];
    int *site = malloc(N * sizeof *site);
    size_t first[DISTINCT], distinct = 0;
    lh_fam_seed(5);
    for (int k = 0; k < DISTINCT; k++) base[k][0] = lh_fam_unif(), base[k][1] = lh_fam_unif(), first[k] = N;
    for (size_t i = 0; i < N; i++) {
        int k = site[i] = (int)(lh_fam_unif() * lh_fam_unif() * DISTINCT); /* skewed: some very often */
        x[2 * i] = base[k][0], x[2 * i + 1] = base[k][1];
        if (first[k] == N) first[k] = i, distinct++;
    }
    lh_options o;
    lh_options_default(&o);
    lh_tri *one = NULL, *two = NULL;
    LH_EXPECT_EQ_INT(lh_delaunay(2, N, x, &o, &one), LH_OK);
    o.threads = 2;
    LH_EXPECT_EQ_INT(lh_delaunay(2, N, x, &o, &two), LH_OK);
    if (one && two) {
        LH_EXPECT_TRUE(lh_test_same_tri(one, two));
        LH_EXPECT_EQ_INT((long)lh_tri_duplicate_count(two), (long)(N - distinct));
        const lh_index *of = lh_tri_duplicate_of(two);
        for (size_t i = 0; i < N && !LH_FAILED(); i++) LH_EXPECT_EQ_INT((long)of[i], (long)first[site[i]]);
    }
    lh_tri_free(one);
    lh_tri_free(two);
    free(site);
    free(x);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(threads_give_the_one_thread_output),
        LH_CASE(workers_insert_sites),
        LH_CASE(deferred_sites_are_inserted_afterwards),
        LH_CASE(sites_of_stopped_workers_are_inserted_afterwards),
        LH_CASE(every_allocation_failure_is_survived_with_threads),
        LH_CASE(duplicates_are_merged_alike_by_threads),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
