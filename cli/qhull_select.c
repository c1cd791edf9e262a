/*
 * qhull_select.c — Qhull's print filters for qconvex, qdelaunay and qvoronoi (Qhull's manual,
 * "Print options"): Pdk:n prints the facets whose unit normal has coordinate k
 * >= n, PDk:n those with <= n (n 0 when left out; several combine, all must hold;
 * when no facet meets them, the closest one, as Qhull);
 * QGn keeps the facets visible from point n (left out of the hull, as Qhull does;
 * QG-n: those not visible), QVn those with vertex n (QV-n: without); PAn makes the
 * n largest (by area; a Delaunay facet's is its simplex's volume) of the facets kept
 * the good ones. The good facets are printed (Pg) unless PG asks for their
 * neighbours that are not good. The normal is qconvex's outward facet normal, or qdelaunay's
 * lifted one with Qhull's Qbb scaling of the lifted coordinate (lower facets point
 * down). The facets a filter drops join the other facets, so they keep negative ids
 * in Fn and FN as Qhull's unprinted ones do.
 */
#include "qhull.h"
#include "qhull_print.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void lh_cli_qlifted_normal(const lh_cli_qmodel *mo, lh_cli_qlift s, const lh_index *v, int up,
                           double *n)
{
    const int d = mo->d;
    double x[LH_DELAUNAY_MAX_DIM + 1][LH_DELAUNAY_MAX_DIM + 1], off;
    const double *p[LH_DELAUNAY_MAX_DIM + 1] = {0};
    for (int k = 0; k <= d; k++) {
        size_t i = (size_t)v[k];
        memcpy(x[k], mo->xyz + i * d, d * sizeof(double));
        x[k][d] = lh_cli_qlifted(mo, s, i);
        p[k] = x[k];
    }
    if (!lh_hyperplane(mo->pred, d + 1, p, n, &off)) /* d + 1 > LH_ORIENT_MAX_DIM */
        for (int j = 0; j <= d; j++) n[j] = 0;
    if ((n[d] > 0) != up)
        for (int j = 0; j <= d; j++) n[j] = -n[j];
}

void lh_cli_qfacet_normal(const lh_cli_qmodel *mo, const lh_cli_qopts *o, lh_cli_qlift s,
                          size_t t, double *n)
{
    double off;
    int e;
    if (o->prog == LH_QPROG_CONVEX) lh_cli_qfacet_plane(mo, t, n, &off, &e);
    else lh_cli_qlifted_normal(mo, s, mo->vert + t * mo->nv, o->furthest, n);
}

/* keep[t] &= every Pdk / PDk condition. */
static int normal_filters(const lh_cli_qmodel *mo, const lh_cli_qopts *o, char *keep)
{
    const int dims = mo->d + (o->prog != LH_QPROG_CONVEX);
    for (int i = 0; i < o->npd; i++)
        if (o->pd[i].k >= dims) {
            fprintf(stderr, "lifthull %s: option 'P%c%d': the facets' normals have coordinates "
                    "0..%d\n", o->name, o->pd[i].ge ? 'd' : 'D', o->pd[i].k, dims - 1);
            return -1;
        }
    if (o->npd && dims > LH_ORIENT_MAX_DIM) {
        fprintf(stderr, "lifthull %s: options 'Pdk' and 'PDk' need at most %d-d facet normals\n",
                o->name, LH_ORIENT_MAX_DIM);
        return -1;
    }
    lh_cli_qlift s = o->prog == LH_QPROG_CONVEX ? (lh_cli_qlift){0, 1, 0} : lh_cli_qlift_scale(mo);
    size_t left = 0, closest = mo->m;
    double best = INFINITY;
    for (size_t t = 0; t < mo->m && o->npd; t++) {
        if (!keep[t]) continue;
        double n[LH_DELAUNAY_MAX_DIM + 1], far = 0;
        lh_cli_qfacet_normal(mo, o, s, t, n);
        for (int i = 0; i < o->npd; i++) {
            double c = n[o->pd[i].k];
            if (o->pd[i].ge ? !(c >= o->pd[i].at) : !(c <= o->pd[i].at)) keep[t] = 0;
            far += fabs(o->pd[i].at - c);
        }
        left += keep[t] != 0;
        if (!keep[t] && far < best) best = far, closest = t;
    }
    /* Qhull (qh_findgood): when no facet meets the bounds, the one closest to them
     * (the least sum of |n - bound|, the first of equal ones) is the good one */
    if (!left && closest < mo->m) keep[closest] = 1;
    return 1;
}

