/* triangle.c — `lifthull triangle`: Shewchuk's Triangle spelled the same way
 * (switches, file names, formats), for scripts and fingers that know it:
 *     lifthull triangle -pq30a0.01 A.poly   ->  A.1.node A.1.ele A.1.poly
 * Computed by lh_pslg_triangulate (exact). Switches Triangle has and lifthull does not
 * (yet) are refused by name; switches that choose among Triangle's algorithms or its
 * arithmetic are accepted and change nothing (lifthull is always exact). */
#include "cli.h"
#include "outfile.h"
#include "pslg_io.h"
#include "switches.h"

#include <stdlib.h>
#include <string.h>

typedef struct sw {
    int p, r, q, a_regions, A, c, D, Y, O, I, Q, V, S, noP, s;
    double angle, area;
    size_t steiner;
    lh_cli_tri_files files;
} sw;

static const char *const usage_text =
    "usage: lifthull triangle [-prqaAcDsYSjevno2zBPNEIOQVgilFCX] FILE[.poly|.node|.json]\n"
    "\n"
    "Triangle's command line (J. R. Shewchuk), computed exactly by lifthull: the same\n"
    "switches, input and output files. FILE.poly (or -p FILE) is a planar straight-line\n"
    "graph; FILE.node a point set; FILE.json polygon rings ([[[x,y],...], hole, ...]).\n"
    "Output: FILE.1.node, FILE.1.ele, FILE.1.poly (.poly input) — from FILE.1.* come\n"
    "FILE.2.* — replacing earlier outputs, never the input; all files or none.\n"
    "\n"
    "  -p      triangulate the graph: constrained Delaunay triangulation of its domain\n"
    "  -r      refine FILE.node + FILE.ele (with -p FILE.poly's segments and holes,\n"
    "          with -a FILE.area's per-triangle bounds): FILE.1 -> FILE.2\n"
    "  -q[A]   quality mesh: no angle below A degrees (default 20, at most 40)\n"
    "  -a[X]   no triangle area above X; -a alone: the .poly regions' area bounds\n"
    "  -A      regional attributes: each triangle gets its region's attribute\n"
    "  -c      keep the convex hull (do not carve from the outside); with a .node\n"
    "          (or -r) input, write FILE.1.poly: the hull's (the mesh's boundary) edges\n"
    "  -D      conforming Delaunay: segments split until every triangle is Delaunay\n"
    "  -s      segments split at midpoints until each is a chain of Delaunay edges\n"
    "  -Y      no Steiner points on the boundary; -YY: on no segment\n"
    "  -S[N]   at most N Steiner points\n"
    "  -j      leave points that are in no triangle out of the output\n"
    "  -e      write FILE.1.edge; -n FILE.1.neigh; -g FILE.1.off\n"
    "  -v      write the Voronoi diagram: FILE.1.v.node, FILE.1.v.edge (Triangle's\n"
    "          format: a vertex per triangle, an edge per edge, rays \"t -1 dx dy\")\n"
    "  -o2     quadratic elements: 6 nodes per triangle, the midpoints of the edges\n"
    "          opposite corners 1, 2, 3 numbered after the vertices\n"
    "  -z      number everything from 0 (default 1)\n"
    "  -B      no boundary markers; -P no .poly; -N no .node; -E no .ele output\n"
    "  -I      no iteration number in the output names (FILE.node ...)\n"
    "  -O      ignore the holes of the .poly\n"
    "  -Q      quiet; -V verbose: the quality report (angles, areas, histogram)\n"
    "  -i -F -l -C -X   Triangle's choices of algorithm or arithmetic: accepted,\n"
    "          nothing changes (lifthull is always exact)\n"
    "not supported (refused): -u -k -L -w -W\n"
    "\n"
    "examples:\n"
    "  lifthull triangle -pq30 examples/A.poly       # the letter A: examples/A.1.*\n"
    "  lifthull triangle -pq30a0.01 examples/A.poly  # ... with small triangles\n"
    "  lifthull triangle examples/dots.node          # Delaunay triangulation of points\n"
    "\n"
    "exit codes: 0 success, 1 failure, 2 usage error, 3 bad input\n";

