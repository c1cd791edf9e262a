/* tetgen.c — `lifthull tetgen`: Si's TetGen spelled the same way (switches, file
 * names, formats), for scripts and fingers that know it:
 *     lifthull tetgen -pA box.poly   ->  box.1.node box.1.ele box.1.face
 * Computed by lh_tetrahedralize (exact). TetGen's switches whose meaning lifthull does
 * not have yet are refused by name; those that choose TetGen's arithmetic or
 * tolerances are accepted and change nothing (lifthull is always exact). */
#define _POSIX_C_SOURCE 200809L /* access */
#include "cli.h"
#include "outfile.h"
#include "switches.h"
#include "tetgen_io.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct tsw {
    int p, Y, c, A, f, e, n, k, g, z, B, N, E, F, I, Q, V, d, C, S;
    int q, a, a_regions; /* -q[R][/D], -a[V]; -a alone: the regions' bounds */
    int o2;              /* -o2: second-order nodes */
    int m;               /* -m: the sizes of FILE.mtr */
    int O, level, ops;   /* -O[level][/ops]; ops 0 when not given */
    int r;               /* -r: refine FILE.node + FILE.ele */
    double ratio, angle, volume;
    size_t steiner, d_limit;
} tsw;

static const char *const usage_text =
    "usage: lifthull tetgen [-prYcAqamfenkgzBNEFIQVdSOCo2] FILE[.poly|.smesh|.node|.off|.ply|.stl|.mesh|.obj]\n"
    "\n"
    "TetGen's command line (H. Si), computed exactly by lifthull: the same switches,\n"
    "input and output files. FILE.poly / .smesh (TetGen's piecewise linear complexes),\n"
    "a surface (.off, .ply, .stl ascii or binary, Medit .mesh, Wavefront .obj), or\n"
    "FILE.node (points). Output: FILE.1.node, FILE.1.ele, FILE.1.face — from FILE.1.*\n"
    "come FILE.2.* — replacing earlier outputs, never the input; all files or none.\n"
    "\n"
    "  -r      refine the mesh FILE.node + FILE.ele (with -q, -a, -m): its points and\n"
    "          boundary kept, and faces between tetrahedra of different attributes (-A:\n"
    "          kept in FILE.2.ele); its tetrahedra become constrained Delaunay ones\n"
    "  -p      tetrahedralize the PLC: every facet a union of faces, every segment a\n"
    "          union of edges (without -p: the Delaunay tetrahedralization of the points)\n"
    "  -Y      no Steiner points on the boundary (segments and facets)\n"
    "  -c      keep the convex hull (do not carve from the outside; holes still are)\n"
    "  -A      region attributes: each tetrahedron gets its region's, in FILE.1.ele\n"
    "  -q[R][/D] quality: refine until every tetrahedron's circumradius over its\n"
    "          shortest edge is at most R (default 2, at least 1), except next to small\n"
    "          input angles (-V counts those left); then tets with a dihedral angle\n"
    "          under D degrees (default 10) are flipped away where flips can\n"
    "  -a[V]   refine until every tetrahedron's volume is at most V; -a alone: each\n"
    "          region's volume bound from the .poly (both may be given)\n"
    "  -m      refine until every tetrahedron's circumradius is at most the size\n"
    "          FILE.mtr gives at its circumcentre (one per input point: \"n 1\", then a\n"
    "          size a line; interpolated linearly between the input's points)\n"
    "  -S[N]   at most N Steiner points (more needed: an error; refinement stops there)\n"    "  -O[L][/ops] after refinement, L passes (0..10, default 3) of flips that raise the\n"
    "          worst shape; -O0: none. ops: 1 flips (TetGen's 2 smoothing and 4 vertex\n"
    "          insertion are not implemented: asking for them says so on stderr)\n"
    "  -f      FILE.1.face lists every face (default: the boundary and facet faces)\n"
    "  -e      write FILE.1.edge: every edge, with its segment's marker (0: none)\n"
    "  -n      write FILE.1.neigh;  -k FILE.1.vtk (legacy VTK);  -g FILE.1.mesh (Medit)\n"
    "  -z      number everything from 0 (default: as the input, usually 1)\n"
    "  -B      no boundary markers;  -N no .node;  -E no .ele;  -F no .face or .edge\n"
    "  -I      no iteration number in the output names (FILE.node ...)\n"
    "  -d[N]   list the pairs of facets that intersect (the first N), do not mesh;\n"
    "          exit status 1 when there is one\n"
    "  -C      check the mesh exactly (lh_tetmesh_check) and print the verdict\n"
    "  -Q      quiet; -V statistics (Steiner points by kind, those off their facet by\n"
    "          rounding, what refinement left over the bounds) and TetGen's quality\n"
    "          figures: volume, edge, aspect, face and dihedral angle ranges and\n"
    "          histograms, and a radius-edge ratio histogram\n"
    "  -T[x] -X -M -J   TetGen's tolerance, arithmetic, facet merging and keeping unused\n"
    "          points: accepted, nothing changes (lifthull is exact, never merges facets\n"
    "          and keeps every input point in the .node, in a tetrahedron or not)\n"
    "  -o2     second-order nodes: a node at every edge's midpoint, in FILE.1.node;\n"
    "          FILE.1.ele lists 10 per tetrahedron, .face 6 and .edge 3 (TetGen 1.5's\n"
    "          order); not with -k or -g\n"
    "not implemented yet (refused): -R -i -w -v\n"
    "\n"
    "examples:\n"
    "  lifthull tetgen -pA examples/box.poly     # examples/box.1.node .ele .face\n"
    "  lifthull tetgen examples/cube.node        # Delaunay: examples/cube.1.node .ele .face\n"
    "  lifthull tetgen -fenkV examples/cube.node # every face and edge, .neigh, .vtk, statistics\n"
    "\n"
    "exit codes: 0 success, 1 failure (or -d found intersections, -C an invalid mesh),\n"
    "2 usage error, 3 bad input\n";

