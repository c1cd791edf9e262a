/* mesh.c — `lifthull mesh`: 2D meshing with lifthull's own long options — the
 * computation of `lifthull triangle` (lh_pslg_triangulate: constrained Delaunay
 * triangulation of a .poly, .node or JSON rings, optionally refined), written in the
 * format -o's extension names, or the quality report on standard output. A 3D input
 * goes to mesh3.c (lh_tetrahedralize, as `lifthull tetgen`). */
#include "cli.h"
#include "outfile.h"
#include "pslg_io.h"
#include "tetgen_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: lifthull mesh [OPTIONS] FILE[.poly|.node|.json] [-o OUT [-f]]\n"
    "       lifthull mesh [OPTIONS] FILE[.poly|.smesh|.node|.off|.ply|.stl|.mesh|.obj] [-o OUT [-f]]\n"
    "\n"
    "The constrained Delaunay triangulation of a planar straight-line graph (Triangle's\n"
    "FILE.poly; a .poly without vertices takes FILE.node's), of a point set (FILE.node)\n"
    "or of polygons with holes (FILE.json: [[[x,y],...], hole, ...], even-odd rule),\n"
    "restricted to its domain and refined on request (Ruppert/Shewchuk Delaunay\n"
    "refinement with off-centres). Exact: every segment is kept, every other edge is\n"
    "locally Delaunay. The same computation as `lifthull triangle`, spelled the\n"
    "lifthull way.\n"
    "\n"
    "Output: without -o the quality report (counts, angle and area ranges, an angle\n"
    "histogram, the triangles left below the bounds) on standard output; with -o OUT\n"
    "the format its extension names, written whole or not at all, never an input:\n"
    "  .vtu   VTK (ParaView): triangles, neighbours, point data 'marker' (boundary\n"
    "         markers), cell data 'region' with --attributes; binary (--ascii: text)\n"
    "  .msh   Gmsh 4.1 (markers as node data)    .off  OFF\n"
    "  .node  Triangle's files OUT.node, OUT.ele, and OUT.poly for a .poly or .json\n"
    "         input (.ele names the same three)\n"
    "  .svg   a picture: triangles shaded by their smallest angle, those below the\n"
    "         bound red, the segments drawn thick\n"
    "\n"
    "options:\n"
    "  --min-angle DEG        refine until no angle is below DEG degrees (0..40;\n"
    "                         default 0: no bound); angles between input segments\n"
    "                         below it stay, their triangles reported\n"
    "  --quality              the same with 20 degrees (unless --min-angle is given)\n"
    "  --max-area A           refine until no triangle's area is above A\n"
    "  --region-areas         the .poly regions' area bounds apply\n"
    "  --attributes           each triangle gets its region's attribute\n"
    "  --convex-hull          keep the convex hull (no carving from the outside)\n"
    "  --conforming           split segments until every triangle is Delaunay\n"
    "  --no-boundary-steiner  no Steiner points on boundary segments (Triangle's -Y)\n"
    "  --no-segment-steiner   no Steiner points on any segment (Triangle's -YY)\n"
    "  --max-steiner N        at most N Steiner points\n"
    "  --check                verify the mesh exactly and print the verdict (3D)\n"
    "  --ignore-holes         ignore the .poly's holes\n"
    "  --smooth N             N passes of smoothing after refinement: free Steiner\n"
    "                         points move to raise the smallest angle around them\n"
    "  --split-crossings      segments that cross get a vertex at the crossing\n"
    "                         (default: an error naming both)\n"
    "  --report               print the quality report as well as writing -o\n"
    "  -o OUT                 write OUT; an existing file needs -f\n"
    "  -f                     -o may replace existing files\n"
    "  -q, --quiet            no summary line after writing -o\n"
    "  --ascii                a .vtu as text (default: binary, base64 inline)\n"
    "\n"
    "3D input (a .poly or .node with 3 coordinates, .smesh, .off, .ply, .stl, Medit\n"
    "  .mesh, .obj): the tetrahedralization of the piecewise linear complex, every\n"
    "  facet a union of faces, every segment a union of edges (`lifthull tetgen -p`);\n"
    "  a .node: the Delaunay tetrahedralization. Without -o the statistics; -o OUT:\n"
    "  .vtu   VTK: tetrahedra, neighbours, point data 'marker', cell data 'region'\n"
    "         with --region-attributes; binary (--ascii: text)\n"
    "  .msh   Gmsh 4.1 (markers as node data)\n"
    "  .mesh  Medit: vertices, boundary triangles with their facet markers and\n"
    "         tetrahedra with their region attributes as references\n"
    "  .svg   a picture: the boundary faces coloured by facet marker, seen from an\n"
    "         oblique direction; with --clip the mesh cut through the middle, each\n"
    "         face coloured by its tetrahedron's smallest dihedral angle, and the\n"
    "         dihedral angles' histogram\n"
    "  options: --convex-hull, --no-boundary-steiner (no Steiner points on segments\n"
    "  or facets), --max-steiner N, --region-attributes (or --attributes), --check\n"
    "  (lh_tetmesh_check's verdict on the mesh: exit 1 when invalid), --report,\n"
    "  --quiet (-q), -o, -f, --ascii; the 2D refinement options are refused. Quality\n"
    "  refinement (TetGen's -q R/D and -a, docs/meshing3d.md):\n"
    "  --radius-edge R        refine until every tetrahedron's circumradius over its\n"
    "                         shortest edge is at most R (at least 1), except next to\n"
    "                         small input angles (--report counts those left)\n"
    "  --quality              the same with R = 2 (unless --radius-edge is given)\n"
    "  --min-dihedral D       after refinement, flip away tetrahedra with a dihedral\n"
    "                         angle under D degrees where flips can (default 10)\n"
    "  --max-volume V         refine until no tetrahedron's volume is above V\n"
    "  --region-volumes       the .poly regions' volume bounds apply\n"
    "\n"
    "examples:\n"
    "  lifthull mesh examples/A.poly --min-angle 30       # the quality report\n"
    "  lifthull mesh examples/A.poly --min-angle 30 --max-area 0.01 -o A.vtu -f\n"
    "  lifthull mesh examples/A.poly --quality -o A.svg -f\n"
    "  lifthull mesh examples/lake.json --min-angle 25 -o lake.node -f  # and .ele .poly\n"
    "  lifthull mesh examples/box.poly -o box.svg -f      # 3D: the boundary, pictured\n"
    "  lifthull mesh examples/box.poly --quality --max-volume 0.01 -o box.vtu -f\n"
    "  lifthull mesh examples/box.poly --quality --max-volume 0.01 --clip -o q.svg -f\n"
    "\n"
    "exit codes: 0 done (triangles below the bounds are reported, not an error), 1 out\n"
    "of memory or an output file could not be written, 2 usage, 3 bad input file\n"
    "(unreadable, malformed, crossing segments, an empty domain, collinear points).\n";

