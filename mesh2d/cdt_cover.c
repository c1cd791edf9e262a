/*
 * cdt_cover.c — refining an existing mesh (Triangle's -r): its triangles (lh_pslg.cover)
 * are the domain. Their boundary edges (edges of one triangle, directed with the old
 * interior on their left) become segments before any input segment, so they own
 * their edges; subsegment parent -(i+2) names boundary edge i. Then every new
 * triangle lies inside or outside the union of the old ones: a triangle that runs
 * along a boundary edge the same way is inside, the other way outside (an exact
 * comparison of collinear directions), and a flood across edges that are not on the
 * boundary carries that to the rest. An old triangle's area bound goes to the new
 * triangles whose centroids it holds — at the start and for every triangle that
 * refinement makes, since a cavity may span several old triangles (m2_locate.c's walk
 * on the old mesh, linked by sorted edge records, from the last one found or an old
 * triangle at a vertex of the new one).
 */
#include <stdlib.h>
#include <string.h>

#include "refine.h"

typedef struct rec { lh_index lo, hi, t; int k; } rec;

static int rec_cmp(const void *x, const void *y)
{
    const rec *a = x, *b = y;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return a->t < b->t ? -1 : a->t > b->t;
}

/* The old triangles, counterclockwise (flat ones left out), linked. */
static lh_status load(lh__cover *cv, const lh_pslg *g)
{
    lh__m2 *o = &cv->mesh;
    lh_status st = lh__m2_reserve_tris(o, g->cover_count + 1);
    if (st != LH_OK) return st;
    for (size_t i = 0; i < g->cover_count; i++) {
        lh_index v[3];
        for (int k = 0; k < 3; k++) {
            v[k] = g->cover[3 * i + k];
            if (v[k] < 0 || (size_t)v[k] >= g->n) return LH_ERR_INVALID_ARGUMENT;
        }
        const int s = lh__m2_orient(o, v[0], v[1], v[2]);
        if (s == 0) continue;
        const lh_index t = lh__m2_new_tri(o);
        o->v[3 * (size_t)t] = v[0];
        o->v[3 * (size_t)t + 1] = s > 0 ? v[1] : v[2];
        o->v[3 * (size_t)t + 2] = s > 0 ? v[2] : v[1];
        cv->old[t] = (lh_index)i;
    }
    return LH_OK;
}

/* Neighbours by sorted edges; the edges of one triangle are the boundary. */
static lh_status link(lh__cover *cv, const lh_index *dup)
{
    lh__m2 *o = &cv->mesh;
    const size_t n = 3 * o->nt;
    rec *r = lh__alloc(&o->al, (n ? n : 1) * sizeof *r);
    cv->bnd = lh__alloc(&o->al, (n ? n : 1) * 2 * sizeof *cv->bnd);
    if (!r || !cv->bnd) {
        lh__free(&o->al, r);
        return LH_ERR_NOMEM;
    }
    for (size_t t = 0; t < o->nt; t++)
        for (int k = 0; k < 3; k++) {
            const lh_index a = o->v[3 * t + (k + 1) % 3], b = o->v[3 * t + (k + 2) % 3];
            r[3 * t + k] = (rec){a < b ? a : b, a < b ? b : a, (lh_index)t, k};
            o->nb[3 * t + k] = -1;
            o->sg[3 * t + k] = -1;
        }
    qsort(r, n, sizeof *r, rec_cmp);
    lh_status st = LH_OK;
    cv->bnd_count = 0;
    for (size_t i = 0; i < n && st == LH_OK;) {
        size_t j = i + 1;
        while (j < n && r[j].lo == r[i].lo && r[j].hi == r[i].hi) j++;
        if (j - i == 2) {
            o->nb[3 * (size_t)r[i].t + r[i].k] = r[i + 1].t;
            o->nb[3 * (size_t)r[i + 1].t + r[i + 1].k] = r[i].t;
        } else if (j - i == 1) {
            const size_t t = (size_t)r[i].t;
            cv->bnd[2 * cv->bnd_count] = dup[o->v[3 * t + (r[i].k + 1) % 3]];
            cv->bnd[2 * cv->bnd_count++ + 1] = dup[o->v[3 * t + (r[i].k + 2) % 3]];
        } else {
            st = LH_ERR_INVALID_ARGUMENT; /* an edge of three triangles */
        }
        i = j;
    }
    lh__free(&o->al, r);
    return st;
}

lh_status lh__cover_build(lh__cover *cv, const lh_allocator *al, const lh_pslg *g,
                          const lh_index *dup)
{
    memset(cv, 0, sizeof *cv);
    lh_status st = lh__m2_init(&cv->mesh, al, g->n, g->xy, 0, NULL, NULL);
    if (st != LH_OK) return st;
    cv->old = lh__alloc(al, (g->cover_count + 1) * sizeof *cv->old);
    if (!cv->old) return LH_ERR_NOMEM;
    if ((st = load(cv, g)) != LH_OK || (st = link(cv, dup)) != LH_OK) return st;
    for (size_t t = 0; t < cv->mesh.nt; t++)
        for (int k = 0; k < 3; k++) cv->mesh.vt[cv->mesh.v[3 * t + k]] = (lh_index)t;
    cv->mesh.walk_hint = cv->mesh.nt ? 0 : -1;
    return cv->mesh.nt ? LH_OK : LH_ERR_DEGENERATE;
}

