/* test_ridges.c — the ways the engine links new cells when a ridge's packed
 * vertices do not fit in 64 bits (insert_impl.h: large n in 4D and up; turning in
 * place of twins in 3D beyond 2^32 sites), and turning in 2D in place of the tour:
 * forced here at small n, Delaunay and furthest-site, they must give exactly
 * lh_delaunay's simplices. */
#include "lh_eng_test.h"
#include "lh_families.h"
#include "lh_test.h"

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

/* The engine with the large-n linking forced (Delaunay: turning; furthest-site: the
 * ridge hash, its keys hashed from 4D on) against lh_delaunay, simplex for simplex. */
static void same_as_lh_delaunay(lh_test_state *lh_t_, int d, int fam, size_t size, int furthest)
{
    double *x = malloc(size * d * sizeof *x);
    lh_index *dup = malloc(size * sizeof *dup);
    lh_fam_seed((uint64_t)(3 * d + fam));
    size_t n = lh_fam_make(fam, d, size, x);
    lh__eng e;
    LH_ASSERT_EQ_INT(lh__eng_init(&e, NULL, d, n, x, dup, NULL), LH_OK);
    e.finite_conflict = furthest ? outside : inside;
    e.user = &e;
    e.inside_conflicts = !furthest;
    e.hashed_ridges = 1;
    int affdim;
    LH_EXPECT_EQ_INT(lh__eng_build(&e, 1024, &affdim), LH_OK);
    const int nv = d + 1;
    size_t count;
    lh_index *cells = lh_test_engine_cells(&e, &count);
    LH_EXPECT_TRUE(count > 0);
    lh_options o;
    lh_options_default(&o);
    o.furthest_site = furthest;
    lh_tri *t = NULL;
    LH_EXPECT_EQ_INT(lh_delaunay(d, n, x, &o, &t), LH_OK);
    LH_EXPECT_EQ_U64(count, lh_tri_count(t));
    if (t && count == lh_tri_count(t))
        LH_EXPECT_TRUE(!memcmp(cells, lh_tri_simplices(t), count * nv * sizeof *cells));
    if (LH_FAILED()) LH_NOTE("d=%d %s%s", d, lh_fam_name[fam], furthest ? " furthest-site" : "");
    lh_tri_free(t);
    lh__eng_release(&e);
    free(cells);
    free(dup);
    free(x);
}

LH_TEST(large_n_linking_gives_the_same_triangulation)
{
    static const size_t size[7] = {0, 0, 2000, 1000, 300, 120, 50};
    const int fams[3] = {F_CUBE, F_SPHERE_EXACT, F_GRID};
    for (int d = 2; d <= 6 && !LH_FAILED(); d++)
        for (int f = 0; f < 3 && !LH_FAILED(); f++)
            for (int furthest = 0; furthest < 2 && !LH_FAILED(); furthest++)
                same_as_lh_delaunay(lh_t_, d, fams[f], size[d], furthest);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(large_n_linking_gives_the_same_triangulation),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
