/* bench_counters.h — the predicate counters of a triangulation built by lh_delaunay, for
 * bench_delaunay's exact-path fraction (lifthull.h has no accessor for them). */
#ifndef LH_BENCH_COUNTERS_H
#define LH_BENCH_COUNTERS_H

#include <lifthull.h>

#ifdef __cplusplus
extern "C" {
#endif

/* How often each predicate stage ran while t was built (lh_delaunay's whole run: the
 * insertions, the fixed-dimension engines' inline filters included, and the output's
 * orientation checks). All zero for t NULL. */
void lh_bench_tri_counters(const lh_tri *t, lh_pred_counters *out);

#ifdef __cplusplus
}
#endif

#endif
