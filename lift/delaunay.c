/*
 * delaunay.c — lh_delaunay: sites merged and ordered (order.c), an initial simplex,
 * then each site inserted by walking to a cell in conflict and handing the cavity
 * to hull/'s lh__tds_insert; output in canonical form (output.c).
 *
 * Conflict (the lifted view, ARCHITECTURE section 1):
 *   - a finite cell t conflicts with q when q is strictly inside its circumsphere,
 *     insphere_sos(t, q) < 0: the lifted facet t+ is visible from q+. The perturbation
 *     acts on the lifted coordinates first (lifthull.h), so cospherical sites are
 *     split consistently and no flat simplex can appear;
 *   - an infinite cell (hull facet f, infinity) conflicts when q is strictly beyond f,
 *     orient_d(f -> q) > 0; when q lies on f's hyperplane it conflicts exactly when
 *     the finite cell across f does — q is then inside f's circumsphere within the
 *     hyperplane (CGAL's rule), so sites on the hull boundary become vertices
 *     without flat simplices.
 * Location: a remembering stochastic visibility walk (Devillers, Pion & Teillaud,
 * "Walking in a triangulation", IJFCS 13(2), 2002) from the last new cell; it stops
 * in the closed simplex containing q or in an infinite cell whose facet q sees.
 */
#include "dt.h"
#include "lh_exact.h"

#include <string.h>

_Static_assert(LH_DELAUNAY_MAX_DIM <= LH_INSPHERE_MAX_DIM, "Delaunay in R^d needs insphere_d");

void lh_options_default(lh_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    opt->seed = 0x5eed;
}

static int inf_index(const int32_t *v, int nv)
{
    for (int k = 0; k < nv; k++)
        if (v[k] == LH__INF) return k;
    return -1;
}

static int finite_conflict(lh__dt *b, int32_t c)
{
    const int32_t *v = b->tds.vert + (size_t)c * b->nv;
    for (int k = 0; k < b->nv; k++) b->pts[k] = lh__dt_site(b, v[k]);
    b->pts[b->nv] = lh__dt_site(b, b->q);
    return lh__insphere_sos_fast(b->pred, b->d, b->pts) < 0;
}

static int conflict(void *user, int32_t c)
{
    lh__dt *b = user;
    const int32_t *v = b->tds.vert + (size_t)c * b->nv;
    int inf = inf_index(v, b->nv);
    if (inf < 0) return finite_conflict(b, c);
    for (int k = 0; k < b->nv; k++) b->pts[k] = k == inf ? lh__dt_site(b, b->q) : lh__dt_site(b, v[k]);
    int o = lh__orient_fast(b->pred, b->d, b->pts);
    if (o) return o > 0;
    return finite_conflict(b, b->tds.nbr[(size_t)c * b->nv + inf]);
}

/* orient_d of cell c with its vertex k replaced by q (c finite). */
static int orient_replaced(lh__dt *b, const int32_t *v, int k)
{
    for (int j = 0; j < b->nv; j++) b->pts[j] = lh__dt_site(b, j == k ? b->q : v[j]);
    return lh__orient_fast(b->pred, b->d, b->pts);
}

static int32_t any_conflict_cell(lh__dt *b)
{
    for (int32_t c = 0; c < b->tds.top; c++)
        if (!lh__tds_dead(&b->tds, c) && conflict(b, c)) return c;
    return -1;
}

static int32_t locate(lh__dt *b)
{
    const int nv = b->nv;
    int32_t c = b->hint, prev = -1;
    size_t limit = 64 + 8 * (size_t)b->tds.live;
    for (size_t step = 0; step < limit; step++) {
        const int32_t *v = b->tds.vert + (size_t)c * nv;
        int inf = inf_index(v, nv);
        if (inf >= 0) {
            if (prev >= 0 || conflict(b, c)) return c; /* entered across its facet */
            prev = c;
            c = b->tds.nbr[(size_t)c * nv + inf];
            continue;
        }
        int s = (int)(lh__rng_next(&b->rng) % (uint64_t)nv), moved = 0;
        for (int t = 0; t < nv && !moved; t++) {
            int k = (s + t) % nv;
            int32_t n = b->tds.nbr[(size_t)c * nv + k];
            if (n == prev || orient_replaced(b, v, k) >= 0) continue;
            prev = c;
            c = n;
            moved = 1;
        }
        if (!moved) return c;
    }
    return any_conflict_cell(b); /* not reached in practice; bounded either way */
}

