/*
 * fuzz_tetrahedralize.c — libFuzzer target: lh_tetrahedralize and the recovery on
 * small PLCs decoded from the bytes, then lh_tetmesh_check on what it returns.
 *   byte 0: options — bit 0 convex_hull, bit 1 skip the intersection test (then the
 *           facets may cross and recovery must still end), bit 2 coordinates as int8
 *           (else a 0..3 grid: coplanar, cocircular, cospherical, duplicate points),
 *           bits 3-4 the scale 2^0, 2^200, 2^-200 or 2^40, bit 5 region attributes,
 *           bit 6 -Y (boundary_steiner off), bit 7 quality refinement (-q1.414);
 *   byte 1: points, 4 + (byte % 21); bit 7 second-order nodes; bit 6 the mesh refined
 *           again (-r: lh_plc_from_tetmesh, then regions_only and -q1.414), which
 *           must give a valid mesh conforming to that PLC, or a documented status;
 *   then 3 bytes a point; then facets, each a byte k (3 + k % 3 corners) and k point
 *   numbers (mod n), up to 24; then up to 2 hole points (3 bytes each, grid/2).
 * It must never crash or leak, and:
 *   - LH_OK: the mesh passes lh_tetmesh_check against the PLC (valid, conforming up to
 *     rounded Steiner points; facets and their edges carved away whole outside the
 *     surface pass) — or without it, still a valid mesh whose subfaces and
 *     subsegments are its faces and edges, when the facets intersect and the test was
 *     skipped (the PLC is not one: conformity is undefined) or a hole point is given
 *     (the check does not tell every polygon edge a hole carved away from a missing
 *     one: finding-hole-slit, a ring through one point twice beside two holes); its
 *     point count is the PLC's plus the Steiner points, none on the boundary with -Y;
 *   - a failure is a documented status with a one-line printable message.
 * Anything else aborts. Build as the other targets (fuzz/README.md).
 */
#include "fuzz_common.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXN 24
#define MAXF 24

typedef struct input {
    double xyz[3 * MAXN], holes[6];
    lh_index ff[MAXF + 1], pf[MAXF + 1], pv[5 * MAXF];
    lh_plc g;
    lh_tetmesh_options opt;
    int again; /* refine the mesh again (-r) */
} input;

static double coord(uint8_t b, int int8, int e)
{
    double x = int8 ? (double)(int8_t)b : (double)(b % 4);
    return ldexp(x, e);
}

/* The PLC and options the bytes say; 0 when too short. */
static int decode(const uint8_t *d, size_t size, input *in)
{
    static const int scales[4] = {0, 200, -200, 40};
    if (size < 2 + 12) return 0;
    memset(in, 0, sizeof *in);
    lh_tetmesh_options_default(&in->opt);
    in->opt.convex_hull = d[0] & 1;
    in->opt.check_intersections = !(d[0] & 2);
    in->opt.region_attributes = (d[0] >> 5) & 1;
    in->opt.boundary_steiner = !((d[0] >> 6) & 1); /* -Y: interior Steiner points only */
    in->opt.max_steiner = 100; /* bounds the time of recovery that cannot settle */
    in->opt.max_radius_edge = d[0] >> 7 ? 1.414 : 0;
    in->opt.second_order = d[1] >> 7;
    in->again = (d[1] >> 6) & 1;
    int int8 = (d[0] >> 2) & 1, e = scales[(d[0] >> 3) & 3];
    size_t n = 4 + d[1] % 21, at = 2;
    if (size < at + 3 * n) return 0;
    for (size_t i = 0; i < 3 * n; i++) in->xyz[i] = coord(d[at++], int8, e);
    size_t f = 0, v = 0;
    while (f < MAXF && at < size) {
        size_t k = 3 + d[at] % 3;
        if (at + 1 + k > size) break;
        at++;
        in->ff[f] = (lh_index)f, in->pf[f] = (lh_index)v;
        for (size_t j = 0; j < k; j++) in->pv[v++] = (lh_index)(d[at++] % n);
        f++;
        if (at < size && d[at] == 0xff) { /* holes follow */
            at++;
            break;
        }
    }
    in->ff[f] = (lh_index)f, in->pf[f] = (lh_index)v;
    size_t h = 0;
    while (h < 2 && at + 3 <= size) {
        for (int j = 0; j < 3; j++) in->holes[3 * h + j] = ldexp(coord(d[at++], int8, e), -1);
        h++;
    }
    lh_plc *g = &in->g;
    g->n = n, g->xyz = in->xyz;
    g->facet_count = g->polygon_count = f;
    g->facet_first = in->ff, g->polygon_first = in->pf, g->polygon_vertices = in->pv;
    g->hole_count = h, g->holes = in->holes;
    return 1;
}

static int documented(lh_status st)
{
    return st == LH_ERR_INVALID_ARGUMENT || st == LH_ERR_DEGENERATE ||
           st == LH_ERR_INTERSECTING_FACETS || st == LH_ERR_STEINER_LIMIT ||
           st == LH_ERR_CROSSING_SEGMENTS;
}

