/*
 * qhalf_print.c — Qhull's outputs for a halfspace intersection (qhull.org, "qhalf",
 * Qhull 2020.2's layout): the intersection points are the groups of dual hull facets
 * on one hyperplane (Qhull's merged facets), numbered in the order Fp prints them;
 * the halfspaces keep their input numbers.
 *
 * Coplanar halfspaces (Fc, FP, Fs) are exact here: the redundant halfspaces whose
 * dual point lies exactly on a facet of the dual hull (its hyperplane passes
 * through an intersection point), each listed with the first such point. Qhull
 * finds them within its rounding and keeps them only with Fc or Qc. A merge count
 * (Fm) is the number of the group's dual simplices less one, as Qhull merges two
 * triangles into a square (at most 511).
 */
#include "qhalf.h"
#include "qhull_print.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void print_points(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    const int d = hs->d;
    fprintf(f, "%d\n%zu\n", d, r->groups);
    for (size_t g = 0; g < r->groups; g++) {
        lh_cli_qcoords_scaled(f, r->point + g * d, r->exp[g], d);
        fputc('\n', f);
    }
}

/* i: the halfspaces of each point, Qhull's trailing blank; Fv: with counts. */
static void print_incident(FILE *f, const lh_cli_hresult *r, int counts)
{
    fprintf(f, "%zu\n", r->groups);
    for (size_t g = 0; g < r->groups; g++) {
        if (counts) fprintf(f, "%" LH_INDEX_PRI, r->off[g + 1] - r->off[g]);
        for (lh_index k = r->off[g]; k < r->off[g + 1]; k++)
            fprintf(f, counts ? " %" LH_INDEX_PRI : "%" LH_INDEX_PRI " ", r->idx[k]);
        fputc('\n', f);
    }
}

/* p: the non-redundant halfspaces' dual points (the dual hull's vertices). */
static void print_duals(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    size_t nv = lh_hull_vertex_count(r->hull);
    fprintf(f, "%d\n%zu\n", hs->d, nv);
    for (size_t i = 0; i < nv; i++) {
        lh_cli_qcoords(f, r->dual + (size_t)lh_hull_vertices(r->hull)[i] * hs->d, hs->d);
        fputc('\n', f);
    }
}

/* Fn: each point's neighbouring points (across the sides of its dual facets, other
 * groups, each once, in the order met). */
static int print_neighbours(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    lh_index *seen = malloc((r->groups ? r->groups : 1) * sizeof *seen);
    lh_index *list = malloc((m ? m : 1) * d * sizeof *list);
    lh_index *by = malloc((m ? m : 1) * sizeof *by); /* facets, grouped */
    lh_index *at = calloc(r->groups + 1, sizeof *at);
    if (!seen || !list || !by || !at) {
        free(seen), free(list), free(by), free(at);
        return 0;
    }
    for (size_t t = 0; t < m; t++) at[r->group_of[t] + 1]++;
    for (size_t g = 0; g < r->groups; g++) at[g + 1] += at[g];
    for (size_t t = 0; t < m; t++) by[at[r->group_of[t]]++] = (lh_index)t;
    for (size_t g = r->groups; g > 0; g--) at[g] = at[g - 1];
    at[0] = 0;
    fprintf(f, "%zu\n", r->groups);
    for (size_t g = 0; g < r->groups; g++) seen[g] = -1;
    for (size_t g = 0; g < r->groups; g++) {
        size_t c = 0;
        for (lh_index e = at[g]; e < at[g + 1]; e++)
            for (int k = 0; k < d; k++) {
                lh_index t = r->nbr[(size_t)by[e] * d + k], h = t < 0 ? -1 : r->group_of[t];
                if (h >= 0 && (size_t)h != g && seen[h] != (lh_index)g) seen[h] = (lh_index)g, list[c++] = h;
            }
        fprintf(f, "%zu", c);
        for (size_t k = 0; k < c; k++) fprintf(f, " %" LH_INDEX_PRI, list[k]);
        fputc('\n', f);
    }
    free(seen), free(list), free(by), free(at);
    return 1;
}

