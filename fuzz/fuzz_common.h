/* fuzz_common.h — what the reader targets share: a counting allocator (nothing may
 * leak), the input as a file, and the one-line message contract of lifthull's
 * readers. */
#ifndef LH_FUZZ_COMMON_H
#define LH_FUZZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* user points at a long: live blocks. */
static inline void *lh_fuzz_count_alloc(void *user, size_t size)
{
    ++*(long *)user;
    return malloc(size);
}

static inline void lh_fuzz_count_free(void *user, void *ptr)
{
    --*(long *)user;
    free(ptr);
}

/* A temporary file holding data[1..size) (data[0] picks the reader's options),
 * rewound; NULL when none can be made. */
static inline FILE *lh_fuzz_file(const uint8_t *data, size_t size)
{
    FILE *f = tmpfile();
    if (!f) return NULL;
    if (size > 1 && fwrite(data + 1, 1, size - 1, f) != size - 1) abort();
    rewind(f);
    return f;
}

/* msg is "NAME:LINE:COL: " (LINE, COL positive) then printable bytes only; else abort. */
static inline void lh_fuzz_check_message(const char *msg, const char *name)
{
    size_t len = strlen(name);
    if (strncmp(msg, name, len) || msg[len] != ':') abort();
    const char *q = msg + len + 1;
    for (int field = 0; field < 2; field++) {
        if (*q < '1' || *q > '9') abort();
        while (*q >= '0' && *q <= '9') q++;
        if (*q++ != ':') abort();
    }
    if (*q != ' ') abort();
    for (const char *k = msg; *k; k++)
        if (*k < 0x20 || *k > 0x7e) abort();
}

#endif
