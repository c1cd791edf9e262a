/* trimesh_write.c — a 2D mesh in Triangle's files (.node .ele .poly .edge .neigh,
 * and .off), the formats of https://www.cs.cmu.edu/~quake/triangle.html's file
 * pages: headers "count 2 attributes markers", "count 3 attributes", "count markers",
 * items numbered from the base; neighbour k across from corner k, -1 for none. */
#include "pslg_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "outfile.h"

typedef struct ctx {
    const lh_trimesh *m;
    const lh_cli_tri_files *w;
    lh_index *num;   /* output number of each point (-1: jettisoned) */
    size_t kept;
    lh_cli_edges e;  /* the edges (-e, -v, -o2), or none */
} ctx;

static long long num(const ctx *c, lh_index p) { return (long long)c->num[p] + c->w->base; }

/* (x + y) / 2, or x / 2 + y / 2 where the sum overflows (both near +-DBL_MAX): the
 * same double wherever the sum is finite, never an infinity between finite ends. */
static double mid(double x, double y)
{
    const double s = x + y;
    return isfinite(s) ? s / 2 : x / 2 + y / 2;
}

static void write_node(FILE *f, const ctx *c)
{
    const lh_trimesh *m = c->m;
    const double *xy = lh_trimesh_points(m), *at = lh_trimesh_point_attrs(m);
    const lh_index *mk = lh_trimesh_point_markers(m);
    const int na = lh_trimesh_point_attr_count(m);
    fprintf(f, "%zu  2  %d  %d\n", c->kept + (c->w->order2 ? c->e.n : 0), na, c->w->markers ? 1 : 0);
    for (size_t p = 0; p < lh_trimesh_point_count(m); p++) {
        if (c->num[p] < 0) continue;
        fprintf(f, "%4lld    %.17g  %.17g", num(c, (lh_index)p), xy[2 * p], xy[2 * p + 1]);
        for (int j = 0; j < na; j++) fprintf(f, "  %.17g", at[p * (size_t)na + j]);
        if (c->w->markers) fprintf(f, "    %lld", (long long)mk[p]);
        fputc('\n', f);
    }
    /* -o2: a node at the middle of edge k numbered kept + k, its attributes the
       ends' mean, its marker the edge's (Triangle's rule for a point on an edge) */
    for (size_t k = 0; c->w->order2 && k < c->e.n; k++) {
        const lh_index a = c->e.end[2 * k], b = c->e.end[2 * k + 1];
        fprintf(f, "%4lld    %.17g  %.17g", (long long)(c->kept + k) + c->w->base, mid(xy[2 * a], xy[2 * b]),
                mid(xy[2 * a + 1], xy[2 * b + 1]));
        for (int j = 0; j < na; j++) fprintf(f, "  %.17g", mid(at[a * (size_t)na + j], at[b * (size_t)na + j]));
        if (c->w->markers) fprintf(f, "    %lld", (long long)c->e.mark[k]);
        fputc('\n', f);
    }
}

static void write_ele(FILE *f, const ctx *c)
{
    const lh_trimesh *m = c->m;
    const lh_index *t = lh_trimesh_triangles(m);
    const double *ta = lh_trimesh_triangle_attrs(m);
    const size_t nt = lh_trimesh_triangle_count(m);
    fprintf(f, "%zu  %d  %d\n", nt, c->w->order2 ? 6 : 3, ta ? 1 : 0);
    for (size_t i = 0; i < nt; i++) {
        fprintf(f, "%4lld    %4lld  %4lld  %4lld", (long long)i + c->w->base, num(c, t[3 * i]),
                num(c, t[3 * i + 1]), num(c, t[3 * i + 2]));
        /* -o2: then the midpoints of the edges opposite corners 1, 2, 3 (Triangle's order) */
        for (int j = 0; c->w->order2 && j < 3; j++)
            fprintf(f, "  %4lld", (long long)(c->kept + (size_t)c->e.id[3 * i + j]) + c->w->base);
        if (ta) fprintf(f, "    %.17g", ta[i]);
        fputc('\n', f);
    }
}

