/*
 * engine.c — the incremental driver (engine.h): set-up, initial simplex, the
 * insertion loop (insert_impl.h, generic or fixed-dimension) over the sites in
 * order; the convex hull facets from the infinite cells.
 */
#include "engine.h"

#include "lh_exact.h"

#include <string.h>

lh_status lh__eng_check_args(int d, int lo, int hi, size_t n, const double *xyz,
                             const lh_options *opt)
{
    if (d < lo || d > hi) return LH_ERR_DIMENSION;
    if (!xyz && n > 0) return LH_ERR_INVALID_ARGUMENT;
    if (n >= (size_t)LH_INDEX_MAX || n > SIZE_MAX / ((size_t)d * sizeof(double)))
        return LH_ERR_TOO_LARGE;
    if (opt && opt->alloc && (!opt->alloc->alloc || !opt->alloc->free))
        return LH_ERR_INVALID_ARGUMENT;
    return lh_coords_validate(d, n, xyz, NULL);
}

/* Everything of lh__eng_init but the predicate context. */
static void setup(lh__eng *e, const lh_allocator *alloc, int d, size_t n, const double *xyz,
                  lh_index *dup, const lh_options *opt)
{
    memset(e, 0, sizeof *e);
    lh__allocator_init(&e->alloc, alloc);
    e->d = d;
    e->nv = d + 1;
    e->n = n;
    e->xyz = xyz;
    e->dup = dup;
    e->rng = (opt ? opt->seed : LH__DEFAULT_SEED) | 1;
    double hi[LH__ENGINE_MAX_DIM]; /* the bounding box and whether every coordinate is
                                      an integer, one pass over the sites */
    size_t fractions = 0;
    for (int j = 0; j < d; j++) e->lo[j] = hi[j] = n ? xyz[j] : 0;
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < d; j++) {
            const double x = xyz[i * (size_t)d + j];
            e->lo[j] = x < e->lo[j] ? x : e->lo[j];
            hi[j] = x > hi[j] ? x : hi[j];
            fractions += lh__dbl_fraction(x);
        }
    e->integer = !fractions;
    for (int j = 0; j < d; j++) e->span[j] = hi[j] - e->lo[j]; /* rounding is monotone:
                                                                 every difference is within */
    e->threads = opt ? lh__threads(opt->threads) : 1;
    e->progress = opt ? opt->progress : NULL;
    e->progress_user = opt ? opt->progress_user : NULL;
}

lh_status lh__eng_init(lh__eng *e, const lh_allocator *alloc, int d, size_t n,
                       const double *xyz, lh_index *dup, const lh_options *opt)
{
    setup(e, alloc, d, n, xyz, dup, opt);
    return lh_pred_create(&e->alloc, &e->pred);
}

void lh__eng_init_shared(lh__eng *e, const lh_allocator *alloc, int d, size_t n,
                         const double *xyz, lh_index *dup, lh_pred *pred)
{
    setup(e, alloc, d, n, xyz, dup, NULL);
    e->pred = pred;
    e->pred_shared = 1;
}

void lh__eng_release(lh__eng *e)
{
    lh__tds_release(&e->tds);
    lh__free(&e->alloc, e->order);
    lh__free(&e->alloc, e->site_copy);
    if (!e->pred_shared) lh_pred_free(e->pred);
    e->order = NULL;
    e->site = e->site_copy = NULL;
    e->pred = NULL;
}

int lh__eng_finite(const lh__eng *e, lh_index c)
{
    return e->tds.vert[(size_t)c * e->nv] != LH__INF;
}

/* The first d+2 cells: the simplex of vertices 0..d, positively oriented, and the
 * infinite cell over each of its facets (lh__eng_make_infinite). */
static lh_status start(lh__eng *e)
{
    const int nv = e->nv;
    lh_index s[LH__ENGINE_MAX_DIM + 1] = {0}, cells[LH__ENGINE_MAX_DIM + 2];
    for (int k = 0; k < nv; k++) {
        s[k] = k;
        e->pts[k] = lh__eng_site(e, s[k]);
    }
    if (lh_orient(e->pred, e->d, e->pts) < 0) {
        lh_index x = s[0];
        s[0] = s[1];
        s[1] = x;
    }
    for (int i = 0; i <= nv; i++) {
        lh_index c = lh__tds_new_cell(&e->tds);
        if (c < 0) return LH_ERR_NOMEM;
        cells[i] = c;
        lh_index *v = e->tds.vert + (size_t)c * nv;
        if (i < nv)
            lh__eng_make_infinite(v, s, nv, i);
        else
            memcpy(v, s, (size_t)nv * sizeof *v);
    }
    lh__tds_link_all(&e->tds, cells, nv + 1);
    e->hint = cells[nv];
    return LH_OK;
}

lh_status lh__eng_insert(lh__eng *e, const lh_index *list, size_t count)
{
    return (e->insert ? e->insert : lh__eng_insert_generic)(e, 0, count, list);
}

