/* lh_api_test.c — see lh_api_test.h. */
#include "lh_api_test.h"

#include <string.h>

int lh_test_same_tri(const lh_tri *a, const lh_tri *b)
{
    int k = lh_tri_simplex_dim(a);
    size_t n = lh_tri_site_count(a), c = lh_tri_count(a), h = lh_tri_hull_count(a);
    if (k != lh_tri_simplex_dim(b) || n != lh_tri_site_count(b) || c != lh_tri_count(b) ||
        h != lh_tri_hull_count(b) || lh_tri_duplicate_count(a) != lh_tri_duplicate_count(b))
        return 0;
    size_t s = (size_t)(k + 1) * c * sizeof(lh_index);
    return !memcmp(lh_tri_simplices(a), lh_tri_simplices(b), s) &&
           !memcmp(lh_tri_neighbors(a), lh_tri_neighbors(b), s) &&
           !memcmp(lh_tri_hull_facets(a), lh_tri_hull_facets(b), (size_t)k * h * sizeof(lh_index)) &&
           !memcmp(lh_tri_vertex_simplex(a), lh_tri_vertex_simplex(b), n * sizeof(lh_index)) &&
           !memcmp(lh_tri_duplicate_of(a), lh_tri_duplicate_of(b), n * sizeof(lh_index));
}

long lh_test_every_failure(lh_test_state *lh_t_, lh_test_alloc_run run, const void *user)
{
    for (long k = 1;; k++) {
        lh_test_counter c = {0, k, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh_status st = run(lh_t_, &a, user);
        LH_EXPECT_EQ_INT(c.live, 0);
        if (st == LH_OK) return k;
        LH_EXPECT_EQ_INT(st, LH_ERR_NOMEM);
        if (LH_FAILED()) {
            LH_NOTE("failing allocation %ld", k);
            return k;
        }
    }
}
