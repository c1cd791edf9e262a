/*
 * interpolate.c — lh_tri_interpolate: piecewise-linear interpolation over the
 * simplices (scipy's LinearNDInterpolator does the same over Qhull's), Sibson's
 * natural neighbours (natural.c), or the nearest site's value (nearest.c). Each
 * query starts its walk where the previous one ended.
 */
#include "dt.h"
#include "lh_alloc.h"

#include <math.h>

/* The representative of site i (duplicates carry no values of their own). */
static const double *values_of(const lh_tri *t, int channels, const double *values, lh_index i)
{
    return values + (size_t)t->dup[i] * channels;
}

static void fill_nan(double *out, int channels)
{
    for (int c = 0; c < channels; c++) out[c] = NAN;
}

/* out = sum w_i * values(site_i). */
static void combine(const lh_tri *t, int channels, const double *values, size_t m,
                    const lh_index *sites, const double *w, double *out)
{
    for (int c = 0; c < channels; c++) out[c] = 0;
    for (size_t i = 0; i < m; i++) {
        const double *v = values_of(t, channels, values, sites[i]);
        for (int c = 0; c < channels; c++) out[c] += w[i] * v[c];
    }
}

static lh_status linear(lh_tri *t, const double *q, int channels, const double *values,
                        lh_index *hint, double *out)
{
    lh_location loc;
    lh_status st = lh_tri_locate(t, q, *hint, &loc);
    if (st != LH_OK) return st;
    if (loc.simplex < 0) {
        fill_nan(out, channels);
        return LH_OK;
    }
    *hint = loc.simplex;
    const int nv = t->frame.k + 1;
    combine(t, channels, values, (size_t)nv, t->simp + (size_t)loc.simplex * nv, loc.bary, out);
    return LH_OK;
}

static lh_status nearest(lh_tri *t, const double *q, int channels, const double *values,
                         lh_index *hint, double *out)
{
    lh_index s;
    lh_status st = lh_tri_nearest(t, q, *hint, &s);
    if (st != LH_OK) return st;
    *hint = t->vsimp[s];
    const double w = 1;
    combine(t, channels, values, 1, &s, &w, out);
    return LH_OK;
}

/* Sibson's coordinates into a buffer that grows to the number of natural
 * neighbours. */
typedef struct nbuf {
    size_t cap;
    lh_index *site;
    double *w;
} nbuf;

static lh_status natural(lh_tri *t, const double *q, int channels, const double *values,
                         lh_index *hint, nbuf *b, double *out)
{
    size_t count;
    lh_status st;
    while ((st = lh_tri_natural_coords(t, q, *hint, b->cap, b->site, b->w, &count)) ==
           LH_ERR_BUFFER_TOO_SMALL) {
        size_t cap = 2 * count;
        lh__free(&t->alloc, b->site);
        lh__free(&t->alloc, b->w);
        b->site = lh__alloc(&t->alloc, cap * sizeof *b->site);
        b->w = lh__alloc(&t->alloc, cap * sizeof *b->w);
        b->cap = b->site && b->w ? cap : 0;
        if (!b->cap) return LH_ERR_NOMEM;
    }
    if (st == LH_ERR_INVALID_ARGUMENT && count == 0 && lh_coords_validate(t->d, 1, q, NULL) == LH_OK) {
        fill_nan(out, channels); /* outside the hull */
        return LH_OK;
    }
    if (st != LH_OK) return st;
    *hint = t->vsimp[t->dup[b->site[0]]];
    combine(t, channels, values, count, b->site, b->w, out);
    return LH_OK;
}

lh_status lh_tri_interpolate(lh_tri *t, lh_interp_method method, size_t m, const double *q,
                             int channels, const double *values, double *out)
{
    if (!t || (m && (!q || !out)) || !values || channels < 1) return LH_ERR_INVALID_ARGUMENT;
    if (method != LH_INTERP_LINEAR && method != LH_INTERP_NATURAL && method != LH_INTERP_NEAREST)
        return LH_ERR_INVALID_ARGUMENT;
    if (method != LH_INTERP_LINEAR && t->furthest) return LH_ERR_INVALID_ARGUMENT;
    if (method == LH_INTERP_NATURAL && (t->d > 3 || t->frame.k != t->d)) return LH_ERR_DIMENSION;
    lh_index hint = -1;
    nbuf b = {0, NULL, NULL};
    lh_status st = LH_OK;
    for (size_t i = 0; i < m && st == LH_OK; i++) {
        const double *qi = q + i * (size_t)t->d;
        double *oi = out + i * (size_t)channels;
        if (method == LH_INTERP_LINEAR)
            st = linear(t, qi, channels, values, &hint, oi);
        else if (method == LH_INTERP_NEAREST)
            st = nearest(t, qi, channels, values, &hint, oi);
        else
            st = natural(t, qi, channels, values, &hint, &b, oi);
    }
    lh__free(&t->alloc, b.site);
    lh__free(&t->alloc, b.w);
    return st;
}
