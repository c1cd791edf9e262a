/* args.c — shared option parsing of the native commands (args.h). */
#include "args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage_error(const char *cmd, const char *what, const char *arg)
{
    fprintf(stderr, "lifthull %s: %s '%s' (lifthull %s --help)\n", cmd, what, arg, cmd);
    return -1;
}

/* A whole number in lo..hi written as decimal digits only (no sign, blank or
 * exponent; not empty) into *out; 0 when s is anything else. */
static int whole(const char *s, long lo, long hi, int *out)
{
    long k = 0;
    if (!*s || strspn(s, "0123456789") != strlen(s) || strlen(s) > 9) return 0;
    for (; *s; s++) k = 10 * k + (*s - '0');
    if (k < lo || k > hi) return 0;
    *out = (int)k;
    return 1;
}

/* The option letter of argument s, or 0 when it is not an option. */
static char letter(const char *s)
{
    if (!strcmp(s, "--circles")) return 'c';
    if (!strcmp(s, "--ascii")) return 'A';
    if (!strcmp(s, "--values")) return 'v';
    if (!strcmp(s, "--threads")) return 't';
    if (!strcmp(s, "--format")) return 'F';
    if (s[0] == '-' && s[1] && !s[2] && strchr("suaqfom", s[1])) return s[1];
    return 0;
}

int lh_cli_args_parse(lh_cli_args *a, const char *cmd, const char *accepted, int min_files,
                      int max_files, int argc, char **argv, const char *help)
{
    memset(a, 0, sizeof *a);
    a->threads = 0; /* every CPU: the output is the same for every count */
    for (int i = 0; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            fputs(help, stdout);
            return 1;
        }
        char c = letter(s);
        if (s[0] == '-' && s[1] && (!c || (c != 't' && c != 'F' && !strchr(accepted, c))))
            return usage_error(cmd, "unknown option", s);
        if (!c) {
            if (a->nfile == max_files) return usage_error(cmd, "one operand too many:", s);
            a->file[a->nfile++] = s;
            continue;
        }
        if (strchr("omvtF", c) && i + 1 == argc) return usage_error(cmd, "a value is needed after", s);
        switch (c) {
        case 's': a->summary = 1; break;
        case 'u': a->furthest = 1; break;
        case 'a': a->affine = 1; break;
        case 'q': a->quiet = 1; break;
        case 'f': a->force = 1; break;
        case 'c': a->circles = 1; break;
        case 'A': a->ascii = 1; break;
        case 'o': a->output = argv[++i]; break;
        case 'm': a->method = argv[++i]; break;
        case 'F': {
            const char *f = argv[++i];
            a->format = !strcmp(f, "qhull") ? LH_FORMAT_QHULL : !strcmp(f, "node") ? LH_FORMAT_NODE
                      : !strcmp(f, "columns") ? LH_FORMAT_COLUMNS : (lh_format)-1;
            if (a->format == (lh_format)-1) return usage_error(cmd, "--format takes qhull, node or columns, not", f);
            break;
        }
        case 't': /* every point command accepts it */
            if (!whole(argv[++i], 0, 4096, &a->threads))
                return usage_error(cmd, "--threads takes a whole number from 0 to 4096, not", argv[i]);
            break;
        default:
            if (!whole(argv[++i], 1, 6, &a->values))
                return usage_error(cmd, "--values takes a whole number from 1 to 6, not", argv[i]);
        }
    }
    if (a->nfile < min_files) {
        fprintf(stderr, "lifthull %s: %d input file%s needed (lifthull %s --help)\n", cmd, min_files,
                min_files > 1 ? "s are" : " is", cmd);
        return -1;
    }
    return 0;
}
