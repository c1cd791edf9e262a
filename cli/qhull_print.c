/*
 * qhull_print.c — Qhull's text formats for facets: i, Fv, Fn, FN, o, p, s, Fx, and
 * qconvex's planes (n, Fi, Fo) and centrums (FC); the measures (FA, FS, Fa, Fs) are
 * in qhull_measure.c. Byte habits as Qhull 2020.2:
 * coordinates as "%6.16g " (trailing blank), index lists of 'i' and 'o' with a
 * trailing blank, those of Fn, FN, Fv without; the lifted coordinate of qdelaunay's
 * 'o' and 'p' scaled to [0, max |coordinate|] as Qhull's Qbb does.
 */
#include "qhull.h"
#include "qhull_print.h"
#include "qhull_sides.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void lh_cli_qcoords(FILE *f, const double *x, int d)
{
    for (int j = 0; j < d; j++) fprintf(f, "%6.16g ", x[j]);
}

void lh_cli_qscaled(FILE *f, int width, int prec, double m, int e)
{
    double x = ldexp(m, e);
    if (isnormal(x) || m == 0) {
        fprintf(f, "%*.*g", width, prec, x);
        return;
    }
#if LDBL_MAX_EXP > DBL_MAX_EXP
    fprintf(f, "%*.*Lg", width, prec, ldexpl((long double)m, e));
#else
    double lg = log10(fabs(m)) + e * log10(2.0), k = floor(lg);
    fprintf(f, "%s%.*fe%+.0f", m < 0 ? "-" : "", prec > 1 ? prec - 1 : 0, pow(10.0, lg - k), k);
#endif
}

void lh_cli_qcoords_scaled(FILE *f, const double *m, int e, int d)
{
    for (int j = 0; j < d; j++) {
        lh_cli_qscaled(f, 6, 16, m[j], e);
        fputc(' ', f);
    }
}

/* The lifted coordinate |p|^2 scaled to [0, max |coordinate|] (Qhull's Qbb). */
typedef lh_cli_qlift lift_scale;

lh_cli_qlift lh_cli_qlift_scale(const lh_cli_qmodel *mo)
{
    double low = INFINITY, high = -INFINITY, big = 0;
    for (size_t i = 0; i < mo->n * (size_t)mo->d; i++) big = fmax(big, fabs(mo->xyz[i]));
    int e;
    frexp(big, &e); /* |x| 2^-e < 1: the squares and their sums stay finite */
    for (size_t i = 0; i < mo->n; i++) {
        double z = 0;
        for (int j = 0; j < mo->d; j++) {
            double x = ldexp(mo->xyz[i * mo->d + j], -e);
            z += x * x;
        }
        if (z < low) low = z;
        if (z > high) high = z;
    }
    lift_scale s = {low, high > low ? ldexp(big, -e) / (high - low) : 1, e};
    return s;
}

double lh_cli_qlifted_scaled(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i)
{
    const double *x = mo->xyz + i * mo->d;
    double z = 0;
    for (int j = 0; j < mo->d; j++) {
        double y = ldexp(x[j], -s.exp);
        z += y * y;
    }
    return (z - s.low) * s.factor; /* at most max |coordinate| 2^-exp < 1 when high > low */
}

double lh_cli_qlifted(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i)
{
    return ldexp(lh_cli_qlifted_scaled(mo, s, i), s.exp);
}

static void lifted_point(FILE *f, const lh_cli_qmodel *mo, lift_scale s, size_t i)
{
    lh_cli_qcoords(f, mo->xyz + i * mo->d, mo->d);
    lh_cli_qscaled(f, 6, 16, lh_cli_qlifted_scaled(mo, s, i), s.exp);
    fputs(" \n", f);
}

int lh_cli_qis_vertex(const lh_cli_qmodel *mo, size_t i)
{
    for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
        if (mo->inc[k] >= 0) return 1;
    return 0;
}

size_t lh_cli_qvertex_count(const lh_cli_qmodel *mo)
{
    size_t v = 0;
    for (size_t i = 0; i < mo->n; i++) v += lh_cli_qis_vertex(mo, i);
    return v;
}