static void printable(const char *msg)
{
    if (!msg[0]) abort();
    for (const char *k = msg; *k; k++)
        if (*k < 0x20 || *k > 0x7e) abort();
}

/* The points: the n corners, then with second order one midpoint node per tet edge,
 * each named alike by lh_tetmesh_tet_midpoints and lh_tetmesh_midpoint. */
static int second_order_ok(const lh_tetmesh *m, size_t n, int second)
{
    static const int e[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    const lh_index *tv = lh_tetmesh_tets(m), *mid = lh_tetmesh_tet_midpoints(m);
    const size_t np = lh_tetmesh_point_count(m), nt = lh_tetmesh_tet_count(m);
    if (!second) return np == n && !mid;
    if (np < n || (nt && !mid)) return 0;
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 6; k++) {
            const lh_index x = mid[6 * t + k];
            if (x < (lh_index)n || (size_t)x >= np ||
                x != lh_tetmesh_midpoint(m, tv[4 * t + e[k][1]], tv[4 * t + e[k][0]]))
                return 0;
        }
    return 1;
}

/* -r: mesh m as the PLC it bounds, refined with regions_only: a valid mesh conforming
 * to that PLC, or a documented status (aborts otherwise). */
static void refine_again(const lh_tetmesh *m, const input *in, const lh_allocator *al)
{
    lh_plc g;
    lh_error err;
    lh_status st = lh_plc_from_tetmesh(lh_tetmesh_point_count(m), lh_tetmesh_points(m), lh_tetmesh_point_markers(m),
                                       lh_tetmesh_tet_count(m), lh_tetmesh_tets(m), lh_tetmesh_tet_attrs(m), al, &g,
                                       &err);
    if (st != LH_OK) {
        if (!documented(st)) abort();
        printable(err.message);
        return;
    }
    lh_tetmesh_options o = in->opt;
    o.regions_only = 1, o.max_radius_edge = 1.414, o.second_order = 0, o.check_intersections = 1;
    lh_tetmesh *r = NULL;
    st = lh_tetrahedralize(&g, &o, &r, &err);
    if (st == LH_OK) {
        lh_error cerr;
        if (lh_tetmesh_check(lh_tetmesh_point_count(r), lh_tetmesh_points(r), lh_tetmesh_tet_count(r),
                             lh_tetmesh_tets(r), lh_tetmesh_face_count(r), lh_tetmesh_faces(r),
                             lh_tetmesh_face_parents(r), lh_tetmesh_edge_count(r), lh_tetmesh_edges(r), 0, &g,
                             NULL, NULL, &cerr) != LH_OK) {
            fprintf(stderr, "fuzz_tetrahedralize: the mesh refined again fails its check: %s\n", cerr.message);
            abort();
        }
    } else {
        if (r || !documented(st)) abort();
        printable(err.message);
    }
    lh_tetmesh_free(r);
    lh_plc_free(&g);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static input in;
    if (!decode(data, size, &in)) return 0;
    long live = 0;
    lh_allocator al = {lh_fuzz_count_alloc, lh_fuzz_count_free, &live};
    in.opt.alloc = &al;
    lh_tetmesh *m = NULL;
    lh_error err;
    lh_status st = lh_tetrahedralize(&in.g, &in.opt, &m, &err);
    if (st == LH_OK) {
        lh_tetmesh_stats s;
        lh_tetmesh_stats_get(m, &s);
        if (!second_order_ok(m, in.g.n + s.steiner_points, in.opt.second_order)) abort();
        lh_tetmesh_quality q;
        if (lh_tetmesh_measure(lh_tetmesh_point_count(m), lh_tetmesh_points(m), lh_tetmesh_tet_count(m),
                               lh_tetmesh_tets(m), &al, &q, &err) != LH_OK ||
            q.tets != lh_tetmesh_tet_count(m))
            abort();
        if (!in.opt.boundary_steiner && s.steiner_on_segments + s.steiner_on_facets) abort();
        size_t off = 0, pairs = 0;
        lh_error cerr;
        if (!in.opt.check_intersections &&
            lh_plc_intersections(&in.g, NULL, 0, NULL, &pairs, &cerr) != LH_OK)
            abort();
        lh_status ck = lh_tetmesh_check(
            lh_tetmesh_point_count(m), lh_tetmesh_points(m), lh_tetmesh_tet_count(m),
            lh_tetmesh_tets(m), lh_tetmesh_face_count(m), lh_tetmesh_faces(m),
            lh_tetmesh_face_parents(m), lh_tetmesh_edge_count(m), lh_tetmesh_edges(m),
            in.opt.convex_hull || in.g.facet_count == 0, pairs || in.g.hole_count ? NULL : &in.g,
            &off, NULL, &cerr);
        if (ck != LH_OK) {
            fprintf(stderr, "fuzz_tetrahedralize: the mesh fails its check: %s\n", cerr.message);
            abort();
        }
        if (in.again) refine_again(m, &in, &al);
    } else {
        if (m || !documented(st)) abort();
        printable(err.message);
    }
    lh_tetmesh_free(m);
    if (live != 0) abort();
    return 0;
}
