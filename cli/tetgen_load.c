/* tetgen_load.c — reading a 3D meshing input for `tetgen` and `mesh` (tetgen_io.h):
 * any format lh_plc_read knows (a .poly without points takes BASE.node's), or a
 * .node point set read as points; and what is said about it: failures, -d's
 * intersecting facets, -C's verdict, the summary and -V's statistics. */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include "tetgen_io.h"

#include "cli.h"
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static const char *const plc_ext[] = {".poly", ".smesh", ".node", ".off", ".ply", ".stl", ".mesh", ".obj"};
enum { n_plc_ext = sizeof plc_ext / sizeof plc_ext[0] };

int lh_cli_plc_path(const char *path, size_t *stem)
{
    const size_t n = strlen(path);
    for (int i = 0; i < n_plc_ext; i++) {
        const size_t e = strlen(plc_ext[i]);
        if (n > e && !strcasecmp(path + n - e, plc_ext[i]) && path[n - e - 1] != '/') {
            *stem = n - e;
            return 1;
        }
    }
    return 0;
}

/* path opened for reading (binary formats too), or NULL after "lifthull CMD: PATH: ...". */
static FILE *open_input(const char *cmd, const char *path)
{
    FILE *f = fopen(path, "rb");
    struct stat st;
    if (!f) fprintf(stderr, "lifthull %s: %s: %s\n", cmd, path, strerror(errno));
    else if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fprintf(stderr, "lifthull %s: %s: is a directory, not an input file\n", cmd, path);
        fclose(f);
        f = NULL;
    }
    return f;
}

static void say(const char *cmd, const char *path, const lh_error *err, lh_status st)
{
    if (err->message[0]) fprintf(stderr, "lifthull %s: %s\n", cmd, err->message);
    else fprintf(stderr, "lifthull %s: %s: %s\n", cmd, path, lh_status_message(st));
}

/* Points of a .node file (3 coordinates) into p. */
static int read_points(const char *cmd, const char *path, lh_points *p)
{
    FILE *f = open_input(cmd, path);
    if (!f) return 0;
    lh_error err;
    lh_status st = lh_points_read(f, path, LH_FORMAT_NODE, NULL, p, &err);
    fclose(f);
    if (st != LH_OK) say(cmd, path, &err, st);
    else if (p->d != 3) fprintf(stderr, "lifthull %s: %s: the points have %d coordinates; 3D meshing needs 3\n",
                                cmd, path, p->d);
    return st == LH_OK && p->d == 3;
}

/* A .poly that lists no points: BASE.node's, as TetGen reads them. */
static int attach_node(lh_cli_plc *in, const char *cmd, size_t stem)
{
    in->node_path = lh_cli_path_ext(in->path, stem, ".node");
    if (!in->node_path) return 0;
    lh_points p;
    memset(&p, 0, sizeof p);
    int ok = read_points(cmd, in->node_path, &p);
    lh_status st = ok ? lh_plc_take_points(&in->g, &p) : LH_OK;
    if (st != LH_OK) fprintf(stderr, "lifthull %s: %s: %s\n", cmd, in->node_path, lh_status_message(st));
    lh_points_free(&p);
    return ok && st == LH_OK;
}

/* Whether f (rewound after) is a binary PLY ("format binary_..." in its header) or
 * STL (a NUL among its first bytes: the 80-byte header's padding or the count). */
static int binary_input(FILE *f)
{
    char head[513];
    const size_t n = fread(head, 1, sizeof head - 1, f);
    rewind(f);
    head[n] = 0;
    return strlen(head) < n || strstr(head, "\nformat binary") != NULL;
}

int lh_cli_plc_load(lh_cli_plc *in, const char *cmd, const char *path)
{
    memset(in, 0, sizeof *in);
    in->path = path;
    size_t stem = strlen(path);
    const int known = lh_cli_plc_path(path, &stem);
    int ok;
    if (known && !strcasecmp(path + stem, ".node")) {
        ok = read_points(cmd, path, &in->pts);
        in->g.n = in->pts.n;
        in->g.xyz = in->pts.xyz;
        in->g.attr_count = in->pts.attr_count;
        in->g.attr = in->pts.attr;
        in->g.point_marker = in->pts.marker;
        in->g.first_index = in->pts.first_index;
    } else {
        FILE *f = open_input(cmd, path);
        if (!f) return 0;
        in->binary = binary_input(f);
        lh_error err;
        lh_status st = lh_plc_read(f, path, LH_PLC_AUTO, NULL, &in->g, &err);
        fclose(f);
        in->read = st == LH_OK;
        if (st != LH_OK) say(cmd, path, &err, st);
        ok = st == LH_OK && (in->g.n > 0 || attach_node(in, cmd, stem));
        if (ok && in->g.n == 0) fprintf(stderr, "lifthull %s: %s: no points\n", cmd, path), ok = 0;
    }
    if (!ok) lh_cli_plc_free(in);
    return ok;
}

