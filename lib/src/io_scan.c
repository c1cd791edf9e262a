/* io_scan.c — the readers' byte scanner, tokens and diagnostics (io_internal.h).
 *
 * Positions: line and column are 1-based; the column counts bytes (a tab is one
 * column, as compilers count). A CRLF line end is located at its '\r'. */
#include "io_internal.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* Refills the block from f; the next byte, or EOF (after a read error too). */
static int refill(lh__scan *s)
{
    s->block_pos = 0;
    s->block_len = fread(s->block, 1, sizeof s->block, s->f);
    if (s->block_len == 0) {
        if (ferror(s->f)) s->read_error = 1;
        return EOF;
    }
    return s->block[s->block_pos++];
}

static inline int fetch(lh__scan *s)
{
    if (s->block_pos < s->block_len) return s->block[s->block_pos++];
    if (s->pre_pos < s->pre_len) return s->pre[s->pre_pos++];
    return refill(s);
}

lh__scan *lh__scan_open(FILE *f, size_t pre_want, const lh_allocator *al, const char *name,
                        lh_error *err)
{
    lh__scan *s = lh__alloc(al, sizeof *s);
    if (!s) {
        if (err) err->line = err->column = 1;
        lh__error_say(err, LH_ERR_NOMEM, "%s:1:1: out of memory for the input buffer", name);
        return NULL;
    }
    memset(s, 0, offsetof(lh__scan, head));
    s->al = *al;
    size_t len = 0;
    int c;
    while (len < pre_want && len < sizeof s->head && (c = getc(f)) != EOF)
        s->head[len++] = (unsigned char)c;
    s->f = f;
    s->pre = s->head;
    s->pre_len = len;
    /* The UTF-8 encoding of U+FEFF, which some editors put first (RFC 3629, 6). */
    if (len >= 3 && s->head[0] == 0xEF && s->head[1] == 0xBB && s->head[2] == 0xBF) s->pre_pos = 3;
    s->name = name;
    s->err = err;
    s->line = 1;
    s->col = 1;
    s->c = fetch(s);
    return s;
}

void lh__scan_close(lh__scan *s)
{
    if (!s) return;
    const lh_allocator al = s->al;
    lh__free(&al, s);
}

static inline void advance(lh__scan *s)
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

void lh__scan_advance(lh__scan *s) { advance(s); }

static int is_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

int lh__is_text(int c) { return (c >= 0x20 && c < 0x7f) || is_blank(c) || c == '\n'; }

int lh__starts_number(int c) { return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'; }

void lh__scan_skip(lh__scan *s, int cross_lines)
{
    for (;;) {
        while (is_blank(s->c) || (cross_lines && s->c == '\n')) advance(s);
        if (s->c != '#') return;
        /* A comment may hold any byte but NUL, which the next token reports. */
        while (s->c != EOF && s->c != '\n' && s->c != 0) advance(s);
    }
}

void lh__scan_skip_line(lh__scan *s)
{
    while (s->c != EOF && s->c != '\n' && s->c != 0) advance(s);
    if (s->c == '\n') advance(s);
}

/* A text byte that is neither blank nor a line end nor '#' (nor a splitting ','). */
static inline int word_char(int c, int commas)
{
    return c > 0x20 && c < 0x7f && c != '#' && !(commas && c == ',');
}

static inline int word_byte(const lh__scan *s) { return word_char(s->c, s->commas); }

/* Appends to t the word bytes that follow in the block (the pre bytes being used
 * up), at most up to LH_READ_MAX_TOKEN, advancing over them: advance() for bytes
 * that are neither '\n' nor '\r', without the per-byte calls. */
static void take_run(lh__scan *s, lh__token *t)
{
    const unsigned char *in = s->block;
    char *out = t->text;
    size_t i = s->block_pos, len = t->len, room = LH_READ_MAX_TOKEN - len;
    size_t stop = s->block_len - i < room ? s->block_len : i + room;
    if (s->commas) {
        while (i < stop && word_char(in[i], 1)) out[len++] = (char)in[i++];
    } else {
        while (i < stop && word_char(in[i], 0)) out[len++] = (char)in[i++];
    }
    t->len = len;
    s->col += i - s->block_pos;
    s->block_pos = i;
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
        advance(s);
    } else if (s->c == 0) {
        t->kind = LH__TOK_NUL;
    } else if (s->commas && s->c == ',') {
        t->kind = LH__TOK_COMMA;
        t->text[0] = ',';
        t->text[1] = 0;
        t->len = 1;
        advance(s);
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
            s->col++; /* advance(s) for a byte that is neither '\n' nor '\r' */
            s->cr_col = 0;
            if (s->pre_pos == s->pre_len) take_run(s, t);
            s->c = fetch(s);
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
    if (!s->err) return st;
    s->err->line = t->line;
    s->err->column = t->col;
    return lh__error_say(s->err, st, "%s:%zu:%zu: %s", s->name, t->line, t->col, text);
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
    return lh__parse_double(t->text, t->len, x);
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

lh_status lh__header_field(lh__scan *s, const char *what, long long hi, int *v, int *ended)
{
    lh__token t;
    long long x;
    if (*ended) return LH_OK;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) {
        *ended = 1;
        return LH_OK;
    }
    if (!lh__word_integer(&t, &x) || x < 0 || x > hi) return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
    *v = (int)x;
    return LH_OK;
}
