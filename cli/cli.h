/* cli.h — subcommands of the lifthull tool (a client of lifthull.h only). */
#ifndef LH_CLI_H
#define LH_CLI_H

/* Exit codes, documented in `lifthull --help`. */
enum { LH_EXIT_OK = 0, LH_EXIT_FAIL = 1, LH_EXIT_USAGE = 2, LH_EXIT_INPUT = 3 };

int lh_cli_selfcheck(int argc, char **argv);
int lh_cli_delaunay(int argc, char **argv);

#endif
