/* lh_eng_test.c — see lh_eng_test.h. */
#include "lh_eng_test.h"

#include <stdlib.h>
#include <string.h>

lh_index *lh_test_engine_cells(lh__eng *e, size_t *count)
{
    const int nv = e->nv;
    const size_t top = (size_t)e->tds.top;
    lh_index *raw = malloc((top * nv + 1) * sizeof *raw);
    lh_index *cells = malloc((top * nv + 1) * sizeof *cells);
    lh_index *order = malloc((top + 1) * sizeof *order);
    size_t k = 0;
    for (lh_index c = 0; raw && c < e->tds.top; c++) {
        if (lh__tds_dead(&e->tds, c) || !lh__eng_finite(e, c)) continue;
        memcpy(raw + k * nv, e->tds.vert + (size_t)c * nv, (size_t)nv * sizeof *raw);
        lh__canonical(raw + k * nv, nv);
        k++;
    }
    if (!raw || !cells || !order || !lh__sort_tuples(&e->alloc, raw, nv, k, e->n, cells, order)) k = 0;
    free(raw);
    free(order);
    *count = k;
    return cells;
}
