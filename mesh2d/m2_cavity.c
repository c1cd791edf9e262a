/*
 * m2_cavity.c — replacing a set of triangles by another that covers the same region
 * (m2.h, lh__m2_cavity): the one step behind segment insertion (Anglada 1997; Shewchuk
 * & Brown 2015, "Fast segment insertion and incremental construction of constrained
 * Delaunay triangulations") and Bowyer-Watson point insertion (Bowyer 1981; Watson
 * 1981). The caller decides the geometry; this file only relinks: new triangles'
 * edges are paired by their vertex pair (sorted records), and an edge of a new
 * triangle that runs the same way as a boundary edge of the cavity takes that edge's
 * outside neighbour and subsegment.
 */
#include <stdlib.h>
#include <string.h>

#include "m2.h"

enum { BND = 6 }; /* boundary record: x, y, outside triangle, subsegment, its position
                     there, the dead triangle it is an edge of */

void lh__m2_cavity_free(lh__m2 *m, lh__m2_cavity *c)
{
    lh__free(&m->al, c->dead);
    lh__free(&m->al, c->tri);
    lh__free(&m->al, c->tsg);
    lh__free(&m->al, c->bnd);
    lh__free(&m->al, c->rec);
    lh__free(&m->al, c->stack);
    lh__free(&m->al, c->chain[0]);
    lh__free(&m->al, c->chain[1]);
    lh__free(&m->al, c->reg);
    memset(c, 0, sizeof *c);
}

void lh__m2_cavity_clear(lh__m2_cavity *c) { c->dead_count = c->tri_count = c->bnd_count = 0; }

