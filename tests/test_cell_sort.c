/* test_cell_sort.c — lh__tds_sort_cells (hull/cell_sort.c) on rows made to reach
 * each of its ways to order rows with one first vertex: groups above the insertion
 * sort's size, whose packed keys (the vertices after the first, as many as fit in
 * 64 bits) often tie, so that the vertices past the key decide; on one and two
 * threads. The result must be the finite rows first, each in canonical form with its
 * neighbour row permuted alike, in strictly increasing lexicographic order, and the
 * same finite rows whatever the threads. */
#include "engine.h"
#include "lh_test.h"

#include <stdlib.h>
#include <string.h>

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t next_random(void) { return lh__rng_next(&rng_state); }

/* Rows of nv vertices below n: `groups` first vertices spaced by `spread`, each with
 * `per` rows whose next nv - 2 vertices come from 5 choices (the keys tie) and whose
 * last vertex is the row's own; entries shuffled in each row, rows shuffled; then
 * `infinite` rows holding the vertex at infinity. Neighbour entries name their
 * (row, position) so that the test can follow them. */
static size_t make_rows(lh__tds *t, int nv, size_t groups, size_t per, lh_index spread, size_t infinite)
{
    const size_t count = groups * per + infinite;
    size_t r = 0;
    for (size_t g = 0; g < groups; g++)
        for (size_t i = 0; i < per; i++, r++) {
            lh_index *v = t->vert + r * (size_t)nv, base = (lh_index)g * spread;
            v[0] = base;
            for (int k = 1; k < nv - 1; k++) v[k] = base + (lh_index)(k * 5 + i % 5);
            v[nv - 1] = base + (lh_index)(nv * 5 + i);
        }
    for (; r < count; r++) {
        lh_index *v = t->vert + r * (size_t)nv;
        v[0] = LH__INF;
        for (int k = 1; k < nv; k++) v[k] = (lh_index)(r * (size_t)nv + (size_t)k);
    }
    for (r = 0; r < count; r++) { /* shuffled entries (the vertex at infinity stays first) */
        lh_index *v = t->vert + r * (size_t)nv;
        for (int k = nv - 1; k > (v[0] < 0); k--) {
            int j = (v[0] < 0) + (int)(next_random() % (uint64_t)(k + 1 - (v[0] < 0)));
            lh_index x = v[k];
            v[k] = v[j], v[j] = x;
        }
    }
    for (r = count; r-- > 1;) { /* shuffled rows */
        size_t j = (size_t)(next_random() % (r + 1));
        for (int k = 0; k < nv; k++) {
            lh_index x = t->vert[r * nv + k];
            t->vert[r * nv + k] = t->vert[j * nv + k], t->vert[j * nv + k] = x;
        }
    }
    for (r = 0; r < count; r++)
        for (int k = 0; k < nv; k++) t->nbr[r * nv + k] = (lh_index)(r * (size_t)nv + (size_t)k);
    t->top = t->live = (lh_index)count;
    return count;
}

/* Row a before row b, lexicographically. */
static int row_before(const lh_index *a, const lh_index *b, int nv)
{
    for (int k = 0; k < nv; k++)
        if (a[k] != b[k]) return a[k] < b[k];
    return 0;
}

/* Sorts the rows with `threads` and checks the result against the rows before
 * (in): returns the sorted finite vertex rows (malloc'd) for comparing runs (the
 * other rows' order depends on the threads: cell_sort.c, first_pass). */
static lh_index *sort_and_check(lh_test_state *lh_t_, int nv, size_t n, size_t groups, size_t per,
                                lh_index spread, int threads)
{
    lh__tds t;
    const size_t infinite = 50, total = groups * per + infinite;
    lh_index *in = malloc(total * nv * sizeof *in), *orig = malloc(total * sizeof *orig);
    if (!in || !orig || lh__tds_init(&t, NULL, nv, (lh_index)total) != LH_OK) {
        LH_EXPECT_TRUE(0); /* no memory for the test itself */
        free(in);
        free(orig);
        return NULL;
    }
    rng_state = 0x9e3779b97f4a7c15u;
    make_rows(&t, nv, groups, per, spread, infinite);
    memcpy(in, t.vert, total * nv * sizeof *in);
    size_t count = 0;
    LH_EXPECT_EQ_INT(lh__tds_sort_cells(&t, n, orig, &count, threads), LH_OK);
    LH_EXPECT_EQ_U64(count, groups * per);
    size_t unordered = 0, not_canonical = 0, not_carried = 0;
    for (size_t r = 0; r < total; r++) {
        const lh_index *v = t.vert + r * nv, *from = in + (size_t)orig[r] * nv;
        for (int k = 0; k < nv; k++) { /* neighbour entry k came with vertex k */
            const lh_index id = t.nbr[r * nv + k];
            not_carried += id / nv != orig[r] || from[id % nv] != v[k];
        }
        if (r >= count) {
            not_canonical += v[0] != LH__INF;
            continue;
        }
        for (int k = 0; k + 2 < nv; k++) not_canonical += !(v[k] < v[k + 1]);
        not_canonical += !(v[nv - 3] < v[nv - 1]) || v[nv - 2] == v[nv - 1];
        if (r) unordered += !row_before(v - nv, v, nv);
    }
    LH_EXPECT_EQ_U64(unordered, 0);
    LH_EXPECT_EQ_U64(not_canonical, 0);
    LH_EXPECT_EQ_U64(not_carried, 0);
    if (LH_FAILED()) LH_NOTE("nv=%d n=%zu threads=%d", nv, n, threads);
    lh_index *out = malloc(count * nv * sizeof *out + 1);
    if (out) memcpy(out, t.vert, count * nv * sizeof *out);
    free(in);
    free(orig);
    lh__tds_release(&t);
    return out;
}

/* 4D rows below 2^20 sites (3 vertices in a key, the fourth decides ties), 5D rows
 * below 5000 (4 in a key) and 4D rows below 2000 (the whole row in the key), 200, 40
 * and 30 rows a group, each bucket gathered (gather_sort); then 3D rows below 4000
 * whose 80 000 rows in one bucket are too many to gather, so that it is sorted in
 * place (digit pass, group_sort): the same on 2 and 3 threads. The first case's
 * 52 000 rows take 2 and 3 threads, whose parts of the first pass's buckets leave
 * hundreds of rows misplaced (first_pass: without its repair, this test fails). */
LH_TEST(groups_are_ordered_past_their_keys)
{
    static const struct {
        int nv;
        size_t n, groups, per;
        lh_index spread;
    } cases[] = {{5, (size_t)1 << 20, 260, 200, 1000},
                 {6, 5000, 40, 40, 120},
                 {5, 2000, 10, 30, 150},
                 {4, 4000, 32, 2500, 1}};
    for (size_t c = 0; c < LH_COUNT(cases) && !LH_FAILED(); c++) {
        const size_t rows = cases[c].groups * cases[c].per * cases[c].nv;
        lh_index *one = sort_and_check(lh_t_, cases[c].nv, cases[c].n, cases[c].groups, cases[c].per,
                                       cases[c].spread, 1);
        for (int threads = 2; threads <= 3; threads++) {
            lh_index *more = sort_and_check(lh_t_, cases[c].nv, cases[c].n, cases[c].groups, cases[c].per,
                                            cases[c].spread, threads);
            LH_EXPECT_TRUE(one && more && !memcmp(one, more, rows * sizeof *one));
            free(more);
        }
        free(one);
    }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(groups_are_ordered_past_their_keys)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
