/*
 * qhull_model.c — the facets Qhull's formats print, from lifthull's results: the
 * Delaunay simplices with, across the convex hull, the upper hull's facets (the
 * furthest-site triangulation of the hull's vertices; with Qu the roles swap), or
 * the convex hull's facets with their neighbours.
 */
#include "cli.h"
#include "qhull.h"
#include "qhull_sides.h"

#include <stdlib.h>
#include <string.h>

/* The distinct sites on the hull (increasing), from the hull facets. */
static lh_index *hull_sites(const lh_tri *t, size_t n, size_t *count)
{
    char *on = calloc(n ? n : 1, 1);
    lh_index *list = malloc((n ? n : 1) * sizeof *list);
    if (!on || !list) {
        free(on);
        free(list);
        return NULL;
    }
    const int k = lh_tri_simplex_dim(t);
    const lh_index *h = lh_tri_hull_facets(t);
    for (size_t i = 0; i < lh_tri_hull_count(t) * (size_t)k; i++) on[h[i]] = 1;
    *count = 0;
    for (size_t i = 0; i < n; i++)
        if (on[i]) list[(*count)++] = (lh_index)i;
    free(on);
    return list;
}

/* The furthest-site triangulation of the hull's sites, in site numbering. */
static lh_status upper_hull(lh_cli_qmodel *mo)
{
    size_t h;
    lh_index *sites = hull_sites(mo->tri, mo->n, &h);
    double *x = sites ? malloc(h * (size_t)mo->d * sizeof *x) : NULL;
    lh_status st = LH_ERR_NOMEM;
    if (x) {
        for (size_t i = 0; i < h; i++) memcpy(x + i * mo->d, mo->xyz + (size_t)sites[i] * mo->d, mo->d * sizeof *x);
        lh_options opt;
        lh_options_default(&opt);
        opt.furthest_site = 1;
        st = lh_delaunay(mo->d, h, x, &opt, &mo->tri_other);
    }
    if (st == LH_OK) {
        mo->m_other = lh_tri_count(mo->tri_other);
        mo->other = malloc((mo->m_other ? mo->m_other : 1) * mo->nv * sizeof *mo->other);
        if (!mo->other) st = LH_ERR_NOMEM;
        const lh_index *s = lh_tri_simplices(mo->tri_other);
        for (size_t i = 0; mo->other && i < mo->m_other * mo->nv; i++) mo->other[i] = sites[s[i]];
    }
    free(sites);
    free(x);
    return st;
}

/* With Qu: the Delaunay triangulation of all sites is the other side. */
static lh_status lower_hull(lh_cli_qmodel *mo)
{
    lh_status st = lh_delaunay(mo->d, mo->n, mo->xyz, NULL, &mo->tri_other);
    if (st != LH_OK) return st;
    mo->m_other = lh_tri_count(mo->tri_other);
    mo->other = malloc((mo->m_other ? mo->m_other : 1) * mo->nv * sizeof *mo->other);
    if (!mo->other) return LH_ERR_NOMEM;
    memcpy(mo->other, lh_tri_simplices(mo->tri_other), mo->m_other * mo->nv * sizeof *mo->other);
    return LH_OK;
}

/* Hull sides with no upper facet across: where sites lie on a hull facet without
 * being extreme, the lifted hull has vertical facets over it, which Qhull counts
 * among its upper facets. Each such side gets one of its own (its d vertices, the
 * last slot -1), so every side has a negative id, as in Qhull. */
static lh_status vertical_facets(lh_cli_qmodel *mo)
{
    size_t extra = 0, nv = (size_t)mo->nv;
    for (size_t i = 0; i < mo->m * nv; i++) extra += mo->nbr[i] == LH_CLI_NO_SIDE;
    if (!extra) return LH_OK;
    lh_index *other = malloc((mo->m_other + extra) * nv * sizeof *other);
    if (!other) return LH_ERR_NOMEM;
    memcpy(other, mo->other, mo->m_other * nv * sizeof *other);
    free(mo->other);
    mo->other = other;
    for (size_t i = 0; i < mo->m * nv; i++) {
        if (mo->nbr[i] != LH_CLI_NO_SIDE) continue;
        lh_index *g = other + mo->m_other * nv;
        const lh_index *v = mo->vert + i / nv * nv;
        for (size_t k = 0, w = 0; k < nv; k++)
            if (k != i % nv) g[w++] = v[k];
        g[nv - 1] = -1;
        mo->nbr[i] = -(lh_index)++mo->m_other;
    }
    return LH_OK;
}

