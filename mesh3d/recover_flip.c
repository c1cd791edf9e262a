/*
 * recover_flip.c — constraints recovered by flips before any is split (Si, "TetGen, a
 * Delaunay-based quality tetrahedral mesh generator", ACM TOMS 41(2) 2015, sec. 3.2;
 * Shewchuk, "Updating and constructing constrained Delaunay and constrained regular
 * triangulations by flips", SoCG 2003).
 *
 * A subsegment a b that is not an edge leaves a through the face opposite a of the
 * one tet whose cone at a holds b strictly. A 2-3 flip of that face, when the two
 * tets beside it form a convex union, makes an edge from a to the far apex and takes
 * one tet off the way to b; when their union is not convex, or when a b runs inside a
 * face from a, an edge of that face is removed instead (Shewchuk's edge removal: the
 * 3-2, 4-4 and 2-2 flips and larger rings). A try from a, then from b, that does not
 * end in the edge is undone. Edges in the way are tried in coordinate order, each
 * first by a plain removal, then with its ring lowered one level, and so on; an
 * edge one removal took out is not made again by another for the same constraint.
 * Patches are recovered next (recover_flip_patch.c). Flips never remove a subsegment
 * (t3_ctx.lock), and each new tet is checked positive exactly, the same region filled.
 * What flips do not recover is split (recover.c); the mesh is loaded again from the
 * Delaunay tetrahedralization after each round's insertions, so a round's flips start
 * from the point set alone. Constraints are taken in the order of their points'
 * coordinates, and every choice is geometric, so the result does not depend on the
 * input's order. Mesh improvement (improve.c) uses the same edge removal and 2-3
 * flip, each kept only when the tets it makes beat the worst it takes out.
 */
#include "recover.h"
#include "tet_geom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Flips tried on one constraint before it is left to splitting. */
#define T3_FLIPS_PER_CONSTRAINT 64

static const double *pt(const t3_ctx *c, lh_index p)
{
    return c->xyz + 3 * (size_t)p;
}

int lh__t3_orient4(t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e)
{
    const double *p[4] = {pt(c, a), pt(c, b), pt(c, d), pt(c, e)};
    return lh_orient(c->pred, 3, p);
}

double lh__t3_shape(const t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e)
{
    const double *p[4] = {pt(c, a), pt(c, b), pt(c, d), pt(c, e)};
    double u[3][3], big = 0, l = 0;
    int ex;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) big = fmax(big, fabs(u[i][k] = p[i + 1][k] - p[0][k]));
    frexp(big, &ex);
    const double unit = ldexp(1, -ex); /* exact: a power of two, in range */
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) u[i][k] *= unit;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            double w = u[(i + 1) % 3][k] - u[i][k];
            l += u[i][k] * u[i][k] + w * w;
        }
    double v = u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) -
               u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0]) +
               u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]);
    double r = l > 0 && isfinite(l) ? fabs(v) / (l * sqrt(l)) : 0;
    return isfinite(r) ? r : 0;
}

/* The shape of tet a b d e that a flip would make: 0 (no better than any) when, after
 * refinement, it would break a bound refinement met: its volume over the region's
 * bound, its circumradius over the sizing's size at its circumcentre. */
static double made_shape(const t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e, double shape)
{
    if (!c->flip_bounded || (!(c->flip_volume > 0) && !c->opt->sizing)) return shape;
    lh_index v[4] = {a, b, d, e};
    lh__t3_sort_points(c, v, 4);
    const double *p[4] = {pt(c, v[0]), pt(c, v[1]), pt(c, v[2]), pt(c, v[3])};
    t3_tet_measure m;
    lh__t3_tet_measure(p, &m);
    if (c->flip_volume > 0 && lh__t3_volume_over(&m, c->flip_volume)) return 0;
    const double h = c->opt->sizing ? c->opt->sizing(c->opt->sizing_user, m.cc) : 0;
    return h > 0 && isfinite(h) && m.radius > h ? 0 : shape;
}

static int has(const lh_index *t, lh_index v)
{
    return t[0] == v || t[1] == v || t[2] == v || t[3] == v;
}

static int slot_of(const lh_index *t, lh_index v)
{
    for (int j = 0; j < 4; j++)
        if (t[j] == v) return j;
    return -1;
}

/* ---- the order constraints are taken in ---- */

typedef struct keyed {
    double key[9];
    lh_index i;
} keyed;

static int cmp_keyed(const void *x, const void *y)
{
    const keyed *a = x, *b = y;
    for (int k = 0; k < 9; k++)
        if (a->key[k] != b->key[k]) return a->key[k] < b->key[k] ? -1 : 1;
    return 0;
}

