/* io_plc_stl.c — STL files (3D Systems, "StereoLithography Interface Specification",
 * 1989) as lh_plc_read reads them.
 *
 * ascii (keywords in any case, separated by any blanks and line ends):
 *
 *     solid [NAME]                        the rest of the line is the name
 *     facet normal NX NY NZ               the normal is read (any numbers) and not used
 *       outer loop
 *         vertex X Y Z                    three times; finite numbers
 *       endloop
 *     endfacet                            ... one facet a triangle
 *     endsolid [NAME]                     the rest of the line; another solid may follow
 *
 * binary: an 80-byte header (any bytes), the triangle count (uint32), then that many
 * 50-byte records: the normal (3 float32, not used), 3 corners (3 float32 each), an
 * attribute (uint16, not used); little-endian; nothing after the last record.
 *
 * A file is binary unless it starts "solid" (in any case, after a UTF-8 BOM). One that
 * does is binary still when its length is known (it is shorter than the 4 KiB the
 * scanner reads ahead, so a pipe works too) and is 84 + 50 * count bytes, or when
 * those bytes hold a NUL or, after the first line (the name may be UTF-8), a byte that
 * is not text: an ascii STL has neither, a binary one has NULs in its count and
 * attributes and bytes above 0x7e in its floats.
 *
 * STL repeats each corner in every triangle: corners with the same coordinates (as
 * doubles; -0.0 and 0.0 are one, kept as 0.0) are merged exactly, with a hash table,
 * into one point, numbered in the order of first appearance; each triangle is a facet
 * of one polygon (marker 0). A triangle with two equal corners is kept as read: it is
 * the mesher's to report. Triangles are numbered from 1 in messages ("NAME:LINE:COL:
 * ..." in ascii, "NAME: triangle 5: ..." in binary); point_line and facet_line hold
 * the line (ascii) or the triangle's number (binary). A file of no triangle is an
 * error.
 */
#include "io_plc.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include <strings.h>

typedef struct stl {
    lh__scan *s;
    lh__plc_build *b;
    lh_index *table; /* open addressing: point + 1, 0 when free; cap a power of 2 */
    size_t cap;
    lh__token t;
} stl;

/* ---- merging corners -------------------------------------------------------------- */

static size_t hash(const double xyz[3])
{
    uint64_t h = 0x243F6A8885A308D3u;
    for (int i = 0; i < 3; i++) {
        uint64_t u;
        memcpy(&u, &xyz[i], sizeof u);
        h = (h ^ u) * 0x9E3779B97F4A7C15u; /* Fibonacci hashing (Knuth, TAOCP 6.4) */
        h ^= h >> 29;
    }
    return (size_t)h;
}

/* The slot of xyz in table: its point's, or the free one where it would go. */
static size_t slot(const stl *r, const double xyz[3])
{
    const double *p = r->b->g->xyz;
    size_t h = hash(xyz) & (r->cap - 1);
    for (; r->table[h]; h = (h + 1) & (r->cap - 1)) {
        const double *q = p + 3 * (size_t)(r->table[h] - 1);
        if (q[0] == xyz[0] && q[1] == xyz[1] && q[2] == xyz[2]) break;
    }
    return h;
}

/* Doubles the table (load kept at most 1/2). */
static lh_status rehash(stl *r)
{
    const lh_allocator *a = &r->b->g->alloc_;
    size_t cap = r->cap ? 2 * r->cap : 1024;
    if (cap > SIZE_MAX / sizeof *r->table) return LH_ERR_TOO_LARGE;
    lh_index *old = r->table;
    size_t old_cap = r->cap;
    r->table = lh__alloc(a, cap * sizeof *r->table);
    if (!r->table) {
        r->table = old;
        return LH_ERR_NOMEM;
    }
    memset(r->table, 0, cap * sizeof *r->table);
    r->cap = cap;
    for (size_t i = 0; i < old_cap; i++)
        if (old[i]) r->table[slot(r, r->b->g->xyz + 3 * (size_t)(old[i] - 1))] = old[i];
    lh__free(a, old);
    return LH_OK;
}

