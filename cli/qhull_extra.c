/*
 * qhull_extra.c — Qhull's FI, Fm, FQ, Fc, FP and the Mathematica (m) and Maple (FM)
 * pictures, for qconvex and qdelaunay, in Qhull 2020.2's layout.
 *
 * Coplanar points (Fc, FP) are exact here: for qconvex the sites that are not
 * vertices and lie exactly on a facet's hyperplane (each with the first such
 * facet), for qdelaunay and qvoronoi the merged duplicates (with the first facet of
 * the site they were merged into). Facet ids are the output's facet numbers (FI
 * prints them; qvoronoi's Voronoi vertex v >= 1 is facet v - 1); no facet is ever
 * merged, so Fm prints 0 for each.
 */
#include "qhull.h"
#include "qhull_print.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void print_ids(FILE *f, const lh_cli_qmodel *mo, int merges)
{
    fprintf(f, "%zu\n", mo->m);
    for (size_t t = 0; t < mo->m; t++) fprintf(f, "%zu\n", merges ? (size_t)0 : t);
}

/* The first printed facet site i is coplanar with, or -1. */
static lh_index coplanar_facet(const lh_cli_qopts *o, const lh_cli_qmodel *mo, size_t i)
{
    if (lh_cli_qis_vertex(mo, i) || (lh_index)i == mo->excluded) return -1;
    if (o->prog != LH_QPROG_CONVEX) {
        size_t v = (size_t)mo->dup[i];
        if (v == i) return -1; /* a site that is no vertex and no duplicate: none here */
        for (lh_index k = mo->inc_off[v]; k < mo->inc_off[v + 1]; k++)
            if (mo->inc[k] >= 0) return mo->inc[k];
        return -1;
    }
    const int d = mo->d;
    const double *p[LH_DELAUNAY_MAX_DIM + 1] = {0};
    p[d] = mo->xyz + i * d;
    for (size_t t = 0; t < mo->m; t++) {
        for (int k = 0; k < d; k++) p[k] = mo->xyz + (size_t)mo->vert[t * d + k] * d;
        if (lh_orient(mo->pred, d, p) == 0) return (lh_index)t;
    }
    return -1;
}

/* Fc: per facet, its coplanar points; FP: per coplanar point its facet's nearest
 * vertex (exact comparison; the first of equally near ones), the point, the facet
 * and the distance. */
static int print_coplanar(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, int nearest)
{
    lh_index *of = malloc((mo->n ? mo->n : 1) * sizeof *of);
    size_t *count = calloc(mo->m ? mo->m : 1, sizeof *count), total = 0;
    if (!of || !count) {
        free(of);
        free(count);
        return 0;
    }
    for (size_t i = 0; i < mo->n; i++) {
        of[i] = coplanar_facet(o, mo, i);
        if (of[i] >= 0) count[of[i]]++, total++;
    }
    const int d = mo->d;
    if (nearest) {
        fprintf(f, "%zu\n", total);
        for (size_t i = 0; i < mo->n; i++) {
            if (of[i] < 0) continue;
            const lh_index *v = mo->vert + (size_t)of[i] * mo->nv;
            const double *q = mo->xyz + i * d;
            lh_index best = v[0];
            for (int k = 1; k < mo->nv; k++)
                if (lh_distance_compare(mo->pred, d, q, mo->xyz + (size_t)v[k] * d,
                                        mo->xyz + (size_t)best * d) < 0 ||
                    (lh_distance_compare(mo->pred, d, q, mo->xyz + (size_t)v[k] * d,
                                         mo->xyz + (size_t)best * d) == 0 && v[k] < best))
                    best = v[k];
            double s = 0;
            for (int j = 0; j < d; j++) {
                double e = q[j] - mo->xyz[(size_t)best * d + j];
                s += e * e;
            }
            fprintf(f, "%" LH_INDEX_PRI " %zu %" LH_INDEX_PRI " %6.16g \n", best, i, of[i], sqrt(s));
        }
    } else {
        fprintf(f, "%zu\n", mo->m);
        for (size_t t = 0; t < mo->m; t++) {
            fprintf(f, "%zu", count[t]);
            for (size_t i = 0; i < mo->n && count[t]; i++)
                if (of[i] == (lh_index)t) fprintf(f, " %zu", i);
            fputc('\n', f);
        }
    }
    free(of);
    free(count);
    return 1;
}

