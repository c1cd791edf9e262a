/* io_node.c — Triangle's and TetGen's .node files (Shewchuk, Triangle's documentation,
 * ".node files"; Si, TetGen 1.5 manual, section 5.2.1):
 *
 *     n d [attributes [markers]]                   attributes >= 0, markers 0 or 1
 *     number x_1 .. x_d [attribute ...] [marker]   one line per point
 *
 * Blank lines and '#' comments may go anywhere; the points are numbered consecutively
 * from 0 or 1. Triangle reads d = 2 and TetGen d = 3; lifthull 2..8. As Triangle does,
 * omitted header fields are 0; unlike it, every field of a point line must be there. */
#include "io_internal.h"

#include <math.h>
#include <stdint.h>

#define MAX_ATTRIBUTES LH__READ_MAX_ATTR

static lh_status read_header(lh__scan *s, lh__builder *b, size_t *n)
{
    lh__token t;
    int ended = 0, markers = 0;
    lh__scan_next(s, 1, &t);
    lh_status st = lh__count(s, &t, "the number of points", n);
    if (st != LH_OK) return st;
    lh__scan_next(s, 0, &t);
    st = lh__dimension(s, &t, &b->p->d);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of attributes (an integer from 0 to 1000)",
                          MAX_ATTRIBUTES, &b->p->attr_count, &ended);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of boundary markers (0 or 1)", 1, &markers, &ended);
    if (st != LH_OK || ended) return st;
    b->markers = markers;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    return lh__expected(s, LH_ERR_PARSE, &t,
                        "the end of the header line (points, dimension, attributes, markers)",
                        NULL);
}

/* The point's number: the first is 0 or 1 (and sets first_index), then consecutive. */
static lh_status point_number(lh__scan *s, lh__builder *b, size_t i, size_t n)
{
    lh__token t;
    long long v, want = b->p->first_index + (long long)i;
    lh__scan_next(s, 1, &t);
    if (lh__word_integer(&t, &v) && (i ? v == want : v == 0 || v == 1)) {
        if (i == 0) b->p->first_index = (int)v;
        return LH_OK;
    }
    char what[80], tail[64];
    if (i == 0) snprintf(what, sizeof what, "the first point's number (0 or 1)");
    else if (t.kind == LH__TOK_WORD) snprintf(what, sizeof what, "point number %lld (numbers are consecutive)", want);
    else snprintf(what, sizeof what, "point number %lld", want);
    snprintf(tail, sizeof tail, " (%zu point%s declared)", n, n == 1 ? "" : "s");
    return lh__expected(s, LH_ERR_PARSE, &t, what, t.kind == LH__TOK_EOF ? tail : NULL);
}

/* `count` numbers of the current line into x: coordinates or attributes. */
static lh_status numbers(lh__scan *s, int count, const char *field, const char *noun,
                         long long number, double *x)
{
    lh__token t;
    for (int j = 0; j < count; j++) {
        lh__scan_next(s, 0, &t);
        if (lh__word_double(&t, &x[j]) && isfinite(x[j])) continue;
        char what[100];
        snprintf(what, sizeof what, "%s %d of point %lld", field, j + 1, number);
        return lh__number(s, &t, what, noun, NULL, &x[j]);
    }
    return LH_OK;
}

static lh_status marker_and_end(lh__scan *s, lh__builder *b, long long number, lh_index *marker)
{
    lh__token t;
    char what[100];
    long long v;
    if (b->markers) {
        lh__scan_next(s, 0, &t);
        if (!lh__word_integer(&t, &v) || v < -LH_INDEX_MAX - 1 || v > LH_INDEX_MAX) {
            snprintf(what, sizeof what, "the boundary marker of point %lld (an integer)", number);
            return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
        }
        *marker = (lh_index)v;
    }
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    snprintf(what, sizeof what, "the end of the line after point %lld", number);
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

static lh_status read_point(lh__scan *s, lh__builder *b, size_t i, size_t n, double *attr)
{
    double x[LH_DELAUNAY_MAX_DIM];
    lh_index marker = 0;
    lh__token at;
    lh_status st = point_number(s, b, i, n);
    long long number = b->p->first_index + (long long)i;
    at.line = s->line;
    at.col = s->col;
    if (st == LH_OK) st = numbers(s, b->p->d, "coordinate", "points", number, x);
    if (st == LH_OK) st = numbers(s, b->p->attr_count, "attribute", "accepted", number, attr);
    if (st == LH_OK) st = marker_and_end(s, b, number, &marker);
    return st == LH_OK ? lh__push(s, b, &at, x, attr, marker) : st;
}

lh_status lh__read_node(lh__scan *s, lh__builder *b)
{
    size_t n;
    lh_status st = read_header(s, b, &n);
    if (st != LH_OK) return st;
    b->expected = n;
    for (size_t i = 0; i < n; i++) {
        st = read_point(s, b, i, n, s->attr);
        if (st != LH_OK) return st;
    }
    lh__token t;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    char what[80];
    snprintf(what, sizeof what, "the end of the input after %zu point%s", n, n == 1 ? "" : "s");
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}
