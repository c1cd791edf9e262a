/*
 * plc_build.c — the lh_plc builder the readers share (io_plc.h), lh_plc_free and
 * lh_plc_take_points.
 */
#include "io_plc.h"

#include <stdint.h>
#include <string.h>

void lh_plc_free(lh_plc *g)
{
    if (!g) return;
    if (g->alloc_.free) {
        void *arrays[] = {
            g->xyz,          g->attr,          g->point_marker,     g->facet_first,
            g->facet_marker, g->polygon_first, g->polygon_vertices, g->facet_hole_first,
            g->facet_holes,  g->segments,      g->segment_marker,   g->holes,
            g->regions,      g->point_line,    g->facet_line,       g->segment_line,
            g->hole_line,    g->region_line};
        for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
            lh__free(&g->alloc_, arrays[i]);
    }
    memset(g, 0, sizeof *g);
}

lh_status lh__plc_build_init(lh__plc_build *b, lh_plc *g, const lh_allocator *alloc)
{
    memset(b, 0, sizeof *b);
    if (!g) return LH_ERR_INVALID_ARGUMENT;
    memset(g, 0, sizeof *g);
    if (!lh__allocator_init(&g->alloc_, alloc)) {
        memset(g, 0, sizeof *g);
        return LH_ERR_INVALID_ARGUMENT;
    }
    b->g = g;
    return LH_OK;
}

void lh__plc_build_fail(lh__plc_build *b)
{
    if (b->g) lh_plc_free(b->g);
    memset(b, 0, sizeof *b);
}

/* Makes room for `need` elements of `size` bytes in *arr (capacity *cap, doubling). */
static lh_status grow(lh__plc_build *b, void **arr, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return LH_OK;
    size_t c = *cap ? *cap : 16;
    while (c < need) {
        if (c > SIZE_MAX / 2) return LH_ERR_TOO_LARGE;
        c *= 2;
    }
    if (c > SIZE_MAX / size || c > (size_t)LH_INDEX_MAX) return LH_ERR_TOO_LARGE;
    void *p = lh__alloc(&b->g->alloc_, c * size);
    if (!p) return LH_ERR_NOMEM;
    if (*arr) {
        memcpy(p, *arr, *cap * size);
        lh__free(&b->g->alloc_, *arr);
    }
    *arr = p;
    *cap = c;
    return LH_OK;
}

#define GROW(b, arr, capv, need, size) grow((b), (void **)&(arr), &(capv), (need), (size))

/* One of several parallel arrays that share a count and a capacity. */
typedef struct column {
    void **arr;
    size_t size; /* bytes per element */
} column;

/* grow() for parallel arrays: room for `need` elements in each, *cap their shared
 * capacity (updated once all have grown). */
static lh_status grow_columns(lh__plc_build *b, const column *cols, int ncols, size_t need,
                              size_t *cap)
{
    size_t c = *cap;
    for (int i = 0; i < ncols; i++) {
        c = *cap;
        lh_status st = grow(b, cols[i].arr, &c, need, cols[i].size);
        if (st != LH_OK) return st;
    }
    *cap = c;
    return LH_OK;
}

lh_status lh__plc_point(lh__plc_build *b, const double xyz[3], const double *attr, lh_index marker,
                        size_t line)
{
    lh_plc *g = b->g;
    size_t n = g->n, k = (size_t)g->attr_count;
    if (k > SIZE_MAX / sizeof(double) / 4) return LH_ERR_TOO_LARGE;
    const column cols[] = {{(void **)&g->xyz, 3 * sizeof(double)},
                           {(void **)&g->point_marker, sizeof(lh_index)},
                           {(void **)&g->point_line, sizeof(size_t)},
                           {(void **)&g->attr, k * sizeof(double)}};
    lh_status st = grow_columns(b, cols, k ? 4 : 3, n + 1, &b->cap_points);
    if (st != LH_OK) return st;
    if (k) memcpy(g->attr + n * k, attr, k * sizeof(double));
    memcpy(g->xyz + 3 * n, xyz, 3 * sizeof(double));
    g->point_marker[n] = marker;
    g->point_line[n] = line;
    g->n = n + 1;
    return LH_OK;
}

lh_status lh__plc_facet(lh__plc_build *b, lh_index marker, size_t line)
{
    lh_plc *g = b->g;
    size_t f = g->facet_count;
    /* facet_first and facet_hole_first get one slot more, for the closing offset. */
    const column cols[] = {{(void **)&g->facet_first, sizeof(lh_index)},
                           {(void **)&g->facet_hole_first, sizeof(lh_index)},
                           {(void **)&g->facet_marker, sizeof(lh_index)},
                           {(void **)&g->facet_line, sizeof(size_t)}};
    lh_status st = grow_columns(b, cols, 4, f + 2, &b->cap_facets);
    if (st != LH_OK) return st;
    g->facet_first[f] = (lh_index)g->polygon_count;
    g->facet_hole_first[f] = (lh_index)b->facet_holes;
    g->facet_marker[f] = marker;
    g->facet_line[f] = line;
    g->facet_count = f + 1;
    b->facet_open = 1;
    return LH_OK;
}

