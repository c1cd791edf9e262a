/* bound_read.c — files of per-item bounds, beside a mesh's input:
 *
 * Triangle's .area, for `triangle -ra` (pslg_io.h):
 *     count                 the number of triangles of the .ele beside it
 *     number area           one line per triangle, numbered from 0 or 1 consecutively;
 *                           an area <= 0 (Triangle writes -1): no bound
 * TetGen's .mtr, for `tetgen -m` (tetgen_io.h):
 *     count 1               the number of points of the input, one size each
 *     size                  one line per point, in the input's order: the edge length
 *                           wanted there, a positive number
 *
 * '#' starts a comment; blank lines anywhere; lines of any length. The whole file is
 * read first, so a NUL byte or a token running on after a number is seen as such.
 * Every problem is one line "FILE:LINE:COL: expected ..., found ..." on stderr. */
#include "pslg_io.h"
#include "tetgen_io.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct area_text {
    const char *path, *p, *end;
    size_t line;
    const char *line_start;
} area_text;

typedef struct token {
    const char *s;   /* NULL: the end of the file; s == e: the end of a line */
    size_t len, line, col;
    int nul;         /* a NUL byte where the token would start */
} token;

/* The next token on the current line (eol = 0) or on any later one (eol = 1). */
static token next(area_text *x, int any_line)
{
    for (;;) {
        while (x->p < x->end && (*x->p == ' ' || *x->p == '\t' || *x->p == '\r')) x->p++;
        if (x->p < x->end && *x->p == '#')
            while (x->p < x->end && *x->p != '\n') x->p++;
        if (x->p < x->end && *x->p == '\n' && any_line) {
            x->p++;
            x->line++;
            x->line_start = x->p;
            continue;
        }
        break;
    }
    token t = {x->p, 0, x->line, (size_t)(x->p - x->line_start) + 1, 0};
    if (x->p == x->end) t.s = NULL;
    else if (*x->p == 0) t.nul = 1;
    while (x->p < x->end && !strchr(" \t\r\n#", *x->p) && *x->p) x->p++;
    t.len = (size_t)(x->p - t.s);
    if (t.nul) x->p++;
    return t;
}

static int expected(const area_text *x, const token *t, const char *what)
{
    if (!t->s) fprintf(stderr, "%s:%zu:%zu: expected %s, found the end of the file\n", x->path, t->line, t->col, what);
    else if (t->nul) fprintf(stderr, "%s:%zu:%zu: expected %s, found a NUL byte\n", x->path, t->line, t->col, what);
    else if (!t->len) fprintf(stderr, "%s:%zu:%zu: expected %s, found the end of the line\n", x->path, t->line, t->col, what);
    else fprintf(stderr, "%s:%zu:%zu: expected %s, found '%.*s'\n", x->path, t->line, t->col, what,
                 (int)(t->len > 40 ? 40 : t->len), t->s);
    return 0;
}

/* A whole token as a decimal integer of at most 18 digits. */
static int integer(const token *t, long long *v)
{
    if (!t->s || t->nul || !t->len || t->len > 18) return 0;
    *v = 0;
    for (size_t i = 0; i < t->len; i++) {
        if (t->s[i] < '0' || t->s[i] > '9') return 0;
        *v = 10 * *v + (t->s[i] - '0');
    }
    return 1;
}

/* A whole token as a double (strtod's syntax, of any length, as a .node's numbers):
 * 1 finite, 2 NaN or infinity, 3 a finite decimal beyond DBL_MAX; 0 not a number,
 * -1 out of memory for a long token's copy. */
static int number(const token *t, double *v)
{
    char small[64], *buf = small;
    if (!t->s || t->nul || !t->len) return 0;
    if (t->len >= sizeof small && !(buf = malloc(t->len + 1))) return -1;
    memcpy(buf, t->s, t->len);
    buf[t->len] = 0;
    char *end;
    *v = strtod(buf, &end);
    const int kind = end != buf + t->len ? 0 : isfinite(*v) ? 1 : strpbrk(buf, "iInN") ? 2 : 3;
    if (buf != small) free(buf);
    return kind;
}

/* The end of the line (or of the file) after what; 0 after printing otherwise. */
static int line_end(area_text *x, const char *what)
{
    token t = next(x, 0);
    return !t.s || (!t.nul && !t.len) ? 1 : expected(x, &t, what);
}

/* Point k's line of a .mtr: its size, a positive number. */
static int size_item(area_text *x, size_t k, double *size)
{
    char what[96];
    token t = next(x, 1);
    snprintf(what, sizeof what, "the size at point %zu (a positive number)", k + 1);
    const int kind = number(&t, size);
    if (kind < 0) {
        fprintf(stderr, "%s: out of memory\n", x->path);
        return 0;
    }
    if (kind != 1 || !(*size > 0)) {
        if (kind == 0 || kind == 1) return expected(x, &t, what);
        fprintf(stderr, "%s:%zu:%zu: the size at point %zu is '%.*s'%s\n", x->path, t.line, t.col, k + 1,
                (int)t.len, t.s, kind == 2 ? ": NaN and infinities are not accepted" : ", which overflows a double");
        return 0;
    }
    snprintf(what, sizeof what, "the end of the line after point %zu's size", k + 1);
    return line_end(x, what);
}