void lh__cover_free(lh__cover *cv)
{
    if (!cv->mesh.al.free) return;
    const lh_allocator al = cv->mesh.al;
    lh__free(&al, cv->old);
    lh__free(&al, cv->bnd);
    lh__free(&al, cv->claim);
    lh__m2_free(&cv->mesh);
}

lh_status lh__cover_segments(lh__m2 *m, lh__m2_cavity *c, const lh__cover *cv, lh__m2_problem *pb)
{
    for (size_t i = 0; i < cv->bnd_count; i++) {
        const lh_index a = cv->bnd[2 * i], b = cv->bnd[2 * i + 1];
        if (a == b) continue;
        lh_status st = lh__m2_insert_segment(m, c, a, b, LH__COVER_PARENT(i), pb);
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

lh_status lh__cover_claim(lh__m2 *m, lh_index s, lh_index parent)
{
    lh__cover *cv = m->cover;
    if (!lh__m2_grow(m, (void **)&cv->claim, 2 * cv->claim_count, &cv->claim_cap, 2 * (cv->claim_count + 1),
                     sizeof(lh_index)))
        return LH_ERR_NOMEM;
    cv->claim[2 * cv->claim_count] = s;
    cv->claim[2 * cv->claim_count++ + 1] = parent;
    return LH_OK;
}

void lh__cover_relabel(lh__m2 *m, const lh__cover *cv)
{
    for (size_t i = 0; i < cv->claim_count; i++) {
        const lh_index s = cv->claim[2 * i];
        if (m->sp[s] <= LH__COVER_PARENT(0)) m->sp[s] = cv->claim[2 * i + 1];
    }
}

lh_status lh__cover_outside(lh__m2 *m, lh__m2_cavity *c, const lh__cover *cv, uint32_t e)
{
    const uint32_t in = lh__m2_new_epoch(m);
    c->stack_count = 0;
    lh_status st;
    for (size_t t = 0; t < m->nt; t++) {
        if (m->v[3 * t] < 0) continue;
        for (int k = 0; k < 3; k++) {
            const lh_index s = m->sg[3 * t + k];
            if (s < 0 || m->sp[s] > LH__COVER_PARENT(0)) continue;
            const size_t i = (size_t)LH__COVER_PARENT(m->sp[s]); /* the map is its own inverse */
            const double *x = lh__m2_pt(m, m->v[3 * t + (k + 1) % 3]), *y = lh__m2_pt(m, m->v[3 * t + (k + 2) % 3]);
            if (m->mark[t] != in && lh__m2_same_way(x, y, lh__m2_pt(m, cv->bnd[2 * i]), lh__m2_pt(m, cv->bnd[2 * i + 1]))) {
                m->mark[t] = in;
                if ((st = lh__m2_stack_push(m, c, (lh_index)t)) != LH_OK) return st;
            }
        }
    }
    while (c->stack_count) {
        const size_t t = (size_t)c->stack[--c->stack_count];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k], s = m->sg[3 * t + k];
            if (n < 0 || m->mark[n] == in || (s >= 0 && m->sp[s] <= LH__COVER_PARENT(0))) continue;
            m->mark[n] = in;
            if ((st = lh__m2_stack_push(m, c, n)) != LH_OK) return st;
        }
    }
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0 && m->mark[t] != in) m->mark[t] = e;
    return LH_OK;
}

void lh__cover_area_of(lh__m2 *m, lh__cover *cv, const double *area, lh_index t)
{
    double p[2] = {0, 0};
    for (int k = 0; k < 3; k++) {
        const double *q = lh__m2_pt(m, m->v[3 * (size_t)t + k]);
        p[0] += q[0] / 3, p[1] += q[1] / 3;
    }
    lh_index blocked, o = cv->mesh.walk_hint >= 0 ? lh__m2_locate(&cv->mesh, -1, p, 0, &blocked) : -1;
    for (int k = 0; k < 3 && o < 0; k++) { /* from an old triangle at each corner */
        const lh_index v = m->v[3 * (size_t)t + k];
        if ((size_t)v < cv->mesh.np && cv->mesh.vt[v] >= 0) o = lh__m2_locate(&cv->mesh, cv->mesh.vt[v], p, 0, &blocked);
    }
    if (o < 0) o = lh__m2_scan(&cv->mesh, p);
    if (o >= 0) m->tarea[t] = area[cv->old[o]];
}

lh_status lh__cover_areas(lh__m2 *m, lh__cover *cv, const double *area)
{
    for (size_t t = 0; t < m->nt; t++)
        if (m->v[3 * t] >= 0) lh__cover_area_of(m, cv, area, (lh_index)t);
    return LH_OK;
}