/* The pictures' vertex: qconvex's coordinates, or qdelaunay's lifted point. */
static void picture_point(FILE *f, const lh_cli_qmodel *mo, lh_cli_qlift s, int lifted, size_t i,
                          const char *open, const char *close)
{
    const double *x = mo->xyz + i * mo->d;
    fputs(open, f);
    for (int j = 0; j < mo->d; j++) fprintf(f, "%s%16.8f", j ? ", " : "", x[j]);
    if (lifted) fprintf(f, ", %16.8f", lh_cli_qlifted(mo, s, i));
    fputs(close, f);
}

/* m (Mathematica) and FM (Maple): 2-d hull edges as lines, 3-d hull facets or 2-d
 * Delaunay triangles (lifted) as polygons, vertices in the facet's order. */
static void print_picture(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, int maple)
{
    int lifted = o->prog != LH_QPROG_CONVEX;
    lh_cli_qlift s = lifted ? lh_cli_qlift_scale(mo) : (lh_cli_qlift){0, 1, 0};
    if (mo->nv == 2) { /* 2-d hull: segments */
        fputs(maple ? "PLOT(CURVES(\n" : "{\n", f);
        for (size_t t = 0; t < mo->m; t++) {
            const lh_index *v = mo->vert + t * 2;
            fputs(t ? "," : "", f);
            picture_point(f, mo, s, 0, (size_t)v[0], maple ? "[[" : "Line[{{", maple ? "], " : "}, ");
            picture_point(f, mo, s, 0, (size_t)v[1], maple ? "[" : "{", maple ? "]]\n" : "}}]\n");
        }
        fputs(maple ? "));\n" : "}\n", f);
        return;
    }
    fputs(maple ? "PLOT3D(POLYGONS(\n" : "{\n", f);
    for (size_t t = 0; t < mo->m; t++) {
        const lh_index *v = mo->vert + t * 3;
        if (t) fputs(",\n", f);
        for (int k = 0; k < 3; k++)
            picture_point(f, mo, s, lifted, (size_t)v[k],
                          k ? (maple ? "[" : "{") : (maple ? "[[" : "Polygon[{{"),
                          k < 2 ? (maple ? "],\n" : "},\n") : (maple ? "]]" : "}}]"));
    }
    fputs(maple ? "));\n" : "}\n", f);
}

int lh_cli_qprint_extra(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt)
{
    if (!strcmp(opt, "FI") || !strcmp(opt, "Fm")) print_ids(f, mo, opt[1] == 'm');
    else if (!strcmp(opt, "FQ")) fprintf(f, "%s\n", o->command);
    else if (!strcmp(opt, "Fc") || !strcmp(opt, "FP")) return print_coplanar(f, o, mo, opt[1] == 'P');
    else if (!strcmp(opt, "G")) return lh_cli_qprint_geomview(f, o, mo);
    else if (!strcmp(opt, "f") || !strcmp(opt, "FF")) lh_cli_qprint_fields(f, o, mo);
    else print_picture(f, o, mo, opt[1] == 'M');
    return 1;
}

/* G and its suboptions for a picture of `dims` coordinates (Qhull's rules: 2-d to
 * 4-d; Ga, Gr, Gh, Gn not in 4-d, Gr and Gh not in 2-d, where Qhull warns and
 * draws without them). 0 after printing the problem. */