/* FN: for every halfspace, the points on it (none for a redundant one). */
static int print_per_halfspace(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    lh_index *at = calloc(hs->n + 1, sizeof *at);
    size_t total = (size_t)r->off[r->groups];
    lh_index *list = malloc((total ? total : 1) * sizeof *list);
    if (!at || !list) {
        free(at), free(list);
        return 0;
    }
    for (size_t k = 0; k < total; k++) at[r->idx[k] + 1]++;
    for (size_t i = 0; i < hs->n; i++) at[i + 1] += at[i];
    for (size_t g = 0; g < r->groups; g++)
        for (lh_index k = r->off[g]; k < r->off[g + 1]; k++) list[at[r->idx[k]]++] = (lh_index)g;
    fprintf(f, "%zu\n", hs->n);
    for (size_t i = 0, from = 0; i < hs->n; from = (size_t)at[i++]) {
        fprintf(f, "%zu", (size_t)at[i] - from);
        for (size_t k = from; k < (size_t)at[i]; k++) fprintf(f, " %" LH_INDEX_PRI, list[k]);
        fputc('\n', f);
    }
    free(at), free(list);
    return 1;
}

static int is_vertex(const lh_cli_hresult *r, lh_index i)
{
    const lh_index *v = lh_hull_vertices(r->hull);
    size_t lo = 0, hi = lh_hull_vertex_count(r->hull); /* increasing */
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (v[mid] < i) lo = mid + 1;
        else hi = mid;
    }
    return lo < lh_hull_vertex_count(r->hull) && v[lo] == i;
}

/* of[i]: the first point whose dual facet halfspace i's dual point lies on, for a
 * redundant halfspace; -1 otherwise. Returns how many have one. */
static size_t coplanar(const lh_cli_halfspaces *hs, const lh_cli_hresult *r, lh_index *of)
{
    const int d = hs->d;
    const lh_index *v = lh_hull_facets(r->hull);
    size_t total = 0;
    for (size_t i = 0; i < hs->n; i++) {
        of[i] = -1;
        if (is_vertex(r, (lh_index)i)) continue;
        const double *p[LH_DELAUNAY_MAX_DIM + 1];
        p[d] = r->dual + i * d;
        for (size_t g = 0; g < r->groups && of[i] < 0; g++) {
            for (int k = 0; k < d; k++) p[k] = r->dual + (size_t)v[(size_t)r->first[g] * d + k] * d;
            if (lh_orient(r->pred, d, p) == 0) of[i] = (lh_index)g;
        }
        total += of[i] >= 0;
    }
    return total;
}

/* Fc: per point, its coplanar halfspaces; FP: per coplanar halfspace the nearest of
 * its point's halfspaces (dual distance, exact; the first of equally near ones),
 * the halfspace, the point and the dual distance. */
static int print_coplanar(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r, int nearest)
{
    const int d = hs->d;
    lh_index *of = malloc((hs->n ? hs->n : 1) * sizeof *of);
    size_t *count = calloc(r->groups ? r->groups : 1, sizeof *count);
    if (!of || !count) {
        free(of), free(count);
        return 0;
    }
    size_t total = coplanar(hs, r, of);
    for (size_t i = 0; i < hs->n; i++)
        if (of[i] >= 0) count[of[i]]++;
    fprintf(f, "%zu\n", nearest ? total : r->groups);
    for (size_t g = 0; !nearest && g < r->groups; g++) {
        fprintf(f, "%zu", count[g]);
        for (size_t i = 0; i < hs->n && count[g]; i++)
            if (of[i] == (lh_index)g) fprintf(f, " %zu", i);
        fputc('\n', f);
    }
    for (size_t i = 0; nearest && i < hs->n; i++) {
        if (of[i] < 0) continue;
        const double *q = r->dual + i * d;
        lh_index best = r->idx[r->off[of[i]]];
        for (lh_index k = r->off[of[i]] + 1; k < r->off[of[i] + 1]; k++)
            if (lh_distance_compare(r->pred, d, q, r->dual + (size_t)r->idx[k] * d,
                                    r->dual + (size_t)best * d) < 0)
                best = r->idx[k];
        double s = 0;
        for (int j = 0; j < d; j++) {
            double e = q[j] - r->dual[(size_t)best * d + j];
            s += e * e;
        }
        fprintf(f, "%" LH_INDEX_PRI " %zu %" LH_INDEX_PRI " %6.16g \n", best, i, of[i], sqrt(s));
    }
    free(of), free(count);
    return 1;
}

/* Fs: ten integers, then two reals (Qhull's outer and inner plane offsets: 0 here,
 * every dual point exactly inside or on every facet). */
