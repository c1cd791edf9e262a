/* io_plc_ply.c — Stanford PLY files (Turk, "The PLY polygon file format", 1994) as
 * lh_plc_read reads them:
 *
 *     ply
 *     format ascii 1.0 | binary_little_endian 1.0 | binary_big_endian 1.0
 *     comment ... | obj_info ...               (header lines, anywhere after ply)
 *     element vertex N                         N from 1 to LH_READ_MAX_POINTS
 *     property TYPE x, property TYPE y, property TYPE z   (any order, each once)
 *     element face M                           (optional: no face, only points)
 *     property list COUNT INDEX vertex_indices (or vertex_index)
 *     element NAME K, property ...             other elements (skipped)
 *     end_header
 *
 * TYPE is char int8 uchar uint8 short int16 ushort uint16 int int32 uint uint32 float
 * float32 double float64; COUNT and INDEX are integer types. Elements may come in any
 * order and have other properties (skipped: by their sizes in binary files, lists
 * included). The body holds each element's records in header order: ascii one record
 * a line (blank lines ignored), binary each value packed in its type's size and the
 * file's byte order, a list as its count then its items, nothing after the last; an
 * ascii value of an integer type is written as an integer.
 * Each face of k >= 3 vertices is one facet of one polygon (marker 0); a face of fewer
 * vertices is an error, and so is an index outside 0..N-1 or a coordinate that is NaN
 * or infinite. Records are numbered from 0 in messages, as faces number vertices
 * ("NAME:LINE:COL: face 5: ..." in ascii, "NAME: face 5: ..." in binary); point_line
 * and facet_line hold the line (ascii) or the record number plus 1 (binary). Counts
 * are checked against the data as it comes: nothing is allocated for a declared count.
 */
#include "io_plc.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

enum { T_I8 = 1, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 };
enum { R_SKIP, R_X, R_Y, R_Z, R_INDICES }; /* a property's role */
enum { E_OTHER, E_VERTEX, E_FACE };        /* an element's kind */
enum { F_ASCII, F_LITTLE, F_BIG };         /* the body's format */

#define MAX_ELEMENTS 32
#define MAX_PROPERTIES 256

typedef struct ply_prop {
    unsigned char type, count_type, list, role;
    char name[24]; /* for messages (cut) */
} ply_prop;

typedef struct ply_elem {
    int kind;
    size_t count, first, props; /* records; properties first .. first+props-1 */
    char name[24];
} ply_elem;

typedef struct ply {
    lh__scan *s;
    lh__plc_build *b;
    int format;
    ply_elem elem[MAX_ELEMENTS];
    size_t elems;
    ply_prop prop[MAX_PROPERTIES];
    size_t props;
    size_t nv;       /* declared vertices */
    lh__token t, at; /* the last token; the record's first (ascii) */
    lh_index *idx;   /* a face's vertex indices (capacity cap) */
    size_t cap, k;
} ply;

static int type_of(const char *w)
{
    static const struct {
        const char *name;
        int type;
    } types[] = {{"char", T_I8},   {"int8", T_I8},     {"uchar", T_U8},   {"uint8", T_U8},
                 {"short", T_I16}, {"int16", T_I16},   {"ushort", T_U16}, {"uint16", T_U16},
                 {"int", T_I32},   {"int32", T_I32},   {"uint", T_U32},   {"uint32", T_U32},
                 {"float", T_F32}, {"float32", T_F32}, {"double", T_F64}, {"float64", T_F64}};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(w, types[i].name) == 0) return types[i].type;
    return 0;
}

static size_t type_size(int type)
{
    static const unsigned char size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
    return size[type];
}

static int is_word(const lh__token *t, const char *w)
{
    return t->kind == LH__TOK_WORD && strcmp(t->text, w) == 0;
}

/* ---- the header ----------------------------------------------------------------- */

static lh_status expect_word(ply *r, const char *w, const char *what)
{
    lh__scan_next(r->s, 0, &r->t);
    return is_word(&r->t, w) ? LH_OK : lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
}

static lh_status line_end(ply *r, const char *after)
{
    char what[80];
    lh__scan_next(r->s, 0, &r->t);
    if (r->t.kind == LH__TOK_EOL) return LH_OK;
    snprintf(what, sizeof what, "the end of the line after %s", after);
    return lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
}

