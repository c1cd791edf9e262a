/*
 * io_plc_obj.c — lh_plc_read's Wavefront OBJ reader (Wavefront Technologies, "Object
 * Files (.obj)", Advanced Visualizer manual, appendix B1), as lifthull accepts it:
 *
 *     v x y z [w | r g b [a]]       a point; up to 4 numbers after z ignored (the
 *                                   weight w, or a vertex colour as MeshLab writes)
 *     f i_1 i_2 .. i_k              a facet of one polygon, k >= 3; each i is v,
 *                                   v/t, v/t/n or v//n (t and n ignored)
 *     l i_1 i_2 .. i_k              a polyline, k >= 2: segments i_1 i_2, i_2 i_3, ...
 *     vt, vn, vp, g, o, s, usemtl, mtllib, p and the free-form statements
 *                                   (cstype, curv, surf, ...): ignored
 *
 * One statement a line (no '\' continuation); '#' comments and blank lines anywhere.
 * Vertex numbers are 1-based, or negative: -1 is the last vertex defined so far; a
 * number must name a vertex defined on an earlier line. Any other statement, a face
 * of fewer than 3 vertices, NaN or an infinity, and a file without a vertex are
 * errors naming the line. Facets and segments get marker 0.
 */
#include "io_plc_text.h"

#include <limits.h>
#include <string.h>

#define OBJ_EXTRA 4 /* numbers a 'v' line may carry after x y z */

typedef struct obj_ctx {
    lh__scan *s;
    lh__plc_build *b;
    lh__plc_ring ring;
    size_t faces, polylines;
} obj_ctx;

/* text[0..len) as an optional sign and 1 or more digits (saturated); 1 when it is. */
static int integer(const char *text, size_t len, long long *v)
{
    size_t i = 0;
    int neg = 0;
    if (i < len && (text[i] == '+' || text[i] == '-')) neg = text[i++] == '-';
    if (i == len) return 0;
    long long x = 0;
    for (; i < len; i++) {
        if (text[i] < '0' || text[i] > '9') return 0;
        int d = text[i] - '0';
        x = x > (LLONG_MAX - d) / 10 ? LLONG_MAX : 10 * x + d;
    }
    *v = neg ? -x : x;
    return 1;
}

/* Word t as "v", "v/t", "v/t/n" or "v//n" (t, n: integers, ignored) into *v: the
 * vertex number as written. */
static int vertex_ref(const lh__token *t, long long *v)
{
    if (t->kind != LH__TOK_WORD) return 0;
    const char *p = t->text, *end = p + t->len, *slash = memchr(p, '/', t->len);
    if (!integer(p, (size_t)((slash ? slash : end) - p), v)) return 0;
    if (!slash) return 1;
    const char *q = slash + 1, *slash2 = memchr(q, '/', (size_t)(end - q));
    long long ignored;
    const char *tex_end = slash2 ? slash2 : end;
    if (tex_end > q && !integer(q, (size_t)(tex_end - q), &ignored)) return 0;
    if (!slash2) return tex_end > q; /* "v/" is not a reference */
    q = slash2 + 1;
    return q < end && integer(q, (size_t)(end - q), &ignored);
}

/* The vertex named by word t (1-based or negative), 0-based into *v. */
static lh_status vertex(obj_ctx *x, const lh__token *t, const char *what, lh_index *v)
{
    long long k, n = (long long)x->b->g->n;
    if (vertex_ref(t, &k) && k != 0 && k >= -n && k <= n) {
        *v = (lh_index)(k > 0 ? k - 1 : n + k);
        return LH_OK;
    }
    char w[200];
    if (n) snprintf(w, sizeof w, "%s (a vertex number from 1 to %lld or from -%lld to -1)", what, n, n);
    else snprintf(w, sizeof w, "%s (a vertex number; no vertex is defined yet)", what);
    return lh__expected(x->s, LH_ERR_PARSE, t, w, NULL);
}

static lh_status read_v(obj_ctx *x, const lh__token *at)
{
    lh__scan *s = x->s;
    char item[64];
    double xyz[3], extra;
    lh__token t;
    snprintf(item, sizeof item, "vertex %zu", x->b->g->n + 1);
    lh_status st = lh__plc_numbers(s, 1, 3, "coordinate", item, "points", xyz);
    for (int j = 0; st == LH_OK; j++) {
        lh__scan_next(s, 0, &t);
        if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) break;
        if (j < OBJ_EXTRA && lh__word_double(&t, &extra)) continue;
        char what[120];
        snprintf(what, sizeof what, "the end of the line after %s", item);
        st = lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
    }
    if (st != LH_OK) return st;
    return lh__plc_built(s, lh__plc_point(x->b, xyz, NULL, 0, at->line), at, item);
}

