/*
 * recover_suppress.c — Steiner points taken off the boundary: once every constraint
 * is in the mesh and the domain is carved, each Steiner point p on a segment or inside
 * a facet is taken off it again, as TetGen does for -Y (Si 2015, its suppression of
 * boundary Steiner points; the construction here is this one's; docs/meshing3d.md):
 *   - the constraint faces around p, grouped by patch (p's fans), are triangulated
 *     again without p, each in its patch's projection, so that p's two subsegments
 *     become one edge (triangulate: the worst triangle best shaped; or fan_from a
 *     ring point);
 *   - those faces cut p's star (the tets around it) into sectors; each sector is
 *     filled again as the cone from one apex over its boundary: the faces opposite p,
 *     and the new facet faces on its side;
 *   - the apex is one of the sector's points (old_point) or a new point q, p moved a
 *     little into the sector (new_point); it is kept only when exact orient_3 puts it
 *     strictly on the inner side of every one of those faces it is not on. Then the
 *     cones tile the sector (each positive over a closed surface that goes once
 *     around the apex), and the apex is on no constraint.
 * New points cost nothing outside the domain (they are carved away); inside it they
 * are made only in the later passes: at most one per point without -Y, as many as
 * needed with -Y; the last passes take out those whose stars allow it. With -Y, a point left (on two segments, a star too large, no apex)
 * ends meshing with LH_ERR_STEINER_LIMIT naming it. Points are taken in coordinate
 * order, and every choice is made on coordinates (sort_star, sort_fans, canon_tet),
 * so the result does not depend on input order.
 */
#include "facets.h"
#include "lh_sort.h"
#include "recover.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The constraint faces: a hash set of sorted triples, each with its patch. */
typedef struct faceset {
    lh_index *slot; /* 4 per slot: the triple (-1: empty, -2: removed) and the patch */
    size_t cap;     /* a power of 2 */
} faceset;

static size_t fs_hash(const lh_index *f, size_t cap)
{
    uint64_t h = (uint64_t)f[0] * 0x9e3779b97f4a7c15u ^ (uint64_t)f[1] * 0xc2b2ae3d27d4eb4fu ^
                 (uint64_t)f[2] * 0x165667b19e3779f9u;
    return (size_t)(h ^ h >> 29) & (cap - 1);
}

/* The slot of sorted triple f, or of the first free one on its probe path. */
static lh_index *fs_find(const faceset *s, const lh_index *f, int for_insert)
{
    lh_index *free_slot = NULL;
    for (size_t i = fs_hash(f, s->cap);; i = (i + 1) & (s->cap - 1)) {
        lh_index *e = s->slot + 4 * i;
        if (e[0] == -1) return for_insert && free_slot ? free_slot : e;
        if (e[0] == -2) {
            if (!free_slot) free_slot = e;
            continue;
        }
        if (e[0] == f[0] && e[1] == f[1] && e[2] == f[2]) return e;
    }
}

/* The patch of face f (any order), or -1. */
static lh_index fs_get(const faceset *s, const lh_index *f0)
{
    lh_index f[3] = {f0[0], f0[1], f0[2]};
    lh__t3_sort3(f);
    const lh_index *e = fs_find(s, f, 0);
    return e[0] == -1 ? -1 : e[3];
}

static void fs_remove(faceset *s, const lh_index *f0)
{
    lh_index f[3] = {f0[0], f0[1], f0[2]};
    lh__t3_sort3(f);
    lh_index *e = fs_find(s, f, 0);
    if (e[0] >= 0) e[0] = -2;
}

/* Adds f with patch k (the first patch stays when f is there). The set holds at most
 * half its slots, removed ones included: the caller sized it for every face made. */
static void fs_put(faceset *s, const lh_index *f0, lh_index k)
{
    lh_index f[3] = {f0[0], f0[1], f0[2]};
    lh__t3_sort3(f);
    lh_index *e = fs_find(s, f, 1);
    if (e[0] >= 0) return;
    memcpy(e, f, 3 * sizeof(lh_index));
    e[3] = k;
}

static const double *pt(const t3_ctx *c, lh_index p)
{
    return c->xyz + 3 * (size_t)p;
}

