/* plc_build_test.h — small lh_plc values built in C for the tests of facets and
 * their intersections: fixed-size arrays inside the struct, no allocation. */
#ifndef PLC_BUILD_TEST_H
#define PLC_BUILD_TEST_H

#include "lifthull.h"

#include <string.h>

typedef struct tplc {
    lh_plc g;
    double xyz[3 * 256];
    lh_index ff[2049], pf[2049], pv[8192], hf[2049];
    double fh[3 * 64];
    size_t nh;
} tplc;

/* An empty PLC whose arrays are b's own. */
static inline void tplc_init(tplc *b)
{
    memset(b, 0, sizeof *b);
    b->g.xyz = b->xyz;
    b->g.facet_first = b->ff;
    b->g.polygon_first = b->pf;
    b->g.polygon_vertices = b->pv;
    b->g.facet_hole_first = b->hf;
    b->g.facet_holes = b->fh;
}

static inline lh_index tplc_point(tplc *b, double x, double y, double z)
{
    double *p = b->xyz + 3 * b->g.n;
    p[0] = x, p[1] = y, p[2] = z;
    return (lh_index)b->g.n++;
}

/* Starts a facet (its polygons and holes follow). */
static inline void tplc_facet(tplc *b)
{
    const size_t f = b->g.facet_count++;
    b->ff[f + 1] = b->ff[f];
    b->hf[f + 1] = b->hf[f];
}

/* A polygon of m vertices in the current facet. */
static inline void tplc_polygon(tplc *b, size_t m, const lh_index *v)
{
    const size_t p = b->g.polygon_count++;
    memcpy(b->pv + b->pf[p], v, m * sizeof *v);
    b->pf[p + 1] = b->pf[p] + (lh_index)m;
    b->ff[b->g.facet_count]++;
}

/* A facet of one polygon. */
static inline void tplc_face(tplc *b, size_t m, const lh_index *v)
{
    tplc_facet(b);
    tplc_polygon(b, m, v);
}

/* A hole point in the current facet. */
static inline void tplc_hole(tplc *b, double x, double y, double z)
{
    double *p = b->fh + 3 * b->nh++;
    p[0] = x, p[1] = y, p[2] = z;
    b->hf[b->g.facet_count]++;
}

#endif