static int geom_fits(const lh_cli_qopts *o, int dims)
{
    const int extras = o->geom & (LH_QG_POINTS | LH_QG_RIDGES | LH_QG_INTERSECT | LH_QG_SPHERES |
                                  LH_QG_CENTRUMS);
    if (dims < 2 || dims > 4) {
        fprintf(stderr, "lifthull %s: option 'G': Geomview output is only available for 2-d, 3-d "
                "and 4-d pictures (Qhull's rule; here %d-d%s)\n", o->name, dims,
                o->prog == LH_QPROG_DELAUNAY ? ", the lifted hull" : "");
        return 0;
    }
    if (dims == 4 && (o->geom & (LH_QG_POINTS | LH_QG_RIDGES | LH_QG_INTERSECT | LH_QG_NOPLANES))) {
        fprintf(stderr, "lifthull %s: options 'Ga', 'Gr', 'Gh' and 'Gn' are for 2-d and 3-d "
                "pictures (a 4-d one draws its ridges)\n", o->name);
        return 0;
    }
    if ((o->geom & LH_QG_TRANSPARENT) &&
        (o->prog != LH_QPROG_DELAUNAY || dims != 4 || o->geom_drop >= 0)) {
        fprintf(stderr, "lifthull %s: option 'Gt': transparent outer ridges need a 3-d Delaunay "
                "triangulation and no GDn (Qhull's rule)\n", o->name);
        return 0;
    }
    if (dims == 4 && (o->geom & (LH_QG_SPHERES | LH_QG_CENTRUMS)))
        fprintf(stderr, "lifthull %s: options 'Gv' and 'Gc' ignored: no spheres or centrums in a "
                "4-d picture (as Qhull)\n", o->name);
    if (dims == 2 && (o->geom & (LH_QG_RIDGES | LH_QG_INTERSECT)))
        fprintf(stderr, "lifthull %s: options 'Gr' and 'Gh' ignored: no ridges to draw in a 2-d "
                "picture (as Qhull)\n", o->name);
    if ((o->geom & LH_QG_NOPLANES) && !(o->geom & (LH_QG_INNER | LH_QG_OUTER)) &&
        !(dims == 3 ? extras : extras & (LH_QG_POINTS | LH_QG_SPHERES | LH_QG_CENTRUMS))) {
        fprintf(stderr, "lifthull %s: option 'Gn': no output specified for Geomview (Gn leaves "
                "the facets out: add Ga, Gv, Gc, Gr or Gh)\n", o->name);
        return 0;
    }
    if (o->geom_drop >= 0 && dims != 4)
        fprintf(stderr, "lifthull %s: option 'GD%d' ignored: it drops a coordinate of 4-d "
                "pictures only\n", o->name, o->geom_drop);
    return 1;
}

int lh_cli_qcheck_outputs(const lh_cli_qopts *o, int d, size_t n)
{
    const struct lh_cli_qgood *g[2] = {&o->gpoint, &o->gvertex};
    for (int k = 0; k < 2; k++)
        if (g[k]->on && g[k]->n >= n) { /* Qhull: QH6150 */
            fprintf(stderr, "lifthull %s: option 'Q%c%s%zu': point %zu is not among the %zu input "
                    "points (0..%zu)\n", o->name, k ? 'V' : 'G', g[k]->not ? "-" : "", g[k]->n,
                    g[k]->n, n, n ? n - 1 : 0);
            return 0;
        }
    for (int i = 0; i < o->nout; i++) {
        const char *w = o->out[i];
        if ((!strcmp(w, "f") || !strcmp(w, "FF")) && o->prog != LH_QPROG_CONVEX &&
            d + 1 > LH_ORIENT_MAX_DIM) {
            fprintf(stderr, "lifthull %s: option '%s': the lifted facets' normals are for at most "
                    "%d-d input\n", o->name, w, LH_ORIENT_MAX_DIM - 1);
            return 0;
        }
        if (!strcmp(w, "G") && o->prog == LH_QPROG_VORONOI && d != 2) {
            fprintf(stderr, "lifthull qvoronoi: option 'G': Geomview output for Voronoi diagrams "
                    "only for 2-d (Qhull's rule; here %d-d)\n", d);
            return 0;
        }
        if (!strcmp(w, "G") && o->prog != LH_QPROG_VORONOI) {
            if (!geom_fits(o, d + (o->prog != LH_QPROG_CONVEX))) return 0;
            continue;
        }
        if ((strcmp(w, "m") && strcmp(w, "FM") && strcmp(w, "G")) ||
            (o->prog == LH_QPROG_CONVEX ? d == 2 || d == 3 : d == 2))
            continue;
        fprintf(stderr, "lifthull %s: option '%s': Mathematica, Maple and Geomview output are for "
                "2-d and 3-d convex hulls and 2-d Delaunay triangulations (here %d-d)\n", o->name, w, d);
        return 0;
    }
    return 1;
}