/* The first d+2 cells: the simplex order[0..d], positively oriented, and one
 * infinite cell per facet, oriented by exchanging two of its finite vertices. */
static lh_status start(lh__dt *b)
{
    const int nv = b->nv;
    int32_t s[LH_DELAUNAY_MAX_DIM + 1] = {0}, cells[LH_DELAUNAY_MAX_DIM + 2];
    for (int k = 0; k < nv; k++) {
        s[k] = b->order[k];
        b->pts[k] = lh__dt_site(b, s[k]);
    }
    if (lh_orient(b->pred, b->d, b->pts) < 0) {
        int32_t x = s[0];
        s[0] = s[1];
        s[1] = x;
    }
    for (int i = 0; i <= nv; i++) {
        int32_t c = lh__tds_new_cell(&b->tds);
        if (c < 0) return LH_ERR_NOMEM;
        cells[i] = c;
        int32_t *v = b->tds.vert + (size_t)c * nv;
        memcpy(v, s, (size_t)nv * sizeof *v);
        if (i < nv) { /* infinite cell replacing vertex i */
            v[i] = LH__INF;
            int a = i == 0 ? 1 : 0, z = i == nv - 1 ? nv - 2 : nv - 1;
            int32_t x = v[a];
            v[a] = v[z];
            v[z] = x;
        }
    }
    lh__tds_link_all(&b->tds, cells, nv + 1);
    for (int k = 0; k < nv; k++) b->v2c[s[k]] = cells[nv];
    b->hint = cells[nv];
    return LH_OK;
}

static lh_status insert_all(lh__dt *b)
{
    for (size_t i = (size_t)b->nv; i < b->norder; i++) {
        b->q = b->order[i];
        int32_t c = locate(b);
        if (c < 0) return LH_ERR_INTERNAL;
        lh_status st = lh__tds_insert(&b->tds, c, b->q, conflict, b);
        if (st != LH_OK) return st;
        for (size_t f = 0; f < b->tds.nbound; f++) {
            int32_t N = b->tds.fresh[f];
            const int32_t *v = b->tds.vert + (size_t)N * b->nv;
            for (int k = 0; k < b->nv; k++)
                if (v[k] != LH__INF) b->v2c[v[k]] = N;
        }
        b->hint = b->tds.fresh[0];
    }
    return LH_OK;
}

/* Cells (finite and infinite) expected for n uniform sites: about 2n, 6.8n, 31n,
 * 161n in 2D..5D (measured), with 10% room; higher dimensions start smaller and
 * grow by doubling. */
static int32_t expected_cells(int d, size_t n)
{
    static const double per_site[LH_DELAUNAY_MAX_DIM + 1] = {0, 0, 2.2, 7.5, 34, 180, 400, 400, 400};
    double c = per_site[d] * (double)n + 256;
    return c > INT32_MAX / 2 ? INT32_MAX / 2 : (int32_t)c;
}

static lh_status check_args(int d, size_t n, const double *xyz, const lh_options *opt)
{
    if (d < LH_DELAUNAY_MIN_DIM || d > LH_DELAUNAY_MAX_DIM) return LH_ERR_DIMENSION;
    if (!xyz && n > 0) return LH_ERR_INVALID_ARGUMENT;
    if (n >= (size_t)INT32_MAX || n > SIZE_MAX / ((size_t)d * sizeof(double)))
        return LH_ERR_TOO_LARGE;
    if (opt && opt->alloc && (!opt->alloc->alloc || !opt->alloc->free))
        return LH_ERR_INVALID_ARGUMENT;
    return lh_coords_validate(d, n, xyz, NULL);
}