typedef struct mesh_args {
    lh_trimesh_options opt;
    const char *file, *output;
    int force, quiet, report, ignore_holes, quality, angle_given, ascii, check;
    const char *only2d; /* the first option of 2D meshing only, or NULL */
    const char *only3d; /* the first option of 3D meshing only, or NULL */
    double radius_edge, min_dihedral, max_volume; /* 3D refinement (0: none) */
    int region_volumes, clip;
} mesh_args;

static int usage_error(const char *what, const char *arg)
{
    fprintf(stderr, "lifthull mesh: %s '%s' (lifthull mesh --help)\n", what, arg);
    return -1;
}

/* The value of option `name`: a number within lo..hi (whole with `whole`). Returns
 * 1, or 0 after printing the problem. */
static int number(const char *name, const char *s, double lo, double hi, int whole, double *out)
{
    char *end;
    const double x = strtod(s, &end);
    if (end == s || *end || !(x >= lo && x <= hi) || (whole && (!s[0] || s[strspn(s, "0123456789")]))) {
        char what[96];
        snprintf(what, sizeof what, "%s takes %s from %g to %g, not", name, whole ? "a whole number" : "a number",
                 lo, hi);
        usage_error(what, s);
        return 0;
    }
    *out = x;
    return 1;
}

/* Returns 0 to go on, 1 after --help, -1 after a usage error. */
static int parse(mesh_args *a, int argc, char **argv)
{
    memset(a, 0, sizeof *a);
    lh_trimesh_options_default(&a->opt);
    static const char *const valued[] = {"-o",           "--min-angle",    "--max-area",   "--max-steiner",
                                         "--smooth",     "--threads",      "--radius-edge", "--min-dihedral",
                                         "--max-volume"};
    for (int i = 0; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            fputs(help, stdout);
            return 1;
        }
        if (s[0] != '-' || !s[1]) {
            if (a->file) return usage_error("one input file only, not also", s);
            a->file = s;
            continue;
        }
        const char *v = NULL;
        for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++)
            if (!strcmp(s, valued[k])) {
                if (i + 1 == argc) return usage_error("a value is needed after", s);
                v = argv[++i];
            }
        double x;
        static const char *const only2d[] = {"--min-angle",  "--max-area",          "--region-areas",
                                             "--conforming", "--split-crossings",   "--no-segment-steiner",
                                             "--ignore-holes", "--smooth"};
        static const char *const only3d[] = {"--radius-edge", "--min-dihedral", "--max-volume", "--region-volumes",
                                             "--clip"};
        for (size_t k = 0; k < sizeof only2d / sizeof only2d[0] && !a->only2d; k++)
            if (!strcmp(s, only2d[k])) a->only2d = only2d[k];
        for (size_t k = 0; k < sizeof only3d / sizeof only3d[0] && !a->only3d; k++)
            if (!strcmp(s, only3d[k])) a->only3d = only3d[k];
        if (!strcmp(s, "-o")) a->output = v;
        else if (!strcmp(s, "-f")) a->force = 1;
        else if (!strcmp(s, "-q") || !strcmp(s, "--quiet")) a->quiet = 1;
        else if (!strcmp(s, "--check")) a->check = 1;
        else if (!strcmp(s, "--report")) a->report = 1;
        else if (!strcmp(s, "--ascii")) a->ascii = 1;
        else if (!strcmp(s, "--quality")) a->quality = 1;
        else if (!strcmp(s, "--region-areas")) a->opt.region_areas = 1;
        else if (!strcmp(s, "--region-volumes")) a->region_volumes = 1;
        else if (!strcmp(s, "--clip")) a->clip = 1;
        else if (!strcmp(s, "--attributes") || !strcmp(s, "--region-attributes")) a->opt.region_attributes = 1;
        else if (!strcmp(s, "--convex-hull")) a->opt.convex_hull = 1;
        else if (!strcmp(s, "--conforming")) a->opt.conforming = 1;
        else if (!strcmp(s, "--split-crossings")) a->opt.split_crossings = 1;
        else if (!strcmp(s, "--no-boundary-steiner")) a->opt.boundary_steiner = a->opt.boundary_steiner < 0 ? -1 : 0;
        else if (!strcmp(s, "--no-segment-steiner")) a->opt.boundary_steiner = -1;
        else if (!strcmp(s, "--ignore-holes")) a->ignore_holes = 1;
        else if (!strcmp(s, "--min-angle")) {
            if (!number(s, v, 0, LH_TRIMESH_MAX_ANGLE, 0, &a->opt.min_angle)) return -1;
            a->angle_given = 1;
        } else if (!strcmp(s, "--max-area")) {
            if (!number(s, v, 0, 1e308, 0, &a->opt.max_area)) return -1;
        } else if (!strcmp(s, "--radius-edge")) {
            if (!number(s, v, 1, 1e308, 0, &a->radius_edge)) return -1;
        } else if (!strcmp(s, "--min-dihedral")) {
            if (!number(s, v, 0, 89, 0, &a->min_dihedral)) return -1;
        } else if (!strcmp(s, "--max-volume")) {
            if (!number(s, v, 0, 1e308, 0, &a->max_volume)) return -1;
        } else if (!strcmp(s, "--max-steiner")) {
            if (!number(s, v, 0, 1e15, 1, &x)) return -1;
            a->opt.max_steiner = (size_t)x;
        } else if (!strcmp(s, "--smooth")) {
            if (!number(s, v, 0, 1000, 1, &x)) return -1;
            a->opt.smooth = (int)x;
        } else if (!strcmp(s, "--threads")) { /* as the point commands; meshing is sequential */
            if (!number(s, v, 0, 4096, 1, &x)) return -1;
            if (x > 1) fprintf(stderr, "lifthull mesh: --threads %s: meshing runs on one thread\n", v);
        } else {
            return usage_error("unknown option", s);
        }
    }
    if (a->quality && !a->angle_given) a->opt.min_angle = 20;
    if (!a->file) {
        fprintf(stderr, "lifthull mesh: an input file is needed (lifthull mesh --help)\n");
        return -1;
    }
    return 0;
}

