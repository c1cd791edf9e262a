/* switches.c — switch words, operands and output names of `triangle` and `tetgen`
 * (switches.h). */
#include "switches.h"

#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int lh_cli_switch_number(const char *s, int *j, double *out)
{
    const char *p = s + *j + 1;
    if (!isdigit((unsigned char)*p) && *p != '.') return 0;
    char *end;
    *out = strtod(p, &end);
    *j += (int)(end - p);
    return 1;
}

size_t lh_cli_switch_count(const char *s, int *j, size_t none)
{
    double x;
    return !lh_cli_switch_number(s, j, &x) ? none : x >= (double)SIZE_MAX ? SIZE_MAX : (size_t)x;
}

int lh_cli_switch_args(int argc, char **argv, const char *cmd, const char *help,
                       int (*parse)(const char *word, void *opt), void *opt, const char **file)
{
    *file = NULL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(help, stdout);
            return 1;
        }
        if (argv[i][0] == '-' && argv[i][1]) {
            if (!parse(argv[i], opt)) return -1;
        } else if (*file) {
            fprintf(stderr, "lifthull %s: one input file, not '%s' and '%s'\n", cmd, *file, argv[i]);
            return -1;
        } else {
            *file = argv[i];
        }
    }
    if (!*file) {
        fputs(help, stderr);
        return -1;
    }
    return 0;
}

char *lh_cli_out_base(const char *base, size_t n, int no_number)
{
    char *o = malloc(n + 24);
    if (!o) return NULL;
    size_t d = n;
    while (d > 0 && isdigit((unsigned char)base[d - 1])) d--;
    memcpy(o, base, n);
    o[n] = 0;
    if (no_number) return o;
    if (d < n && d > 1 && base[d - 1] == '.' && n - d < 18)
        snprintf(o + d, 24, "%lld", atoll(base + d) + 1);
    else
        snprintf(o + n, 24, ".1");
    return o;
}
