/*
 * io_plc_off.c — lh_plc_read's OFF reader (Geomview's "Object File Format", OOGL's
 * OFF(5)), as lifthull accepts it:
 *
 *     [ST][C][N]OFF                  the header keyword; optional (a file may start
 *                                    with the counts); "4OFF", "nOFF" and "OFF BINARY"
 *                                    are refused (not 3D text)
 *     vertices faces [edges]         vertices >= 1, faces >= 0, edges ignored; may
 *                                    follow the keyword on its line
 *     x y z [extra ...]              one line per vertex; extra numbers (normal,
 *                                    colour, texture coordinates) only when the
 *                                    keyword has a prefix, and ignored
 *     k v_0 .. v_{k-1} [colour]      one line per face: k >= 3 vertex numbers from 0,
 *                                    then at most 4 numbers (a colour), ignored
 *
 * Blank lines and '#' comments may go anywhere. Each face becomes one facet of one
 * polygon, marker 0; a face of fewer than 3 vertices is an error naming its line, as
 * is a vertex number out of range, NaN or an infinity, a count larger than the data
 * and anything after the last face.
 */
#include "io_plc_text.h"

#include <math.h>
#include <string.h>

#define OFF_EXTRA 9  /* numbers a vertex line may carry after x y z (N, C, ST)   */
#define OFF_COLOUR 4 /* numbers a face line may carry after its vertices (r g b a) */

/* Whether w is the keyword [ST][C][N]OFF; *prefixed: it has a prefix. */
static int off_keyword(const char *w, int *prefixed)
{
    const char *p = w;
    if (strncmp(p, "ST", 2) == 0) p += 2;
    if (*p == 'C') p++;
    if (*p == 'N') p++;
    *prefixed = p != w;
    return strcmp(p, "OFF") == 0;
}

/* The keyword (optional) and the counts: *t is the first token, read crossing lines. */
static lh_status read_header(lh__scan *s, lh__token *t, size_t *nv, size_t *nf, int *prefixed)
{
    long long v;
    lh_status st;
    *prefixed = 0;
    if (t->kind == LH__TOK_WORD && !lh__word_integer(t, &v)) {
        if (!off_keyword(t->text, prefixed))
            return lh__expected(s, LH_ERR_PARSE, t,
                                "the OFF header ('OFF', 'COFF', 'NOFF', 'CNOFF', 'STOFF'...) or the number of vertices",
                                NULL);
        lh__scan_next(s, 0, t);
        if (t->kind == LH__TOK_EOL) lh__scan_next(s, 1, t);
        else if (t->kind == LH__TOK_WORD && strcmp(t->text, "BINARY") == 0)
            return lh__fail_at(s, LH_ERR_PARSE, t, "binary OFF is not read: write it as text");
    }
    st = lh__plc_count(s, t, "the number of vertices", 1, nv);
    if (st == LH_OK) {
        lh__scan_next(s, 0, t);
        st = lh__plc_count(s, t, "the number of faces", 0, nf);
    }
    if (st != LH_OK) return st;
    lh__scan_next(s, 0, t); /* the number of edges, which nothing uses */
    if (t->kind == LH__TOK_EOL || t->kind == LH__TOK_EOF) return LH_OK;
    if (!lh__word_integer(t, &v) || v < 0)
        return lh__expected(s, LH_ERR_PARSE, t, "the number of edges (an integer from 0) or the end of the line", NULL);
    return lh__plc_line_end(s, "the counts (vertices, faces, edges)");
}

/* After a vertex's x y z (prefixed: up to OFF_EXTRA numbers ignored) or a face's
 * vertices (up to OFF_COLOUR numbers ignored): the end of the line. */
static lh_status extra_and_end(lh__scan *s, int allowed, const char *item, const char *what)
{
    lh__token t;
    double x;
    for (int j = 0;; j++) {
        lh__scan_next(s, 0, &t);
        if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
        if (j == allowed || !lh__word_double(&t, &x)) break;
    }
    char w[200];
    snprintf(w, sizeof w, "the end of the line after %s%s", item, what);
    return lh__expected(s, LH_ERR_PARSE, &t, w, NULL);
}

static lh_status read_vertex(lh__scan *s, lh__plc_build *b, size_t i, size_t nv, int prefixed)
{
    char item[64];
    double xyz[3];
    lh__token t;
    lh__plc_item(item, sizeof item, "vertex ", (long long)i);
    lh__scan_next(s, 1, &t);
    lh_status st = LH_OK;
    if (!lh__word_double(&t, &xyz[0]) || !isfinite(xyz[0])) { /* named only to report */
        char what[80], tail[64];
        snprintf(what, sizeof what, "coordinate 1 of %s", item);
        snprintf(tail, sizeof tail, " (%zu vert%s declared)", nv, nv == 1 ? "ex" : "ices");
        st = lh__number(s, &t, what, "points", tail, &xyz[0]);
    }
    if (st == LH_OK) st = lh__plc_numbers(s, 2, 2, "coordinate", item, "points", xyz + 1);
    if (st == LH_OK)
        st = extra_and_end(s, prefixed ? OFF_EXTRA : 0, item,
                           prefixed ? " (its normal, colour or texture numbers)" : "");
    if (st == LH_OK) st = lh__plc_built(s, lh__plc_point(b, xyz, NULL, 0, t.line), &t, item);
    return st;
}

static lh_status read_face(lh__scan *s, lh__plc_build *b, lh__plc_ring *r, size_t i, size_t nf)
{
    char item[64], what[120];
    lh__token at, t;
    size_t k;
    lh__plc_item(item, sizeof item, "face ", (long long)i);
    lh__scan_next(s, 1, &at);
    if (at.kind == LH__TOK_EOF) {
        char tail[64];
        snprintf(what, sizeof what, "the number of vertices of %s", item);
        snprintf(tail, sizeof tail, " (%zu face%s declared)", nf, nf == 1 ? "" : "s");
        return lh__expected(s, LH_ERR_PARSE, &at, what, tail);
    }
    lh_status st = lh__plc_count_of(s, &at, "the number of vertices of ", item, 3, &k);
    r->k = 0;
    for (size_t j = 0; st == LH_OK && j < k; j++) {
        lh_index v;
        lh__scan_next(s, 0, &t);
        st = lh__plc_vertex(s, &t, 0, b->g->n, j + 1, item, &v);
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_ring_push(b, r, v), &t, item);
    }
    if (st == LH_OK) st = extra_and_end(s, OFF_COLOUR, item, " (or its colour: up to 4 numbers)");
    if (st != LH_OK) return st;
    st = lh__plc_facet(b, 0, at.line);
    if (st == LH_OK) st = lh__plc_polygon(b, r->v, r->k);
    return lh__plc_built(s, st, &at, item);
}

lh_status lh__plc_read_off(lh__scan *s, lh__plc_build *b)
{
    lh__token t;
    size_t nv, nf;
    int prefixed;
    lh__scan_next(s, 1, &t);
    lh_status st = read_header(s, &t, &nv, &nf, &prefixed);
    for (size_t i = 0; st == LH_OK && i < nv; i++) st = read_vertex(s, b, i, nv, prefixed);
    lh__plc_ring r = {0};
    for (size_t i = 0; st == LH_OK && i < nf; i++) st = read_face(s, b, &r, i, nf);
    lh__plc_ring_free(b, &r);
    if (st != LH_OK) return st;
    char items[64];
    snprintf(items, sizeof items, "%zu face%s", nf, nf == 1 ? "" : "s");
    return lh__plc_input_end(s, items);
}
