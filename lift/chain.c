/*
 * chain.c — the Delaunay triangulation of collinear sites within their line
 * (lh_options.affine_hull with affine dimension 1): the segments between
 * consecutive distinct sites along the line; furthest-site, the one segment between
 * the two ends (the upper hull of sites lifted to a parabola). The order along the
 * line is the order of one coordinate J[0] on which the sites differ, compared
 * exactly. Segments are oriented along the line (orient_1 of the projections
 * positive), which is their canonical form; the two hull facets are the end sites.
 */
#include "dt.h"
#include "lh_sort.h"

#include <string.h>

typedef struct line_ctx {
    const double *xyz;
    int d, j;
} line_ctx;

/* Along the line, then by index (so an exact duplicate follows its first site). */
static int line_cmp(const void *vctx, lh_index a, lh_index b)
{
    const line_ctx *c = vctx;
    double x = c->xyz[(size_t)a * c->d + c->j], y = c->xyz[(size_t)b * c->d + c->j];
    if (x != y) return x < y ? -1 : 1;
    return (a > b) - (a < b);
}

/* The distinct sites in line order into seq (returns their number); t->dup. */
static size_t sort_along(lh_tri *t, lh_index *seq, lh_index *tmp)
{
    line_ctx c = {t->xyz, t->d, t->frame.J[0]};
    for (size_t i = 0; i < t->n; i++) seq[i] = (lh_index)i;
    lh__sort_idx(seq, tmp, t->n, line_cmp, &c);
    size_t m = 0;
    t->ndup = 0;
    for (size_t i = 0; i < t->n; i++) {
        lh_index s = seq[i];
        if (m && t->xyz[(size_t)seq[m - 1] * t->d + c.j] == t->xyz[(size_t)s * t->d + c.j]) {
            t->dup[s] = seq[m - 1]; /* the same point of the line, a smaller index */
            t->ndup++;
            continue;
        }
        t->dup[s] = s;
        seq[m++] = s;
    }
    return m;
}

/* Segments seq[i], seq[i+1] (or, furthest-site, the ends), sorted, with neighbours,
 * hull facets and incident simplices. */
static lh_status write_chain(lh_tri *t, const lh_index *seq, size_t m, lh_index *raw, lh_index *order)
{
    size_t count = t->furthest ? 1 : m - 1;
    for (size_t i = 0; i < count; i++) {
        raw[2 * i] = seq[i];
        raw[2 * i + 1] = t->furthest ? seq[m - 1] : seq[i + 1];
    }
    t->count = count;
    t->simp = lh__alloc(&t->alloc, (2 * count + 1) * sizeof *t->simp);
    t->nbr = lh__alloc(&t->alloc, (2 * count + 1) * sizeof *t->nbr);
    t->hull = lh__alloc(&t->alloc, 3 * sizeof *t->hull);
    t->vsimp = lh__alloc(&t->alloc, (t->n + 1) * sizeof *t->vsimp);
    if (!t->simp || !t->nbr || !t->hull || !t->vsimp) return LH_ERR_NOMEM;
    if (!lh__sort_tuples(&t->alloc, raw, 2, count, t->n, t->simp, order)) return LH_ERR_NOMEM;
    lh_index *pos = raw; /* segment i along the line is output simplex pos[i] */
    for (size_t s = 0; s < count; s++) pos[order[s]] = (lh_index)s;
    for (size_t i = 0; i < count; i++) {
        t->nbr[2 * (size_t)pos[i]] = i + 1 < count ? pos[i + 1] : -1; /* opposite the start */
        t->nbr[2 * (size_t)pos[i] + 1] = i > 0 ? pos[i - 1] : -1;   /* opposite the end */
    }
    t->hull_count = 2;
    t->hull[0] = seq[0] < seq[m - 1] ? seq[0] : seq[m - 1];
    t->hull[1] = seq[0] < seq[m - 1] ? seq[m - 1] : seq[0];
    for (size_t i = 0; i < t->n; i++) t->vsimp[i] = -1;
    for (size_t s = count; s-- > 0;)
        for (int k = 0; k < 2; k++) t->vsimp[t->simp[2 * s + k]] = (lh_index)s;
    return LH_OK;
}

lh_status lh__dt_chain(lh_tri *t)
{
    lh_index *seq = lh__alloc(&t->alloc, (t->n + 1) * sizeof *seq);
    lh_index *tmp = lh__alloc(&t->alloc, (t->n + 1) * sizeof *tmp);
    lh_index *raw = lh__alloc(&t->alloc, (2 * t->n + 1) * sizeof *raw);
    lh_status st = seq && tmp && raw ? lh_pred_create(&t->alloc, &t->pred) : LH_ERR_NOMEM;
    if (st == LH_OK) {
        size_t m = sort_along(t, seq, tmp);
        st = m >= 2 ? write_chain(t, seq, m, raw, tmp) : LH_ERR_INTERNAL;
    }
    lh__free(&t->alloc, seq);
    lh__free(&t->alloc, tmp);
    lh__free(&t->alloc, raw);
    return st;
}
