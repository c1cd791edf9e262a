/* generate.c — `lifthull points`: test point sets (placeholder). */
#include "cli.h"

#include <stdio.h>

int lh_cli_generate(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "lifthull points: not implemented yet\n");
    return LH_EXIT_USAGE;
}
