/* lh_api_test.h — test helpers that need the library (the rest of the harness,
 * lh_test.h, does not). */
#ifndef LH_API_TEST_H
#define LH_API_TEST_H

#include "lh_test.h"
#include "lifthull.h"

/* Whether two Delaunay handles hold the same output, byte for byte: the same simplex
 * dimension k, counts, simplices, neighbours, hull facets, incident simplices and
 * duplicate map (the ambient dimension may differ: a triangulation within a plane of
 * R^3 against the same one in R^2). */
int lh_test_same_tri(const lh_tri *a, const lh_tri *b);

/* One run of an entry point with the given allocator; it frees what it built and
 * returns its status (checking on failure that it handed nothing back). */
typedef lh_status (*lh_test_alloc_run)(lh_test_state *lh_t_, const lh_allocator *a, const void *user);

/* Runs `run` with the k-th allocation failing, k = 1, 2, ... until a run succeeds:
 * every failing run must report LH_ERR_NOMEM and leave nothing allocated. Returns the
 * number of runs. */
long lh_test_every_failure(lh_test_state *lh_t_, lh_test_alloc_run run, const void *user);

/* Runs `run` with the default allocator on a thread of its own: its status, and in
 * *stack the bytes of stack it used (lh_test_stack_used; 0 when no thread ran, then
 * LH_ERR_INTERNAL). */
lh_status lh_test_run_on_thread(lh_test_state *lh_t_, lh_test_alloc_run run, const void *user,
                                size_t *stack);

/* An allocator that records the largest single request and the blocks live: to see
 * that a reader does not allocate from a count it has not read the data for. */
typedef struct lh_test_biggest {
    size_t largest;
    long live;
} lh_test_biggest;
/* The allocator over *b (zeroed first). */
lh_allocator lh_test_biggest_allocator(lh_test_biggest *b);

/* A PSLG reader (lh_poly_read, lh_rings_read, ...). */
typedef lh_status (*lh_test_pslg_reader)(FILE *, const char *, const lh_allocator *, lh_pslg *, lh_error *);
/* Reads dir/path with rd: the reader's status (LH_ERR_IO when it cannot be opened). */
lh_status lh_test_pslg_file(lh_test_pslg_reader rd, const char *dir, const char *path, lh_pslg *g);
/* Reads text as a .poly file. */
lh_status lh_test_pslg_text(const char *text, lh_pslg *g);
/* lh_cdt_check of a mesh with its subsegments, boundary edges checked. */
lh_status lh_test_check_trimesh(const lh_trimesh *m, lh_error *err);

#endif
