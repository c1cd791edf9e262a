/* trimesh_edges.c — the edges of a 2D mesh as Triangle numbers them (its .edge file),
 * and what Triangle builds on them: the Voronoi diagram (-v: FILE.v.node, FILE.v.edge,
 * https://www.cs.cmu.edu/~quake/triangle.voronoi.html and triangle.edge.html) and the
 * midpoint nodes of quadratic elements (-o2, triangle.highorder.html). */
#include "pslg_io.h"

#include <math.h>
#include <stdlib.h>

/* The subsegment lying on edge a-b, if any (its marker): a sorted lookup. */
typedef struct segkey { lh_index lo, hi, mk; } segkey;
static int segkey_cmp(const void *x, const void *y)
{
    const segkey *a = x, *b = y;
    return a->lo != b->lo ? (a->lo < b->lo ? -1 : 1) : a->hi != b->hi ? (a->hi < b->hi ? -1 : 1) : 0;
}

void lh_cli_edges_free(lh_cli_edges *e)
{
    free(e->id);
    free(e->end);
    free(e->mark);
    free(e->tri);
    e->id = e->end = e->mark = e->tri = NULL;
    e->n = 0;
}

/* Markers: each edge's subsegment's, else 0 (every boundary edge is a subsegment). */
static int mark_edges(lh_cli_edges *e, const lh_trimesh *m)
{
    const size_t ns = lh_trimesh_segment_count(m);
    const lh_index *s = lh_trimesh_segments(m), *sm = lh_trimesh_segment_markers(m);
    segkey *k = malloc((ns ? ns : 1) * sizeof *k);
    if (!k) return 0;
    for (size_t i = 0; i < ns; i++) {
        const lh_index a = s[2 * i], b = s[2 * i + 1];
        k[i] = (segkey){a < b ? a : b, a < b ? b : a, sm[i]};
    }
    qsort(k, ns, sizeof *k, segkey_cmp);
    for (size_t i = 0; i < e->n; i++) {
        const lh_index a = e->end[2 * i], b = e->end[2 * i + 1];
        const segkey key = {a < b ? a : b, a < b ? b : a, 0};
        const segkey *hit = bsearch(&key, k, ns, sizeof *k, segkey_cmp);
        e->mark[i] = hit ? hit->mk : 0;
    }
    free(k);
    return 1;
}

int lh_cli_edges_build(lh_cli_edges *e, const lh_trimesh *m)
{
    const size_t nt = lh_trimesh_triangle_count(m);
    const lh_index *t = lh_trimesh_triangles(m), *nb = lh_trimesh_neighbors(m);
    size_t ne = 0;
    for (size_t i = 0; i < 3 * nt; i++) ne += nb[i] < 0 || (size_t)nb[i] > i / 3;
    e->n = ne;
    e->id = malloc((nt ? 3 * nt : 1) * sizeof *e->id);
    e->end = malloc((ne ? 2 * ne : 1) * sizeof *e->end);
    e->mark = malloc((ne ? ne : 1) * sizeof *e->mark);
    e->tri = malloc((ne ? 2 * ne : 1) * sizeof *e->tri);
    if (!e->id || !e->end || !e->mark || !e->tri) {
        lh_cli_edges_free(e);
        return 0;
    }
    size_t k = 0;
    for (size_t i = 0; i < nt; i++)
        for (int j = 0; j < 3; j++) {
            const lh_index n = nb[3 * i + j];
            if (n >= 0 && (size_t)n < i) { /* numbered at n, the edge across from i */
                int q = 0;
                while (q < 2 && nb[3 * (size_t)n + q] != (lh_index)i) q++;
                e->id[3 * i + j] = e->id[3 * (size_t)n + q];
                continue;
            }
            e->id[3 * i + j] = (lh_index)k;
            e->end[2 * k] = t[3 * i + (j + 1) % 3];
            e->end[2 * k + 1] = t[3 * i + (j + 2) % 3];
            e->tri[2 * k] = (lh_index)i;
            e->tri[2 * k + 1] = n;
            k++;
        }
    if (!mark_edges(e, m)) {
        lh_cli_edges_free(e);
        return 0;
    }
    return 1;
}

