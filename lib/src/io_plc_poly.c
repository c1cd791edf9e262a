/*
 * io_plc_poly.c — lh_plc_read's TetGen readers: .poly, .smesh and .node (Si, TetGen
 * 1.5 manual, sections 5.2.1-5.2.3), as lifthull accepts them:
 *
 *     n [3 [attributes [markers]]]        part 1, the points; n = 0 (.poly, .smesh):
 *                                         the points are in the .node of the same name
 *     number x y z [attribute ...] [marker]    n lines, numbered from 0 or 1
 *     facets [markers]                    part 2 (not in a .node)
 *     .poly, each facet:
 *       polygons [holes [marker]]         polygons >= 1; a marker only with markers 1
 *       k v_1 .. v_k                      each polygon: k >= 1 vertex numbers
 *       number x y z                      each hole point of the facet
 *     .smesh, each facet:
 *       k v_1 .. v_k [marker]             one polygon of k >= 3 vertices
 *     holes                               part 3 (optional at the end of the input)
 *     number x y z                        a point in each hole of the volume
 *     regions                             part 4 (optional)
 *     number x y z attribute [max_volume] no max_volume: no bound (-1)
 *
 * Blank lines and '#' comments go anywhere; every item is on one line. Omitted
 * header fields are TetGen's defaults (dimension 3, no attributes, no markers); the
 * dimension must be 3. Points are numbered consecutively from the first one's
 * number, 0 or 1 (first_index), and vertex numbers range over them; with n = 0 they
 * are stored as read (first_index 0) until lh_plc_take_points renumbers them from the
 * .node's first number. The numbers of hole and region lines are integers that, as
 * in TetGen, nothing uses. A facet needs a polygon of 3 or more vertices (polygons of
 * 1 or 2, lone points and slits, may come with it); one without is an error naming
 * the facet's line. Markers are 0 where the file has none.
 */
#include "io_plc_text.h"

#include <string.h>

#define MAX_ATTRIBUTES LH__READ_MAX_ATTR

typedef struct poly_ctx {
    lh__scan *s;
    lh__plc_build *b;
    lh__plc_ring ring;
    const char *ext;   /* ".poly", ".smesh", ".node" (for the dimension's message) */
    int point_markers, facet_markers;
} poly_ctx;