typedef struct sized {
    double area;
    size_t t;
} sized;

static int larger_first(const void *a, const void *b)
{
    const sized *x = a, *y = b;
    if (x->area != y->area) return x->area < y->area ? 1 : -1;
    return (x->t > y->t) - (x->t < y->t);
}

/* QGn: whether point g sees facet v: qconvex, g strictly outside the facet's
 * hyperplane (the model lists a hull facet with its last two vertices exchanged:
 * orient_d < 0 outside); qdelaunay, g's lifted point strictly below the lifted
 * simplex, i.e. g strictly inside its circumsphere (with Qu: strictly outside). The
 * lifted coordinate's scaling (Qbb) is affine and increasing: it changes no answer. */
static int visible(const lh_cli_qmodel *mo, const lh_cli_qopts *o, const lh_index *v, size_t g)
{
    const int d = mo->d;
    const double *p[LH_DELAUNAY_MAX_DIM + 2] = {0};
    for (int k = 0; k < mo->nv; k++) p[k] = mo->xyz + (size_t)v[k] * d;
    p[mo->nv] = mo->xyz + g * d;
    if (o->prog == LH_QPROG_CONVEX) return lh_orient(mo->pred, d, p) < 0;
    int side = lh_insphere(mo->pred, d, p) * lh_orient(mo->pred, d, p); /* < 0: inside */
    return o->furthest ? side > 0 : side < 0;
}

/* keep[t] &= QGn (facet t visible from point n; QG-n: not visible), or (vertex) QVn
 * (n one of its vertices; QV-n: not one). Qhull applies QVn after Pdk and its
 * closest facet (qh_findgood_all): so does lh_cli_qselect. */
static void point_filters(const lh_cli_qmodel *mo, const lh_cli_qopts *o, char *keep, int vertex)
{
    for (size_t t = 0; t < mo->m; t++) {
        const lh_index *v = mo->vert + t * mo->nv;
        if (vertex && o->gvertex.on) {
            int has = 0;
            for (int k = 0; k < mo->nv; k++) has |= v[k] == (lh_index)o->gvertex.n;
            if (has == o->gvertex.not) keep[t] = 0;
        }
        if (!vertex && o->gpoint.on && visible(mo, o, v, o->gpoint.n) == o->gpoint.not) keep[t] = 0;
    }
}

/* PAn, Pg, PG: the good facets are those kept so far (PAn: the n largest of them);
 * keep = the good ones, or (PG) their neighbours that are not good; mo->ngood
 * counts the good ones. */
static int good_filters(lh_cli_qmodel *mo, const lh_cli_qopts *o, char *keep)
{
    double *area = malloc((mo->m ? mo->m : 1) * sizeof *area);
    sized *order = malloc((mo->m ? mo->m : 1) * sizeof *order);
    char *good = malloc(mo->m ? mo->m : 1);
    int ok = area && order && good &&
             (!o->largest ||
              lh_simplex_measures(mo->d, mo->nv - 1, mo->xyz, mo->n, mo->m, mo->vert, area, NULL) == LH_OK);
    if (ok) {
        memcpy(good, keep, mo->m);
        if (o->largest) {
            size_t c = 0;
            for (size_t t = 0; t < mo->m; t++)
                if (keep[t]) order[c++] = (sized){area[t], t};
            qsort(order, c, sizeof *order, larger_first);
            memset(good, 0, mo->m);
            for (size_t i = 0; i < c && i < o->largest; i++) good[order[i].t] = 1;
        }
        mo->ngood = 0;
        for (size_t t = 0; t < mo->m; t++) mo->ngood += good[t] != 0;
        for (size_t t = 0; t < mo->m; t++) keep[t] = good[t] && !o->good_nbrs;
        for (size_t t = 0; t < mo->m && o->good_nbrs; t++)
            for (int k = 0; good[t] && k < mo->nv; k++) {
                lh_index u = mo->nbr[t * mo->nv + k];
                if (u >= 0 && !good[u]) keep[u] = 1;
            }
    }
    free(area);
    free(order);
    free(good);
    return ok;
}

