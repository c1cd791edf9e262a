/*
 * io_rings.c — lh_rings_read: one polygon as JSON rings, the format of earcut's test
 * fixtures (mapbox/earcut, test/fixtures/<name>.json; GeoJSON's Polygon coordinates, RFC
 * 7946, 3.1.6, without its closing point):
 *
 *     [ [[x,y], [x,y], ...],     the outer ring
 *       [[x,y], ...], ... ]      then the holes' rings
 *
 * Numbers are JSON's (RFC 8259, 6: an optional '-', digits without a leading 0, an
 * optional fraction and exponent), whitespace may go between any two tokens. A ring's
 * last point equal to its first is dropped (a closed ring); the ring's k points become
 * k vertices and, for k >= 2, the cycle of k segments (a ring of one point, earcut's
 * Steiner point, is a vertex alone). Degenerate rings are kept as they are: the
 * triangulator reports what it cannot use, by the lines kept here.
 */
#include "io_pslg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int space(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

static int word_byte(int c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
           c == '+' || c == '-' || c == '.';
}

/* The next token: a number-like word, or one other text byte ('[', ']', ',', ...) as a
 * word of its own, or what the scanner reports (end, NUL, non-text byte, read error). */
static void next(lh__scan *s, lh__token *t)
{
    while (space(s->c)) lh__scan_advance(s);
    t->line = s->line;
    t->col = s->col;
    t->len = 0;
    t->text[0] = 0;
    t->byte = s->c;
    if (s->c == EOF) {
        t->kind = s->read_error ? LH__TOK_READ_ERROR : LH__TOK_EOF;
    } else if (s->c == 0) {
        t->kind = LH__TOK_NUL;
    } else if (!lh__is_text(s->c)) {
        t->kind = LH__TOK_BYTE;
    } else if (!word_byte(s->c)) {
        t->kind = LH__TOK_WORD;
        t->text[t->len++] = (char)s->c;
        t->text[t->len] = 0;
        lh__scan_advance(s);
    } else {
        t->kind = LH__TOK_WORD;
        while (word_byte(s->c)) {
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

static int is(const lh__token *t, char c) { return t->kind == LH__TOK_WORD && t->len == 1 && t->text[0] == c; }

static const char *digits(const char *p)
{
    while (*p >= '0' && *p <= '9') p++;
    return p;
}

/* Whether the word is a JSON number. */
static int json_number(const char *p)
{
    if (*p == '-') p++;
    if (*p == '0') p++;
    else if (*p >= '1' && *p <= '9') p = digits(p);
    else return 0;
    if (*p == '.') {
        if (p[1] < '0' || p[1] > '9') return 0;
        p = digits(p + 1);
    }
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (*p < '0' || *p > '9') return 0;
        p = digits(p);
    }
    return *p == 0;
}

typedef struct rings_ctx {
    lh__scan *s;
    lh_pslg *g;
    size_t vcap, scap;
} rings_ctx;

/* Coordinate j (1 or 2) of point k of ring r. NaN and infinities, which JSON cannot
 * write but some writers do ("NaN", "Infinity"), are named as such. */
static lh_status coordinate(rings_ctx *x, int j, size_t k, size_t r, double *v)
{
    lh__token t;
    char what[120];
    next(x->s, &t);
    snprintf(what, sizeof what, "coordinate %d of point %zu of ring %zu", j, k, r);
    if (t.kind == LH__TOK_WORD && json_number(t.text)) {
        *v = strtod(t.text, NULL);
        return isfinite(*v) ? LH_OK : lh__nonfinite(x->s, &t, what, "points");
    }
    if (lh__word_double(&t, v) && !isfinite(*v)) return lh__nonfinite(x->s, &t, what, "points");
    if (t.kind == LH__TOK_WORD) strcat(what, " (a number)");
    return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
}

/* Expects the one-byte token c, named `what`. */
static lh_status punct(rings_ctx *x, char c, const char *what)
{
    lh__token t;
    next(x->s, &t);
    return is(&t, c) ? LH_OK : lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
}

/* Point k of ring r, after its '[' (token at). */
static lh_status read_point(rings_ctx *x, const lh__token *at, size_t k, size_t r)
{
    lh_pslg *g = x->g;
    double xy[2];
    char what[120];
    lh_status st = coordinate(x, 1, k, r, &xy[0]);
    snprintf(what, sizeof what, "',' after coordinate 1 of point %zu of ring %zu", k, r);
    if (st == LH_OK) st = punct(x, ',', what);
    if (st == LH_OK) st = coordinate(x, 2, k, r, &xy[1]);
    snprintf(what, sizeof what, "']' after coordinate 2 of point %zu of ring %zu (a point is [x, y])", k, r);
    if (st == LH_OK) st = punct(x, ']', what);
    if (st != LH_OK) return st;
    if (g->n == (size_t)LH_READ_MAX_POINTS) {
        snprintf(what, sizeof what, "the end of the input after %lld points (the most lifthull reads)",
                 (long long)LH_READ_MAX_POINTS);
        return lh__expected(x->s, LH_ERR_TOO_LARGE, at, what, NULL);
    }
    const lh__pslg_col cols[] = {{(void **)&g->xy, 2 * sizeof *g->xy}, {(void **)&g->vertex_line, sizeof *g->vertex_line}};
    snprintf(what, sizeof what, "point %zu of ring", k);
    st = lh__pslg_room(x->s, &g->alloc_, cols, 2, g->n, 0, &x->vcap, at, what, (long long)r);
    if (st != LH_OK) return st;
    memcpy(g->xy + 2 * g->n, xy, sizeof xy);
    g->vertex_line[g->n++] = at->line;
    return LH_OK;
}

/* The cycle of segments of the ring of vertices first..g->n-1, after its closing point
 * (equal to its first) is dropped. */
static lh_status close_ring(rings_ctx *x, size_t first, const lh__token *at, size_t r)
{
    lh_pslg *g = x->g;
    size_t k = g->n - first;
    if (k >= 2 && g->xy[2 * first] == g->xy[2 * (g->n - 1)] &&
        g->xy[2 * first + 1] == g->xy[2 * (g->n - 1) + 1]) {
        g->n--;
        k--;
    }
    if (k < 2) return LH_OK;
    const lh__pslg_col cols[] = {{(void **)&g->segments, 2 * sizeof *g->segments},
                                 {(void **)&g->segment_line, sizeof *g->segment_line}};
    for (size_t i = 0; i < k; i++) {
        lh_status st = lh__pslg_room(x->s, &g->alloc_, cols, 2, g->segment_count, 0, &x->scap, at,
                                     "the segments of ring", (long long)r);
        if (st != LH_OK) return st;
        size_t a = first + i, b = first + (i + 1) % k;
        g->segments[2 * g->segment_count] = (lh_index)a;
        g->segments[2 * g->segment_count + 1] = (lh_index)b;
        g->segment_line[g->segment_count++] = g->vertex_line[a];
    }
    return LH_OK;
}

/* Ring r, after its '[' (token at). */
static lh_status read_ring(rings_ctx *x, const lh__token *at, size_t r)
{
    lh__token t;
    char what[120];
    size_t first = x->g->n;
    for (size_t k = 1;; k++) {
        next(x->s, &t);
        if (!is(&t, '[')) {
            snprintf(what, sizeof what, "'[' (point %zu of ring %zu)", k, r);
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        }
        lh_status st = read_point(x, &t, k, r);
        if (st != LH_OK) return st;
        next(x->s, &t);
        if (is(&t, ']')) break;
        if (!is(&t, ',')) {
            snprintf(what, sizeof what, "',' or ']' after point %zu of ring %zu", k, r);
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        }
    }
    return close_ring(x, first, at, r);
}

static lh_status read_rings(rings_ctx *x)
{
    lh__token t;
    char what[120];
    lh_status st = punct(x, '[', "'[' (a polygon: a list of rings)");
    size_t r = 1;
    for (; st == LH_OK; r++) {
        next(x->s, &t);
        if (!is(&t, '[')) {
            snprintf(what, sizeof what, "'[' (ring %zu: a list of points)", r);
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        }
        st = read_ring(x, &t, r);
        if (st != LH_OK) return st;
        next(x->s, &t);
        if (is(&t, ']')) break;
        if (!is(&t, ',')) {
            snprintf(what, sizeof what, "',' or ']' after ring %zu", r);
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        }
    }
    if (st != LH_OK) return st;
    next(x->s, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    snprintf(what, sizeof what, "the end of the input after the polygon (%zu ring%s)", r, r == 1 ? "" : "s");
    return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
}

static lh_status read_rings_file(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                                 lh_error *err)
{
    lh_status st = lh__pslg_start(f, alloc, out);
    if (st != LH_OK) return st;
    lh__scan *s = lh__pslg_scan_open(f, out, name, err);
    if (!s) return LH_ERR_NOMEM;
    rings_ctx x = {s, out, 0, 0};
    st = read_rings(&x);
    lh__scan_close(s);
    if (st != LH_OK) {
        lh_pslg_free(out);
        return st;
    }
    out->even_odd = 1;
    return LH_OK;
}

lh_status lh_rings_read(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                        lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, read_rings_file(f, name, alloc, out, err));
}
