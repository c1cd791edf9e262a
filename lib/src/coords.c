/* coords.c — validation of caller coordinates against the accepted range
 * (lifthull.h: every finite double; NaN and infinities are rejected). */
#include "lifthull.h"

#include <math.h>

lh_status lh_coords_validate(int d, size_t n, const double *xyz, size_t *bad_index)
{
    if (d < 1) return LH_ERR_INVALID_ARGUMENT;
    if (n > (size_t)-1 / (size_t)d) return LH_ERR_TOO_LARGE;
    if (n > 0 && !xyz) return LH_ERR_INVALID_ARGUMENT;
    size_t count = n * (size_t)d;
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(xyz[i])) {
            if (bad_index) *bad_index = i;
            return LH_ERR_NONFINITE;
        }
    }
    return LH_OK;
}