/* What the end of name says: one of the `n` extensions (its index), or -1. */
static int ext_index(const char *name, const char *const *exts, int n, size_t *stem)
{
    const size_t len = strlen(name);
    for (int i = 0; i < n; i++) {
        const size_t e = strlen(exts[i]);
        if (len > e && !strcmp(name + len - e, exts[i]) && name[len - e - 1] != '/') {
            *stem = len - e;
            return i;
        }
    }
    return -1;
}

enum { OUT_VTU, OUT_MSH, OUT_OFF, OUT_NODE, OUT_ELE, OUT_SVG, OUT_COUNT };
static const char *const out_ext[OUT_COUNT] = {".vtu", ".msh", ".off", ".node", ".ele", ".svg"};

double *lh_cli_mesh_markers(const char *output, const char *node_path, const lh_index *pm, size_t np)
{
    if (lh_cli_same_file(output, node_path)) {
        fprintf(stderr, "lifthull mesh: '%s' is an input file; it is not overwritten\n", output);
        return NULL;
    }
    double *marker = malloc((np ? np : 1) * sizeof *marker);
    if (!marker) fprintf(stderr, "lifthull mesh: out of memory\n");
    for (size_t p = 0; marker && p < np; p++) marker[p] = (double)pm[p];
    return marker;
}