/* -S's count after s[*j]: none is 0, as Triangle; a number is rounded down, and one
 * that no size_t holds (1e30, 1e400: strtod's HUGE_VAL) means no limit, the budget
 * unbounded rather than wrapped around. A sign is refused (0 returned, after a
 * message). */
static int steiner_after(const char *s, int *j, size_t *out)
{
    const char c = s[*j + 1];
    if (c == '-' || c == '+') {
        fprintf(stderr, "lifthull triangle: -S takes a count of Steiner points (0 or more), not '%s'\n", s + *j + 1);
        return 0;
    }
    *out = lh_cli_switch_count(s, j, 0);
    return 1;
}

static int parse_switches(const char *s, void *opt)
{
    sw *o = opt;
    for (int j = 1; s[j]; j++) {
        double x;
        switch (s[j]) {
        case 'p': o->p = 1; break;
        case 'r': o->r = 1; break;
        case 'q': o->q = 1; o->angle = lh_cli_switch_number(s, &j, &x) ? x : 20; break;
        case 'a':
            if (lh_cli_switch_number(s, &j, &x)) o->area = x; else o->a_regions = 1;
            break;
        case 'A': o->A = 1; break;
        case 'c': o->c = 1; break;
        case 'D': o->D = 1; break;
        case 'Y': o->Y++; break;
        case 'S':
            o->S = 1;
            if (!steiner_after(s, &j, &o->steiner)) return 0;
            break;
        case 'j': o->files.jettison = 1; break;
        case 'e': o->files.edge = 1; break;
        case 'n': o->files.neigh = 1; break;
        case 'g': o->files.off = 1; break;
        case 'z': o->files.base = 0; break;
        case 'B': o->files.markers = 0; break;
        case 'P': o->noP = 1; break;
        case 'N': o->files.node = 0; break;
        case 'E': o->files.ele = 0; break;
        case 'I': o->I = 1; break;
        case 'O': o->O = 1; break;
        case 'Q': o->Q = 1; break;
        case 'V': o->V = 1; break;
        case 'v': o->files.voronoi = 1; break;
        case 'o':
            if (s[j + 1] != '2') {
                fprintf(stderr, "lifthull triangle: -o must be -o2 (quadratic elements), not '%s'\n", s);
                return 0;
            }
            o->files.order2 = 1, j++;
            break;
        case 's': o->s = 1; break;
        case 'i': case 'F': case 'l': case 'C': case 'X': break;
        case 'u': case 'k': case 'L': case 'w': case 'W':
            fprintf(stderr, "lifthull triangle: -%c is not supported (see lifthull triangle --help)\n", s[j]);
            return 0;
        default:
            fprintf(stderr, "lifthull triangle: unknown switch '%c' in '%s' (see --help)\n", s[j], s);
            return 0;
        }
    }
    return 1;
}

/* FILE's kind and base name (FILE without its extension), malloc'ed. */
static char *base_of(const char *file, int p, int *kind)
{
    const size_t n = strlen(file);
    static const struct { const char *ext; int kind; } known[] = {
        {".poly", LH_CLI_POLY}, {".node", LH_CLI_NODE}, {".json", LH_CLI_RINGS},
        {".ele", LH_CLI_NODE}, {".area", LH_CLI_NODE}}; /* -r: BASE.node, BASE.ele */
    *kind = p ? LH_CLI_POLY : LH_CLI_NODE;
    size_t cut = n;
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++) {
        const size_t e = strlen(known[i].ext);
        if (n > e && !strcmp(file + n - e, known[i].ext)) {
            cut = n - e;
            *kind = known[i].kind;
            if (*kind == LH_CLI_NODE && p) *kind = LH_CLI_POLY;
        }
    }
    char *b = malloc(cut + 1);
    if (b) memcpy(b, file, cut), b[cut] = 0;
    return b;
}