lh_status lh__m2_cavity_push_dead(lh__m2 *m, lh__m2_cavity *c, lh_index t)
{
    if (!lh__m2_grow(m, (void **)&c->dead, c->dead_count, &c->dead_cap, c->dead_count + 1,
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    c->dead[c->dead_count++] = t;
    return LH_OK;
}

lh_status lh__m2_stack_push(lh__m2 *m, lh__m2_cavity *c, lh_index t)
{
    if (!lh__m2_grow(m, (void **)&c->stack, c->stack_count, &c->stack_cap, c->stack_count + 1,
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    c->stack[c->stack_count++] = t;
    return LH_OK;
}

lh_status lh__m2_cavity_push_tri(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b,
                                 lh_index d, const lh_index sg[3])
{
    size_t cap = c->tri_cap;
    if (!lh__m2_grow(m, (void **)&c->tri, 3 * c->tri_count, &cap, 3 * (c->tri_count + 1),
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    size_t cap2 = c->tri_cap;
    if (!lh__m2_grow(m, (void **)&c->tsg, 3 * c->tri_count, &cap2, 3 * (c->tri_count + 1),
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    c->tri_cap = cap < cap2 ? cap : cap2;
    lh_index *v = c->tri + 3 * c->tri_count, *s = c->tsg + 3 * c->tri_count;
    v[0] = a, v[1] = b, v[2] = d;
    for (int k = 0; k < 3; k++) s[k] = sg ? sg[k] : -1;
    c->tri_count++;
    return LH_OK;
}

static int rec_less(const lh_index *x, const lh_index *y)
{
    return x[0] != y[0] ? x[0] < y[0] : x[1] != y[1] ? x[1] < y[1] : x[2] < y[2];
}

static int rec_cmp(const void *x, const void *y)
{
    return rec_less(x, y) ? -1 : rec_less(y, x) ? 1 : 0;
}

/* Sorts the records (3 lh_index each): insertion sort for the usual few dozen. */
static void sort_records(lh_index *r, size_t n)
{
    if (n > 48) {
        qsort(r, n, 3 * sizeof *r, rec_cmp);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        lh_index t[3] = {r[3 * i], r[3 * i + 1], r[3 * i + 2]};
        size_t j = i;
        for (; j > 0 && rec_less(t, r + 3 * (j - 1)); j--) memcpy(r + 3 * j, r + 3 * (j - 1), sizeof t);
        memcpy(r + 3 * j, t, sizeof t);
    }
}

static void put_record(lh_index *r, lh_index x, lh_index y, lh_index who)
{
    r[0] = x < y ? x : y;
    r[1] = x < y ? y : x;
    r[2] = who;
}

/* The cavity's boundary: edges of dead triangles whose other side is not dead. */
static lh_status collect_boundary(lh__m2 *m, lh__m2_cavity *c, uint32_t e)
{
    c->bnd_count = 0;
    for (size_t i = 0; i < c->dead_count; i++) {
        const size_t t = (size_t)c->dead[i];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k];
            if (n >= 0 && m->mark[n] == e) continue;
            lh_status st = lh__m2_cavity_push_bnd(m, c, (lh_index)t, k);
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

/* The region (attribute, area bound) of each new triangle, into c->reg before the
 * dead triangles' slots are reused: that of the dead triangle whose boundary edge it
 * takes, else dead[0]'s. A cavity crosses no subsegment but the one a point splits
 * (lh__m2_insert_point), so the dead triangles on each side of that one lie in one
 * region each (regions flood across every other edge, cdt_domain.c), and each new
 * triangle lies on one side, holding a boundary edge of that side: the regions stay
 * bounded by the segments, as in Triangle, where a triangle's pieces keep its
 * attribute. fan: new triangle i holds boundary edge i (lh__m2_cavity_apply_fan);
 * else the nr sorted records pair them. */
static lh_status new_regions(lh__m2 *m, lh__m2_cavity *c, int fan, size_t nr)
{
    if (!m->tattr || !c->dead_count) return LH_OK;
    if (!lh__m2_grow(m, (void **)&c->reg, 0, &c->reg_cap, 2 * c->tri_count, sizeof(double)))
        return LH_ERR_NOMEM;
    for (size_t i = 0; i < c->tri_count; i++) {
        const size_t d = (size_t)(fan ? c->bnd[BND * i + 5] : c->dead[0]);
        c->reg[2 * i] = m->tattr[d], c->reg[2 * i + 1] = m->tarea[d];
    }
    for (size_t i = 0; !fan && i + 1 < nr; i++) {
        const lh_index *r = c->rec + 3 * i; /* a boundary record sorts first in its pair */
        if (r[0] != r[3] || r[1] != r[4] || r[2] >= 0 || r[5] < 0) continue;
        const size_t d = (size_t)c->bnd[BND * (size_t)(-r[2] - 1) + 5], k = (size_t)r[5] / 3;
        c->reg[2 * k] = m->tattr[d], c->reg[2 * k + 1] = m->tarea[d];
    }
    return LH_OK;
}

/* New triangle i, in slot t, takes its region from c->reg (none without dead ones). */
static void set_region(lh__m2 *m, const lh__m2_cavity *c, size_t i, size_t t)
{
    if (!m->tattr) return;
    m->tattr[t] = c->dead_count ? c->reg[2 * i] : 0;
    m->tarea[t] = c->dead_count ? c->reg[2 * i + 1] : 0;
}

lh_status lh__m2_cavity_apply(lh__m2 *m, lh__m2_cavity *c)
{
    const uint32_t e = lh__m2_new_epoch(m);
    for (size_t i = 0; i < c->dead_count; i++) m->mark[c->dead[i]] = e;
    lh_status st = collect_boundary(m, c, e);
    if (st != LH_OK) return st;
    const size_t nr = 3 * c->tri_count + c->bnd_count;
    if (!lh__m2_grow(m, (void **)&c->rec, 0, &c->rec_cap, 3 * nr, sizeof(lh_index)))
        return LH_ERR_NOMEM;
    /* the dead triangles' slots are reused: only the excess needs room */
    if (c->tri_count > c->dead_count && (st = lh__m2_reserve_tris(m, c->tri_count - c->dead_count)) != LH_OK)
        return st;
    size_t r = 0;
    for (size_t i = 0; i < c->tri_count; i++)
        for (int k = 0; k < 3; k++)
            put_record(c->rec + 3 * r++, c->tri[3 * i + (k + 1) % 3], c->tri[3 * i + (k + 2) % 3],
                       (lh_index)(3 * i + k));
    for (size_t j = 0; j < c->bnd_count; j++)
        put_record(c->rec + 3 * r++, c->bnd[BND * j], c->bnd[BND * j + 1], -(lh_index)j - 1);
    sort_records(c->rec, nr);

    if ((st = new_regions(m, c, 0, nr)) != LH_OK) return st;
    for (size_t i = 0; i < c->dead_count; i++) lh__m2_kill_tri(m, c->dead[i]);
    lh_index *id = c->stack; /* new triangle ids: reuse the stack's storage */
    c->stack_count = 0;
    for (size_t i = 0; i < c->tri_count; i++) {
        if ((st = lh__m2_stack_push(m, c, lh__m2_new_tri(m))) != LH_OK) return st;
        id = c->stack;
        const size_t t = (size_t)id[i];
        set_region(m, c, i, t);
        for (int k = 0; k < 3; k++) {
            m->v[3 * t + k] = c->tri[3 * i + k];
            m->sg[3 * t + k] = c->tsg[3 * i + k];
            m->nb[3 * t + k] = -1;
            m->vt[c->tri[3 * i + k]] = (lh_index)t;
        }
    }
    /* pair the records: new-new (opposite directions) or new-boundary (same direction) */
    for (size_t i = 0; i < nr;) {
        size_t j = i + 1;
        while (j < nr && c->rec[3 * j] == c->rec[3 * i] && c->rec[3 * j + 1] == c->rec[3 * i + 1]) j++;
        if (j - i == 2) {
            const lh_index a = c->rec[3 * i + 2], b = c->rec[3 * i + 5]; /* a < b: boundary first */
            if (b < 0) return LH_ERR_INTERNAL; /* two boundary edges alike */
            const size_t tb = (size_t)id[b / 3];
            if (a >= 0) {
                const size_t ta = (size_t)id[a / 3];
                m->nb[3 * ta + a % 3] = (lh_index)tb;
                m->nb[3 * tb + b % 3] = (lh_index)ta;
            } else {
                const lh_index *bd = c->bnd + BND * (size_t)(-a - 1), n = bd[2];
                m->nb[3 * tb + b % 3] = n;
                m->sg[3 * tb + b % 3] = bd[3];
                if (n >= 0) m->nb[3 * (size_t)n + bd[4]] = (lh_index)tb;
            }
        } else if (j - i != 1 || (c->rec[3 * i + 2] < 0 && c->bnd[BND * (size_t)(-c->rec[3 * i + 2] - 1) + 2] >= 0)) {
            return LH_ERR_INTERNAL; /* an edge on three sides, or an uncovered live edge */
        }
        i = j;
    }
    return LH_OK;
}

lh_status lh__m2_cavity_push_bnd(lh__m2 *m, lh__m2_cavity *c, lh_index t, int k)
{
    if (!lh__m2_grow(m, (void **)&c->bnd, BND * c->bnd_count, &c->bnd_cap, BND * (c->bnd_count + 1),
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    lh_index *b = c->bnd + BND * c->bnd_count++;
    const lh_index n = m->nb[3 * (size_t)t + k];
    b[0] = m->v[3 * (size_t)t + (k + 1) % 3];
    b[1] = m->v[3 * (size_t)t + (k + 2) % 3];
    b[2] = n;
    b[3] = m->sg[3 * (size_t)t + k];
    b[4] = n >= 0 ? lh__m2_npos(m, n, t) : -1;
    b[5] = t;
    return LH_OK;
}

/* The fan case: new triangle i is (x_i, y_i, p) on boundary edge i (c->bnd, pushed
 * in the same order), so its neighbour across x_i-y_i is that edge's outside, and
 * across y_i-p and p-x_i the fan triangles starting at y_i and ending at x_i: a
 * search among the few triangles of the fan (the general pairing past 32). */
lh_status lh__m2_cavity_apply_fan(lh__m2 *m, lh__m2_cavity *c)
{
    const size_t k = c->tri_count;
    if (k > 32 || c->bnd_count != k) {
        c->bnd_count = 0;
        return lh__m2_cavity_apply(m, c);
    }
    lh_status st = k > c->dead_count ? lh__m2_reserve_tris(m, k - c->dead_count) : LH_OK;
    if (st != LH_OK) return st;
    if ((st = new_regions(m, c, 1, 0)) != LH_OK) return st;
    for (size_t i = 0; i < c->dead_count; i++) lh__m2_kill_tri(m, c->dead[i]);
    lh_index id[32];
    c->stack_count = 0;
    for (size_t i = 0; i < k; i++) {
        if ((st = lh__m2_stack_push(m, c, lh__m2_new_tri(m))) != LH_OK) return st;
        id[i] = c->stack[i];
    }
    for (size_t i = 0; i < k; i++) {
        const size_t t = (size_t)id[i];
        const lh_index *v = c->tri + 3 * i, *b = c->bnd + BND * i;
        set_region(m, c, i, t);
        lh_index nx = -1, ny = -1; /* across y-p: starts at y; across p-x: ends at x */
        for (size_t j = 0; j < k; j++) {
            if (c->tri[3 * j] == v[1]) nx = id[j];
            if (c->tri[3 * j + 1] == v[0]) ny = id[j];
        }
        for (int q = 0; q < 3; q++) {
            m->v[3 * t + q] = v[q];
            m->vt[v[q]] = (lh_index)t;
        }
        m->nb[3 * t] = nx, m->nb[3 * t + 1] = ny, m->nb[3 * t + 2] = b[2];
        m->sg[3 * t] = c->tsg[3 * i], m->sg[3 * t + 1] = c->tsg[3 * i + 1], m->sg[3 * t + 2] = b[3];
        if (b[2] >= 0) m->nb[3 * (size_t)b[2] + b[4]] = (lh_index)t;
    }
    return LH_OK;
}
