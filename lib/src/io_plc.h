/*
 * io_plc.h — what the PLC readers share (lh_plc_read, lifthull.h): a builder that
 * grows an lh_plc item by item, and each format's reader.
 *
 * Builder invariant: b->g's arrays hold the items added so far; facet_first,
 * polygon_first and facet_hole_first are closed (their last offset written) only by
 * lh__plc_build_done. Markers are always kept (0 when the format has none) and every
 * item's line (binary formats: its record number) too. On any failure the reader
 * calls lh__plc_build_fail, which frees everything and zeroes the lh_plc.
 */
#ifndef LH_IO_PLC_H
#define LH_IO_PLC_H

#include "io_internal.h"

#include <stdint.h>

typedef struct lh__plc_build {
    lh_plc *g;
    size_t cap_points, cap_facets, cap_polygons, cap_vertices, cap_facet_holes;
    size_t cap_segments, cap_holes, cap_regions;
    size_t facet_holes; /* facet hole points so far (g has no count for them) */
    size_t vertices;    /* polygon vertices so far                           */
    int facet_open;     /* a facet was begun: polygons go to it              */
} lh__plc_build;

/* Starts an empty lh_plc in g with the allocator (NULL: malloc/free). LH_OK or
 * LH_ERR_INVALID_ARGUMENT (g NULL, an allocator without hooks). */
lh_status lh__plc_build_init(lh__plc_build *b, lh_plc *g, const lh_allocator *alloc);
/* Appends a point (attr: g->attr_count values, or NULL when attr_count is 0). */
lh_status lh__plc_point(lh__plc_build *b, const double xyz[3], const double *attr, lh_index marker,
                        size_t line);
/* Begins a facet; the polygons and facet holes added next belong to it. */
lh_status lh__plc_facet(lh__plc_build *b, lh_index marker, size_t line);
/* Appends a polygon of k >= 1 vertices (0-based point indices) to the open facet. */
lh_status lh__plc_polygon(lh__plc_build *b, const lh_index *v, size_t k);
/* Appends a hole point to the open facet. */
lh_status lh__plc_facet_hole(lh__plc_build *b, const double xyz[3]);
lh_status lh__plc_segment(lh__plc_build *b, lh_index p, lh_index q, lh_index marker, size_t line);
lh_status lh__plc_hole(lh__plc_build *b, const double xyz[3], size_t line);
/* A region: x y z attribute max_volume. */
lh_status lh__plc_region(lh__plc_build *b, const double r[5], size_t line);
/* Closes the offset arrays. LH_OK or LH_ERR_NOMEM. */
lh_status lh__plc_build_done(lh__plc_build *b);
/* Frees everything added and zeroes g. */
void lh__plc_build_fail(lh__plc_build *b);

/* The readers: each reads s to its end into b (and may set b->g->first_index). */
lh_status lh__plc_read_poly(lh__scan *s, lh__plc_build *b, int smesh);
lh_status lh__plc_read_node(lh__scan *s, lh__plc_build *b);
lh_status lh__plc_read_off(lh__scan *s, lh__plc_build *b);
lh_status lh__plc_read_ply(lh__scan *s, lh__plc_build *b);
lh_status lh__plc_read_stl(lh__scan *s, lh__plc_build *b);
lh_status lh__plc_read_medit(lh__scan *s, lh__plc_build *b);
lh_status lh__plc_read_obj(lh__scan *s, lh__plc_build *b);

/* Binary records (io_plc_bin.c). Copies the next k bytes of s into buf: 1, or 0 when
 * the input ends first (s->read_error tells a read error). */
int lh__plc_bytes(lh__scan *s, unsigned char *buf, size_t k);
/* buf[0..k) (k <= 8) as an unsigned integer in the given byte order. */
uint64_t lh__plc_unpack(const unsigned char *buf, size_t k, int big_endian);
/* The float32 of IEEE 754 bits (the low 32 of bits) as a double. */
double lh__plc_float32(uint64_t bits);
/* Writes "NAME:LINE:COL: WHAT N: TEXT" (at t; t NULL, a binary record: "NAME: WHAT N:
 * TEXT") into s->err and returns st. */
lh_status lh__plc_record_fail(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                              size_t n, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;
/* The input ended inside record N: "...: WHAT N: the input ends (D PLURAL declared)"
 * (LH_ERR_PARSE), or "read error" (LH_ERR_IO). */
lh_status lh__plc_record_end(lh__scan *s, const lh__token *t, const char *what, size_t n,
                             size_t declared, const char *plural);
/* A builder failure st (LH_ERR_NOMEM, LH_ERR_TOO_LARGE) named after record N. */
lh_status lh__plc_record_built(lh__scan *s, lh_status st, const lh__token *t, const char *what,
                               size_t n);

/* The format of name's extension (case-insensitive), else of the first bytes
 * head[0..len); LH_PLC_OFF when nothing tells. */
lh_plc_format lh__plc_detect(const char *name, const unsigned char *head, size_t len);

#endif
