/*
 * fuzz_plc_binary.c — libFuzzer target over lh_plc_read's PLY and STL readers (ascii
 * and binary). The first byte picks the name and format: "in.ply", "in.stl", "in"
 * (LH_PLC_AUTO from the content), or "in" with LH_PLC_PLY or LH_PLC_STL; the rest is
 * the file. Whatever comes back must keep the contract of lifthull.h: LH_OK with an
 * empty message, at least one point, finite coordinates, each facet one polygon of at
 * least 3 vertices naming points (STL: exactly 3, and no two points equal: corners are
 * merged), offsets closed, point and facet lines positive and never decreasing; or a
 * documented failure with a zeroed lh_plc and ONE printable line "NAME:LINE:COL: ..."
 * (text) or "NAME: ..." (a binary record). Everything allocated is freed (a counting
 * allocator). Anything else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Lines positive, never decreasing. */
static void lines(const size_t *line, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (line[i] < 1 || (i && line[i] < line[i - 1])) abort();
}

/* No two points equal (STL's corners are merged): sorted copies compared. */
static int cmp3(const void *a, const void *b)
{
    const double *p = a, *q = b;
    for (int i = 0; i < 3; i++)
        if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
    return 0;
}

static void distinct(const lh_plc *g)
{
    double *c = malloc(3 * g->n * sizeof *c);
    if (!c) return;
    memcpy(c, g->xyz, 3 * g->n * sizeof *c);
    qsort(c, g->n, 3 * sizeof *c, cmp3);
    for (size_t i = 1; i < g->n; i++)
        if (cmp3(c + 3 * (i - 1), c + 3 * i) == 0) abort();
    free(c);
}

static void check_ok(const lh_plc *g, const char *msg, int stl)
{
    if (msg[0] || g->n < 1 || !g->xyz || !g->point_line || g->attr_count || g->attr ||
        g->first_index || g->facet_count != g->polygon_count || !g->facet_first ||
        !g->polygon_first || !g->facet_hole_first || g->segment_count || g->hole_count ||
        g->region_count)
        abort();
    for (size_t i = 0; i < 3 * g->n; i++)
        if (!isfinite(g->xyz[i])) abort();
    lines(g->point_line, g->n);
    if (g->facet_count) lines(g->facet_line, g->facet_count);
    for (size_t f = 0; f <= g->facet_count; f++)
        if (g->facet_first[f] != (lh_index)f || g->facet_hole_first[f] != 0) abort();
    if (g->polygon_first[0] != 0) abort();
    for (size_t p = 0; p < g->polygon_count; p++) {
        lh_index a = g->polygon_first[p], b = g->polygon_first[p + 1];
        if (b - a < 3 || (stl && b - a != 3)) abort();
        for (lh_index k = a; k < b; k++)
            if (g->polygon_vertices[k] < 0 || (size_t)g->polygon_vertices[k] >= g->n) abort();
    }
    if (stl) distinct(g);
}

/* "NAME:LINE:COL: " or "NAME: " then printable bytes only. */
static void check_message(const char *msg, const char *name)
{
    size_t len = strlen(name);
    if (strncmp(msg, name, len) || msg[len] != ':') abort();
    if (msg[len + 1] != ' ') lh_fuzz_check_message(msg, name);
    for (const char *k = msg; *k; k++)
        if (*k < 0x20 || *k > 0x7e) abort();
}

static void check_failure(lh_status st, const lh_plc *g, const char *msg, const char *name)
{
    static const lh_plc zero;
    if (st != LH_ERR_PARSE && st != LH_ERR_NONFINITE && st != LH_ERR_TOO_LARGE && st != LH_ERR_IO)
        abort();
    if (memcmp(g, &zero, sizeof zero) != 0) abort();
    check_message(msg, name);
}

static int starts(const uint8_t *in, size_t len, const char *word)
{
    return len >= strlen(word) && memcmp(in, word, strlen(word)) == 0;
}

/* Which reader ran: 0 PLY, 1 STL, -1 another (lh__plc_detect's rule for "in"). */
static int reader(int pick, const uint8_t *in, size_t len)
{
    if (pick != 2) return pick == 1 || pick == 4;
    if (starts(in, len, "ply")) return 0;
    if (starts(in, len, "solid")) return 1;
    if (starts(in, len, "MeshVersionFormatted")) return -1;
    return memchr(in, 0, len < 4096 ? len : 4096) ? 1 : -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"in.ply", "in.stl", "in", "in", "in"};
    static const lh_plc_format formats[] = {LH_PLC_AUTO, LH_PLC_AUTO, LH_PLC_AUTO, LH_PLC_PLY,
                                            LH_PLC_STL};
    if (size < 1) return 0;
    int pick = data[0] % 5;
    FILE *f = lh_fuzz_file(data, size);
    if (!f) return 0;
    long live = 0;
    lh_allocator a = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    lh_error err;
    lh_plc g;
    lh_status st = lh_plc_read(f, names[pick], formats[pick], &a, &g, &err);
    fclose(f);
    if (st == LH_OK) {
        int kind = reader(pick, data + 1, size - 1);
        if (kind >= 0)
            check_ok(&g, err.message, kind);
        else if (err.message[0])
            abort(); /* another format's reader: not this target's */
    } else {
        check_failure(st, &g, err.message, names[pick]);
    }
    lh_plc_free(&g);
    if (live != 0) abort();
    return 0;
}