/* The point of corner xyz (finite): an earlier one with the same coordinates, or a new
 * one read at line. */
static lh_status corner(stl *r, double xyz[3], size_t line, lh_index *v)
{
    lh_plc *g = r->b->g;
    for (int i = 0; i < 3; i++)
        if (xyz[i] == 0) xyz[i] = 0; /* -0.0 is 0.0 */
    lh_status st = 2 * (g->n + 1) > r->cap ? rehash(r) : LH_OK;
    if (st != LH_OK) return st;
    size_t h = slot(r, xyz);
    if (r->table[h]) {
        *v = r->table[h] - 1;
        return LH_OK;
    }
    if (g->n >= LH_READ_MAX_POINTS) return LH_ERR_TOO_LARGE;
    if ((st = lh__plc_point(r->b, xyz, NULL, 0, line)) != LH_OK) return st;
    *v = (lh_index)(g->n - 1);
    r->table[h] = (lh_index)g->n;
    return LH_OK;
}

/* Triangle number n (from 1) of corners c, read at line (t: its token, NULL binary). */
static lh_status triangle(stl *r, double c[9], size_t n, size_t line, const lh__token *t)
{
    lh_index v[3];
    lh_status st = LH_OK;
    for (int k = 0; k < 3 && st == LH_OK; k++) st = corner(r, c + 3 * k, line, &v[k]);
    if (st == LH_OK) st = lh__plc_facet(r->b, 0, line);
    if (st == LH_OK) st = lh__plc_polygon(r->b, v, 3);
    return st == LH_OK ? LH_OK : lh__plc_record_built(r->s, st, t, "triangle", n);
}

/* ---- ascii ------------------------------------------------------------------------ */

static int is_key(const lh__token *t, const char *w)
{
    return t->kind == LH__TOK_WORD && strcasecmp(t->text, w) == 0;
}

static lh_status keyword(stl *r, const char *w, size_t n)
{
    char what[80];
    lh__scan_next(r->s, 1, &r->t);
    if (is_key(&r->t, w)) return LH_OK;
    snprintf(what, sizeof what, "'%s' (triangle %zu)", w, n);
    return lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
}

/* "facet" read: the rest of triangle n. */
static lh_status ascii_facet(stl *r, size_t n)
{
    static const char axis[] = "xyz";
    char what[80];
    double c[9], x;
    lh__token at = r->t; /* "facet" */
    lh_status st = keyword(r, "normal", n);
    for (int i = 0; i < 3 && st == LH_OK; i++) {
        lh__scan_next(r->s, 1, &r->t);
        snprintf(what, sizeof what, "the normal's %c of triangle %zu (a number)", axis[i], n);
        if (!lh__word_double(&r->t, &x)) st = lh__expected(r->s, LH_ERR_PARSE, &r->t, what, NULL);
    }
    if (st == LH_OK) st = keyword(r, "outer", n);
    if (st == LH_OK) st = keyword(r, "loop", n);
    for (int k = 0; k < 3 && st == LH_OK; k++) {
        st = keyword(r, "vertex", n);
        for (int i = 0; i < 3 && st == LH_OK; i++) {
            lh__scan_next(r->s, 1, &r->t);
            snprintf(what, sizeof what, "%c of corner %d of triangle %zu", axis[i], k + 1, n);
            st = lh__number(r->s, &r->t, what, "points", NULL, &c[3 * k + i]);
        }
    }
    if (st == LH_OK) st = keyword(r, "endloop", n);
    if (st == LH_OK) st = keyword(r, "endfacet", n);
    return st == LH_OK ? triangle(r, c, n, at.line, &at) : st;
}