static lh_status delaunay(lh_cli_qmodel *mo, const lh_cli_qopts *o)
{
    lh_options opt;
    lh_options_default(&opt);
    opt.furthest_site = o->furthest;
    double t0 = lh_cli_seconds();
    lh_status st = lh_delaunay(mo->d, mo->n, mo->xyz, &opt, &mo->tri);
    mo->seconds = lh_cli_seconds() - t0;
    if (st != LH_OK) return st;
    mo->nv = mo->d + 1;
    mo->m = lh_tri_count(mo->tri);
    mo->vert = lh_tri_simplices(mo->tri);
    mo->dup = lh_tri_duplicate_of(mo->tri);
    mo->ndup = lh_tri_duplicate_count(mo->tri);
    mo->nbr = malloc((mo->m ? mo->m : 1) * mo->nv * sizeof *mo->nbr);
    if (!mo->nbr) return LH_ERR_NOMEM;
    memcpy(mo->nbr, lh_tri_neighbors(mo->tri), mo->m * mo->nv * sizeof *mo->nbr);
    st = o->furthest ? lower_hull(mo) : upper_hull(mo);
    if (st != LH_OK) return st;
    if (!lh_cli_pair_across(mo->nv, mo->m, mo->vert, mo->nbr, mo->m_other, mo->other,
                            lh_tri_neighbors(mo->tri_other)))
        return LH_ERR_NOMEM;
    return vertical_facets(mo);
}

static lh_status convex(lh_cli_qmodel *mo)
{
    double t0 = lh_cli_seconds();
    lh_status st = lh_convex_hull(mo->d, mo->n, mo->xyz, NULL, &mo->hull);
    mo->seconds = lh_cli_seconds() - t0;
    if (st != LH_OK) return st;
    mo->nv = mo->d;
    mo->m = lh_hull_facet_count(mo->hull);
    /* Qhull lists a hull facet's vertices with the opposite parity (seen: every
     * facet, d = 2..5): the last two exchanged. */
    mo->own_vert = malloc((mo->m ? mo->m : 1) * mo->nv * sizeof *mo->own_vert);
    if (!mo->own_vert) return LH_ERR_NOMEM;
    memcpy(mo->own_vert, lh_hull_facets(mo->hull), mo->m * mo->nv * sizeof *mo->own_vert);
    for (size_t f = 0; f < mo->m; f++) {
        lh_index *v = mo->own_vert + f * mo->nv, x = v[mo->nv - 1];
        v[mo->nv - 1] = v[mo->nv - 2];
        v[mo->nv - 2] = x;
    }
    mo->vert = mo->own_vert;
    mo->dup = lh_hull_duplicate_of(mo->hull);
    for (size_t i = 0; i < mo->n; i++) mo->ndup += mo->dup[i] != (lh_index)i;
    mo->nbr = malloc((mo->m ? mo->m : 1) * mo->nv * sizeof *mo->nbr);
    if (!mo->nbr || !lh_cli_pair_within(mo->nv, mo->m, mo->vert, mo->nbr)) return LH_ERR_NOMEM;
    return LH_OK;
}

/* Site -> facets (main, then other as -(j+1)), by counting. */
lh_status lh_cli_qmodel_incidence(lh_cli_qmodel *mo)
{
    mo->inc_off = calloc(mo->n + 1, sizeof *mo->inc_off);
    size_t total = (mo->m + mo->m_other) * mo->nv;
    mo->inc = malloc((total ? total : 1) * sizeof *mo->inc);
    if (!mo->inc_off || !mo->inc) return LH_ERR_NOMEM;
    for (size_t i = 0; i < mo->m * mo->nv; i++) mo->inc_off[mo->vert[i] + 1]++;
    for (size_t i = 0; i < mo->m_other * mo->nv; i++)
        if (mo->other[i] >= 0) mo->inc_off[mo->other[i] + 1]++; /* -1: a vertical facet's slot */
    for (size_t i = 0; i < mo->n; i++) mo->inc_off[i + 1] += mo->inc_off[i];
    lh_index *fill = malloc((mo->n ? mo->n : 1) * sizeof *fill);
    if (!fill) return LH_ERR_NOMEM;
    memcpy(fill, mo->inc_off, mo->n * sizeof *fill);
    for (size_t i = 0; i < mo->m * mo->nv; i++) mo->inc[fill[mo->vert[i]]++] = (lh_index)(i / mo->nv);
    for (size_t i = 0; i < mo->m_other * mo->nv; i++)
        if (mo->other[i] >= 0) mo->inc[fill[mo->other[i]]++] = -(lh_index)(i / mo->nv) - 1;
    free(fill);
    return LH_OK;
}

/* QGn: the sites but point g, for the hull to be built on (Qhull leaves point n
 * out of the hull). */
