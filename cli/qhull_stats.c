/*
 * qhull_stats.c — Qhull's Ts for lifthull: what the computation did, on standard
 * error after the outputs. Qhull's own statistics (precision constants, distance
 * tests, merges) have no counterpart under exact arithmetic; lifthull reports its
 * sizes, time and how each predicate call was decided (lh_pred_counters).
 */
#include "qhull.h"
#include "qhull_print.h"

#include <inttypes.h>

static void counter(FILE *f, uint64_t v, const char *what)
{
    fprintf(f, "%10" PRIu64 " %s\n", v, what);
}

void lh_cli_qstats(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    fprintf(f, "\nlifthull statistics: %s\n\n", o->command);
    fprintf(f, "%10zu input sites in %d-d\n", mo->n, mo->d);
    counter(f, mo->ndup, "duplicates merged");
    counter(f, lh_cli_qvertex_count(mo), "vertices of the printed facets");
    counter(f, mo->m, "facets printed");
    counter(f, mo->m_other, "other facets (negative ids)");
    fprintf(f, "%10.3g CPU seconds for the %s\n\n", mo->seconds,
            o->prog == LH_QPROG_CONVEX ? "hull" : "triangulation");
    if (!mo->tri) {
        fputs("predicate statistics: kept by lh_convex_hull internally (not reported)\n\n", f);
        return;
    }
    lh_pred_counters c;
    lh_tri_pred_counters_get(mo->tri, &c);
    fputs("predicate statistics (every answer exact)\n", f);
    counter(f, c.calls, "predicate calls");
    counter(f, c.filter_exits, "decided by the floating-point filter");
    counter(f, c.grid_exits, "decided by the filter's bound against the coordinates' granularity");
    counter(f, c.residue_exits, "proven exactly 0 by residues");
    counter(f, c.exact_exits, "decided by the exact integer stage");
    counter(f, c.zero_results, "exact zeros (cospherical or coplanar sites)");
    counter(f, c.sos_fast + c.sos_general, "ties broken by symbolic perturbation");
    fputc('\n', f);
}
