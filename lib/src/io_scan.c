/* io_scan.c — the readers' byte scanner, tokens and diagnostics (io_internal.h).
 *
 * Positions: line and column are 1-based; the column counts bytes (a tab is one
 * column, as compilers count). A CRLF line end is located at its '\r'. */
#include "io_internal.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int fetch(lh__scan *s)
{
    if (s->pre_pos < s->pre_len) return s->pre[s->pre_pos++];
    int c = getc(s->f);
    if (c == EOF && ferror(s->f)) s->read_error = 1;
    return c;
}

void lh__scan_init(lh__scan *s, FILE *f, const unsigned char *pre, size_t pre_len,
                   const char *name, char *msg, size_t msg_size)
{
    memset(s, 0, sizeof *s);
    s->f = f;
    s->pre = pre;
    s->pre_len = pre_len;
    /* The UTF-8 encoding of U+FEFF, which some editors put first (RFC 3629, 6). */
    if (pre_len >= 3 && pre[0] == 0xEF && pre[1] == 0xBB && pre[2] == 0xBF) s->pre_pos = 3;
    s->name = name;
    s->msg = msg;
    s->msg_size = msg_size;
    s->line = 1;
    s->col = 1;
    s->c = fetch(s);
}

void lh__scan_advance(lh__scan *s)
{
    int was = s->c;
    size_t col = s->col;
    if (was == EOF) return;
    if (was == '\n') {
        s->line++;
        s->col = 1;
    } else {
        s->col++;
    }
    s->c = fetch(s);
    s->cr_col = (was == '\r' && s->c == '\n') ? col : 0;
}

static int is_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

int lh__is_text(int c) { return (c >= 0x20 && c < 0x7f) || is_blank(c) || c == '\n'; }

