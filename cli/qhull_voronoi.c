/*
 * qhull_voronoi.c — qvoronoi's formats from the Delaunay model: Voronoi vertex v >= 1
 * is the circumcentre of simplex v - 1 and vertex 0 stands for infinity (Qhull
 * prints it as -10.101 in every coordinate); the ridge of sites i < j is dual to
 * the Delaunay edge ij, its vertices the simplices around that edge, and it is
 * unbounded (bounded) exactly when the edge lies (does not lie) on the convex hull.
 * Cospherical sites make several simplices with one circumcentre: they form one
 * cell of the Delaunay complex (lh_tri_complex_cells), one Voronoi vertex. As Qhull
 * with Qt, every simplex keeps its number in 'p' and 'o', but a ridge or a region
 * (also in FN) lists each cell once, by its smallest simplex. The ridges are the
 * edges of the Delaunay complex (lh_tri_complex_edges: sites whose regions share a
 * face of dimension d-1; not two sites meeting at one Voronoi vertex only, as across the
 * diagonal of a grid square, nor in 4D and up along a smaller face, which Qhull
 * prints) that have d distinct cells around them (the one at infinity counted once),
 * Qhull's rule.
 * Qhull's 'o' lists each region's vertices in cyclic order in 2D; so does this.
 */
#include "qhull_print.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Whether simplex s containing site i has an open side (on the hull) that contains
 * every site of `keep` (count sites). */
static int open_side_with(const lh_cli_qmodel *mo, lh_index s, const lh_index *keep, int count)
{
    for (int k = 0; k < mo->nv; k++) {
        if (mo->nbr[(size_t)s * mo->nv + k] >= 0) continue;
        lh_index drop = mo->vert[(size_t)s * mo->nv + k];
        int ok = 1;
        for (int c = 0; c < count; c++) ok &= keep[c] != drop;
        if (ok) return 1;
    }
    return 0;
}

static int contains(const lh_cli_qmodel *mo, lh_index s, lh_index v)
{
    for (int k = 0; k < mo->nv; k++)
        if (mo->vert[(size_t)s * mo->nv + k] == v) return 1;
    return 0;
}

/* num[s]: the number of the Voronoi vertex standing for simplex s's cell of the
 * Delaunay complex: the number of the cell's smallest simplex, 1 + its rank among
 * the good simplices (print filters: mo->good; without, every simplex is good and
 * simplex s is vertex s + 1), or 0 when that simplex is not good. NULL when out of
 * memory. */
static lh_index *cell_numbers(const lh_cli_qmodel *mo)
{
    size_t nc;
    const lh_index *off, *vert, *cell;
    if (lh_tri_complex(mo->tri, &nc, &off, &vert) != LH_OK || lh_tri_complex_cells(mo->tri, &cell) != LH_OK)
        return NULL;
    lh_index *first = malloc((nc ? nc : 1) * sizeof *first);
    lh_index *num = malloc((mo->m ? mo->m : 1) * sizeof *num);
    if (!first || !num) {
        free(first);
        free(num);
        return NULL;
    }
    for (size_t c = 0; c < nc; c++) first[c] = -1;
    lh_index rank = 0;
    for (size_t s = 0; s < mo->m; s++) {
        if (first[cell[s]] < 0) first[cell[s]] = (lh_index)s;
        num[s] = !mo->good || mo->good[s] ? ++rank : 0;
    }
    for (size_t s = 0; s < mo->m; s++) num[s] = num[first[cell[s]]]; /* first <= s: already final */
    free(first);
    return num;
}

/* Whether simplex s is printed as a Voronoi vertex (print filters). */
static int good(const lh_cli_qmodel *mo, size_t s)
{
    return !mo->good || mo->good[s];
}

static size_t good_count(const lh_cli_qmodel *mo)
{
    size_t count = 0;
    for (size_t s = 0; s < mo->m; s++) count += good(mo, s) != 0;
    return count;
}

/* Appends r to list[0..*count-1] unless it is there or 0 (a vertex not printed). */
static void add_once(lh_index *list, size_t *count, lh_index r)
{
    if (!r) return;
    for (size_t k = 0; k < *count; k++)
        if (list[k] == r) return;
    list[(*count)++] = r;
}

typedef struct ridge_pass {
    FILE *f;         /* NULL: count only */
    int which;       /* 'v': Fv, 'i': bounded (Fi), 'o': unbounded (Fo) */
    const double *x; /* sites */
    size_t count;
    const lh_index *num; /* cell_numbers */
    lh_index *around;    /* room for the cells around an edge */
    lh_index only;       /* QVn: the ridges of site n only (Qhull); -1: all */
} ridge_pass;

