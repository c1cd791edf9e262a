/* trimesh_edges.c — the edges of a 2D mesh as Triangle numbers them (its .edge file),
 * and what Triangle builds on them: the Voronoi diagram (-v: FILE.v.node, FILE.v.edge,
 * https://www.cs.cmu.edu/~quake/triangle.voronoi.html and triangle.edge.html) and the
 * midpoint nodes of quadratic elements (-o2, triangle.highorder.html). */
#include "pslg_io.h"
#include "qhull_print.h"

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

/* Triangle t's circumcentre and the barycentric weights w of it in t (for the
 * attributes, extrapolated outside t), from its vertex o, on the edge vectors scaled
 * by 2^-e (lh_triangle_scaled_edges): no square over- or underflows for points near
 * +-DBL_MAX or 1e-300; elsewhere the same doubles as unscaled. The centre is
 * p[o] + u 2^e: c, or where that passes DBL_MAX, (p[o] 2^-e + u) 2^e.
 * From o = the first vertex as a rule. Where the cross product of its two edges is
 * below its rounding error (at most 2^-52 of |bx dy| + |by dx|: Higham 2002, 3.1), the
 * triangle is a needle: then o is an end of the shortest edge, so that the
 * numerators do not cancel (the short edge's terms are the small ones), and the
 * cross product is Kahan's with fma (2 ulps: Jeannerod, Louvet and Muller 2013). */
typedef struct centre {
    const double *a; /* p[o] */
    double u[2], c[2], w[3];
    int e;
} centre;

static void circumcentre(const lh_trimesh *m, size_t t, centre *z)
{
    const double *xy = lh_trimesh_points(m);
    const lh_index *v = lh_trimesh_triangles(m) + 3 * t;
    const double *p[3] = {xy + 2 * (size_t)v[0], xy + 2 * (size_t)v[1], xy + 2 * (size_t)v[2]};
    double ed[3][2];
    const int e = lh_triangle_scaled_edges(p[0], p[1], p[2], ed);
    int o = 0;
    double pq = ed[2][0] * -ed[1][1], qp = ed[2][1] * -ed[1][0], den = 2 * (pq - qp);
    if (!(fabs(pq - qp) > 0x1p-52 * (fabs(pq) + fabs(qp)))) {
        int k = 0; /* the shortest edge, opposite corner k: o = corner k + 1 */
        for (int j = 1; j < 3; j++)
            if (ed[j][0] * ed[j][0] + ed[j][1] * ed[j][1] < ed[k][0] * ed[k][0] + ed[k][1] * ed[k][1]) k = j;
        o = (k + 1) % 3;
        const double *b = ed[(o + 2) % 3], *d = ed[(o + 1) % 3]; /* b - o, o - d */
        qp = b[1] * -d[0];
        den = 2 * (fma(b[0], -d[1], -qp) - fma(b[1], -d[0], -qp));
    }
    const int o1 = (o + 1) % 3, o2 = (o + 2) % 3;
    const double bx = ed[o2][0], by = ed[o2][1], dx = -ed[o1][0], dy = -ed[o1][1]; /* p[o+1] - p[o], p[o+2] - p[o] */
    const double b2 = bx * bx + by * by, d2 = dx * dx + dy * dy;
    const double ux = (dy * b2 - by * d2) / den, uy = (bx * d2 - dx * b2) / den;
    z->a = p[o], z->e = e, z->u[0] = ux, z->u[1] = uy;
    z->c[0] = p[o][0] + ldexp(ux, e), z->c[1] = p[o][1] + ldexp(uy, e);
    /* u = w1 (b - a) + w2 (d - a): Cramer's rule with the same denominator / 2 */
    z->w[o1] = 2 * (ux * dy - uy * dx) / den;
    z->w[o2] = 2 * (bx * uy - by * ux) / den;
    z->w[o] = 1 - z->w[o1] - z->w[o2];
}

/* Coordinate j of the centre as "%.17g", with all its digits where it passes
 * DBL_MAX (docs/meshing.md): as qvoronoi's o and p print such centres. */
static void centre_coordinate(FILE *f, const centre *z, int j)
{
    if (isfinite(z->c[j])) fprintf(f, "%.17g", z->c[j]);
    else lh_cli_qscaled(f, 0, 17, ldexp(z->a[j], -z->e) + z->u[j], z->e);
}

void lh_cli_write_vnode(FILE *f, const lh_trimesh *m, int base)
{
    const size_t nt = lh_trimesh_triangle_count(m);
    const int na = lh_trimesh_point_attr_count(m);
    const double *at = lh_trimesh_point_attrs(m);
    const lh_index *v = lh_trimesh_triangles(m);
    fprintf(f, "%zu  2  %d  0\n", nt, na);
    for (size_t i = 0; i < nt; i++) {
        centre z;
        circumcentre(m, i, &z);
        fprintf(f, "%4lld    ", (long long)i + base);
        centre_coordinate(f, &z, 0);
        fputs("  ", f);
        centre_coordinate(f, &z, 1);
        for (int j = 0; j < na; j++) {
            double x = 0;
            for (int k = 0; k < 3; k++) x += z.w[k] * at[(size_t)v[3 * i + k] * (size_t)na + (size_t)j];
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