static lh_status read_format(ply *r)
{
    static const char *const names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
    lh_status st = expect_word(r, "ply", "'ply' (the first line of a PLY file)");
    if (st == LH_OK) st = line_end(r, "'ply'");
    if (st != LH_OK) return st;
    for (;;) { /* comments may come before the format line too */
        lh__scan_next(r->s, 1, &r->t);
        if (!is_word(&r->t, "comment") && !is_word(&r->t, "obj_info")) break;
        lh__scan_skip_line(r->s);
    }
    if (!is_word(&r->t, "format"))
        return lh__expected(r->s, LH_ERR_PARSE, &r->t, "'format' (the line after 'ply')", NULL);
    lh__scan_next(r->s, 0, &r->t);
    r->format = -1;
    for (int i = 0; i < 3; i++)
        if (is_word(&r->t, names[i])) r->format = i;
    if (r->format < 0)
        return lh__expected(r->s, LH_ERR_PARSE, &r->t,
                            "ascii, binary_little_endian or binary_big_endian", NULL);
    st = expect_word(r, "1.0", "the version 1.0");
    return st == LH_OK ? line_end(r, "the format") : st;
}

/* The count of an element: its token in r->t. */
static lh_status element_count(ply *r, ply_elem *e)
{
    long long v = 0, hi = e->kind == E_VERTEX ? LH_READ_MAX_POINTS : LH_INDEX_MAX;
    char what[100];
    if (e->kind == E_VERTEX) return lh__count(r->s, &r->t, "the number of vertices", &e->count);
    if (lh__word_integer(&r->t, &v) && v >= 0 && v <= hi) {
        e->count = (size_t)v;
        return LH_OK;
    }
    snprintf(what, sizeof what, "the number of %.20s elements (an integer from 0 to %lld)", e->name,
             hi);
    return lh__expected(r->s, v > hi && r->t.kind == LH__TOK_WORD ? LH_ERR_TOO_LARGE : LH_ERR_PARSE,
                        &r->t, what, NULL);
}

static lh_status read_element(ply *r)
{
    if (r->elems == MAX_ELEMENTS)
        return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "more than 32 elements");
    ply_elem *e = &r->elem[r->elems];
    memset(e, 0, sizeof *e);
    lh__scan_next(r->s, 0, &r->t);
    if (r->t.kind != LH__TOK_WORD)
        return lh__expected(r->s, LH_ERR_PARSE, &r->t, "the element's name", NULL);
    snprintf(e->name, sizeof e->name, "%.23s", r->t.text);
    e->kind = is_word(&r->t, "vertex") ? E_VERTEX : is_word(&r->t, "face") ? E_FACE : E_OTHER;
    for (size_t i = 0; e->kind != E_OTHER && i < r->elems; i++)
        if (r->elem[i].kind == e->kind)
            return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "a second element of this name");
    lh__scan_next(r->s, 0, &r->t);
    lh_status st = element_count(r, e);
    if (st != LH_OK) return st;
    if (e->kind == E_VERTEX) r->nv = e->count;
    e->first = r->props;
    r->elems++;
    return line_end(r, "the element's count");
}

static lh_status scalar_type(ply *r, int integer, const char *what, unsigned char *type)
{
    lh__scan_next(r->s, 0, &r->t);
    int t = r->t.kind == LH__TOK_WORD ? type_of(r->t.text) : 0;
    if (t && (!integer || t < T_F32)) {
        *type = (unsigned char)t;
        return LH_OK;
    }
    return lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
}

/* A property's role from its element and name (in r->t), once each. */
static lh_status property_role(ply *r, const ply_elem *e, ply_prop *p, const lh__token *at)
{
    static const char *const xyz[] = {"x", "y", "z"};
    for (int i = 0; e->kind == E_VERTEX && !p->list && i < 3; i++)
        if (strcmp(r->t.text, xyz[i]) == 0) p->role = (unsigned char)(R_X + i);
    if (e->kind == E_FACE && p->list &&
        (is_word(&r->t, "vertex_indices") || is_word(&r->t, "vertex_index")))
        p->role = R_INDICES;
    if (e->kind == E_FACE && p->role == R_INDICES && p->type >= T_F32)
        return lh__fail_at(r->s, LH_ERR_PARSE, at,
                           "the vertex indices' type is not an integer type");
    if (e->kind == E_VERTEX && p->list && r->t.text[0] && strchr("xyz", r->t.text[0]) &&
        !r->t.text[1])
        return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "a coordinate is a list");
    for (size_t j = e->first; p->role != R_SKIP && j < r->props; j++)
        if (r->prop[j].role == p->role)
            return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "a second property of this name");
    return LH_OK;
}

