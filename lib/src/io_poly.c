/*
 * io_poly.c — lh_poly_read: Triangle's .poly files (Shewchuk, Triangle's documentation,
 * ".poly files", https://www.cs.cmu.edu/~quake/triangle.poly.html), and what every
 * lh_pslg reader shares (io_pslg.h), lh_pslg_take_points and lh_pslg_free:
 *
 *     n 2 [attributes [markers]]             n = 0: the vertices are in the .node file
 *     number x y [attribute ...] [marker]    n vertex lines
 *     segments [markers]
 *     number a b [marker]                    endpoints: vertex numbers
 *     holes
 *     number x y                             a point inside each hole
 *     regions                                this section is optional
 *     number x y attribute [max_area]        no max_area: the attribute's value
 *
 * As in .node files (io_node.c): blank lines and '#' comments anywhere, omitted header
 * fields are Triangle's defaults (dimension 2, no attributes, no markers), every field
 * of an item line must be there; region lines are Triangle's too (a fourth number
 * missing is the third's, as triangle.c's readholes reads it: la.poly's regions).
 * The items are numbered consecutively from the file's first number, 0 or 1, in every
 * section; the endpoints too (with n = 0, until lh_pslg_take_points renumbers them
 * from the .node's first number, as Triangle reads them). The line of every item is kept
 * for the triangulator's diagnostics; what the graph means (duplicate vertices,
 * crossing segments) is not looked at here.
 */
#include "io_pslg.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#define MAX_ATTRIBUTES LH__READ_MAX_ATTR

/* ---- shared by the PSLG readers ---------------------------------------------------- */

void lh_pslg_free(lh_pslg *g)
{
    if (!g) return;
    if (g->alloc_.free) {
        void *arrays[] = {g->xy,           g->attr,        g->vertex_marker, g->segments,
                          g->segment_marker, g->holes,      g->regions,       g->vertex_line,
                          g->segment_line,  g->hole_line,   g->region_line};
        for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
            lh__free(&g->alloc_, arrays[i]);
    }
    memset(g, 0, sizeof *g);
}

lh_status lh__pslg_start(FILE *f, const lh_allocator *alloc, lh_pslg *out)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (!f || !lh__allocator_init(&out->alloc_, alloc)) {
        memset(out, 0, sizeof *out);
        return LH_ERR_INVALID_ARGUMENT;
    }
    return LH_OK;
}

lh__scan *lh__pslg_scan_open(FILE *f, lh_pslg *out, const char *name, lh_error *err)
{
    lh__scan *s = lh__scan_open(f, LH__PSLG_PRE, &out->alloc_, name ? name : "<input>", err);
    if (!s) lh_pslg_free(out);
    return s;
}

lh_status lh__pslg_room(lh__scan *s, const lh_allocator *a, const lh__pslg_col *cols,
                        int ncols, size_t count, size_t declared, size_t *cap,
                        const lh__token *at, const char *noun, long long number)
{
    if (count < *cap) return LH_OK;
    size_t want = *cap ? 2 * *cap : 64;
    if (declared && want > declared) want = declared;
    if (want <= count) want = count + 1;
    lh_status st = LH_OK;
    void *fresh[8] = {0};
    for (int k = 0; k < ncols && st == LH_OK; k++) {
        if (!cols[k].bytes) continue;
        if (want > SIZE_MAX / cols[k].bytes) st = LH_ERR_TOO_LARGE;
        else if (!(fresh[k] = lh__alloc(a, want * cols[k].bytes))) st = LH_ERR_NOMEM;
        else if (count) memcpy(fresh[k], *cols[k].arr, count * cols[k].bytes);
    }
    for (int k = 0; k < ncols; k++) {
        if (!cols[k].bytes) continue;
        lh__free(a, st == LH_OK ? *cols[k].arr : fresh[k]);
        if (st == LH_OK) *cols[k].arr = fresh[k];
    }
    if (st == LH_OK) {
        *cap = want;
        return LH_OK;
    }
    char text[160];
    snprintf(text, sizeof text, "%s for %s %lld",
             st == LH_ERR_NOMEM ? "out of memory" : "out of address space", noun, number);
    return lh__fail_at(s, st, at, text);
}

lh_status lh_pslg_take_points(lh_pslg *g, lh_points *p)
{
    if (!g || !p || p->d != 2 || p->n == 0 || !p->xyz || g->n || g->xy || g->attr ||
        g->vertex_marker || g->vertex_line || g->alloc_.alloc != p->alloc_.alloc ||
        g->alloc_.free != p->alloc_.free || g->alloc_.user != p->alloc_.user)
        return LH_ERR_INVALID_ARGUMENT;
    /* The endpoints were read against g's base; Triangle numbers them as the .node. */
    lh_index shift = (lh_index)(g->first_index - p->first_index);
    for (size_t i = 0; shift && i < 2 * g->segment_count; i++) g->segments[i] += shift;
    g->first_index = p->first_index;
    g->item_first_shift = (int)shift; /* the .poly's items keep their own numbers */
    g->n = p->n;
    g->xy = p->xyz;
    g->attr_count = p->attr_count;
    g->attr = p->attr;
    g->vertex_marker = p->marker;
    memset(p, 0, sizeof *p);
    return LH_OK;
}