/* Triangle t's circumcentre c and the barycentric weights w of c in t (for the
 * attributes, extrapolated outside t), from t's first vertex, on the edge vectors
 * scaled by a power of two (lh_cli_scaled_edges): no square over- or underflows for
 * points near +-DBL_MAX or 1e-300; elsewhere the same doubles as unscaled. */
static void circumcentre(const lh_trimesh *m, size_t t, double c[2], double w[3])
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *v = lh_trimesh_triangles(m) + 3 * t;
    const double *p[3] = {xy + 2 * (size_t)v[0], xy + 2 * (size_t)v[1], xy + 2 * (size_t)v[2]};
    double ed[3][2];
    long e;
    lh_cli_scaled_edges(p, ed, &e);
    const double *a = p[0];
    const double bx = ed[2][0], by = ed[2][1], dx = -ed[1][0], dy = -ed[1][1]; /* b - a, d - a */
    const double den = 2 * (bx * dy - by * dx), b2 = bx * bx + by * by, d2 = dx * dx + dy * dy;
    const double ux = (dy * b2 - by * d2) / den, uy = (bx * d2 - dx * b2) / den;
    c[0] = a[0] + ldexp(ux, (int)e), c[1] = a[1] + ldexp(uy, (int)e);
    /* u = w1 (b - a) + w2 (d - a): Cramer's rule with the same denominator / 2 */
    w[1] = 2 * (ux * dy - uy * dx) / den;
    w[2] = 2 * (bx * uy - by * ux) / den;
    w[0] = 1 - w[1] - w[2];
}

void lh_cli_write_vnode(FILE *f, const lh_trimesh *m, int base)
{
    const size_t nt = lh_trimesh_triangle_count(m);
    const int na = lh_trimesh_point_attr_count(m);
    const double *at = lh_trimesh_point_attrs(m);
    const lh_index *v = lh_trimesh_triangles(m);
    fprintf(f, "%zu  2  %d  0\n", nt, na);
    for (size_t i = 0; i < nt; i++) {
        double c[2], w[3];
        circumcentre(m, i, c, w);
        fprintf(f, "%4lld    %.17g  %.17g", (long long)i + base, c[0], c[1]);
        for (int j = 0; j < na; j++) {
            double x = 0;
            for (int k = 0; k < 3; k++) x += w[k] * at[(size_t)v[3 * i + k] * (size_t)na + (size_t)j];
            fprintf(f, "  %.17g", x);
        }
        fputc('\n', f);
    }
}

void lh_cli_write_vedge(FILE *f, const lh_trimesh *m, const lh_cli_edges *e, int base)
{
    const double *xy = lh_trimesh_points(m);
    fprintf(f, "%zu  0\n", e->n);
    for (size_t k = 0; k < e->n; k++) {
        const lh_index t = e->tri[2 * k], n = e->tri[2 * k + 1];
        fprintf(f, "%4lld    %4lld  ", (long long)k + base, (long long)t + base);
        if (n >= 0) {
            fprintf(f, "%4lld\n", (long long)n + base);
            continue;
        }
        /* a ray: outward across the hull edge a -> b (counterclockwise in t), its
           direction the edge turned clockwise, as long as the edge (half as long where
           that overflows, near +-DBL_MAX: a direction, never an infinity) */
        const double *a = xy + 2 * (size_t)e->end[2 * k], *b = xy + 2 * (size_t)e->end[2 * k + 1];
        double dx = b[1] - a[1], dy = a[0] - b[0];
        if (!isfinite(dx) || !isfinite(dy)) dx = b[1] / 2 - a[1] / 2, dy = a[0] / 2 - b[0] / 2;
        fprintf(f, "  -1    %.17g  %.17g\n", dx, dy);
    }
}
