/* io_tool.c — a driver of the file formats for the scripted tests (tests/io/):
 *   io_tool read FILE [auto|qhull|node|columns]
 *       reads FILE (or "-": standard input); prints "FORMAT d n first_index attr_count
 *       markers" and then every point's coordinates ("%.17g"), attributes and marker;
 *       on failure the reader's one-line message on stderr and exit status 3.
 *   io_tool mesh FILE PREFIX
 *       reads FILE, triangulates it (lh_delaunay) and writes PREFIX.vtu, .msh, .node,
 *       .ele, .neigh (first index 1), and .off when d = 2; the values are 0.5 * index. */
#include "lifthull.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int read_points(const char *file, lh_format fmt, lh_points *p)
{
    lh_error err;
    FILE *f = strcmp(file, "-") ? fopen(file, "rb") : stdin;
    if (!f) {
        perror(file);
        return 0;
    }
    lh_status st = lh_points_read(f, file, fmt, NULL, p, &err);
    if (f != stdin) fclose(f);
    if (st != LH_OK) fprintf(stderr, "%s [%s]\n", err.message, lh_status_name(st));
    return st == LH_OK;
}

static int print_points(const lh_points *p)
{
    printf("%s %d %zu %d %d %d\n", lh_format_name(p->format), p->d, p->n, p->first_index,
           p->attr_count, p->marker != NULL);
    for (size_t i = 0; i < p->n; i++) {
        for (int j = 0; j < p->d; j++) printf("%s%.17g", j ? " " : "", p->xyz[i * (size_t)p->d + j]);
        for (int j = 0; j < p->attr_count; j++) printf(" %.17g", p->attr[i * (size_t)p->attr_count + j]);
        if (p->marker) printf(" %" LH_INDEX_PRI, p->marker[i]);
        printf("\n");
    }
    return 0;
}

typedef lh_status (*writer)(FILE *f, const lh_mesh_view *m);

/* The ASCII .vtu (lh_vtu_write with ascii set). */
static lh_status vtu_ascii(FILE *f, const lh_mesh_view *m)
{
    const lh_vtu_options o = {1, NULL, NULL};
    return lh_vtu_write(f, m, &o);
}

/* The binary .vtu, with a cell field "quarter" (cell i: i / 4). */
static lh_status vtu_binary(FILE *f, const lh_mesh_view *m)
{
    double *q = malloc((m->count ? m->count : 1) * sizeof *q);
    if (!q) return LH_ERR_NOMEM;
    for (size_t i = 0; i < m->count; i++) q[i] = 0.25 * (double)i;
    const lh_vtu_options o = {0, q, "quarter"};
    lh_status st = lh_vtu_write(f, m, &o);
    free(q);
    return st;
}

static int write_one(const char *prefix, const char *ext, const lh_mesh_view *m, writer w,
                     lh_status (*wi)(FILE *, const lh_mesh_view *, int))
{
    char path[4096];
    snprintf(path, sizeof path, "%s.%s", prefix, ext);
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        return 1;
    }
    lh_status st = w ? w(f, m) : wi(f, m, 1);
    if (fclose(f) != 0 && st == LH_OK) st = LH_ERR_IO;
    if (st != LH_OK) fprintf(stderr, "%s: %s\n", path, lh_status_message(st));
    return st != LH_OK;
}

static int mesh(const lh_points *p, const char *prefix)
{
    lh_tri *t;
    lh_status st = lh_delaunay(p->d, p->n, p->xyz, NULL, &t);
    if (st != LH_OK) {
        fprintf(stderr, "delaunay: %s\n", lh_status_message(st));
        return 1;
    }
    double *values = malloc(p->n * sizeof *values);
    if (!values) return 1;
    for (size_t i = 0; i < p->n; i++) values[i] = 0.5 * (double)i;
    lh_mesh_view m = {p->d, p->n, p->xyz, lh_tri_simplex_dim(t), lh_tri_count(t),
                      lh_tri_simplices(t), lh_tri_neighbors(t), values, "half_index"};
    int bad = write_one(prefix, "vtu", &m, vtu_ascii, NULL) +
              write_one(prefix, "bin.vtu", &m, vtu_binary, NULL) +
              write_one(prefix, "msh", &m, lh_msh_write, NULL) +
              write_one(prefix, "node", &m, NULL, lh_node_write) +
              write_one(prefix, "ele", &m, NULL, lh_ele_write) +
              write_one(prefix, "neigh", &m, NULL, lh_neigh_write);
    if (p->d == 2) bad += write_one(prefix, "off", &m, lh_off_write, NULL);
    free(values);
    lh_tri_free(t);
    return bad != 0;
}

int main(int argc, char **argv)
{
    static const char *names[] = {"auto", "qhull", "node", "columns"};
    lh_format fmt = LH_FORMAT_AUTO;
    if (argc < 3 || (strcmp(argv[1], "read") && strcmp(argv[1], "mesh"))) {
        fprintf(stderr, "usage: io_tool read FILE [FORMAT] | io_tool mesh FILE PREFIX\n");
        return 2;
    }
    if (!strcmp(argv[1], "read") && argc > 3)
        for (int i = 0; i < 4; i++)
            if (!strcmp(argv[3], names[i])) fmt = (lh_format)i;
    lh_points p;
    if (!read_points(argv[2], fmt, &p)) return 3;
    int rc = !strcmp(argv[1], "read") ? print_points(&p) : argc > 3 ? mesh(&p, argv[3]) : 2;
    lh_points_free(&p);
    return rc;
}