/* The tets of BASE.ele (4 points each; the first attribute of each, if any, into
 * *attr, malloc'ed): 1, or 0 after printing the problem. */
static int read_tets(const char *cmd, const char *path, size_t n, lh_cells *c, double **attr)
{
    FILE *f = open_input(cmd, path);
    if (!f) return 0;
    lh_error err;
    lh_status st = lh_cells_read(f, path, n, NULL, c, &err);
    fclose(f);
    if (st != LH_OK) return say(cmd, path, &err, st), 0;
    if (c->nv != 4) {
        fprintf(stderr, "lifthull %s: %s: cells of %d points; a tetrahedral mesh has 4\n", cmd, path, c->nv);
        return 0;
    }
    *attr = c->attr_count ? malloc((c->count ? c->count : 1) * sizeof **attr) : NULL;
    if (c->attr_count && !*attr) return fprintf(stderr, "lifthull %s: out of memory\n", cmd), 0;
    for (size_t t = 0; *attr && t < c->count; t++) (*attr)[t] = c->attr[t * (size_t)c->attr_count];
    return 1;
}

int lh_cli_mesh_load(lh_cli_plc *in, const char *cmd, const char *node_path, size_t stem)
{
    memset(in, 0, sizeof *in);
    in->path = node_path;
    lh_points p;
    lh_cells c;
    double *attr = NULL;
    memset(&p, 0, sizeof p), memset(&c, 0, sizeof c);
    char *ele = lh_cli_path_ext(node_path, stem, ".ele");
    int ok = ele && read_points(cmd, node_path, &p) && read_tets(cmd, ele, p.n, &c, &attr);
    if (!ele) fprintf(stderr, "lifthull %s: out of memory\n", cmd);
    lh_error err;
    lh_status st = ok ? lh_plc_from_tetmesh(p.n, p.xyz, p.marker, c.count, c.v, attr, NULL, &in->g, &err) : LH_OK;
    if (st != LH_OK)
        fprintf(stderr, "lifthull %s: %s: %s%s\n", cmd, ele, err.message[0] ? err.message : lh_status_message(st),
                st == LH_ERR_INVALID_MESH || st == LH_ERR_DEGENERATE ? " (tetrahedra and points numbered from 0)" : "");
    in->read = ok = ok && st == LH_OK;
    in->g.first_index = p.first_index;
    lh_points_free(&p), lh_cells_free(&c);
    free(attr), free(ele);
    if (!ok) lh_cli_plc_free(in);
    return ok;
}

void lh_cli_plc_free(lh_cli_plc *in)
{
    if (in->read) lh_plc_free(&in->g);
    lh_points_free(&in->pts);
    free(in->node_path);
    memset(in, 0, sizeof *in);
}

int lh_cli_plc_is_points(const lh_cli_plc *in) { return !in->g.facet_count && !in->g.segment_count; }

void lh_cli_plc_points_only(lh_cli_plc *in)
{
    lh_plc *g = &in->g;
    g->facet_count = g->polygon_count = g->segment_count = g->hole_count = g->region_count = 0;
}

void lh_cli_plc_report(const lh_cli_plc *in, const char *cmd, const lh_error *err)
{
    if (err->message[0] && !strncmp(err->message, in->path, strlen(in->path)))
        fprintf(stderr, "lifthull %s: %s\n", cmd, err->message);
    else
        fprintf(stderr, "lifthull %s: %s: %s\n", cmd, in->path,
                err->message[0] ? err->message : lh_status_message(err->status));
}

int lh_cli_plc_exit(lh_status st)
{
    return st == LH_ERR_NOMEM || st == LH_ERR_INTERNAL || st == LH_ERR_IO ? LH_EXIT_FAIL : LH_EXIT_INPUT;
}

/* " (line L)" when the reader kept facet f's line, " (record R)" in a binary file. */
static void facet_place(FILE *out, const lh_cli_plc *in, lh_index f)
{
    if (in->g.facet_line) fprintf(out, " (%s %zu)", in->binary ? "record" : "line", in->g.facet_line[f]);
}