static void print_i(FILE *f, const lh_cli_qmodel *mo)
{
    fprintf(f, "%zu\n", mo->m);
    for (size_t s = 0; s < mo->m; s++) {
        for (int k = 0; k < mo->nv; k++) fprintf(f, "%" LH_INDEX_PRI " ", mo->vert[s * mo->nv + k]);
        fputc('\n', f);
    }
}

static int desc(const void *a, const void *b)
{
    lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return (x < y) - (x > y);
}

static void print_fv(FILE *f, const lh_cli_qmodel *mo)
{
    fprintf(f, "%zu\n", mo->m);
    for (size_t s = 0; s < mo->m; s++) {
        lh_index v[LH_DELAUNAY_MAX_DIM + 1];
        memcpy(v, mo->vert + s * mo->nv, mo->nv * sizeof *v);
        qsort(v, (size_t)mo->nv, sizeof *v, desc);
        fprintf(f, "%d", mo->nv);
        for (int k = 0; k < mo->nv; k++) fprintf(f, " %" LH_INDEX_PRI, v[k]);
        fputc('\n', f);
    }
}

static void print_id(FILE *f, lh_index id)
{
    if (id == LH_CLI_NO_SIDE)
        fputs(" -0", f); /* a hull side with no upper facet across: never expected */
    else
        fprintf(f, " %" LH_INDEX_PRI, id);
}

static void print_fn(FILE *f, const lh_cli_qmodel *mo)
{
    fprintf(f, "%zu\n", mo->m);
    for (size_t s = 0; s < mo->m; s++) {
        fprintf(f, "%d", mo->nv);
        for (int k = 0; k < mo->nv; k++) print_id(f, mo->nbr[s * mo->nv + k]);
        fputc('\n', f);
    }
}

static void print_fN(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    fprintf(f, "%zu\n", mo->n);
    for (size_t i = 0; i < mo->n; i++) {
        if (lh_cli_qselecting(o) && !lh_cli_qis_vertex(mo, i)) { /* no printed facet's */
            fputs("0\n", f);
            continue;
        }
        fprintf(f, "%" LH_INDEX_PRI, mo->inc_off[i + 1] - mo->inc_off[i]);
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++) print_id(f, mo->inc[k]);
        fputc('\n', f);
    }
}

static void print_p(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    size_t count = 0;
    for (size_t i = 0; i < mo->n; i++) count += lh_cli_qis_vertex(mo, i);
    int lifted = o->prog != LH_QPROG_CONVEX;
    if (o->cdd) /* FD: cdd's format, a 1 before each point */
        fprintf(f, "%s\nbegin\n%zu %d real\n", o->command, count, mo->d + lifted + 1);
    else
        fprintf(f, "%d\n%zu\n", mo->d + lifted, count);
    lift_scale s = lh_cli_qlift_scale(mo);
    for (size_t i = 0; i < mo->n; i++) {
        if (!lh_cli_qis_vertex(mo, i)) continue;
        if (o->cdd) fputs("1 ", f);
        if (lifted) {
            lifted_point(f, mo, s, i);
        } else {
            lh_cli_qcoords(f, mo->xyz + i * mo->d, mo->d);
            fputc('\n', f);
        }
    }
    if (o->cdd) fputs("end\n", f);
}

static void print_o(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    int lifted = o->prog != LH_QPROG_CONVEX;
    fprintf(f, "%d\n%zu %zu %zu\n", mo->d + lifted, mo->n, mo->m, mo->m * mo->nv / 2);
    lift_scale s = lh_cli_qlift_scale(mo);
    for (size_t i = 0; i < mo->n; i++) {
        if (lifted) {
            lifted_point(f, mo, s, i);
        } else {
            lh_cli_qcoords(f, mo->xyz + i * mo->d, mo->d);
            fputc('\n', f);
        }
    }
    for (size_t t = 0; t < mo->m; t++) {
        fprintf(f, "%d ", mo->nv);
        for (int k = 0; k < mo->nv; k++) fprintf(f, "%" LH_INDEX_PRI " ", mo->vert[t * mo->nv + k]);
        fputc('\n', f);
    }
}

