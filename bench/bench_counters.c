/* bench_counters.c — lh_bench_tri_counters (bench_counters.h). lh_delaunay's engine counts
 * every predicate call in its own context, and the handle keeps that context for its
 * queries (struct lh_tri's pred, lift/dt.h) but the public header does not hand it out.
 * This file alone in bench/ reads the library's private layout; bench/CMakeLists.txt
 * compiles it against the internal headers of the same source tree, so the layout always
 * matches the library it is linked with. */
#include "bench_counters.h"

#include "dt.h"

void lh_bench_tri_counters(const lh_tri *t, lh_pred_counters *out)
{
    lh_pred_counters_get(t ? t->pred : NULL, out);
}
