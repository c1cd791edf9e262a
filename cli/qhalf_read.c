/*
 * qhalf_read.c — `lifthull qhalf`'s input: Qhull's halfspace format (dimension d+1,
 * count, then d+1 coefficients a_i, b_i a line, a_i.x + b_i <= 0; optionally first a
 * one-point "interior point" block) or cdd's H-representation (Fp/--cdd: b_i first,
 * sign flipped), read whole with line numbers for the messages.
 */
#include "cli.h"
#include "qhalf.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef lh_cli_halfspaces halfspaces;

/* A token reader over the whole input with line numbers. */
typedef struct scan {
    const char *s, *name;
    size_t line;
} scan;

static void skip_blank(scan *t, int newlines)
{
    for (; *t->s && isspace((unsigned char)*t->s) && (newlines || *t->s != '\n'); t->s++)
        t->line += *t->s == '\n';
}

/* The next number (across lines); 0 after printing an error naming `what`. */
static int number(scan *t, double *v, const char *what)
{
    skip_blank(t, 1);
    char *end;
    errno = 0;
    *v = strtod(t->s, &end);
    if (end == t->s || !isfinite(*v) || (*end && !isspace((unsigned char)*end))) {
        fprintf(stderr, "%s:%zu: expected %s, found %s\n", t->name, t->line, what,
                *t->s ? "text that is not a finite number" : "the end of the input");
        return 0;
    }
    t->s = end;
    return 1;
}

/* A count or a dimension as a long: -1 when it is not a whole number in 0..2^31. */
static long whole(double v)
{
    return v >= 0 && v <= 2147483648.0 && v == floor(v) ? (long)v : -1;
}

/* A header line: an integer, then either a second integer on the same line or a
 * comment (then the count is the next number, on a later line). Lines before it
 * that start with a character no number starts with are comments, as Qhull's
 * (qconvex FQ writes one). */
static int header(scan *t, long *dim, long *count, char *comment, size_t size)
{
    for (skip_blank(t, 1); *t->s && !isdigit((unsigned char)*t->s) && !strchr("+-.", *t->s); skip_blank(t, 1)) {
        size_t k = strcspn(t->s, "\r\n");
        if (comment && !*comment) snprintf(comment, size, "%.*s", (int)(k < size ? k : size - 1), t->s);
        t->s += k;
    }
    double v;
    if (!number(t, &v, "a dimension")) return 0;
    *dim = whole(v);
    skip_blank(t, 0);
    char *end;
    double c = *t->s && *t->s != '\n' ? strtod(t->s, &end) : 0;
    if (*t->s && *t->s != '\n' && end != t->s && (!*end || isspace((unsigned char)*end))) {
        t->s = end;
    } else {
        while (*t->s && *t->s != '\n') t->s++; /* a comment, as rbox writes */
        if (!number(t, &c, "the number of halfspaces")) return 0;
    }
    *count = whole(c);
    return 1;
}

static char *slurp(FILE *f, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *b = malloc(cap + 1);
    for (size_t k; b && (k = fread(b + n, 1, cap - n, f)) > 0;) {
        n += k;
        if (n == cap) {
            char *g = realloc(b, 2 * cap + 1);
            if (!g) free(b);
            b = g;
            cap *= 2;
        }
    }
    if (b) b[n] = 0;
    *len = n;
    return b;
}

/* Appends the coefficients of halfspace hs->n (d + 1 numbers, from the current
 * position), growing the arrays as they fill: memory follows what the input holds,
 * never a count it announces. cdd: cdd's row b' a' (b' + a'.x >= 0), stored as
 * Qhull's -a', -b'. 0 after printing the problem. */
static int append(scan *t, halfspaces *hs, size_t *cap, int cdd)
{
    const size_t D = (size_t)hs->d + 1;
    if (hs->n == *cap) {
        size_t c = *cap ? 2 * *cap : 256;
        double *h = realloc(hs->h, c * D * sizeof *h);
        if (h) hs->h = h;
        size_t *l = h ? realloc(hs->line, c * sizeof *l) : NULL;
        if (l) hs->line = l;
        if (!h || !l) {
            fprintf(stderr, "%s: out of memory\n", t->name);
            return 0;
        }
        *cap = c;
    }
    double *row = hs->h + hs->n * D;
    for (size_t j = 0; j < D; j++) {
        if (!number(t, &row[j], "a coefficient")) return 0;
        if (j == 0) hs->line[hs->n] = t->line;
    }
    if (cdd) {
        double b = row[0];
        for (size_t j = 0; j + 1 < D; j++) row[j] = -row[j + 1];
        row[D - 1] = -b;
    }
    hs->n++;
    return 1;
}