static void write_poly(FILE *f, const ctx *c, const lh_pslg *g)
{
    const lh_trimesh *m = c->m;
    const lh_index *s = lh_trimesh_segments(m), *sm = lh_trimesh_segment_markers(m);
    const size_t ns = lh_trimesh_segment_count(m);
    fprintf(f, "0  2  %d  %d\n", lh_trimesh_point_attr_count(m), c->w->markers ? 1 : 0);
    fprintf(f, "%zu  %d\n", ns, c->w->markers ? 1 : 0);
    for (size_t i = 0; i < ns; i++) {
        fprintf(f, "%4lld    %4lld  %4lld", (long long)i + c->w->base, num(c, s[2 * i]), num(c, s[2 * i + 1]));
        if (c->w->markers) fprintf(f, "    %lld", (long long)sm[i]);
        fputc('\n', f);
    }
    fprintf(f, "%zu\n", g->hole_count);
    for (size_t h = 0; h < g->hole_count; h++)
        fprintf(f, "%4lld    %.17g  %.17g\n", (long long)h + c->w->base, g->holes[2 * h], g->holes[2 * h + 1]);
    if (g->region_count) {
        fprintf(f, "%zu\n", g->region_count);
        for (size_t r = 0; r < g->region_count; r++) {
            const double *q = g->regions + 4 * r;
            fprintf(f, "%4lld    %.17g  %.17g  %.17g  %.17g\n", (long long)r + c->w->base, q[0], q[1], q[2], q[3]);
        }
    }
}

static void write_edge(FILE *f, const ctx *c)
{
    fprintf(f, "%zu  %d\n", c->e.n, c->w->markers ? 1 : 0);
    for (size_t k = 0; k < c->e.n; k++) {
        fprintf(f, "%4lld    %4lld  %4lld", (long long)k + c->w->base, num(c, c->e.end[2 * k]),
                num(c, c->e.end[2 * k + 1]));
        if (c->w->markers) fprintf(f, "    %lld", (long long)c->e.mark[k]);
        fputc('\n', f);
    }
}

static void write_neigh(FILE *f, const ctx *c)
{
    const size_t nt = lh_trimesh_triangle_count(c->m);
    const lh_index *nb = lh_trimesh_neighbors(c->m);
    fprintf(f, "%zu  3\n", nt);
    for (size_t i = 0; i < nt; i++) {
        fprintf(f, "%4lld", (long long)i + c->w->base);
        for (int j = 0; j < 3; j++)
            fprintf(f, "  %4lld", nb[3 * i + j] < 0 ? -1LL : (long long)nb[3 * i + j] + c->w->base);
        fputc('\n', f);
    }
}

static void write_off(FILE *f, const ctx *c)
{
    const lh_trimesh *m = c->m;
    const double *xy = lh_trimesh_points(m);
    const lh_index *t = lh_trimesh_triangles(m);
    const size_t nt = lh_trimesh_triangle_count(m);
    fprintf(f, "OFF\n%zu  %zu  0\n", c->kept, nt);
    for (size_t p = 0; p < lh_trimesh_point_count(m); p++)
        if (c->num[p] >= 0) fprintf(f, "%.17g  %.17g  0\n", xy[2 * p], xy[2 * p + 1]);
    for (size_t i = 0; i < nt; i++)
        fprintf(f, "3  %lld  %lld  %lld\n", (long long)c->num[t[3 * i]], (long long)c->num[t[3 * i + 1]],
                (long long)c->num[t[3 * i + 2]]);
}

