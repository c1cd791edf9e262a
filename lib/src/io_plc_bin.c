/* io_plc_bin.c — what the PLY and STL readers share (io_plc.h): raw bytes of binary
 * records, numbers in either byte order, and diagnostics that name the record. */
#include "io_plc.h"

#include <stdarg.h>
#include <string.h>

int lh__plc_bytes(lh__scan *s, unsigned char *buf, size_t k)
{
    for (size_t i = 0; i < k; i++) {
        if (s->c == EOF) return 0;
        buf[i] = (unsigned char)s->c;
        lh__scan_advance(s);
    }
    return 1;
}

uint64_t lh__plc_unpack(const unsigned char *buf, size_t k, int big_endian)
{
    uint64_t u = 0;
    for (size_t i = 0; i < k; i++) u = u << 8 | buf[big_endian ? i : k - 1 - i];
    return u;
}

double lh__plc_float32(uint64_t bits)
{
    uint32_t w = (uint32_t)bits;
    float f;
    memcpy(&f, &w, sizeof f);
    return (double)f;
}

lh_status lh__plc_record_fail(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                              size_t n, const char *fmt, ...)
{
    char text[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (!s->err) return st;
    if (!t) return lh__error_say(s->err, st, "%s: %s %zu: %s", s->name, what, n, text);
    s->err->line = t->line;
    s->err->column = t->col;
    return lh__error_say(s->err, st, "%s:%zu:%zu: %s %zu: %s", s->name, t->line, t->col, what,
                         n, text);
}

lh_status lh__plc_record_end(lh__scan *s, const lh__token *t, const char *what, size_t n,
                             size_t declared, const char *plural)
{
    if (s->read_error) return lh__plc_record_fail(s, LH_ERR_IO, t, what, n, "read error");
    return lh__plc_record_fail(s, LH_ERR_PARSE, t, what, n, "the input ends (%zu %s declared)",
                               declared, plural);
}

lh_status lh__plc_record_built(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                               size_t n)
{
    if (st == LH_ERR_NOMEM) return lh__plc_record_fail(s, st, t, what, n, "out of memory");
    if (st == LH_ERR_TOO_LARGE)
        return lh__plc_record_fail(s, st, t, what, n, "more items than lh_index numbers");
    return st;
}
