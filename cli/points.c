/* points.c — Qhull-format point reader with file:line:column diagnostics. */
#include "points.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct scan {
    FILE *f;
    const char *name;
    long line, col;
    int c; /* current character, EOF at end */
} scan;

static void advance(scan *s)
{
    if (s->c == '\n') {
        s->line++;
        s->col = 0;
    }
    s->c = fgetc(s->f);
    s->col++;
}

/* Skips blanks and comments; returns 0 at end of input. */
static int skip(scan *s)
{
    for (;;) {
        while (s->c != EOF && isspace(s->c)) advance(s);
        if (s->c == '#') {
            while (s->c != EOF && s->c != '\n') advance(s);
            continue;
        }
        return s->c != EOF;
    }
}

static int error(const scan *s, const char *what)
{
    fprintf(stderr, "%s:%ld:%ld: %s\n", s->name, s->line, s->col, what);
    return 0;
}

/* One token into buf; 0 at end of input or if the token is too long. */
static int token(scan *s, char *buf, size_t size, long *line, long *col)
{
    if (!skip(s)) return 0;
    *line = s->line;
    *col = s->col;
    size_t k = 0;
    while (s->c != EOF && !isspace(s->c) && s->c != '#') {
        if (k + 1 >= size) return -1;
        buf[k++] = (char)s->c;
        advance(s);
    }
    buf[k] = 0;
    return 1;
}

static int read_count(scan *s, const char *what, long max, long *out, scan *where)
{
    char buf[64], msg[160];
    long line, col;
    int r = token(s, buf, sizeof buf, &line, &col);
    scan at = *s;
    at.line = r ? line : s->line;
    at.col = r ? col : s->col;
    if (r == 0) {
        snprintf(msg, sizeof msg, "expected %s, found the end of the input", what);
        return error(&at, msg);
    }
    char *end;
    errno = 0;
    long v = r > 0 ? strtol(buf, &end, 10) : 0;
    if (r < 0 || *end || errno || v < 1 || v > max) {
        snprintf(msg, sizeof msg, "expected %s (an integer from 1 to %ld), found '%.20s'", what, max, r < 0 ? "a very long token" : buf);
        return error(&at, msg);
    }
    *out = v;
    if (where) *where = at;
    return 1;
}

int lh_cli_read_points(FILE *f, const char *name, lh_cli_points *out)
{
    scan s = {f, name, 1, 0, 0};
    memset(out, 0, sizeof *out);
    advance(&s);
    long d, n;
    scan dim_at;
    if (!read_count(&s, "the dimension", 8, &d, &dim_at)) return 0;
    if (d < 2) return error(&dim_at, "expected the dimension to be 2..8: lifthull works in 2 to 8 dimensions");
    /* The rest of the dimension's line is the count (the one-line "d n" form) or a
     * comment (rbox writes its command line there), as in Qhull. */
    char rest[256];
    size_t k = 0;
    while (s.c != EOF && s.c != '\n') {
        if (k + 1 < sizeof rest) rest[k++] = (char)s.c;
        advance(&s);
    }
    rest[k] = 0;
    char *end;
    errno = 0;
    long inline_n = strtol(rest, &end, 10);
    while (isspace((unsigned char)*end)) end++;
    if (end != rest && !*end && !errno && inline_n >= 1 && inline_n < INT32_MAX)
        n = inline_n;
    else if (!read_count(&s, "the number of points", INT32_MAX - 1, &n, NULL))
        return 0;
    double *xyz = malloc((size_t)n * (size_t)d * sizeof *xyz);
    if (!xyz) {
        fprintf(stderr, "%s: out of memory for %ld points\n", name, n);
        return 0;
    }
    char buf[128], msg[200];
    for (long i = 0; i < n * d; i++) {
        long line, col;
        int r = token(&s, buf, sizeof buf, &line, &col);
        scan at = s;
        at.line = r ? line : s.line;
        at.col = r ? col : s.col;
        if (r == 0) {
            snprintf(msg, sizeof msg, "expected coordinate %ld of point %ld, found the end of the input (%ld points declared)",
                     i % d + 1, i / d + 1, n);
            free(xyz);
            return error(&at, msg);
        }
        char *stop;
        double x = r > 0 ? strtod(buf, &stop) : 0;
        if (r < 0 || *stop || stop == buf) {
            snprintf(msg, sizeof msg, "expected coordinate %ld of point %ld (a number), found '%.20s'",
                     i % d + 1, i / d + 1, r < 0 ? "a very long token" : buf);
            free(xyz);
            return error(&at, msg);
        }
        if (!isfinite(x)) {
            snprintf(msg, sizeof msg, "coordinate %ld of point %ld is '%.20s': NaN and infinities are not points",
                     i % d + 1, i / d + 1, buf);
            free(xyz);
            return error(&at, msg);
        }
        xyz[i] = x;
    }
    long line, col;
    int r = token(&s, buf, sizeof buf, &line, &col);
    if (r != 0) {
        scan at = s;
        at.line = line;
        at.col = col;
        snprintf(msg, sizeof msg, "expected the end of the input after %ld points of dimension %ld, found '%.20s'", n, d, r < 0 ? "a very long token" : buf);
        free(xyz);
        return error(&at, msg);
    }
    out->d = (int)d;
    out->n = (size_t)n;
    out->xyz = xyz;
    return 1;
}
