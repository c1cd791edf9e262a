/* io_columns.c — columns of numbers, one point a line: plain tables ("x y z") and CSV
 * (RFC 4180 without quoted fields). Fields are separated by blanks or by one comma with
 * optional blanks around it; every line holds the same number d = 2..8 of fields (the
 * first data line sets d); '#' comments and blank lines may go anywhere. A first line
 * whose first field is not a number is a header of column names and is skipped. */
#include "io_internal.h"

#include <math.h>

/* The error for field k of the current point (t: what stands there). When t ends the
 * line, say how many fields a line needs. */
static lh_status field_error(lh__scan *s, const lh__builder *b, const lh__token *t, int k,
                             size_t first_line)
{
    char what[140];
    double x;
    int d = b->p->d, end = t->kind == LH__TOK_EOL || t->kind == LH__TOK_EOF;
    size_t point = b->p->n + 1;
    if (end && d)
        snprintf(what, sizeof what, "coordinate %d of point %zu (%d per line, as on line %zu)",
                 k + 1, point, d, first_line);
    else if (end && k < LH_DELAUNAY_MIN_DIM)
        snprintf(what, sizeof what, "coordinate %d of point %zu (2 to 8 per line)", k + 1, point);
    else
        snprintf(what, sizeof what, "coordinate %d of point %zu", k + 1, point);
    lh_status st = lh__number(s, t, what, "points", NULL, &x);
    return end && !d && k < LH_DELAUNAY_MIN_DIM ? LH_ERR_DIMENSION : st;
}

/* Reads the fields of one line into x (*k of them), t holding the line's first token
 * on entry and the line's end on return. */
static lh_status read_fields(lh__scan *s, const lh__builder *b, lh__token *t, double *x,
                             int *k, size_t first_line)
{
    int d = b->p->d, max = d ? d : LH_DELAUNAY_MAX_DIM;
    for (*k = 0;;) {
        if (!lh__word_double(t, &x[*k]) || !isfinite(x[*k])) return field_error(s, b, t, *k, first_line);
        ++*k;
        lh__scan_next(s, 0, t);
        if (t->kind != LH__TOK_COMMA && (t->kind == LH__TOK_EOL || t->kind == LH__TOK_EOF))
            return LH_OK;
        if (*k == max) {
            char what[120];
            if (d) snprintf(what, sizeof what, "the end of the line after %d coordinates (as on line %zu)", d, first_line);
            else snprintf(what, sizeof what, "the end of the line after 8 coordinates (8 is the largest dimension)");
            return lh__expected(s, d ? LH_ERR_PARSE : LH_ERR_DIMENSION, t, what, NULL);
        }
        if (t->kind == LH__TOK_COMMA) lh__scan_next(s, 0, t);
    }
}

/* A first line that starts with a word that is not a number (or with a byte above
 * 0x7f, as a UTF-8 name) is a header. */
static int is_header(const lh__token *t)
{
    double x;
    return (t->kind == LH__TOK_WORD && !lh__word_double(t, &x)) ||
           (t->kind == LH__TOK_BYTE && t->byte >= 0x80);
}

lh_status lh__read_columns(lh__scan *s, lh__builder *b)
{
    lh__token t;
    double x[LH_DELAUNAY_MAX_DIM];
    size_t first_line = 0;
    int k;
    s->commas = 1;
    lh__scan_next(s, 1, &t);
    if (is_header(&t)) {
        lh__scan_skip_line(s);
        lh__scan_next(s, 1, &t);
    }
    while (t.kind != LH__TOK_EOF) {
        size_t line = t.line;
        lh_status st = read_fields(s, b, &t, x, &k, first_line);
        if (st == LH_OK && k < (b->p->d ? b->p->d : LH_DELAUNAY_MIN_DIM))
            st = field_error(s, b, &t, k, first_line);
        if (st != LH_OK) return st;
        if (!b->p->d) {
            b->p->d = k;
            first_line = line;
        }
        st = lh__push(s, b, &t, x, NULL, 0);
        if (st != LH_OK) return st;
        lh__scan_next(s, 1, &t);
    }
    if (b->p->n) return LH_OK;
    return lh__expected(s, LH_ERR_PARSE, &t, "a line of coordinates", NULL);
}