int lh__starts_number(int c) { return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'; }

void lh__scan_skip(lh__scan *s, int cross_lines)
{
    for (;;) {
        while (is_blank(s->c) || (cross_lines && s->c == '\n')) lh__scan_advance(s);
        if (s->c != '#') return;
        /* A comment may hold any byte but NUL, which the next token reports. */
        while (s->c != EOF && s->c != '\n' && s->c != 0) lh__scan_advance(s);
    }
}

void lh__scan_skip_line(lh__scan *s)
{
    while (s->c != EOF && s->c != '\n' && s->c != 0) lh__scan_advance(s);
    if (s->c == '\n') lh__scan_advance(s);
}

static int word_byte(const lh__scan *s)
{
    int c = s->c;
    return c != EOF && lh__is_text(c) && !is_blank(c) && c != '\n' && c != '#' &&
           !(s->commas && c == ',');
}

void lh__scan_next(lh__scan *s, int cross_lines, lh__token *t)
{
    lh__scan_skip(s, cross_lines);
    t->line = s->line;
    t->col = s->col;
    t->len = 0;
    t->text[0] = 0;
    t->byte = s->c;
    if (s->c == EOF) {
        t->kind = s->read_error ? LH__TOK_READ_ERROR : LH__TOK_EOF;
    } else if (s->c == '\n') {
        t->kind = LH__TOK_EOL;
        if (s->cr_col) t->col = s->cr_col;
        lh__scan_advance(s);
    } else if (s->c == 0) {
        t->kind = LH__TOK_NUL;
    } else if (s->commas && s->c == ',') {
        t->kind = LH__TOK_COMMA;
        t->text[0] = ',';
        t->text[1] = 0;
        t->len = 1;
        lh__scan_advance(s);
    } else if (!word_byte(s)) {
        t->kind = LH__TOK_BYTE;
    } else {
        t->kind = LH__TOK_WORD;
        while (word_byte(s)) {
            if (t->len == LH_READ_MAX_TOKEN) {
                t->kind = LH__TOK_LONG;
                t->text[0] = 0;
                return;
            }
            t->text[t->len++] = (char)s->c;
            lh__scan_advance(s);
        }
        t->text[t->len] = 0;
    }
}

/* What t is, for "found ...". */
static void describe(const lh__token *t, char *buf, size_t size)
{
    switch (t->kind) {
    case LH__TOK_WORD:
    case LH__TOK_COMMA:
        snprintf(buf, size, t->len > 20 ? "'%.20s...'" : "'%.20s'", t->text); /* len <= 20 */
        break;
    case LH__TOK_EOL: snprintf(buf, size, "the end of the line"); break;
    case LH__TOK_EOF: snprintf(buf, size, "the end of the input"); break;
    case LH__TOK_LONG: snprintf(buf, size, "a token of more than %d bytes", LH_READ_MAX_TOKEN); break;
    case LH__TOK_NUL: snprintf(buf, size, "a NUL byte"); break;
    case LH__TOK_BYTE: snprintf(buf, size, "a non-text byte 0x%02x", (unsigned)t->byte & 0xffu); break;
    case LH__TOK_READ_ERROR: snprintf(buf, size, "a read error"); break;
    }
}

lh_status lh__fail_at(lh__scan *s, lh_status st, const lh__token *t, const char *text)
{
    if (s->msg && s->msg_size)
        snprintf(s->msg, s->msg_size, "%s:%zu:%zu: %s", s->name, t->line, t->col, text);
    return st;
}

lh_status lh__expected(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                       const char *tail)
{
    char found[64], text[400];
    describe(t, found, sizeof found);
    snprintf(text, sizeof text, "expected %s, found %s%s", what, found, tail ? tail : "");
    if (t->kind == LH__TOK_READ_ERROR) st = LH_ERR_IO;
    else if (t->kind == LH__TOK_NUL || t->kind == LH__TOK_BYTE || t->kind == LH__TOK_LONG)
        st = LH_ERR_PARSE;
    return lh__fail_at(s, st, t, text);
}

int lh__word_double(const lh__token *t, double *x)
{
    if (t->kind != LH__TOK_WORD || t->len == 0) return 0;
    char *end;
    *x = strtod(t->text, &end);
    return end == t->text + t->len;
}

int lh__word_integer(const lh__token *t, long long *v)
{
    if (t->kind != LH__TOK_WORD) return 0;
    const char *p = t->text;
    int neg = *p == '-';
    if (*p == '+' || *p == '-') p++;
    if (!*p) return 0;
    long long x = 0;
    for (; *p; p++) {
        if (*p < '0' || *p > '9') return 0;
        int digit = *p - '0';
        x = x > (LLONG_MAX - digit) / 10 ? LLONG_MAX : 10 * x + digit;
    }
    *v = neg ? -x : x;
    return 1;
}

lh_status lh__nonfinite(lh__scan *s, const lh__token *t, const char *what,
                        const char *noun)
{
    char text[400];
    /* strtod gives an infinity for a finite decimal beyond DBL_MAX: say so. */
    if (!strpbrk(t->text, "iInN"))
        snprintf(text, sizeof text, "%s is '%.20s', which overflows a double", what, t->text);
    else
        snprintf(text, sizeof text, "%s is '%.20s': NaN and infinities are not %s", what,
                 t->text, noun);
    return lh__fail_at(s, LH_ERR_NONFINITE, t, text);
}

lh_status lh__number(lh__scan *s, const lh__token *t, const char *what, const char *noun,
                     const char *end_tail, double *x)
{
    if (t->kind == LH__TOK_EOF || t->kind == LH__TOK_EOL)
        return lh__expected(s, LH_ERR_PARSE, t, what, t->kind == LH__TOK_EOF ? end_tail : NULL);
    if (!lh__word_double(t, x)) {
        char w[200];
        snprintf(w, sizeof w, "%s (a number)", what);
        return lh__expected(s, LH_ERR_PARSE, t, w, NULL);
    }
    if (!isfinite(*x)) return lh__nonfinite(s, t, what, noun);
    return LH_OK;
}

/* The CLI prints these as they are (tests/cli/bad_input.sh). */
lh_status lh__dimension(lh__scan *s, const lh__token *t, int *d)
{
    const char *what = "the dimension (an integer from 2 to 8)";
    long long v;
    if (!lh__word_integer(t, &v))
        return lh__expected(s, LH_ERR_PARSE, t,
                            t->kind == LH__TOK_WORD ? what : "the dimension", NULL);
    if (v < LH_DELAUNAY_MIN_DIM || v > LH_DELAUNAY_MAX_DIM)
        return lh__expected(s, LH_ERR_DIMENSION, t, what, NULL);
    *d = (int)v;
    return LH_OK;
}

lh_status lh__count(lh__scan *s, const lh__token *t, const char *what, size_t *n)
{
    char w[200];
    long long v;
    snprintf(w, sizeof w, "%s (an integer from 1 to %" LH_INDEX_PRI ")", what, LH_READ_MAX_POINTS);
    if (!lh__word_integer(t, &v) || v < 1)
        return lh__expected(s, LH_ERR_PARSE, t, t->kind == LH__TOK_WORD ? w : what, NULL);
    if (v > LH_READ_MAX_POINTS) return lh__expected(s, LH_ERR_TOO_LARGE, t, w, NULL);
    *n = (size_t)v;
    return LH_OK;
}
