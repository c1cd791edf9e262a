/* cli.h — subcommands of the lifthull tool (a client of lifthull.h only). */
#ifndef LH_CLI_H
#define LH_CLI_H

/* Exit codes, documented in `lifthull --help`. */
enum { LH_EXIT_OK = 0, LH_EXIT_FAIL = 1, LH_EXIT_USAGE = 2, LH_EXIT_INPUT = 3 };

int lh_cli_selfcheck(int argc, char **argv);
int lh_cli_delaunay(int argc, char **argv);
int lh_cli_hull(int argc, char **argv);
int lh_cli_generate(int argc, char **argv);
int lh_cli_voronoi(int argc, char **argv);
int lh_cli_locate(int argc, char **argv);
int lh_cli_interpolate(int argc, char **argv);
int lh_cli_check(int argc, char **argv);
int lh_cli_qdelaunay(int argc, char **argv);
int lh_cli_qvoronoi(int argc, char **argv);
int lh_cli_qconvex(int argc, char **argv);
int lh_cli_qhalf(int argc, char **argv);
int lh_cli_triangle(int argc, char **argv);
int lh_cli_tetgen(int argc, char **argv);
int lh_cli_mesh(int argc, char **argv);

/* Shared by the commands that read points (common.c). */
#include <stdio.h>

#include "lifthull.h"
double lh_cli_seconds(void);
/* Opens path for reading; NULL after printing "PATH: problem" (a directory too). */
FILE *lh_cli_open_input(const char *path);
/* Reads FILE (or standard input for NULL or "-") in format fmt (LH_FORMAT_AUTO: by
 * name and content); 0 after printing the error. */
int lh_cli_load(const char *file, lh_format fmt, lh_points *pts, const char **name);
/* lh_cli_load with a progress line while reading (progress.h; prog may be NULL). */
struct lh_cli_progress;
int lh_cli_load_progress(const char *file, lh_format fmt, lh_points *pts, const char **name,
                         struct lh_cli_progress *prog);
/* Both files (sites, then queries); 0 after printing the problem. */
int lh_cli_load_pair(const char *f1, const char *f2, lh_format fmt, lh_points *a, lh_points *b,
                     const char **names);
void lh_cli_report_failure(const char *name, int d, size_t n, const double *xyz, lh_status st);
/* Flushes standard output: LH_EXIT_OK, or LH_EXIT_FAIL with a message. */
int lh_cli_finish_output(const char *cmd);

#endif
