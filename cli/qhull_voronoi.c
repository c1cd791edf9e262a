/*
 * qhull_voronoi.c — qvoronoi's formats from the Delaunay model: Voronoi vertex v >= 1
 * is the circumcentre of simplex v - 1 and vertex 0 stands for infinity (Qhull
 * prints it as -10.101 in every coordinate); the ridge of sites i < j is dual to
 * the Delaunay edge ij, its vertices the simplices around that edge, and it is
 * unbounded (bounded) exactly when the edge lies (does not lie) on the convex hull.
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

static int cmp_index(const void *a, const void *b)
{
    lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return (x > y) - (x < y);
}

typedef struct ridge_pass {
    FILE *f;         /* NULL: count only */
    int which;       /* 'v': Fv, 'i': bounded (Fi), 'o': unbounded (Fo) */
    const double *x; /* sites */
    size_t count;
} ridge_pass;

/* A ridge needs d vertices, the one at infinity counted once, to be printed: Qhull
 * leaves out the unbounded ridges with fewer (qh_eachvoronoi, "count >= hull_dim - 1"). */
static void print_ridge(ridge_pass *rp, const lh_cli_qmodel *mo, lh_index i, lh_index j, int unbounded)
{
    if ((rp->which == 'i' && unbounded) || (rp->which == 'o' && !unbounded)) return;
    const int d = mo->d;
    int around = 0; /* the simplices around edge ij */
    for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
        around += mo->inc[k] >= 0 && contains(mo, mo->inc[k], j);
    if (around + unbounded < d) return;
    rp->count++;
    if (!rp->f) return;
    if (rp->which == 'v') {
        fprintf(rp->f, "%d %" LH_INDEX_PRI " %" LH_INDEX_PRI "%s", around + unbounded + 2, i, j,
                unbounded ? " 0" : "");
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
            if (mo->inc[k] >= 0 && contains(mo, mo->inc[k], j))
                fprintf(rp->f, " %" LH_INDEX_PRI, mo->inc[k] + 1);
        fputc('\n', rp->f);
        return;
    }
    /* the bisector, normal from i towards j */
    const double *a = rp->x + (size_t)i * d, *b = rp->x + (size_t)j * d;
    double n[LH_DELAUNAY_MAX_DIM], len = 0, off = 0;
    for (int c = 0; c < d; c++) {
        n[c] = b[c] - a[c];
        len += n[c] * n[c];
    }
    len = sqrt(len);
    for (int c = 0; c < d; c++) {
        n[c] /= len;
        off -= n[c] * 0.5 * (a[c] + b[c]);
    }
    fprintf(rp->f, "%d %" LH_INDEX_PRI " %" LH_INDEX_PRI " ", d + 3, i, j);
    lh_cli_qcoords(rp->f, n, d);
    fprintf(rp->f, "%6.16g \n", off);
}

/* Every Delaunay edge ij, i < j, in increasing order. */
static int ridges(ridge_pass *rp, const lh_cli_qmodel *mo)
{
    lh_index *mark = calloc(mo->n ? mo->n : 1, sizeof *mark);
    lh_index *nb = malloc((mo->n ? mo->n : 1) * sizeof *nb);
    if (!mark || !nb) {
        free(mark);
        free(nb);
        return 0;
    }
    for (size_t i = 0; i < mo->n; i++) {
        size_t cnt = 0;
        for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1]; k++)
            for (int v = 0; mo->inc[k] >= 0 && v < mo->nv; v++) {
                lh_index j = mo->vert[(size_t)mo->inc[k] * mo->nv + v];
                if (j > (lh_index)i && mark[j] != (lh_index)i + 1) {
                    mark[j] = (lh_index)i + 1;
                    nb[cnt++] = j;
                }
            }
        qsort(nb, cnt, sizeof *nb, cmp_index);
        for (size_t c = 0; c < cnt; c++) {
            lh_index pair[2] = {(lh_index)i, nb[c]};
            int unbounded = 0;
            for (lh_index k = mo->inc_off[i]; k < mo->inc_off[i + 1] && !unbounded; k++)
                unbounded = mo->inc[k] >= 0 && contains(mo, mo->inc[k], nb[c]) &&
                            open_side_with(mo, mo->inc[k], pair, 2);
            print_ridge(rp, mo, (lh_index)i, nb[c], unbounded);
        }
    }
    free(mark);
    free(nb);
    return 1;
}

static int print_ridges(FILE *f, const lh_cli_qmodel *mo, int which)
{
    ridge_pass rp = {NULL, which, mo->xyz, 0};
    if (!ridges(&rp, mo)) return 0;
    fprintf(f, "%zu\n", rp.count);
    rp.f = f;
    rp.count = 0;
    return ridges(&rp, mo);
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

static int print_regions(FILE *f, const lh_cli_qmodel *mo)
{
    lh_index *list = malloc((mo->m ? mo->m : 1) * sizeof *list);
    if (!list) return 0;
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
        fprintf(f, "%zu", count + (count && unbounded));
        for (size_t c = 0; c < count; c++) fprintf(f, " %" LH_INDEX_PRI, list[c] + 1);
        fputs(count && unbounded ? " 0\n" : "\n", f);
    }
    free(list);
    return 1;
}

int lh_cli_qprint_voronoi(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo, const char *opt)
{
    (void)o;
    const double *c;
    if (lh_tri_circumcenters(mo->tri, &c) != LH_OK) return 0;
    const int d = mo->d;
    if (!strcmp(opt, "p") || !strcmp(opt, "o")) {
        int full = opt[0] == 'o';
        fprintf(f, "%d\n", d);
        if (full) {
            fprintf(f, "%zu %zu 1\n", mo->m + 1, mo->n);
            for (int j = 0; j < d; j++) fprintf(f, "%6.16g ", -10.101);
            fputc('\n', f);
        } else {
            fprintf(f, "%zu\n", mo->m);
        }
        for (size_t s = 0; s < mo->m; s++) {
            lh_cli_qcoords(f, c + s * d, d);
            fputc('\n', f);
        }
        return full ? print_regions(f, mo) : 1;
    }
    return print_ridges(f, mo, !strcmp(opt, "Fv") ? 'v' : !strcmp(opt, "Fi") ? 'i' : 'o');
}
