/* natural.c — lh_tri_natural_coords (placeholder). */
#include "dt.h"

lh_status lh_tri_natural_coords(lh_tri *t, const double *q, int32_t hint, size_t cap,
                                int32_t *sites, double *weights, size_t *count)
{
    (void)t; (void)q; (void)hint; (void)cap; (void)sites; (void)weights;
    if (count) *count = 0;
    return LH_ERR_DIMENSION;
}
