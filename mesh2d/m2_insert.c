/*
 * m2_insert.c — Bowyer-Watson insertion of a point into the constrained Delaunay
 * triangulation (Bowyer 1981; Watson 1981; constrained: the cavity never crosses a
 * subsegment, Chew 1989). The cavity is the triangles reachable from the one holding
 * p whose circumcircles hold p strictly (exact incircle), so it is star-shaped from
 * p; that is checked anyway (exact orient_2 on every new triangle) and a point that
 * fails it is refused, leaving the mesh as it was. A point splitting subsegment s
 * starts from both triangles beside s and keeps the two halves as subsegments.
 */
#include <math.h>

#include "m2.h"
#include "m2_geom.h"

/* p encroaches subsegment s: it sees s under more than 90 degrees (inside the
 * diametral circle, Ruppert 1995), or, with m->lens set for an angle bound t, more
 * than 180 - 2t degrees (inside the diametral lens, Shewchuk 2002 §4.4): the apex
 * angle's cosine is below -cos 2t, i.e. dot < 0 and dot^2 >= cos^2 2t |pa|^2 |pb|^2,
 * on the two vectors each scaled by a power of two (m2_geom.h). */
int lh__m2_encroaches(const lh__m2 *m, lh_index s, const double *p)
{
    double u[2], v[2]; /* p->a and p->b, each scaled alone: the angle is scale-free */
    lh__g_vec(p, lh__m2_pt(m, m->sv[2 * (size_t)s]), u);
    lh__g_vec(p, lh__m2_pt(m, m->sv[2 * (size_t)s + 1]), v);
    const double dot = lh__g_dot(u, v);
    if (!(dot < 0)) return 0;
    return m->lens <= 0 || dot * dot >= m->lens * (u[0] * u[0] + u[1] * u[1]) * (v[0] * v[0] + v[1] * v[1]);
}

static lh_status grow_cavity(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index split,
                             uint32_t e, lh__m2_ins *r)
{
    lh_status st;
    for (size_t i = 0; i < c->dead_count; i++) {
        const size_t t = (size_t)c->dead[i];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k], s = m->sg[3 * t + k];
            if (n >= 0 && m->mark[n] == e) continue;
            if (s >= 0) {
                if (s != split && r->check_encroach && lh__m2_encroaches(m, s, p)) {
                    if (!lh__m2_grow(m, (void **)&r->enc, r->enc_count, &r->enc_cap,
                                     r->enc_count + 1, sizeof(lh_index)))
                        return LH_ERR_NOMEM;
                    r->enc[r->enc_count++] = s;
                }
                continue;
            }
            if (n < 0) continue;
            const lh_index *v = m->v + 3 * (size_t)n;
            if (lh__m2_incircle(m, v[0], v[1], v[2], p) >= 0) continue;
            m->mark[n] = e;
            if ((st = lh__m2_cavity_push_dead(m, c, n)) != LH_OK) return st;
        }
    }
    return LH_OK;
}

