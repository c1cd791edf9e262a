/*
 * lh_eng_test.h — for the tests that drive hull/'s engine directly (INTERNAL, with
 * hull/ on the include path): its cells as the output would list them.
 */
#ifndef LH_ENG_TEST_H
#define LH_ENG_TEST_H

#include "engine.h"

/* The finite cells of built engine e, each in canonical form (lh__canonical), sorted
 * lexicographically: *count tuples of e->nv indices, malloc'd (free it); *count = 0
 * when memory runs out. */
lh_index *lh_test_engine_cells(lh__eng *e, size_t *count);

#endif
