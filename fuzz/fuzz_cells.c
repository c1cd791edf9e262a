/*
 * fuzz_cells.c — libFuzzer target over the cell-list reader lh_cells_read (Qhull's 'i'
 * and Triangle/TetGen .ele). The first byte picks the number of points the indices
 * must name (0: unchecked, 1, 3, 4, 10, 100, 1000, INT32_MAX) and the name ("in",
 * "in.ele", "cells.txt", "x"); the rest is the file. Whatever comes back must keep the
 * contract of lifthull.h: LH_OK with 1 <= count, 2 <= nv <= 9, first_index 0 or 1, every
 * index in 0..n_points-1 (or >= 0 when unchecked) and an empty
 * message, and the cells written back as an 'i' file read back equal; or one of the
 * documented failures with zeroed cells and ONE printable line "NAME:LINE:COL: ..."
 * (LINE and COL positive decimal numbers; no raw byte of the input, no line end).
 * Everything allocated is freed (a counting allocator). Anything else aborts. Build as
 * fuzz_delaunay.c (fuzz/README.md).
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_ok(const lh_cells *c, size_t n_points, const char *msg)
{
    if (c->count < 1 || c->nv < 2 || c->nv > 9 || !c->v || msg[0] ||
        (c->first_index != 0 && c->first_index != 1))
        abort();
    for (size_t i = 0; i < c->count * (size_t)c->nv; i++)
        if (c->v[i] < 0 || (n_points && (size_t)c->v[i] >= n_points)) abort();
}

/* "NAME:LINE:COL: " then printable bytes only. */
static void check_failure(lh_status st, const lh_cells *c, const char *msg, const char *name)
{
    if (st != LH_ERR_PARSE && st != LH_ERR_TOO_LARGE && st != LH_ERR_IO && st != LH_ERR_NONFINITE) abort();
    if (c->v || c->count || c->nv || c->first_index) abort();
    lh_fuzz_check_message(msg, name);
}

/* Writes c as an 'i' file and reads it back: the same cells, base 0. */
static void round_trip(const lh_cells *c, size_t n_points, const lh_allocator *a)
{
    FILE *f = tmpfile();
    if (!f) return;
    fprintf(f, "%zu\n", c->count);
    for (size_t i = 0; i < c->count; i++)
        for (int k = 0; k < c->nv; k++)
            fprintf(f, "%" LH_INDEX_PRI "%c", c->v[i * c->nv + k], k + 1 < c->nv ? ' ' : '\n');
    rewind(f);
    lh_cells back;
    lh_error err;
    if (lh_cells_read(f, "back", n_points, a, &back, &err) != LH_OK) abort();
    fclose(f);
    if (back.count != c->count || back.nv != c->nv || back.first_index != 0 ||
        memcmp(back.v, c->v, c->count * (size_t)c->nv * sizeof *c->v))
        abort();
    lh_cells_free(&back);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *names[] = {"in", "in.ele", "cells.txt", "x"};
    static const size_t points[] = {0, 1, 3, 4, 10, 100, 1000, INT32_MAX};
    if (size < 1) return 0;
    FILE *f = lh_fuzz_file(data, size);
    if (!f) return 0;
    long live = 0;
    lh_allocator a = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    const char *name = names[(data[0] >> 3) & 3];
    size_t n_points = points[data[0] & 7];
    lh_error err;
    lh_cells c;
    lh_status st = lh_cells_read(f, name, n_points, &a, &c, &err);
    fclose(f);
    if (st == LH_OK) {
        check_ok(&c, n_points, err.message);
        if (c.count <= 4096) round_trip(&c, n_points, &a);
    } else {
        check_failure(st, &c, err.message, name);
    }
    lh_cells_free(&c);
    if (live != 0) abort();
    return 0;
}