void lh_tri_free(lh_tri *t)
{
    if (!t) return;
    lh_allocator a = t->alloc;
    lh__free(&a, t->xyz);
    lh__free(&a, t->dup);
    lh__free(&a, t->simp);
    lh__free(&a, t->nbr);
    lh__free(&a, t->hull);
    lh__free(&a, t->vsimp);
    lh__free(&a, t);
}

static lh_status new_handle(int d, size_t n, const double *xyz, const lh_options *opt,
                            lh_tri **out)
{
    lh_allocator a;
    lh__allocator_init(&a, opt ? opt->alloc : NULL);
    lh_tri *t = lh__alloc(&a, sizeof *t);
    if (!t) return LH_ERR_NOMEM;
    memset(t, 0, sizeof *t);
    t->alloc = a;
    t->d = d;
    t->n = n;
    t->xyz = lh__alloc(&a, n * (size_t)d * sizeof *t->xyz);
    t->dup = lh__alloc(&a, n * sizeof *t->dup);
    if (!t->xyz || !t->dup) {
        lh_tri_free(t);
        return LH_ERR_NOMEM;
    }
    if (n) memcpy(t->xyz, xyz, n * (size_t)d * sizeof *t->xyz);
    *out = t;
    return LH_OK;
}

static void builder_release(lh__dt *b)
{
    lh__tds_release(&b->tds);
    lh__free(&b->t->alloc, b->order);
    lh__free(&b->t->alloc, b->v2c);
    lh_pred_free(b->pred);
}

/* Everything up to the initial simplex; *affdim gets the sites' affine dimension. */
static lh_status prepare(lh__dt *b, int *affdim)
{
    lh_status st = lh_pred_create(&b->t->alloc, &b->pred);
    if (st != LH_OK) return st;
    if ((st = lh__dt_order_sites(b)) != LH_OK) return st;
    *affdim = lh__dt_initial_simplex(b);
    return LH_OK;
}

lh_status lh_delaunay(int d, size_t n, const double *xyz, const lh_options *opt,
                      lh_tri **out)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    *out = NULL;
    lh_status st = check_args(d, n, xyz, opt);
    if (st != LH_OK) return st;
    lh__dt b;
    memset(&b, 0, sizeof b);
    b.d = d;
    b.nv = d + 1;
    b.rng = (opt ? opt->seed : 0x5eed) | 1;
    if ((st = new_handle(d, n, xyz, opt, &b.t)) != LH_OK) return st;
    int affdim = -1;
    st = prepare(&b, &affdim);
    if (st == LH_OK && affdim < d) st = LH_ERR_DEGENERATE;
    if (st == LH_OK) {
        st = lh__tds_init(&b.tds, &b.t->alloc, b.nv, expected_cells(d, b.norder));
    }
    if (st == LH_OK) {
        b.v2c = lh__alloc(&b.t->alloc, n * sizeof *b.v2c);
        st = b.v2c ? LH_OK : LH_ERR_NOMEM;
    }
    if (st == LH_OK) st = start(&b);
    if (st == LH_OK) st = insert_all(&b);
    if (st == LH_OK) st = lh__dt_extract(&b);
    builder_release(&b);
    if (st != LH_OK) {
        lh_tri_free(b.t);
        return st;
    }
    *out = b.t;
    return LH_OK;
}

lh_status lh_affine_dim(int d, size_t n, const double *xyz, int *dim)
{
    if (!dim) return LH_ERR_INVALID_ARGUMENT;
    lh_status st = check_args(d, n, xyz, NULL);
    if (st != LH_OK) return st;
    lh__dt b;
    memset(&b, 0, sizeof b);
    b.d = d;
    b.nv = d + 1;
    b.rng = 0x5eed;
    if ((st = new_handle(d, n, xyz, NULL, &b.t)) != LH_OK) return st;
    st = lh_pred_create(NULL, &b.pred);
    if (st == LH_OK) st = lh__dt_order_sites(&b);
    if (st == LH_OK) *dim = lh__dt_initial_simplex(&b);
    builder_release(&b);
    lh_tri_free(b.t);
    return st;
}
