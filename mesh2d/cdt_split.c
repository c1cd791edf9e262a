/*
 * cdt_split.c — Triangle's -s: segments made edges of the Delaunay triangulation by
 * splitting them at their midpoints (Ruppert 1995's way of recovering segments, "true
 * to Ruppert's original algorithm" in Triangle's words) instead of being kept as
 * constrained edges. Run on the constrained Delaunay triangulation before the domain
 * is carved: every subsegment that is not locally Delaunay (the apex across it
 * strictly inside the circumcircle of the triangle on its other side) is split at its
 * midpoint, and the subsegments beside the new triangles are checked again, until
 * every subsegment is locally Delaunay. Then every edge is, so the triangulation of
 * the vertices and Steiner points is Delaunay and each segment a chain of its edges
 * (a conforming Delaunay triangulation of the graph; Triangle splits while it
 * inserts each segment, so its points may differ). A subsegment shorter than 2^-40
 * of the input's extent, or whose rounded midpoint is refused, stays constrained and
 * is counted; the Steiner budget stops the splitting.
 */
#include <math.h>

#include "m2_geom.h"
#include "refine.h"

/* Whether subsegment s is not locally Delaunay (both sides in the mesh). */
static int not_delaunay(const lh__m2 *m, lh_index s)
{
    int pos;
    const lh_index t = lh__m2_find_subseg(m, s, &pos);
    if (t < 0) return 0;
    const lh_index n = m->nb[3 * (size_t)t + pos];
    if (n < 0) return 0;
    const lh_index *v = m->v + 3 * (size_t)t;
    const lh_index d = m->v[3 * (size_t)n + lh__m2_npos(m, n, t)];
    return lh__m2_incircle(m, v[0], v[1], v[2], lh__m2_pt(m, d)) < 0;
}

static lh_status push(lh__m2 *m, lh_index **q, size_t *count, size_t *cap, lh_index s)
{
    if (!lh__m2_grow(m, (void **)q, *count, cap, *count + 1, sizeof(lh_index))) return LH_ERR_NOMEM;
    (*q)[(*count)++] = s;
    return LH_OK;
}

/* The new point pi on subsegment a-b: attributes linear along it, the mean of the
 * ends' (halved first where their sum overflows: never an infinity between finite
 * values, and the same double wherever the sum is finite). */
static void point_data(lh__m2 *m, lh_index pi, lh_index a, lh_index b)
{
    const int na = m->attr_count;
    for (int j = 0; j < na; j++) {
        const double x = m->attr[(size_t)a * na + j], y = m->attr[(size_t)b * na + j], sum = x + y;
        m->attr[(size_t)pi * na + j] = isfinite(sum) ? sum / 2 : x / 2 + y / 2;
    }
}

/* Whether subsegment s is at least the floor (fm * 2^fe) long. */
static int splittable(const lh__m2 *m, lh_index s, double fm, long fe)
{
    double d[2];
    const int e = lh__g_vec(lh__m2_pt(m, m->sv[2 * (size_t)s]), lh__m2_pt(m, m->sv[2 * (size_t)s + 1]), d);
    return lh__g_cmp(lh__g_len(d[0], d[1]), e, fm, fe) >= 0;
}

/* One split of subsegment s at its midpoint; the subsegments beside the new
 * triangles go on the queue. *done = 0 when the point was refused. */
static lh_status split(lh__m2 *m, lh__m2_cavity *c, lh__m2_ins *ins, lh_index s, lh_index **q,
                       size_t *count, size_t *cap, int *done)
{
    const lh_index a = m->sv[2 * (size_t)s], b = m->sv[2 * (size_t)s + 1];
    const double *pa = lh__m2_pt(m, a), *pb = lh__m2_pt(m, b);
    double p[2];
    lh__g_along(pa, pb, 0.5, p); /* the difference halved in a scaled frame: finite */
    ins->check_encroach = 0;
    ins->origin = NULL;
    lh_status st = lh__m2_insert_point(m, c, p, -1, s, ins);
    *done = st == LH_OK && ins->result == LH__M2_INSERTED;
    if (!*done) return st;
    point_data(m, ins->vertex, a, b);
    for (size_t i = 0; i < c->stack_count && st == LH_OK; i++)
        for (int k = 0; k < 3 && st == LH_OK; k++) {
            const lh_index e = m->sg[3 * (size_t)c->stack[i] + k];
            if (e >= 0) st = push(m, q, count, cap, e);
        }
    return st;
}

lh_status lh__m2_split_segments(lh__m2 *m, lh__m2_cavity *c, size_t max_steiner, size_t *added,
                                size_t *unsplit)
{
    lh_index *q = NULL;
    size_t count = 0, cap = 0;
    lh__m2_ins ins = {0};
    lh_status st = LH_OK;
    double fm;
    long fe;
    lh__m2_length_floor(m, &fm, &fe);
    *added = *unsplit = 0;
    for (size_t s = m->ns; s-- > 0 && st == LH_OK;) st = push(m, &q, &count, &cap, (lh_index)s);
    while (st == LH_OK && count && *added < max_steiner) {
        const lh_index s = q[--count];
        if (!not_delaunay(m, s)) continue;
        int done = 0;
        if (splittable(m, s, fm, fe) && (st = split(m, c, &ins, s, &q, &count, &cap, &done)) != LH_OK) break;
        *added += (size_t)done;
    }
    for (size_t s = 0; s < m->ns && st == LH_OK; s++) *unsplit += (size_t)not_delaunay(m, (lh_index)s);
    lh__free(&m->al, q);
    lh__free(&m->al, ins.enc);
    return st;
}
