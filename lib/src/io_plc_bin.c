/* io_plc_bin.c — what the PLY and STL readers share (io_plc.h): raw bytes of binary
 * records, numbers in either byte order, and diagnostics that name the record. */
#include "io_plc.h"

#include <stdarg.h>
#include <string.h>

/* The scanner's invariant (io_internal.h): s->c, then pre[pre_pos..pre_len), then
 * block[block_pos..block_len), then the FILE. Once the read-ahead is used up the bytes
 * after s->c are taken from the block at once; lines and columns mean nothing in binary
 * records, so they are not kept. */
int lh__plc_bytes(lh__scan *s, unsigned char *buf, size_t k)
{
    size_t i = 0;
    while (i < k) {
        if (s->c == EOF) return 0;
        buf[i++] = (unsigned char)s->c;
        if (s->pre_pos == s->pre_len) {
            size_t m = s->block_len - s->block_pos;
            if (m > k - i) m = k - i;
            memcpy(buf + i, s->block + s->block_pos, m);
            s->block_pos += m;
            i += m;
        }
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
    return lh__error_say(s->err, st, "%s:%zu:%zu: %s %zu: %s", s->name, t->line, t->col, what, n,
                         text);
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
