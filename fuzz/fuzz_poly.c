/*
 * fuzz_poly.c — libFuzzer target over the PSLG readers: the bytes are a .poly file for
 * lh_poly_read ("in.poly") and, when the first byte is '[', also JSON rings for
 * lh_rings_read ("in.json"). Whatever comes back must keep the contract of lifthull.h:
 * LH_OK with an empty message, every array present exactly when its count is not 0,
 * finite numbers, first_index 0 or 1, endpoints naming vertices (from 0, when the
 * vertices are in a .node), the lines of the items increasing through the file, and
 * the graph written back as a .poly read back equal; or one of the documented failures
 * with a zeroed lh_pslg and ONE printable line "NAME:LINE:COL: ..." (LINE and COL
 * positive). An n = 0 .poly is given vertices from a .node numbered from the other base
 * (lh_pslg_take_points). Everything allocated is freed (a counting allocator). Anything
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

/* Lines at least first, never decreasing; returns the last (or first). */
static size_t lines(const size_t *line, size_t count, size_t first)
{
    for (size_t i = 0; i < count; i++) {
        if (line[i] < first) abort();
        first = line[i];
    }
    return first;
}

static void check_ok(const lh_pslg *g, const char *msg, int rings)
{
    if (msg[0] || (g->first_index != 0 && g->first_index != 1) || g->attr_count < 0 ||
        g->attr_count > 1000 || g->even_odd != rings || !g->alloc_.alloc)
        abort();
    if ((g->n > 0) != (g->xy != NULL) || (g->n > 0) != (g->vertex_line != NULL) ||
        (g->n > 0 && g->attr_count > 0) != (g->attr != NULL) ||
        (g->n == 0 && (g->attr_count || g->vertex_marker)) ||
        (g->segment_count > 0) != (g->segments != NULL) ||
        (g->segment_count > 0) != (g->segment_line != NULL) ||
        (!g->segment_count && g->segment_marker) ||
        (g->hole_count > 0) != (g->holes != NULL && g->hole_line != NULL) ||
        (g->region_count > 0) != (g->regions != NULL && g->region_line != NULL))
        abort();
    finite(g->xy, 2 * g->n);
    finite(g->attr, g->n * (size_t)g->attr_count);
    finite(g->holes, 2 * g->hole_count);
    finite(g->regions, 4 * g->region_count);
    /* with n = 0 an endpoint 0 of a 1-based file is stored as -1, until
     * lh_pslg_take_points renumbers the endpoints as the .node */
    for (size_t i = 0; i < 2 * g->segment_count; i++)
        if (g->segments[i] < (g->n ? 0 : -g->first_index) || (g->n && (size_t)g->segments[i] >= g->n)) abort();
    size_t at = lines(g->vertex_line, g->n, 1);
    if (rings) { /* cycles of consecutive vertices, each segment on its start's line */
        if (g->vertex_marker || g->segment_marker || g->hole_count || g->region_count || g->first_index)
            abort();
        for (size_t i = 0; i < g->segment_count; i++) {
            lh_index a = g->segments[2 * i], b = g->segments[2 * i + 1];
            if ((b != a + 1 && b >= a) || g->segment_line[i] != g->vertex_line[a]) abort();
        }
        return;
    }
    at = lines(g->segment_line, g->segment_count, at);
    at = lines(g->hole_line, g->hole_count, at);
    lines(g->region_line, g->region_count, at);
}

static void check_failure(lh_status st, const lh_pslg *g, const char *msg, const char *name)
{
    if (st != LH_ERR_PARSE && st != LH_ERR_DIMENSION && st != LH_ERR_NONFINITE &&
        st != LH_ERR_TOO_LARGE && st != LH_ERR_IO)
        abort();
    if (g->n || g->xy || g->attr || g->attr_count || g->vertex_marker || g->segment_count ||
        g->segments || g->segment_marker || g->hole_count || g->holes || g->region_count ||
        g->regions || g->even_odd || g->first_index || g->vertex_line || g->segment_line ||
        g->hole_line || g->region_line || g->alloc_.alloc || g->alloc_.free || g->alloc_.user)
        abort();
    lh_fuzz_check_message(msg, name);
}

