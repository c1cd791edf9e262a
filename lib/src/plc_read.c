/*
 * plc_read.c — lh_plc_read: opens the scanner, picks the format and hands over to
 * its reader (io_plc.h); lh_plc_take_points; the formats' names.
 */
#include "io_plc.h"

#include <string.h>
#include <strings.h>

const char *lh_plc_format_name(lh_plc_format format)
{
    static const char *const names[] = {"auto", "poly", "smesh", "node", "off",
                                        "ply",  "stl",  "medit", "obj"};
    if ((unsigned)format >= sizeof names / sizeof names[0]) return "unknown";
    return names[format];
}

static int ends_with(const char *name, const char *ext)
{
    size_t n = strlen(name), e = strlen(ext);
    return n > e && strcasecmp(name + n - e, ext) == 0;
}

static int starts_with(const unsigned char *head, size_t len, const char *word)
{
    size_t w = strlen(word);
    return len >= w && strncasecmp((const char *)head, word, w) == 0;
}

lh_plc_format lh__plc_detect(const char *name, const unsigned char *head, size_t len)
{
    static const struct {
        const char *ext;
        lh_plc_format f;
    } by_ext[] = {{".poly", LH_PLC_POLY},  {".smesh", LH_PLC_SMESH}, {".node", LH_PLC_NODE},
                  {".off", LH_PLC_OFF},    {".ply", LH_PLC_PLY},     {".stl", LH_PLC_STL},
                  {".mesh", LH_PLC_MEDIT}, {".obj", LH_PLC_OBJ}};
    for (size_t i = 0; name && i < sizeof by_ext / sizeof by_ext[0]; i++)
        if (ends_with(name, by_ext[i].ext)) return by_ext[i].f;
    if (starts_with(head, len, "ply")) return LH_PLC_PLY;
    /* ASCII STL starts "solid", and so may a binary one's 80-byte header: the reader
       tells them apart (io_plc_stl.c). */
    if (starts_with(head, len, "solid")) return LH_PLC_STL;
    if (starts_with(head, len, "MeshVersionFormatted")) return LH_PLC_MEDIT;
    /* Binary STL (any header): its count and records hold NULs, which no text has. */
    if (memchr(head, 0, len)) return LH_PLC_STL;
    for (size_t i = 0; i + 1 < len; i++) {
        if ((i == 0 || head[i - 1] == '\n') && (head[i] == 'v' || head[i] == 'f') &&
            (head[i + 1] == ' ' || head[i + 1] == '\t'))
            return LH_PLC_OBJ;
    }
    return LH_PLC_OFF;
}

static lh_status read_format(lh__scan *s, lh__plc_build *b, lh_plc_format format)
{
    switch (format) {
    case LH_PLC_POLY: return lh__plc_read_poly(s, b, 0);
    case LH_PLC_SMESH: return lh__plc_read_poly(s, b, 1);
    case LH_PLC_NODE: return lh__plc_read_node(s, b);
    case LH_PLC_OFF: return lh__plc_read_off(s, b);
    case LH_PLC_PLY: return lh__plc_read_ply(s, b);
    case LH_PLC_STL: return lh__plc_read_stl(s, b);
    case LH_PLC_MEDIT: return lh__plc_read_medit(s, b);
    case LH_PLC_OBJ: return lh__plc_read_obj(s, b);
    default: return LH_ERR_INVALID_ARGUMENT;
    }
}

lh_status lh_plc_read(FILE *f, const char *name, lh_plc_format format, const lh_allocator *alloc,
                      lh_plc *out, lh_error *err)
{
    lh__error_clear(err);
    lh__plc_build b;
    lh_status st = lh__plc_build_init(&b, out, alloc);
    if (st == LH_OK && (!f || (unsigned)format > LH_PLC_OBJ)) st = LH_ERR_INVALID_ARGUMENT;
    if (st != LH_OK) {
        if (out) lh_plc_free(out);
        return lh__error_done(err, st);
    }
    const char *shown = name ? name : "<input>";
    lh__scan *s = lh__scan_open(f, LH__IO_PREFIX, &out->alloc_, shown, err);
    if (!s) {
        lh__plc_build_fail(&b);
        return lh__error_done(err, LH_ERR_NOMEM);
    }
    if (format == LH_PLC_AUTO) format = lh__plc_detect(name, s->pre, s->pre_len);
    st = read_format(s, &b, format);
    if (st == LH_OK) st = lh__plc_build_done(&b);
    if (st == LH_ERR_NOMEM && err && !err->message[0])
        lh__error_say(err, st, "%s: out of memory", shown);
    lh__scan_close(s);
    if (st != LH_OK) lh__plc_build_fail(&b);
    return lh__error_done(err, st);
}

lh_status lh_plc_take_points(lh_plc *g, lh_points *p)
{
    if (!g || !p || p->d != 3 || p->n == 0 || !p->xyz || g->n || g->xyz || g->attr ||
        g->point_marker || g->point_line || g->alloc_.alloc != p->alloc_.alloc ||
        g->alloc_.free != p->alloc_.free || g->alloc_.user != p->alloc_.user)
        return LH_ERR_INVALID_ARGUMENT;
    /* The facets were read against g's base; TetGen numbers them as the .node. */
    lh_index shift = (lh_index)(g->first_index - p->first_index);
    size_t nv = g->polygon_count ? (size_t)g->polygon_first[g->polygon_count] : 0;
    for (size_t i = 0; shift && i < nv; i++) g->polygon_vertices[i] += shift;
    for (size_t i = 0; shift && i < 2 * g->segment_count; i++) g->segments[i] += shift;
    g->first_index = p->first_index;
    g->n = p->n;
    g->xyz = p->xyz;
    g->attr_count = p->attr_count;
    g->attr = p->attr;
    g->point_marker = p->marker;
    memset(p, 0, sizeof *p);
    return LH_OK;
}