/* The bisector of sites a and b: n.x + off 2^e = 0, |n| = 1, n from a towards b.
 * Computed on the sites scaled by 2^-e, e the exponent of their largest coordinate
 * (exact, but for bits below 2^-1074 of the tiny coordinates beside a huge one), so
 * nothing overflows; the difference is scaled to a largest entry in [0.5, 1) before
 * its length is taken, so nothing underflows: finite and accurate from the
 * subnormals to DBL_MAX. */
static void bisector(const double *a, const double *b, int d, double *n, double *off, int *e)
{
    double big = 0, as[LH_DELAUNAY_MAX_DIM], bs[LH_DELAUNAY_MAX_DIM], most = 0, len = 0;
    for (int c = 0; c < d; c++) big = fmax(big, fmax(fabs(a[c]), fabs(b[c])));
    frexp(big, e);
    for (int c = 0; c < d; c++) {
        as[c] = ldexp(a[c], -*e);
        bs[c] = ldexp(b[c], -*e);
        n[c] = bs[c] - as[c]; /* |as|, |bs| < 1: no overflow */
        most = fmax(most, fabs(n[c]));
    }
    int g;
    frexp(most, &g); /* most > 0: the sites are distinct */
    for (int c = 0; c < d; c++) {
        n[c] = ldexp(n[c], -g);
        len += n[c] * n[c];
    }
    len = sqrt(len); /* in [0.5, sqrt(d)] */
    *off = 0;
    for (int c = 0; c < d; c++) {
        n[c] /= len;
        *off -= n[c] * (0.5 * as[c] + 0.5 * bs[c]);
    }
}

/* A ridge needs d vertices, the one at infinity counted once, to be printed: Qhull
 * leaves out the unbounded ridges with fewer (qh_eachvoronoi, "count >= hull_dim - 1"). */
static void print_ridge(ridge_pass *rp, const lh_cli_qmodel *mo, lh_index i, lh_index j, int unbounded)
{
    if ((rp->which == 'i' && unbounded) || (rp->which == 'o' && !unbounded)) return;
    const int d = mo->d;
    size_t around = 0; /* the cells around edge ij */
    for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
        if (mo->inc[k] >= 0 && contains(mo, mo->inc[k], j)) add_once(rp->around, &around, rp->num[mo->inc[k]]);
    if (!around || around + (size_t)unbounded < (size_t)d) return;
    rp->count++;
    if (!rp->f) return;
    if (rp->which == 'v') {
        fprintf(rp->f, "%zu %" LH_INDEX_PRI " %" LH_INDEX_PRI "%s", around + (size_t)unbounded + 2, i, j,
                unbounded ? " 0" : "");
        for (size_t k = 0; k < around; k++) fprintf(rp->f, " %" LH_INDEX_PRI, rp->around[k]);
        fputc('\n', rp->f);
        return;
    }
    double n[LH_DELAUNAY_MAX_DIM], off;
    int e;
    bisector(rp->x + (size_t)i * d, rp->x + (size_t)j * d, d, n, &off, &e);
    fprintf(rp->f, "%d %" LH_INDEX_PRI " %" LH_INDEX_PRI " ", d + 3, i, j);
    lh_cli_qcoords(rp->f, n, d);
    lh_cli_qscaled(rp->f, 6, 16, off, e);
    fputs(" \n", rp->f);
}

/* Every edge ij of the Delaunay complex, i < j, in increasing order (an edge of the
 * complex is one of every triangulation of its cells: the simplices around it are
 * found through the incidences). */
static int ridges(ridge_pass *rp, const lh_cli_qmodel *mo)
{
    size_t count;
    const lh_index *e;
    if (lh_tri_complex_edges(mo->tri, &count, &e) != LH_OK) return 0;
    for (size_t r = 0; r < count; r++) {
        lh_index i = e[2 * r], j = e[2 * r + 1];
        if (rp->only >= 0 && i != rp->only && j != rp->only) continue;
        int unbounded = 0;
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1] && !unbounded; k++)
            unbounded = mo->inc[k] >= 0 && contains(mo, mo->inc[k], j) && open_side_with(mo, mo->inc[k], e + 2 * r, 2);
        print_ridge(rp, mo, i, j, unbounded);
    }
    return 1;
}

/* The most facets around one site. */
static size_t max_incidence(const lh_cli_qmodel *mo)
{
    size_t most = 1;
    for (size_t i = 0; i < mo->n; i++)
        if ((size_t)(mo->inc_off[i + 1] - mo->inc_off[i]) > most) most = (size_t)(mo->inc_off[i + 1] - mo->inc_off[i]);
    return most;
}