static int print_sizes(FILE *f, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    lh_index *of = malloc((hs->n ? hs->n : 1) * sizeof *of);
    if (!of) return 0;
    size_t cop = coplanar(hs, r, of), nv = lh_hull_vertex_count(r->hull), merged = 0;
    free(of);
    for (size_t g = 0; g < r->groups; g++) merged += r->off[g + 1] - r->off[g] > hs->d;
    fprintf(f, "10 %d %zu %zu %zu %zu %zu %zu %zu 0 0\n", hs->d, hs->n, nv, r->groups, nv, r->groups,
            cop, merged);
    fprintf(f, "2 %6.16g %6.16g\n", 0.0, 0.0);
    return 1;
}

static void print_summary(FILE *f, const lh_cli_qopts *o, const lh_cli_halfspaces *hs,
                          const lh_cli_hresult *r)
{
    fprintf(f, "\nHalfspace intersection by the convex hull of %zu points in %d-d:\n\n"
               "  Number of halfspaces: %zu\n  Number of non-redundant halfspaces: %zu\n"
               "  Number of intersection points: %zu\n\nStatistics for: %s\n\n"
               "  Exact arithmetic on the dual points (each rounded once)\n"
               "  CPU seconds to compute the hull: %.3g\n\n",
            hs->n, hs->d, hs->n, lh_hull_vertex_count(r->hull), r->groups, o->command, r->seconds);
}

int lh_cli_qhalf_print(FILE *f, const lh_cli_qopts *o, const lh_cli_halfspaces *hs,
                       const lh_cli_hresult *r, const char *opt)
{
    int ok = 1;
    if (!strcmp(opt, "Fp")) {
        print_points(f, hs, r);
    } else if (!strcmp(opt, "i") || !strcmp(opt, "Fv")) {
        print_incident(f, r, opt[0] == 'F');
    } else if (!strcmp(opt, "Fx")) {
        size_t nv = lh_hull_vertex_count(r->hull);
        fprintf(f, "%zu\n", nv);
        for (size_t i = 0; i < nv; i++) fprintf(f, "%" LH_INDEX_PRI "\n", lh_hull_vertices(r->hull)[i]);
    } else if (!strcmp(opt, "p")) {
        print_duals(f, hs, r);
    } else if (!strcmp(opt, "Fn")) {
        ok = print_neighbours(f, hs, r);
    } else if (!strcmp(opt, "FN")) {
        ok = print_per_halfspace(f, hs, r);
    } else if (!strcmp(opt, "FI") || !strcmp(opt, "Fm")) {
        fprintf(f, "%zu\n", r->groups);
        for (size_t g = 0; g < r->groups; g++)
            fprintf(f, "%zu\n", opt[1] == 'I' ? g : (size_t)(r->facets[g] - 1 < 511 ? r->facets[g] - 1 : 511));
    } else if (!strcmp(opt, "Fc") || !strcmp(opt, "FP")) {
        ok = print_coplanar(f, hs, r, opt[1] == 'P');
    } else if (!strcmp(opt, "Fs")) {
        ok = print_sizes(f, hs, r);
    } else if (!strcmp(opt, "FQ")) {
        fprintf(f, "%s\n", o->command);
    } else {
        print_summary(f, o, hs, r);
    }
    if (!ok) fprintf(stderr, "lifthull qhalf: out of memory\n");
    return ok;
}

int lh_cli_qhalf_verify(const lh_cli_qopts *o, const lh_cli_halfspaces *hs, const lh_cli_hresult *r)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    const lh_index *v = lh_hull_facets(r->hull);
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (size_t t = 0; t < m; t++) {
        for (int k = 0; k < d; k++) p[k] = r->dual + (size_t)v[t * d + k] * d;
        for (size_t i = 0; i < hs->n; i++) {
            p[d] = r->dual + i * d;
            if (lh_orient(r->pred, d, p) > 0) { /* the duals' origin is on the negative side */
                fprintf(stderr, "lifthull %s: Tv: halfspace %zu's dual point is outside dual facet "
                        "%zu: the result is wrong\n", o->name, i, t);
                return 0;
            }
        }
    }
    fprintf(stderr, "lifthull %s: Tv: the exact check passed (every halfspace's dual point inside "
            "or on every facet of the dual hull: each redundant halfspace is implied by the "
            "others, each intersection point bounded)\n", o->name);
    return 1;
}
