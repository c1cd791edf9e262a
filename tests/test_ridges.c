/* test_ridges.c — the ways the engine links new cells when a ridge's packed
 * vertices do not fit in 64 bits (insert_link_*.h: large n in 4D and up; turning in
 * place of twins in 3D beyond 2^32 sites), and turning in 2D in place of the tour:
 * forced here at small n, Delaunay and furthest-site, they must give exactly
 * lh_delaunay's simplices; and turning where the boundary numbering of 4D and up
 * runs out. */
#include "lh_eng_test.h"
#include "lh_families.h"
#include "lh_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The lifted tests, through the public predicate: Delaunay (q inside the
 * circumsphere) and furthest-site (q outside). */
static int lifted_sign(lh__eng *e, const lh_index *v, lh_index q)
{
    const double *p[LH__ENGINE_MAX_DIM + 2];
    for (int k = 0; k <= e->d; k++) p[k] = lh__eng_site(e, v[k]);
    p[e->d + 1] = lh__eng_site(e, q);
    return lh_insphere_sos(e->pred, e->d, p);
}
static int inside(void *user, const lh_index *v, lh_index q) { return lifted_sign(user, v, q) < 0; }
static int outside(void *user, const lh_index *v, lh_index q) { return lifted_sign(user, v, q) > 0; }

/* The cells of the engine on sites x (Delaunay, or furthest-site), with the
 * large-n linking forced when `hashed`; *turned: its insertions linked by turning.
 * NULL (count 0) when building fails. */
static lh_index *engine_cells(int d, size_t n, const double *x, int furthest, int hashed, size_t *count,
                              size_t *turned)
{
    lh_index *dup = malloc(n * sizeof *dup), *cells = NULL;
    lh__eng e;
    *count = *turned = 0;
    if (!dup) return NULL;
    if (lh__eng_init(&e, NULL, d, n, x, dup, NULL) == LH_OK) {
        e.finite_conflict = furthest ? outside : inside;
        e.user = &e;
        e.inside_conflicts = !furthest;
        e.dbg.hashed_ridges = hashed;
        int affdim;
        if (lh__eng_build(&e, 1024, &affdim) == LH_OK) cells = lh_test_engine_cells(&e, count);
        *turned = e.dbg.turned;
    }
    lh__eng_release(&e);
    free(dup);
    return cells;
}

/* Whether cells a (count tuples of d + 1) are lh_delaunay's simplices of x. */
static int same_as_lh_delaunay(int d, size_t n, const double *x, int furthest, const lh_index *a, size_t count)
{
    lh_options o;
    lh_options_default(&o);
    o.furthest_site = furthest;
    lh_tri *t = NULL;
    int same = lh_delaunay(d, n, x, &o, &t) == LH_OK && lh_tri_count(t) == count &&
               !memcmp(a, lh_tri_simplices(t), count * (size_t)(d + 1) * sizeof *a);
    lh_tri_free(t);
    return same;
}

/* The engine with the large-n linking forced (Delaunay: turning; furthest-site: the
 * ridge hash, its keys hashed from 4D on) against lh_delaunay, simplex for simplex. */
static void forced_as_lh_delaunay(lh_test_state *lh_t_, int d, int fam, size_t size, int furthest)
{
    double *x = malloc(size * d * sizeof *x);
    lh_fam_seed((uint64_t)(3 * d + fam));
    size_t n = lh_fam_make(fam, d, size, x), count, turned;
    lh_index *cells = engine_cells(d, n, x, furthest, 1, &count, &turned);
    LH_EXPECT_TRUE(count > 0);
    LH_EXPECT_TRUE(same_as_lh_delaunay(d, n, x, furthest, cells, count));
    if (LH_FAILED()) LH_NOTE("d=%d %s%s", d, lh_fam_name[fam], furthest ? " furthest-site" : "");
    free(cells);
    free(x);
}

LH_TEST(large_n_linking_gives_the_same_triangulation)
{
    static const size_t size[7] = {0, 0, 2000, 1000, 300, 120, 50};
    const int fams[3] = {F_CUBE, F_SPHERE_EXACT, F_GRID};
    for (int d = 2; d <= 6 && !LH_FAILED(); d++)
        for (int f = 0; f < 3 && !LH_FAILED(); f++)
            for (int furthest = 0; furthest < 2 && !LH_FAILED(); furthest++)
                forced_as_lh_delaunay(lh_t_, d, fams[f], size[d], furthest);
}

/* Sites on the moment curve (t, t^2, t^3, t^4) have a Delaunay triangulation in
 * which every two sites are joined (it is neighbourly), so a site inserted after
 * 255 others has a cavity whose boundary has more than 255 vertices: the numbers
 * of number_ridges run out and turning links the cells. The engine (the generic
 * loop) and lh_delaunay (the fixed-dimension one) must still give the
 * triangulation that turning alone gives. */
LH_TEST(boundaries_beyond_255_vertices_are_linked_by_turning)
{
    enum { N = 400, D = 4 };
    double *x = malloc(N * D * sizeof *x);
    for (int i = 0; i < N; i++)
        for (int j = 0, p = 1; j < D; j++, p++) x[i * D + j] = pow((i + 1) / (double)N, p);
    size_t count, turned, ref_count, ref_turned;
    lh_index *ref = engine_cells(D, N, x, 0, 1, &ref_count, &ref_turned);
    lh_index *cells = engine_cells(D, N, x, 0, 0, &count, &turned);
    LH_EXPECT_TRUE(ref_count > (size_t)N * N / 8); /* quadratic: neighbourly */
    LH_EXPECT_TRUE(turned > 0 && turned < N);
    LH_EXPECT_EQ_U64(count, ref_count);
    LH_EXPECT_TRUE(count == ref_count && !memcmp(cells, ref, count * (D + 1) * sizeof *cells));
    LH_EXPECT_TRUE(same_as_lh_delaunay(D, N, x, 0, ref, ref_count));
    LH_NOTE("%zu cells, %zu of %d insertions linked by turning", count, turned, N);
    free(ref);
    free(cells);
    free(x);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(large_n_linking_gives_the_same_triangulation),
        LH_CASE(boundaries_beyond_255_vertices_are_linked_by_turning),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