static int refuse(char c, const char *what)
{
    fprintf(stderr, "lifthull tetgen: -%c (%s) is not implemented yet (see lifthull tetgen --help)\n", c, what);
    return 0;
}

static int parse_switches(const char *s, void *opt)
{
    tsw *o = opt;
    for (int j = 1; s[j]; j++) {
        double x;
        switch (s[j]) {
        case 'p': o->p = 1; break;
        case 'Y': o->Y = 1; break;
        case 'c': o->c = 1; break;
        case 'A': o->A = 1; break;
        case 'f': o->f = 1; break;
        case 'e': o->e = 1; break;
        case 'n': o->n = 1; break;
        case 'k': o->k = 1; break;
        case 'g': o->g = 1; break;
        case 'z': o->z = 1; break;
        case 'B': o->B = 1; break;
        case 'N': o->N = 1; break;
        case 'E': o->E = 1; break;
        case 'F': o->F = 1; break;
        case 'I': o->I = 1; break;
        case 'Q': o->Q = 1; break;
        case 'V': o->V++; break;
        case 'C': o->C = 1; break;
        case 'd': o->d = 1, o->d_limit = lh_cli_switch_count(s, &j, 0); break;
        case 'S':
            if (s[j + 1] == '-' || s[j + 1] == '+') {
                fprintf(stderr, "lifthull tetgen: -S takes a count of Steiner points (0 or more), not '%s'\n",
                        s + j + 1);
                return 0;
            }
            o->S = 1, o->steiner = lh_cli_switch_count(s, &j, 0);
            break;
        case 'q': /* -q[ratio][/angle] */
            o->q = 1, o->ratio = 2;
            if (lh_cli_switch_number(s, &j, &x)) o->ratio = x;
            if (s[j + 1] == '/') j++, o->angle = lh_cli_switch_number(s, &j, &x) ? x : 0;
            break;
        case 'a':
            if (lh_cli_switch_number(s, &j, &x))
                o->a = 1, o->volume = x;
            else
                o->a_regions = 1;
            break;
        case 'T': lh_cli_switch_number(s, &j, &x); break; /* exact coplanarity: no tolerance */
        case 'X': case 'M': case 'J': break;
        case 'O': /* -O[level][/ops] */
            o->O = 1, o->level = 3, o->ops = 0;
            if (lh_cli_switch_number(s, &j, &x)) o->level = x >= 0 && x <= 10 && x == (int)x ? (int)x : -1;
            if (s[j + 1] == '/') j++, o->ops = lh_cli_switch_number(s, &j, &x) && x >= 0 && x <= 7 && x == (int)x ? (int)x : -1;
            break;
        case 'r': o->r = 1; break;
        case 'm': o->m = 1; break;
        case 'R': return refuse('R', "mesh coarsening");
        case 'i': return refuse('i', "inserting points");
        case 'w': return refuse('w', "weighted Delaunay");
        case 'v': return refuse('v', "the Voronoi diagram");
        case 'o':
            if (s[j + 1] == '2') {
                o->o2 = 1, j++;
                break;
            }
            fprintf(stderr, "lifthull tetgen: -o must be -o2 (quadratic elements), not '%s'\n", s);
            return 0;
        default:
            fprintf(stderr, "lifthull tetgen: unknown switch '%c' in '%s' (see --help)\n", s[j], s);
            return 0;
        }
    }
    return 1;
}

