/* io_points.c — lh_points_read: the prefix, the choice of format, the reader; the
 * growing arrays of lh_points (lifthull.h, "file formats"). */
#include "io_internal.h"

#include <stdint.h>
#include <string.h>

#define INITIAL_POINTS 256

const char *lh_format_name(lh_format format)
{
    switch (format) {
    case LH_FORMAT_AUTO: return "auto";
    case LH_FORMAT_QHULL: return "qhull";
    case LH_FORMAT_NODE: return "node";
    case LH_FORMAT_COLUMNS: return "columns";
    }
    return "unknown";
}

void lh_points_free(lh_points *p)
{
    if (!p) return;
    if (p->alloc_.free) {
        lh__free(&p->alloc_, p->xyz);
        lh__free(&p->alloc_, p->attr);
        lh__free(&p->alloc_, p->marker);
    }
    memset(p, 0, sizeof *p);
}

/* Moves the first n items of *old (item bytes each) into a new block of cap items. */
static void *move(const lh_allocator *a, void *old, size_t n, size_t cap, size_t item)
{
    void *fresh = lh__alloc(a, cap * item);
    if (fresh && n) memcpy(fresh, old, n * item);
    return fresh;
}

/* Capacity for at least `need` points: doubling, capped by the declared count (a
 * count is a hint, never trusted for one large allocation up front). */
static lh_status grow(lh__builder *b, size_t need)
{
    lh_points *p = b->p;
    size_t cap = b->cap ? 2 * b->cap : INITIAL_POINTS;
    if (b->expected && cap > b->expected) cap = b->expected;
    if (cap < need) cap = need;
    if (cap > LH_READ_MAX_POINTS) cap = LH_READ_MAX_POINTS;
    size_t per = (size_t)p->d + (size_t)p->attr_count;
    if (cap > SIZE_MAX / sizeof(double) / per) return LH_ERR_TOO_LARGE;
    double *xyz = move(b->a, p->xyz, p->n * (size_t)p->d, cap * (size_t)p->d, sizeof *xyz);
    double *attr = p->attr_count ? move(b->a, p->attr, p->n * (size_t)p->attr_count,
                                        cap * (size_t)p->attr_count, sizeof *attr)
                                 : NULL;
    lh_index *marker = b->markers ? move(b->a, p->marker, p->n, cap, sizeof *marker) : NULL;
    if (!xyz || (p->attr_count && !attr) || (b->markers && !marker)) {
        lh__free(b->a, xyz);
        lh__free(b->a, attr);
        lh__free(b->a, marker);
        return LH_ERR_NOMEM;
    }
    lh__free(b->a, p->xyz);
    lh__free(b->a, p->attr);
    lh__free(b->a, p->marker);
    p->xyz = xyz;
    p->attr = attr;
    p->marker = marker;
    b->cap = cap;
    return LH_OK;
}

lh_status lh__push(lh__scan *s, lh__builder *b, const lh__token *at, const double *xyz,
                   const double *attr, lh_index marker)
{
    lh_points *p = b->p;
    if (p->n == LH_READ_MAX_POINTS) {
        char what[100];
        snprintf(what, sizeof what, "the end of the input after %" LH_INDEX_PRI
                 " points (the most lifthull reads)", LH_READ_MAX_POINTS);
        return lh__expected(s, LH_ERR_TOO_LARGE, at, what, NULL);
    }
    if (p->n == b->cap) {
        lh_status st = grow(b, p->n + 1);
        if (st != LH_OK) {
            char text[160];
            snprintf(text, sizeof text, "%s for point %zu",
                     st == LH_ERR_NOMEM ? "out of memory" : "out of address space", p->n + 1);
            return lh__fail_at(s, st, at, text);
        }
    }
    memcpy(p->xyz + p->n * (size_t)p->d, xyz, (size_t)p->d * sizeof *xyz);
    if (p->attr_count)
        memcpy(p->attr + p->n * (size_t)p->attr_count, attr,
               (size_t)p->attr_count * sizeof *attr);
    if (b->markers) p->marker[p->n] = marker;
    p->n++;
    return LH_OK;
}

static lh_status read_points(FILE *f, const char *name, lh_format format, const lh_allocator *alloc,
                             lh_points *out, lh_error *err)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (!f || format < LH_FORMAT_AUTO || format > LH_FORMAT_COLUMNS) return LH_ERR_INVALID_ARGUMENT;
    if (!lh__allocator_init(&out->alloc_, alloc)) return LH_ERR_INVALID_ARGUMENT;
    if (!name) name = "<input>";
    lh__scan *s = lh__scan_open(f, LH__IO_PREFIX, &out->alloc_, name, err);
    if (!s) {
        lh_points_free(out);
        return LH_ERR_NOMEM;
    }
    if (format == LH_FORMAT_AUTO)
        format = lh__format_detect(name, s->head, s->pre_len, s->pre_len < LH__IO_PREFIX);
    out->format = format;
    lh__builder b = {out, &out->alloc_, 0, 0, 0};
    lh_status st = format == LH_FORMAT_QHULL  ? lh__read_qhull(s, &b)
                   : format == LH_FORMAT_NODE ? lh__read_node(s, &b)
                                              : lh__read_columns(s, &b);
    lh__scan_close(s);
    if (st != LH_OK) lh_points_free(out);
    return st;
}

lh_status lh_points_read(FILE *f, const char *name, lh_format format, const lh_allocator *alloc,
                         lh_points *out, lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, read_points(f, name, format, alloc, out, err));
}
