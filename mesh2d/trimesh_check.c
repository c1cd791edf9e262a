/*
 * trimesh_check.c — lh_cdt_check: the exact validity check of a constrained
 * Delaunay triangulation of a 2D domain. Edges are sorted records (low vertex, high
 * vertex, triangle, position); each decision is an exact orient_2 or incircle.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lh_alloc.h"
#include "lh_error.h"

typedef struct edge { lh_index lo, hi, t; int pos, seg; } edge;

static int edge_cmp(const void *x, const void *y)
{
    const edge *a = x, *b = y;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return a->t < b->t ? -1 : a->t > b->t;
}

static edge *find(edge *e, size_t n, lh_index a, lh_index b)
{
    const edge key = {a < b ? a : b, a < b ? b : a, -1, 0, 0};
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (edge_cmp(e + mid, &key) < 0) lo = mid + 1; else hi = mid;
    }
    return lo < n && e[lo].lo == key.lo && e[lo].hi == key.hi ? e + lo : NULL;
}

static lh_status fail(lh_error *err, const char *what, size_t i)
{
    if (err) snprintf(err->message, sizeof err->message, what, i);
    return LH_ERR_INVALID_MESH;
}

static lh_status check(lh_pred *pr, size_t n, const double *xy, size_t nt, const lh_index *tri,
                       size_t ns, const lh_index *segs, int boundary_free, edge *e, lh_error *err)
{
    for (size_t t = 0; t < nt; t++) {
        const double *p[3];
        for (int k = 0; k < 3; k++) {
            if (tri[3 * t + k] < 0 || (size_t)tri[3 * t + k] >= n)
                return fail(err, "triangle %zu names no point", t);
            p[k] = xy + 2 * (size_t)tri[3 * t + k];
        }
        if (lh_orient(pr, 2, p) <= 0)
            return fail(err, "triangle %zu is not counterclockwise with positive area", t);
        for (int k = 0; k < 3; k++) {
            const lh_index a = tri[3 * t + (k + 1) % 3], b = tri[3 * t + (k + 2) % 3];
            e[3 * t + k] = (edge){a < b ? a : b, a < b ? b : a, (lh_index)t, k, 0};
        }
    }
    qsort(e, 3 * nt, sizeof *e, edge_cmp);
    for (size_t s = 0; s < ns; s++) {
        edge *x = find(e, 3 * nt, segs[2 * s], segs[2 * s + 1]);
        if (!x) return fail(err, "subsegment %zu is not an edge of the triangulation", s);
        x->seg = 1;
        if (x + 1 < e + 3 * nt && x[1].lo == x->lo && x[1].hi == x->hi) x[1].seg = 1;
    }
    for (size_t i = 0; i < 3 * nt;) {
        size_t j = i + 1;
        while (j < 3 * nt && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        if (j - i > 2)
            return fail(err, "an edge of triangle %zu is shared by three triangles",
                        (size_t)e[i].t);
        if (j - i == 1 && !e[i].seg && !boundary_free)
            return fail(err, "a boundary edge of triangle %zu is not a subsegment", (size_t)e[i].t);
        if (j - i == 2) {
            const lh_index *A = tri + 3 * (size_t)e[i].t, *B = tri + 3 * (size_t)e[i + 1].t;
            /* the two must run the edge in opposite directions */
            if (A[(e[i].pos + 1) % 3] != B[(e[i + 1].pos + 2) % 3])
                return fail(err, "triangles %zu overlap across an edge", (size_t)e[i].t);
            if (!e[i].seg) {
                const double *p[4] = {xy + 2 * (size_t)A[0], xy + 2 * (size_t)A[1], xy + 2 * (size_t)A[2],
                                      xy + 2 * (size_t)B[e[i + 1].pos]};
                if (lh_insphere(pr, 2, p) < 0)
                    return fail(err,
                                "an unconstrained edge of triangle %zu is not locally Delaunay",
                                (size_t)e[i].t);
            }
        }
        i = j;
    }
    return LH_OK;
}

static lh_status cdt_check(size_t n, const double *xy, size_t tri_count, const lh_index *tris,
                           size_t seg_count, const lh_index *segs, int boundary_free,
                           const lh_allocator *alloc, lh_error *err)
{
    lh_allocator al;
    if (!lh__allocator_init(&al, alloc))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "the allocator lacks alloc or free");
    if ((n && !xy) || (tri_count && !tris) || (seg_count && !segs))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "%s is NULL with a count above 0",
                             n && !xy             ? "xy"
                             : tri_count && !tris ? "tris"
                                                  : "segs");
    for (size_t s = 0; s < 2 * seg_count; s++)
        if (segs[s] < 0 || (size_t)segs[s] >= n)
            return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                 "subsegment %zu: endpoint %lld is not a point (0..%zu)", s / 2,
                                 (long long)segs[s], n ? n - 1 : 0);
    if (tri_count > SIZE_MAX / (3 * sizeof(edge)))
        return lh__error_say(err, LH_ERR_TOO_LARGE,
                             "%zu triangles: more than the address space holds", tri_count);
    lh_pred *pr = NULL;
    edge *e = lh__alloc(&al, (tri_count ? 3 * tri_count : 1) * sizeof *e);
    lh_status st = e ? lh_pred_create(&al, &pr) : LH_ERR_NOMEM;
    if (st == LH_OK) st = check(pr, n, xy, tri_count, tris, seg_count, segs, boundary_free, e, err);
    lh_pred_free(pr);
    lh__free(&al, e);
    return st;
}

lh_status lh_cdt_check(size_t n, const double *xy, size_t tri_count, const lh_index *tris,
                       size_t seg_count, const lh_index *segs, int boundary_free,
                       const lh_allocator *alloc, lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(
        err, cdt_check(n, xy, tri_count, tris, seg_count, segs, boundary_free, alloc, err));
}
