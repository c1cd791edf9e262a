/*
 * recover_suppress.c — -Y (no Steiner point on the boundary): once every constraint
 * is in the mesh, each Steiner point p on a segment or inside a facet is taken off
 * the boundary again, as TetGen does for -Y (Si 2015, its suppression of boundary
 * Steiner points; the construction here is this one's; docs/meshing3d.md):
 *   - the constraint faces around p, grouped by patch (p's fans), are triangulated
 *     again without p, each in its patch's projection, so that p's two subsegments
 *     become one edge (triangulate: the worst triangle best shaped);
 *   - those faces cut p's star (the tets around it) into sectors; each sector is
 *     filled again as the cone from one new point q over its boundary: the faces
 *     opposite p, and the new facet faces on its side;
 *   - q is p moved a little into the sector (new_point), kept only when exact
 *     orient_3 puts it strictly on the inner side of every one of those faces. Then
 *     the cones tile the sector (each positive over a closed surface that goes once
 *     around q), and q is on no constraint (it is inside the sector).
 * A point on two segments, whose star is too large, or with no such q ends meshing
 * with LH_ERR_STEINER_LIMIT naming it. Points are taken in coordinate order, and every
 * choice is made on coordinates, so the result does not depend on input order.
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
    lh_index nv[SUP_NEW][4]; /* the new tets; -2 - i stands for sector i's new point */
    int nnew;
    double q[SUP_SECTORS][3];
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
static int triangulate(t3_ctx *c, int ax, int sg, const lh_index *v, int m, lh_index *out,
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

/* The fan's ring triangulated without p, in the projection of its patch: the path as
 * one polygon (p's two subsegments joined into the side from its last point to its
 * first); a cycle around a point on a segment cut along that segment (a b: p's
 * neighbours on it) into two; a cycle around a point inside a facet as one. The ring
 * need not be exactly planar (Steiner points are rounded): the cones' exact check
 * decides. 0 when there is no such triangulation. */
static int fan_triangulate(t3_ctx *c, fan *f, lh_index a, lh_index b)
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
        return triangulate(c, ax, sg, poly, f->len, f->tri, &f->ntri);
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
        if (!triangulate(c, ax, sg, poly, m, f->tri, &f->ntri)) return 0;
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

/* p's star into s: its sectors (tets joined across the faces through p that are no
 * constraint) and fans (the constraint faces through p by patch, as rings). *ok = 0
 * when p's star reaches the hull off a constraint, or is beyond the bounds. */
static lh_status gather(t3_ctx *c, const faceset *fs, sup *s, int *ok)
{
    size_t k;
    lh_index e[SUP_FANS][2 * SUP_RING];
    int ne[SUP_FANS] = {0};
    *ok = 0;
    lh_status st = lh__t3_mesh_star(c, s->p, &k);
    if (st != LH_OK || k == 0 || k > SUP_TETS) return st;
    s->ntet = (int)k;
    memcpy(s->tet, c->sbuf, k * sizeof(lh_index));
    for (int i = 0; i < s->ntet; i++) s->parent[i] = i;
    s->nfan = 0;
    for (int i = 0; i < s->ntet; i++)
        for (int j = 0; j < 4; j++) {
            const lh_index t = s->tet[i], u = c->tn[4 * (size_t)t + j];
            if (c->tv[4 * (size_t)t + j] == s->p) continue;
            lh_index f[3];
            face_of(c, t, j, f);
            const lh_index pk = fs_get(fs, f);
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
            s->sector[r] = s->nsector++;
        }
        s->sector[i] = s->sector[r];
    }
    for (int i = 0; i < s->nfan; i++)
        if (!ring_order(s->fan + i, e[i], ne[i])) return LH_OK;
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

/* The new tets: for each sector, its tets with p replaced by the sector's new point,
 * and each new facet triangle on its side with that point; 0 when too many. */
static int templates(t3_ctx *c, sup *s)
{
    s->nnew = 0;
    for (int i = 0; i < s->ntet; i++) {
        lh_index *t = s->nv[s->nnew++];
        for (int j = 0; j < 4; j++) {
            const lh_index v = c->tv[4 * (size_t)s->tet[i] + j];
            t[j] = v == s->p ? -2 - s->sector[i] : v;
        }
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

/* How deep q lies inside sector i: the least distance, in units of 2^unit_exp, from q
 * to the plane of a face of its cone, negative when on the wrong side (floating
 * point: it ranks candidates, exact orient_3 decides). */
static double depth(const t3_ctx *c, const sup *s, int i, const double *q, int sense)
{
    double least = HUGE_VAL;
    for (int n = 0; n < s->nnew; n++) {
        double x[4][3];
        int mine = 0;
        for (int j = 0; j < 4; j++) {
            const lh_index v = s->nv[n][j];
            mine |= v == -2 - i;
            const double *y = v < 0 ? q : pt(c, v);
            for (int k = 0; k < 3; k++) x[j][k] = ldexp(y[k], -c->unit_exp);
        }
        if (!mine) continue;
        double u[3], v[3], w[3], f[3], g[3], h[3]; /* the volume, and the face without q */
        for (int k = 0; k < 3; k++)
            u[k] = x[1][k] - x[0][k], v[k] = x[2][k] - x[0][k], w[k] = x[3][k] - x[0][k];
        const double vol = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                           w[2] * (u[0] * v[1] - u[1] * v[0]);
        int a = 0, b, d;
        while (s->nv[n][a] != -2 - i) a++;
        b = (a + 1) % 4, d = (a + 2) % 4;
        const int e = (a + 3) % 4;
        for (int k = 0; k < 3; k++) f[k] = x[d][k] - x[b][k], g[k] = x[e][k] - x[b][k];
        for (int k = 0; k < 3; k++)
            h[k] = f[(k + 1) % 3] * g[(k + 2) % 3] - f[(k + 2) % 3] * g[(k + 1) % 3];
        const double area = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        least = fmin(least, area > 0 ? sense * vol / area : -HUGE_VAL);
    }
    return least;
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
    const double *p = pt(c, s->p);
    double g[3] = {0, 0, 0}, n[3], dir[SUP_DIRS][3];
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
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++) x[k] += pt(c, c->tv[4 * (size_t)s->tet[a] + j])[k] / 4;
        rel(c, x, p, y);
        const double l = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
        for (int k = 0; k < 3; k++) dir[nd][k] = l > 0 ? y[k] / l : 0;
        nd++;
    }
    for (;;) { /* the deepest candidate not yet tried, checked exactly */
        double best = 0, q[3], bq[3];
        int bd = -1;
        for (int d = 0; d < nd; d++) {
            double t = 0.5;
            for (int h = 0; h < SUP_HALVINGS; h++, t /= 2) {
                if (dir[d][0] == 0 && dir[d][1] == 0 && dir[d][2] == 0) break;
                for (int k = 0; k < 3; k++) q[k] = p[k] + ldexp(t * L * dir[d][k], c->unit_exp);
                const double dp = depth(c, s, i, q, sense);
                if (dp > best) best = dp, bd = d, memcpy(bq, q, sizeof q);
            }
        }
        if (bd < 0) return 0;
        if (sees_all(c, s, i, bq)) {
            memcpy(s->q[i], bq, sizeof bq);
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

/* The new points numbered in coordinate order, the star replaced by the cones, the
 * fans' faces replaced in the set, and p taken off its chain or patch. */
static lh_status apply(t3_ctx *c, faceset *fs, size_t *used, sup *s)
{
    int order[SUP_SECTORS];
    lh_index idx[SUP_SECTORS];
    for (int i = 0; i < s->nsector; i++) order[i] = i;
    for (int a = 1; a < s->nsector; a++)
        for (int b = a; b > 0 && cmp3(s->q[order[b]], s->q[order[b - 1]]) < 0; b--) {
            const int x = order[b];
            order[b] = order[b - 1], order[b - 1] = x;
        }
    lh_status st = lh__t3_xyz_room(c, (size_t)s->nsector);
    if (st != LH_OK) return st;
    for (int r = 0; r < s->nsector; r++) {
        idx[order[r]] = (lh_index)(c->n + (size_t)r);
        memcpy(c->xyz + 3 * (c->n + (size_t)r), s->q[order[r]], 3 * sizeof(double));
    }
    c->n += (size_t)s->nsector;
    c->steiner += (size_t)s->nsector;
    for (int n = 0; n < s->nnew; n++)
        for (int j = 0; j < 4; j++)
            if (s->nv[n][j] < 0) s->nv[n][j] = idx[-2 - s->nv[n][j]];
    int ok;
    st = lh__t3_mesh_replace(c, s->tet, s->ntet, s->nv, s->nnew, &ok);
    if (st != LH_OK) return st;
    if (!ok) return lh__t3_say(c, LH_ERR_INTERNAL, 0, "-Y: a flat tetrahedron in a checked cone");
    size_t added = 0;
    for (int m = 0; m < s->nfan; m++) added += (size_t)s->fan[m].ntri;
    if (2 * (*used + added) >= fs->cap && (st = fs_rehash(c, fs, 2 * (*used + added))) != LH_OK)
        return st;
    for (int m = 0; m < s->nfan; m++) {
        const fan *fn = s->fan + m;
        for (int r = 0; r < fn->len - !fn->closed; r++) {
            const lh_index f[3] = {s->p, fn->ring[r], fn->ring[(r + 1) % fn->len]};
            fs_remove(fs, f);
        }
        for (int r = 0; r < fn->ntri; r++) fs_put(fs, fn->tri + 3 * r, fn->patch);
    }
    *used += added;
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

/* Takes p off the boundary; *ok = 0, and nothing changed, when it cannot. */
static lh_status suppress_point(t3_ctx *c, faceset *fs, size_t *used, sup *s, int *ok)
{
    lh_index a, b;
    *ok = 0;
    if (!neighbours(c, s->p, &a, &b)) return LH_OK;
    lh_status st = gather(c, fs, s, ok);
    if (st != LH_OK || !*ok) return st;
    fan_sides(c, s, ok);
    for (int m = 0; *ok && m < s->nfan; m++) {
        const fan *fn = s->fan + m; /* a path runs from one neighbour of p to the other */
        if (!fn->closed && !((fn->ring[0] == a && fn->ring[fn->len - 1] == b) ||
                             (fn->ring[0] == b && fn->ring[fn->len - 1] == a)))
            *ok = 0;
        if (*ok) *ok = fan_triangulate(c, s->fan + m, a, b);
    }
    if (*ok) *ok = templates(c, s);
    for (int i = 0; *ok && i < s->nsector; i++) *ok = new_point(c, s, i);
    return *ok ? apply(c, fs, used, s) : LH_OK;
}

static int cmp_point(const void *ctx, lh_index a, lh_index b)
{
    const t3_ctx *c = ctx;
    return cmp3(pt(c, a), pt(c, b));
}

lh_status lh__t3_suppress(t3_ctx *c)
{
    size_t m = 0, used = 0;
    lh_index *list =
        lh__alloc(&c->al, (2 * (c->node_count + c->pnode_count) + 1) * sizeof(lh_index));
    sup *s = lh__alloc(&c->al, sizeof *s);
    faceset fs = {NULL, 0};
    lh_status st = list && s ? LH_OK : lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t i = 0; st == LH_OK && i < c->node_count + c->pnode_count; i++) {
        const lh_index p = i < c->node_count ? c->node[i].p : c->pnode[i - c->node_count].p;
        if ((size_t)p >= c->n_input) list[m++] = p;
    }
    if (st == LH_OK) st = fs_fill(c, &fs, &used);
    if (st == LH_OK) lh__sort_idx(list, list + m, m, cmp_point, c);
    if (st == LH_OK) { /* the sorted list without repeats */
        size_t w = 0;
        for (size_t i = 0; i < m; i++)
            if (w == 0 || list[i] != list[w - 1]) list[w++] = list[i];
        m = w;
    }
    c->journal = 0;
    /* passes over the points left: taking one off can make room around another */
    for (size_t left = m + 1; st == LH_OK && m && m < left;) {
        left = m, m = 0;
        for (size_t i = 0; st == LH_OK && i < left; i++) {
            int ok;
            s->p = list[i];
            st = suppress_point(c, &fs, &used, s, &ok);
            if (st == LH_OK && !ok) list[m++] = list[i];
        }
    }
    if (st == LH_OK && m) {
        const double *x = pt(c, list[0]);
        st = lh__t3_say(c, LH_ERR_STEINER_LIMIT, 0,
                        "-Y: %zu boundary Steiner points could not be moved off the boundary, "
                        "e.g. (%.17g, %.17g, %.17g); without -Y they stay there",
                        m, x[0], x[1], x[2]);
    }
    lh__free(&c->al, list);
    lh__free(&c->al, s);
    lh__free(&c->al, fs.slot);
    if (st != LH_OK) return st;
    lh__t3_mesh_compact(c);
    return lh__t3_stars(c);
}