static lh_status header_end(lh__scan *s, int ended, const char *what)
{
    if (ended) return LH_OK;
    lh__token t;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

/* "n [3 [attributes [markers]]]"; n >= lo. */
static lh_status read_point_header(poly_ctx *x, long long lo, size_t *n)
{
    lh__scan *s = x->s;
    lh__token t;
    long long d;
    int ended = 0, attrs = 0;
    char dim[80];
    lh__scan_next(s, 1, &t);
    lh_status st = lh__plc_count(s, &t, "the number of points", lo, n);
    if (st != LH_OK) return st;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    snprintf(dim, sizeof dim, "the dimension (3: a %s file is 3D)", x->ext);
    if (!lh__word_integer(&t, &d)) return lh__expected(s, LH_ERR_PARSE, &t, dim, NULL);
    if (d != 3) return lh__expected(s, LH_ERR_DIMENSION, &t, dim, NULL);
    st = lh__header_field(s, "the number of attributes (an integer from 0 to 1000)", MAX_ATTRIBUTES,
                          &attrs, &ended);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of boundary markers (0 or 1)", 1, &x->point_markers, &ended);
    if (st == LH_OK)
        st = header_end(s, ended, "the end of the header line (points, dimension, attributes, markers)");
    if (*n) x->b->g->attr_count = attrs;
    else x->point_markers = 0; /* the .node's, which lh_plc_take_points brings */
    return st;
}

/* Point i's number (into *t): the first is 0 or 1 and sets first_index, then consecutive. */
static lh_status point_number(poly_ctx *x, size_t i, size_t n, lh__token *t)
{
    lh_plc *g = x->b->g;
    long long v, want = g->first_index + (long long)i;
    lh__scan_next(x->s, 1, t);
    if (lh__word_integer(t, &v) && (i ? v == want : v == 0 || v == 1)) {
        if (i == 0) g->first_index = (int)v;
        return LH_OK;
    }
    char what[80], tail[64];
    if (i == 0) snprintf(what, sizeof what, "the first point's number (0 or 1)");
    else if (t->kind == LH__TOK_WORD) snprintf(what, sizeof what, "point number %lld (numbers are consecutive)", want);
    else snprintf(what, sizeof what, "point number %lld", want);
    snprintf(tail, sizeof tail, " (%zu point%s declared)", n, n == 1 ? "" : "s");
    return lh__expected(x->s, LH_ERR_PARSE, t, what, t->kind == LH__TOK_EOF ? tail : NULL);
}

static lh_status read_point(poly_ctx *x, size_t i, size_t n)
{
    lh_plc *g = x->b->g;
    lh__scan *s = x->s;
    lh__token at, t;
    double xyz[3];
    lh_index m = 0;
    char item[64];
    lh_status st = point_number(x, i, n, &at);
    snprintf(item, sizeof item, "point %lld", g->first_index + (long long)i);
    if (st == LH_OK) st = lh__plc_numbers(s, 1, 3, "coordinate", item, "points", xyz);
    if (st == LH_OK) st = lh__plc_numbers(s, 1, g->attr_count, "attribute", item, "accepted", s->attr);
    if (st == LH_OK && x->point_markers) {
        char what[100];
        snprintf(what, sizeof what, "the boundary marker of %s", item);
        lh__scan_next(s, 0, &t);
        st = lh__plc_integer(s, &t, what, &m);
    }
    if (st == LH_OK) st = lh__plc_line_end(s, item);
    if (st != LH_OK) return st;
    return lh__plc_built(s, lh__plc_point(x->b, xyz, s->attr, m, at.line), &at, item);
}

static lh_status read_points(poly_ctx *x, long long lo)
{
    size_t n;
    lh_status st = read_point_header(x, lo, &n);
    for (size_t i = 0; st == LH_OK && i < n; i++) st = read_point(x, i, n);
    return st;
}

/* k vertex numbers of the current line into x->ring, named "vertex j of ITEM". */
static lh_status read_vertices(poly_ctx *x, size_t k, const char *item)
{
    lh_plc *g = x->b->g;
    lh__token t;
    x->ring.k = 0;
    for (size_t j = 0; j < k; j++) {
        lh_index v;
        lh__scan_next(x->s, 0, &t);
        lh_status st = lh__plc_vertex(x->s, &t, g->first_index, g->n, j + 1, item, &v);
        if (st == LH_OK) st = lh__plc_built(x->s, lh__plc_ring_push(x->b, &x->ring, v), &t, item);
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

/* The rest of a facet's line: its marker when the facets have markers (missing: 0,
 * as TetGen reads it), then the line's end. */
static lh_status facet_tail(poly_ctx *x, const char *item, lh_index *m)
{
    lh__token t;
    char what[100];
    *m = 0;
    if (!x->facet_markers) return lh__plc_line_end(x->s, item);
    lh__scan_next(x->s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    snprintf(what, sizeof what, "the boundary marker of %s", item);
    lh_status st = lh__plc_integer(x->s, &t, what, m);
    return st == LH_OK ? lh__plc_line_end(x->s, item) : st;
}

/* The first token of item `item` (crossing lines): the end of the input names the
 * declared count. */
static lh_status item_start(lh__scan *s, lh__token *t, const char *what, size_t declared,
                            const char *many)
{
    lh__scan_next(s, 1, t);
    if (t->kind != LH__TOK_EOF) return LH_OK;
    char tail[80]; /* many is a regular plural: one is many less its 's' */
    snprintf(tail, sizeof tail, " (%zu %.*s declared)", declared, (int)(strlen(many) - (declared == 1)), many);
    return lh__expected(s, LH_ERR_PARSE, t, what, tail);
}

/* A .smesh facet: "k v_1 .. v_k [marker]", k >= 3. */
static lh_status read_smesh_facet(poly_ctx *x, const char *item, size_t declared)
{
    lh__token at;
    char what[120];
    size_t k;
    lh_index m;
    snprintf(what, sizeof what, "the number of vertices of %s", item);
    lh_status st = item_start(x->s, &at, what, declared, "facets");
    if (st == LH_OK) st = lh__plc_count(x->s, &at, what, 3, &k);
    if (st == LH_OK) st = read_vertices(x, k, item);
    if (st == LH_OK) st = facet_tail(x, item, &m);
    if (st != LH_OK) return st;
    st = lh__plc_facet(x->b, m, at.line);
    if (st == LH_OK) st = lh__plc_polygon(x->b, x->ring.v, x->ring.k);
    return lh__plc_built(x->s, st, &at, item);
}

/* A hole point "number x y z" of ITEM (a facet's or the volume's); into *t its first
 * token. */
static lh_status hole_point(poly_ctx *x, const char *item, size_t declared, const char *many,
                            lh__token *t, double xyz[3])
{
    char what[160];
    lh_index number;
    snprintf(what, sizeof what, "the number of %s", item);
    lh_status st = item_start(x->s, t, what, declared, many);
    if (st == LH_OK) st = lh__plc_integer(x->s, t, what, &number);
    if (st == LH_OK) st = lh__plc_numbers(x->s, 1, 3, "coordinate", item, "points", xyz);
    return st == LH_OK ? lh__plc_line_end(x->s, item) : st;
}

/* A .poly facet: "polygons [holes [marker]]", its polygons, its hole points. */
static lh_status read_poly_facet(poly_ctx *x, const char *item, size_t declared)
{
    lh__scan *s = x->s;
    lh__token at, t;
    char what[160], sub[120];
    size_t polygons, holes = 0;
    lh_index m = 0;
    snprintf(what, sizeof what, "the number of polygons of %s", item);
    lh_status st = item_start(s, &at, what, declared, "facets");
    if (st == LH_OK) st = lh__plc_count(s, &at, what, 1, &polygons);
    if (st != LH_OK) return st;
    lh__scan_next(s, 0, &t);
    if (t.kind != LH__TOK_EOL && t.kind != LH__TOK_EOF) {
        snprintf(what, sizeof what, "the number of hole points of %s", item);
        st = lh__plc_count(s, &t, what, 0, &holes);
        if (st == LH_OK) st = facet_tail(x, item, &m);
        if (st != LH_OK) return st;
    }
    st = lh__plc_built(s, lh__plc_facet(x->b, m, at.line), &at, item);
    int big = 0;
    for (size_t j = 0; st == LH_OK && j < polygons; j++) {
        size_t k = 0;
        snprintf(sub, sizeof sub, "polygon %zu of %s", j + 1, item);
        snprintf(what, sizeof what, "the number of vertices of %s", sub);
        st = item_start(s, &t, what, polygons, "polygons");
        if (st == LH_OK) st = lh__plc_count(s, &t, what, 1, &k);
        if (st == LH_OK) st = read_vertices(x, k, sub);
        if (st == LH_OK) st = lh__plc_line_end(s, sub);
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_polygon(x->b, x->ring.v, k), &t, sub);
        big |= k >= 3;
    }
    if (st == LH_OK && !big) {
        snprintf(what, sizeof what, "%s has no polygon of 3 or more vertices", item);
        return lh__fail_at(s, LH_ERR_PARSE, &at, what);
    }
    for (size_t j = 0; st == LH_OK && j < holes; j++) {
        double xyz[3];
        snprintf(sub, sizeof sub, "hole point %zu of %s", j + 1, item);
        st = hole_point(x, sub, holes, "hole points", &t, xyz);
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_facet_hole(x->b, xyz), &t, sub);
    }
    return st;
}

static lh_status read_facets(poly_ctx *x, int smesh)
{
    lh__scan *s = x->s;
    lh__token t;
    size_t n;
    int ended = 0;
    lh__scan_next(s, 1, &t);
    lh_status st = lh__plc_count(s, &t, "the number of facets", 0, &n);
    if (st == LH_OK)
        st = lh__header_field(s, "the number of facet boundary markers (0 or 1)", 1, &x->facet_markers, &ended);
    if (st == LH_OK) st = header_end(s, ended, "the end of the line after the number of facets and markers");
    for (size_t i = 0; st == LH_OK && i < n; i++) {
        char item[64];
        snprintf(item, sizeof item, "facet %lld", x->b->g->first_index + (long long)i);
        st = smesh ? read_smesh_facet(x, item, n) : read_poly_facet(x, item, n);
    }
    return st;
}

/* Part 3 or 4: "count" then count items of per = 3 (holes: x y z) or 5 numbers
 * (regions: x y z attribute [max_volume]). *present: the section was there (the end
 * of the input may come instead). */
static lh_status read_points_section(poly_ctx *x, int per, const char *one, const char *many,
                                     int *present)
{
    lh__scan *s = x->s;
    lh__token t;
    size_t n;
    char what[160], item[64];
    *present = 0;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    *present = 1;
    snprintf(what, sizeof what, "the number of %s", many);
    lh_status st = lh__plc_count(s, &t, what, 0, &n);
    if (st == LH_OK) st = lh__plc_line_end(s, what);
    for (size_t i = 0; st == LH_OK && i < n; i++) {
        double v[5] = {0, 0, 0, 0, -1};
        snprintf(item, sizeof item, "%s %lld", one, x->b->g->first_index + (long long)i);
        if (per == 3) {
            st = hole_point(x, item, n, many, &t, v);
            if (st == LH_OK) st = lh__plc_built(s, lh__plc_hole(x->b, v, t.line), &t, item);
            continue;
        }
        lh_index number;
        lh__token u;
        snprintf(what, sizeof what, "the number of %s", item);
        st = item_start(s, &t, what, n, many);
        if (st == LH_OK) st = lh__plc_integer(s, &t, what, &number);
        if (st == LH_OK) st = lh__plc_numbers(s, 1, 3, "coordinate", item, "points", v);
        if (st == LH_OK) {
            snprintf(what, sizeof what, "the attribute of %s", item);
            lh__scan_next(s, 0, &u);
            st = lh__number(s, &u, what, "accepted", NULL, &v[3]);
        }
        if (st == LH_OK) lh__scan_next(s, 0, &u);
        if (st == LH_OK && u.kind != LH__TOK_EOL && u.kind != LH__TOK_EOF) {
            snprintf(what, sizeof what, "the maximum volume of %s", item);
            st = lh__number(s, &u, what, "accepted", NULL, &v[4]);
            if (st == LH_OK) st = lh__plc_line_end(s, item);
        }
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_region(x->b, v, t.line), &t, item);
    }
    return st;
}

static lh_status read_sections(poly_ctx *x, int smesh)
{
    int holes, regions = 0;
    lh_status st = read_points(x, 0);
    if (st == LH_OK && x->b->g->n == 0) x->b->g->first_index = 0; /* raw until take_points */
    if (st == LH_OK) st = read_facets(x, smesh);
    if (st == LH_OK) st = read_points_section(x, 3, "hole", "holes", &holes);
    if (st == LH_OK && holes) st = read_points_section(x, 5, "region", "regions", &regions);
    if (st != LH_OK || !regions) return st;
    char items[80];
    snprintf(items, sizeof items, "%zu region%s", x->b->g->region_count,
             x->b->g->region_count == 1 ? "" : "s");
    return lh__plc_input_end(x->s, items);
}

lh_status lh__plc_read_poly(lh__scan *s, lh__plc_build *b, int smesh)
{
    poly_ctx x = {s, b, {0}, smesh ? ".smesh" : ".poly", 0, 0};
    lh_status st = read_sections(&x, smesh);
    lh__plc_ring_free(b, &x.ring);
    return st;
}

lh_status lh__plc_read_node(lh__scan *s, lh__plc_build *b)
{
    poly_ctx x = {s, b, {0}, ".node", 0, 0};
    lh_status st = read_points(&x, 1);
    if (st != LH_OK) return st;
    char items[80];
    snprintf(items, sizeof items, "%zu point%s", b->g->n, b->g->n == 1 ? "" : "s");
    return lh__plc_input_end(s, items);
}
