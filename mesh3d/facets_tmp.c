/* facets_tmp.c — a stand-in: each facet's first ring as a fan. */
#include "facets.h"

#include <string.h>

lh_status lh__facets_triangulate(const lh_plc *g, const lh_allocator *al, lh__facet_tris *out,
                                 lh_error *err)
{
    memset(out, 0, sizeof *out);
    size_t cnt = 0;
    for (size_t f = 0; f < g->facet_count; f++) {
        lh_index p = g->facet_first[f];
        if (p >= g->facet_first[f + 1]) continue;
        size_t k = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
        if (k >= 3) cnt += k - 2;
    }
    out->tri = lh__alloc(al, (3 * cnt + 1) * sizeof(lh_index));
    out->facet = lh__alloc(al, (cnt + 1) * sizeof(lh_index));
    if (!out->tri || !out->facet) {
        lh__facet_tris_free(al, out);
        return lh__error_say(err, LH_ERR_NOMEM, "out of memory");
    }
    for (size_t f = 0; f < g->facet_count; f++) {
        lh_index p = g->facet_first[f];
        if (p >= g->facet_first[f + 1]) continue;
        const lh_index *v = g->polygon_vertices + g->polygon_first[p];
        size_t k = (size_t)(g->polygon_first[p + 1] - g->polygon_first[p]);
        for (size_t i = 1; i + 1 < k; i++) {
            lh_index *t = out->tri + 3 * out->count;
            t[0] = v[0], t[1] = v[i], t[2] = v[i + 1];
            out->facet[out->count++] = (lh_index)f;
        }
    }
    return LH_OK;
}

void lh__facet_tris_free(const lh_allocator *al, lh__facet_tris *t)
{
    lh__free(al, t->tri);
    lh__free(al, t->facet);
    memset(t, 0, sizeof *t);
}