static lh_status read_property(ply *r)
{
    if (r->elems == 0)
        return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "a property before any element");
    if (r->props == MAX_PROPERTIES)
        return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "more than 256 properties");
    ply_elem *e = &r->elem[r->elems - 1];
    ply_prop *p = &r->prop[r->props];
    memset(p, 0, sizeof *p);
    const char *any = "a type (char, uchar, short, ushort, int, uint, float, double, ...)";
    lh_status st = scalar_type(r, 0, any, &p->type);
    if (st != LH_OK && is_word(&r->t, "list")) {
        p->list = 1;
        st = scalar_type(r, 1, "the list count's type (an integer type)", &p->count_type);
        if (st == LH_OK) st = scalar_type(r, 0, any, &p->type);
    }
    if (st != LH_OK) return st;
    lh__token at = r->t;
    lh__scan_next(r->s, 0, &r->t);
    if (r->t.kind != LH__TOK_WORD)
        return lh__expected(r->s, LH_ERR_PARSE, &r->t, "the property's name", NULL);
    snprintf(p->name, sizeof p->name, "%.23s", r->t.text);
    if ((st = property_role(r, e, p, &at)) != LH_OK) return st;
    r->props++;
    e->props++;
    return line_end(r, "the property's name");
}

/* What the header must declare: the vertices with x, y and z; the faces' indices. */
static lh_status header_complete(ply *r)
{
    int have[R_INDICES + 1] = {0}, vertex = 0, face = 0;
    for (size_t i = 0; i < r->elems; i++) {
        const ply_elem *e = &r->elem[i];
        vertex |= e->kind == E_VERTEX;
        face |= e->kind == E_FACE;
        for (size_t j = e->first; j < e->first + e->props; j++) have[r->prop[j].role] = 1;
    }
    const char *missing = !vertex      ? "the header declares no vertex element"
                          : !have[R_X] ? "the vertex element has no property x"
                          : !have[R_Y] ? "the vertex element has no property y"
                          : !have[R_Z] ? "the vertex element has no property z"
                          : face && !have[R_INDICES]
                              ? "the face element has no property list vertex_indices"
                              : NULL;
    return missing ? lh__fail_at(r->s, LH_ERR_PARSE, &r->t, missing) : LH_OK;
}

static lh_status read_header(ply *r)
{
    lh_status st = read_format(r);
    while (st == LH_OK) {
        lh__scan_next(r->s, 1, &r->t);
        if (is_word(&r->t, "comment") || is_word(&r->t, "obj_info"))
            lh__scan_skip_line(r->s);
        else if (is_word(&r->t, "element"))
            st = read_element(r);
        else if (is_word(&r->t, "property"))
            st = read_property(r);
        else if (is_word(&r->t, "end_header"))
            break;
        else
            st = lh__expected(r->s, LH_ERR_PARSE, &r->t,
                              "a header line (element, property, comment, end_header)", NULL);
    }
    if (st != LH_OK) return st;
    if ((st = header_complete(r)) != LH_OK) return st;
    /* The body starts right after this line's end: binary bytes follow it. */
    lh__scan_next(r->s, 0, &r->t);
    if (r->t.kind == LH__TOK_EOL || (r->t.kind == LH__TOK_EOF && r->format == F_ASCII))
        return LH_OK;
    return lh__expected(r->s, LH_ERR_PARSE, &r->t, "the end of the line after end_header", NULL);
}

/* ---- the body --------------------------------------------------------------------- */

/* The next value of a record: *x (any type), *v (an integer type: exactly). In ascii
 * the token stays in r->t (r->at too for the record's first value); item is the list
 * item (or -1: the property or its count). */
