/*
 * io_plc_medit.c — lh_plc_read's Medit reader: the ASCII .mesh of Frey's Medit and
 * Loseille's libMeshb (INRIA, "the Medit file format", ljll.fr/frey/logiciels/
 * Docmedit.dir), as lifthull accepts it:
 *
 *     MeshVersionFormatted v           first; v from 1 to 4 (the text is the same)
 *     Dimension 3                      before every section
 *     Vertices  n  then n lines "x y z ref"          the points (ref: the marker)
 *     Triangles n  then n lines "a b c ref"          a facet each (ref: its marker)
 *     Quadrilaterals n  then n lines "a b c d ref"   a facet each
 *     Edges n  then n lines "a b ref"                a segment each
 *     KEYWORD n  then n lines                        any other section (Tetrahedra,
 *                                                    Corners, Ridges, ...): skipped
 *     End                              optional; nothing but comments after it
 *
 * Keywords are case-sensitive, as Medit writes them; a keyword and its count may be
 * on one line or two, every item is on a line of its own; vertex numbers are 1-based
 * and must name a vertex of the Vertices section, which comes before the sections
 * that use it (and only once). '#' comments and blank lines go anywhere. A file
 * without Vertices is an error.
 */
#include "io_plc_text.h"

#include <string.h>

typedef struct medit_ctx {
    lh__scan *s;
    lh__plc_build *b;
    lh__plc_ring ring;
    int vertices; /* the Vertices section was read */
} medit_ctx;

/* The count after keyword kw (crossing lines), read into *t. */
static lh_status section_count(medit_ctx *x, const char *kw, size_t *n, lh__token *t)
{
    char what[120];
    lh__scan_next(x->s, 1, t);
    snprintf(what, sizeof what, "the number of %.40s", kw);
    return lh__plc_count(x->s, t, what, 0, n);
}

/* The first token of item i of section kw (crossing lines); the end names the count. */
static lh_status item_start(medit_ctx *x, lh__token *t, const char *what, size_t n,
                            const char *kw)
{
    lh__scan_next(x->s, 1, t);
    if (t->kind != LH__TOK_EOF) return LH_OK;
    char tail[120];
    snprintf(tail, sizeof tail, " (%zu %.40s declared)", n, kw);
    return lh__expected(x->s, LH_ERR_PARSE, t, what, tail);
}

/* "ref" then the end of the line, of ITEM. */
static lh_status ref_and_end(medit_ctx *x, const char *item, lh_index *ref)
{
    lh__token t;
    char what[120];
    lh__scan_next(x->s, 0, &t);
    snprintf(what, sizeof what, "the reference of %s", item);
    lh_status st = lh__plc_integer(x->s, &t, what, ref);
    return st == LH_OK ? lh__plc_line_end(x->s, item) : st;
}

static lh_status read_vertices(medit_ctx *x)
{
    lh__scan *s = x->s;
    size_t n;
    lh__token c;
    lh_status st = section_count(x, "Vertices", &n, &c);
    if (st == LH_OK && n == 0) return lh__fail_at(s, LH_ERR_PARSE, &c, "a mesh needs vertices: Vertices 0");
    for (size_t i = 0; st == LH_OK && i < n; i++) {
        lh__token t;
        char item[64], what[100];
        double xyz[3];
        lh_index ref;
        snprintf(item, sizeof item, "vertex %zu", i + 1);
        snprintf(what, sizeof what, "coordinate 1 of %s", item);
        st = item_start(x, &t, what, n, "Vertices");
        if (st == LH_OK) st = lh__number(s, &t, what, "points", NULL, &xyz[0]);
        if (st == LH_OK) st = lh__plc_numbers(s, 2, 2, "coordinate", item, "points", xyz + 1);
        if (st == LH_OK) st = ref_and_end(x, item, &ref);
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_point(x->b, xyz, NULL, ref, t.line), &t, item);
    }
    x->vertices = 1;
    return st;
}

/* Triangles (k 3), Quadrilaterals (4) or Edges (2): each "v_1 .. v_k ref". */
static lh_status read_elements(medit_ctx *x, const char *kw, const char *one, size_t k)
{
    lh__scan *s = x->s;
    size_t n;
    lh__token t, at;
    lh_status st = section_count(x, kw, &n, &t);
    for (size_t i = 0; st == LH_OK && i < n; i++) {
        char item[64], what[120];
        lh_index ref;
        snprintf(item, sizeof item, "%s %zu", one, i + 1);
        x->ring.k = 0;
        for (size_t j = 0; st == LH_OK && j < k; j++) {
            lh_index v;
            if (j == 0) {
                snprintf(what, sizeof what, "vertex 1 of %s", item);
                st = item_start(x, &t, what, n, kw);
                at = t;
            } else {
                lh__scan_next(s, 0, &t);
            }
            if (st == LH_OK) st = lh__plc_vertex(s, &t, 1, x->b->g->n, j + 1, item, &v);
            if (st == LH_OK) st = lh__plc_built(s, lh__plc_ring_push(x->b, &x->ring, v), &t, item);
        }
        if (st == LH_OK) st = ref_and_end(x, item, &ref);
        if (st != LH_OK) break;
        if (k == 2) {
            st = lh__plc_segment(x->b, x->ring.v[0], x->ring.v[1], ref, at.line);
        } else {
            st = lh__plc_facet(x->b, ref, at.line);
            if (st == LH_OK) st = lh__plc_polygon(x->b, x->ring.v, k);
        }
        st = lh__plc_built(s, st, &at, item);
    }
    return st;
}

