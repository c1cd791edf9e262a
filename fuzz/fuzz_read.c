/*
 * fuzz_read.c — libFuzzer target over every point reader (lh_points_read). The first
 * byte picks the format (auto, qhull, node, columns) and the name's extension (none,
 * .node, .csv, .txt); the rest is the file. Whatever comes back must keep the
 * contract of lifthull.h: LH_OK with 1 <= n, 2 <= d <= 8, finite values, a concrete
 * format, first_index 0 or 1 and an empty message; or one of the documented failures
 * with zeroed points and ONE printable line "NAME:LINE:COL: ..." (no raw byte of the
 * input, no line end). Everything allocated is freed (a counting allocator). Anything
 * else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_ok(const lh_points *p, const char *msg)
{
    if (p->n < 1 || p->d < 2 || p->d > 8 || p->format == LH_FORMAT_AUTO || msg[0] ||
        (p->first_index != 0 && p->first_index != 1) || p->attr_count < 0 ||
        (p->attr_count > 0) != (p->attr != NULL))
        abort();
    for (size_t i = 0; i < p->n * (size_t)p->d; i++)
        if (!isfinite(p->xyz[i])) abort();
    for (size_t i = 0; i < p->n * (size_t)p->attr_count; i++)
        if (!isfinite(p->attr[i])) abort();
}

static void check_failure(lh_status st, const lh_points *p, const char *msg, const char *name)
{
    if (st != LH_ERR_PARSE && st != LH_ERR_DIMENSION && st != LH_ERR_NONFINITE &&
        st != LH_ERR_TOO_LARGE && st != LH_ERR_IO)
        abort();
    if (p->xyz || p->attr || p->marker || p->n || p->d) abort();
    lh_fuzz_check_message(msg, name);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *names[] = {"in", "in.node", "in.csv", "in.txt"};
    if (size < 1) return 0;
    FILE *f = lh_fuzz_file(data, size);
    if (!f) return 0;
    long live = 0;
    lh_allocator a = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    const char *name = names[(data[0] >> 2) & 3];
    lh_error err;
    lh_points p;
    lh_status st = lh_points_read(f, name, (lh_format)(data[0] & 3), &a, &p, &err);
    fclose(f);
    if (st == LH_OK) check_ok(&p, err.message);
    else check_failure(st, &p, err.message, name);
    lh_points_free(&p);
    if (live != 0) abort();
    return 0;
}