/* ---- .poly ----------------------------------------------------------------------- */

/* One section of the file: its items' names, declared count, arrays' capacity. */
typedef struct section {
    const char *one, *many;
    size_t declared, cap;
} section;

typedef struct poly_ctx {
    lh__scan *s;
    lh_pslg *g;
    section v, seg, hole, reg;
    int vertex_markers, segment_markers;
    int based; /* g->first_index is the file's first number */
} poly_ctx;

/* A section's count (0..LH_READ_MAX_POINTS); or_end: the end of the input may come
 * instead (the optional regions). */
static lh_status read_count(lh__scan *s, const lh__token *t, const char *what, int or_end,
                            size_t *n)
{
    char w[200], shortw[160];
    long long v;
    const char *end = or_end ? " or the end of the input" : "";
    snprintf(w, sizeof w, "%s (an integer from 0 to %lld)%s", what, (long long)LH_READ_MAX_POINTS, end);
    snprintf(shortw, sizeof shortw, "%s%s", what, end);
    if (!lh__word_integer(t, &v) || v < 0)
        return lh__expected(s, LH_ERR_PARSE, t, t->kind == LH__TOK_WORD ? w : shortw, NULL);
    if (v > LH_READ_MAX_POINTS) return lh__expected(s, LH_ERR_TOO_LARGE, t, w, NULL);
    *n = (size_t)v;
    return LH_OK;
}

