/*
 * plc_check.c — an lh_plc's arrays checked before meshing: counts with their arrays,
 * offsets that rise, indices in range, every facet with a polygon of 3 or more points,
 * finite coordinates. Each fault is named with the item's number and, for what a
 * reader made, its line.
 */
#include "recover.h"

static size_t line_of(const size_t *lines, size_t i)
{
    return lines ? lines[i] : 0;
}

static lh_status bad(t3_ctx *c, size_t line, const char *what)
{
    return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line, "%s", what);
}

static lh_status check_arrays(t3_ctx *c)
{
    const lh_plc *g = c->g;
    if (g->n && !g->xyz) return bad(c, 0, "points: a count without coordinates");
    if (g->facet_count && (!g->facet_first || !g->polygon_first || !g->polygon_vertices))
        return bad(c, 0, "facets: a count without facet_first, polygon_first or polygon_vertices");
    if (g->segment_count && !g->segments) return bad(c, 0, "segments: a count without the array");
    if (g->hole_count && !g->holes) return bad(c, 0, "holes: a count without the array");
    if (g->region_count && !g->regions) return bad(c, 0, "regions: a count without the array");
    if (g->n >= (size_t)LH_INDEX_MAX / 8 || g->facet_count >= (size_t)LH_INDEX_MAX / 8)
        return lh__t3_say(c, LH_ERR_TOO_LARGE, 0, "more points or facets than lh_index numbers");
    return LH_OK;
}

static lh_status check_facet(t3_ctx *c, size_t f)
{
    const lh_plc *g = c->g;
    size_t line = line_of(g->facet_line, f);
    long shown = (long)f + g->first_index;
    lh_index p0 = g->facet_first[f], p1 = g->facet_first[f + 1];
    if (p0 < 0 || p1 < p0 || (size_t)p1 > g->polygon_count)
        return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line,
                          "facet %ld: polygon offsets out of order", shown);
    int ring = 0;
    for (lh_index p = p0; p < p1; p++) {
        lh_index v0 = g->polygon_first[p], v1 = g->polygon_first[p + 1];
        if (v0 < 0 || v1 <= v0)
            return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line,
                              "facet %ld: a polygon without points", shown);
        ring |= v1 - v0 >= 3;
        for (lh_index i = v0; i < v1; i++) {
            lh_index v = g->polygon_vertices[i];
            if (v < 0 || (size_t)v >= g->n)
                return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line,
                                  "facet %ld: point %ld does not exist (%zu points)", shown,
                                  (long)v + g->first_index, g->n);
        }
    }
    if (!ring)
        return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line,
                          "facet %ld has no polygon of 3 or more points", shown);
    return LH_OK;
}

static lh_status check_seeds(t3_ctx *c, const double *x, size_t count, int stride,
                             const size_t *lines, const char *what)
{
    for (size_t i = 0; i < count; i++)
        for (int k = 0; k < 3; k++)
            if (!(x[stride * i + k] - x[stride * i + k] == 0))
                return lh__t3_say(c, LH_ERR_NONFINITE, line_of(lines, i),
                                  "%s %zu: a coordinate is NaN or infinite", what,
                                  i + (size_t)c->g->first_index);
    return LH_OK;
}

lh_status lh__t3_plc_check(t3_ctx *c)
{
    const lh_plc *g = c->g;
    lh_status st = check_arrays(c);
    if (st != LH_OK) return st;
    if (g->facet_count && (g->facet_first[0] != 0 || g->polygon_first[0] != 0))
        return bad(c, 0, "facets: the offsets must start at 0");
    for (size_t f = 0; f < g->facet_count; f++)
        if ((st = check_facet(c, f)) != LH_OK) return st;
    for (size_t s = 0; s < 2 * g->segment_count; s++)
        if (g->segments[s] < 0 || (size_t)g->segments[s] >= g->n)
            return lh__t3_say(c, LH_ERR_INVALID_ARGUMENT, line_of(g->segment_line, s / 2),
                              "segment %zu: point %ld does not exist (%zu points)",
                              s / 2 + (size_t)g->first_index, (long)g->segments[s] + g->first_index,
                              g->n);
    lh_error e;
    if (lh_coords_validate(3, g->n, g->xyz, &e) != LH_OK)
        return lh__t3_say(c, LH_ERR_NONFINITE, line_of(g->point_line, e.index / 3),
                          "point %zu: a coordinate is NaN or infinite",
                          e.index / 3 + (size_t)g->first_index);
    if ((st = check_seeds(c, g->holes, g->hole_count, 3, g->hole_line, "hole")) != LH_OK) return st;
    return check_seeds(c, g->regions, g->region_count, 5, g->region_line, "region");
}