/* A section read past: its count, then as many lines. */
static lh_status skip_section(medit_ctx *x, const char *kw)
{
    size_t n;
    lh__token t;
    lh_status st = section_count(x, kw, &n, &t);
    for (size_t i = 0; st == LH_OK && i < n; i++) {
        char what[120];
        snprintf(what, sizeof what, "line %zu of %.40s", i + 1, kw);
        st = item_start(x, &t, what, n, kw);
        if (st == LH_OK && t.kind != LH__TOK_WORD) st = lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        if (st == LH_OK) lh__scan_skip_line(x->s);
    }
    return st;
}

/* "MeshVersionFormatted v" and "Dimension 3". */
static lh_status read_header(medit_ctx *x)
{
    lh__scan *s = x->s;
    lh__token t;
    long long v;
    lh__scan_next(s, 1, &t);
    if (t.kind != LH__TOK_WORD || strcmp(t.text, "MeshVersionFormatted") != 0)
        return lh__expected(s, LH_ERR_PARSE, &t, "'MeshVersionFormatted'", NULL);
    lh__scan_next(s, 1, &t);
    if (!lh__word_integer(&t, &v) || v < 1 || v > 4)
        return lh__expected(s, LH_ERR_PARSE, &t, "the mesh version (an integer from 1 to 4)", NULL);
    lh__scan_next(s, 1, &t);
    if (t.kind != LH__TOK_WORD || strcmp(t.text, "Dimension") != 0)
        return lh__expected(s, LH_ERR_PARSE, &t, "'Dimension'", NULL);
    lh__scan_next(s, 1, &t);
    if (!lh__word_integer(&t, &v))
        return lh__expected(s, LH_ERR_PARSE, &t, "the dimension (3)", NULL);
    if (v != 3) return lh__expected(s, LH_ERR_DIMENSION, &t, "the dimension (3: a PLC is 3D)", NULL);
    return LH_OK;
}

static lh_status read_medit(medit_ctx *x)
{
    lh__scan *s = x->s;
    lh__token t;
    lh_status st = read_header(x);
    while (st == LH_OK) {
        lh__scan_next(s, 1, &t);
        if (t.kind == LH__TOK_EOF || (t.kind == LH__TOK_WORD && strcmp(t.text, "End") == 0)) break;
        long long v;
        if (t.kind != LH__TOK_WORD || lh__word_integer(&t, &v))
            return lh__expected(s, LH_ERR_PARSE, &t, "a keyword (Vertices, Triangles, Quadrilaterals, Edges, ..., End)", NULL);
        int uses = !strcmp(t.text, "Triangles") || !strcmp(t.text, "Quadrilaterals") || !strcmp(t.text, "Edges");
        if (!strcmp(t.text, "Vertices") && x->vertices)
            return lh__fail_at(s, LH_ERR_PARSE, &t, "a second Vertices section");
        if (uses && !x->vertices) {
            char text[120];
            snprintf(text, sizeof text, "%.40s before Vertices", t.text);
            return lh__fail_at(s, LH_ERR_PARSE, &t, text);
        }
        if (!strcmp(t.text, "Vertices")) st = read_vertices(x);
        else if (!strcmp(t.text, "Triangles")) st = read_elements(x, "Triangles", "triangle", 3);
        else if (!strcmp(t.text, "Quadrilaterals")) st = read_elements(x, "Quadrilaterals", "quadrilateral", 4);
        else if (!strcmp(t.text, "Edges")) st = read_elements(x, "Edges", "edge", 2);
        else {
            char kw[LH_READ_MAX_TOKEN + 1];
            memcpy(kw, t.text, t.len + 1);
            st = skip_section(x, kw);
        }
    }
    if (st != LH_OK) return st;
    if (!x->vertices) return lh__expected(s, LH_ERR_PARSE, &t, "the Vertices section", NULL);
    return t.kind == LH__TOK_EOF ? LH_OK : lh__plc_input_end(s, "End");
}

lh_status lh__plc_read_medit(lh__scan *s, lh__plc_build *b)
{
    medit_ctx x = {s, b, {0}, 0};
    b->g->first_index = 1;
    lh_status st = read_medit(&x);
    lh__plc_ring_free(b, &x.ring);
    return st;
}