/* Point numbers: all points, or (j) only those in a triangle, in order. */
static int number_points(ctx *c)
{
    const size_t np = lh_trimesh_point_count(c->m), nt = lh_trimesh_triangle_count(c->m);
    const lh_index *t = lh_trimesh_triangles(c->m);
    c->num = malloc((np ? np : 1) * sizeof *c->num);
    if (!c->num) return 0;
    for (size_t p = 0; p < np; p++) c->num[p] = c->w->jettison ? -1 : 0;
    if (c->w->jettison)
        for (size_t i = 0; i < 3 * nt; i++) c->num[t[i]] = 0;
    c->kept = 0;
    for (size_t p = 0; p < np; p++)
        if (c->num[p] >= 0) c->num[p] = (lh_index)c->kept++;
    return 1;
}

/* BASE.node etc. for the files w asks for (lh_cli_paths: NULL where not wanted); 0
 * when out of memory. */
static const char *const tri_ext[] = {".node", ".ele", ".poly", ".edge", ".neigh", ".off", ".v.node", ".v.edge"};
enum { nfiles = 8 };

static int tri_paths(const char *base, const lh_cli_tri_files *w, char *path[nfiles])
{
    const int want[nfiles] = {w->node, w->ele, w->poly, w->edge, w->neigh, w->off, w->voronoi, w->voronoi};
    return lh_cli_paths(base, strlen(base), tri_ext, want, nfiles, path);
}

int lh_cli_trimesh_check(const char *base, const lh_cli_tri_files *w, const char *input, const char *cmd)
{
    char *path[nfiles];
    int ok = tri_paths(base, w, path);
    if (!ok) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    for (int i = 0; i < nfiles && ok; i++)
        if (path[i]) ok = lh_cli_out_check(cmd, path[i], !w->no_replace, input);
    lh_cli_paths_free(path, nfiles);
    return ok;
}

/* File i of tri_ext; write errors show at the close (lh_cli_outset_close). */
static void write_file(int i, FILE *f, const ctx *c, const lh_pslg *g)
{
    switch (i) {
    case 0: write_node(f, c); break;
    case 1: write_ele(f, c); break;
    case 2: write_poly(f, c, g); break;
    case 3: write_edge(f, c); break;
    case 4: write_neigh(f, c); break;
    case 5: write_off(f, c); break;
    case 6: lh_cli_write_vnode(f, c->m, c->w->base); break;
    default: lh_cli_write_vedge(f, c->m, &c->e, c->w->base); break;
    }
}

int lh_cli_trimesh_write(const lh_trimesh *m, const lh_cli_pslg *in, const char *base,
                         const lh_cli_tri_files *w, const char *cmd)
{
    char *path[nfiles];
    FILE *f[nfiles] = {0};
    ctx c = {m, w, NULL, 0, {0, NULL, NULL, NULL, NULL}};
    int ok = tri_paths(base, w, path);
    ok = ok && number_points(&c) && (!(w->edge || w->voronoi || w->order2) || lh_cli_edges_build(&c.e, m));
    if (!ok) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    /* every target checked and its temporary opened before anything is written */
    lh_cli_outset set;
    lh_cli_outset_init(&set, cmd, !w->no_replace, in->path);
    for (int i = 0; i < nfiles && ok; i++) {
        if (!path[i]) continue;
        /* Triangle replaces its outputs; the inputs themselves never */
        if (lh_cli_same_file(path[i], in->node_path)) {
            fprintf(stderr, "lifthull %s: '%s' is an input file; it is not overwritten\n", cmd, path[i]);
            ok = 0;
        } else {
            ok = (f[i] = lh_cli_outset_add(&set, path[i])) != NULL;
        }
    }
    for (int i = 0; i < nfiles && ok; i++)
        if (f[i]) write_file(i, f[i], &c, &in->g);
    /* all or none: renamed only when every file was written */
    const int rc = lh_cli_outset_close(&set, ok);
    lh_cli_paths_free(path, nfiles);
    free(c.num);
    lh_cli_edges_free(&c.e);
    return rc;
}
