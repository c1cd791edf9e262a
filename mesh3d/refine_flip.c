/*
 * refine_flip.c — Lawson's flips after a round's insertions (Joe, "Construction of
 * three-dimensional Delaunay triangulations using local transformations", CAGD 8,
 * 1991; in a constrained mesh, Shewchuk, "Updating and constructing constrained
 * Delaunay and constrained regular triangulations by flips", SoCG 2003): a face that
 * is no wall, between tets of one region, whose tet beyond holds its far point in its
 * circumsphere (not locally Delaunay) is flipped, 2-3 when the line of the two far
 * points crosses it, else 3-2 around the edge that line passes beyond when three
 * tets share it and it is no subsegment. Such faces are left by the flips that
 * recovered the boundary and by cavities cut short at walls; each flip lowers the
 * lifted tetrahedralization, so the flips end. They go in passes, each in the
 * coordinate order of the faces' points, so that the mesh they make depends on the
 * geometry alone.
 */
#include "refine.h"

#include "lh_sort.h"

#include <string.h>

/* Passes before the flips stop (each finds the faces the last one made). */
#define T3_FLIP_PASSES 64

/* A face to look at: its tet and corner, and its points then (corner's first). */
typedef struct t3_face {
    lh_index t, v[4];
    int j;
} t3_face;

typedef struct t3_flips {
    t3_refine *r;
    t3_ctx *c;
    t3_face *face;
    size_t count, cap;
} t3_flips;

static lh_status put(t3_flips *f, lh_index t, int j)
{
    lh_status st =
        lh__t3_grow(f->c, (void **)&f->face, &f->cap, f->count, f->count + 1, sizeof(t3_face));
    if (st != LH_OK) return st;
    t3_face *e = f->face + f->count++;
    e->t = t, e->j = j;
    const lh_index *tv = f->c->tv + 4 * (size_t)t;
    e->v[0] = tv[j];
    for (int a = 0, w = 1; a < 4; a++)
        if (a != j) e->v[w++] = tv[a];
    return LH_OK;
}

/* The point of tet u that is not in tet t. */
static lh_index far_point(const t3_ctx *c, lh_index t, lh_index u)
{
    const lh_index *tv = c->tv + 4 * (size_t)t;
    for (int a = 0; a < 4; a++) {
        const lh_index v = c->tv[4 * (size_t)u + a];
        if (v != tv[0] && v != tv[1] && v != tv[2] && v != tv[3]) return v;
    }
    return -1;
}

/* Whether face j of tet t may be flipped and is not locally Delaunay. */
static int flippable(t3_flips *f, lh_index t, int j)
{
    t3_ctx *c = f->c;
    const t3_domain *d = &f->r->d;
    const lh_index u = c->tn[4 * (size_t)t + (size_t)j];
    if (u < 0 || lh__t3_wall_of(d, (size_t)t, j) >= 0 || d->label[u] != d->label[t]) return 0;
    return lh__t3_in_sphere(c, (size_t)t, lh__t3_pt(c, far_point(c, t, u)));
}

/* The faces of tet t that are flippable into f's list. */
static lh_status put_tet(t3_flips *f, lh_index t)
{
    for (int j = 0; j < 4; j++)
        if (flippable(f, t, j)) {
            lh_status st = put(f, t, j);
            if (st != LH_OK) return st;
        }
    return LH_OK;
}

static int cmp_face(const void *ctx, lh_index i, lh_index j)
{
    const t3_flips *f = ctx;
    const t3_face *a = f->face + i, *b = f->face + j;
    lh_index p[4], q[4];
    memcpy(p, a->v, sizeof p), memcpy(q, b->v, sizeof q);
    lh__t3_sort_points(f->c, p + 1, 3), lh__t3_sort_points(f->c, q + 1, 3);
    for (int k = 1; k < 5; k++) {
        const int s = lh__t3_cmp_xyz(lh__t3_pt(f->c, p[k % 4]), lh__t3_pt(f->c, q[k % 4]));
        if (s) return s;
    }
    return 0;
}

