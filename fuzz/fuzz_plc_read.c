/*
 * fuzz_plc_read.c — libFuzzer target over lh_plc_read, every format. The first byte
 * picks the format (byte % 9: auto, poly, smesh, node, off, ply, stl, medit, obj) and,
 * for auto, the name's extension (byte / 9 % 9, "none" for 0); the rest is the file.
 * Whatever comes back must keep the contract of lifthull.h: LH_OK with an empty
 * message, first_index 0 or 1, the offset arrays present and increasing, every polygon
 * of 1 or more vertices and every facet with one of 3 or more, vertex numbers naming
 * points (n = 0, a .poly or .smesh without points: from 0), finite numbers, the items'
 * lines never decreasing (text formats); the PLC written back as a TetGen .poly read
 * back equal (segments aside: a .poly has none). Or one of the documented failures
 * with a zeroed lh_plc and ONE printable line "NAME:LINE:COL: ..." (binary PLY and
 * STL: "NAME: ..."). Everything allocated is freed (a counting allocator). Anything
 * else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void finite(const double *x, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (!isfinite(x[i])) abort();
}

static void lines(const size_t *line, size_t count)
{
    for (size_t i = 0; line && i < count; i++)
        if (line[i] < 1 || (i && line[i] < line[i - 1])) abort();
}

static int binary_capable(lh_plc_format f) { return f == LH_PLC_PLY || f == LH_PLC_STL; }

static void check_ok(const lh_plc *g, const char *msg, lh_plc_format fmt)
{
    if (msg[0] || (g->first_index != 0 && g->first_index != 1) || g->attr_count < 0 ||
        g->attr_count > 1000 || !g->facet_first || !g->polygon_first || !g->facet_hole_first ||
        (g->n > 0) != (g->xyz != NULL) || (g->n == 0 && g->attr_count) ||
        (g->n > 0 && g->attr_count > 0) != (g->attr != NULL) ||
        (g->segment_count > 0) != (g->segments != NULL) || (g->hole_count > 0) != (g->holes != NULL) ||
        (g->region_count > 0) != (g->regions != NULL) || g->facet_first[0] != 0)
        abort();
    if (g->n == 0 && fmt != LH_PLC_POLY && fmt != LH_PLC_SMESH && fmt != LH_PLC_AUTO) abort();
    finite(g->xyz, 3 * g->n);
    finite(g->attr, g->n * (size_t)g->attr_count);
    finite(g->holes, 3 * g->hole_count);
    finite(g->regions, 5 * g->region_count);
    for (size_t f = 0; f < g->facet_count; f++) {
        int big = 0;
        if (g->facet_first[f + 1] <= g->facet_first[f] || g->facet_hole_first[f + 1] < g->facet_hole_first[f])
            abort();
        for (lh_index p = g->facet_first[f]; p < g->facet_first[f + 1]; p++) {
            lh_index k = g->polygon_first[p + 1] - g->polygon_first[p];
            if (k < 1) abort();
            big |= k >= 3;
        }
        if (!big) abort();
    }
    if ((size_t)g->facet_first[g->facet_count] != g->polygon_count || g->polygon_first[0] != 0) abort();
    size_t nv = (size_t)g->polygon_first[g->polygon_count];
    size_t nh = (size_t)g->facet_hole_first[g->facet_count];
    finite(g->facet_holes, 3 * nh);
    for (size_t i = 0; i < nv; i++)
        if (g->polygon_vertices[i] < 0 || (g->n && (size_t)g->polygon_vertices[i] >= g->n)) abort();
    for (size_t i = 0; i < 2 * g->segment_count; i++)
        if (g->segments[i] < 0 || (g->n && (size_t)g->segments[i] >= g->n)) abort();
    if (binary_capable(fmt) || fmt == LH_PLC_AUTO) return;
    lines(g->point_line, g->n);
    lines(g->facet_line, g->facet_count);
    lines(g->segment_line, g->segment_count);
    lines(g->hole_line, g->hole_count);
    lines(g->region_line, g->region_count);
}

static void check_failure(lh_status st, const lh_plc *g, const char *msg, const char *name,
                          lh_plc_format fmt)
{
    if (st != LH_ERR_PARSE && st != LH_ERR_DIMENSION && st != LH_ERR_NONFINITE &&
        st != LH_ERR_TOO_LARGE && st != LH_ERR_IO)
        abort();
    lh_plc zero;
    memset(&zero, 0, sizeof zero);
    if (memcmp(g, &zero, sizeof zero) != 0) abort();
    if (!binary_capable(fmt) && fmt != LH_PLC_AUTO) {
        lh_fuzz_check_message(msg, name);
        return;
    }
    size_t len = strlen(name); /* binary formats name a record, not a line */
    if (strncmp(msg, name, len) != 0 || msg[len] != ':') abort();
    for (const char *k = msg; *k; k++)
        if (*k < 0x20 || *k > 0x7e) abort();
}