static void copy_range(void *ctx, size_t lo, size_t hi)
{
    lh__eng *e = ctx;
    const size_t d = (size_t)e->d;
    for (size_t i = lo; i < hi; i++) {
        if (i + LH__AHEAD < hi) LH__PREFETCH(lh__eng_input(e, (size_t)e->order[i + LH__AHEAD]));
        const double *p = lh__eng_input(e, (size_t)e->order[i]);
        for (size_t j = 0; j < d; j++) e->site_copy[i * d + j] = p[j];
    }
}

/* e->site: the distinct sites in insertion order. */
static lh_status copy_sites(lh__eng *e)
{
    const size_t d = (size_t)e->d;
    e->site_copy = lh__alloc(&e->alloc, (e->norder * d + 1) * sizeof *e->site_copy);
    if (!e->site_copy) return LH_ERR_NOMEM;
    lh__par_range(e->threads, e->norder, copy_range, e);
    e->site = e->site_copy;
    return LH_OK;
}

static void restore_range(void *ctx, size_t lo, size_t hi)
{
    lh__eng *e = ctx;
    const int nv = e->nv;
    for (size_t c = lo; c < hi; c++) {
        if (lh__tds_dead(&e->tds, (lh_index)c)) continue;
        lh_index *v = e->tds.vert + c * nv;
        for (int k = 0; k < nv; k++)
            if (v[k] >= 0) v[k] = e->order[v[k]];
    }
}

/* Vertex v becomes the caller's index order[v]; the copy of the sites goes. */
static void restore_indices(lh__eng *e)
{
    lh__par_range(e->threads, (size_t)e->tds.top, restore_range, e);
    lh__free(&e->alloc, e->site_copy);
    e->site = e->site_copy = NULL;
}

/* Every site after the initial simplex, in order, with a progress report every
 * 2^16 sites when asked (one thread). */
static lh_status insert_all(lh__eng *e)
{
    lh__insert_fn insert = e->insert ? e->insert : lh__eng_insert_generic;
    const size_t chunk = e->progress ? (size_t)1 << 16 : e->norder;
    lh_status st = LH_OK;
    for (size_t at = (size_t)e->nv; at < e->norder && st == LH_OK; at += chunk) {
        size_t k = e->norder - at < chunk ? e->norder - at : chunk;
        st = insert(e, at, k, NULL);
        if (st == LH_OK && e->progress) e->progress(e->progress_user, at + k, e->norder);
    }
    return st;
}

lh_status lh__eng_build(lh__eng *e, lh_index cells_hint, int *affdim)
{
    lh_status st = lh__eng_order(e);
    if (st != LH_OK) return st;
    *affdim = lh__eng_initial_simplex(e);
    if (*affdim < e->d) return LH_ERR_DEGENERATE;
    if ((st = copy_sites(e)) != LH_OK) return st;
    const int par = e->threads > 1 && e->insert_par;
    if (par && cells_hint < LH_INDEX_MAX / 2) /* the phases' blocks and margins: room, not memory, as */
        cells_hint += cells_hint / 16;        /* pages are touched only when used */
    if ((st = lh__tds_init(&e->tds, &e->alloc, e->nv, cells_hint)) != LH_OK) return st;
    if (!e->dbg.hashed_ridges) lh__tds_vertex_bound(&e->tds, e->norder + 1);
    if ((st = start(e)) != LH_OK) return st;
    st = par ? lh__eng_insert_parallel(e, (size_t)e->nv) : insert_all(e);
    if (st == LH_OK) restore_indices(e);
    return st;
}

lh_status lh__eng_hull_facets(lh__eng *e, lh_index first, lh_index **out, size_t *count)
{
    const int nv = e->nv, d = e->d;
    size_t h = 0;
    for (lh_index c = first; c < e->tds.top; c++)
        if (!lh__tds_dead(&e->tds, c) && !lh__eng_finite(e, c)) h++;
    lh_index *raw = lh__alloc(&e->alloc, (h * d + 1) * sizeof *raw);
    lh_index *facets = lh__alloc(&e->alloc, (h * d + 1) * sizeof *facets);
    lh_index *order = lh__alloc(&e->alloc, (h + 1) * sizeof *order);
    lh_status st = raw && facets && order ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        size_t f = 0;
        for (lh_index c = first; c < e->tds.top; c++) {
            if (lh__tds_dead(&e->tds, c) || lh__eng_finite(e, c)) continue;
            const lh_index *v = e->tds.vert + (size_t)c * nv;
            lh_index *o = raw + f * d;
            for (int k = 1; k < nv; k++) o[k - 1] = v[k];
            /* Moving the outside point from position 0 (LH__INF's) to the end takes
             * d exchanges; compensate an odd number with one more. */
            if (d & 1) {
                lh_index x = o[0];
                o[0] = o[1];
                o[1] = x;
            }
            lh__canonical(o, d);
            f++;
        }
        if (!lh__sort_tuples(&e->alloc, raw, d, h, e->n, facets, order)) st = LH_ERR_NOMEM;
    }
    lh__free(&e->alloc, raw);
    lh__free(&e->alloc, order);
    if (st != LH_OK) {
        lh__free(&e->alloc, facets);
        return st;
    }
    *out = facets;
    *count = h;
    return LH_OK;
}
