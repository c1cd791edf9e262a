/* switches.h — what the commands spelled as Triangle and TetGen share (triangle.c,
 * tetgen.c): switch words with numbers after their letters, the operands, and the
 * iteration-numbered output names. */
#ifndef LH_CLI_SWITCHES_H
#define LH_CLI_SWITCHES_H

#include <stddef.h>

/* A number right after the switch letter s[*j] (digits, '.', an exponent): into
 * *out, *j moved to its last character; 0 when none follows. */
int lh_cli_switch_number(const char *s, int *j, double *out);

/* A count after s[*j]: none is `none`, a number is rounded down, one that no size_t
 * holds (1e30, 1e400) is SIZE_MAX. */
size_t lh_cli_switch_count(const char *s, int *j, size_t none);

/* Reads argv: --help or -h prints help and returns 1; each word starting with '-'
 * goes to parse (0 from it: a usage error, already printed); one operand into *file.
 * Returns 0 with *file set, or -1 after a usage error ("lifthull CMD: ..."). */
int lh_cli_switch_args(int argc, char **argv, const char *cmd, const char *help,
                       int (*parse)(const char *word, void *opt), void *opt, const char **file);

/* The output base of input base[0..n): BASE.1, or BASE.(k+1) when BASE ends in .k
 * (Triangle's and TetGen's rule); BASE itself with no_number. malloc'ed; NULL when out
 * of memory. */
char *lh_cli_out_base(const char *base, size_t n, int no_number);

#endif