static int parse_mtr(area_text *x, size_t count, double *size)
{
    char what[96];
    token t = next(x, 1);
    long long n;
    snprintf(what, sizeof what, "the number of points (%zu, as in the input)", count);
    if (!integer(&t, &n) || (unsigned long long)n != count) return expected(x, &t, what);
    t = next(x, 0);
    if (!integer(&t, &n) || n != 1) return expected(x, &t, "the sizes per point, 1");
    if (!line_end(x, "the end of the header line")) return 0;
    for (size_t k = 0; k < count; k++)
        if (!size_item(x, k, &size[k])) return 0;
    t = next(x, 1);
    if (!t.s) return 1;
    snprintf(what, sizeof what, "the end of the file after %zu sizes", count);
    return expected(x, &t, what);
}

/* Triangle k's line: "number area" then the end of the line. */
static int item(area_text *x, size_t k, long long *first, double *area)
{
    char what[96];
    token t = next(x, 1);
    long long num;
    const long long want = *first < 0 ? 0 : *first + (long long)k;
    if (!integer(&t, &num) || (*first < 0 ? num > 1 : num != want)) {
        if (*first < 0) snprintf(what, sizeof what, "the first triangle's number (0 or 1)");
        else snprintf(what, sizeof what, "triangle number %lld", want);
        return expected(x, &t, what);
    }
    if (*first < 0) *first = num;
    t = next(x, 0);
    snprintf(what, sizeof what, "the area bound of triangle %lld (a number)", num);
    const int kind = number(&t, area);
    if (kind < 0) {
        fprintf(stderr, "%s: out of memory\n", x->path);
        return 0;
    }
    if (!kind) return expected(x, &t, what);
    if (kind > 1) {
        fprintf(stderr, "%s:%zu:%zu: the area bound of triangle %lld is '%.*s'%s\n", x->path, t.line, t.col, num,
                (int)t.len, t.s, kind == 2 ? ": NaN and infinities are not accepted (0 or below: no bound)"
                                           : ", which overflows a double");
        return 0;
    }
    t = next(x, 0);
    if (!t.s || (!t.nul && !t.len)) return 1;
    snprintf(what, sizeof what, "the end of the line after triangle %lld's area bound", num);
    return expected(x, &t, what);
}

static int parse(area_text *x, size_t count, double *area)
{
    char what[96];
    token t = next(x, 1);
    long long n;
    snprintf(what, sizeof what, "the number of triangles (%zu, as in the .ele)", count);
    if (!integer(&t, &n) || (unsigned long long)n != count) return expected(x, &t, what);
    t = next(x, 0);
    if (!t.s || (!t.nul && !t.len)) { /* the header's end */
        long long first = -1;
        for (size_t k = 0; k < count; k++)
            if (!item(x, k, &first, &area[k])) return 0;
        t = next(x, 1);
        if (!t.s) return 1;
        snprintf(what, sizeof what, "the end of the file after %zu triangles", count);
        return expected(x, &t, what);
    }
    return expected(x, &t, "the end of the header line");
}

/* The whole of file f, malloc'ed, in *text and *len; 0 after printing the problem. */
static int slurp(FILE *f, const char *path, char **text, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *b = malloc(cap);
    for (size_t got = 1; b && got;) {
        if (n == cap) {
            char *nb = cap > SIZE_MAX / 2 ? NULL : realloc(b, cap * 2);
            if (!nb) break;
            b = nb, cap *= 2;
        }
        got = fread(b + n, 1, cap - n, f);
        n += got;
    }
    if (!b || ferror(f) || !feof(f)) {
        fprintf(stderr, "%s: %s\n", path, !b || !ferror(f) ? "out of memory" : strerror(errno));
        free(b);
        return 0;
    }
    *text = b, *len = n;
    return 1;
}

/* The file read whole and parsed by one of the parsers above. */
static int read_with(FILE *f, const char *path, size_t count, double *v, int (*parser)(area_text *, size_t, double *))
{
    char *text;
    size_t len;
    if (!slurp(f, path, &text, &len)) return 0;
    area_text x = {path, text, text + len, 1, text};
    const int ok = parser(&x, count, v);
    free(text);
    return ok;
}

int lh_cli_area_read(FILE *f, const char *path, size_t count, double *area)
{
    return read_with(f, path, count, area, parse);
}

int lh_cli_mtr_read(FILE *f, const char *path, size_t count, double *size)
{
    return read_with(f, path, count, size, parse_mtr);
}
