/* io_qhull.c — Qhull's point format, as qhull(1) and rbox(1) describe it ("Input
 * format": the dimension, the number of points, then the coordinates; "a comment
 * starts with a non-numeric character and continues to the end of line"):
 *
 *     [title lines]  d [n] [comment]  [n [comment]]  x_1 x_2 ... x_{n*d}
 *
 * Where lifthull differs, for clearer messages: the dimension comes first (Qhull also
 * takes "n d" when n > d), comments inside the coordinates start with '#' only, and
 * a title is only allowed before the dimension. */
#include "io_internal.h"

#include <math.h>

/* Lines before the dimension whose first non-blank byte is text that cannot start a
 * number are a title (Qhull lists the first comment in its summary). */
static void skip_titles(lh__scan *s)
{
    for (;;) {
        lh__scan_skip(s, 1);
        if (s->c == EOF || lh__starts_number(s->c) || !lh__is_text(s->c)) return;
        lh__scan_skip_line(s);
    }
}

/* After the dimension or the count: a word that cannot start a number makes the rest
 * of the line a comment (rbox writes "3 rbox 10 D3"). */
static void header_comment(lh__scan *s)
{
    lh__scan_skip(s, 0);
    if (s->c != EOF && s->c != '\n' && lh__is_text(s->c) && !lh__starts_number(s->c))
        lh__scan_skip_line(s);
}

static lh_status read_header(lh__scan *s, int *d, size_t *n)
{
    lh__token t;
    skip_titles(s);
    lh__scan_next(s, 1, &t);
    lh_status st = lh__dimension(s, &t, d);
    if (st != LH_OK) return st;
    header_comment(s);
    lh__scan_next(s, 1, &t);
    st = lh__count(s, &t, "the number of points", n);
    if (st != LH_OK) return st;
    header_comment(s);
    return LH_OK;
}

static lh_status read_point(lh__scan *s, lh__builder *b, size_t i, size_t n)
{
    double x[LH_DELAUNAY_MAX_DIM];
    lh__token t;
    for (int j = 0; j < b->p->d; j++) {
        lh__scan_next(s, 1, &t);
        if (lh__word_double(&t, &x[j]) && isfinite(x[j])) continue;
        char what[80], tail[64];
        snprintf(what, sizeof what, "coordinate %d of point %zu", j + 1, i + 1);
        snprintf(tail, sizeof tail, " (%zu point%s declared)", n, n == 1 ? "" : "s");
        return lh__number(s, &t, what, "points", tail, &x[j]);
    }
    return lh__push(s, b, &t, x, NULL, 0);
}

lh_status lh__read_qhull(lh__scan *s, lh__builder *b)
{
    size_t n;
    lh_status st = read_header(s, &b->p->d, &n);
    b->expected = n;
    for (size_t i = 0; st == LH_OK && i < n; i++) st = read_point(s, b, i, n);
    if (st != LH_OK) return st;
    lh__token t;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    char what[120];
    snprintf(what, sizeof what, "the end of the input after %zu point%s of dimension %d", n,
             n == 1 ? "" : "s", b->p->d);
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}