/* Extreme points, increasing (Qhull lists them in its facets' order): qconvex, the
 * hull's vertices; qdelaunay and qvoronoi, the sites on the hull's boundary (on an
 * upper or vertical facet, as Qhull's); with Qu, the furthest-site triangulation's
 * vertices (the corners: a site inside a hull facet lifts below the upper hull).
 * With good facets selected, only those that are vertices of printed facets. */
static void print_fx(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    size_t count = 0;
    const int selecting = lh_cli_qselecting(o);
    for (int pass = 0; pass < 2; pass++) {
        if (pass) fprintf(f, "%zu\n", count);
        for (size_t i = 0; i < mo->n; i++) {
            int on = 0;
            for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1] && !on; k++)
                on = o->prog == LH_QPROG_CONVEX ||
                     (o->furthest ? mo->inc[k] >= 0 : mo->inc[k] < 0 && (size_t)-mo->inc[k] <= mo->m_upper);
            on &= !selecting || lh_cli_qis_vertex(mo, i);
            if (!on) continue;
            if (pass) fprintf(f, "%zu\n", i);
            else count++;
        }
    }
}

/* With a selection of good facets (QGn, QVn, Pdk, PDk, PAn) Qhull's summary counts
 * the whole hull and then the good facets; QGn's point is not among the points. */
static int print_s(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    size_t v = lh_cli_qvertex_count(mo->all ? mo->all : mo), n = mo->n - (mo->excluded >= 0);
    int good = lh_cli_qselecting(o) && !o->good_nbrs;
    if (o->prog == LH_QPROG_CONVEX) {
        if (good) /* the other facets are the dropped ones: with them, the whole hull */
            for (size_t i = v = 0; i < mo->n; i++) v += mo->inc_off[i + 1] > mo->inc_off[i];
        fprintf(f, "\nConvex hull of %zu points in %d-d:\n\n  Number of vertices: %zu\n"
                   "  Number of facets: %zu\n", n, mo->d, v, mo->m + (good ? mo->m_other : 0));
        if (good && mo->m) fprintf(f, "  Number of 'good' facets: %zu\n", mo->m); /* Qhull: not 0 */
    } else if (o->prog == LH_QPROG_VORONOI) {
        fprintf(f, "\nVoronoi diagram by the convex hull of %zu points in %d-d:\n\n"
                   "  Number of Voronoi regions%s: %zu\n  Number of %sVoronoi vertices: %zu\n",
                n, mo->d + 1, o->furthest ? " (furthest-site)" : "", v,
                o->npd || o->gvertex.on || o->gpoint.on ? "'good' " : "",
                mo->ngood); /* Qhull: no 'good' for PAn; with PG, the good ones */
    } else {
        fprintf(f, "\n%sDelaunay triangulation by the convex hull of %zu points in %d-d:\n\n"
                   "  Number of input sites: %zu\n  Number of %s%sDelaunay regions: %zu\n",
                o->furthest ? "Furthest-site " : "", n, mo->d + 1, n, good ? "'good' " : "",
                o->furthest ? "furthest-site " : "", mo->m);
    }
    if (mo->ndup) fprintf(f, "  Number of duplicate sites merged: %zu\n", mo->ndup);
    fprintf(f, "\nStatistics for: %s\n\n  Number of points processed: %zu\n"
               "  Exact arithmetic: every facet a simplex, no merging, no precision error\n"
               "  CPU seconds to compute %s: %.3g\n",
            o->command, n - mo->ndup, o->prog == LH_QPROG_CONVEX ? "the hull" : "the triangulation",
            mo->seconds);
    if (o->areas) { /* FA, FS: Qhull's lines, its "%2.8g" */
        double area, volume;
        if (!lh_cli_qtotals(mo, &area, &volume)) return 0;
        fprintf(f, "  Total facet area:   %2.8g\n", area);
        if (o->prog == LH_QPROG_CONVEX) fprintf(f, "  Total volume:       %2.8g\n", volume);
    }
    fputc('\n', f);
    return 1;
}