static lh_status value(ply *r, const ply_elem *e, size_t rec, const ply_prop *p, int type,
                       long long item, double *x, long long *v)
{
    if (r->format != F_ASCII) {
        unsigned char buf[8];
        size_t k = type_size(type);
        if (!lh__plc_bytes(r->s, buf, k))
            return lh__plc_record_end(r->s, NULL, e->name, rec, e->count,
                                      e->kind == E_VERTEX ? "vertices"
                                      : e->kind == E_FACE ? "faces"
                                                          : "records");
        uint64_t u = lh__plc_unpack(buf, k, r->format == F_BIG);
        if (type == T_F32)
            *x = lh__plc_float32(u);
        else if (type == T_F64)
            memcpy(x, &u, sizeof *x);
        else {
            /* two's complement: the top bit of a signed type weighs -2^(8k-1) */
            int sign = (type == T_I8 || type == T_I16 || type == T_I32) && u >> (8 * k - 1);
            *v = sign ? (long long)u - (1LL << (8 * k)) : (long long)u;
            *x = (double)*v;
        }
        return LH_OK;
    }
    int first = r->at.kind == LH__TOK_EOF;
    lh__scan_next(r->s, first, &r->t);
    if (first) r->at = r->t;
    if (type < T_F32 && lh__word_integer(&r->t, v)) {
        *x = (double)*v;
        return LH_OK;
    }
    if (type >= T_F32 && lh__word_double(&r->t, x)) return LH_OK;
    char what[120], tail[64];
    if (item < 0 && p->list)
        snprintf(what, sizeof what, "the length of %s of %s %zu (an integer)", p->name, e->name,
                 rec);
    else if (item < 0)
        snprintf(what, sizeof what, "%s of %s %zu (%s)", p->name, e->name, rec,
                 type < T_F32 ? "an integer" : "a number");
    else
        snprintf(what, sizeof what, "%s[%lld] of %s %zu (%s)", p->name, item, e->name, rec,
                 type < T_F32 ? "an integer" : "a number");
    snprintf(tail, sizeof tail, " (element %s %zu in the header)", e->name, e->count);
    return lh__expected(r->s, LH_ERR_PARSE, &r->t, what, r->t.kind == LH__TOK_EOF ? tail : NULL);
}

/* Where a record's fault is: the token (ascii), none (binary: the record names it). */
static const lh__token *where(const ply *r, const lh__token *t)
{
    return r->format == F_ASCII ? t : NULL;
}

/* A vertex index of face rec, appended to r->idx. */
static lh_status face_index(ply *r, const ply_elem *e, size_t rec, long long v)
{
    if (v < 0 || (unsigned long long)v >= r->nv)
        return lh__plc_record_fail(
            r->s, LH_ERR_PARSE, where(r, &r->t), e->name, rec,
            "vertex index %lld is out of range (%zu vertices, numbered from 0)", v, r->nv);
    if (r->k == r->cap) { /* doubling: as long as the indices read so far */
        size_t cap = r->cap ? 2 * r->cap : 16;
        lh_status st = cap > (size_t)LH_INDEX_MAX ? LH_ERR_TOO_LARGE : LH_ERR_NOMEM;
        lh_index *idx = st == LH_ERR_NOMEM ? lh__alloc(&r->b->g->alloc_, cap * sizeof *idx) : NULL;
        if (!idx) return lh__plc_record_built(r->s, st, where(r, &r->t), e->name, rec);
        if (r->k) memcpy(idx, r->idx, r->k * sizeof *idx);
        lh__free(&r->b->g->alloc_, r->idx);
        r->idx = idx;
        r->cap = cap;
    }
    r->idx[r->k++] = (lh_index)v;
    return LH_OK;
}

/* One list property of record rec: its length, then its items. */
static lh_status list(ply *r, const ply_elem *e, size_t rec, const ply_prop *p)
{
    double x;
    long long len, v = 0;
    lh_status st = value(r, e, rec, p, p->count_type, -1, &x, &len);
    if (st != LH_OK) return st;
    if (len < 0)
        return lh__plc_record_fail(r->s, LH_ERR_PARSE, where(r, &r->t), e->name, rec,
                                   "the length of %s is %lld", p->name, len);
    for (long long i = 0; i < len; i++) {
        if ((st = value(r, e, rec, p, p->type, i, &x, &v)) != LH_OK) return st;
        if (p->role == R_INDICES && (st = face_index(r, e, rec, v)) != LH_OK) return st;
    }
    return LH_OK;
}

/* A coordinate: finite. */
static lh_status coordinate(ply *r, const ply_elem *e, size_t rec, const ply_prop *p, double *x)
{
    long long v;
    lh_status st = value(r, e, rec, p, p->type, -1, x, &v);
    if (st != LH_OK || isfinite(*x)) return st;
    if (r->format == F_ASCII) {
        char what[80];
        snprintf(what, sizeof what, "%s of %s %zu", p->name, e->name, rec);
        return lh__nonfinite(r->s, &r->t, what, "points");
    }
    return lh__plc_record_fail(r->s, LH_ERR_NONFINITE, NULL, e->name, rec,
                               "%s is %g: NaN and infinities are not points", p->name, *x);
}

