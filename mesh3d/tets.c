/*
 * tets.c — the mesh the constraints are sought in (t3_ctx.tv, .tn): loaded from the
 * Delaunay tetrahedralization after each insertion, then changed by flips that
 * replace a few tetrahedra by others filling the same region (recover_flip.c).
 * Replaced tetrahedra stay as dead slots (tv[4 t] = -1) until compaction.
 */
#include "recover.h"

#include <string.h>

static lh_status grow(t3_ctx *c, lh_index **a, size_t cap, size_t old, size_t per)
{
    lh_index *x = lh__alloc(&c->al, per * cap * sizeof(lh_index));
    if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    if (old) memcpy(x, *a, per * old * sizeof(lh_index));
    lh__free(&c->al, *a);
    *a = x;
    return LH_OK;
}

/* Room for need tets in tv, tn and tmark, and for every point in vtet. */
static lh_status room(t3_ctx *c, size_t need)
{
    lh_status st = LH_OK;
    if (need > c->tet_cap) {
        size_t cap = 2 * need + 16;
        st = grow(c, &c->tv, cap, c->tet_count, 4);
        if (st == LH_OK) st = grow(c, &c->tn, cap, c->tet_count, 4);
        if (st == LH_OK) st = grow(c, &c->tmark, cap, c->tet_count, 1);
        if (st != LH_OK) return st;
        memset(c->tmark + c->tet_count, 0, (cap - c->tet_count) * sizeof(lh_index));
        c->tet_cap = cap;
    }
    if (c->n > c->vtet_cap) {
        size_t cap = 2 * c->n + 16;
        if ((st = grow(c, &c->vtet, cap, c->vtet_cap, 1)) != LH_OK) return st;
        for (size_t v = c->vtet_cap; v < cap; v++) c->vtet[v] = -1;
        c->vtet_cap = cap;
    }
    return LH_OK;
}

lh_status lh__t3_mesh_room(t3_ctx *c, size_t need)
{
    return room(c, need);
}

static void note_points(t3_ctx *c, size_t t)
{
    for (int j = 0; j < 4; j++) c->vtet[c->tv[4 * t + j]] = (lh_index)t;
}

lh_status lh__t3_mesh_load(t3_ctx *c)
{
    size_t count = lh_tri_count(c->dt);
    c->tet_count = 0;
    lh_status st = room(c, count);
    if (st != LH_OK) return st;
    memcpy(c->tv, lh_tri_simplices(c->dt), 4 * count * sizeof(lh_index));
    memcpy(c->tn, lh_tri_neighbors(c->dt), 4 * count * sizeof(lh_index));
    memset(c->tmark, 0, count * sizeof(lh_index));
    c->tet_count = count;
    for (size_t v = 0; v < c->n; v++) c->vtet[v] = -1;
    for (size_t t = 0; t < count; t++) note_points(c, t);
    return LH_OK;
}

lh_index lh__t3_mesh_mark(t3_ctx *c)
{
    if (++c->tgen == 0x7fffffff) { /* the marks wrap: start again from zero */
        memset(c->tmark, 0, c->tet_count * sizeof(lh_index));
        c->tgen = 1;
    }
    return c->tgen;
}

lh_status lh__t3_mesh_star(t3_ctx *c, lh_index v, size_t *count)
{
    size_t k = 0;
    lh_index gen = lh__t3_mesh_mark(c), t0 = c->vtet[v];
    *count = 0;
    if (t0 < 0) return LH_OK;
    lh_status st = lh__t3_room(c, &c->sbuf, &c->scap, 1);
    if (st != LH_OK) return st;
    c->sbuf[k++] = t0;
    c->tmark[t0] = gen;
    for (size_t i = 0; i < k; i++) { /* across the faces through v */
        const lh_index t = c->sbuf[i];
        for (int j = 0; j < 4; j++) {
            lh_index u = c->tn[4 * (size_t)t + j];
            if (c->tv[4 * (size_t)t + j] == v || u < 0 || c->tmark[u] == gen) continue;
            if ((st = lh__t3_room(c, &c->sbuf, &c->scap, k + 1)) != LH_OK) return st;
            c->tmark[u] = gen;
            c->sbuf[k++] = u;
        }
    }
    *count = k;
    return LH_OK;
}

/* Whether face f (3 points) and g are the same set. */
static int same_face(const lh_index *f, const lh_index *g)
{
    for (int i = 0; i < 3; i++)
        if (f[i] != g[0] && f[i] != g[1] && f[i] != g[2]) return 0;
    return 1;
}