/* g as a TetGen .poly (3D), every number with 17 digits. */
static void write_poly(FILE *f, const lh_plc *g)
{
    int b = g->first_index;
    fprintf(f, "%zu 3 %d %d\n", g->n, g->n ? g->attr_count : 0, g->point_marker != NULL);
    for (size_t i = 0; i < g->n; i++) {
        fprintf(f, "%zu %.17g %.17g %.17g", i + b, g->xyz[3 * i], g->xyz[3 * i + 1], g->xyz[3 * i + 2]);
        for (int j = 0; j < g->attr_count; j++) fprintf(f, " %.17g", g->attr[i * (size_t)g->attr_count + j]);
        if (g->point_marker) fprintf(f, " %lld", (long long)g->point_marker[i]);
        fputc('\n', f);
    }
    int vb = g->n ? b : 0; /* n = 0: vertex numbers stored as read */
    fprintf(f, "%zu 1\n", g->facet_count);
    for (size_t k = 0; k < g->facet_count; k++) {
        lh_index h0 = g->facet_hole_first[k], h1 = g->facet_hole_first[k + 1];
        fprintf(f, "%lld %lld %lld\n", (long long)(g->facet_first[k + 1] - g->facet_first[k]),
                (long long)(h1 - h0), g->facet_marker ? (long long)g->facet_marker[k] : 0LL);
        for (lh_index p = g->facet_first[k]; p < g->facet_first[k + 1]; p++) {
            fprintf(f, "%lld", (long long)(g->polygon_first[p + 1] - g->polygon_first[p]));
            for (lh_index v = g->polygon_first[p]; v < g->polygon_first[p + 1]; v++)
                fprintf(f, " %lld", (long long)g->polygon_vertices[v] + vb);
            fputc('\n', f);
        }
        for (lh_index h = h0; h < h1; h++)
            fprintf(f, "%d %.17g %.17g %.17g\n", (int)(h - h0) + 1, g->facet_holes[3 * h],
                    g->facet_holes[3 * h + 1], g->facet_holes[3 * h + 2]);
    }
    fprintf(f, "%zu\n", g->hole_count);
    for (size_t i = 0; i < g->hole_count; i++)
        fprintf(f, "%zu %.17g %.17g %.17g\n", i + b, g->holes[3 * i], g->holes[3 * i + 1], g->holes[3 * i + 2]);
    fprintf(f, "%zu\n", g->region_count);
    for (size_t i = 0; i < g->region_count; i++)
        fprintf(f, "%zu %.17g %.17g %.17g %.17g %.17g\n", i + b, g->regions[5 * i], g->regions[5 * i + 1],
                g->regions[5 * i + 2], g->regions[5 * i + 3], g->regions[5 * i + 4]);
}

static int same(const void *a, const void *b, size_t bytes)
{
    return bytes == 0 || (a && b && memcmp(a, b, bytes) == 0);
}

static void round_trip(const lh_plc *g, const lh_allocator *a)
{
    FILE *f = tmpfile();
    if (!f) return;
    write_poly(f, g);
    rewind(f);
    lh_plc back;
    lh_error err;
    if (lh_plc_read(f, "back.poly", LH_PLC_POLY, a, &back, &err) != LH_OK) abort();
    fclose(f);
    size_t nv = (size_t)g->polygon_first[g->polygon_count];
    size_t nh = (size_t)g->facet_hole_first[g->facet_count];
    size_t fc = g->facet_count + 1, pc = g->polygon_count + 1;
    if (back.n != g->n || back.attr_count != (g->n ? g->attr_count : 0) ||
        back.facet_count != g->facet_count || back.polygon_count != g->polygon_count ||
        back.hole_count != g->hole_count || back.region_count != g->region_count ||
        (g->n && back.first_index != g->first_index) ||
        !same(back.xyz, g->xyz, 3 * g->n * sizeof(double)) ||
        !same(back.attr, g->attr, g->n * (size_t)g->attr_count * sizeof(double)) ||
        !same(back.point_marker, g->point_marker, g->point_marker ? g->n * sizeof(lh_index) : 0) ||
        !same(back.facet_first, g->facet_first, fc * sizeof(lh_index)) ||
        !same(back.facet_marker, g->facet_marker, g->facet_marker ? g->facet_count * sizeof(lh_index) : 0) ||
        !same(back.polygon_first, g->polygon_first, pc * sizeof(lh_index)) ||
        !same(back.polygon_vertices, g->polygon_vertices, nv * sizeof(lh_index)) ||
        !same(back.facet_hole_first, g->facet_hole_first, fc * sizeof(lh_index)) ||
        !same(back.facet_holes, g->facet_holes, 3 * nh * sizeof(double)) ||
        !same(back.holes, g->holes, 3 * g->hole_count * sizeof(double)) ||
        !same(back.regions, g->regions, 5 * g->region_count * sizeof(double)))
        abort();
    lh_plc_free(&back);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const names[] = {"in",      "in.poly", "in.smesh", "in.node", "in.off",
                                         "in.ply",  "in.stl",  "in.mesh",  "in.obj"};
    if (size < 1) return 0;
    lh_plc_format fmt = (lh_plc_format)(data[0] % 9);
    const char *name = names[fmt == LH_PLC_AUTO ? data[0] / 9 % 9 : (int)fmt];
    FILE *f = lh_fuzz_file(data, size);
    if (!f) return 0;
    long live = 0;
    lh_allocator a = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    lh_error err;
    lh_plc g;
    lh_status st = lh_plc_read(f, name, fmt, &a, &g, &err);
    fclose(f);
    if (st == LH_OK) {
        check_ok(&g, err.message, fmt);
        round_trip(&g, &a);
    } else {
        check_failure(st, &g, err.message, name, fmt);
    }
    lh_plc_free(&g);
    if (live != 0) abort();
    return 0;
}
