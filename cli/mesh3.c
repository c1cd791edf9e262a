/* mesh3.c — `lifthull mesh` with a 3D input (tetgen_io.h): lh_tetrahedralize of a
 * PLC (.poly .smesh .off .ply .stl .mesh .obj) or a point set (.node), written in the
 * format -o's extension names (.vtu .msh .mesh .svg), or its statistics on standard
 * output. mesh.c parses the options and sends 3D inputs here. */
#include "cli.h"
#include "outfile.h"
#include "tetgen_io.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* The dimension field of a Triangle/TetGen header ("n d ..."), the first line that is
 * not blank or a comment; *n its count. 0 when unreadable. */
static int header_dim(const char *path, long *n)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int d = 0;
    while (f && fgets(line, sizeof line, f)) {
        const char *s = line + strspn(line, " \t\r\n");
        if (!strncmp(s, "\xef\xbb\xbf", 3)) s += 3;
        if (!*s || *s == '#') continue;
        if (sscanf(s, "%ld %d", n, &d) != 2) d = 0;
        break;
    }
    if (f) fclose(f);
    return d;
}

int lh_cli_plc_is_3d(const char *path)
{
    size_t stem;
    if (!lh_cli_plc_path(path, &stem)) return 0;
    const char *ext = path + stem;
    if (strcasecmp(ext, ".poly") && strcasecmp(ext, ".node")) return 1;
    long n = 0;
    int d = header_dim(path, &n);
    if (d && n == 0 && !strcasecmp(ext, ".poly")) {
        char *node = lh_cli_path_ext(path, stem, ".node");
        d = node ? header_dim(node, &n) : 0;
        free(node);
    }
    return d == 3;
}

lh_status lh_cli_tetmesh_medit(FILE *f, const lh_tetmesh *m, int markers, int attrs, const char *cmd)
{
    const double *a = attrs ? lh_tetmesh_tet_attrs(m) : NULL;
    const size_t nt = lh_tetmesh_tet_count(m);
    lh_index *refs = a ? malloc((nt ? nt : 1) * sizeof *refs) : NULL;
    if (a && !refs) return LH_ERR_NOMEM;
    for (size_t i = 0; refs && i < nt; i++) {
        if (!(a[i] >= -(double)LH_INDEX_MAX && a[i] <= (double)LH_INDEX_MAX && a[i] == (double)(lh_index)a[i])) {
            fprintf(stderr, "lifthull %s: region attribute %.17g is not a whole number: Medit references are "
                            "integers\n", cmd, a[i]);
            free(refs);
            return LH_ERR_INVALID_ARGUMENT;
        }
        refs[i] = (lh_index)a[i];
    }
    const lh_mesh_view v = {3, lh_tetmesh_point_count(m), lh_tetmesh_points(m), 3, nt, lh_tetmesh_tets(m),
                            NULL, NULL, NULL};
    const lh_medit_refs r = {markers ? lh_tetmesh_point_markers(m) : NULL, refs, lh_tetmesh_face_count(m),
                             lh_tetmesh_faces(m), markers ? lh_tetmesh_face_markers(m) : NULL};
    lh_status st = lh_medit_write(f, &v, &r);
    free(refs);
    return st;
}

enum { OUT_VTU, OUT_MSH, OUT_MESH, OUT_SVG, OUT_COUNT };
static const char *const out_ext[OUT_COUNT] = {".vtu", ".msh", ".mesh", ".svg"};

static int out_kind(const char *name)
{
    const size_t n = strlen(name);
    for (int i = 0; i < OUT_COUNT; i++) {
        const size_t e = strlen(out_ext[i]);
        if (n > e && !strcmp(name + n - e, out_ext[i]) && name[n - e - 1] != '/') return i;
    }
    return -1;
}

