/*
 * io_pslg.h — what the PSLG readers share (lifthull.h, "2D meshing"): io_poly.c
 * (Triangle's .poly, and lh_pslg_take_points / lh_pslg_free) and io_rings.c (JSON
 * rings). Both scan with io_scan.c and write its one-line diagnostics.
 */
#ifndef LH_IO_PSLG_H
#define LH_IO_PSLG_H

#include "io_internal.h"

/* One array of a table of items (vertices, segments, ...): *arr holds `bytes` bytes an
 * item; bytes 0: the array is not kept. */
typedef struct lh__pslg_col {
    void **arr;
    size_t bytes;
} lh__pslg_col;

/* Room for one more item in every column when `count` are held and *cap fit: the
 * capacity doubles from 64, capped by the declared count (0: unknown), which is never
 * trusted for one large allocation. On failure the columns are as they were and
 * "out of memory for NOUN NUMBER" (LH_ERR_NOMEM) or "out of address space for ..."
 * (LH_ERR_TOO_LARGE) is written at `at`. */
lh_status lh__pslg_room(lh__scan *s, const lh_allocator *a, const lh__pslg_col *cols,
                        int ncols, size_t count, size_t declared, size_t *cap,
                        const lh__token *at, const char *noun, long long number);

/* The readers' start: *out zeroed with its allocator hooks. Returns
 * LH_ERR_INVALID_ARGUMENT for a NULL f or out or hooks without alloc or free. */
lh_status lh__pslg_start(FILE *f, const lh_allocator *alloc, lh_pslg *out);

/* A scanner on f with out's allocator (lh__scan_open): the first LH__PSLG_PRE bytes
 * are read ahead so that a UTF-8 BOM is skipped. NULL when out of memory: then out
 * is freed (lh_pslg_free) and err says so. */
#define LH__PSLG_PRE 3
lh__scan *lh__pslg_scan_open(FILE *f, lh_pslg *out, const char *name, lh_error *err);

#endif
