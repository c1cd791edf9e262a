/*
 * dims.c — lh_delaunay: the fixed-dimension insertion loops (delaunay_d2.c ..
 * delaunay_d5.c) chosen once here, at the API boundary, for lift/'s Delaunay
 * triangulation; other dimensions, and lh_options.generic_engine, run the generic
 * loop. The handle keeps the choice for lh_tri_insert.
 */
#include "dt.h"

lh_status lh__dims_insert_2(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_3(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_4(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_5(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_2_par(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_3_par(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_4_par(lh__eng *e, size_t first, size_t count, const lh_index *list);
lh_status lh__dims_insert_5_par(lh__eng *e, size_t first, size_t count, const lh_index *list);

static lh__insert_fn pick(int d, int parallel)
{
    switch (d) {
    case 2: return parallel ? lh__dims_insert_2_par : lh__dims_insert_2;
    case 3: return parallel ? lh__dims_insert_3_par : lh__dims_insert_3;
    case 4: return parallel ? lh__dims_insert_4_par : lh__dims_insert_4;
    case 5: return parallel ? lh__dims_insert_5_par : lh__dims_insert_5;
    default: return NULL;
    }
}

lh_status lh_delaunay(int d, size_t n, const double *xyz, const lh_options *opt,
                      lh_tri **out)
{
    return lh__dt_delaunay(d, n, xyz, opt, opt && opt->generic_engine ? NULL : pick, out);
}