lh_status lh__plc_polygon(lh__plc_build *b, const lh_index *v, size_t k)
{
    lh_plc *g = b->g;
    if (!b->facet_open || k == 0) return LH_ERR_INVALID_ARGUMENT;
    size_t p = g->polygon_count;
    lh_status st;
    if ((st = GROW(b, g->polygon_first, b->cap_polygons, p + 2, sizeof(lh_index)))) return st;
    if (b->vertices > SIZE_MAX - k) return LH_ERR_TOO_LARGE;
    if ((st = GROW(b, g->polygon_vertices, b->cap_vertices, b->vertices + k, sizeof(lh_index))))
        return st;
    g->polygon_first[p] = (lh_index)b->vertices;
    memcpy(g->polygon_vertices + b->vertices, v, k * sizeof(lh_index));
    b->vertices += k;
    g->polygon_count = p + 1;
    return LH_OK;
}

lh_status lh__plc_facet_hole(lh__plc_build *b, const double xyz[3])
{
    if (!b->facet_open) return LH_ERR_INVALID_ARGUMENT;
    lh_status st =
        GROW(b, b->g->facet_holes, b->cap_facet_holes, b->facet_holes + 1, 3 * sizeof(double));
    if (st) return st;
    memcpy(b->g->facet_holes + 3 * b->facet_holes, xyz, 3 * sizeof(double));
    b->facet_holes++;
    return LH_OK;
}

lh_status lh__plc_segment(lh__plc_build *b, lh_index p, lh_index q, lh_index marker, size_t line)
{
    lh_plc *g = b->g;
    size_t s = g->segment_count;
    const column cols[] = {{(void **)&g->segments, 2 * sizeof(lh_index)},
                           {(void **)&g->segment_marker, sizeof(lh_index)},
                           {(void **)&g->segment_line, sizeof(size_t)}};
    lh_status st = grow_columns(b, cols, 3, s + 1, &b->cap_segments);
    if (st != LH_OK) return st;
    g->segments[2 * s] = p;
    g->segments[2 * s + 1] = q;
    g->segment_marker[s] = marker;
    g->segment_line[s] = line;
    g->segment_count = s + 1;
    return LH_OK;
}

/* A seed point (a hole's x y z, a region's x y z attribute max_volume: width values)
 * appended to *vals / *lines, *count of them. */
static lh_status seed_add(lh__plc_build *b, double **vals, size_t **lines, size_t *count,
                          size_t *capv, const double *v, int width, size_t line)
{
    size_t n = *count;
    const column cols[] = {{(void **)vals, (size_t)width * sizeof(double)},
                           {(void **)lines, sizeof(size_t)}};
    lh_status st = grow_columns(b, cols, 2, n + 1, capv);
    if (st != LH_OK) return st;
    memcpy(*vals + (size_t)width * n, v, (size_t)width * sizeof(double));
    (*lines)[n] = line;
    *count = n + 1;
    return LH_OK;
}

lh_status lh__plc_hole(lh__plc_build *b, const double xyz[3], size_t line)
{
    lh_plc *g = b->g;
    return seed_add(b, &g->holes, &g->hole_line, &g->hole_count, &b->cap_holes, xyz, 3, line);
}

lh_status lh__plc_region(lh__plc_build *b, const double r[5], size_t line)
{
    lh_plc *g = b->g;
    return seed_add(b, &g->regions, &g->region_line, &g->region_count, &b->cap_regions, r, 5, line);
}

/* One lh_index array of a single element, for an offsets array with no item yet. */
static lh_status offsets_empty(lh__plc_build *b, lh_index **arr)
{
    if (*arr) return LH_OK;
    *arr = lh__alloc(&b->g->alloc_, sizeof(lh_index));
    return *arr ? LH_OK : LH_ERR_NOMEM;
}

lh_status lh__plc_build_done(lh__plc_build *b)
{
    lh_plc *g = b->g;
    lh_status st;
    /* lh__plc_facet and lh__plc_polygon keep a slot for the closing offset. */
    if ((st = offsets_empty(b, &g->facet_first)) || (st = offsets_empty(b, &g->facet_hole_first)) ||
        (st = offsets_empty(b, &g->polygon_first)))
        return st;
    g->facet_first[g->facet_count] = (lh_index)g->polygon_count;
    g->facet_hole_first[g->facet_count] = (lh_index)b->facet_holes;
    g->polygon_first[g->polygon_count] = (lh_index)b->vertices;
    b->facet_open = 0;
    return LH_OK;
}
