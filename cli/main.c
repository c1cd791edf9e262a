/* main.c — the lifthull command line: dispatch, --help, --version. */
#include "cli.h"
#include "lifthull.h"

#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: lifthull COMMAND [ARGS]\n"
            "       lifthull --version | --help\n"
            "\n"
            "commands:\n"
            "  delaunay [-s] [-u] [-a] [FILE]\n"
            "                     Delaunay triangulation of the points in FILE (or standard\n"
            "                     input), Qhull's point format (dimension, count, coordinates;\n"
            "                     rbox output as it is); writes the simplices in Qhull's 'i'\n"
            "                     format (count, then one simplex per line, 0-based site\n"
            "                     indices); -s writes a summary instead; -u gives the\n"
            "                     furthest-site triangulation (Qhull's Qu); -a triangulates\n"
            "                     points that span only a k-flat (1 <= k < d) within it\n"
            "                     (k+1 indices per simplex) instead of failing.\n"
            "                     e.g.  rbox 1000 D3 | lifthull delaunay\n"
            "  hull [-s] [FILE]   convex hull facets of the points, qconvex's 'i' format\n"
            "                     (count, then one facet per line, d 0-based site indices,\n"
            "                     oriented outward); -s writes a summary instead.\n"
            "                     e.g.  rbox 1000 D4 | lifthull hull -s\n"
            "  selfcheck [FILE]   check the exact predicates on near-degenerate cases\n"
            "                     (FILE: lines 'orient K SIGN coords...' or\n"
            "                     'insphere D SIGN coords...'; default: the bundled\n"
            "                     tests/data/near_degenerate.txt)\n"
            "\n"
            "exit codes: 0 success, 1 a check failed, 2 usage error, 3 bad input file\n");
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
    if (!strcmp(cmd, "selfcheck")) return lh_cli_selfcheck(argc - 2, argv + 2);
    if (!strcmp(cmd, "delaunay")) return lh_cli_delaunay(argc - 2, argv + 2);
    if (!strcmp(cmd, "hull")) return lh_cli_hull(argc - 2, argv + 2);
    fprintf(stderr, "lifthull: unknown command '%s' (try lifthull --help)\n", cmd);
    return LH_EXIT_USAGE;
}