static int run(const sw *o, const char *file)
{
    int kind, rc = LH_EXIT_FAIL;
    char *base = base_of(file, o->p, &kind), *outb = base ? lh_cli_out_base(base, strlen(base), o->I) : NULL, *path = NULL;
    lh_cli_pslg in;
    lh_trimesh *m = NULL;
    if (!base || !outb) goto done;
    /* Triangle reads BASE.poly with -p, else BASE.node, whatever extension FILE has
       (but for polygon rings, which have no other form) */
    path = kind == LH_CLI_RINGS ? lh_cli_path_ext(file, strlen(file), "")
                                : lh_cli_path_ext(base, strlen(base), kind == LH_CLI_POLY ? ".poly" : ".node");
    if (!path) goto done;
    /* every output file is checked before the input is read */
    if (!lh_cli_trimesh_check(outb, &o->files, path, "triangle")) goto done;
    if (!lh_cli_pslg_load(&in, path, base, kind) ||
        (o->r && !lh_cli_pslg_load_mesh(&in, base, o->a_regions))) {
        if (in.path) lh_cli_pslg_free(&in);
        rc = LH_EXIT_INPUT;
        goto done;
    }
    if (o->O) in.g.hole_count = 0;
    lh_trimesh_options opt;
    lh_trimesh_options_default(&opt);
    opt.convex_hull = o->c;
    opt.conforming = o->D;
    opt.min_angle = o->q ? o->angle : 0;
    opt.max_area = o->area;
    opt.region_areas = o->a_regions;
    opt.region_attributes = o->A;
    opt.boundary_steiner = o->Y == 0 ? 1 : o->Y == 1 ? 0 : -1;
    opt.split_segments = o->s;
    if (o->S) opt.max_steiner = o->steiner;
    lh_error err;
    const double t0 = lh_cli_seconds();
    lh_status st = lh_pslg_triangulate(&in.g, &opt, &m, &err);
    const double secs = lh_cli_seconds() - t0;
    if (getenv("LIFTHULL_TIMING")) fprintf(stderr, "compute_ms=%.3f\n", 1e3 * secs); /* for bench/ */
    if (st != LH_OK) {
        lh_cli_pslg_report(&in, &err);
        rc = st == LH_ERR_NOMEM || st == LH_ERR_INTERNAL ? LH_EXIT_FAIL : LH_EXIT_INPUT;
    } else {
        rc = lh_cli_trimesh_write(m, &in, outb, &o->files, "triangle");
        if (rc == LH_EXIT_OK && o->V) lh_cli_trimesh_report(stdout, m, opt.min_angle, o->files.base);
        if (rc == LH_EXIT_OK && !o->Q && !o->V) {
            lh_trimesh_stats s;
            lh_trimesh_stats_get(m, &s);
            printf("%s: %zu points, %zu triangles (%zu Steiner points), smallest angle %.4g degrees, %.3f s\n",
                   outb, lh_trimesh_point_count(m), s.triangles, s.steiner_points, s.min_angle, secs);
            if (s.bad_triangles)
                printf("%zu triangles are below the bounds (input angles below %.4g degrees%s; -V lists them)\n",
                       s.bad_triangles, opt.min_angle, s.steiner_limit_reached ? ", or the Steiner limit" : "");
            if (s.segments_unsplit) lh_cli_trimesh_unsplit(stdout, &s);
            if (s.steiner_budget_reached) lh_cli_trimesh_budget(stdout, &s, opt.min_angle);
        }
    }
    lh_trimesh_free(m);
    lh_cli_pslg_free(&in);
done:
    if (rc == LH_EXIT_FAIL && !m && !base) fprintf(stderr, "lifthull triangle: out of memory\n");
    free(base);
    free(outb);
    free(path);
    return rc;
}

int lh_cli_triangle(int argc, char **argv)
{
    sw o;
    memset(&o, 0, sizeof o);
    o.files = (lh_cli_tri_files){1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0};
    const char *file;
    const int r = lh_cli_switch_args(argc, argv, "triangle", usage_text, parse_switches, &o, &file);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (o.q && !(o.angle >= 0 && o.angle <= LH_TRIMESH_MAX_ANGLE)) {
        fprintf(stderr, "lifthull triangle: -q%.17g: the angle bound must be 0..%g degrees\n", o.angle,
                LH_TRIMESH_MAX_ANGLE);
        return LH_EXIT_USAGE;
    }
    int kind;
    free(base_of(file, o.p, &kind));
    /* Triangle writes a .poly for -p, and with -c for a point set (the hull's edges) or
       a mesh refined (its boundary edges) */
    o.files.poly = (kind != LH_CLI_NODE || o.c) && !o.noP;
    return run(&o, file);
}