static void face_of(const lh_index *tet, int j, lh_index *f)
{
    int w = 0;
    for (int k = 0; k < 4; k++)
        if (k != j) f[w++] = tet[k];
}

/* One outer face of the replaced tets: its points, the tet beyond and the slot of
 * that tet that points back. */
typedef struct outer_face {
    lh_index f[3], u;
    int back;
} outer_face;

/* lh_index slots an outer_face takes in c->rbuf, rounded up. */
#define OUTER ((sizeof(outer_face) + sizeof(lh_index) - 1) / sizeof(lh_index))

/* Journal entry of a replacement, pushed on c->jbuf: each old tet (slot, points,
 * neighbours: 9), each outer tet's pointer back (tet, slot, value: 3), then the
 * counts (old tets, pointers, tets in the mesh before: 3). */
static lh_status journal(t3_ctx *c, const lh_index *old, int nold, const outer_face *of, int nof)
{
    lh_status st =
        lh__t3_room(c, &c->jbuf, &c->jcap, c->jlen + 9 * (size_t)nold + 3 * (size_t)nof + 3);
    if (st != LH_OK) return st;
    lh_index *j = c->jbuf + c->jlen;
    for (int i = 0; i < nold; i++, j += 9) {
        j[0] = old[i];
        memcpy(j + 1, c->tv + 4 * (size_t)old[i], 4 * sizeof(lh_index));
        memcpy(j + 5, c->tn + 4 * (size_t)old[i], 4 * sizeof(lh_index));
    }
    int nback = 0;
    for (int k = 0; k < nof; k++) {
        if (of[k].u < 0) continue;
        j[0] = of[k].u, j[1] = of[k].back;
        j[2] = c->tn[4 * (size_t)of[k].u + of[k].back];
        j += 3, nback++;
    }
    j[0] = nold, j[1] = nback, j[2] = (lh_index)c->tet_count;
    c->jlen = (size_t)(j + 3 - c->jbuf);
    return LH_OK;
}

void lh__t3_mesh_undo(t3_ctx *c, size_t mark)
{
    c->made_count = 0;
    while (c->jlen > mark) {
        const lh_index *h = c->jbuf + c->jlen - 3;
        int nold = (int)h[0], nback = (int)h[1];
        c->tet_count = (size_t)h[2];
        const lh_index *b = h - 3 * (size_t)nback, *o = b - 9 * (size_t)nold;
        for (int k = 0; k < nback; k++) c->tn[4 * (size_t)b[3 * k] + b[3 * k + 1]] = b[3 * k + 2];
        for (int i = 0; i < nold; i++) {
            const lh_index *e = o + 9 * i;
            memcpy(c->tv + 4 * (size_t)e[0], e + 1, 4 * sizeof(lh_index));
            memcpy(c->tn + 4 * (size_t)e[0], e + 5, 4 * sizeof(lh_index));
            c->tmark[e[0]] = 0;
            note_points(c, (size_t)e[0]);
        }
        c->flips--;
        c->jlen = (size_t)(o - c->jbuf);
    }
}

