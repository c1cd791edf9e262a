/*
 * tetgen_check.c — lh_tetmesh_check on a mesh in TetGen's files, for the tests that
 * compare it with the independent checker (tetgen_oracle.sh, check_tetmesh.py).
 *
 *     tetgen_check BASE [INPUT.off]
 *
 * reads BASE.node, BASE.ele, BASE.face, BASE.edge (absent files: none), numbered
 * from the .node file's first index; with INPUT.off also the PLC (each OFF face a
 * facet of one polygon, its points the mesh's first ones) and checks conformity to
 * it, subfaces matched to facets by containment. Prints "BASE: valid (off_exact N)"
 * and exits 0, or prints the checker's message and exits 1; 2 for unreadable files.
 */
#include "lifthull.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The next line with something on it other than a comment, or NULL. */
static char *next_line(FILE *f, char *buf, size_t size)
{
    while (fgets(buf, (int)size, f)) {
        char *p = buf + strspn(buf, " \t\r");
        if (*p && *p != '#' && *p != '\n') return p;
    }
    return NULL;
}

/* Reads a TetGen cell file: count, then per line an index and `per` point numbers. */
static lh_index *read_cells(const char *base, const char *ext, int per, long first, size_t *count)
{
    char path[1024], buf[4096];
    snprintf(path, sizeof path, "%s%s", base, ext);
    *count = 0;
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    char *p = next_line(f, buf, sizeof buf);
    const long n = p ? strtol(p, NULL, 10) : -1;
    lh_index *v = n >= 0 ? malloc(((size_t)n * (size_t)per + 1) * sizeof *v) : NULL;
    for (long i = 0; v && i < n; i++) {
        if (!(p = next_line(f, buf, sizeof buf))) break;
        strtol(p, &p, 10);
        for (int k = 0; k < per; k++) v[(size_t)i * (size_t)per + (size_t)k] = (lh_index)(strtol(p, &p, 10) - first);
        *count = (size_t)i + 1;
    }
    fclose(f);
    return v;
}

static double *read_node(const char *base, size_t *n, long *first)
{
    char path[1024], buf[4096];
    snprintf(path, sizeof path, "%s.node", base);
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    char *p = next_line(f, buf, sizeof buf);
    const long cnt = p ? strtol(p, NULL, 10) : -1;
    double *xyz = cnt >= 0 ? malloc(((size_t)cnt * 3 + 1) * sizeof *xyz) : NULL;
    *n = 0;
    for (long i = 0; xyz && i < cnt && (p = next_line(f, buf, sizeof buf)); i++) {
        const long id = strtol(p, &p, 10);
        if (i == 0) *first = id;
        for (int k = 0; k < 3; k++) xyz[3 * i + k] = strtod(p, &p);
        *n = (size_t)i + 1;
    }
    fclose(f);
    return xyz;
}

/* The OFF file's faces as one-polygon facets of g (points: set by the caller). */
static int read_off(const char *path, lh_plc *g, lh_index **arrays)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char word[64];
    long nv = -1, nf = -1, ne = 0;
    int ok = fscanf(f, " %63s", word) == 1;
    if (ok && strstr(word, "OFF")) ok = fscanf(f, "%ld %ld %ld", &nv, &nf, &ne) == 3;
    else ok = 0;
    for (long i = 0; ok && i < 3 * nv; i++) {
        double x;
        ok = fscanf(f, "%lf", &x) == 1;
    }
    size_t cap = 16 * (size_t)(nf > 0 ? nf : 1), used = 0;
    lh_index *ff = ok ? malloc(((size_t)nf + 1) * sizeof *ff) : NULL;
    lh_index *pf = ok ? malloc(((size_t)nf + 1) * sizeof *pf) : NULL;
    lh_index *pv = ok ? malloc(cap * sizeof *pv) : NULL;
    ok = ok && ff && pf && pv;
    for (long i = 0; ok && i < nf; i++) {
        long k;
        ok = fscanf(f, "%ld", &k) == 1 && k >= 1 && (size_t)k <= cap - used;
        ff[i] = (lh_index)i, pf[i] = (lh_index)used;
        for (long j = 0; ok && j < k; j++) {
            long v;
            ok = fscanf(f, "%ld", &v) == 1;
            pv[used++] = (lh_index)v;
            char rest[256];
            if (ok && j == k - 1 && !fgets(rest, sizeof rest, f)) rest[0] = 0; /* colours */
        }
    }
    fclose(f);
    if (ok) {
        ff[nf] = (lh_index)nf, pf[nf] = (lh_index)used;
        g->n = (size_t)nv, g->facet_count = g->polygon_count = (size_t)nf;
        g->facet_first = ff, g->polygon_first = pf, g->polygon_vertices = pv;
    }
    arrays[0] = ff, arrays[1] = pf, arrays[2] = pv;
    return ok;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: tetgen_check BASE [INPUT.off]\n");
        return 2;
    }
    const char *base = argv[1];
    size_t n = 0, nt, nf, ne;
    long first = 0;
    double *xyz = read_node(base, &n, &first);
    lh_index *tets = read_cells(base, ".ele", 4, first, &nt);
    lh_index *faces = read_cells(base, ".face", 3, first, &nf);
    lh_index *edges = read_cells(base, ".edge", 2, first, &ne);
    lh_plc g;
    memset(&g, 0, sizeof g);
    lh_index *arrays[3] = {NULL, NULL, NULL};
    int rc = 2;
    if (!xyz || !tets) fprintf(stderr, "%s: cannot read the .node or .ele file\n", base);
    else if (argc == 3 && !read_off(argv[2], &g, arrays)) fprintf(stderr, "%s: cannot read\n", argv[2]);
    else {
        size_t off = 0;
        lh_error err;
        const lh_status st = lh_tetmesh_check(n, xyz, nt, tets, nf, faces, NULL, ne, edges, 0,
                                              argc == 3 ? &g : NULL, &off, NULL, &err);
        if (st == LH_OK) printf("%s: valid (off_exact %zu)\n", base, off);
        else printf("%s: %s: %s\n", base, lh_status_name(st), err.message);
        rc = st == LH_OK ? 0 : 1;
    }
    for (int i = 0; i < 3; i++) free(arrays[i]);
    free(xyz), free(tets), free(faces), free(edges);
    return rc;
}
