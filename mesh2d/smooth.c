/*
 * smooth.c — optional smoothing after refinement: each Steiner point that lies on no
 * segment moves towards the centroid of its neighbours (Laplacian smoothing; e.g.
 * Field 1988, "Laplacian smoothing and Delaunay triangulations": all the way, half or
 * a quarter of it, whichever is best) only when that raises the smallest angle of the
 * triangles around it, keeps every one of them positively
 * oriented (exact orient_2 with the new position) and within its area bound. Input
 * vertices and points on segments never move. After each pass Lawson's flips (Lawson
 * 1977) make the mesh constrained Delaunay again, which cannot lower the smallest
 * angle (the constrained Delaunay triangulation maximises it: Lee & Lin 1986), so the
 * mesh's smallest angle never goes down.
 */
#include <math.h>
#include <string.h>

#include "m2_geom.h"
#include "refine.h"

/* The ring of v's neighbours, counterclockwise, when v is interior (a closed fan of
 * at most cap triangles): their count, else 0. tri[i] is the triangle (v, ring[i],
 * ring[i+1]). */
static size_t ring_of(const lh__m2 *m, lh_index v, lh_index *ring, lh_index *tri, size_t cap)
{
    const lh_index t0 = m->vt[v];
    lh_index t = t0;
    size_t n = 0;
    do {
        if (t < 0 || n == cap) return 0;
        const int i = lh__m2_vpos(m, t, v);
        tri[n] = t;
        ring[n++] = m->v[3 * (size_t)t + (i + 1) % 3];
        t = m->nb[3 * (size_t)t + (i + 1) % 3]; /* across v - (i+2): counterclockwise */
    } while (t != t0);
    return n;
}

/* The sine of the smallest angle around v were it at c (-1: a triangle would turn
 * over or pass its area bound). The sine, from twice the area over two edge lengths
 * (m2_geom.h), keeps its relative precision at tiny angles, where a cosine is 1 to
 * the last bit. */
static double star_worst(const lh__m2 *m, const lh_index *ring, const lh_index *tri, size_t n,
                         const double *c, double max_area)
{
    double worst = 2;
    for (size_t i = 0; i < n; i++) {
        const double *a = lh__m2_pt(m, ring[i]), *b = lh__m2_pt(m, ring[(i + 1) % n]);
        if (lh__m2_orient_pt(m, ring[i], ring[(i + 1) % n], c) <= 0) return -1;
        double bound = max_area;
        if (m->tarea && m->tarea[tri[i]] > 0 && (bound <= 0 || m->tarea[tri[i]] < bound)) bound = m->tarea[tri[i]];
        lh__g_tri g;
        lh__g_measure(a, b, c, &g);
        if (lh__g_area_above(&g, bound)) return -1;
        worst = g.sin_min < worst ? g.sin_min : worst;
    }
    return worst;
}

/* Tries v at its neighbours' centroid, then halfway and a quarter of the way there;
 * moves it to the best of them if that beats where it is. Returns 1 when it moved. */
static int move(lh__m2 *m, lh_index v, double max_area)
{
    enum { CAP = 32 };
    lh_index ring[CAP], tri[CAP];
    const size_t n = ring_of(m, v, ring, tri, CAP);
    if (n < 3) return 0;
    double c[2] = {0, 0};
    for (size_t i = 0; i < n; i++) {
        const double *q = lh__m2_pt(m, ring[i]);
        c[0] += q[0] / (double)n, c[1] += q[1] / (double)n;
    }
    const double p[2] = {m->xy[2 * (size_t)v], m->xy[2 * (size_t)v + 1]};
    double best = star_worst(m, ring, tri, n, p, 0), at[2] = {p[0], p[1]};
    for (double f = 1; f > 0.2; f /= 2) {
        const double q[2] = {p[0] + f * (c[0] - p[0]), p[1] + f * (c[1] - p[1])};
        const double w = star_worst(m, ring, tri, n, q, max_area);
        if (w > best) best = w, at[0] = q[0], at[1] = q[1];
    }
    if (at[0] == p[0] && at[1] == p[1]) return 0; /* the smallest angle must grow */
    m->xy[2 * (size_t)v] = at[0];
    m->xy[2 * (size_t)v + 1] = at[1];
    return 1;
}