/* The references of an 'f' (least 3) or 'l' (least 2) line into x->ring. */
static lh_status read_refs(obj_ctx *x, const lh__token *at, const char *item, size_t least)
{
    lh__scan *s = x->s;
    lh__token t;
    char what[120];
    x->ring.k = 0;
    for (;;) {
        lh_index v = 0;
        lh__scan_next(s, 0, &t);
        if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) break;
        snprintf(what, sizeof what, "vertex %zu of %s", x->ring.k + 1, item);
        lh_status st = vertex(x, &t, what, &v);
        if (st == LH_OK) st = lh__plc_built(s, lh__plc_ring_push(x->b, &x->ring, v), &t, item);
        if (st != LH_OK) return st;
    }
    if (x->ring.k >= least) return LH_OK;
    snprintf(what, sizeof what, "%s has %zu vert%s: %s needs %zu or more", item, x->ring.k,
             x->ring.k == 1 ? "ex" : "ices", least == 3 ? "a facet" : "a polyline", least);
    return lh__fail_at(s, LH_ERR_PARSE, at, what);
}

static lh_status read_f(obj_ctx *x, const lh__token *at)
{
    char item[64];
    snprintf(item, sizeof item, "face %zu", ++x->faces);
    lh_status st = read_refs(x, at, item, 3);
    if (st != LH_OK) return st;
    st = lh__plc_facet(x->b, 0, at->line);
    if (st == LH_OK) st = lh__plc_polygon(x->b, x->ring.v, x->ring.k);
    return lh__plc_built(x->s, st, at, item);
}

static lh_status read_l(obj_ctx *x, const lh__token *at)
{
    char item[64];
    snprintf(item, sizeof item, "polyline %zu", ++x->polylines);
    lh_status st = read_refs(x, at, item, 2);
    for (size_t i = 1; st == LH_OK && i < x->ring.k; i++)
        st = lh__plc_built(x->s, lh__plc_segment(x->b, x->ring.v[i - 1], x->ring.v[i], 0, at->line),
                           at, item);
    return st;
}

/* Statements read past, to the end of their line. */
static int ignored(const char *w)
{
    static const char *const words[] = {
        "vt",   "vn",   "vp",    "g",     "o",    "s",     "usemtl", "mtllib",  "p",
        "cstype", "deg", "bmat", "step",  "curv", "curv2", "surf",   "parm",    "trim",
        "hole", "scrv", "sp",    "end",   "con",  "mg",    "bevel",  "c_interp", "d_interp",
        "lod",  "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strcmp(w, words[i]) == 0) return 1;
    return 0;
}

static lh_status read_obj(obj_ctx *x)
{
    lh__scan *s = x->s;
    lh__token t;
    lh_status st = LH_OK;
    while (st == LH_OK) {
        lh__scan_next(s, 1, &t);
        if (t.kind == LH__TOK_EOF) break;
        if (t.kind == LH__TOK_WORD && strcmp(t.text, "v") == 0) st = read_v(x, &t);
        else if (t.kind == LH__TOK_WORD && strcmp(t.text, "f") == 0) st = read_f(x, &t);
        else if (t.kind == LH__TOK_WORD && strcmp(t.text, "l") == 0) st = read_l(x, &t);
        else if (t.kind == LH__TOK_WORD && ignored(t.text)) lh__scan_skip_line(s);
        else
            st = lh__expected(s, LH_ERR_PARSE, &t,
                              "an OBJ statement (v, f, l, vt, vn, g, o, s, usemtl, mtllib, ...)", NULL);
    }
    if (st == LH_OK && x->b->g->n == 0)
        return lh__expected(s, LH_ERR_PARSE, &t, "a vertex ('v x y z')", NULL);
    return st;
}

lh_status lh__plc_read_obj(lh__scan *s, lh__plc_build *b)
{
    obj_ctx x = {s, b, {0}, 0, 0};
    b->g->first_index = 1;
    lh_status st = read_obj(&x);
    lh__plc_ring_free(b, &x.ring);
    return st;
}