lh_status lh__t3_mesh_replace(t3_ctx *c, const lh_index *old, int nold, lh_index (*nv)[4], int nnew,
                              int *ok)
{
    *ok = 0;
    for (int i = 0; i < nnew; i++) { /* every new tet positive, none flat */
        const double *p[4];
        for (int k = 0; k < 4; k++) p[k] = c->xyz + 3 * (size_t)nv[i][k];
        int o = lh_orient(c->pred, 3, p);
        if (o == 0) return LH_OK;
        if (o < 0) {
            lh_index x = nv[i][0];
            nv[i][0] = nv[i][1];
            nv[i][1] = x;
        }
    }
    size_t need = c->tet_count + (size_t)(nnew > nold ? nnew - nold : 0);
    lh_status st = room(c, need);
    if (st == LH_OK) st = lh__t3_room(c, &c->rbuf, &c->rcap, OUTER * 4 * (size_t)nold + (size_t)nnew);
    if (st != LH_OK) return st;
    outer_face *of = (outer_face *)(void *)c->rbuf;
    lh_index *slot = c->rbuf + OUTER * 4 * (size_t)nold;
    int nof = 0;
    for (int i = 0; i < nold; i++)
        for (int j = 0; j < 4; j++) {
            lh_index u = c->tn[4 * (size_t)old[i] + j];
            int inside = 0;
            for (int k = 0; k < nold; k++) inside |= u == old[k];
            if (inside) continue;
            outer_face *o = of + nof++;
            face_of(c->tv + 4 * (size_t)old[i], j, o->f);
            o->u = u, o->back = -1;
            for (int k = 0; u >= 0 && k < 4; k++)
                if (c->tn[4 * (size_t)u + k] == old[i]) o->back = k;
        }
    if (c->journal && (st = journal(c, old, nold, of, nof)) != LH_OK) return st;
    for (int i = 0; i < nnew; i++) slot[i] = i < nold ? old[i] : (lh_index)c->tet_count++;
    c->made_count = nnew <= T3_FLIP_TETS ? nnew : 0;
    memcpy(c->made, slot, (size_t)c->made_count * sizeof(lh_index));
    for (int i = nnew; i < nold; i++) c->tv[4 * (size_t)old[i]] = -1; /* dead */
    for (int i = 0; i < nnew; i++) {
        const size_t t = (size_t)slot[i];
        memcpy(c->tv + 4 * t, nv[i], 4 * sizeof(lh_index));
        c->tmark[t] = 0;
    }
    for (int i = 0; i < nnew; i++)
        for (int j = 0; j < 4; j++) {
            lh_index f[3], g[3], to = -1;
            face_of(nv[i], j, f);
            int found = 0;
            for (int k = 0; k < nof && !found; k++)
                if (same_face(f, of[k].f)) {
                    found = 1, to = of[k].u;
                    if (to >= 0) c->tn[4 * (size_t)to + of[k].back] = slot[i];
                }
            for (int k = 0; k < nnew && !found; k++)
                for (int m = 0; m < 4 && k != i && !found; m++) {
                    face_of(nv[k], m, g);
                    if (same_face(f, g)) found = 1, to = slot[k];
                }
            c->tn[4 * (size_t)slot[i] + j] = to;
        }
    for (int i = 0; i < nnew; i++) note_points(c, (size_t)slot[i]);
    c->flips++;
    *ok = 1;
    return LH_OK;
}

void lh__t3_mesh_compact(t3_ctx *c)
{
    size_t w = 0;
    lh_index *map = c->tmark; /* the marks serve as the renumbering */
    for (size_t t = 0; t < c->tet_count; t++) map[t] = c->tv[4 * t] < 0 ? -1 : (lh_index)w++;
    for (size_t t = 0; t < c->tet_count; t++) {
        if (map[t] < 0) continue;
        for (int j = 0; j < 4; j++) {
            lh_index u = c->tn[4 * t + j];
            c->tn[4 * (size_t)map[t] + j] = u < 0 ? -1 : map[u];
            c->tv[4 * (size_t)map[t] + j] = c->tv[4 * t + j];
        }
    }
    c->tet_count = w;
    memset(c->tmark, 0, w * sizeof(lh_index));
    c->tgen = 0;
    for (size_t v = 0; v < c->n; v++) c->vtet[v] = -1;
    for (size_t t = 0; t < w; t++) note_points(c, t);
}

int lh__t3_mesh_side(t3_ctx *c, size_t t, int j, const double *q)
{
    const double *p[4];
    for (int k = 0; k < 4; k++) p[k] = k == j ? q : c->xyz + 3 * (size_t)c->tv[4 * t + k];
    return lh_orient(c->pred, 3, p);
}

/* A walk that crosses a face q lies beyond, starting each step from another face so
 * that it cannot cycle for long in a mesh that flips made non-Delaunay; every tet is
 * tried when the walk leaves the mesh or runs long. */
lh_index lh__t3_mesh_walk(t3_ctx *c, lh_index t0, const double *q)
{
    lh_index t = t0;
    for (size_t step = 0; t >= 0 && step < 4 * c->tet_count + 64; step++) {
        int out = -1;
        for (int i = 0; i < 4 && out < 0; i++) {
            int j = (int)((step + (size_t)i) % 4);
            if (lh__t3_mesh_side(c, (size_t)t, j, q) < 0) out = j;
        }
        if (out < 0) return t;
        t = c->tn[4 * (size_t)t + out];
    }
    for (size_t u = 0; u < c->tet_count; u++) {
        if (c->tv[4 * u] < 0) continue; /* dead */
        int in = 1;
        for (int j = 0; j < 4 && in; j++) in = lh__t3_mesh_side(c, u, j, q) >= 0;
        if (in) return (lh_index)u;
    }
    return -1;
}