static int print_ridges(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, int which)
{
    ridge_pass rp = {NULL, which, mo->xyz, 0, cell_numbers(mo), malloc(max_incidence(mo) * sizeof(lh_index)),
                     o->gvertex.on && !o->gvertex.not ? (lh_index)o->gvertex.n : -1};
    int ok = rp.num && rp.around && ridges(&rp, mo);
    if (ok) {
        fprintf(f, "%zu\n", rp.count);
        rp.f = f;
        rp.count = 0;
        ok = ridges(&rp, mo);
    }
    free((void *)rp.num);
    free(rp.around);
    return ok;
}

/* The simplices around site i in the plane, in cyclic order: from one with an open
 * side through i (when i is on the hull) across the sides through i. */
static size_t cyclic_2d(const lh_cli_qmodel *mo, lh_index i, lh_index *out)
{
    lh_index first = mo->inc[mo->inc_off[i]];
    for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
        if (mo->inc[k] >= 0 && open_side_with(mo, mo->inc[k], &i, 1)) first = mo->inc[k];
    size_t count = 0;
    lh_index prev = -1, cur = first;
    while (cur >= 0 && (count == 0 || cur != first)) {
        out[count++] = cur;
        lh_index next = -1;
        for (int k = 0; k < 3; k++) {
            lh_index nb = mo->nbr[(size_t)cur * 3 + k];
            if (mo->vert[(size_t)cur * 3 + k] != i && nb >= 0 && nb != prev) next = nb;
        }
        prev = cur;
        cur = next;
    }
    return count;
}

/* list[0..count-1] (simplices) as their cells' numbers, each once, in order of
 * first appearance (those not printed left out); returns the new count. */
static size_t cells_once(const lh_index *num, lh_index *list, size_t count)
{
    size_t w = 0;
    for (size_t c = 0; c < count; c++) add_once(list, &w, num[list[c]]);
    return w;
}

/* 'o': each region's Voronoi vertices, 0 (infinity) last for an unbounded one; 'G'
 * (geom): without 0, a comment naming the site, and a site that is no vertex (a
 * merged duplicate) as Qhull's "coplanar or isolated" line. */
static int print_regions(FILE *f, const lh_cli_qmodel *mo, int geom)
{
    lh_index *list = malloc((mo->m ? mo->m : 1) * sizeof *list), *num = cell_numbers(mo);
    if (!list || !num) {
        free(list);
        free(num);
        return 0;
    }
    for (size_t i = 0; i < mo->n; i++) {
        size_t count = 0;
        int unbounded = 0;
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++) {
            if (mo->inc[k] < 0) continue;
            list[count++] = mo->inc[k];
            lh_index site = (lh_index)i;
            unbounded |= open_side_with(mo, mo->inc[k], &site, 1);
        }
        if (count && mo->d == 2) count = cyclic_2d(mo, (lh_index)i, list);
        count = cells_once(num, list, count); /* a cell's simplices are consecutive in 2D */
        if (geom && !count) {
            fprintf(f, " # p%zu is coplanar or isolated\n", i);
            continue;
        }
        unbounded &= !geom;
        fprintf(f, "%zu", count + (count && unbounded));
        for (size_t c = 0; c < count; c++) fprintf(f, " %" LH_INDEX_PRI, list[c]);
        if (geom) fprintf(f, " # p%zu", i);
        fputs(count && unbounded ? " 0\n" : "\n", f);
    }
    free(list);
    free(num);
    return 1;
}

/* FN: for each site the Voronoi vertices of its region, as Qhull's ids (the 'o'
 * number less one): each cell of the Delaunay complex once, by its smallest simplex
 * as in 'o' and Fv, in increasing order; then, negative, the upper Delaunay
 * facets around the site (Qhull's "vertices at infinity"), one per simplex of the
 * upper hull; then, negative after them, the simplices a print filter dropped (as
 * qdelaunay numbers them). A site with no printed vertex: 0, as Qhull. */