/* One file (.vtu .msh .off .svg) through the whole-or-nothing mechanism. */
static int write_one(const mesh_args *a, const lh_cli_pslg *in, const lh_trimesh *m, int kind)
{
    const size_t np = lh_trimesh_point_count(m), nt = lh_trimesh_triangle_count(m);
    double *marker = lh_cli_mesh_markers(a->output, in->node_path, lh_trimesh_point_markers(m), np);
    if (!marker) return LH_EXIT_FAIL;
    lh_mesh_view v = {2, np, lh_trimesh_points(m), 2, nt, lh_trimesh_triangles(m), lh_trimesh_neighbors(m),
                      kind == OUT_OFF ? NULL : marker, "marker"};
    lh_cli_out out;
    if (!lh_cli_out_open(&out, "mesh", a->output, a->force, in->path)) {
        free(marker);
        return LH_EXIT_FAIL;
    }
    lh_status st = LH_OK;
    int ok;
    switch (kind) {
    case OUT_VTU: {
        const lh_vtu_options vo = {a->ascii, lh_trimesh_triangle_attrs(m), "region"};
        ok = (st = lh_vtu_write(out.f, &v, &vo)) == LH_OK;
        break;
    }
    case OUT_MSH: ok = (st = lh_msh_write(out.f, &v)) == LH_OK; break;
    case OUT_OFF: ok = (st = lh_off_write(out.f, &v)) == LH_OK; break;
    default: {
        char title[256];
        const char *slash = strrchr(a->file, '/');
        snprintf(title, sizeof title, "lifthull mesh %s", slash ? slash + 1 : a->file);
        ok = lh_cli_trimesh_svg(out.f, m, a->opt.min_angle, title) == 0;
        if (!ok) st = LH_ERR_IO;
    }
    }
    if (!ok && st != LH_ERR_IO) fprintf(stderr, "lifthull mesh: %s: %s\n", a->output, lh_status_message(st));
    free(marker);
    return lh_cli_out_close(&out, "mesh", ok);
}

/* For -o BASE.node or BASE.ele: Triangle's files BASE.node and BASE.ele, numbered from
 * 1, with markers, and BASE.poly for a graph (in_kind), written (m) or, with m NULL,
 * only checked before the input is read. */
static int triangle_files(const mesh_args *a, const lh_cli_pslg *in, int in_kind, const lh_trimesh *m,
                          size_t stem)
{
    char *base = malloc(stem + 1);
    if (!base) {
        fprintf(stderr, "lifthull mesh: out of memory\n");
        return LH_EXIT_FAIL;
    }
    memcpy(base, a->output, stem);
    base[stem] = 0;
    lh_cli_tri_files w = {1, 1, in_kind != LH_CLI_NODE, 0, 0, 0, 1, 1, 0, !a->force, 0, 0};
    const int rc = m ? lh_cli_trimesh_write(m, in, base, &w, "mesh")
                     : lh_cli_trimesh_check(base, &w, a->file, "mesh") ? LH_EXIT_OK : LH_EXIT_FAIL;
    free(base);
    return rc;
}

static int write_output(const mesh_args *a, const lh_cli_pslg *in, const lh_trimesh *m, int kind, size_t stem)
{
    if (kind != OUT_NODE && kind != OUT_ELE) return write_one(a, in, m, kind);
    return triangle_files(a, in, in->kind, m, stem);
}

/* A 3D input: the options that apply, to mesh3.c. */
static int mesh3(const mesh_args *a)
{
    if (a->only2d) {
        usage_error("2D meshing only, not implemented for 3D input yet:", a->only2d);
        return LH_EXIT_USAGE;
    }
    lh_cli_mesh3_args m = {a->file, a->output, a->force, a->quiet, a->ascii, a->check, a->report, a->clip, {0}};
    lh_tetmesh_options_default(&m.opt);
    m.opt.max_radius_edge = a->radius_edge > 0 ? a->radius_edge : a->quality ? 2 : 0; /* TetGen's -q */
    m.opt.min_dihedral = a->min_dihedral;
    m.opt.max_volume = a->max_volume;
    m.opt.region_volumes = a->region_volumes;
    m.opt.convex_hull = a->opt.convex_hull;
    m.opt.boundary_steiner = a->opt.boundary_steiner > 0;
    m.opt.max_steiner = a->opt.max_steiner;
    m.opt.region_attributes = a->opt.region_attributes;
    return lh_cli_mesh3(&m);
}