/* The new triangles: p joined to every boundary edge of the cavity but s's. */
static lh_status fan(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index pi,
                     lh_index split, const lh_index half[2], uint32_t e, int *bad)
{
    const lh_index sa = split >= 0 ? m->sv[2 * (size_t)split] : -1;
    const lh_index sb = split >= 0 ? m->sv[2 * (size_t)split + 1] : -1;
    *bad = 0;
    for (size_t i = 0; i < c->dead_count; i++) {
        const size_t t = (size_t)c->dead[i];
        for (int k = 0; k < 3; k++) {
            const lh_index n = m->nb[3 * t + k];
            if (n >= 0 && m->mark[n] == e) continue;
            if (split >= 0 && m->sg[3 * t + k] == split) continue;
            const lh_index x = m->v[3 * t + (k + 1) % 3], y = m->v[3 * t + (k + 2) % 3];
            if (pi < 0) { /* first pass: geometry only */
                if (lh__m2_orient_pt(m, x, y, p) <= 0) *bad = 1;
                continue;
            }
            /* edge opposite x is y-p, opposite y is p-x */
            lh_index sg[3] = {-1, -1, -1};
            if (split >= 0) {
                sg[0] = y == sa ? half[0] : y == sb ? half[1] : -1;
                sg[1] = x == sa ? half[0] : x == sb ? half[1] : -1;
            }
            lh_status st = lh__m2_cavity_push_tri(m, c, x, y, pi, sg);
            if (st == LH_OK) st = lh__m2_cavity_push_bnd(m, c, (lh_index)t, k);
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

/* Mark triangle t dead in epoch e and push it on the cavity. */
static lh_status mark_dead(lh__m2 *m, lh__m2_cavity *c, lh_index t, uint32_t e)
{
    m->mark[t] = e;
    return lh__m2_cavity_push_dead(m, c, t);
}

/* Seed the cavity of a point splitting subsegment split: the one or two triangles
 * beside it, or r->result = LH__M2_REFUSED with the cavity left empty. */
static lh_status seed_split(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index split,
                            uint32_t e, lh__m2_ins *r)
{
    int pos;
    const lh_index t = lh__m2_find_subseg(m, split, &pos);
    if (t < 0) return LH_ERR_INTERNAL;
    const lh_index n = m->nb[3 * (size_t)t + pos];
    /* The two triangles beside the subsegment join the cavity whatever incircle
     * says, so p must lie in or on both circumcircles: only then are the new edges
     * from p locally Delaunay (Bowyer-Watson's argument). A rounded split point can
     * miss: beside a subsegment much shorter than the circle's radius R (below about
     * sqrt(8 R ulp)) the circle's sagitta is under the rounding, and p rounded to
     * the far side left an unconstrained edge that was not Delaunay. Refused. */
    for (int j = 0; j < 2; j++) {
        const lh_index u = j ? n : t;
        if (u >= 0 && lh__m2_incircle(m, m->v[3 * (size_t)u], m->v[3 * (size_t)u + 1], m->v[3 * (size_t)u + 2], p) > 0) {
            r->result = LH__M2_REFUSED;
            return LH_OK;
        }
    }
    lh_status st = mark_dead(m, c, t, e);
    if (st == LH_OK && n >= 0) st = mark_dead(m, c, n, e);
    return st;
}

/* Seed the cavity of a free point: the triangle holding p, reached from start (in
 * a straight line from r->origin when set). Sets r->result to LH__M2_OUTSIDE,
 * LH__M2_BLOCKED or LH__M2_DUPLICATE instead when p is no new interior point. */
static lh_status seed_free(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index start, uint32_t e,
                           lh__m2_ins *r)
{
    lh_index blocked;
    const lh_index t = r->origin ? lh__m2_walk_line(m, start, r->origin, p, &blocked)
                                 : lh__m2_locate(m, start, p, 1, &blocked);
    if (t < 0 || blocked >= 0) {
        r->result = t < 0 ? LH__M2_OUTSIDE : LH__M2_BLOCKED;
        r->blocked = blocked;
        return LH_OK;
    }
    const lh_index *v = m->v + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
        const double *q = lh__m2_pt(m, v[k]);
        if (q[0] == p[0] && q[1] == p[1]) {
            r->result = LH__M2_DUPLICATE;
            r->vertex = v[k];
            return LH_OK;
        }
    }
    return mark_dead(m, c, t, e);
}

/* Add p as a vertex and fan it over the checked cavity; a split subsegment
 * becomes a-p (split itself) and p-b (a new subsegment). */
static lh_status add_and_fan(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index split,
                             uint32_t e, lh__m2_ins *r)
{
    lh_status st;
    int bad;
    lh_index pi, half[2] = {-1, -1};
    if ((st = lh__m2_add_point(m, p, &pi)) != LH_OK) return st;
    if (split >= 0) {
        const lh_index b = m->sv[2 * (size_t)split + 1];
        if ((st = lh__m2_add_subseg(m, pi, b, m->sp[split], &half[1])) != LH_OK) return st;
        m->smul[half[1]] = m->smul[split];
        m->sv[2 * (size_t)split + 1] = pi; /* split keeps a-p */
        half[0] = split;
        /* fan() compares with the old endpoints: give it b back for the pass */
        m->sv[2 * (size_t)split + 1] = b;
        if ((st = fan(m, c, p, pi, split, half, e, &bad)) != LH_OK) return st;
        m->sv[2 * (size_t)split + 1] = pi;
        m->pseg[pi] = m->sp[split];
    } else if ((st = fan(m, c, p, pi, -1, half, e, &bad)) != LH_OK) {
        return st;
    }
    if ((st = lh__m2_cavity_apply_fan(m, c)) != LH_OK) return st;
    r->vertex = pi;
    return LH_OK;
}

lh_status lh__m2_insert_point(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index start,
                              lh_index split, lh__m2_ins *r)
{
    r->result = LH__M2_INSERTED;
    r->enc_count = 0;
    r->vertex = -1;
    lh__m2_cavity_clear(c);
    const uint32_t e = lh__m2_new_epoch(m);
    lh_status st = split >= 0 ? seed_split(m, c, p, split, e, r) : seed_free(m, c, p, start, e, r);
    if (st != LH_OK || r->result != LH__M2_INSERTED) return st;
    if ((st = grow_cavity(m, c, p, split, e, r)) != LH_OK) return st;
    if (r->enc_count) {
        r->result = LH__M2_ENCROACHES;
        return LH_OK;
    }
    int bad;
    if ((st = fan(m, c, p, -1, split, NULL, e, &bad)) != LH_OK) return st;
    if (bad) {
        r->result = LH__M2_REFUSED;
        return LH_OK;
    }
    return add_and_fan(m, c, p, split, e, r);
}