static lh_status line_end(lh__scan *s, int ended, const char *what)
{
    lh__token t;
    if (ended) return LH_OK;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

/* "n 2 [attributes [markers]]". */
static lh_status read_header(lh__scan *s, lh_pslg *g, size_t *n, int *markers)
{
    const char *dim = "the dimension (2: a .poly file is planar)";
    lh__token t;
    long long d;
    int ended = 0, attrs = 0;
    lh__scan_next(s, 1, &t);
    lh_status st = read_count(s, &t, "the number of vertices", 0, n);
    if (st != LH_OK) return st;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    if (!lh__word_integer(&t, &d)) return lh__expected(s, LH_ERR_PARSE, &t, dim, NULL);
    if (d != 2) return lh__expected(s, LH_ERR_DIMENSION, &t, dim, NULL);
    st = lh__header_field(s, "the number of attributes (an integer from 0 to 1000)", MAX_ATTRIBUTES,
                      &attrs, &ended);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of boundary markers (0 or 1)", 1, markers, &ended);
    if (st == LH_OK)
        st = line_end(s, ended, "the end of the header line (vertices, dimension, attributes, markers)");
    if (*n == 0) *markers = 0; /* the .node's, which lh_pslg_take_points brings */
    else g->attr_count = attrs;
    return st;
}

/* The number of item i of a section (read into *t): the file's first number is 0 or 1
 * (g->first_index), every section counts from it. */
static lh_status item_number(poly_ctx *x, const section *sec, size_t i, lh__token *t)
{
    long long v, want = x->g->first_index + (long long)i;
    lh__scan_next(x->s, 1, t);
    if (lh__word_integer(t, &v) && (x->based ? v == want : v == 0 || v == 1)) {
        if (!x->based) x->g->first_index = (int)v;
        x->based = 1;
        return LH_OK;
    }
    char what[120], tail[80];
    if (!x->based) snprintf(what, sizeof what, "the first %s's number (0 or 1)", sec->one);
    else if (t->kind != LH__TOK_WORD) snprintf(what, sizeof what, "%s number %lld", sec->one, want);
    else if (i) snprintf(what, sizeof what, "%s number %lld (numbers are consecutive)", sec->one, want);
    else snprintf(what, sizeof what, "%s number %lld (this file numbers from %lld)", sec->one, want, want);
    snprintf(tail, sizeof tail, " (%zu %s declared)", sec->declared, sec->declared == 1 ? sec->one : sec->many);
    return lh__expected(x->s, LH_ERR_PARSE, t, what, t->kind == LH__TOK_EOF ? tail : NULL);
}

/* `count` numbers of the current line into x, named "FIELD j of ITEM NUMBER". */
static lh_status numbers(lh__scan *s, int count, const char *field, const char *noun,
                         const section *sec, long long number, double *x)
{
    lh__token t;
    for (int j = 0; j < count; j++) {
        lh__scan_next(s, 0, &t);
        if (lh__word_double(&t, &x[j]) && isfinite(x[j])) continue;
        char what[100];
        snprintf(what, sizeof what, "%s %d of %s %lld", field, j + 1, sec->one, number);
        return lh__number(s, &t, what, noun, NULL, &x[j]);
    }
    return LH_OK;
}

static lh_status marker(lh__scan *s, const section *sec, long long number, lh_index *m)
{
    lh__token t;
    long long v;
    lh__scan_next(s, 0, &t);
    if (lh__word_integer(&t, &v) && v >= -LH_INDEX_MAX - 1 && v <= LH_INDEX_MAX) { /* an lh_index */
        *m = (lh_index)v;
        return LH_OK;
    }
    char what[100];
    snprintf(what, sizeof what, "the boundary marker of %s %lld (an integer)", sec->one, number);
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

static lh_status item_end(lh__scan *s, const section *sec, long long number)
{
    char what[100];
    snprintf(what, sizeof what, "the end of the line after %s %lld", sec->one, number);
    return line_end(s, 0, what);
}

static lh_status read_vertex(poly_ctx *x, size_t i, double *attr)
{
    lh_pslg *g = x->g;
    lh__token at;
    double xy[2];
    lh_index m = 0;
    lh_status st = item_number(x, &x->v, i, &at);
    long long number = g->first_index + (long long)i;
    if (st == LH_OK) st = numbers(x->s, 2, "coordinate", "points", &x->v, number, xy);
    if (st == LH_OK) st = numbers(x->s, g->attr_count, "attribute", "accepted", &x->v, number, attr);
    if (st == LH_OK && x->vertex_markers) st = marker(x->s, &x->v, number, &m);
    if (st == LH_OK) st = item_end(x->s, &x->v, number);
    if (st != LH_OK) return st;
    const lh__pslg_col cols[] = {{(void **)&g->xy, 2 * sizeof *g->xy},
                                 {(void **)&g->attr, (size_t)g->attr_count * sizeof *g->attr},
                                 {(void **)&g->vertex_marker, x->vertex_markers ? sizeof(lh_index) : 0},
                                 {(void **)&g->vertex_line, sizeof *g->vertex_line}};
    st = lh__pslg_room(x->s, &g->alloc_, cols, 4, g->n, x->v.declared, &x->v.cap, &at, "vertex", number);
    if (st != LH_OK) return st;
    memcpy(g->xy + 2 * g->n, xy, sizeof xy);
    if (g->attr_count) memcpy(g->attr + g->n * (size_t)g->attr_count, attr, (size_t)g->attr_count * sizeof *attr);
    if (x->vertex_markers) g->vertex_marker[g->n] = m;
    g->vertex_line[g->n++] = at.line;
    return LH_OK;
}

/* An endpoint of segment `number`: a vertex number from the base to the last one's,
 * stored 0-based. With n = 0 the .node's base is not known yet: any number from 0,
 * stored less the file's base (-1 for 0 in a 1-based file, until
 * lh_pslg_take_points renumbers it). */
static lh_status endpoint(poly_ctx *x, long long number, lh_index *e)
{
    lh__token t;
    long long k, lo = x->g->first_index, hi = lo + (long long)x->g->n - 1;
    lh__scan_next(x->s, 0, &t);
    if (lh__word_integer(&t, &k) && (x->g->n ? k >= lo && k <= hi : k >= 0 && k - lo < LH_INDEX_MAX)) {
        *e = (lh_index)(k - lo);
        return LH_OK;
    }
    char what[120];
    if (x->g->n) snprintf(what, sizeof what, "an endpoint of segment %lld (a vertex number from %lld to %lld)", number, lo, hi);
    else snprintf(what, sizeof what, "an endpoint of segment %lld (a vertex number of the .node, from 0)", number);
    return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
}

static lh_status read_segment(poly_ctx *x, size_t i)
{
    lh_pslg *g = x->g;
    lh__token at;
    lh_index e[2], m = 0;
    lh_status st = item_number(x, &x->seg, i, &at);
    long long number = g->first_index + (long long)i;
    if (st == LH_OK) st = endpoint(x, number, &e[0]);
    if (st == LH_OK) st = endpoint(x, number, &e[1]);
    if (st == LH_OK && x->segment_markers) st = marker(x->s, &x->seg, number, &m);
    if (st == LH_OK) st = item_end(x->s, &x->seg, number);
    if (st != LH_OK) return st;
    const lh__pslg_col cols[] = {{(void **)&g->segments, 2 * sizeof *g->segments},
                                 {(void **)&g->segment_marker, x->segment_markers ? sizeof(lh_index) : 0},
                                 {(void **)&g->segment_line, sizeof *g->segment_line}};
    st = lh__pslg_room(x->s, &g->alloc_, cols, 3, g->segment_count, x->seg.declared, &x->seg.cap, &at,
                       "segment", number);
    if (st != LH_OK) return st;
    memcpy(g->segments + 2 * g->segment_count, e, sizeof e);
    if (x->segment_markers) g->segment_marker[g->segment_count] = m;
    g->segment_line[g->segment_count++] = at.line;
    return LH_OK;
}

/* A hole "number x y" or a region "number x y attribute [max_area]" into the table
 * (*arr, *line, *count) of `per` numbers an item. */
static lh_status read_point_item(poly_ctx *x, section *sec, size_t i, int per, double **arr,
                                 size_t **line, size_t *count)
{
    lh__token at, t;
    double v[4];
    lh_status st = item_number(x, sec, i, &at);
    long long number = x->g->first_index + (long long)i;
    if (st == LH_OK) st = numbers(x->s, 2, "coordinate", "points", sec, number, v);
    if (st == LH_OK && per == 4) {
        char what[100];
        lh__scan_next(x->s, 0, &t);
        snprintf(what, sizeof what, "the attribute of region %lld", number);
        st = lh__number(x->s, &t, what, "accepted", NULL, &v[2]);
        v[3] = v[2];
        if (st == LH_OK) lh__scan_next(x->s, 0, &t);
        if (st == LH_OK && t.kind != LH__TOK_EOL && t.kind != LH__TOK_EOF) {
            snprintf(what, sizeof what, "the maximum area of region %lld", number);
            st = lh__number(x->s, &t, what, "accepted", NULL, &v[3]);
            if (st == LH_OK) st = item_end(x->s, sec, number);
        }
    } else if (st == LH_OK) {
        st = item_end(x->s, sec, number);
    }
    if (st != LH_OK) return st;
    const lh__pslg_col cols[] = {{(void **)arr, (size_t)per * sizeof **arr}, {(void **)line, sizeof **line}};
    st = lh__pslg_room(x->s, &x->g->alloc_, cols, 2, *count, sec->declared, &sec->cap, &at, sec->one, number);
    if (st != LH_OK) return st;
    memcpy(*arr + (size_t)per * *count, v, (size_t)per * sizeof *v);
    (*line)[(*count)++] = at.line;
    return LH_OK;
}

static lh_status read_poly(poly_ctx *x)
{
    lh__scan *s = x->s;
    lh_pslg *g = x->g;
    lh__token t;
    int ended = 0;
    lh_status st = read_header(s, g, &x->v.declared, &x->vertex_markers);
    for (size_t i = 0; st == LH_OK && i < x->v.declared; i++) st = read_vertex(x, i, s->attr);
    if (st != LH_OK) return st;
    lh__scan_next(s, 1, &t);
    st = read_count(s, &t, "the number of segments", 0, &x->seg.declared);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of segment boundary markers (0 or 1)", 1, &x->segment_markers, &ended);
    if (st == LH_OK) st = line_end(s, ended, "the end of the line after the number of segments and markers");
    for (size_t i = 0; st == LH_OK && i < x->seg.declared; i++) st = read_segment(x, i);
    if (st != LH_OK) return st;
    lh__scan_next(s, 1, &t);
    st = read_count(s, &t, "the number of holes", 0, &x->hole.declared);
    if (st == LH_OK) st = line_end(s, 0, "the end of the line after the number of holes");
    for (size_t i = 0; st == LH_OK && i < x->hole.declared; i++)
        st = read_point_item(x, &x->hole, i, 2, &g->holes, &g->hole_line, &g->hole_count);
    if (st != LH_OK) return st;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK; /* no regions */
    st = read_count(s, &t, "the number of regions", 1, &x->reg.declared);
    if (st == LH_OK) st = line_end(s, 0, "the end of the line after the number of regions");
    for (size_t i = 0; st == LH_OK && i < x->reg.declared; i++)
        st = read_point_item(x, &x->reg, i, 4, &g->regions, &g->region_line, &g->region_count);
    if (st != LH_OK) return st;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    char what[80];
    snprintf(what, sizeof what, "the end of the input after %zu region%s", x->reg.declared,
             x->reg.declared == 1 ? "" : "s");
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

static lh_status read_poly_file(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                                lh_error *err)
{
    lh_status st = lh__pslg_start(f, alloc, out);
    if (st != LH_OK) return st;
    lh__scan *s = lh__pslg_scan_open(f, out, name, err);
    if (!s) return LH_ERR_NOMEM;
    poly_ctx x = {s, out, {"vertex", "vertices", 0, 0}, {"segment", "segments", 0, 0},
                  {"hole", "holes", 0, 0}, {"region", "regions", 0, 0}, 0, 0, 0};
    st = read_poly(&x);
    lh__scan_close(s);
    if (st != LH_OK) {
        lh_pslg_free(out);
        return st;
    }
    return LH_OK;
}

lh_status lh_poly_read(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                       lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, read_poly_file(f, name, alloc, out, err));
}