/* Replaces the n tets old by the m tets nv (any orientation), keeping the walls of
 * their outer faces and their region; *done whether it went (no new tet flat). */
static lh_status replace(t3_flips *f, lh_index *old, int n, lh_index (*nv)[4], int m, int *done)
{
    t3_ctx *c = f->c;
    t3_refine *r = f->r;
    *done = 0;
    for (int i = 0; i < m; i++)
        if (lh__t3_shape_sorted(c, nv[i][0], nv[i][1], nv[i][2], nv[i][3]) < T3_SLIVER)
            return LH_OK;
    lh_status st = lh__t3_domain_room(r, c->tet_count + (size_t)m);
    if (st != LH_OK) return st;
    lh_index walls[3 * 4][4]; /* outer faces: sorted points, wall */
    int nw = 0;
    const lh_index label = r->d.label[old[0]];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 4; j++) {
            const lh_index w = lh__t3_wall_of(&r->d, (size_t)old[i], j);
            if (w < 0) continue;
            for (int a = 0, k = 0; a < 4; a++)
                if (a != j) walls[nw][k++] = c->tv[4 * (size_t)old[i] + a];
            lh__t3_sort3(walls[nw]);
            walls[nw++][3] = w;
        }
    st = lh__t3_mesh_replace(c, old, n, nv, m, done);
    if (st != LH_OK || !*done) return st;
    for (int i = 0; i < c->made_count; i++) {
        const size_t s = (size_t)c->made[i];
        r->d.label[s] = label;
        for (int j = 0; j < 4; j++) {
            lh_index g[3];
            for (int a = 0, k = 0; a < 4; a++)
                if (a != j) g[k++] = c->tv[4 * s + (size_t)a];
            lh__t3_sort3(g);
            r->d.wall[4 * s + (size_t)j] = -1;
            for (int w = 0; w < nw; w++)
                if (!memcmp(g, walls[w], sizeof g)) r->d.wall[4 * s + (size_t)j] = walls[w][3];
        }
    }
    return LH_OK;
}

/* The tet around edge a b next to t across its face a b x, or -1. */
static lh_index beside(const t3_ctx *c, lh_index t, lh_index a, lh_index b, lh_index x)
{
    const lh_index *tv = c->tv + 4 * (size_t)t;
    for (int j = 0; j < 4; j++)
        if (tv[j] != a && tv[j] != b && tv[j] != x) return c->tn[4 * (size_t)t + (size_t)j];
    return -1;
}

/* Flips face e (its tet t, the corner j opposite: point d; the far point q of the
 * tet u beyond): 2-3 when the line d q crosses the face inside, else 3-2 around the
 * face's edge it passes beyond, when three tets share that edge in one region with
 * no wall and it is no subsegment. */