static lh_status read_ascii(stl *r)
{
    size_t n = 0;
    lh__scan_next(r->s, 1, &r->t); /* "solid", which chose ascii */
    lh__scan_skip_line(r->s);
    for (;;) {
        lh__scan_next(r->s, 1, &r->t);
        if (is_key(&r->t, "facet")) {
            lh_status st = ascii_facet(r, ++n);
            if (st != LH_OK) return st;
        } else if (is_key(&r->t, "endsolid")) {
            lh__scan_skip_line(r->s);
            lh__scan_next(r->s, 1, &r->t);
            if (r->t.kind == LH__TOK_EOF) break;
            if (!is_key(&r->t, "solid"))
                return lh__expected(r->s, LH_ERR_PARSE, &r->t,
                                    "the end of the input or 'solid' after 'endsolid'", NULL);
            lh__scan_skip_line(r->s);
        } else {
            return lh__expected(r->s, LH_ERR_PARSE, &r->t, "'facet' or 'endsolid'", NULL);
        }
    }
    if (n) return LH_OK;
    return lh__fail_at(r->s, LH_ERR_PARSE, &r->t, "no triangle in the file");
}

/* ---- binary ----------------------------------------------------------------------- */

static lh_status read_binary(stl *r, size_t bom)
{
    lh__scan *s = r->s;
    unsigned char rec[80];
    if (!lh__plc_bytes(s, rec, 80 - bom) || !lh__plc_bytes(s, rec, 4))
        return s->read_error ? lh__error_say(s->err, LH_ERR_IO, "%s: read error", s->name)
                             : lh__error_say(s->err, LH_ERR_PARSE,
                                             "%s: the input ends inside the 84-byte header of a "
                                             "binary STL file",
                                             s->name);
    size_t count = (size_t)lh__plc_unpack(rec, 4, 0);
    if (count == 0)
        return lh__error_say(s->err, LH_ERR_PARSE, "%s: no triangle in the file", s->name);
    for (size_t n = 1; n <= count; n++) {
        double c[9];
        if (!lh__plc_bytes(s, rec, 50))
            return lh__plc_record_end(s, NULL, "triangle", n, count, "triangles");
        for (int i = 0; i < 9; i++) {
            c[i] = lh__plc_float32(lh__plc_unpack(rec + 12 + 4 * i, 4, 0));
            if (!isfinite(c[i]))
                return lh__plc_record_fail(s, LH_ERR_NONFINITE, NULL, "triangle", n,
                                           "%c of corner %d is %g: NaN and infinities are not "
                                           "points",
                                           "xyz"[i % 3], i / 3 + 1, c[i]);
        }
        lh_status st = triangle(r, c, n, n, NULL);
        if (st != LH_OK) return st;
    }
    if (s->c == EOF) return LH_OK;
    return lh__error_say(s->err, LH_ERR_PARSE,
                         "%s: the input goes on after triangle %zu, the last declared", s->name,
                         count);
}

/* Whether the input, starting "solid" or not, is binary (the rule above). */
static int is_binary(const lh__scan *s, size_t bom)
{
    const unsigned char *p = s->pre + bom;
    size_t len = s->pre_len - bom;
    if (len < 5 || strncasecmp((const char *)p, "solid", 5) != 0) return 1;
    if (s->pre_len < LH__IO_PREFIX && s->pre_len >= 84 &&
        s->pre_len - 84 == 50 * lh__plc_unpack(s->pre + 80, 4, 0))
        return 1;
    if (memchr(p, 0, len)) return 1;
    const unsigned char *eol = memchr(p, '\n', len);
    for (size_t i = eol ? (size_t)(eol - p) : len; i < len; i++)
        if (!lh__is_text(p[i])) return 1;
    return 0;
}

lh_status lh__plc_read_stl(lh__scan *s, lh__plc_build *b)
{
    stl r;
    memset(&r, 0, sizeof r);
    r.s = s;
    r.b = b;
    size_t bom = s->pre_len >= 3 && memcmp(s->pre, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    lh_status st = is_binary(s, bom) ? read_binary(&r, bom) : read_ascii(&r);
    lh__free(&b->g->alloc_, r.table);
    return st;
}