static lh_status leave_out(lh_cli_qmodel *mo, size_t g)
{
    const size_t d = (size_t)mo->d;
    mo->own_xyz = malloc((mo->n > 1 ? mo->n - 1 : 1) * d * sizeof *mo->own_xyz);
    if (!mo->own_xyz) return LH_ERR_NOMEM;
    memcpy(mo->own_xyz, mo->xyz, g * d * sizeof *mo->own_xyz);
    memcpy(mo->own_xyz + g * d, mo->xyz + (g + 1) * d, (mo->n - g - 1) * d * sizeof *mo->own_xyz);
    mo->excluded = (lh_index)g;
    mo->n--;
    mo->xyz = mo->own_xyz;
    return LH_OK;
}

/* After leave_out: every site index back in the input's numbering (those from g on
 * move up by one); point g is neither a vertex nor a duplicate. */
static lh_status put_back(lh_cli_qmodel *mo, const double *xyz)
{
    const lh_index g = mo->excluded;
    const size_t nv = (size_t)mo->nv;
    mo->built_n = mo->n++;
    mo->built_xyz = mo->own_xyz;
    mo->xyz = xyz;
    if (!mo->own_vert) {
        mo->own_vert = malloc((mo->m ? mo->m : 1) * nv * sizeof *mo->own_vert);
        if (!mo->own_vert) return LH_ERR_NOMEM;
        memcpy(mo->own_vert, mo->vert, mo->m * nv * sizeof *mo->own_vert);
        mo->vert = mo->own_vert;
    }
    mo->own_dup = malloc(mo->n * sizeof *mo->own_dup);
    if (!mo->own_dup) return LH_ERR_NOMEM;
    for (size_t i = 0; i < mo->m * nv; i++) mo->own_vert[i] += mo->own_vert[i] >= g;
    for (size_t i = 0; i < mo->m_other * nv; i++) mo->other[i] += mo->other[i] >= g;
    for (size_t i = 0; i + 1 < mo->n; i++)
        mo->own_dup[i + ((lh_index)i >= g)] = mo->dup[i] + (mo->dup[i] >= g);
    mo->own_dup[g] = g;
    mo->dup = mo->own_dup;
    return LH_OK;
}

int lh_cli_qmodel_build(lh_cli_qmodel *mo, const lh_cli_qopts *o, int d, size_t n,
                        const double *xyz, const char *name)
{
    memset(mo, 0, sizeof *mo);
    mo->d = d;
    mo->n = mo->built_n = n;
    mo->xyz = mo->built_xyz = xyz;
    mo->excluded = -1;
    lh_status st = lh_pred_create(NULL, &mo->pred);
    if (st == LH_OK && o->gpoint.on) st = leave_out(mo, o->gpoint.n);
    if (st == LH_OK) st = o->prog == LH_QPROG_CONVEX ? convex(mo) : delaunay(mo, o);
    if (st == LH_OK && o->gpoint.on) st = put_back(mo, xyz);
    mo->m_upper = mo->m_other;
    mo->ngood = mo->m;
    if (st == LH_OK) st = lh_cli_qmodel_incidence(mo);
    if (st == LH_OK && o->verify) {
        lh_error err;
        lh_status c = mo->tri ? lh_tri_check(mo->tri, &err) : LH_OK;
        fprintf(stderr, "lifthull %s: Tv: %s\n", o->name,
                !mo->tri     ? "the exact check is for Delaunay output (lifthull check); skipped"
                : c == LH_OK ? "the exact check passed"
                             : err.message);
        if (c != LH_OK) st = c;
    }
    if (st == LH_OK) return 1;
    if (mo->excluded >= 0 && mo->xyz != xyz) /* the hull without QGn's point failed */
        fprintf(stderr, "lifthull %s: option 'QG%s%zu' leaves point %zu out of the hull:\n", o->name,
                o->gpoint.not ? "-" : "", o->gpoint.n, o->gpoint.n);
    lh_cli_report_failure(name, d, mo->n, mo->xyz, st); /* the sites the hull was built on */
    lh_cli_qmodel_free(mo);
    return 0;
}

void lh_cli_qmodel_free(lh_cli_qmodel *mo)
{
    free(mo->nbr);
    free(mo->own_vert);
    free(mo->other);
    free(mo->inc_off);
    free(mo->inc);
    free(mo->own_dup);
    free(mo->good);
    free(mo->own_xyz);
    lh_tri_free(mo->tri);
    lh_tri_free(mo->tri_other);
    lh_hull_free(mo->hull);
    lh_pred_free(mo->pred);
    memset(mo, 0, sizeof *mo);
}