/* What a record of a vertex or face element adds to the PLC. */
static lh_status add_record(ply *r, const ply_elem *e, size_t rec, const double xyz[3])
{
    size_t line = r->format == F_ASCII ? r->at.line : rec + 1;
    lh_status st = LH_OK;
    if (e->kind == E_VERTEX) st = lh__plc_point(r->b, xyz, NULL, 0, line);
    if (e->kind == E_FACE) {
        if (r->k < 3)
            return lh__plc_record_fail(r->s, LH_ERR_PARSE, where(r, &r->at), e->name, rec,
                                       "%zu vertices (a facet has at least 3)", r->k);
        st = lh__plc_facet(r->b, 0, line);
        if (st == LH_OK) st = lh__plc_polygon(r->b, r->idx, r->k);
    }
    return lh__plc_record_built(r->s, st, where(r, &r->at), e->name, rec);
}

static lh_status read_record(ply *r, const ply_elem *e, size_t rec)
{
    double xyz[3] = {0, 0, 0}, x;
    long long v;
    lh_status st = LH_OK;
    r->k = 0;
    r->at.kind = LH__TOK_EOF; /* no value read yet */
    for (size_t j = e->first; st == LH_OK && j < e->first + e->props; j++) {
        const ply_prop *p = &r->prop[j];
        if (p->list)
            st = list(r, e, rec, p);
        else if (p->role != R_SKIP)
            st = coordinate(r, e, rec, p, &xyz[p->role - R_X]);
        else
            st = value(r, e, rec, p, p->type, -1, &x, &v);
    }
    if (st == LH_OK && r->format == F_ASCII) {
        lh__scan_next(r->s, 0, &r->t);
        if (r->t.kind != LH__TOK_EOL && r->t.kind != LH__TOK_EOF) {
            char what[80];
            snprintf(what, sizeof what, "the end of the line after %s %zu", e->name, rec);
            return lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
        }
    }
    return st == LH_OK ? add_record(r, e, rec, xyz) : st;
}

/* An element lifthull does not use, in ascii: one line a record. */
static lh_status skip_ascii(ply *r, const ply_elem *e)
{
    for (size_t rec = 0; rec < e->count; rec++) {
        lh__scan_next(r->s, 1, &r->t);
        if (r->t.kind != LH__TOK_WORD) {
            char what[80], tail[64];
            snprintf(what, sizeof what, "%s %zu", e->name, rec);
            snprintf(tail, sizeof tail, " (element %s %zu in the header)", e->name, e->count);
            return lh__expected(r->s, LH_ERR_PARSE, &r->t, what,
                                r->t.kind == LH__TOK_EOF ? tail : NULL);
        }
        lh__scan_skip_line(r->s);
    }
    return LH_OK;
}

static lh_status read_body(ply *r)
{
    lh_status st = LH_OK;
    for (size_t i = 0; st == LH_OK && i < r->elems; i++) {
        const ply_elem *e = &r->elem[i];
        if (e->props == 0) continue; /* records of no bytes */
        if (e->kind == E_OTHER && r->format == F_ASCII) {
            st = skip_ascii(r, e);
            continue;
        }
        for (size_t rec = 0; st == LH_OK && rec < e->count; rec++) st = read_record(r, e, rec);
    }
    if (st != LH_OK) return st;
    if (r->format == F_ASCII) {
        lh__scan_next(r->s, 1, &r->t);
        if (r->t.kind == LH__TOK_EOF) return LH_OK;
        return lh__expected(r->s, LH_ERR_PARSE, &r->t,
                            "the end of the input after the last element", NULL);
    }
    if (r->s->c == EOF)
        return r->s->read_error ? lh__error_say(r->s->err, LH_ERR_IO, "%s: read error", r->s->name)
                                : LH_OK;
    return lh__error_say(r->s->err, LH_ERR_PARSE, "%s: the input goes on after the last element",
                         r->s->name);
}

lh_status lh__plc_read_ply(lh__scan *s, lh__plc_build *b)
{
    ply r;
    memset(&r, 0, sizeof r);
    r.s = s;
    r.b = b;
    lh_status st = read_header(&r);
    if (st == LH_OK) st = read_body(&r);
    lh__free(&b->g->alloc_, r.idx);
    return st;
}