/* g as a .poly numbered from first_index, every number with 17 digits. */
static void write_poly(FILE *f, const lh_pslg *g)
{
    int b = g->first_index;
    fprintf(f, "%zu 2 %d %d\n", g->n, g->attr_count, g->vertex_marker != NULL);
    for (size_t i = 0; i < g->n; i++) {
        fprintf(f, "%zu %.17g %.17g", i + b, g->xy[2 * i], g->xy[2 * i + 1]);
        for (int j = 0; j < g->attr_count; j++) fprintf(f, " %.17g", g->attr[i * g->attr_count + j]);
        if (g->vertex_marker) fprintf(f, " %lld", (long long)g->vertex_marker[i]);
        fputc('\n', f);
    }
    fprintf(f, "%zu %d\n", g->segment_count, g->segment_marker != NULL);
    for (size_t i = 0; i < g->segment_count; i++) {
        fprintf(f, "%zu %lld %lld", i + b, (long long)g->segments[2 * i] + b, (long long)g->segments[2 * i + 1] + b);
        if (g->segment_marker) fprintf(f, " %lld", (long long)g->segment_marker[i]);
        fputc('\n', f);
    }
    fprintf(f, "%zu\n", g->hole_count);
    for (size_t i = 0; i < g->hole_count; i++)
        fprintf(f, "%zu %.17g %.17g\n", i + b, g->holes[2 * i], g->holes[2 * i + 1]);
    fprintf(f, "%zu\n", g->region_count);
    for (size_t i = 0; i < g->region_count; i++)
        fprintf(f, "%zu %.17g %.17g %.17g %.17g\n", i + b, g->regions[4 * i], g->regions[4 * i + 1],
                g->regions[4 * i + 2], g->regions[4 * i + 3]);
}

static int same(const void *a, const void *b, size_t bytes)
{
    return bytes == 0 || (a && b && memcmp(a, b, bytes) == 0);
}

static void round_trip(const lh_pslg *g, const lh_allocator *a)
{
    FILE *f = tmpfile();
    if (!f) return;
    write_poly(f, g);
    rewind(f);
    lh_pslg back;
    lh_error err;
    if (lh_poly_read(f, "back", a, &back, &err) != LH_OK) abort();
    fclose(f);
    if (back.n != g->n || back.attr_count != (g->n ? g->attr_count : 0) ||
        back.segment_count != g->segment_count || back.hole_count != g->hole_count ||
        back.region_count != g->region_count ||
        (back.first_index != g->first_index && (g->n || g->segment_count || g->hole_count || g->region_count)) ||
        !same(back.xy, g->xy, 2 * g->n * sizeof *g->xy) ||
        !same(back.attr, g->attr, g->n * (size_t)g->attr_count * sizeof *g->attr) ||
        !same(back.vertex_marker, g->vertex_marker, g->vertex_marker ? g->n * sizeof(lh_index) : 0) ||
        !same(back.segments, g->segments, 2 * g->segment_count * sizeof *g->segments) ||
        !same(back.segment_marker, g->segment_marker, g->segment_marker ? g->segment_count * sizeof(lh_index) : 0) ||
        !same(back.holes, g->holes, 2 * g->hole_count * sizeof *g->holes) ||
        !same(back.regions, g->regions, 4 * g->region_count * sizeof *g->regions))
        abort();
    lh_pslg_free(&back);
}

/* An n = 0 graph gets m vertices from a .node numbered from the other base: every
 * endpoint moves by one, within -1..m. */
static void take_points(lh_pslg *g, const lh_allocator *a)
{
    long long m = 1;
    for (size_t i = 0; i < 2 * g->segment_count; i++)
        if (g->segments[i] >= m) m = (long long)g->segments[i] + 1;
    if (m > 4096) return;
    FILE *f = tmpfile();
    if (!f) return;
    int base = 1 - g->first_index, was = g->first_index;
    fprintf(f, "%lld 2 0 1\n", m);
    for (long long i = 0; i < m; i++) fprintf(f, "%lld %lld 0.5 %lld\n", i + base, i, -i);
    rewind(f);
    lh_points p;
    lh_error err;
    if (lh_points_read(f, "p.node", LH_FORMAT_NODE, a, &p, &err) != LH_OK) abort();
    fclose(f);
    lh_index *before = malloc(2 * g->segment_count * sizeof *before + 1);
    if (!before) abort();
    if (g->segment_count) memcpy(before, g->segments, 2 * g->segment_count * sizeof *before);
    if (lh_pslg_take_points(g, &p) != LH_OK || p.xyz || p.n || g->n != (size_t)m ||
        g->first_index != base || !g->vertex_marker || g->vertex_marker[m - 1] != -(m - 1))
        abort();
    for (size_t i = 0; i < 2 * g->segment_count; i++)
        if (g->segments[i] != before[i] + (was - base) || g->segments[i] < -1 || g->segments[i] > m) abort();
    free(before);
    lh_points_free(&p);
}

static void run(const uint8_t *data, size_t size, int rings)
{
    const char *name = rings ? "in.json" : "in.poly";
    FILE *f = tmpfile();
    if (!f) return;
    if (size && fwrite(data, 1, size, f) != size) abort();
    rewind(f);
    long live = 0;
    lh_allocator a = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    lh_error err;
    lh_pslg g;
    lh_status st = rings ? lh_rings_read(f, name, &a, &g, &err)
                         : lh_poly_read(f, name, &a, &g, &err);
    fclose(f);
    if (st == LH_OK) {
        check_ok(&g, err.message, rings);
        round_trip(&g, &a);
        if (!rings && g.n == 0) take_points(&g, &a);
    } else {
        check_failure(st, &g, err.message, name);
    }
    lh_pslg_free(&g);
    if (live != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    run(data, size, 0);
    if (size && data[0] == '[') run(data, size, 1);
    return 0;
}