enum { F_NODE, F_ELE, F_FACE, F_EDGE, F_NEIGH, F_VTK, F_MESH, F_COUNT };
static const char *const file_ext[F_COUNT] = {".node", ".ele", ".face", ".edge", ".neigh", ".vtk", ".mesh"};

static void wanted(const tsw *o, int want[F_COUNT])
{
    want[F_NODE] = !o->N;
    want[F_ELE] = !o->E;
    want[F_FACE] = !o->F;
    want[F_EDGE] = o->e && !o->F;
    want[F_NEIGH] = o->n;
    want[F_VTK] = o->k;
    want[F_MESH] = o->g;
}

/* Whether the tets carry region attributes: -A, for a PLC (-p) or a mesh (-r). */
static int regions(const tsw *o)
{
    return o->A && (o->p || o->r);
}

/* Whether some point has a nonzero marker: the .node's marker column, else none. */
static int any_marker(const lh_tetmesh *m)
{
    const lh_index *pm = lh_tetmesh_point_markers(m);
    for (size_t i = 0; i < lh_tetmesh_point_count(m); i++)
        if (pm[i]) return 1;
    return 0;
}

typedef struct outputs {
    const tsw *o;
    const lh_cli_plc *in;
    const lh_tetmesh *m;
    int first;
    lh_cli_items faces, edges;
} outputs;

/* The faces (v->k 2) or edges (1) of v: TetGen's .face or .edge, with -o2 their
 * midpoints too. */
static lh_status simplices(const outputs *w, FILE *f, const lh_mesh_view *v, const lh_index *markers)
{
    if (w->o->o2) return lh_cli_simplex_order2_write(f, w->m, v->count, v->k + 1, v->cells, markers, w->first);
    return (v->k == 2 ? lh_face_write : lh_edge_write)(f, v, markers, w->first);
}

static lh_status write_file(const outputs *w, int which, FILE *f)
{
    const lh_tetmesh *m = w->m;
    const int markers = !w->o->B;
    const size_t np = lh_tetmesh_point_count(m);
    lh_mesh_view v = {3, np, lh_tetmesh_points(m), 3, lh_tetmesh_tet_count(m), lh_tetmesh_tets(m),
                      lh_tetmesh_neighbors(m), NULL, NULL};
    switch (which) {
    case F_NODE:
        return lh_node_marker_write(f, &v, markers && any_marker(m) ? lh_tetmesh_point_markers(m) : NULL,
                                    w->first);
    case F_ELE: {
        const double *attrs = regions(w->o) ? lh_tetmesh_tet_attrs(m) : NULL;
        return w->o->o2 ? lh_cli_ele_order2_write(f, m, attrs, w->first) : lh_ele_attr_write(f, &v, attrs, w->first);
    }
    case F_NEIGH: return lh_neigh_write(f, &v, w->first);
    case F_VTK: return lh_vtk_write(f, &v, regions(w->o) ? lh_tetmesh_tet_attrs(m) : NULL, NULL);
    case F_FACE:
        v.k = 2;
        v.neighbors = NULL;
        if (w->o->f) {
            v.count = w->faces.n, v.cells = w->faces.v;
            return simplices(w, f, &v, markers ? w->faces.mark : NULL);
        }
        v.count = lh_tetmesh_face_count(m), v.cells = lh_tetmesh_faces(m);
        return simplices(w, f, &v, markers && w->o->p ? lh_tetmesh_face_markers(m) : NULL);
    case F_EDGE:
        v.k = 1, v.count = w->edges.n, v.cells = w->edges.v, v.neighbors = NULL;
        return simplices(w, f, &v, markers ? w->edges.mark : NULL);
    default: return lh_cli_tetmesh_medit(f, m, markers, regions(w->o), "tetgen");
    }
}

