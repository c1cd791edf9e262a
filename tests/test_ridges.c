/* test_ridges.c — the ways the engine links new cells when a ridge's packed
 * vertices do not fit in 64 bits (insert_impl.h: large n in 4D and up; turning in
 * place of twins in 3D beyond 2^32 sites), and turning in the 2D generic engine:
 * forced here at small n, they must give exactly lh_delaunay's simplices. */
#include "engine.h"
#include "lh_families.h"
#include "lh_test.h"

#include <stdlib.h>
#include <string.h>

/* The lifted test, through the public predicate. */
static int lifted(void *user, const lh_index *v, lh_index q)
{
    lh__eng *e = user;
    const double *p[LH__ENGINE_MAX_DIM + 2];
    for (int k = 0; k <= e->d; k++) p[k] = lh__eng_site(e, v[k]);
    p[e->d + 1] = lh__eng_site(e, q);
    return lh_insphere_sos(e->pred, e->d, p) < 0;
}

LH_TEST(large_n_linking_gives_the_same_triangulation)
{
    static const size_t size[7] = {0, 0, 2000, 1000, 300, 120, 50};
    int fams[3] = {F_CUBE, F_SPHERE_EXACT, F_GRID};
    for (int d = 2; d <= 6 && !LH_FAILED(); d++)
        for (int f = 0; f < 3 && !LH_FAILED(); f++) {
            double *x = malloc(size[d] * d * sizeof *x);
            lh_index *dup = malloc(size[d] * sizeof *dup);
            lh_fam_seed((uint64_t)(3 * d + f));
            size_t n = lh_fam_make(fams[f], d, size[d], x);
            lh__eng e;
            LH_ASSERT_EQ_INT(lh__eng_init(&e, NULL, d, n, x, dup, NULL), LH_OK);
            e.finite_conflict = lifted;
            e.user = &e;
            e.inside_conflicts = 1;
            e.hashed_ridges = 1;
            int affdim;
            LH_EXPECT_EQ_INT(lh__eng_build(&e, 1024, &affdim), LH_OK);
            const int nv = d + 1;
            lh_index *raw = malloc((size_t)e.tds.top * nv * sizeof *raw);
            lh_index *cells = malloc((size_t)e.tds.top * nv * sizeof *cells);
            lh_index *order = malloc((size_t)e.tds.top * sizeof *order);
            size_t count = 0;
            for (lh_index c = 0; c < e.tds.top; c++) {
                if (lh__tds_dead(&e.tds, c) || !lh__eng_finite(&e, c)) continue;
                memcpy(raw + count * nv, e.tds.vert + (size_t)c * nv, (size_t)nv * sizeof *raw);
                lh__canonical(raw + count * nv, nv);
                count++;
            }
            LH_ASSERT_TRUE(lh__sort_tuples(&e.alloc, raw, nv, count, n, cells, order));
            lh_tri *t;
            LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
            LH_EXPECT_EQ_U64(count, lh_tri_count(t));
            if (count == lh_tri_count(t))
                LH_EXPECT_TRUE(!memcmp(cells, lh_tri_simplices(t), count * nv * sizeof *cells));
            if (LH_FAILED()) LH_NOTE("d=%d %s", d, lh_fam_name[fams[f]]);
            lh_tri_free(t);
            lh__eng_release(&e);
            free(raw);
            free(cells);
            free(order);
            free(dup);
            free(x);
        }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(large_n_linking_gives_the_same_triangulation),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
