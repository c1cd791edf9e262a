/* stubs.c — placeholders for mesh3d entry points being written (each moves to its
 * own file). */
#include "t3.h"

lh_status lh_plc_intersections(const lh_plc *g, const lh_allocator *alloc, size_t cap,
                               lh_index *pairs, size_t *count, lh_error *err)
{
    (void)g; (void)alloc; (void)cap; (void)pairs;
    if (count) *count = 0;
    return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "lh_plc_intersections: not written yet");
}
