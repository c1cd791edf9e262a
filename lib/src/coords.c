/* coords.c — validation of caller coordinates against the accepted range
 * (lifthull.h: every finite double; NaN and infinities are rejected). */
#include "lh_error.h"
#include "lifthull.h"

#include <math.h>

static lh_status validate(int d, size_t n, const double *xyz, lh_error *err)
{
    if (d < 1) return LH_ERR_INVALID_ARGUMENT;
    if (n > (size_t)-1 / (size_t)d) return LH_ERR_TOO_LARGE;
    if (n > 0 && !xyz) return LH_ERR_INVALID_ARGUMENT;
    size_t count = n * (size_t)d;
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(xyz[i])) {
            if (err) err->index = i;
            return lh__error_say(err, LH_ERR_NONFINITE,
                                 "xyz[%zu] is NaN or infinite (point %zu, coordinate %zu, from 0)",
                                 i, i / (size_t)d, i % (size_t)d);
        }
    }
    return LH_OK;
}

lh_status lh_coords_validate(int d, size_t n, const double *xyz, lh_error *err)
{
    if (!err) return validate(d, n, xyz, NULL); /* the library's own per-query calls */
    lh__error_clear(err);
    return lh__error_done(err, validate(d, n, xyz, err));
}