/* Every file wanted, into one output set: all or none. */
static int write_all(outputs *w, char *path[F_COUNT])
{
    lh_cli_outset set;
    lh_cli_outset_init(&set, "tetgen", 1, w->in->path);
    int ok = (!w->o->f || lh_cli_items_build(&w->faces, w->m, 2)) &&
             (!(w->o->e && !w->o->F) || lh_cli_items_build(&w->edges, w->m, 1));
    if (!ok) fprintf(stderr, "lifthull tetgen: out of memory\n");
    for (int i = 0; i < F_COUNT && ok; i++) {
        if (!path[i]) continue;
        FILE *f = lh_cli_outset_add(&set, path[i]);
        lh_status st = f ? write_file(w, i, f) : LH_ERR_IO;
        if (f && st != LH_OK && st != LH_ERR_IO)
            fprintf(stderr, "lifthull tetgen: %s: %s\n", path[i], lh_status_message(st));
        ok = st == LH_OK;
    }
    lh_cli_items_free(&w->faces);
    lh_cli_items_free(&w->edges);
    return lh_cli_outset_close(&set, ok);
}

static int mesh_and_write(const tsw *o, lh_cli_plc *in, const char *outb, char *path[F_COUNT],
                          lh_cli_sizing *sizing)
{
    lh_tetmesh_options opt;
    lh_tetmesh_options_default(&opt);
    if (sizing) opt.sizing = lh_cli_sizing_at, opt.sizing_user = sizing;
    opt.convex_hull = o->c || lh_cli_plc_is_points(in); /* nothing bounds a point set but its hull */
    opt.boundary_steiner = !o->Y;
    opt.region_attributes = regions(o);
    opt.regions_only = o->r; /* the mesh's parts are the domain, its voids stay */
    if (o->S) opt.max_steiner = o->steiner;
    if (o->q) opt.max_radius_edge = o->ratio, opt.min_dihedral = o->angle;
    if (o->a) opt.max_volume = o->volume;
    opt.region_volumes = o->a_regions && o->p;
    opt.second_order = o->o2;
    if (o->O) opt.optimize_passes = !o->ops || o->ops & 1 ? o->level : 0;
    lh_error err;
    lh_tetmesh *m = NULL;
    const double t0 = lh_cli_seconds();
    lh_status st = lh_tetrahedralize(&in->g, &opt, &m, &err);
    const double secs = lh_cli_seconds() - t0;
    if (getenv("LIFTHULL_TIMING")) fprintf(stderr, "compute_ms=%.3f\n", 1e3 * secs); /* for bench/ */
    if (st != LH_OK) {
        lh_cli_plc_report(in, "tetgen", &err);
        return lh_cli_plc_exit(st);
    }
    outputs w = {o, in, m, o->z ? 0 : in->g.first_index, {0, NULL, NULL}, {0, NULL, NULL}};
    int rc = write_all(&w, path);
    if (rc == LH_EXIT_OK && !o->Q) lh_cli_tetmesh_summary(stdout, outb, m, secs);
    if (rc == LH_EXIT_OK && o->V && !lh_cli_tetmesh_stats(stdout, in, m, "tetgen")) rc = LH_EXIT_FAIL;
    if (rc == LH_EXIT_OK && o->C && !lh_cli_tetmesh_verify(stdout, m, in, "tetgen")) rc = LH_EXIT_FAIL;
    lh_tetmesh_free(m);
    if (rc == LH_EXIT_OK) rc = lh_cli_finish_output("tetgen");
    return rc;
}

/* The input: FILE as named, or without a known extension FILE.node (with -p
 * FILE.poly, or FILE.smesh when only that exists), as TetGen looks for it. */
static char *input_path(const char *file, int p, size_t *stem)
{
    if (lh_cli_plc_path(file, stem)) return lh_cli_path_ext(file, strlen(file), "");
    if (p < 0) { /* -r: FILE.node (and FILE.ele) */
        *stem = strlen(file);
        return lh_cli_path_ext(file, *stem, ".node");
    }
    *stem = strlen(file);
    char *path = lh_cli_path_ext(file, *stem, p ? ".poly" : ".node");
    char *smesh = path && p ? lh_cli_path_ext(file, *stem, ".smesh") : NULL;
    if (smesh && access(path, F_OK) != 0 && access(smesh, F_OK) == 0) { /* else FILE.poly, named if missing */
        free(path);
        return smesh;
    }
    free(smesh);
    return path;
}

