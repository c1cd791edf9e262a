/* io_pslg_test.h — helpers of the PSLG reader tests (test_io_poly*.c, test_io_rings.c,
 * test_io_pslg_memory.c): reading a text or a data file with a reader, the invariants
 * of every reader's output, tables of bad inputs with their exact messages. */
#ifndef LH_IO_PSLG_TEST_H
#define LH_IO_PSLG_TEST_H

#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

/* Input text with its length, so that NUL bytes can be part of it. */
#define TEXT(s) s, sizeof(s) - 1

typedef lh_status (*reader)(FILE *, const char *, const lh_allocator *, lh_pslg *, lh_error *);

/* text[0..len) read by rd as the file `name`; msg (size bytes, may be NULL) receives
 * the reader's lh_error message. LH_ERR_INTERNAL if the lh_error's status is not the
 * returned one. */
lh_status read_text(reader rd, const char *name, const char *text, size_t len,
                    const lh_allocator *a, lh_pslg *g, char *msg, size_t size);
#ifdef LH_TEST_DATA_DIR
/* tests/data/path read by rd, as read_text; LH_ERR_IO when it cannot be opened. */
lh_status read_file(reader rd, const char *path, const lh_allocator *a, lh_pslg *g,
                    char *msg, size_t size);
#endif
/* The invariants of every reader's output: arrays present exactly when counted,
 * finite numbers, endpoints in range (when the vertices are there). */
void check_pslg(lh_test_state *lh_t_, const lh_pslg *g);

typedef struct bad_case {
    const char *name;
    const char *text;
    size_t len;
    lh_status status;
    const char *msg;
} bad_case;

/* Each case read by rd must fail with its status and exact message, hand nothing
 * back and leave nothing allocated. */
void check_bad_cases(lh_test_state *lh_t_, reader rd, const bad_case *cases, size_t count);

#endif