static lh_status flip(t3_flips *f, const t3_face *e, int *done)
{
    t3_ctx *c = f->c;
    const lh_index t = e->t, u = c->tn[4 * (size_t)t + (size_t)e->j], d = e->v[0];
    const lh_index q = far_point(c, t, u), *g = e->v + 1;
    int s[3], out = -1;
    *done = 0;
    for (int k = 0; k < 3; k++) s[k] = lh__t3_orient4(c, d, q, g[k], g[(k + 1) % 3]);
    if (s[0] != 0 && s[0] == s[1] && s[1] == s[2]) {
        lh_index old[2] = {t, u};
        lh_index nv[3][4] = {{d, q, g[0], g[1]}, {d, q, g[1], g[2]}, {d, q, g[2], g[0]}};
        return replace(f, old, 2, nv, 3, done);
    }
    for (int k = 0; k < 3 && out < 0; k++) /* the edge whose sign differs from the others' */
        if (s[k] != 0 && s[(k + 1) % 3] == s[(k + 2) % 3] && s[k] != s[(k + 1) % 3]) out = k;
    if (out < 0) return LH_OK;
    const lh_index a = g[out], b = g[(out + 1) % 3], x = g[(out + 2) % 3];
    const lh_index w = beside(c, t, a, b, x);
    if (w < 0 || w != beside(c, u, a, b, x) || far_point(c, t, w) != q) return LH_OK;
    const t3_domain *dm = &f->r->d;
    if (dm->label[w] != dm->label[t] || lh__t3_sub_slot(f->r, a < b ? a : b, a < b ? b : a)[0] >= 0)
        return LH_OK;
    for (int j = 0; j < 4; j++) /* no wall among the faces around a b */
        if ((c->tv[4 * (size_t)t + j] != a && c->tv[4 * (size_t)t + j] != b &&
             lh__t3_wall_of(dm, (size_t)t, j) >= 0) ||
            (c->tv[4 * (size_t)w + j] != a && c->tv[4 * (size_t)w + j] != b &&
             lh__t3_wall_of(dm, (size_t)w, j) >= 0))
            return LH_OK;
    if (lh__t3_orient4(c, x, d, q, a) * lh__t3_orient4(c, x, d, q, b) >= 0) return LH_OK;
    lh_index old[3] = {t, u, w};
    lh_index nv[2][4] = {{x, d, q, a}, {x, d, q, b}};
    return replace(f, old, 3, nv, 2, done);
}

/* One pass: the listed faces in coordinate order, each flipped when it is still a
 * face and still flippable; the faces of the tets flips made listed for the next. */
static lh_status pass(t3_flips *f)
{
    t3_ctx *c = f->c;
    const size_t n = f->count;
    lh_index *idx = lh__alloc(&c->al, (2 * n + 1) * sizeof(lh_index));
    t3_face *list = lh__alloc(&c->al, (n + 1) * sizeof(t3_face));
    if (!idx || !list) {
        lh__free(&c->al, idx);
        lh__free(&c->al, list);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    for (size_t i = 0; i < n; i++) idx[i] = (lh_index)i;
    lh__sort_idx(idx, idx + n, n, cmp_face, f);
    for (size_t i = 0; i < n; i++) list[i] = f->face[idx[i]];
    f->count = 0;
    lh_status st = LH_OK;
    for (size_t i = 0; i < n && st == LH_OK; i++) {
        const t3_face *e = list + i;
        const lh_index *tv = c->tv + 4 * (size_t)e->t;
        int same = tv[0] >= 0 && tv[e->j] == e->v[0]; /* a dead slot, or another tet there */
        for (int k = 1; k < 4; k++)
            same &= tv[0] == e->v[k] || tv[1] == e->v[k] || tv[2] == e->v[k] || tv[3] == e->v[k];
        if (!same || !flippable(f, e->t, e->j)) continue;
        int done = 0;
        st = flip(f, e, &done);
        lh_index made[T3_FLIP_TETS];
        const int nm = done ? c->made_count : 0;
        memcpy(made, c->made, (size_t)nm * sizeof(lh_index));
        for (int k = 0; k < nm && st == LH_OK; k++) st = put_tet(f, made[k]);
    }
    lh__free(&c->al, idx);
    lh__free(&c->al, list);
    return st;
}

lh_status lh__t3_refine_flips(t3_refine *r, size_t first)
{
    t3_ctx *c = r->c;
    t3_flips f;
    memset(&f, 0, sizeof f);
    f.r = r, f.c = c;
    lh_status st = LH_OK;
    for (size_t t = first; t < c->tet_count && st == LH_OK; t++)
        if (c->tv[4 * t] >= 0) st = put_tet(&f, (lh_index)t);
    for (int p = 0; p < T3_FLIP_PASSES && f.count && st == LH_OK; p++) st = pass(&f);
    lh__free(&c->al, f.face);
    return st;
}