static int run(const tsw *o, const char *file)
{
    size_t stem;
    char *in_path = input_path(file, o->r ? -1 : o->p, &stem), *outb = in_path ? lh_cli_out_base(in_path, stem, o->I) : NULL;
    char *path[F_COUNT] = {0};
    int want[F_COUNT], rc = LH_EXIT_FAIL;
    wanted(o, want);
    if (!in_path || !outb || (!o->d && !lh_cli_paths(outb, strlen(outb), file_ext, want, F_COUNT, path))) {
        fprintf(stderr, "lifthull tetgen: out of memory\n");
        goto done;
    }
    /* every output file is checked before the input is read */
    for (int i = 0; i < F_COUNT; i++)
        if (path[i] && !lh_cli_out_check("tetgen", path[i], 1, in_path)) goto done;
    lh_cli_plc in;
    if (!(o->r ? lh_cli_mesh_load(&in, "tetgen", in_path, stem) : lh_cli_plc_load(&in, "tetgen", in_path))) {
        rc = LH_EXIT_INPUT;
        goto done;
    }
    for (int i = 0; i < F_COUNT; i++)
        if (path[i] && lh_cli_same_file(path[i], in.node_path)) {
            fprintf(stderr, "lifthull tetgen: '%s' is an input file; it is not overwritten\n", path[i]);
            lh_cli_plc_free(&in);
            goto done;
        }
    if (o->d) {
        const int r = lh_cli_plc_intersections(stdout, &in, "tetgen", o->d_limit,
                                               o->z ? 0 : in.g.first_index);
        rc = r < 0 ? LH_EXIT_INPUT : r ? LH_EXIT_FAIL : lh_cli_finish_output("tetgen");
    } else {
        if (!o->p && !o->r) lh_cli_plc_points_only(&in);
        char *mtr = o->m ? lh_cli_path_ext(in_path, stem, ".mtr") : NULL;
        lh_cli_sizing sizing = {NULL, NULL};
        if (o->m && !mtr) fprintf(stderr, "lifthull tetgen: out of memory\n");
        const int sized = !o->m || (mtr && lh_cli_sizing_load(&sizing, mtr, &in.g, "tetgen"));
        rc = sized ? mesh_and_write(o, &in, outb, path, o->m ? &sizing : NULL) : mtr ? LH_EXIT_INPUT : LH_EXIT_FAIL;
        lh_cli_sizing_free(&sizing);
        free(mtr);
    }
    lh_cli_plc_free(&in);
done:
    lh_cli_paths_free(path, F_COUNT);
    free(in_path);
    free(outb);
    return rc;
}

int lh_cli_tetgen(int argc, char **argv)
{
    tsw o;
    memset(&o, 0, sizeof o);
    const char *file;
    const int r = lh_cli_switch_args(argc, argv, "tetgen", usage_text, parse_switches, &o, &file);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (o.q && !(o.ratio >= 1)) {
        fprintf(stderr, "lifthull tetgen: -q takes a radius-edge bound of 1 or more, not %g\n", o.ratio);
        return LH_EXIT_USAGE;
    }
    if (o.q && !(o.angle >= 0 && o.angle < 90)) {
        fprintf(stderr, "lifthull tetgen: -q R/D takes a dihedral angle from 0 to 90 degrees, not %g\n", o.angle);
        return LH_EXIT_USAGE;
    }
    if (o.r && o.a_regions) {
        fprintf(stderr, "lifthull tetgen: -r with -a alone (the volume bounds of FILE.vol) is not implemented "
                        "yet; give -aV\n");
        return LH_EXIT_USAGE;
    }
    if (o.r && o.d) {
        fprintf(stderr, "lifthull tetgen: -d tests a PLC's facets, not a mesh (-r)\n");
        return LH_EXIT_USAGE;
    }
    if (o.O && (o.level < 0 || o.ops < 0)) {
        fprintf(stderr, "lifthull tetgen: -O takes a level from 0 to 10 and /ops from 0 to 7 (whole numbers)\n");
        return LH_EXIT_USAGE;
    }
    if (o.O && (o.ops & 6))
        fprintf(stderr, "lifthull tetgen: -O: only flips (ops 1) are implemented; %s%s not\n",
                o.ops & 2 ? "smoothing (2)" : "", o.ops & 4 ? o.ops & 2 ? " and vertex insertion (4) are" :
                "vertex insertion (4) is" : " is");
    if (o.o2 && (o.k || o.g)) {
        fprintf(stderr, "lifthull tetgen: -o2 writes second-order nodes to the .node, .ele, .face and .edge "
                        "files only, not with -%c (%s)\n", o.k ? 'k' : 'g', o.k ? "VTK" : "Medit");
        return LH_EXIT_USAGE;
    }
        if (o.a && !(o.volume > 0)) {
        fprintf(stderr, "lifthull tetgen: -a takes a volume bound above 0, not %g\n", o.volume);
        return LH_EXIT_USAGE;
    }
    return run(&o, file);
}
