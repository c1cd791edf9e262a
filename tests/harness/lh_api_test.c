/* lh_api_test.c — see lh_api_test.h. */
#include "lh_api_test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

lh_status lh_test_pslg_file(lh_test_pslg_reader rd, const char *dir, const char *path, lh_pslg *g)
{
    char full[512];
    snprintf(full, sizeof full, "%s/%s", dir, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_status st = rd(f, path, NULL, g, NULL);
    fclose(f);
    return st;
}

lh_status lh_test_pslg_text(const char *text, lh_pslg *g)
{
    FILE *f = lh_test_file(text, strlen(text));
    if (!f) return LH_ERR_IO;
    lh_status st = lh_poly_read(f, "t.poly", NULL, g, NULL);
    fclose(f);
    return st;
}

lh_status lh_test_check_trimesh(const lh_trimesh *m, lh_error *err)
{
    return lh_cdt_check(lh_trimesh_point_count(m), lh_trimesh_points(m), lh_trimesh_triangle_count(m),
                            lh_trimesh_triangles(m), lh_trimesh_segment_count(m), lh_trimesh_segments(m), 0, NULL,
                            err);
}

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

typedef struct thread_run {
    lh_test_state *t;
    lh_test_alloc_run run;
    const void *user;
    lh_status st;
} thread_run;

static void *run_thread(void *arg)
{
    thread_run *r = arg;
    r->st = r->run(r->t, NULL, r->user);
    return NULL;
}

lh_status lh_test_run_on_thread(lh_test_state *lh_t_, lh_test_alloc_run run, const void *user,
                                size_t *stack)
{
    thread_run r = {lh_t_, run, user, LH_ERR_INTERNAL};
    *stack = lh_test_stack_used(run_thread, &r);
    return r.st;
}

static void *biggest_alloc(void *user, size_t size)
{
    lh_test_biggest *b = user;
    if (size > b->largest) b->largest = size;
    b->live++;
    return malloc(size);
}

static void biggest_free(void *user, void *ptr)
{
    lh_test_biggest *b = user;
    if (ptr) b->live--;
    free(ptr);
}

lh_allocator lh_test_biggest_allocator(lh_test_biggest *b)
{
    b->largest = 0;
    b->live = 0;
    return (lh_allocator){biggest_alloc, biggest_free, b};
}