/* Moves the facets not kept to the end of the other facets and renumbers. */
static int regroup(lh_cli_qmodel *mo, const char *keep)
{
    const size_t nv = (size_t)mo->nv;
    size_t kept = 0;
    for (size_t t = 0; t < mo->m; t++) kept += keep[t] != 0;
    size_t dropped = mo->m - kept, mo2 = mo->m_other + dropped;
    lh_index *id = malloc((mo->m ? mo->m : 1) * sizeof *id);
    lh_index *vert = malloc((kept ? kept : 1) * nv * sizeof *vert);
    lh_index *nbr = malloc((kept ? kept : 1) * nv * sizeof *nbr);
    lh_index *other = malloc((mo2 ? mo2 : 1) * nv * sizeof *other);
    if (!id || !vert || !nbr || !other) {
        free(id), free(vert), free(nbr), free(other);
        return 0;
    }
    if (mo->m_other) memcpy(other, mo->other, mo->m_other * nv * sizeof *other);
    for (size_t t = 0, a = 0, b = mo->m_other; t < mo->m; t++) {
        lh_index *to = keep[t] ? vert + a * nv : other + b * nv;
        memcpy(to, mo->vert + t * nv, nv * sizeof *to);
        id[t] = keep[t] ? (lh_index)a++ : -(lh_index)++b;
    }
    for (size_t t = 0, a = 0; t < mo->m; t++) {
        if (!keep[t]) continue;
        for (size_t k = 0; k < nv; k++) {
            lh_index u = mo->nbr[t * nv + k];
            nbr[a * nv + k] = u >= 0 ? id[u] : u;
        }
        a++;
    }
    free(id);
    free(mo->own_vert);
    free(mo->nbr);
    free(mo->other);
    free(mo->inc_off);
    free(mo->inc);
    mo->inc_off = mo->inc = NULL;
    mo->vert = mo->own_vert = vert;
    mo->nbr = nbr;
    mo->other = other;
    mo->m = kept;
    mo->m_other = mo2;
    return lh_cli_qmodel_incidence(mo) == LH_OK;
}

int lh_cli_qselecting(const lh_cli_qopts *o)
{
    return o->npd || o->largest || o->good_nbrs || o->gpoint.on || o->gvertex.on;
}

int lh_cli_qselect(lh_cli_qmodel *mo, const lh_cli_qopts *o, lh_cli_qmodel *all)
{
    mo->ngood = mo->m;
    if (!lh_cli_qselecting(o)) return 1; /* Pg alone: every facet is good */
    char *keep = malloc(mo->m ? mo->m : 1);
    if (!keep) goto nomem;
    memset(keep, 1, mo->m);
    point_filters(mo, o, keep, 0);
    int r = normal_filters(mo, o, keep);
    if (r > 0) {
        point_filters(mo, o, keep, 1);
        r = good_filters(mo, o, keep);
    }
    if (r > 0 && all) {
        all->good = malloc(mo->m ? mo->m : 1);
        r = all->good != NULL;
        if (r) memcpy(all->good, keep, mo->m);
        mo->all = all;
    }
    if (r > 0) r = regroup(mo, keep);
    free(keep);
    if (r >= 0 && !r) goto nomem;
    return r;
nomem:
    fprintf(stderr, "lifthull %s: out of memory\n", o->name);
    return 0;
}