static int write_mesh(const lh_cli_mesh3_args *a, const lh_cli_plc *in, const lh_tetmesh *m, int kind)
{
    const size_t np = lh_tetmesh_point_count(m);
    double *marker = lh_cli_mesh_markers(a->output, in->node_path, lh_tetmesh_point_markers(m), np);
    if (!marker) return LH_EXIT_FAIL;
    const lh_mesh_view v = {3, np, lh_tetmesh_points(m), 3, lh_tetmesh_tet_count(m), lh_tetmesh_tets(m),
                            lh_tetmesh_neighbors(m), marker, "marker"};
    lh_cli_out out;
    if (!lh_cli_out_open(&out, "mesh", a->output, a->force, in->path)) {
        free(marker);
        return LH_EXIT_FAIL;
    }
    lh_status st;
    switch (kind) {
    case OUT_VTU: {
        const lh_vtu_options vo = {a->ascii, lh_tetmesh_tet_attrs(m), "region"};
        st = lh_vtu_write(out.f, &v, &vo);
        break;
    }
    case OUT_MSH: st = lh_msh_write(out.f, &v); break;
    case OUT_MESH: st = lh_cli_tetmesh_medit(out.f, m, 1, a->opt.region_attributes, "mesh"); break;
    default: {
        char title[256];
        const char *slash = strrchr(a->file, '/');
        snprintf(title, sizeof title, "lifthull mesh %s", slash ? slash + 1 : a->file);
        st = (a->clip ? lh_cli_tetmesh_svg_clip : lh_cli_tetmesh_svg)(out.f, m, title) == 0 ? LH_OK : LH_ERR_IO;
    }
    }
    if (st != LH_OK && st != LH_ERR_IO && st != LH_ERR_INVALID_ARGUMENT)
        fprintf(stderr, "lifthull mesh: %s: %s\n", a->output, lh_status_message(st));
    free(marker);
    return lh_cli_out_close(&out, "mesh", st == LH_OK);
}

int lh_cli_mesh3(const lh_cli_mesh3_args *a)
{
    const int kind = a->output ? out_kind(a->output) : -1;
    if (a->output && kind < 0) {
        fprintf(stderr, "lifthull mesh: -o: a 3D mesh is written as .vtu, .msh, .mesh or .svg, not '%s' "
                        "(lifthull mesh --help)\n", a->output);
        return LH_EXIT_USAGE;
    }
    /* the output is checked before the input is read */
    if (a->output && !lh_cli_out_check("mesh", a->output, a->force, a->file)) return LH_EXIT_FAIL;
    lh_cli_plc in;
    if (!lh_cli_plc_load(&in, "mesh", a->file)) return LH_EXIT_INPUT;
    lh_tetmesh_options opt = a->opt;
    if (lh_cli_plc_is_points(&in)) opt.convex_hull = 1; /* nothing bounds a point set but its hull */
    lh_error err;
    lh_tetmesh *m = NULL;
    const double t0 = lh_cli_seconds();
    lh_status st = lh_tetrahedralize(&in.g, &opt, &m, &err);
    const double secs = lh_cli_seconds() - t0;
    int rc;
    if (st != LH_OK) {
        lh_cli_plc_report(&in, "mesh", &err);
        rc = lh_cli_plc_exit(st);
    } else if (!a->output) {
        rc = lh_cli_tetmesh_stats(stdout, &in, m, "mesh") ? LH_EXIT_OK : LH_EXIT_FAIL;
    } else {
        rc = write_mesh(a, &in, m, kind);
        if (rc == LH_EXIT_OK && !a->quiet) lh_cli_tetmesh_summary(stdout, a->output, m, secs);
        if (rc == LH_EXIT_OK && a->report && !lh_cli_tetmesh_stats(stdout, &in, m, "mesh")) rc = LH_EXIT_FAIL;
    }
    if (rc == LH_EXIT_OK && a->check && !lh_cli_tetmesh_verify(stdout, m, &in, "mesh")) rc = LH_EXIT_FAIL;
    if (rc == LH_EXIT_OK) rc = lh_cli_finish_output("mesh");
    lh_tetmesh_free(m);
    lh_cli_plc_free(&in);
    return rc;
}