static int cmp3(const double *p, const double *q)
{
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* Compares points lists x and y (n each) by coordinates. */
static int cmp_points(const t3_ctx *c, const lh_index *x, const lh_index *y, int n)
{
    for (int k = 0; k < n; k++) {
        const int r = cmp3(pt(c, x[k]), pt(c, y[k]));
        if (r) return r;
    }
    return 0;
}

/* Tets and faces of one point's suppression (bounded: a star larger fails). */
#define SUP_TETS 256
#define SUP_FANS 8    /* patches through p */
#define SUP_RING 32   /* points of one fan's ring */
#define SUP_SECTORS 8 /* sectors of p's star */
#define SUP_NEW (SUP_TETS + 2 * SUP_FANS * SUP_RING)

/* A patch's fan around p: its ring (the faces' sides opposite p, in order: a path, or
 * a cycle around p), the sectors on either side, and the ring triangulated again. */
typedef struct fan {
    lh_index patch;
    lh_index ring[SUP_RING];
    int len, closed;
    /* the sector on either side (-1: the hull); side 0 is where orient_3(p, a, b, .) > 0
       for its faces p a b in ring order */
    int side[2];
    lh_index tri[3 * SUP_RING]; /* the ring triangulated without p */
    int ntri;
} fan;

typedef struct sup {
    lh_index p;
    lh_index tet[SUP_TETS];
    int ntet, parent[SUP_TETS], sector[SUP_TETS], nsector;
    fan fan[SUP_FANS];
    int nfan;
    lh_index nv[SUP_NEW][4]; /* the new tets; -2 - i stands for sector i's apex */
    int nnew;
    lh_index apex[SUP_SECTORS]; /* sector i's apex: one of its points, or -1: q[i] */
    double q[SUP_SECTORS][3];
    unsigned char sector_out[SUP_SECTORS]; /* whether sector i is outside the domain */
    /* the whole run's */
    faceset fs;         /* the constraint faces */
    size_t used;        /* faces put in fs, removed ones included */
    unsigned char *out; /* per tet: 1 when outside the domain (carved) */
    size_t out_cap;
    int max_new; /* new points inside the domain a point's refill may make */
} sup;

static int find(int *parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

static int local(const sup *s, lh_index t)
{
    for (int i = 0; i < s->ntet; i++)
        if (s->tet[i] == t) return i;
    return -1;
}

/* Orders the fan's sides (pairs u v opposite p, in e) into a ring: a path from one end
 * to the other, or a cycle; 0 when they do not form one. */
static int ring_order(fan *f, const lh_index *e, int ne)
{
    int used[SUP_RING] = {0}, start = 0;
    if (ne + 1 > SUP_RING) return 0;
    for (int i = 0; i < ne; i++) { /* a path starts at a point in one side only */
        for (int k = 0; k < 2; k++) {
            int deg = 0;
            for (int j = 0; j < ne; j++)
                deg += e[2 * j] == e[2 * i + k] || e[2 * j + 1] == e[2 * i + k];
            if (deg == 1) start = 2 * i + k;
            if (deg > 2) return 0;
        }
    }
    f->ring[0] = e[start];
    f->len = 1;
    for (int n = 0; n < ne; n++) {
        lh_index at = f->ring[f->len - 1], next = -1;
        for (int j = 0; j < ne && next < 0; j++) {
            if (used[j]) continue;
            if (e[2 * j] == at)
                next = e[2 * j + 1];
            else if (e[2 * j + 1] == at)
                next = e[2 * j];
            if (next >= 0) used[j] = 1;
        }
        if (next < 0) return 0;
        f->ring[f->len++] = next;
    }
    f->closed = f->ring[f->len - 1] == f->ring[0];
    if (f->closed) f->len--;
    return f->len >= 2;
}

/* A triangle's shape: twice its area over the sum of its squared sides (0 when flat,
 * largest when equilateral), in units of 2^unit_exp; a float that only ranks ears. */
static double shape(const t3_ctx *c, lh_index a, lh_index b, lh_index d)
{
    double u[3], v[3], w[3], x[3];
    for (int k = 0; k < 3; k++) {
        u[k] = ldexp(pt(c, b)[k], -c->unit_exp) - ldexp(pt(c, a)[k], -c->unit_exp);
        v[k] = ldexp(pt(c, d)[k], -c->unit_exp) - ldexp(pt(c, a)[k], -c->unit_exp);
        w[k] = v[k] - u[k];
    }
    for (int k = 0; k < 3; k++)
        x[k] = u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3];
    const double l = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + v[0] * v[0] + v[1] * v[1] +
                     v[2] * v[2] + w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    return l > 0 ? sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / l : 0;
}

/* Whether closed segments a b and d e of the projection share a point other than a
 * common end. */
static int crosses(t3_ctx *c, int ax, lh_index a, lh_index b, lh_index d, lh_index e)
{
    if (a == d || a == e || b == d || b == e) return 0;
    const double *A = pt(c, a), *B = pt(c, b), *D = pt(c, d), *E = pt(c, e);
    const int o1 = lh__orient2_along(c->pred, ax, A, B, D),
              o2 = lh__orient2_along(c->pred, ax, A, B, E);
    const int o3 = lh__orient2_along(c->pred, ax, D, E, A),
              o4 = lh__orient2_along(c->pred, ax, D, E, B);
    if (o1 * o2 > 0 || o3 * o4 > 0) return 0;
    if (o1 || o2 || o3 || o4) return 1;
    const int k = (ax + 1) % 3, l = (ax + 2) % 3; /* collinear: overlap of the projections */
    for (int q = 0; q < 2; q++) {
        const int x = q ? l : k;
        if (fmax(A[x], B[x]) < fmin(D[x], E[x]) || fmax(D[x], E[x]) < fmin(A[x], B[x])) return 0;
    }
    return 1;
}

/* The polygon v (m points, turning sg in the projection along axis ax) triangulated
 * so that its worst triangle is best shaped (dynamic programming over its diagonals,
 * Klincsek 1980): rounded Steiner points make thin triangles whose planes stray from
 * the facet's, which no new point could then see past. A triangle is taken when it
 * turns sg exactly, holds no other point of v, and its sides cross no side of v. The
 * triangles go to out (3 each); 0 when v has no triangulation so. */
static int triangulate_dp(t3_ctx *c, int ax, int sg, const lh_index *v, int m, lh_index *out,
                          int *nout)
{
    static const double none = -1;
    double best[SUP_RING][SUP_RING];
    signed char via[SUP_RING][SUP_RING], open[SUP_RING][SUP_RING];
    for (int a = 0; a < m; a++)
        for (int b = a + 1; b < m; b++) { /* chord a b: a side of v, or crossing none */
            int ok = b == a + 1 || (a == 0 && b == m - 1);
            if (!ok) {
                ok = 1;
                for (int e = 0; e < m && ok; e++)
                    ok = !crosses(c, ax, v[a], v[b], v[e], v[(e + 1) % m]);
            }
            open[a][b] = (signed char)ok;
            best[a][b] = b == a + 1 ? HUGE_VAL : none;
        }
    for (int len = 2; len < m; len++)
        for (int a = 0; a + len < m; a++) {
            const int b = a + len;
            if (!open[a][b]) continue;
            for (int k = a + 1; k < b; k++) {
                if (best[a][k] < 0 || best[k][b] < 0 || !open[a][k] || !open[k][b]) continue;
                const double q = fmin(shape(c, v[a], v[k], v[b]), fmin(best[a][k], best[k][b]));
                if (q <= best[a][b]) continue;
                if (lh__orient2_along(c->pred, ax, pt(c, v[a]), pt(c, v[k]), pt(c, v[b])) != sg)
                    continue;
                int empty = 1;
                for (int e = 0; e < m && empty; e++) {
                    if (e == a || e == k || e == b) continue;
                    const double *x = pt(c, v[e]);
                    empty =
                        !(lh__orient2_along(c->pred, ax, pt(c, v[a]), pt(c, v[k]), x) * sg >= 0 &&
                          lh__orient2_along(c->pred, ax, pt(c, v[k]), pt(c, v[b]), x) * sg >= 0 &&
                          lh__orient2_along(c->pred, ax, pt(c, v[b]), pt(c, v[a]), x) * sg >= 0);
                }
                if (empty) best[a][b] = q, via[a][b] = (signed char)k;
            }
        }
    if (m < 3 || best[0][m - 1] < 0) return 0;
    int stack[2 * SUP_RING], top = 0; /* the chosen triangles, from the chord 0 m-1 down */
    stack[top++] = 0, stack[top++] = m - 1;
    while (top) {
        const int b = stack[--top], a = stack[--top];
        if (b - a < 2) continue;
        const int k = via[a][b];
        lh_index *t = out + 3 * (*nout)++;
        t[0] = v[a], t[1] = v[k], t[2] = v[b];
        stack[top++] = a, stack[top++] = k, stack[top++] = k, stack[top++] = b;
    }
    return 1;
}

/* triangulate_dp on v taken from its least point by coordinates toward the lesser of
 * that point's neighbours, so that ties among triangulations are broken the same
 * wherever v starts and whichever way it runs; the triangles turn sg, as v does. */
static int triangulate(t3_ctx *c, int ax, int sg, const lh_index *v, int m, lh_index *out,
                       int *nout)
{
    if (m < 3) return 0;
    int lo = 0;
    for (int i = 1; i < m; i++) lo = cmp3(pt(c, v[i]), pt(c, v[lo])) < 0 ? i : lo;
    const int dir = cmp3(pt(c, v[(lo + 1) % m]), pt(c, v[(lo + m - 1) % m])) < 0 ? 1 : -1;
    lh_index w[SUP_RING];
    for (int r = 0; r < m; r++) w[r] = v[((lo + dir * r) % m + m) % m];
    const int first = *nout;
    if (!triangulate_dp(c, ax, dir * sg, w, m, out, nout)) return 0;
    for (int t = first; dir < 0 && t < *nout; t++) {
        const lh_index x = out[3 * t];
        out[3 * t] = out[3 * t + 1], out[3 * t + 1] = x;
    }
    return 1;
}

/* The polygon v (m points, turning sg in the projection along axis ax) triangulated
 * as the fan from its point w: each triangle w v[i] v[i+1] turns sg exactly and each
 * chord from w crosses no side of v, so the fan tiles the polygon (its triangles'
 * signed cover of a point is the polygon's winding number there). 0 when it does
 * not, or w is not on v. */
static int fan_from(t3_ctx *c, int ax, int sg, const lh_index *v, int m, lh_index w, lh_index *out,
                    int *nout)
{
    int iw = -1;
    for (int i = 0; i < m; i++) iw = v[i] == w ? i : iw;
    if (iw < 0) return 0;
    for (int k = 1; k + 1 < m; k++) {
        const lh_index x = v[(iw + k) % m], y = v[(iw + k + 1) % m];
        if (lh__orient2_along(c->pred, ax, pt(c, w), pt(c, x), pt(c, y)) != sg) return 0;
        for (int e = 0; k > 1 && e < m; e++)
            if (crosses(c, ax, w, x, v[e], v[(e + 1) % m])) return 0;
    }
    for (int k = 1; k + 1 < m; k++) {
        lh_index *t = out + 3 * (*nout)++;
        t[0] = w, t[1] = v[(iw + k) % m], t[2] = v[(iw + k + 1) % m];
    }
    return 1;
}

/* The fan's ring triangulated without p, in the projection of its patch: the path as
 * one polygon (p's two subsegments joined into the side from its last point to its
 * first); a cycle around a point on a segment cut along that segment (a b: p's
 * neighbours on it) into two; a cycle around a point inside a facet as one. The ring
 * need not be exactly planar (Steiner points are rounded): the cones' exact check
 * decides. 0 when there is no such triangulation. */
static int fan_cut(t3_ctx *c, fan *f, lh_index a, lh_index b, lh_index w)
{
    f->ntri = 0;
    if (!f->closed && f->len == 2) return 1; /* the face p a b alone: a b is the segment */
    const int ax = abs(c->patch_axis[f->patch]) - 1, i0 = (ax + 1) % 3, j0 = (ax + 2) % 3;
    double area = 0; /* the ring's turn (shoelace), the same as its faces' with p */
    for (int r = 0; r < f->len; r++) {
        const double *x = pt(c, f->ring[r]), *y = pt(c, f->ring[(r + 1) % f->len]);
        area += ldexp(x[i0], -c->unit_exp) * ldexp(y[j0], -c->unit_exp) -
                ldexp(x[j0], -c->unit_exp) * ldexp(y[i0], -c->unit_exp);
    }
    if (area == 0 || !isfinite(area)) return 0;
    const int sg = area > 0 ? 1 : -1;
    lh_index poly[SUP_RING];
    if (!f->closed || a < 0) {
        memcpy(poly, f->ring, (size_t)f->len * sizeof(lh_index));
        return w < 0 ? triangulate(c, ax, sg, poly, f->len, f->tri, &f->ntri)
                     : fan_from(c, ax, sg, poly, f->len, w, f->tri, &f->ntri);
    }
    int ia = -1, ib = -1; /* a cycle around a segment's point: two polygons, a to b and b to a */
    for (int i = 0; i < f->len; i++) ia = f->ring[i] == a ? i : ia, ib = f->ring[i] == b ? i : ib;
    if (ia < 0 || ib < 0) return 0;
    for (int half = 0; half < 2; half++) {
        const int from = half ? ib : ia, to = half ? ia : ib;
        int m = 0;
        for (int i = from;; i = (i + 1) % f->len) {
            poly[m++] = f->ring[i];
            if (i == to) break;
        }
        if (w < 0 ? !triangulate(c, ax, sg, poly, m, f->tri, &f->ntri)
                  : !fan_from(c, ax, sg, poly, m, w, f->tri, &f->ntri))
            return 0;
    }
    return 1;
}

/* fan_cut, its triangles then each from its least point by coordinates (the same
 * turn) and in the order of their points: in an order that does not depend on the
 * points' numbers. */
static int fan_triangulate(t3_ctx *c, fan *f, lh_index a, lh_index b, lh_index w)
{
    if (!fan_cut(c, f, a, b, w)) return 0;
    for (int r = 0; r < f->ntri; r++) {
        lh_index *t = f->tri + 3 * r;
        while (cmp3(pt(c, t[1]), pt(c, t[0])) < 0 || cmp3(pt(c, t[2]), pt(c, t[0])) < 0) {
            const lh_index x = t[0];
            t[0] = t[1], t[1] = t[2], t[2] = x;
        }
    }
    for (int r = 1; r < f->ntri; r++)
        for (int q = r; q > 0 && cmp_points(c, f->tri + 3 * q, f->tri + 3 * (q - 1), 3) < 0; q--)
            for (int k = 0; k < 3; k++) {
                const lh_index x = f->tri[3 * q + k];
                f->tri[3 * q + k] = f->tri[3 * (q - 1) + k], f->tri[3 * (q - 1) + k] = x;
            }
    return 1;
}

/* The fan of patch k in s, added when new; NULL when there are too many. */
static fan *fan_of(sup *s, lh_index k)
{
    for (int i = 0; i < s->nfan; i++)
        if (s->fan[i].patch == k) return s->fan + i;
    if (s->nfan == SUP_FANS) return NULL;
    fan *f = s->fan + s->nfan++;
    memset(f, 0, sizeof *f);
    f->patch = k;
    f->side[0] = f->side[1] = -1;
    return f;
}

/* Face j of tet t (its corners but corner j, in order). */
static void face_of(const t3_ctx *c, lh_index t, int j, lh_index *f)
{
    int w = 0;
    for (int k = 0; k < 4; k++)
        if (k != j) f[w++] = c->tv[4 * (size_t)t + k];
}

/* ---- the order of p's star and fans: by coordinates, so that every choice made
   in it (ties among triangulations, apexes, new points) does not depend on the
   points' numbers or the mesh's tet numbers ---- */

/* Tet t's corners other than p, sorted by coordinates. */
static void corners_sorted(const t3_ctx *c, lh_index p, lh_index t, lh_index *x)
{
    int m = 0;
    for (int j = 0; j < 4; j++)
        if (c->tv[4 * (size_t)t + j] != p) x[m++] = c->tv[4 * (size_t)t + j];
    for (int a = 1; a < 3; a++)
        for (int b = a; b > 0 && cmp3(pt(c, x[b]), pt(c, x[b - 1])) < 0; b--) {
            const lh_index y = x[b];
            x[b] = x[b - 1], x[b - 1] = y;
        }
}

/* s->tet by their corners other than p (sorted by coordinates), by coordinates. */
static void sort_star(const t3_ctx *c, sup *s)
{
    lh_index key[SUP_TETS][3];
    for (int i = 0; i < s->ntet; i++) corners_sorted(c, s->p, s->tet[i], key[i]);
    for (int a = 1; a < s->ntet; a++)
        for (int b = a; b > 0 && cmp_points(c, key[b], key[b - 1], 3) < 0; b--) {
            lh_index t = s->tet[b], y[3];
            s->tet[b] = s->tet[b - 1], s->tet[b - 1] = t;
            memcpy(y, key[b], sizeof y);
            memcpy(key[b], key[b - 1], sizeof y);
            memcpy(key[b - 1], y, sizeof y);
        }
}

/* f's ring reversed. */
static void ring_reverse(fan *f)
{
    for (int i = 0, j = f->len - 1; i < j; i++, j--) {
        const lh_index x = f->ring[i];
        f->ring[i] = f->ring[j], f->ring[j] = x;
    }
}

/* Each ring from its least point by coordinates (a path: from its lesser end), toward
 * the lesser of that point's two neighbours on a cycle; then the fans in the order of
 * their rings (no two fans have the same ring: they would share faces). */
static void sort_fans(const t3_ctx *c, sup *s)
{
    for (int i = 0; i < s->nfan; i++) {
        fan *f = s->fan + i;
        if (f->closed) {
            int lo = 0;
            for (int r = 1; r < f->len; r++)
                lo = cmp3(pt(c, f->ring[r]), pt(c, f->ring[lo])) < 0 ? r : lo;
            lh_index x[SUP_RING];
            for (int r = 0; r < f->len; r++) x[r] = f->ring[(lo + r) % f->len];
            memcpy(f->ring, x, (size_t)f->len * sizeof(lh_index));
            if (cmp3(pt(c, f->ring[f->len - 1]), pt(c, f->ring[1])) < 0) {
                ring_reverse(f); /* now ends at the least point: bring it to the front */
                memmove(f->ring + 1, f->ring, (size_t)(f->len - 1) * sizeof(lh_index));
                f->ring[0] = x[0];
            }
        } else if (cmp3(pt(c, f->ring[f->len - 1]), pt(c, f->ring[0])) < 0)
            ring_reverse(f);
    }
    for (int a = 1; a < s->nfan; a++)
        for (int b = a; b > 0; b--) {
            const fan *x = s->fan + b, *y = s->fan + b - 1;
            const int n = x->len < y->len ? x->len : y->len;
            int r = cmp_points(c, x->ring, y->ring, n);
            if (r == 0) r = x->len - y->len;
            if (r >= 0) break;
            const fan t = s->fan[b];
            s->fan[b] = s->fan[b - 1], s->fan[b - 1] = t;
        }
}

/* p's star into s: its sectors (tets joined across the faces through p that are no
 * constraint) and fans (the constraint faces through p by patch, as rings). *ok = 0
 * when p's star reaches the hull off a constraint, or is beyond the bounds. */
static lh_status gather(t3_ctx *c, sup *s, int *ok)
{
    size_t k;
    lh_index e[SUP_FANS][2 * SUP_RING];
    int ne[SUP_FANS] = {0};
    *ok = 0;
    lh_status st = lh__t3_mesh_star(c, s->p, &k);
    if (st != LH_OK || k == 0 || k > SUP_TETS) return st;
    s->ntet = (int)k;
    memcpy(s->tet, c->sbuf, k * sizeof(lh_index));
    sort_star(c, s);
    for (int i = 0; i < s->ntet; i++) s->parent[i] = i;
    s->nfan = 0;
    for (int i = 0; i < s->ntet; i++)
        for (int j = 0; j < 4; j++) {
            const lh_index t = s->tet[i], u = c->tn[4 * (size_t)t + j];
            if (c->tv[4 * (size_t)t + j] == s->p) continue;
            lh_index f[3];
            face_of(c, t, j, f);
            const lh_index pk = fs_get(&s->fs, f);
            if (pk < 0) {
                const int l = u < 0 ? -1 : local(s, u);
                if (l < 0) return LH_OK; /* the hull, off every facet */
                s->parent[find(s->parent, i)] = find(s->parent, l);
                continue;
            }
            fan *fn = fan_of(s, pk);
            if (!fn) return LH_OK;
            const int fi = (int)(fn - s->fan);
            lh_index x = f[0] == s->p ? f[1] : f[0], y = f[2] == s->p ? f[1] : f[2];
            int seen = 0;
            for (int m = 0; m < ne[fi] && !seen; m++)
                seen = (e[fi][2 * m] == x && e[fi][2 * m + 1] == y) ||
                       (e[fi][2 * m] == y && e[fi][2 * m + 1] == x);
            if (seen) continue;
            if (ne[fi] == SUP_RING - 1) return LH_OK;
            e[fi][2 * ne[fi]] = x, e[fi][2 * ne[fi] + 1] = y, ne[fi]++;
        }
    s->nsector = 0;
    for (int i = 0; i < s->ntet; i++) s->sector[i] = -1;
    for (int i = 0; i < s->ntet; i++) {
        const int r = find(s->parent, i);
        if (s->sector[r] < 0) {
            if (s->nsector == SUP_SECTORS) return LH_OK;
            s->sector_out[s->nsector] = 1;
            s->sector[r] = s->nsector++;
        }
        s->sector[i] = s->sector[r];
        s->sector_out[s->sector[i]] &= s->out && s->out[s->tet[i]];
    }
    for (int i = 0; i < s->nfan; i++)
        if (!ring_order(s->fan + i, e[i], ne[i])) return LH_OK;
    sort_fans(c, s);
    *ok = 1;
    return LH_OK;
}

/* Each fan's sectors: on either side of each of its faces, the sector of the tet
 * there, which must be one per side; *ok = 0 otherwise, or when both sides are one
 * sector (a fin in the middle of a sector: no point sees both its sides). */
static void fan_sides(t3_ctx *c, sup *s, int *ok)
{
    *ok = 0;
    for (int i = 0; i < s->ntet; i++)
        for (int j = 0; j < 4; j++) {
            const lh_index t = s->tet[i], w = c->tv[4 * (size_t)t + j];
            if (w == s->p) continue;
            lh_index f[3];
            face_of(c, t, j, f);
            for (int m = 0; m < s->nfan; m++) {
                fan *fn = s->fan + m;
                int in = -1; /* f is a face of this fan: p and side in of its ring */
                for (int r = 0; r < fn->len - !fn->closed && in < 0; r++) {
                    const lh_index x = fn->ring[r], y = fn->ring[(r + 1) % fn->len];
                    if ((f[0] == x || f[1] == x || f[2] == x) &&
                        (f[0] == y || f[1] == y || f[2] == y))
                        in = r;
                }
                if (in < 0) continue;
                const double *x[4] = {pt(c, s->p), pt(c, fn->ring[in]),
                                      pt(c, fn->ring[(in + 1) % fn->len]), pt(c, w)};
                const int sd = lh_orient(c->pred, 3, x) > 0 ? 0 : 1; /* faces in ring order */
                if (fn->side[sd] >= 0 && fn->side[sd] != s->sector[i]) return;
                fn->side[sd] = s->sector[i];
            }
        }
    for (int m = 0; m < s->nfan; m++)
        if (s->fan[m].side[0] == s->fan[m].side[1]) return;
    *ok = 1;
}

/* Template t's corners in a canonical order of the same orientation: its apex first,
 * then its points by coordinates, the last two swapped when that order is an odd
 * permutation of t's; floating-point figures made from it then do not depend on the
 * order the mesh held its corners in. */
static void canon_tet(const t3_ctx *c, lh_index *t)
{
    int odd = 0;
    for (int a = 1; a < 4; a++)
        for (int b = a; b > 0; b--) {
            const lh_index x = t[b], y = t[b - 1];
            if (y < 0 || (x >= 0 && cmp3(pt(c, y), pt(c, x)) <= 0)) break;
            t[b] = y, t[b - 1] = x, odd ^= 1;
        }
    if (odd) {
        const lh_index x = t[2];
        t[2] = t[3], t[3] = x;
    }
}

/* The new tets: for each sector, its tets with p replaced by the sector's apex, and
 * each new facet triangle on its side with that apex, each in canon_tet's order; 0
 * when too many. */
static int templates(t3_ctx *c, sup *s)
{
    s->nnew = 0;
    for (int i = 0; i < s->ntet; i++) {
        lh_index *t = s->nv[s->nnew++];
        for (int j = 0; j < 4; j++) {
            const lh_index v = c->tv[4 * (size_t)s->tet[i] + j];
            t[j] = v == s->p ? -2 - s->sector[i] : v;
        }
        canon_tet(c, t);
    }
    for (int m = 0; m < s->nfan; m++) {
        const fan *fn = s->fan + m;
        for (int sd = 0; sd < 2; sd++) {
            if (fn->side[sd] < 0) continue;
            for (int r = 0; r < fn->ntri; r++) {
                if (s->nnew == SUP_NEW) return 0;
                const lh_index *x = fn->tri + 3 * r; /* in ring order: side 0 positive */
                lh_index *t = s->nv[s->nnew++];
                t[0] = x[sd], t[1] = x[1 - sd], t[2] = x[2];
                t[3] = -2 - fn->side[sd];
                canon_tet(c, t);
            }
        }
    }
    return 1;
}

/* Whether q is strictly on the inner side of every face of sector i's cone. */
static int sees_all(t3_ctx *c, const sup *s, int i, const double *q)
{
    for (int n = 0; n < s->nnew; n++) {
        const double *y[4];
        int mine = 0;
        for (int j = 0; j < 4; j++) {
            const lh_index v = s->nv[n][j];
            mine |= v == -2 - i;
            y[j] = v < 0 ? q : pt(c, v);
        }
        if (mine && lh_orient(c->pred, 3, y) <= 0) return 0;
    }
    return 1;
}

/* Point x relative to p, in units of 2^unit_exp (scaled first: no overflow). */
static void rel(const t3_ctx *c, const double *x, const double *p, double *d)
{
    for (int k = 0; k < 3; k++) d[k] = ldexp(x[k], -c->unit_exp) - ldexp(p[k], -c->unit_exp);
}

/* The unit normal of fan f's new triangles (their cross products summed) toward its
 * side sd; zero when that is not decided in floating point. */
static void fan_normal(t3_ctx *c, const fan *f, int sd, double n[3])
{
    static const double e[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double *E[4] = {e[0], e[1], e[2], e[3]};
    const int sense = lh_orient(c->pred, 3, E); /* orient_3's sign on the side of a x b */
    n[0] = n[1] = n[2] = 0;
    for (int r = 0; r < f->ntri; r++) {
        const lh_index *t = f->tri + 3 * r;
        double u[3], v[3];
        rel(c, pt(c, t[1]), pt(c, t[0]), u);
        rel(c, pt(c, t[2]), pt(c, t[0]), v);
        for (int k = 0; k < 3; k++)
            n[k] += u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3];
    }
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double scale = len == 0 || !isfinite(len) ? 0 : (sd == 0 ? sense : -sense) / len;
    for (int k = 0; k < 3; k++) n[k] *= scale;
}

/* Halvings of the way tried for a new point, and the directions tried. */
#define SUP_HALVINGS 52
#define SUP_DIRS (2 + SUP_TETS)

/* Sector i's cone faces (the faces without its apex) as planes around p, in units
 * of 2^unit_exp: 4 numbers each, the unit normal toward the inside and the offset, so
 * that a point y (relative to p) lies at depth pl[0..2]·y - pl[3] (a face of no area:
 * a plane no point is inside); their number. */
static int cone_planes(const t3_ctx *c, const sup *s, int i, int sense, double (*pl)[4])
{
    int m = 0;
    for (int n = 0; n < s->nnew; n++) {
        int a = 0;
        while (a < 4 && s->nv[n][a] != -2 - i) a++;
        if (a == 4) continue;
        double x[3][3], f[3], g[3], h[3];
        for (int j = 0; j < 3; j++) /* b d e: the corners after a, in cyclic order */
            rel(c, pt(c, s->nv[n][(a + 1 + j) % 4]), pt(c, s->p), x[j]);
        for (int k = 0; k < 3; k++) f[k] = x[1][k] - x[0][k], g[k] = x[2][k] - x[0][k];
        for (int k = 0; k < 3; k++)
            h[k] = f[(k + 1) % 3] * g[(k + 2) % 3] - f[(k + 2) % 3] * g[(k + 1) % 3];
        const double area = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        /* the volume with the apex y at a is (-1)^(a+1) (y - b)·h: a cyclic shift */
        const double scale = area > 0 ? (a % 2 ? sense : -sense) / area : 0;
        for (int k = 0; k < 3; k++) pl[m][k] = h[k] * scale;
        pl[m][3] =
            area > 0 ? pl[m][0] * x[0][0] + pl[m][1] * x[0][1] + pl[m][2] * x[0][2] : HUGE_VAL;
        m++;
    }
    return m;
}

/* How deep q lies inside the cone of planes pl (m of them): its least distance to
 * one, negative when on the wrong side (floating point: it ranks candidates, exact
 * orient_3 decides). */
static double depth(const t3_ctx *c, const sup *s, const double (*pl)[4], int m, const double *q)
{
    double y[3], least = HUGE_VAL;
    rel(c, q, pt(c, s->p), y);
    for (int n = 0; n < m; n++)
        least = fmin(least, pl[n][0] * y[0] + pl[n][1] * y[1] + pl[n][2] * y[2] - pl[n][3]);
    return least;
}

/* Sector i's points but p, in coordinate order, into v; their number. */
static int sector_points(const t3_ctx *c, const sup *s, int i, lh_index *v)
{
    int m = 0;
    for (int a = 0; a < s->ntet; a++)
        for (int j = 0; s->sector[a] == i && j < 4; j++) {
            const lh_index x = c->tv[4 * (size_t)s->tet[a] + j];
            int seen = x == s->p;
            for (int b = 0; b < m && !seen; b++) seen = v[b] == x;
            if (!seen) v[m++] = x;
        }
    for (int a = 1; a < m; a++) /* insertion sort by coordinates */
        for (int b = a; b > 0 && cmp3(pt(c, v[b]), pt(c, v[b - 1])) < 0; b--) {
            const lh_index x = v[b];
            v[b] = v[b - 1], v[b - 1] = x;
        }
    return m;
}

/* Sector i filled without a new point: the cone from one of its own points v over the
 * faces of its boundary that v is not on. By the argument for q (above), the cone
 * tiles the sector when exact orient_3 puts v strictly on the inner side of each of
 * those faces (v's own faces make no tet). s->apex[i] = the point whose cone's worst
 * tet is best shaped, ties to the first in coordinate order; 0 when none does. */
static int old_point(t3_ctx *c, sup *s, int i)
{
    lh_index v[4 * SUP_TETS];
    const int m = sector_points(c, s, i, v);
    double best = 0;
    s->apex[i] = -1;
    for (int a = 0; a < m; a++) {
        double worst = HUGE_VAL;
        for (int n = 0; n < s->nnew && worst > best; n++) {
            lh_index t[4];
            const double *y[4];
            int mine = 0, on = 0;
            for (int j = 0; j < 4; j++) {
                const lh_index x = s->nv[n][j];
                mine |= x == -2 - i;
                on |= x == v[a];
                t[j] = x == -2 - i ? v[a] : x;
                y[j] = x < 0 ? pt(c, v[a]) : pt(c, x);
            }
            if (!mine || on) continue;
            worst = lh_orient(c->pred, 3, y) > 0
                        ? fmin(worst, lh__t3_shape(c, t[0], t[1], t[2], t[3]))
                        : 0;
        }
        if (worst > best && worst >= T3_SLIVER && worst < HUGE_VAL) best = worst, s->apex[i] = v[a];
    }
    return s->apex[i] >= 0;
}

/* Sector i's new point into s->q[i]. Candidates: p moved by 1/2, 1/4, ... of its
 * distance L to the mean g of the sector's other points (summed in coordinate order),
 * along the sum of its fans' normals toward the sector (inside every wedge two planes
 * make), toward g, and toward each of its tets' centroids. They are tried deepest
 * first (depth), the first that exact orient_3 puts inside every face of the cone
 * kept: deep points leave room for the next suppressions around them. 0 when none. */
static int new_point(t3_ctx *c, sup *s, int i)
{
    static const double e[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double *E[4] = {e[0], e[1], e[2], e[3]};
    const int sense = lh_orient(c->pred, 3, E); /* orient_3's sign for a positive volume */
    lh_index v[4 * SUP_TETS];
    const int m = sector_points(c, s, i, v);
    const double *p = pt(c, s->p);
    double g[3] = {0, 0, 0}, n[3], dir[SUP_DIRS][3], pl[SUP_NEW][4];
    const int np = cone_planes(c, s, i, sense, pl);
    for (int a = 0; a < m; a++)
        for (int k = 0; k < 3; k++) g[k] += pt(c, v[a])[k] / m;
    rel(c, g, p, dir[1]);
    const double L = sqrt(dir[1][0] * dir[1][0] + dir[1][1] * dir[1][1] + dir[1][2] * dir[1][2]);
    if (!(L > 0) || !isfinite(L)) return 0;
    dir[0][0] = dir[0][1] = dir[0][2] = 0;
    for (int f = 0; f < s->nfan; f++)
        for (int sd = 0; sd < 2; sd++) {
            if (s->fan[f].side[sd] != i) continue;
            fan_normal(c, s->fan + f, sd, n);
            for (int k = 0; k < 3; k++) dir[0][k] += n[k];
        }
    for (int k = 0; k < 3; k++) dir[1][k] /= L;
    int nd = 2;
    for (int a = 0; a < s->ntet; a++) { /* toward each tet's centroid, scaled to length 1 */
        if (s->sector[a] != i) continue;
        double x[3] = {0, 0, 0}, y[3];
        for (int j = 0; j < 4; j++) { /* its template's corners: in canonical order */
            const double *corner = s->nv[a][j] < 0 ? p : pt(c, s->nv[a][j]);
            for (int k = 0; k < 3; k++) x[k] += corner[k] / 4;
        }
        rel(c, x, p, y);
        const double l = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
        for (int k = 0; k < 3; k++) dir[nd][k] = l > 0 ? y[k] / l : 0;
        nd++;
    }
    for (;;) { /* the deepest candidate not yet tried, checked exactly */
        double best = 0, q[3], bq[3];
        int bd = -1;
        for (int d = 0; d < nd; d++) {
            double t = 0.5, last = -HUGE_VAL;
            /* depth along the ray is concave (a least of linear functions): once it
               falls on the way toward p, it keeps falling */
            for (int h = 0; h < SUP_HALVINGS; h++, t /= 2) {
                if (dir[d][0] == 0 && dir[d][1] == 0 && dir[d][2] == 0) break;
                for (int k = 0; k < 3; k++) q[k] = p[k] + ldexp(t * L * dir[d][k], c->unit_exp);
                const double dp = depth(c, s, pl, np, q);
                if (dp < last) break;
                last = dp;
                if (dp > best) best = dp, bd = d, memcpy(bq, q, sizeof q);
            }
        }
        if (bd < 0) return 0;
        if (sees_all(c, s, i, bq)) {
            memcpy(s->q[i], bq, sizeof bq);
            s->apex[i] = -1;
            return 1;
        }
        dir[bd][0] = dir[bd][1] = dir[bd][2] = 0; /* rounding misled it: not that way */
    }
}

static lh_status fs_init(t3_ctx *c, faceset *s, size_t want)
{
    size_t cap = 64;
    while (cap < 2 * want) cap *= 2;
    s->slot = lh__alloc(&c->al, 4 * cap * sizeof(lh_index));
    if (!s->slot) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    s->cap = cap;
    for (size_t i = 0; i < cap; i++) s->slot[4 * i] = -1;
    return LH_OK;
}

/* The set again, without its removed slots, with room for want faces. */
static lh_status fs_rehash(t3_ctx *c, faceset *s, size_t want)
{
    faceset t;
    lh_status st = fs_init(c, &t, want);
    if (st != LH_OK) return st;
    for (size_t i = 0; i < s->cap; i++)
        if (s->slot[4 * i] >= 0) fs_put(&t, s->slot + 4 * i, s->slot[4 * i + 3]);
    lh__free(&c->al, s->slot);
    *s = t;
    return LH_OK;
}

/* Every patch's faces, with the patch. */
static lh_status fs_fill(t3_ctx *c, faceset *s, size_t *used)
{
    size_t total = 0;
    for (size_t k = 0; k < c->patch_count; k++) total += (size_t)c->cover_len[k];
    lh_status st = fs_init(c, s, total + SUP_FANS * SUP_RING + 64);
    for (size_t k = 0; st == LH_OK && k < c->patch_count; k++) {
        const lh_index *f;
        size_t nf;
        st = lh__t3_patch_cover(c, k, &f, &nf);
        if (st == LH_OK && 2 * (*used + nf + SUP_FANS * SUP_RING) >= s->cap)
            st = fs_rehash(c, s, 2 * (*used + nf) + SUP_FANS * SUP_RING);
        for (size_t i = 0; st == LH_OK && i < nf; i++, (*used)++) fs_put(s, f + 3 * i, (lh_index)k);
    }
    return st;
}

/* Removes p from the chains and the points inside patches. */
static lh_status drop_point(t3_ctx *c, lh_index p)
{
    for (size_t i = 0; i < c->node_count; i++) /* an end is dropped by the sort */
        if (c->node[i].p == p) c->node[i].p = c->seg[c->node[i].seg].a;
    size_t w = 0;
    for (size_t i = 0; i < c->pnode_count; i++)
        if (c->pnode[i].p != p) c->pnode[w++] = c->pnode[i];
    c->pnode_count = w;
    return lh__t3_chains_sort(c);
}

/* s->out with room for every tet of the mesh (new ones are set by the caller). */
static lh_status out_room(t3_ctx *c, sup *s)
{
    if (c->tet_count <= s->out_cap) return LH_OK;
    const size_t cap = 2 * c->tet_count + 64;
    unsigned char *x = lh__alloc(&c->al, cap);
    if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    if (s->out_cap) memcpy(x, s->out, s->out_cap);
    lh__free(&c->al, s->out);
    s->out = x, s->out_cap = cap;
    return LH_OK;
}

/* The new points numbered in coordinate order, the star replaced by the cones (a cone
 * from one of the sector's points without the tets on that point's faces), the fans'
 * faces replaced in the set, and p taken off its chain or patch. */
static lh_status apply(t3_ctx *c, sup *s)
{
    int order[SUP_SECTORS], nq = 0;
    lh_index idx[SUP_SECTORS];
    for (int i = 0; i < s->nsector; i++)
        if (s->apex[i] < 0)
            order[nq++] = i;
        else
            idx[i] = s->apex[i];
    for (int a = 1; a < nq; a++)
        for (int b = a; b > 0 && cmp3(s->q[order[b]], s->q[order[b - 1]]) < 0; b--) {
            const int x = order[b];
            order[b] = order[b - 1], order[b - 1] = x;
        }
    lh_status st = lh__t3_xyz_room(c, (size_t)nq);
    if (st != LH_OK) return st;
    for (int r = 0; r < nq; r++) {
        idx[order[r]] = (lh_index)(c->n + (size_t)r);
        memcpy(c->xyz + 3 * (c->n + (size_t)r), s->q[order[r]], 3 * sizeof(double));
    }
    c->n += (size_t)nq;
    c->steiner += (size_t)nq;
    unsigned char outside[SUP_NEW]; /* each new tet's side of the domain: its sector's */
    int w = 0;
    for (int n = 0; n < s->nnew; n++) { /* every template has its sector's apex */
        int sec = 0, twice = 0;
        for (int j = 0; j < 4; j++) sec = s->nv[n][j] < 0 ? -2 - s->nv[n][j] : sec;
        for (int j = 0; j < 4; j++) twice |= s->nv[n][j] == idx[sec];
        if (twice) continue;
        for (int j = 0; j < 4; j++) s->nv[w][j] = s->nv[n][j] < 0 ? idx[sec] : s->nv[n][j];
        outside[w++] = s->sector_out[sec];
    }
    s->nnew = w;
    const size_t before = c->tet_count;
    int ok;
    st = lh__t3_mesh_replace(c, s->tet, s->ntet, s->nv, s->nnew, &ok);
    if (st != LH_OK) return st;
    if (!ok) return lh__t3_say(c, LH_ERR_INTERNAL, 0, "a flat tetrahedron in a checked cone");
    if (s->out && (st = out_room(c, s)) != LH_OK) return st;
    for (int n = 0; s->out && n < s->nnew; n++)
        s->out[n < s->ntet ? (size_t)s->tet[n] : before + (size_t)(n - s->ntet)] = outside[n];
    size_t added = 0;
    faceset *fs = &s->fs;
    for (int m = 0; m < s->nfan; m++) added += (size_t)s->fan[m].ntri;
    if (2 * (s->used + added) >= fs->cap && (st = fs_rehash(c, fs, 2 * (s->used + added))) != LH_OK)
        return st;
    for (int m = 0; m < s->nfan; m++) {
        const fan *fn = s->fan + m;
        for (int r = 0; r < fn->len - !fn->closed; r++) {
            const lh_index f[3] = {s->p, fn->ring[r], fn->ring[(r + 1) % fn->len]};
            fs_remove(fs, f);
        }
        for (int r = 0; r < fn->ntri; r++) fs_put(fs, fn->tri + 3 * r, fn->patch);
    }
    s->used += added;
    return drop_point(c, s->p);
}

/* p's neighbours on its segment's chain into *a, *b (-1 for a point inside a patch);
 * 0 when p is on two chains. */
static int neighbours(t3_ctx *c, lh_index p, lh_index *a, lh_index *b)
{
    int chains = 0;
    *a = *b = -1;
    for (size_t s = 0; s < c->seg_count; s++)
        for (lh_index i = c->node_first[s]; i < c->node_first[s + 1]; i++) {
            if (c->node[i].p != p) continue;
            chains++;
            *a = i == c->node_first[s] ? c->seg[s].a : c->node[i - 1].p;
            *b = i + 1 == c->node_first[s + 1] ? c->seg[s].b : c->node[i + 1].p;
        }
    return chains <= 1;
}

/* p's star refilled (s->nv) with its fans triangulated without p from w (-1: the
 * best shaped triangulation), each sector's apex one of its points or, when
 * allow_new or the sector is outside the domain (carved later with its point), a
 * new point; 0 when that fails. */
static int refill(t3_ctx *c, sup *s, lh_index a, lh_index b, lh_index w, int allow_new)
{
    for (int m = 0; m < s->nfan; m++)
        if (!fan_triangulate(c, s->fan + m, a, b, w)) return 0;
    if (!templates(c, s)) return 0;
    for (int i = 0; i < s->nsector; i++)
        if (!old_point(c, s, i) && !((allow_new || s->sector_out[i]) && new_point(c, s, i)))
            return 0;
    return 1;
}

/* The new points of the refill inside the domain. */
static int new_inside(const sup *s)
{
    int k = 0;
    for (int i = 0; i < s->nsector; i++) k += s->apex[i] < 0 && !s->sector_out[i];
    return k;
}

/* Takes p off the boundary; *ok = 0, and nothing changed, when it cannot. Tried in
 * turn, each sector's apex one of its points (or a new point outside the domain):
 * the best shaped fans; the fans from each ring point w (in coordinate order: p's
 * edge to w contracted, when w is the apex); then, when s->max_new allows, the best
 * shaped fans with new points inside as well. */
static lh_status suppress_point(t3_ctx *c, sup *s, int *ok)
{
    lh_index a, b;
    *ok = 0;
    if (!neighbours(c, s->p, &a, &b)) return LH_OK;
    lh_status st = gather(c, s, ok);
    if (st != LH_OK || !*ok) return st;
    fan_sides(c, s, ok);
    for (int m = 0; *ok && m < s->nfan; m++) {
        const fan *fn = s->fan + m; /* a path runs from one neighbour of p to the other */
        if (!fn->closed && !((fn->ring[0] == a && fn->ring[fn->len - 1] == b) ||
                             (fn->ring[0] == b && fn->ring[fn->len - 1] == a)))
            *ok = 0;
    }
    if (!*ok) return LH_OK;
    if ((*ok = refill(c, s, a, b, -1, 0))) return apply(c, s);
    lh_index w[SUP_RING];
    int nw = 0;
    for (int r = 0; s->nfan && r < s->fan[0].len; r++) { /* a ring point on every fan */
        int all = 1;
        for (int m = 1; m < s->nfan && all; m++) {
            all = 0;
            for (int q = 0; q < s->fan[m].len; q++) all |= s->fan[m].ring[q] == s->fan[0].ring[r];
        }
        if (all) w[nw++] = s->fan[0].ring[r];
    }
    for (int i = 1; i < nw; i++)
        for (int j = i; j > 0 && cmp3(pt(c, w[j]), pt(c, w[j - 1])) < 0; j--) {
            const lh_index x = w[j];
            w[j] = w[j - 1], w[j - 1] = x;
        }
    for (int i = 0; i < nw; i++)
        if ((*ok = refill(c, s, a, b, w[i], 0))) return apply(c, s);
    if (s->max_new && (*ok = refill(c, s, a, b, -1, 1)) && new_inside(s) <= s->max_new)
        return apply(c, s);
    *ok = 0;
    return LH_OK;
}

static int cmp_point(const void *ctx, lh_index a, lh_index b)
{
    const t3_ctx *c = ctx;
    return cmp3(pt(c, a), pt(c, b));
}

/* The boundary Steiner points in coordinate order, each once, into list; their
 * number. */
static size_t steiner_list(t3_ctx *c, lh_index *list)
{
    size_t m = 0;
    for (size_t i = 0; i < c->node_count + c->pnode_count; i++) {
        const lh_index p = i < c->node_count ? c->node[i].p : c->pnode[i - c->node_count].p;
        if ((size_t)p >= c->n_input) list[m++] = p;
    }
    lh__sort_idx(list, list + m, m, cmp_point, c);
    size_t w = 0;
    for (size_t i = 0; i < m; i++)
        if (w == 0 || list[i] != list[w - 1]) list[w++] = list[i];
    return w;
}

/* Passes over the points left, until one takes none off (taking one off can make
 * room around another); *m: the points left at the front of list. */
static lh_status passes(t3_ctx *c, sup *s, lh_index *list, size_t *m)
{
    lh_status st = LH_OK;
    for (size_t left = *m + 1; st == LH_OK && *m && *m < left;) {
        left = *m, *m = 0;
        for (size_t i = 0; st == LH_OK && i < left; i++) {
            int ok;
            s->p = list[i];
            st = suppress_point(c, s, &ok);
            if (st == LH_OK && !ok) list[(*m)++] = list[i];
        }
    }
    return st;
}

/* The new points from n0 on inside the domain (those outside are carved away)
 * taken out again where their stars can be refilled from their own points: the room
 * later suppressions made around one may have made it needless. */
static lh_status inner_passes(t3_ctx *c, sup *s, size_t n0)
{
    size_t m = 0;
    lh_index *list = lh__alloc(&c->al, 2 * (c->n - n0) * sizeof(lh_index)); /* and scratch */
    if (!list) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t q = n0; q < c->n; q++) { /* a tet holding q: inside the domain or not */
        const lh_index t = c->vtet[q];
        if (t >= 0 && (!s->out || !s->out[t])) list[m++] = (lh_index)q;
    }
    lh__sort_idx(list, list + m, m, cmp_point, c);
    s->max_new = 0;
    lh_status st = passes(c, s, list, &m);
    lh__free(&c->al, list);
    return st;
}

lh_status lh__t3_suppress(t3_ctx *c, int allow_new, const unsigned char *out, size_t *taken)
{
    *taken = 0;
    lh_index *list =
        lh__alloc(&c->al, (2 * (c->node_count + c->pnode_count) + 1) * sizeof(lh_index));
    sup *s = lh__alloc(&c->al, sizeof *s);
    lh_status st = list && s ? LH_OK : lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t all = st == LH_OK ? steiner_list(c, list) : 0, m = all, n0 = c->n;
    if (s) {
        memset(&s->fs, 0, sizeof s->fs);
        s->used = 0, s->out = NULL, s->out_cap = 0, s->max_new = 0;
    }
    if (st == LH_OK && m) st = fs_fill(c, &s->fs, &s->used);
    if (st == LH_OK && m && out && (st = out_room(c, s)) == LH_OK)
        memcpy(s->out, out, c->tet_count);
    c->journal = 0;
    if (st == LH_OK) st = passes(c, s, list, &m); /* first all that need no new point */
    /* then with new points inside: as many as needed with -Y, else at most the one that
       replaces p (which can make room for the next) */
    if (st == LH_OK && m) s->max_new = allow_new ? SUP_SECTORS : 1, st = passes(c, s, list, &m);
    if (st == LH_OK && c->n > n0) st = inner_passes(c, s, n0);
    if (st == LH_OK && m && allow_new) {
        const double *x = pt(c, list[0]);
        st = lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                        "-Y: %zu boundary Steiner points could not be moved off the boundary, "
                        "e.g. (%.17g, %.17g, %.17g); without -Y they stay there",
                        m, x[0], x[1], x[2]);
    }
    if (s) lh__free(&c->al, s->fs.slot), lh__free(&c->al, s->out);
    lh__free(&c->al, list);
    lh__free(&c->al, s);
    *taken = all - m;
    if (st != LH_OK || *taken == 0) return st;
    lh__t3_mesh_compact(c);
    return lh__t3_stars(c);
}
