/* test_insert.c — lh_tri_insert (and lh_tri_insert_unordered, then lh_tri_sort): the
 * result is lh_delaunay's for all the sites, byte for byte, in batches, with
 * duplicates, furthest-site; bad input and allocation failures leave the
 * triangulation unchanged. */
#include "lh_families.h"
#include "lh_test.h"
#include "lh_api_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Builds from the first `first` sites, inserts the rest in `batches` batches, and
 * compares with lh_delaunay of all n; the exact check passes on the result. */
static void insert_matches_build(lh_test_state *lh_t_, int d, size_t n, const double *x,
                                 size_t first, int batches, int furthest, const char *what)
{
    lh_options o;
    lh_options_default(&o);
    o.furthest_site = furthest;
    lh_tri *all, *t;
    lh_status st = lh_delaunay(d, n, x, &o, &all);
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st != LH_OK) {
        LH_NOTE("%s: d=%d n=%zu: %s", what, d, n, lh_status_message(st));
        return;
    }
    st = lh_delaunay(d, first, x, &o, &t);
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st != LH_OK) {
        LH_NOTE("%s: first %zu sites: %s", what, first, lh_status_message(st));
        lh_tri_free(all);
        return;
    }
    size_t at = first;
    for (int b = 0; b < batches; b++) {
        size_t end = b == batches - 1 ? n : at + (n - first) / (size_t)batches;
        LH_EXPECT_EQ_INT(lh_tri_insert(t, end - at, x + at * (size_t)d), LH_OK);
        at = end;
    }
    lh_error err;
    LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(t, all));
    if (LH_FAILED()) LH_NOTE("%s (d=%d n=%zu first=%zu batches=%d): %s", what, d, n, first, batches, err.message);
    lh_tri_free(t);
    lh_tri_free(all);
}

static int cmp_index(const void *a, const void *b)
{
    const lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return (x > y) - (x < y);
}

static int cmp_row9(const void *a, const void *b)
{
    return memcmp(a, b, 9 * sizeof(lh_index)); /* rows padded to 9 entries */
}

/* t's simplices as a set (each sorted, then the list) equal all's; each positively
 * oriented. */
static int same_set(const lh_tri *t, const lh_tri *all, const double *x, int d)
{
    const size_t nv = (size_t)d + 1, m = lh_tri_count(t);
    if (m != lh_tri_count(all)) return 0;
    lh_index *a = calloc(9 * m + 1, sizeof *a), *b = calloc(9 * m + 1, sizeof *b);
    lh_pred *pr;
    int same = a && b && lh_pred_create(NULL, &pr) == LH_OK;
    for (size_t i = 0; same && i < m; i++) {
        const double *p[9];
        for (size_t k = 0; k < nv; k++) p[k] = x + (size_t)lh_tri_simplices(t)[i * nv + k] * d;
        same &= lh_orient(pr, d, p) > 0;
        memcpy(a + 9 * i, lh_tri_simplices(t) + i * nv, nv * sizeof *a);
        memcpy(b + 9 * i, lh_tri_simplices(all) + i * nv, nv * sizeof *b);
        qsort(a + 9 * i, nv, sizeof *a, cmp_index);
        qsort(b + 9 * i, nv, sizeof *b, cmp_index);
    }
    if (same) {
        qsort(a, m, 9 * sizeof *a, cmp_row9);
        qsort(b, m, 9 * sizeof *b, cmp_row9);
        same = !memcmp(a, b, 9 * m * sizeof *a);
        lh_pred_free(pr);
    }
    free(a), free(b);
    return same;
}

/* The same with lh_tri_insert_unordered: the set of simplices is all's after the
 * rounds, and lh_tri_sort makes it all's byte for byte. */
static void unordered_matches_build(lh_test_state *lh_t_, int d, size_t n, const double *x,
                                    size_t first, int batches, const char *what)
{
    lh_tri *all, *t;
    LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &all), LH_OK);
    LH_ASSERT_EQ_INT(lh_delaunay(d, first, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_sort(t), LH_OK); /* sorted already: a no-op */
    size_t at = first;
    for (int b = 0; b < batches; b++) {
        size_t end = b == batches - 1 ? n : at + (n - first) / (size_t)batches;
        LH_EXPECT_EQ_INT(lh_tri_insert_unordered(t, end - at, x + at * (size_t)d), LH_OK);
        at = end;
    }
    LH_EXPECT_TRUE(same_set(t, all, x, d));
    LH_EXPECT_EQ_INT(lh_tri_sort(t), LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(t, all));
    if (LH_FAILED()) LH_NOTE("%s (d=%d n=%zu first=%zu batches=%d)", what, d, n, first, batches);
    lh_tri_free(t);
    lh_tri_free(all);
}