/* The outward hyperplane n.x + off = 0 of hull facet t, |n| = 1, from the exact
 * cofactors (lh_hyperplane). The model lists a hull facet with its last two vertices
 * exchanged (Qhull's parity), so outward is the opposite of that order's orientation. */
void lh_cli_qfacet_plane(const lh_cli_qmodel *mo, size_t t, double *n, double *off, int *e)
{
    const int d = mo->d;
    const double *p[LH_DELAUNAY_MAX_DIM] = {0};
    for (int k = 0; k < d; k++) p[k] = mo->xyz + (size_t)mo->vert[t * d + k] * d;
    lh_hyperplane_exp(mo->pred, d, p, n, off, e);
    for (int j = 0; j < d; j++) n[j] = -n[j];
    *off = -*off;
}

/* n.x + off <= 0 inside; FD prints cdd's rows b - A x >= 0: -off, then -n. */
static void print_planes(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    const int d = mo->d;
    if (o->cdd) fprintf(f, "%s\nbegin\n    %zu %d real\n", o->command, mo->m, d + 1);
    else fprintf(f, "%d\n%zu\n", d + 1, mo->m);
    for (size_t t = 0; t < mo->m; t++) {
        double n[LH_DELAUNAY_MAX_DIM], off;
        int e;
        lh_cli_qfacet_plane(mo, t, n, &off, &e);
        if (o->cdd) {
            lh_cli_qscaled(f, 6, 16, -off, e);
            fputc(' ', f);
            for (int j = 0; j < d; j++) fprintf(f, "%6.16g ", -n[j]);
        } else {
            lh_cli_qcoords(f, n, d);
            lh_cli_qscaled(f, 6, 16, off, e);
            fputc(' ', f);
        }
        fputc('\n', f);
    }
    if (o->cdd) fputs("end\n", f);
}

static void print_centrums(FILE *f, const lh_cli_qmodel *mo)
{
    const int d = mo->d;
    fprintf(f, "%d\n%zu\n", d, mo->m);
    for (size_t t = 0; t < mo->m; t++) {
        double c[LH_DELAUNAY_MAX_DIM] = {0};
        for (int k = 0; k < d; k++)
            for (int j = 0; j < d; j++) c[j] += mo->xyz[(size_t)mo->vert[t * d + k] * d + j] / d;
        lh_cli_qcoords(f, c, d);
        fputc('\n', f);
    }
}

int lh_cli_qprint(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt)
{
    static const char *const facet_formats[] = {"s", "Fn", "i", "Fs", "Fx", "FI", "Fc", "FP"};
    int as_facets = 0; /* qvoronoi prints these of the Delaunay facets, as Qhull */
    for (size_t k = 0; k < sizeof facet_formats / sizeof facet_formats[0]; k++)
        as_facets |= !strcmp(opt, facet_formats[k]);
    if (o->prog == LH_QPROG_VORONOI && !as_facets)
        return lh_cli_qprint_voronoi(f, o, mo->all ? mo->all : mo, opt);
    if (!strcmp(opt, "i")) print_i(f, mo);
    else if (!strcmp(opt, "Fv")) print_fv(f, mo);
    else if (!strcmp(opt, "Fn")) print_fn(f, mo);
    else if (!strcmp(opt, "FN")) print_fN(f, o, mo);
    else if (!strcmp(opt, "p")) print_p(f, o, mo);
    else if (!strcmp(opt, "o") || !strcmp(opt, "Ft")) print_o(f, o, mo);
    else if (!strcmp(opt, "Fx")) print_fx(f, o, mo);
    else if (!strcmp(opt, "s")) return print_s(f, o, mo);
    else if (!strcmp(opt, "FS") || !strcmp(opt, "Fa") || !strcmp(opt, "Fs"))
        return lh_cli_qprint_measure(f, o, mo, opt);
    else if (!strcmp(opt, "n") || !strcmp(opt, "Fi") || !strcmp(opt, "Fo")) print_planes(f, o, mo);
    else if (!strcmp(opt, "FC")) print_centrums(f, mo);
    else return lh_cli_qprint_extra(f, o, mo, opt);
    return 1;
}
