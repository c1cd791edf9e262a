/*
 * output.c — the triangulation as the caller sees it: finite simplices in canonical
 * form (vertices increasing but for one exchange that keeps orient_d > 0; simplices
 * in lexicographic order), neighbours, outward hull facets, an incident simplex per
 * site. Canonical form makes the output a function of the site set alone. The
 * simplex and neighbour arrays are the engine's cell store, sorted in place.
 */
#include "dt.h"

#include <string.h>

typedef struct remap {
    const lh_index *orig;
    lh_index *simplex_of, *nb;
    size_t count, nv;
} remap;

static void invert_range(void *ctx, size_t lo, size_t hi)
{
    const remap *j = ctx;
    for (size_t r = lo; r < hi; r++) {
        if (r + LH__AHEAD < hi) LH__PREFETCH(j->simplex_of + j->orig[r + LH__AHEAD]);
        j->simplex_of[j->orig[r]] = r < j->count ? (lh_index)r : -1;
    }
}

static void remap_range(void *ctx, size_t lo, size_t hi)
{
    const remap *j = ctx;
    for (size_t i = lo; i < hi; i++) {
        if (i + LH__AHEAD * j->nv < hi) LH__PREFETCH(j->simplex_of + j->nb[i + LH__AHEAD * j->nv]);
        j->nb[i] = j->simplex_of[j->nb[i]];
    }
}

/* The simplices are the store's rows 0..count-1 once sorted in place
 * (lh__tds_sort_cells), and its arrays pass to t: no copy of the cells coexists
 * with them. Each neighbour entry, a row's position before the sort, becomes its
 * simplex (-1 for an infinite cell) through simplex_of, the inverse of orig; the
 * random accesses are prefetched LH__AHEAD iterations early. */
static lh_status extract_simplices(lh__eng *b, lh_tri *t, lh_index *orig, int sorted)
{
    lh__tds *s = &b->tds;
    const size_t nv = (size_t)b->nv, top = (size_t)s->top;
    size_t count = 0;
    lh_status st = sorted ? lh__tds_sort_cells(s, t->n, orig, &count, b->threads)
                          : lh__tds_compact_cells(s, orig, &count);
    /* the hull facets from the infinite cells, now after the finite ones: rows
       count.. hold them whole (the sort moves rows; only finite ones change) */
    if (st == LH_OK) st = lh__eng_hull_facets(b, (lh_index)count, &t->hull, &t->hull_count);
    lh_index *simplex_of = NULL;
    if (st == LH_OK && !(simplex_of = lh__alloc(&t->alloc, (top + 1) * sizeof *simplex_of)))
        st = LH_ERR_NOMEM;
    if (st != LH_OK) return st;
    remap job = {orig, simplex_of, s->nbr, count, nv};
    lh__par_range(b->threads, top, invert_range, &job);
    lh__par_range(b->threads, count * nv, remap_range, &job);
    lh__free(&t->alloc, simplex_of);
    t->count = count;
    t->simp = s->vert;
    t->nbr = s->nbr;
    s->vert = s->nbr = NULL;
    return LH_OK;
}

/* An incident simplex per site, the least that holds it (-1: none): from the
 * output itself, so right even for sites that stopped being vertices
 * (furthest-site). Each of `ways` threads takes a range of simplices from its end
 * to its start, writing its least in an array of its own (the first thread's is
 * vsimp); a site's entry is then the first thread's that has one. */
enum { INCIDENT_WAYS = 4 }; /* threads at most: (ways - 1) n more indices */
typedef struct incident {
    const lh_tri *t;
    int nv, ways;
    lh_index *least[INCIDENT_WAYS];
} incident;

static void incident_share(void *ctx, int w, int nw)
{
    const incident *j = ctx;
    const lh_tri *t = j->t;
    const int nv = j->nv;
    lh_index *least = j->least[w];
    for (size_t i = 0; i < t->n; i++) least[i] = -1;
    const size_t lo = lh__share(t->count, w, nw);
    for (size_t c = lh__share(t->count, w + 1, nw); c-- > lo;) {
        if (c >= lo + LH__AHEAD)
            for (int k = 0; k < nv; k++) LH__PREFETCH(least + t->simp[(c - LH__AHEAD) * nv + k]);
        for (int k = 0; k < nv; k++) least[t->simp[c * nv + k]] = (lh_index)c;
    }
}

static void first_incident(void *ctx, size_t lo, size_t hi)
{
    const incident *j = ctx;
    for (size_t i = lo; i < hi; i++) {
        lh_index c = j->least[0][i];
        for (int w = 1; c < 0 && w < j->ways; w++) c = j->least[w][i];
        j->least[0][i] = c;
    }
}

static lh_status incident_simplices(lh_tri *t, int nv, int threads)
{
    const int width = lh__par_width(threads, t->count);
    incident j = {t, nv, width < INCIDENT_WAYS ? width : INCIDENT_WAYS, {NULL}};
    lh_status st = LH_OK;
    for (int w = 0; w < j.ways && st == LH_OK; w++)
        if (!(j.least[w] = lh__alloc(&t->alloc, (t->n + 1) * sizeof *j.least[w]))) st = LH_ERR_NOMEM;
    if (st == LH_OK) {
        lh__par_for(j.ways, incident_share, &j);
        if (j.ways > 1) lh__par_range(threads, t->n, first_incident, &j);
        t->vsimp = j.least[0];
        j.least[0] = NULL;
    }
    for (int w = 0; w < j.ways; w++) lh__free(&t->alloc, j.least[w]);
    return st;
}

lh_status lh__dt_extract(lh__eng *b, lh_tri *t)
{
    return lh__dt_extract_as(b, t, 1);
}

lh_status lh__dt_extract_as(lh__eng *b, lh_tri *t, int sorted)
{
    /* The stamps are no longer needed: their words become the rows' positions
     * before the sort. */
    lh_index *orig = lh__tds_finish(&b->tds);
    lh_status st = orig ? extract_simplices(b, t, orig, sorted) : LH_ERR_NOMEM;
    lh__free(&b->tds.alloc, orig);
    return st == LH_OK ? incident_simplices(t, b->nv, b->threads) : st;
}

int lh_tri_dim(const lh_tri *t) { return t ? t->d : 0; }
int lh_tri_simplex_dim(const lh_tri *t) { return t ? t->frame.k : 0; }
size_t lh_tri_site_count(const lh_tri *t) { return t ? t->n : 0; }
size_t lh_tri_count(const lh_tri *t) { return t ? t->count : 0; }
const lh_index *lh_tri_simplices(const lh_tri *t) { return t ? t->simp : NULL; }
const lh_index *lh_tri_neighbors(const lh_tri *t) { return t ? t->nbr : NULL; }
size_t lh_tri_hull_count(const lh_tri *t) { return t ? t->hull_count : 0; }
const lh_index *lh_tri_hull_facets(const lh_tri *t) { return t ? t->hull : NULL; }
const lh_index *lh_tri_vertex_simplex(const lh_tri *t) { return t ? t->vsimp : NULL; }
const lh_index *lh_tri_duplicate_of(const lh_tri *t) { return t ? t->dup : NULL; }
size_t lh_tri_duplicate_count(const lh_tri *t) { return t ? t->ndup : 0; }

void lh_tri_pred_counters_get(const lh_tri *t, lh_pred_counters *out)
{
    lh_pred_counters_get(t ? t->pred : NULL, out);
}