/* Random order, so that a prefix of a grid is not all on one line. */
static void shuffle(double *x, size_t n, int d)
{
    for (size_t i = n; i > 1; i--) {
        size_t k = lh_fam_rnd() % i;
        for (int j = 0; j < d; j++) {
            double t = x[(i - 1) * d + j];
            x[(i - 1) * d + j] = x[k * d + j];
            x[k * d + j] = t;
        }
    }
}

LH_TEST(insertion_gives_the_triangulation_of_all_sites)
{
    static const size_t size[6] = {0, 0, 1200, 600, 200, 100}; /* > side^(d-1): full-dimensional grids */
    for (int d = 2; d <= 5 && !LH_FAILED(); d++)
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++) {
            double *x = malloc(size[d] * d * sizeof *x);
            lh_fam_seed((uint64_t)(13 * d + fam));
            size_t n = lh_fam_make(fam, d, size[d], x);
            shuffle(x, n, d);
            insert_matches_build(lh_t_, d, n, x, n / 2, 1, 0, lh_fam_name[fam]);
            insert_matches_build(lh_t_, d, n, x, n / 10 + d + 1, 4, 0, lh_fam_name[fam]);
            unordered_matches_build(lh_t_, d, n, x, n / 10 + d + 1, 4, lh_fam_name[fam]);
            free(x);
        }
}

/* The centre of sites on a sphere, inserted last, conflicts with every finite cell:
 * its cavity's boundary is the whole hull, far more than the 63 vertices that 3D
 * linking numbers (insert_link_twins.h, cone_local), so it takes the hashed twins. */
LH_TEST(a_cavity_with_more_boundary_vertices_than_numbers)
{
    enum { N = 300 };
    double x[3 * (N + 1)];
    lh_fam_seed(77);
    for (size_t i = 0; i < N; i++) {
        double r2 = 0;
        for (int j = 0; j < 3; j++) {
            x[3 * i + j] = (double)(lh_fam_rnd() % 2001) - 1000;
            r2 += x[3 * i + j] * x[3 * i + j];
        }
        for (int j = 0; j < 3; j++) x[3 * i + j] = r2 > 0 ? x[3 * i + j] / sqrt(r2) : 1;
    }
    x[3 * N] = x[3 * N + 1] = x[3 * N + 2] = 0;
    insert_matches_build(lh_t_, 3, N + 1, x, N, 1, 0, "sphere and its centre");
}

LH_TEST(one_site_at_a_time_and_furthest_site)
{
    for (int d = 2; d <= 4 && !LH_FAILED(); d++) {
        int fams[3] = {F_CUBE, F_GRID, F_SPHERE_EXACT};
        for (int f = 0; f < 3 && !LH_FAILED(); f++) {
            size_t n = 60;
            double *x = malloc(n * d * sizeof *x);
            lh_fam_seed((uint64_t)(7 * d + f));
            n = lh_fam_make(fams[f], d, n, x);
            shuffle(x, n, d);
            insert_matches_build(lh_t_, d, n, x, n - 20, 20, 0, lh_fam_name[fams[f]]);
            insert_matches_build(lh_t_, d, n, x, n / 2, 3, 1, lh_fam_name[fams[f]]);
            free(x);
        }
    }
}