int lh_cli_mesh(int argc, char **argv)
{
    mesh_args a;
    int r = parse(&a, argc, argv);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (lh_cli_plc_is_3d(a.file)) return mesh3(&a);
    if (a.only3d) {
        usage_error("3D meshing only (a 2D mesh's bounds are --min-angle and --max-area):", a.only3d);
        return LH_EXIT_USAGE;
    }
    if (a.check) {
        usage_error("not implemented for 2D input yet (lifthull check verifies a triangulation):", "--check");
        return LH_EXIT_USAGE;
    }
    static const char *const in_ext[] = {".poly", ".node", ".json"};
    static const int in_kind[] = {LH_CLI_POLY, LH_CLI_NODE, LH_CLI_RINGS};
    size_t stem, out_stem = 0;
    const int ik = ext_index(a.file, in_ext, 3, &stem);
    if (ik < 0) {
        usage_error("the input's name must end in .poly, .node or .json (2D), or .poly, .smesh, .node, "
                    ".off, .ply, .stl, .mesh or .obj (3D):", a.file);
        return LH_EXIT_USAGE;
    }
    const int ok_kind = a.output ? ext_index(a.output, out_ext, OUT_COUNT, &out_stem) : -1;
    if (a.output && ok_kind < 0) {
        usage_error("-o: the name must end in .vtu, .msh, .off, .node, .ele or .svg:", a.output);
        return LH_EXIT_USAGE;
    }
    /* every output file is checked before the input is read */
    if (a.output && (ok_kind == OUT_NODE || ok_kind == OUT_ELE
                         ? triangle_files(&a, NULL, in_kind[ik], NULL, out_stem) != LH_EXIT_OK
                         : !lh_cli_out_check("mesh", a.output, a.force, a.file)))
        return LH_EXIT_FAIL;
    char *base = malloc(stem + 1);
    if (!base) {
        fprintf(stderr, "lifthull mesh: out of memory\n");
        return LH_EXIT_FAIL;
    }
    memcpy(base, a.file, stem);
    base[stem] = 0;
    lh_cli_pslg in;
    const int loaded = lh_cli_pslg_load(&in, a.file, base, in_kind[ik]);
    free(base);
    if (!loaded) return LH_EXIT_INPUT;
    if (a.ignore_holes) in.g.hole_count = 0;
    lh_error err;
    lh_trimesh *m = NULL;
    lh_status st = lh_pslg_triangulate(&in.g, &a.opt, &m, &err);
    int rc;
    if (st != LH_OK) {
        lh_cli_pslg_report(&in, &err);
        rc = st == LH_ERR_NOMEM || st == LH_ERR_INTERNAL ? LH_EXIT_FAIL : LH_EXIT_INPUT;
    } else if (!a.output) {
        lh_cli_trimesh_report(stdout, m, a.opt.min_angle, 1); /* Triangle's numbering */
        rc = lh_cli_finish_output("mesh");
    } else {
        rc = write_output(&a, &in, m, ok_kind, out_stem);
        if (rc == LH_EXIT_OK && a.report) {
            /* numbered as the file written: VTU and OFF cells from 0, .ele and .msh from 1 */
            lh_cli_trimesh_report(stdout, m, a.opt.min_angle, ok_kind == OUT_VTU || ok_kind == OUT_OFF ? 0 : 1);
        } else if (rc == LH_EXIT_OK && !a.quiet) {
            lh_trimesh_stats s;
            lh_trimesh_stats_get(m, &s);
            printf("%s: %zu points, %zu triangles (%zu Steiner points), smallest angle %.4g degrees\n", a.output,
                   lh_trimesh_point_count(m), s.triangles, s.steiner_points, s.min_angle);
            if (s.bad_triangles)
                printf("%zu triangles are below the bounds (small input angles%s; --report lists them)\n",
                       s.bad_triangles, s.steiner_limit_reached ? " or the Steiner limit" : "");
            if (s.segments_unsplit) lh_cli_trimesh_unsplit(stdout, &s);
            if (s.steiner_budget_reached) lh_cli_trimesh_budget(stdout, &s, a.opt.min_angle);
        }
        if (rc == LH_EXIT_OK) rc = lh_cli_finish_output("mesh");
    }
    lh_trimesh_free(m);
    lh_cli_pslg_free(&in);
    return rc;
}