/* The next word (letters up to a blank), lower case, in w (at most 15 characters). */
static void next_word(scan *t, char *w)
{
    skip_blank(t, 1);
    size_t k = 0;
    for (; *t->s && !isspace((unsigned char)*t->s); t->s++)
        if (k < 15) w[k++] = (char)tolower((unsigned char)*t->s);
    w[k] = 0;
}

/* cdd's H-representation (Qhull's Fd): lines up to "begin", "m d+1 real" (or
 * integer), m rows, "end". */
static int cdd_header(scan *t, long *dim, long *count)
{
    char w[16] = "";
    while (*t->s && strcmp(w, "begin")) next_word(t, w);
    if (strcmp(w, "begin")) {
        fprintf(stderr, "%s:%zu: expected cdd's 'begin' line (option Fd), found the end of the "
                "input\n", t->name, t->line);
        return 0;
    }
    double c, dd;
    if (!number(t, &c, "the number of halfspaces") || !number(t, &dd, "the number of columns"))
        return 0;
    next_word(t, w);
    if (strcmp(w, "real") && strcmp(w, "integer")) {
        fprintf(stderr, "%s:%zu: expected cdd's number type 'real' or 'integer', found '%s'\n",
                t->name, t->line, w);
        return 0;
    }
    *count = whole(c);
    *dim = whole(dd);
    return 1;
}

int lh_cli_qhalf_read(const char *file, int cdd, halfspaces *hs, const char **name)
{
    FILE *f = stdin;
    *name = "<stdin>";
    if (file && strcmp(file, "-")) {
        *name = file;
        if (!(f = lh_cli_open_input(file))) return 0; /* said: missing, a directory, ... */
    }
    size_t len;
    char *text = slurp(f, &len);
    int bad = ferror(f);
    if (f != stdin) fclose(f);
    if (!text || bad) {
        fprintf(stderr, "%s: %s\n", *name, text ? "read error" : "out of memory");
        free(text);
        return 0;
    }
    scan t = {text, *name, 1};
    long dim, count;
    int ok = cdd ? cdd_header(&t, &dim, &count) : header(&t, &dim, &count, hs->comment, sizeof hs->comment);
    if (!cdd && ok && count == 1 && dim >= 2 && dim <= LH_DELAUNAY_MAX_DIM) { /* the interior point */
        long cdim = dim;
        hs->has_c = 1;
        for (long j = 0; ok && j < dim; j++) ok = number(&t, &hs->c[j], "a coordinate of the interior point");
        if (ok) ok = header(&t, &dim, &count, NULL, 0);
        if (ok && dim != cdim + 1) {
            fprintf(stderr, "%s:%zu: the interior point has %ld coordinates, so the halfspaces need "
                    "%ld coefficients, not %ld\n", *name, t.line, cdim, cdim + 1, dim);
            ok = 0;
        }
    }
    if (ok && (dim < 3 || dim > LH_DELAUNAY_MAX_DIM + 1 || count < 1 || count > (1L << 30))) {
        fprintf(stderr, "%s:%zu: expected halfspaces of 3..%d coefficients (2-d..%d-d) and a positive "
                "count, found %ld and %ld\n", *name, t.line, LH_DELAUNAY_MAX_DIM + 1,
                LH_DELAUNAY_MAX_DIM, dim, count);
        ok = 0;
    }
    hs->d = (int)dim - 1;
    size_t cap = 0;
    while (ok && hs->n < (size_t)count) ok = append(&t, hs, &cap, cdd);
    if (ok && cdd) {
        char w[16];
        next_word(&t, w);
        if (strcmp(w, "end")) {
            fprintf(stderr, "%s:%zu: expected cdd's 'end' after the %zu halfspaces announced\n",
                    *name, t.line, hs->n);
            ok = 0;
        }
    }
    if (ok) {
        skip_blank(&t, 1);
        if (*t.s && !cdd) {
            fprintf(stderr, "%s:%zu: more than the %zu halfspaces announced\n", *name, t.line, hs->n);
            ok = 0;
        }
    }
    free(text);
    return ok;
}