static int print_neighbors(FILE *f, const lh_cli_qmodel *mo)
{
    lh_index *list = malloc(max_incidence(mo) * sizeof *list), *num = cell_numbers(mo);
    lh_index *dropped = malloc((mo->m ? mo->m : 1) * sizeof *dropped);
    if (!list || !num || !dropped) {
        free(list);
        free(num);
        free(dropped);
        return 0;
    }
    for (size_t s = 0, r = 0; s < mo->m; s++) dropped[s] = good(mo, s) ? 0 : -(lh_index)(mo->m_other + ++r);
    fprintf(f, "%zu\n", mo->n);
    for (size_t i = 0; i < mo->n; i++) {
        size_t count = 0, cells;
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
            if (mo->inc[k] >= 0) add_once(list, &count, num[mo->inc[k]]);
        cells = count;
        if (mo->good && !cells) {
            fputs("0\n", f);
            continue;
        }
        for (size_t c = 0; c < cells; c++) list[c]--; /* Qhull's ids: the number less one */
        for (size_t a = 1; a < cells; a++) /* increasing, as the other formats' lists */
            for (size_t b = a; b > 0 && list[b - 1] > list[b]; b--) {
                lh_index x = list[b];
                list[b] = list[b - 1];
                list[b - 1] = x;
            }
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
            if (mo->inc[k] < 0) list[count++] = mo->inc[k]; /* distinct facets */
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
            if (mo->inc[k] >= 0 && dropped[mo->inc[k]]) list[count++] = dropped[mo->inc[k]];
        fprintf(f, "%zu", count);
        for (size_t c = 0; c < count; c++) fprintf(f, " %" LH_INDEX_PRI, list[c]);
        fputc('\n', f);
    }
    free(list);
    free(num);
    free(dropped);
    return 1;
}

/* Voronoi vertex s + 1: the circumcentre of simplex s, c 2^e (finite where the
 * centre passes DBL_MAX), "%6.16g " each coordinate. */
static void centre(FILE *f, const lh_cli_qmodel *mo, size_t s)
{
    double m[LH_DELAUNAY_MAX_DIM];
    int e;
    lh_tri_circumcenter_exp(mo->tri, s, m, &e);
    lh_cli_qcoords_scaled(f, m, e, mo->d);
}

/* G (2-d only, lh_cli_qcheck_outputs): Qhull's picture of the Voronoi diagram, one
 * OFF object whose vertices are the Voronoi vertices (0: infinity, at the origin and
 * "not used") and whose faces are the sites' regions without infinity; the comment
 * "# v f<id>" names the Delaunay facet (FI's id) of Voronoi vertex v. */
static int print_geomview(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    fprintf(f, "{appearance {linewidth 3} LIST # %s\n", o->command);
    lh_index *num = cell_numbers(mo);
    if (!num) return 0;
    size_t regions = 0; /* the sites with a printed Voronoi vertex (Qhull's count) */
    for (size_t i = 0; i < mo->n; i++) {
        lh_index k = mo->inc_off[i];
        while (k < mo->inc_off[i + 1] && (mo->inc[k] < 0 || !num[mo->inc[k]])) k++;
        regions += k < mo->inc_off[i + 1];
    }
    free(num);
    fprintf(f, "{appearance {+edge -face} OFF %zu %zu 1 # Voronoi centers and cells\n",
            good_count(mo) + 1, regions);
    fprintf(f, "%6.16g %6.16g  0 # infinity not used\n", 0.0, 0.0);
    for (size_t s = 0, v = 0; s < mo->m; s++) {
        if (!good(mo, s)) continue;
        v++;
        fprintf(f, "# %zu f%zu\n", v, v - 1);
        centre(f, mo, s);
        fputs(" 0\n", f);
    }
    if (!print_regions(f, mo, 1)) return 0;
    fputs("}\n}\n", f);
    return 1;
}

int lh_cli_qprint_voronoi(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt)
{
    const int d = mo->d;
    if (!strcmp(opt, "FN")) return print_neighbors(f, mo);
    if (!strcmp(opt, "G")) return print_geomview(f, o, mo);
    if (!strcmp(opt, "p") || !strcmp(opt, "o")) {
        int full = opt[0] == 'o', cdd = o->cdd && !full;
        if (full && o->cdd)
            fprintf(stderr, "lifthull qvoronoi: option 'FD': cdd's format is not available for "
                    "'o' (OFF format; as in Qhull)\n");
        const size_t count = good_count(mo);
        if (cdd) /* FD: cdd's format, a 1 before each point */
            fprintf(f, "%s\nbegin\n%zu %d real\n", o->command, count, d + 1);
        else
            fprintf(f, "%d\n", d);
        if (full) {
            fprintf(f, "%zu %zu 1\n", count + 1, mo->n);
            for (int j = 0; j < d; j++) fprintf(f, "%6.16g ", -10.101);
            fputc('\n', f);
        } else if (!cdd) {
            fprintf(f, "%zu\n", count);
        }
        for (size_t s = 0; s < mo->m; s++) {
            if (!good(mo, s)) continue;
            if (cdd) fputs("1 ", f);
            centre(f, mo, s);
            fputc('\n', f);
        }
        if (cdd) fputs("end\n", f);
        return full ? print_regions(f, mo, 0) : 1;
    }
    return print_ridges(f, o, mo, !strcmp(opt, "Fv") ? 'v' : !strcmp(opt, "Fi") ? 'i' : 'o');
}