/* Flips the edge opposite corner k of t (with neighbour n across it) into the other
 * diagonal of their quadrilateral, keeping every link and subsegment. */
static void flip(lh__m2 *m, lh_index t, int k)
{
    lh_index *tv = m->v + 3 * (size_t)t, *tn = m->nb + 3 * (size_t)t, *ts = m->sg + 3 * (size_t)t;
    const lh_index n = tn[k];
    const int j = lh__m2_npos(m, n, t);
    lh_index *nv = m->v + 3 * (size_t)n, *nn = m->nb + 3 * (size_t)n, *ns = m->sg + 3 * (size_t)n;
    const lh_index a = tv[k], b = tv[(k + 1) % 3], c = tv[(k + 2) % 3], d = nv[j];
    /* t = (a, b, c), n = (d, c, b); after: t = (a, b, d), n = (d, c, a) */
    const lh_index t_ab = tn[(k + 2) % 3], t_ca = tn[(k + 1) % 3];
    const lh_index n_bd = nn[(j + 1) % 3], n_dc = nn[(j + 2) % 3];
    const lh_index s_ab = ts[(k + 2) % 3], s_ca = ts[(k + 1) % 3];
    const lh_index s_bd = ns[(j + 1) % 3], s_dc = ns[(j + 2) % 3];
    tv[0] = a, tv[1] = b, tv[2] = d;
    tn[0] = n_bd, tn[1] = n, tn[2] = t_ab; /* opposite a: b-d; opposite b: d-a; opposite d: a-b */
    ts[0] = s_bd, ts[1] = -1, ts[2] = s_ab;
    nv[0] = d, nv[1] = c, nv[2] = a;
    nn[0] = t_ca, nn[1] = t, nn[2] = n_dc; /* opposite d: c-a; opposite c: a-d; opposite a: d-c */
    ns[0] = s_ca, ns[1] = -1, ns[2] = s_dc;
    if (n_bd >= 0) m->nb[3 * (size_t)n_bd + lh__m2_npos(m, n_bd, n)] = t;
    if (t_ca >= 0) m->nb[3 * (size_t)t_ca + lh__m2_npos(m, t_ca, t)] = n;
    m->vt[a] = m->vt[b] = t;
    m->vt[c] = m->vt[d] = n;
}

/* Lawson's flips until every unconstrained edge is locally Delaunay. */
static lh_status restore_delaunay(lh__m2 *m, lh__m2_cavity *c)
{
    c->stack_count = 0;
    lh_status st;
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0 && (st = lh__m2_stack_push(m, c, (lh_index)t)) != LH_OK) return st;
    while (c->stack_count) {
        const lh_index t = c->stack[--c->stack_count];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * (size_t)t + k];
            if (n < 0 || m->sg[3 * (size_t)t + k] >= 0) continue;
            const lh_index *v = m->v + 3 * (size_t)t;
            const lh_index d = m->v[3 * (size_t)n + lh__m2_npos(m, n, t)];
            if (lh__m2_incircle(m, v[0], v[1], v[2], lh__m2_pt(m, d)) >= 0) continue;
            flip(m, t, k);
            if ((st = lh__m2_stack_push(m, c, t)) != LH_OK || (st = lh__m2_stack_push(m, c, n)) != LH_OK)
                return st;
            break;
        }
    }
    return LH_OK;
}

lh_status lh__m2_smooth(lh__m2 *m, lh__m2_cavity *c, int passes, double max_area, size_t *moved)
{
    *moved = 0;
    for (int pass = 0; pass < passes; pass++) {
        size_t k = 0;
        for (size_t v = m->n_input; v < m->np; v++)
            if (m->pseg[v] == -1 && m->vt[v] >= 0) k += (size_t)move(m, (lh_index)v, max_area);
        *moved += k;
        lh_status st = restore_delaunay(m, c);
        if (st != LH_OK) return st;
        if (!k) break;
    }
    return LH_OK;
}
