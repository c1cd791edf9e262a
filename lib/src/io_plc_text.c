/*
 * io_plc_text.c — what the text PLC readers share (io_plc_text.h).
 */
#include "io_plc_text.h"

#include <math.h>
#include <stdint.h>

lh_status lh__plc_ring_push(lh__plc_build *b, lh__plc_ring *r, lh_index v)
{
    if (r->k == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 16;
        if (cap > (size_t)LH_INDEX_MAX || cap > SIZE_MAX / sizeof *r->v) return LH_ERR_TOO_LARGE;
        lh_index *fresh = lh__alloc(&b->g->alloc_, cap * sizeof *fresh);
        if (!fresh) return LH_ERR_NOMEM;
        for (size_t i = 0; i < r->k; i++) fresh[i] = r->v[i];
        lh__free(&b->g->alloc_, r->v);
        r->v = fresh;
        r->cap = cap;
    }
    r->v[r->k++] = v;
    return LH_OK;
}

void lh__plc_ring_free(lh__plc_build *b, lh__plc_ring *r)
{
    if (r->v) lh__free(&b->g->alloc_, r->v);
    r->v = NULL;
    r->k = r->cap = 0;
}

void lh__plc_item(char *buf, size_t cap, const char *kind, long long i)
{
    char d[24];
    const size_t k = lh__fmt_int(i, d);
    size_t n = 0;
    for (; kind[n] && n + 1 < cap; n++) buf[n] = kind[n];
    for (size_t j = 0; j < k && n + 1 < cap; j++) buf[n++] = d[j];
    buf[n] = '\0';
}

lh_status lh__plc_count_of(lh__scan *s, const lh__token *t, const char *prefix, const char *item,
                           long long lo, size_t *n)
{
    long long v;
    if (lh__word_integer(t, &v) && v >= lo && v <= LH_READ_MAX_POINTS) {
        *n = (size_t)v;
        return LH_OK;
    }
    char what[160];
    snprintf(what, sizeof what, "%.80s%.78s", prefix, item);
    return lh__plc_count(s, t, what, lo, n);
}

lh_status lh__plc_count(lh__scan *s, const lh__token *t, const char *what, long long lo,
                        size_t *n)
{
    long long v;
    const int ok = lh__word_integer(t, &v) && v >= lo;
    if (ok && v <= LH_READ_MAX_POINTS) {
        *n = (size_t)v;
        return LH_OK;
    }
    char w[256];
    snprintf(w, sizeof w, "%.180s (an integer from %lld to %lld)", what, lo,
             (long long)LH_READ_MAX_POINTS);
    if (!ok) return lh__expected(s, LH_ERR_PARSE, t, t->kind == LH__TOK_WORD ? w : what, NULL);
    return lh__expected(s, LH_ERR_TOO_LARGE, t, w, NULL);
}

lh_status lh__plc_vertex(lh__scan *s, const lh__token *t, int base, size_t n, size_t j,
                         const char *item, lh_index *v)
{
    long long k, hi = base + (long long)n - 1;
    if (lh__word_integer(t, &k) && (n ? k >= base && k <= hi : k >= 0 && k - base < LH_INDEX_MAX)) {
        *v = (lh_index)(k - base);
        return LH_OK;
    }
    char w[240];
    if (n)
        snprintf(w, sizeof w, "vertex %zu of %s (a vertex number from %d to %lld)", j, item, base,
                 hi);
    else
        snprintf(w, sizeof w, "vertex %zu of %s (a vertex number of the .node, from 0)", j, item);
    return lh__expected(s, LH_ERR_PARSE, t, w, NULL);
}

lh_status lh__plc_numbers(lh__scan *s, int from, int count, const char *field, const char *item,
                          const char *noun, double *x)
{
    lh__token t;
    for (int j = 0; j < count; j++) {
        lh__scan_next(s, 0, &t);
        if (lh__word_double(&t, &x[j]) && isfinite(x[j])) continue;
        char what[200];
        snprintf(what, sizeof what, "%s %d of %s", field, from + j, item);
        return lh__number(s, &t, what, noun, NULL, &x[j]);
    }
    return LH_OK;
}

lh_status lh__plc_integer(lh__scan *s, const lh__token *t, const char *what, lh_index *m)
{
    long long v;
    if (lh__word_integer(t, &v) && v >= -(long long)LH_INDEX_MAX - 1 && v <= (long long)LH_INDEX_MAX) {
        *m = (lh_index)v;
        return LH_OK;
    }
    char w[200];
    snprintf(w, sizeof w, "%s (an integer)", what);
    return lh__expected(s, LH_ERR_PARSE, t, w, NULL);
}

lh_status lh__plc_line_end(lh__scan *s, const char *item)
{
    lh__token t;
    lh__scan_next(s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    char what[200];
    snprintf(what, sizeof what, "the end of the line after %s", item);
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

lh_status lh__plc_input_end(lh__scan *s, const char *items)
{
    lh__token t;
    lh__scan_next(s, 1, &t);
    if (t.kind == LH__TOK_EOF) return LH_OK;
    char what[200];
    snprintf(what, sizeof what, "the end of the input after %s", items);
    return lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
}

lh_status lh__plc_built(lh__scan *s, lh_status st, const lh__token *at, const char *item)
{
    if (st == LH_OK) return LH_OK;
    char text[200];
    snprintf(text, sizeof text, "%s for %s",
             st == LH_ERR_NOMEM ? "out of memory" : "out of address space", item);
    return lh__fail_at(s, st, at, text);
}
