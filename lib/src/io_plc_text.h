/*
 * io_plc_text.h — what the text PLC readers share (io_plc_off.c, io_plc_poly.c,
 * io_plc_medit.c, io_plc_obj.c): counts, vertex numbers, numbers of an item's line,
 * the end of a line or of the input, the builder's failures as diagnostics, and a
 * growing list of one polygon's vertices. Every message is io_scan.c's one line
 * "NAME:LINE:COL: expected WHAT, found ...".
 */
#ifndef LH_IO_PLC_TEXT_H
#define LH_IO_PLC_TEXT_H

#include "io_plc.h"

/* The vertices of the polygon being read, grown as they are read (a declared vertex
 * count is never trusted for an allocation). Zero-initialise; free with
 * lh__plc_ring_free. */
typedef struct lh__plc_ring {
    lh_index *v;
    size_t k, cap;
} lh__plc_ring;

lh_status lh__plc_ring_push(lh__plc_build *b, lh__plc_ring *r, lh_index v);
void lh__plc_ring_free(lh__plc_build *b, lh__plc_ring *r);

/* Token t as a count from lo to LH_READ_MAX_POINTS: "expected WHAT (an integer from
 * LO to MAX), found ..." (LH_ERR_TOO_LARGE above MAX). */
lh_status lh__plc_count(lh__scan *s, const lh__token *t, const char *what, long long lo,
                        size_t *n);
/* lh__plc_count with WHAT = PREFIX ITEM, formatted only when it reports. */
lh_status lh__plc_count_of(lh__scan *s, const lh__token *t, const char *prefix, const char *item,
                           long long lo, size_t *n);
/* "KIND I" into buf (cap bytes, truncated, NUL-terminated): an item's name, as
 * snprintf's "%s%lld" would write it, at a fraction of its cost per item. */
void lh__plc_item(char *buf, size_t cap, const char *kind, long long i);
/* Token t as vertex j (from 1) of ITEM, a vertex number from base to base+n-1, stored
 * 0-based in *v: "expected vertex J of ITEM (a vertex number from LO to HI), found
 * ...". n == 0 (a .poly whose points are in its .node): any number from 0, stored
 * less base. */
lh_status lh__plc_vertex(lh__scan *s, const lh__token *t, int base, size_t n, size_t j,
                         const char *item, lh_index *v);
/* `count` numbers of the current line into x, each named "FIELD j of ITEM" (j from
 * `from`); noun for lh__nonfinite ("points", "accepted"). */
lh_status lh__plc_numbers(lh__scan *s, int from, int count, const char *field, const char *item,
                          const char *noun, double *x);
/* Token t as an integer that fits an lh_index (a marker, a reference) into *m:
 * "expected WHAT (an integer), found ...". */
lh_status lh__plc_integer(lh__scan *s, const lh__token *t, const char *what, lh_index *m);
/* The end of the line or of the input next: "expected the end of the line after
 * ITEM, found ...". */
lh_status lh__plc_line_end(lh__scan *s, const char *item);
/* The end of the input next: "expected the end of the input after ITEMS, found ...". */
lh_status lh__plc_input_end(lh__scan *s, const char *items);
/* A builder's failure st (LH_ERR_NOMEM, LH_ERR_TOO_LARGE) as "out of memory for ITEM"
 * ("out of address space for ITEM") at `at`; LH_OK stays LH_OK. */
lh_status lh__plc_built(lh__scan *s, lh_status st, const lh__token *at, const char *item);

#endif