LH_TEST(inserted_duplicates_are_merged_into_the_first)
{
    /* Sites 5.. repeat earlier ones (one as -0.0) and each other. */
    double x[] = {0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25, /* built */
                  1, 0, -0.0, 1, 2, 2, 2, 2, 0.5, 0.25, 3, -1};
    size_t n = sizeof x / sizeof x[0] / 2;
    insert_matches_build(lh_t_, 2, n, x, 5, 1, 0, "duplicates");
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 5, x, NULL, &t), LH_OK);
    LH_ASSERT_EQ_INT(lh_tri_insert(t, n - 5, x + 10), LH_OK);
    const lh_index *dup = lh_tri_duplicate_of(t);
    lh_index want[11] = {0, 1, 2, 3, 4, 1, 2, 7, 7, 4, 10};
    for (size_t i = 0; i < n; i++) LH_EXPECT_EQ_INT(dup[i], want[i]);
    LH_EXPECT_EQ_U64(lh_tri_duplicate_count(t), 4);
    LH_EXPECT_EQ_INT(lh_tri_vertex_simplex(t)[5], -1);
    lh_tri_free(t);
}

/* A copy of t's simplices (to see that a failed call changed nothing). */
static lh_index *copy_simplices(const lh_tri *t)
{
    size_t s = (size_t)(lh_tri_dim(t) + 1) * lh_tri_count(t) * sizeof(lh_index);
    lh_index *c = malloc(s + 1);
    memcpy(c, lh_tri_simplices(t), s);
    return c;
}

LH_TEST(bad_input_leaves_the_triangulation_unchanged)
{
    double x[] = {0, 0, 1, 0, 0, 1, 1, 1}, more[] = {0.5, 0.5, NAN, 0.2, 7, 7};
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 4, x, NULL, &t), LH_OK);
    lh_index *before = copy_simplices(t);
    size_t count = lh_tri_count(t);
    LH_EXPECT_EQ_INT(lh_tri_insert(NULL, 1, more), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_insert(t, 1, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_insert(t, 0, NULL), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_insert(t, 3, more), LH_ERR_NONFINITE);
    more[2] = INFINITY;
    LH_EXPECT_EQ_INT(lh_tri_insert(t, 3, more), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(lh_tri_insert(t, SIZE_MAX / 2, more), LH_ERR_TOO_LARGE);
    LH_EXPECT_EQ_U64(lh_tri_site_count(t), 4);
    LH_ASSERT_EQ_U64(lh_tri_count(t), count);
    LH_EXPECT_TRUE(!memcmp(before, lh_tri_simplices(t), count * 3 * sizeof(lh_index)));
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    free(before);
    lh_tri_free(t);
}

LH_TEST(every_allocation_failure_leaves_the_triangulation_unchanged)
{
    enum { N = 300, M = 100, D = 3 };
    double *x = malloc((N + M) * D * sizeof *x);
    lh_fam_seed(17);
    lh_fam_make(F_DUPLICATES, D, N + M, x);
    long k = 1;
    for (;; k++) {
        lh_test_counter c = {0, 0, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh_options o;
        lh_options_default(&o);
        o.alloc = &a;
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(D, N, x, &o, &t), LH_OK);
        lh_index *before = copy_simplices(t);
        size_t count = lh_tri_count(t);
        c.fail_at = c.calls + k; /* the k-th allocation of the insertion fails */
        lh_status st = lh_tri_insert(t, M, x + N * D);
        if (st != LH_OK) {
            LH_EXPECT_EQ_INT(st, LH_ERR_NOMEM);
            LH_EXPECT_EQ_U64(lh_tri_count(t), count);
            LH_EXPECT_EQ_U64(lh_tri_site_count(t), N);
            if (lh_tri_count(t) == count)
                LH_EXPECT_TRUE(!memcmp(before, lh_tri_simplices(t), count * (D + 1) * sizeof(lh_index)));
        }
        c.fail_at = 0; /* the check allocates through the handle's hooks too */
        LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
        free(before);
        lh_tri_free(t);
        LH_EXPECT_EQ_INT(c.live, 0);
        if (st == LH_OK || LH_FAILED()) break;
    }
    if (LH_FAILED()) LH_NOTE("failing allocation %ld of the insertion", k);
    LH_EXPECT_GT_INT(k, 5); /* it allocates */
    free(x);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(insertion_gives_the_triangulation_of_all_sites),
        LH_CASE(a_cavity_with_more_boundary_vertices_than_numbers),
        LH_CASE(one_site_at_a_time_and_furthest_site),
        LH_CASE(inserted_duplicates_are_merged_into_the_first),
        LH_CASE(bad_input_leaves_the_triangulation_unchanged),
        LH_CASE(every_allocation_failure_leaves_the_triangulation_unchanged),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