static int cmp_point(const double *p, const double *q)
{
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

double lh__t3_shape_sorted(const t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e)
{
    lh_index v[4] = {a, b, d, e};
    lh__t3_sort_points(c, v, 4);
    return lh__t3_shape(c, v[0], v[1], v[2], v[3]);
}

/* The patch's first triangle's corners' coordinates, in coordinate order. */
static void patch_key(const t3_ctx *c, size_t k, double *key)
{
    const lh_index *t = c->tri + 3 * (size_t)c->patch_tri[c->patch_first[k]];
    const double *p[3] = {pt(c, t[0]), pt(c, t[1]), pt(c, t[2])};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2 - a; b++)
            if (cmp_point(p[b], p[b + 1]) > 0) {
                const double *x = p[b];
                p[b] = p[b + 1];
                p[b + 1] = x;
            }
    for (int i = 0; i < 3; i++) memcpy(key + 3 * i, p[i], 3 * sizeof(double));
}

static lh_status orders(t3_ctx *c)
{
    size_t m = c->seg_count > c->patch_count ? c->seg_count : c->patch_count;
    keyed *kb = lh__alloc(&c->al, (m + 1) * sizeof(keyed));
    c->seg_order = lh__alloc(&c->al, (c->seg_count + 1) * sizeof(lh_index));
    c->patch_order = lh__alloc(&c->al, (c->patch_count + 1) * sizeof(lh_index));
    if (!kb || !c->seg_order || !c->patch_order) {
        lh__free(&c->al, kb);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    for (size_t s = 0; s < c->seg_count; s++) {
        memcpy(kb[s].key, pt(c, c->seg[s].a), 3 * sizeof(double));
        memcpy(kb[s].key + 3, pt(c, c->seg[s].b), 3 * sizeof(double));
        kb[s].key[6] = kb[s].key[7] = kb[s].key[8] = 0;
        kb[s].i = (lh_index)s;
    }
    if (c->seg_count) qsort(kb, c->seg_count, sizeof(keyed), cmp_keyed);
    for (size_t s = 0; s < c->seg_count; s++) c->seg_order[s] = kb[s].i;
    for (size_t k = 0; k < c->patch_count; k++) {
        patch_key(c, k, kb[k].key);
        kb[k].i = (lh_index)k;
    }
    if (c->patch_count) qsort(kb, c->patch_count, sizeof(keyed), cmp_keyed);
    for (size_t k = 0; k < c->patch_count; k++) c->patch_order[k] = kb[k].i;
    lh__free(&c->al, kb);
    return LH_OK;
}

/* ---- what no flip may remove: the subsegments, the edges of patches recovered ---- */

static lh_status count_lock(t3_ctx *c, lh_index p, lh_index q, lh_index s, size_t i, void *total)
{
    (void)q, (void)s, (void)i;
    c->lock_first[p + 1]++;
    ++*(size_t *)total;
    return LH_OK;
}

static lh_status put_lock(t3_ctx *c, lh_index p, lh_index q, lh_index s, size_t i, void *unused)
{
    (void)s, (void)i, (void)unused;
    c->lock[c->lock_first[p]++] = q;
    return LH_OK;
}

/* lock_first and lock: the subsegments by their smaller end (a counting sort). */
static lh_status locks(t3_ctx *c)
{
    if (c->xlock_count) memset(c->xlock, 0xff, 2 * c->xlock_cap * sizeof(lh_index));
    c->xlock_count = 0;
    size_t total = 0;
    lh_status st = lh__t3_room(c, &c->lock_first, &c->lock_first_cap, c->n + 1);
    if (st != LH_OK) return st;
    memset(c->lock_first, 0, (c->n + 1) * sizeof(lh_index));
    if ((st = lh__t3_each_subsegment(c, count_lock, &total)) != LH_OK) return st;
    if ((st = lh__t3_room(c, &c->lock, &c->lock_cap, total + 1)) != LH_OK) return st;
    for (size_t v = 0; v < c->n; v++) c->lock_first[v + 1] += c->lock_first[v];
    if ((st = lh__t3_each_subsegment(c, put_lock, NULL)) != LH_OK) return st;
    for (size_t v = c->n; v > 0; v--) c->lock_first[v] = c->lock_first[v - 1];
    c->lock_first[0] = 0;
    return LH_OK;
}

/* The slot of edge p q (p < q) in the hash set xlock: where it is, else the empty
 * slot it would go in (linear probing; the set is at most half full). */
static lh_index *xlock_slot(const t3_ctx *c, lh_index p, lh_index q)
{
    size_t mask = c->xlock_cap - 1;
    size_t h = ((size_t)p * 0x9E3779B97F4A7C15u ^ (size_t)q * 0xC2B2AE3D27D4EB4Fu) & mask;
    for (;; h = (h + 1) & mask) {
        lh_index *e = c->xlock + 2 * h;
        if (e[0] < 0 || (e[0] == p && e[1] == q)) return e;
    }
}

lh_status lh__t3_lock(t3_ctx *c, lh_index p, lh_index q)
{
    if (p > q) {
        lh_index x = p;
        p = q;
        q = x;
    }
    if (2 * (c->xlock_count + 1) > c->xlock_cap) { /* rehash into twice the slots */
        size_t old_cap = c->xlock_cap, cap = old_cap ? 2 * old_cap : 64;
        lh_index *old = c->xlock, *x = lh__alloc(&c->al, 2 * cap * sizeof(lh_index));
        if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        memset(x, 0xff, 2 * cap * sizeof(lh_index));
        c->xlock = x, c->xlock_cap = cap;
        for (size_t i = 0; i < old_cap; i++)
            if (old[2 * i] >= 0)
                memcpy(xlock_slot(c, old[2 * i], old[2 * i + 1]), old + 2 * i,
                       2 * sizeof(lh_index));
        lh__free(&c->al, old);
    }
    lh_index *e = xlock_slot(c, p, q);
    if (e[0] < 0) e[0] = p, e[1] = q, c->xlock_count++;
    return LH_OK;
}

int lh__t3_locked(const t3_ctx *c, lh_index p, lh_index q)
{
    if (p > q) {
        lh_index x = p;
        p = q;
        q = x;
    }
    for (lh_index i = c->lock_first[p]; i < c->lock_first[p + 1]; i++)
        if (c->lock[i] == q) return 1;
    return c->xlock_count && *xlock_slot(c, p, q) >= 0;
}

/* ---- flips ---- */

/* The 2-3 flip of face j of tet t (opposite its point a) with the tet beyond, whose
 * far point is q: when a q crosses the face's interior and every new tet's shape is
 * over floor (at least T3_SLIVER). */
static lh_status flip23(t3_ctx *c, lh_index t, int j, double floor, int *done)
{
    *done = 0;
    lh_index u = c->tn[4 * (size_t)t + j];
    if (u < 0) return LH_OK;
    const lh_index *tv = c->tv + 4 * (size_t)t, a = tv[j];
    lh_index f[3], w = 0, q = -1;
    for (int k = 0; k < 4; k++)
        if (k != j) f[w++] = tv[k];
    for (int k = 0; k < 4; k++)
        if (!has(tv, c->tv[4 * (size_t)u + k])) q = c->tv[4 * (size_t)u + k];
    int s0 = lh__t3_orient4(c, a, q, f[0], f[1]), s1 = lh__t3_orient4(c, a, q, f[1], f[2]);
    int s2 = lh__t3_orient4(c, a, q, f[2], f[0]);
    if (s0 == 0 || s0 != s1 || s1 != s2) return LH_OK;
    for (int k = 0; k < 3; k++) {
        const double sh = floor > 0 ? made_shape(c, a, q, f[k], f[(k + 1) % 3],
                                                 lh__t3_shape_sorted(c, a, q, f[k], f[(k + 1) % 3]))
                                    : lh__t3_shape(c, a, q, f[k], f[(k + 1) % 3]);
        if (sh < T3_SLIVER || sh <= floor) return LH_OK;
    }
    lh_index old[2] = {t, u};
    lh_index nv[3][4] = {{a, q, f[0], f[1]}, {a, q, f[1], f[2]}, {a, q, f[2], f[0]}};
    return lh__t3_mesh_replace(c, old, 2, nv, 3, done);
}

/* Ring sizes edge removal triangulates: up to T3_RING points around the edge; rings
 * of up to T3_RING_MAX are first lowered by degree-lowering flips (reduce). */
#define T3_RING 7
#define T3_RING_MAX 12

/* The points around edge x y, in the turn of orient(x, y, r_i, r_i+1) > 0, and the
 * tets between them: *closed, or an open fan from one hull face to the other. */
typedef struct ring {
    lh_index x, y, r[T3_RING_MAX + 1], t[T3_RING_MAX];
    int k, closed; /* k points; k tets when closed, k - 1 when open */
} ring;

/* The other two points of tet t than x and y, in the turn around x y. */
static void others(t3_ctx *c, lh_index t, lh_index x, lh_index y, lh_index *u, lh_index *w)
{
    const lh_index *tv = c->tv + 4 * (size_t)t;
    lh_index o[2];
    int n = 0;
    for (int j = 0; j < 4; j++)
        if (tv[j] != x && tv[j] != y) o[n++] = tv[j];
    int s = lh__t3_orient4(c, x, y, o[0], o[1]);
    *u = s > 0 ? o[0] : o[1], *w = s > 0 ? o[1] : o[0];
}

/* The far point of the tet beside t across its face without point `off`, and that
 * tet (-1: the hull). */
static lh_index across(t3_ctx *c, lh_index t, lh_index off, lh_index keep0, lh_index keep1,
                       lh_index keep2, lh_index *far)
{
    lh_index u = c->tn[4 * (size_t)t + slot_of(c->tv + 4 * (size_t)t, off)];
    for (int j = 0; u >= 0 && j < 4; j++) {
        lh_index v = c->tv[4 * (size_t)u + j];
        if (v != keep0 && v != keep1 && v != keep2) *far = v;
    }
    return u;
}

/* The ring of edge x y from tet t; 0 when it has more than T3_RING_MAX points. */
static int ring_of(t3_ctx *c, lh_index t, lh_index x, lh_index y, ring *g)
{
    lh_index a, b, cur = t, far = -1;
    g->x = x, g->y = y;
    others(c, t, x, y, &a, &b);
    for (int step = 0;; step++) { /* back to the hull, or round to t */
        if (step > T3_RING_MAX) return 0;
        lh_index u = across(c, cur, b, x, y, a, &far);
        if (u < 0 || u == t) break;
        b = a, a = far, cur = u;
    }
    g->k = 0;
    g->r[g->k++] = a;
    for (lh_index start = cur;;) {
        if (g->k > T3_RING_MAX) return 0;
        g->t[g->k - 1] = cur;
        g->r[g->k++] = b;
        lh_index u = across(c, cur, a, x, y, b, &far);
        if (u == start) {
            g->closed = 1, g->k--;
            return g->k <= T3_RING_MAX;
        }
        if (u < 0) {
            g->closed = 0;
            return g->k <= T3_RING_MAX;
        }
        a = b, b = far, cur = u;
    }
}

static int before(const t3_ctx *c, lh_index p, lh_index q)
{
    return cmp_point(pt(c, p), pt(c, q)) < 0;
}

/* A closed ring turned to start at its point first in coordinates, so that what is
 * tried first does not depend on the tets' numbering. */
static void ring_start(const t3_ctx *c, ring *g)
{
    if (!g->closed) return;
    int m = 0;
    for (int i = 1; i < g->k; i++)
        if (before(c, g->r[i], g->r[m])) m = i;
    lh_index r[T3_RING_MAX], t[T3_RING_MAX];
    for (int i = 0; i < g->k; i++) r[i] = g->r[(i + m) % g->k], t[i] = g->t[(i + m) % g->k];
    memcpy(g->r, r, sizeof r);
    memcpy(g->t, t, sizeof t);
}

/* A triangulation of the ring's k-gon (k <= T3_RING) as corner triples, each with its
 * corners in ring order; search() builds them in a fixed order: the triangle on edge
 * 0 (k-1) with apex m = 1 .. k-2, then the two sides' triangulations. */
typedef struct tris {
    int n; /* triangles so far */
    int v[T3_RING - 2][3];
} tris;

/* The search for the best triangulation of a ring (search below). */
typedef struct enum_ctx {
    t3_ctx *c;
    ring *g;
    int s;       /* the side x is on, once a triangle fixed it */
    double best; /* the best triangulation's worst tet shape so far (-1: none) */
    tris keep;   /* that triangulation */
    /* per triangle lo < m < hi of the ring, once known: the side x is on (0: not a
       triangle to use) and its two tets' worse shape — the search meets each often */
    signed char side[T3_RING][T3_RING][T3_RING];
    double w[T3_RING][T3_RING][T3_RING];
} enum_ctx;

/* Whether the edge between ring points i < j is a diagonal that one of the current
 * constraint's removals took out: a removal does not undo an earlier one, so that
 * two removals cannot take turns (a tabu list). */
static int makes_gone(const enum_ctx *e, int i, int j)
{
    const ring *g = e->g;
    if (j - i < 2 || (i == 0 && j == g->k - 1)) return 0;
    lh_index p = g->r[i] < g->r[j] ? g->r[i] : g->r[j], q = g->r[i] ^ g->r[j] ^ p;
    for (int k = 0; k < e->c->gone_count; k++)
        if (e->c->gone[2 * k] == p && e->c->gone[2 * k + 1] == q) return 1;
    return 0;
}

/* The side x is on of triangle lo m hi, 0 when x and y are not strictly on opposite
 * sides or it makes an edge gone; its tets' worse shape into *w. */
static int triangle_side(enum_ctx *e, int lo, int m, int hi, double *w)
{
    signed char *sd = &e->side[lo][m][hi];
    if (*sd == 2) {
        const ring *g = e->g;
        const lh_index a = g->r[lo], b = g->r[m], d = g->r[hi];
        int sx = lh__t3_orient4(e->c, a, b, d, g->x), sy = lh__t3_orient4(e->c, a, b, d, g->y);
        *sd = (signed char)(sx != 0 && sx == -sy && !makes_gone(e, lo, m) && !makes_gone(e, m, hi)
                                ? sx
                                : 0);
        if (*sd)
            e->w[lo][m][hi] = fmin(made_shape(e->c, g->x, a, b, d, lh__t3_shape(e->c, g->x, a, b, d)),
                                   made_shape(e->c, g->y, a, b, d, lh__t3_shape(e->c, g->y, a, b, d)));
    }
    *w = e->w[lo][m][hi];
    return *sd;
}

/* Depth-first over the triangulations of the polygons on the stack, keeping the
 * one whose worst tet (its shape so far: worst) is best; a triangle whose sides x
 * and y are not strictly opposite, or no better than the best, ends the branch. */
static void search(enum_ctx *e, tris *tr, int (*stack)[2], int top, double worst)
{
    if (top == 0) {
        e->best = worst, e->keep = *tr;
        return;
    }
    int lo = stack[top - 1][0], hi = stack[top - 1][1];
    if (hi - lo < 2) {
        search(e, tr, stack, top - 1, worst);
        return;
    }
    for (int m = lo + 1; m < hi; m++) {
        int *v = tr->v[tr->n];
        v[0] = lo, v[1] = m, v[2] = hi;
        double w;
        int sx = triangle_side(e, lo, m, hi, &w);
        if (!sx || (e->s && sx != e->s)) continue;
        w = fmin(w, worst);
        if (w <= e->best || w < T3_SLIVER) continue;
        int keep = e->s;
        e->s = sx;
        tr->n++;
        stack[top - 1][0] = lo, stack[top - 1][1] = m;
        stack[top][0] = m, stack[top][1] = hi;
        search(e, tr, stack, top + 1, w);
        stack[top - 1][0] = lo, stack[top - 1][1] = hi;
        tr->n--;
        e->s = keep;
    }
}

/* The worst shape of the tets around the ring's edge (improving: what a removal
 * must beat). */
static double ring_worst(t3_ctx *c, const ring *g)
{
    double w = INFINITY;
    for (int i = 0; i + 1 < g->k + g->closed; i++)
        w = fmin(w, lh__t3_shape(c, g->x, g->y, g->r[i], g->r[(i + 1) % g->k]));
    return w;
}

/* Edge removal, below. */
static lh_status remove_edge_at(t3_ctx *c, lh_index t, lh_index p, lh_index q, int depth,
                                int *done);

/* A tet holding p and q, or -1. */
static lh_status tet_of_edge(t3_ctx *c, lh_index p, lh_index q, lh_index *t)
{
    for (int i = 0; i < c->made_count; i++) /* the last flip's tets first */
        if (has(c->tv + 4 * (size_t)c->made[i], p) && has(c->tv + 4 * (size_t)c->made[i], q)) {
            *t = c->made[i];
            return LH_OK;
        }
    size_t k;
    lh_status st = lh__t3_mesh_star(c, p, &k);
    *t = -1;
    for (size_t i = 0; st == LH_OK && i < k && *t < 0; i++)
        if (has(c->tv + 4 * (size_t)c->sbuf[i], q)) *t = c->sbuf[i];
    return st;
}

/* When no triangulation of the ring removes its edge: r_i is taken off the ring by
 * the 2-3 flip of the face p q r_i (when r_i-1 r_i+1 crosses it), or by removing the
 * edge p r_i or q r_i (one level down), and the removal is tried again (Si 2015, sec.
 * 3.2: TetGen's flipnm lowers an edge's degree so). A branch that does not end in
 * the removal is undone. */
static lh_status reduce(t3_ctx *c, const ring *g, int depth, int *done)
{
    int lo = g->closed ? 0 : 1, hi = g->closed ? g->k : g->k - 1;
    *done = 0;
    for (int i = lo; i < hi && !*done; i++) {
        const size_t mark = c->jlen;
        const int gone = c->gone_count;
        lh_index t = g->t[(i + g->k - 1) % g->k], r = g->r[(i + g->k - 1) % g->k], u;
        int flipped;
        for (int way = 0; way < 3 && !*done; way++) { /* the face p q r_i flipped away, or
                                                         the edge p r_i or q r_i removed */
            lh_index ri = g->r[i], e = way == 1 ? g->x : g->y;
            lh_status st = LH_OK;
            if (way == 0)
                st = flip23(c, t, slot_of(c->tv + 4 * (size_t)t, r), 0, &flipped);
            else /* t holds x, y, r_i-1 and r_i: the edge e r_i */
                st = remove_edge_at(c, t, e, ri, depth, &flipped);
            if (st == LH_OK && flipped) st = tet_of_edge(c, g->x, g->y, &u);
            if (st == LH_OK && flipped && u >= 0)
                st = remove_edge_at(c, u, g->x, g->y, depth, done);
            if (st != LH_OK) return st;
            if (!*done) lh__t3_mesh_undo(c, mark), c->gone_count = gone;
        }
    }
    return LH_OK;
}

/* Levels of degree-lowering before an edge removal is given up, and the edge removals
 * one constraint may try (c->flip_budget): the time a constraint flips cannot recover
 * costs is bounded. */
#define T3_REDUCE_DEPTH 3
#define T3_RETRY_REMOVALS 100 /* on a later pass (T3_REMOVALS: recover.h) */

/* Edge removal (Shewchuk, "Two discrete optimization algorithms for the topological
 * improvement of tetrahedral meshes", 2002, sec. 3): the tets around edge p q of tet
 * t replaced by p and q joined to a triangulation of the ring of points around it —
 * the 3-2 flip for three, the 4-4 flip for four with two opposite points coplanar
 * with the edge, the 2-2 flip of two coplanar hull faces. Valid when every new tet
 * is positive: p and q strictly on opposite sides of every triangle, the same sides
 * for all; an open ring (an edge on the hull) needs its two end points coplanar with
 * p q, so that the hull keeps its shape. Never a subsegment. *done says whether.
 * A ring with no such triangulation, or of more than T3_RING points, is lowered first
 * (reduce) while depth allows. */
static lh_status remove_edge_at(t3_ctx *c, lh_index t, lh_index p, lh_index q, int depth, int *done)
{
    ring g;
    *done = 0;
    if (lh__t3_locked(c, p, q) || c->flip_budget == 0) return LH_OK;
    c->flip_budget--;
    if (before(c, q, p)) {
        lh_index x = p;
        p = q;
        q = x;
    }
    if (!ring_of(c, t, p, q, &g) || g.k < 3) return LH_OK;
    if (!g.closed && lh__t3_orient4(c, p, q, g.r[0], g.r[g.k - 1]) != 0) return LH_OK;
    ring_start(c, &g);
    if (g.k > T3_RING) return depth > 0 ? reduce(c, &g, depth - 1, done) : LH_OK;
    enum_ctx e = {c, &g, 0, c->improving ? ring_worst(c, &g) : -1, {0, {{0}}}, {{{0}}}, {{{0}}}};
    memset(e.side, 2, sizeof e.side);
    tris tr = {0, {{0}}};
    int stack[T3_RING][2] = {{0, g.k - 1}};
    search(&e, &tr, stack, 1, INFINITY);
    if (e.keep.n == 0) return depth > 0 ? reduce(c, &g, depth - 1, done) : LH_OK;
    lh_index nv[2 * (T3_RING - 2)][4];
    for (int i = 0; i < e.keep.n; i++)
        for (int s = 0; s < 2; s++) {
            nv[2 * i + s][0] = s ? q : p;
            for (int j = 0; j < 3; j++) nv[2 * i + s][j + 1] = g.r[e.keep.v[i][j]];
        }
    lh_status st = lh__t3_mesh_replace(c, g.t, g.closed ? g.k : g.k - 1, nv, 2 * e.keep.n, done);
    if (st == LH_OK && *done && c->gone_count < T3_GONE) {
        c->gone[2 * c->gone_count] = p < q ? p : q;
        c->gone[2 * c->gone_count++ + 1] = p < q ? q : p;
    }
    return st;
}

/* ---- the edges in the way, taken in coordinate order ---- */

/* Edge p q of tet t as a candidate for removal: c->fbuf gets (first end, second end,
 * t), ends in coordinate order, once per edge. */
lh_status lh__t3_candidate(t3_ctx *c, lh_index t, lh_index p, lh_index q, size_t *ne)
{
    if (before(c, q, p)) {
        lh_index x = p;
        p = q;
        q = x;
    }
    for (size_t i = 0; i < *ne; i++)
        if (c->fbuf[3 * i] == p && c->fbuf[3 * i + 1] == q) return LH_OK;
    lh_status st = lh__t3_room(c, &c->fbuf, &c->fcap, 3 * (*ne + 1));
    if (st != LH_OK) return st;
    c->fbuf[3 * *ne] = p, c->fbuf[3 * *ne + 1] = q, c->fbuf[3 * *ne + 2] = t;
    ++*ne;
    return LH_OK;
}

static int edge_before(const t3_ctx *c, const lh_index *e, const lh_index *f)
{
    int k = cmp_point(pt(c, e[0]), pt(c, f[0]));
    return k < 0 || (k == 0 && before(c, e[1], f[1]));
}

lh_status lh__t3_remove_first(t3_ctx *c, size_t ne, int *done)
{
    *done = 0;
    for (size_t i = 1; i < ne; i++) /* insertion sort: a handful of edges */
        for (size_t j = i; j > 0 && edge_before(c, c->fbuf + 3 * j, c->fbuf + 3 * (j - 1)); j--)
            for (int k = 0; k < 3; k++) {
                lh_index x = c->fbuf[3 * j + k];
                c->fbuf[3 * j + k] = c->fbuf[3 * (j - 1) + k];
                c->fbuf[3 * (j - 1) + k] = x;
            }
    for (int depth = 0; depth <= T3_REDUCE_DEPTH && !*done; depth++)
        for (size_t i = 0; i < ne && !*done; i++) {
            lh_status st = remove_edge_at(c, c->fbuf[3 * i + 2], c->fbuf[3 * i], c->fbuf[3 * i + 1],
                                          depth, done);
            if (st != LH_OK) return st;
        }
    return LH_OK;
}

/* Steps of plane_walk before it stops collecting. */
#define T3_WALK_STEPS 64

/* a b runs in the plane of the face a u w of tet t and crosses its edge u w: that
 * edge and the edges of the coplanar faces a b crosses after it, as candidates for
 * removal, until a b reaches b or a point, or leaves the plane (Sloan's walk, "A fast
 * algorithm for generating constrained Delaunay triangulations", 1993, in the plane
 * of coplanar faces: an edge whose removal is not valid may have one beyond it that
 * is). Which side of a b a point is on is the side of the plane through a, b and a
 * point o off the faces' plane. */
static lh_status plane_walk(t3_ctx *c, lh_index a, lh_index b, lh_index t, lh_index u, lh_index w,
                            size_t *ne)
{
    lh_index prev = a;
    for (int step = 0; step < T3_WALK_STEPS; step++) {
        lh_status st = lh__t3_candidate(c, t, u, w, ne);
        ring g;
        if (st != LH_OK || !ring_of(c, t, u, w, &g)) return st;
        lh_index z = -1, o = -1, tz = -1;
        const int nt = g.closed ? g.k : g.k - 1;
        for (int i = 0; i < g.k; i++) {
            if (g.r[i] == prev) continue;
            if (lh__t3_orient4(c, u, w, prev, g.r[i]) != 0) {
                o = g.r[i];
                continue;
            }
            z = g.r[i];
            tz = i < nt ? g.t[i] : g.t[i - 1];
        }
        if (z < 0 || o < 0 || z == b || lh__t3_collinear(c->pred, pt(c, a), pt(c, b), pt(c, z)))
            return LH_OK;
        int sz = lh__t3_orient4(c, a, b, o, z), su = lh__t3_orient4(c, a, b, o, u);
        if (sz == 0) return LH_OK;
        if (sz == su)
            prev = u, u = z;
        else
            prev = w, w = z;
        t = tz;
    }
    return LH_OK;
}

/* ---- segments ---- */

enum { CONE_NONE, CONE_EDGE, CONE_TET, CONE_FACE };

/* Whether a b is an edge (CONE_EDGE); else the tet *t around a whose cone at a holds
 * b strictly (CONE_TET: a b leaves t through its face opposite a), or holds it on one
 * face only, the one opposite corner *j (CONE_FACE: a b runs inside that face and
 * leaves it through its edge off a); else CONE_NONE (a b runs along an edge). */
static lh_status cone_tet(t3_ctx *c, lh_index a, lh_index b, lh_index *t, int *j, int *kind)
{
    size_t k;
    lh_status st = lh__t3_mesh_star(c, a, &k);
    *kind = CONE_NONE;
    for (size_t i = 0; i < k && st == LH_OK; i++) {
        const lh_index *tv = c->tv + 4 * (size_t)c->sbuf[i];
        if (has(tv, b)) {
            *kind = CONE_EDGE;
            return LH_OK;
        }
    }
    for (size_t i = 0; i < k && st == LH_OK; i++) {
        const lh_index *tv = c->tv + 4 * (size_t)c->sbuf[i];
        int neg = 0, zeros = 0, zero = -1;
        for (int m = 0; m < 4 && !neg; m++) {
            if (tv[m] == a) continue;
            const double *p[4];
            for (int q = 0; q < 4; q++) p[q] = pt(c, q == m ? b : tv[q]);
            int o = lh_orient(c->pred, 3, p);
            neg = o < 0;
            if (o == 0) zeros++, zero = m;
        }
        if (neg || zeros > 1) continue;
        *t = c->sbuf[i], *j = zero;
        *kind = zeros ? CONE_FACE : CONE_TET;
        if (!zeros) return LH_OK;
    }
    return st;
}

/* Flips toward the edge a b; *edge says whether it is one at the end. */
static lh_status flip_edge(t3_ctx *c, lh_index a, lh_index b, int *edge)
{
    *edge = 0;
    for (int it = 0; it < T3_FLIPS_PER_CONSTRAINT; it++) {
        lh_index t;
        int kind, done = 0, z;
        lh_status st = cone_tet(c, a, b, &t, &z, &kind);
        if (st != LH_OK || kind == CONE_NONE || kind == CONE_EDGE) {
            *edge = kind == CONE_EDGE;
            return st;
        }
        int j = slot_of(c->tv + 4 * (size_t)t, a);
        if (kind == CONE_FACE) { /* the edge of t off a and corner z is in the way */
            lh_index e[2], w = 0;
            size_t ne = 0;
            for (int m = 0; m < 4; m++)
                if (m != j && m != z) e[w++] = c->tv[4 * (size_t)t + m];
            if ((st = plane_walk(c, a, b, t, e[0], e[1], &ne)) != LH_OK) return st;
            if ((st = lh__t3_remove_first(c, ne, &done)) != LH_OK) return st;
            if (!done) return LH_OK;
            continue;
        }
        if ((st = flip23(c, t, j, 0, &done)) != LH_OK) return st;
        size_t ne = 0;
        for (int k = 0; !done && k < 4; k++) /* a reflex edge of the face */
            for (int m = k + 1; k != j && m < 4; m++)
                if (m != j && (st = lh__t3_candidate(c, t, c->tv[4 * (size_t)t + k],
                                                     c->tv[4 * (size_t)t + m], &ne)) != LH_OK)
                    return st;
        if (!done && (st = lh__t3_remove_first(c, ne, &done)) != LH_OK) return st;
        if (!done) return LH_OK;
    }
    return LH_OK;
}

void lh__t3_try_begin(t3_ctx *c, size_t budget)
{
    c->jlen = 0;
    c->flip_budget = budget;
    c->gone_count = 0;
}

/* Passes over the subsegments: what one pass's flips elsewhere made recoverable is
 * tried again in the next, while a pass recovers something. */
#define T3_FLIP_PASSES 4

/* Subsegment p q by flips from either end, with at most `budget` edge removals in
 * all, else left as it was (the journal undone); *edge says whether. */
static lh_status flip_subsegment(t3_ctx *c, lh_index p, lh_index q, size_t budget, int *edge)
{
    lh__t3_try_begin(c, budget);
    lh_status st = flip_edge(c, p, q, edge);
    if (st == LH_OK && !*edge) lh__t3_mesh_undo(c, 0); /* no trace of a failed try */
    c->gone_count = 0;
    if (st == LH_OK && !*edge) st = flip_edge(c, q, p, edge);
    if (st == LH_OK && !*edge) lh__t3_mesh_undo(c, 0);
    c->jlen = 0;
    return st;
}

/* The first pass over the segments in order: the subsegments flips did not recover,
 * in that order, into c->todo (2 each), *missing of them. */
static lh_status segment_pass(t3_ctx *c, size_t *missing)
{
    *missing = 0;
    for (size_t i = 0; i < c->seg_count; i++) {
        lh_index s = c->seg_order[i];
        size_t cl = (size_t)(c->node_first[s + 1] - c->node_first[s]) + 2;
        lh_status st = lh__t3_room(c, &c->vbuf, &c->vcap, cl);
        if (st != LH_OK) return st;
        lh__t3_chain(c, s, c->vbuf, c->vcap);
        for (size_t j = 0; j + 1 < cl; j++) {
            int edge;
            /* an edge of the loaded mesh stays one: flips remove no subsegment */
            if (lh__t3_has_edge(c, c->vbuf[j], c->vbuf[j + 1])) continue;
            st = flip_subsegment(c, c->vbuf[j], c->vbuf[j + 1], T3_REMOVALS, &edge);
            if (st != LH_OK) return st;
            if (edge) continue;
            if ((st = lh__t3_room(c, &c->todo, &c->todo_cap, 2 * (*missing + 1))) != LH_OK)
                return st;
            c->todo[2 * *missing] = c->vbuf[j], c->todo[2 * *missing + 1] = c->vbuf[j + 1];
            ++*missing;
        }
    }
    return LH_OK;
}

/* A later pass over those: the ones still missing kept, in order; *gained: how many
 * this pass recovered. What a first pass's search did not find, a retry finds when
 * flips elsewhere made it easy, so it searches less. */
static lh_status retry_pass(t3_ctx *c, size_t *missing, size_t *gained)
{
    size_t w = 0;
    *gained = 0;
    for (size_t i = 0; i < *missing; i++) {
        int edge;
        lh_status st =
            flip_subsegment(c, c->todo[2 * i], c->todo[2 * i + 1], T3_RETRY_REMOVALS, &edge);
        if (st != LH_OK) return st;
        if (edge) {
            ++*gained;
            continue;
        }
        c->todo[2 * w] = c->todo[2 * i], c->todo[2 * w + 1] = c->todo[2 * i + 1];
        w++;
    }
    *missing = w;
    return LH_OK;
}

lh_status lh__t3_flip(t3_ctx *c)
{
    lh_status st = c->seg_order ? LH_OK : orders(c);
    if (st == LH_OK) st = locks(c);
    if (st == LH_OK) st = lh__t3_room(c, &c->pmark, &c->pmark_cap, c->n);
    if (st == LH_OK) memset(c->pmark, 0, c->n * sizeof(lh_index)), c->pgen = 0;
    size_t missing = 0, gained = 1;
    c->flips = 0;
    c->journal = 1;
    if (st == LH_OK) st = segment_pass(c, &missing);
    for (int pass = 1; pass < T3_FLIP_PASSES && missing && gained && st == LH_OK; pass++)
        st = retry_pass(c, &missing, &gained);
    /* patches once every subsegment is an edge (recover_flip_patch.c) */
    for (size_t i = 0; missing == 0 && i < c->patch_count && st == LH_OK; i++)
        st = lh__t3_flip_patch(c, (size_t)c->patch_order[i]);
    c->journal = 0;
    if (st != LH_OK || c->flips == 0) return st; /* the stars are the loaded mesh's */
    lh__t3_mesh_compact(c);
    return lh__t3_stars(c);
}

lh_status lh__t3_locks(t3_ctx *c)
{
    return locks(c);
}

lh_status lh__t3_improve_edge(t3_ctx *c, lh_index t, lh_index p, lh_index q, int *done)
{
    c->improving = 1;
    lh_status st = remove_edge_at(c, t, p, q, 0, done);
    c->improving = 0;
    return st;
}

lh_status lh__t3_improve_face(t3_ctx *c, lh_index t, int j, int *done)
{
    const lh_index *tv = c->tv + 4 * (size_t)t, u = c->tn[4 * (size_t)t + j];
    const lh_index f0 = tv[(j + 1) % 4], f1 = tv[(j + 2) % 4], f2 = tv[(j + 3) % 4];
    *done = 0;
    if (u < 0 || (lh__t3_locked(c, f0, f1) && lh__t3_locked(c, f1, f2) && lh__t3_locked(c, f2, f0)))
        return LH_OK;
    const lh_index *uv = c->tv + 4 * (size_t)u;
    const double floor = fmin(lh__t3_shape_sorted(c, tv[0], tv[1], tv[2], tv[3]),
                              lh__t3_shape_sorted(c, uv[0], uv[1], uv[2], uv[3]));
    return flip23(c, t, j, floor, done);
}