int lh_cli_plc_intersections(FILE *out, const lh_cli_plc *in, const char *cmd, size_t limit, int first)
{
    lh_error err;
    size_t count = 0;
    lh_status st = lh_plc_intersections(&in->g, NULL, 0, NULL, &count, &err);
    const size_t cap = limit && limit < count ? limit : count;
    lh_index *pairs = st == LH_OK && cap ? malloc(2 * cap * sizeof *pairs) : NULL;
    if (st == LH_OK && cap && !pairs) st = err.status = LH_ERR_NOMEM, err.message[0] = 0;
    if (st == LH_OK && cap) st = lh_plc_intersections(&in->g, NULL, cap, pairs, &count, &err);
    if (st != LH_OK) {
        lh_cli_plc_report(in, cmd, &err);
        free(pairs);
        return -1;
    }
    for (size_t i = 0; i < cap; i++) {
        fprintf(out, "%s: facet %lld", in->path, (long long)pairs[2 * i] + first);
        facet_place(out, in, pairs[2 * i]);
        fprintf(out, " and facet %lld", (long long)pairs[2 * i + 1] + first);
        facet_place(out, in, pairs[2 * i + 1]);
        fprintf(out, " intersect\n");
    }
    if (!count) fprintf(out, "%s: no facets intersect (%zu facets)\n", in->path, in->g.facet_count);
    else if (cap < count) fprintf(out, "%s: %zu pairs of facets intersect; the first %zu %s listed\n", in->path,
                                  count, cap, cap == 1 ? "is" : "are");
    else fprintf(out, "%s: %zu pair%s of facets intersect\n", in->path, count, count == 1 ? "" : "s");
    free(pairs);
    return count > 0;
}

int lh_cli_tetmesh_verify(FILE *out, const lh_tetmesh *m, const lh_cli_plc *in, const char *cmd)
{
    lh_error err;
    size_t off = 0;
    const lh_plc *g = in->g.facet_count || in->g.segment_count ? &in->g : NULL;
    lh_status st = lh_tetmesh_check(lh_tetmesh_point_count(m), lh_tetmesh_points(m), lh_tetmesh_tet_count(m),
                                    lh_tetmesh_tets(m), lh_tetmesh_face_count(m), lh_tetmesh_faces(m),
                                    lh_tetmesh_face_parents(m), lh_tetmesh_edge_count(m), lh_tetmesh_edges(m), 0,
                                    g, &off, NULL, &err);
    if (st == LH_OK) {
        fprintf(out, "check: the mesh is valid%s (exact; %zu Steiner points on their facet or segment "
                     "up to rounding only)\n", g ? " and conforms to the input" : "", off);
        return 1;
    }
    if (st == LH_ERR_INVALID_MESH) {
        fprintf(out, "check: the mesh is NOT valid: %s\n", err.message[0] ? err.message : lh_status_message(st));
        return 0;
    }
    fprintf(stderr, "lifthull %s: the check could not run: %s\n", cmd, err.message[0] ? err.message : lh_status_message(st));
    return 0;
}

void lh_cli_tetmesh_summary(FILE *out, const char *name, const lh_tetmesh *m, double secs)
{
    lh_tetmesh_stats s;
    lh_tetmesh_stats_get(m, &s);
    fprintf(out, "%s: %zu points, %zu tetrahedra, %zu boundary faces (%zu Steiner points), %.3f s\n", name,
            lh_tetmesh_point_count(m), s.tets, s.faces, s.steiner_points, secs);
}

int lh_cli_tetmesh_stats(FILE *out, const lh_cli_plc *in, const lh_tetmesh *m, const char *cmd)
{
    lh_tetmesh_stats s;
    lh_tetmesh_stats_get(m, &s);
    const lh_plc *g = &in->g;
    fprintf(out, "Statistics:\n\n");
    fprintf(out, "  Input points: %zu (%zu duplicates merged)\n", s.input_points, s.duplicates_merged);
    fprintf(out, "  Input facets: %zu (%zu not exactly planar)\n", g->facet_count, s.facets_nonplanar);
    fprintf(out, "  Input free segments: %zu\n  Input holes: %zu (%zu ignored)\n", g->segment_count, g->hole_count,
            s.holes_ignored);
    fprintf(out, "  Input regions: %zu (%zu ignored)\n\n", g->region_count, s.regions_ignored);
    fprintf(out, "  Mesh points: %zu\n  Mesh tetrahedra: %zu\n", lh_tetmesh_point_count(m), s.tets);
    fprintf(out, "  Mesh faces on facets and boundary: %zu\n  Mesh edges on segments: %zu\n", s.faces, s.edges);
    fprintf(out, "  Mesh regions: %zu\n", s.regions);
    fprintf(out, "  Steiner points: %zu (%zu on segments, %zu on facets, %zu interior)\n", s.steiner_points,
            s.steiner_on_segments, s.steiner_on_facets, s.steiner_interior);
    fprintf(out, "  Steiner points on their segment or facet up to rounding only: %zu\n\n", s.steiner_off_exact);
    fprintf(out, "  Smallest dihedral angle: %.6g degrees\n  Largest radius-edge ratio: %.6g\n", s.min_dihedral,
            s.max_radius_edge);
    fprintf(out,
            "  Quality refinement: %zu Steiner points; tetrahedra left over the radius-edge bound: %zu,"
            " over the volume bound: %zu, under the dihedral bound: %zu, over the size: %zu\n",
            s.refine_points, s.over_radius_edge, s.over_volume, s.under_dihedral, s.over_size);
    lh_cli_tetmesh_leftovers(out, m, 20, in->g.first_index);
    return lh_cli_tetmesh_quality(out, m, cmd);
}
