/*
 * m2_locate.c — point location in the 2D mesh by the visibility walk (Devillers,
 * Pion & Teillaud 2002, "Walking in a triangulation"): step across an edge that has
 * p strictly on its far side, choosing among two such edges by a deterministic
 * pseudo-random rotation so that the walk cannot cycle for long; after 4 * live + 64
 * steps (never seen; a constrained triangulation gives no termination proof) every
 * triangle is tested in turn. Exact orientation tests throughout.
 */
#include "m2.h"

static int contains(const lh__m2 *m, lh_index t, const double *p)
{
    const lh_index *v = m->v + 3 * (size_t)t;
    return lh__m2_orient_pt(m, v[0], v[1], p) >= 0 && lh__m2_orient_pt(m, v[1], v[2], p) >= 0 &&
           lh__m2_orient_pt(m, v[2], v[0], p) >= 0;
}

lh_index lh__m2_scan(const lh__m2 *m, const double *p)
{
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0 && contains(m, (lh_index)t, p)) return (lh_index)t;
    return -1;
}

lh_index lh__m2_locate(lh__m2 *m, lh_index start, const double *p, int stop_at_segments,
                       lh_index *blocked)
{
    *blocked = -1;
    if (start < 0 || m->v[3 * (size_t)start] < 0) start = m->walk_hint;
    if (start < 0 || m->v[3 * (size_t)start] < 0) return lh__m2_scan(m, p);
    uint32_t rot = (uint32_t)start * 2654435761u;
    lh_index t = start;
    for (size_t step = 0, limit = 4 * m->live + 64; step < limit; step++) {
        const lh_index *v = m->v + 3 * (size_t)t;
        rot = rot * 1103515245u + 12345u;
        const int k0 = (int)((rot >> 16) % 3);
        int moved = 0;
        for (int i = 0; i < 3 && !moved; i++) {
            const int k = (k0 + i) % 3;
            if (lh__m2_orient_pt(m, v[(k + 1) % 3], v[(k + 2) % 3], p) >= 0) continue;
            if (stop_at_segments && m->sg[3 * (size_t)t + k] >= 0) {
                *blocked = m->sg[3 * (size_t)t + k];
                return t;
            }
            const lh_index n = m->nb[3 * (size_t)t + k];
            if (n < 0) return -1; /* outside the mesh */
            t = n;
            moved = 1;
        }
        if (!moved) {
            m->walk_hint = t;
            return t;
        }
    }
    return lh__m2_scan(m, p);
}

/* The straight walk along g -> p from triangle t, which holds g: each step leaves
 * through the edge x -> y (counterclockwise) with x right of or on the line and y left
 * of or on it, while p lies strictly beyond that edge. Stops at a subsegment
 * (*blocked) or the boundary (-1). 4 * live + 64 steps at most, then -1 with
 * *blocked = -1 (a degenerate line; never seen). */
lh_index lh__m2_walk_line(lh__m2 *m, lh_index t, const double *g, const double *p,
                          lh_index *blocked)
{
    *blocked = -1;
    lh_index prev = -1;
    for (size_t step = 0, limit = 4 * m->live + 64; step < limit; step++) {
        const lh_index *v = m->v + 3 * (size_t)t;
        int exit = -1;
        for (int k = 0; k < 3 && exit < 0; k++) {
            const lh_index x = v[(k + 1) % 3], y = v[(k + 2) % 3];
            if (m->nb[3 * (size_t)t + k] == prev && prev >= 0) continue;
            if (lh__m2_orient_pt(m, x, y, p) >= 0) continue;
            const double *px = lh__m2_pt(m, x), *py = lh__m2_pt(m, y);
            const double *ax[3] = {g, p, px}, *ay[3] = {g, p, py};
            if (lh_orient(m->pred, 2, ax) <= 0 && lh_orient(m->pred, 2, ay) >= 0) exit = k;
        }
        if (exit < 0) return t; /* p is in t (closed) */
        if (m->sg[3 * (size_t)t + exit] >= 0) {
            *blocked = m->sg[3 * (size_t)t + exit];
            return t;
        }
        prev = t;
        t = m->nb[3 * (size_t)t + exit];
        if (t < 0) return -1;
    }
    return -1;
}
