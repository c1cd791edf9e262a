/* main.c — the lifthull command line: dispatch, --help, --version. Every command
 * answers --help itself (usage, options, examples). */
#include "cli.h"
#include "lifthull.h"

#include <stdio.h>
#include <string.h>

typedef struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command;

static const command commands[] = {
    {"delaunay", lh_cli_delaunay, "Delaunay triangulation (Qhull's 'i' format, VTK, Gmsh, Triangle, OFF, SVG)"},
    {"voronoi", lh_cli_voronoi, "Voronoi diagram (qvoronoi's 'o' format, or an SVG picture)"},
    {"hull", lh_cli_hull, "convex hull facets (qconvex's 'i' format)"},
    {"locate", lh_cli_locate, "the simplex holding each query point, and its nearest site"},
    {"interpolate", lh_cli_interpolate, "values at the sites interpolated at query points"},
    {"check", lh_cli_check, "exactly verify a Delaunay triangulation given as points + simplices"},
    {"points", lh_cli_generate, "generate test point sets (uniform, ball, sphere, grid, clusters)"},
    {"qdelaunay", lh_cli_qdelaunay, "Qhull's qdelaunay, exact: same options and formats (i Fn FN o p s ...)"},
    {"qvoronoi", lh_cli_qvoronoi, "Qhull's qvoronoi, exact: same options and formats (o p Fv Fi Fo ...)"},
    {"qconvex", lh_cli_qconvex, "Qhull's qconvex, exact: same options and formats (i o n Fn FN ...)"},
    {"qhalf", lh_cli_qhalf, "Qhull's qhalf: halfspace intersection by the exact hull of the dual points"},
    {"triangle", lh_cli_triangle, "Triangle's 2D meshing, exact: same switches and files (-pq30a0.1 A.poly)"},
    {"tetgen", lh_cli_tetgen, "TetGen's 3D meshing, exact: same switches and files (-pYA box.poly)"},
    {"mesh", lh_cli_mesh, "2D and 3D meshing of a .poly, .off, .node ... (VTK, Gmsh, Medit, Triangle, SVG)"},
    {"selfcheck", lh_cli_selfcheck, "check the exact predicates on near-degenerate cases"},
};
enum { n_commands = sizeof commands / sizeof commands[0] };

static void usage(FILE *out)
{
    fprintf(out, "usage: lifthull COMMAND [OPTIONS] [FILE]\n"
                 "       lifthull COMMAND --help\n"
                 "       lifthull --version | --help\n\ncommands:\n");
    for (int i = 0; i < n_commands; i++) fprintf(out, "  %-12s %s\n", commands[i].name, commands[i].summary);
    fprintf(out, "\nevery command: --help (usage and examples). The point commands (delaunay,\n"
                 "voronoi, hull, locate, interpolate, check): --format qhull|node|columns to\n"
                 "read their input files so (default: by name and content), and --threads N\n"
                 "for the Delaunay triangulation (default 0: one per CPU; the output is the same).\n"
                 "Manual: docs/lifthull.1\n"
                 "\nexit codes: 0 success, 1 a computation or check failed, 2 usage error,\n"
                 "            3 bad input file\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return LH_EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "--version")) {
        printf("lifthull %s\n", lh_version_string());
        return LH_EXIT_OK;
    }
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        usage(stdout);
        return LH_EXIT_OK;
    }
    for (int i = 0; i < n_commands; i++)
        if (!strcmp(cmd, commands[i].name)) return commands[i].run(argc - 2, argv + 2);
    fprintf(stderr, "lifthull: unknown command '%s' (try lifthull --help)\n", cmd);
    return LH_EXIT_USAGE;
}
