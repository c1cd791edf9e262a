/*
 * refine_split.c — where a bad tetrahedron is split (refine.h): its circumcentre, or,
 * when that encroaches the boundary, the subsegment's or subface's point, queued for
 * the round's insertion. Which one is decided in floating point (tet_geom.c) and
 * only steers refinement: the insertion and the recovery after it are exact.
 */
#include "refine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The circumcentre and radius of triangle f, from its corners in coordinate order
 * (the same figures whatever the numbering); 0 when flat. */
static int face_circumcentre(const t3_ctx *c, const lh_index *f, double cc[3], double *rad)
{
    const double *p[3];
    lh__t3_sorted_points(c, f, 3, p);
    return lh__t3_tri_circumcentre(p[0], p[1], p[2], cc, rad);
}

/* Simplices a, b (n points each) compared by their points in coordinate order. */
static int cmp_simplex(const t3_ctx *c, const lh_index *a, const lh_index *b, int n)
{
    const double *p[2][3];
    lh__t3_sorted_points(c, a, n, p[0]);
    lh__t3_sorted_points(c, b, n, p[1]);
    for (int i = 0; i < n; i++) {
        int s = lh__t3_cmp_xyz(p[0][i], p[1][i]);
        if (s) return s;
    }
    return 0;
}

/* Whether face j of tet t is where the domain ends for a walk: a wall, the hull, or
 * a tet outside. */
static int blocked(const t3_refine *r, size_t t, int j)
{
    const lh_index u = r->c->tn[4 * t + (size_t)j];
    return u < 0 || r->d.label[u] == T3_OUT || lh__t3_wall_of(&r->d, t, j) >= 0;
}

/* A walk from tet t towards x: the tet holding x (*hit = -1), or the tet whose face
 * *hit the walk would cross out of the domain or through a wall; -1 when it runs
 * longer than T3_REGION_MAX steps (a circumcentre that far from its tet, a sliver's,
 * is left as a conflict region that large is; or a cycle in a mesh flips made
 * non-Delaunay). Of the faces x lies beyond, it crosses the one whose opposite
 * corner is first in coordinate order: a path of the geometry alone, whatever the
 * tets' and points' numbers. */
static lh_index walk(t3_refine *r, lh_index t, const double *x, int *hit)
{
    t3_ctx *c = r->c;
    for (size_t step = 0; step < T3_REGION_MAX; step++) {
        int out = -1;
        for (int j = 0; j < 4; j++) {
            if (lh__t3_mesh_side(c, (size_t)t, j, x) >= 0) continue;
            if (out < 0 || lh__t3_cmp_xyz(lh__t3_pt(c, c->tv[4 * (size_t)t + (size_t)j]),
                                          lh__t3_pt(c, c->tv[4 * (size_t)t + (size_t)out])) < 0)
                out = j;
        }
        *hit = out;
        if (out < 0 || blocked(r, (size_t)t, out)) return t;
        t = c->tn[4 * (size_t)t + out];
    }
    return -1;
}

int lh__t3_in_sphere(t3_ctx *c, size_t t, const double *x)
{
    const double *p[5];
    for (int j = 0; j < 4; j++) p[j] = lh__t3_pt(c, c->tv[4 * t + j]);
    p[4] = x;
    return lh_insphere_sos(c->pred, 3, p) < 0;
}

/* Appends to r->reg the conflict region of x from the tets r->reg[first..]: they
 * and the tets reached across faces that are not blocked whose circumspheres hold x
 * (Bowyer-Watson): a set of the geometry alone. r->cut when it reaches
 * T3_REGION_MAX tets (then only part of it is gathered). */
static lh_status grow(t3_refine *r, size_t first, const double *x)
{
    t3_ctx *c = r->c;
    const lh_index gen = lh__t3_mesh_mark(c);
    for (size_t i = first; i < r->reg_count; i++) c->tmark[r->reg[i]] = gen;
    for (size_t i = first; i < r->reg_count && r->reg_count - first < T3_REGION_MAX; i++) {
        const size_t t = (size_t)r->reg[i];
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * t + (size_t)j];
            if (blocked(r, t, j) || c->tmark[u] == gen || !lh__t3_in_sphere(c, (size_t)u, x))
                continue;
            lh_status st = lh__t3_room(c, &r->reg, &r->reg_cap, r->reg_count + 1);
            if (st != LH_OK) return st;
            c->tmark[u] = gen;
            r->reg[r->reg_count++] = u;
        }
    }
    r->cut |= r->reg_count - first >= T3_REGION_MAX;
    return LH_OK;
}

/* The conflict region of x from tet t0, appended to r->reg. */
static lh_status conflict(t3_refine *r, lh_index t0, const double *x)
{
    lh_status st = lh__t3_room(r->c, &r->reg, &r->reg_cap, r->reg_count + 1);
    if (st != LH_OK) return st;
    r->reg[r->reg_count++] = t0;
    return grow(r, r->reg_count - 1, x);
}

/* The conflict region of x from every tet at edge p q (x on it: all of them hold
 * it, on both sides of the facets through it), appended to r->reg. */
static lh_status conflict_edge(t3_refine *r, lh_index p, lh_index q, const double *x)
{
    t3_ctx *c = r->c;
    const size_t first = r->reg_count;
    for (lh_index i = c->star_first[p]; i < c->star_first[p + 1]; i++) {
        const lh_index t = c->star[i], *v = c->tv + 4 * (size_t)t;
        if (v[0] != q && v[1] != q && v[2] != q && v[3] != q) continue;
        lh_status st = lh__t3_room(c, &r->reg, &r->reg_cap, r->reg_count + 1);
        if (st != LH_OK) return st;
        r->reg[r->reg_count++] = t;
    }
    return grow(r, first, x);
}

/* The subsegment p q's entry (p, q, segment, chain index), or NULL. */
static const lh_index *sub_find(const t3_refine *r, lh_index p, lh_index q)
{
    const lh_index *e = lh__t3_sub_slot(r, p < q ? p : q, p < q ? q : p);
    return e[0] >= 0 ? e : NULL;
}

/* Among the edges of r->reg[from..] the subsegment x encroaches first in coordinate
 * order, or NULL. */
static const lh_index *encroached_seg(const t3_refine *r, size_t from, const double *x)
{
    const t3_ctx *c = r->c;
    const lh_index *best = NULL;
    for (size_t i = from; i < r->reg_count; i++) {
        const lh_index *v = c->tv + 4 * (size_t)r->reg[i];
        for (int a = 0; a < 4; a++)
            for (int b = a + 1; b < 4; b++) {
                const lh_index *e = sub_find(r, v[a], v[b]);
                if (!e || (best && cmp_simplex(c, e, best, 2) >= 0)) continue;
                if (lh__t3_in_diametral(lh__t3_pt(c, e[0]), lh__t3_pt(c, e[1]), x)) best = e;
            }
    }
    return best;
}

/* Among the walls of r->reg's tets the subface x encroaches (inside its equatorial
 * sphere) first in coordinate order: its tet and face into *t, *j; 0 when none. */
static int encroached_face(const t3_refine *r, const double *x, lh_index *t, int *j)
{
    const t3_ctx *c = r->c;
    lh_index best[3] = {-1, -1, -1};
    for (size_t i = 0; i < r->reg_count; i++) {
        const size_t u = (size_t)r->reg[i];
        for (int k = 0; k < 4; k++) {
            if (lh__t3_wall_of(&r->d, u, k) < 0) continue;
            lh_index f[3];
            for (int a = 0, w = 0; a < 4; a++)
                if (a != k) f[w++] = c->tv[4 * u + (size_t)a];
            if (best[0] >= 0 && cmp_simplex(c, f, best, 3) >= 0) continue;
            double cc[3], rad;
            if (!face_circumcentre(c, f, cc, &rad)) continue;
            if (!(lh__t3_dist(cc, x) < rad)) continue;
            memcpy(best, f, sizeof f);
            *t = (lh_index)u, *j = k;
        }
    }
    return best[0] >= 0;
}

/* Whether x lies in patch k: in one of its triangles, projected along its axis
 * (exact orient_2 on the projected doubles), and not on its polygon edges. */
static int in_patch(t3_ctx *c, size_t k, const double *x)
{
    const int ax = abs(c->patch_axis[k]) - 1, i0 = (ax + 1) % 3, i1 = (ax + 2) % 3;
    const double X[2] = {x[i0], x[i1]};
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++) {
        const size_t t = (size_t)c->patch_tri[a];
        double P[3][2];
        for (int e = 0; e < 3; e++) {
            const double *q = lh__t3_pt(c, c->tri[3 * t + (size_t)e]);
            P[e][0] = q[i0], P[e][1] = q[i1];
        }
        const double *tri[3] = {P[0], P[1], P[2]};
        const int o = lh_orient(c->pred, 2, tri);
        int inside = o != 0;
        for (int e = 0; e < 3 && inside; e++) {
            const double *side[3] = {P[e], P[(e + 1) % 3], X};
            const int s = lh_orient(c->pred, 2, side) * o;
            inside = s > 0 || (s == 0 && c->tri_seg[3 * t + (size_t)e] < 0);
        }
        if (inside) return 1;
    }
    return 0;
}

/* The subsegment of patch k's polygon edges that x encroaches first in coordinate
 * order, or NULL. A subface's circumcentre outside
 * its facet encroaches one (Shewchuk 1998, the projection lemma). */
static const lh_index *patch_encroached_seg(t3_refine *r, size_t k, const double *x)
{
    t3_ctx *c = r->c;
    const lh_index *best = NULL;
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++)
        for (int e = 0; e < 3; e++) {
            const lh_index s = c->tri_seg[3 * (size_t)c->patch_tri[a] + (size_t)e];
            if (s < 0) continue;
            size_t cl = (size_t)(c->node_first[s + 1] - c->node_first[s]) + 2;
            if (lh__t3_room(c, &c->vbuf, &c->vcap, cl) != LH_OK) return NULL;
            lh__t3_chain(c, s, c->vbuf, c->vcap);
            for (size_t i = 0; i + 1 < cl; i++) {
                const lh_index *f = sub_find(r, c->vbuf[i], c->vbuf[i + 1]);
                if (!f || (best && cmp_simplex(c, f, best, 2) >= 0)) continue;
                if (lh__t3_in_diametral(lh__t3_pt(c, f[0]), lh__t3_pt(c, f[1]), x)) best = f;
            }
        }
    return best;
}

lh_status lh__t3_refuse(t3_refine *r, const double *x)
{
    t3_ctx *c = r->c;
    if (r->refused_count == r->refused_cap) {
        size_t cap = 2 * r->refused_cap + 8;
        double *y = lh__alloc(&c->al, 3 * cap * sizeof(double));
        if (!y) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        if (r->refused_count) memcpy(y, r->refused, 3 * r->refused_count * sizeof(double));
        lh__free(&c->al, r->refused);
        r->refused = y, r->refused_cap = cap;
    }
    memcpy(r->refused + 3 * r->refused_count++, x, 3 * sizeof(double));
    return LH_OK;
}

/* Drops the last queued point when it was refused (r->why then says so). */
static void unless_refused(t3_refine *r)
{
    t3_ctx *c = r->c;
    if (c->new_count == 0 || c->new_node[c->new_count - 1].p >= 0) return;
    const double *x = c->new_xyz + 3 * (c->new_count - 1);
    for (size_t i = 0; i < r->refused_count; i++)
        if (lh__t3_cmp_xyz(r->refused + 3 * i, x) == 0) {
            c->new_count--;
            r->why = LH_LEFT_REFUSED;
            return;
        }
}

/* Queues point x (for segment or patch seg, as lh__t3_queue) unless refused. */
static lh_status queue(t3_refine *r, lh_index seg, const double *x)
{
    r->why = T3_QUEUED;
    lh_status st = lh__t3_queue(r->c, seg, 0, -1, x);
    if (st == LH_OK) unless_refused(r);
    return st;
}

/* *ok: whether x, with conflict region r->reg[from..], goes in this round. Not when
 * the region was cut; not nearer a corner of the region than the spacing (half the
 * input's closest pair, or cbrt(v) / 4 under a volume bound v: t3_refine.spacing),
 * so that refinement ends however small the input's angles (a bounded domain holds
 * finitely many points that far apart; the tets it cannot improve are counted); and
 * not nearer a point taken this round whose region meets x's than the two points'
 * insertion radii (their distances to the nearest corners of their regions), so the
 * round's points never crowd each other (r->why says which). If it goes, its
 * region's tets are claimed for it. */
static lh_status admit(t3_refine *r, size_t from, const double *x, int *ok)
{
    const t3_ctx *c = r->c;
    double near = INFINITY;
    *ok = 0;
    for (size_t i = from; i < r->reg_count && !r->cut; i++)
        for (int j = 0; j < 4; j++)
            near =
                fmin(near, lh__t3_dist(lh__t3_pt(c, c->tv[4 * (size_t)r->reg[i] + (size_t)j]), x));
    r->why = r->cut ? LH_LEFT_REGION : LH_LEFT_SPACING;
    if (r->cut || !(near >= r->spacing_now)) return LH_OK;
    r->why = T3_CLAIMED;
    for (size_t i = from; i < r->reg_count; i++) {
        const lh_index t = r->reg[i];
        if (r->claim[t] != r->round) continue;
        const double *q = r->taken + 4 * (size_t)r->claim_by[t];
        if (lh__t3_dist(q, x) < fmin(near, q[3])) return LH_OK;
    }
    if (r->taken_count == r->taken_cap) {
        size_t cap = 2 * r->taken_cap + 64;
        double *y = lh__alloc(&r->c->al, 4 * cap * sizeof(double));
        if (!y) return lh__t3_say(r->c, LH_ERR_NOMEM, 0, "out of memory");
        if (r->taken_count) memcpy(y, r->taken, 4 * r->taken_count * sizeof(double));
        lh__free(&r->c->al, r->taken);
        r->taken = y, r->taken_cap = cap;
    }
    double *q = r->taken + 4 * r->taken_count;
    memcpy(q, x, 3 * sizeof(double)), q[3] = near;
    for (size_t i = from; i < r->reg_count; i++)
        r->claim[r->reg[i]] = r->round, r->claim_by[r->reg[i]] = (lh_index)r->taken_count;
    r->taken_count++;
    return *ok = 1, LH_OK;
}

/* Queues the split of subsegment e (its entry in r->sub) if its midpoint is
 * admitted. */
static lh_status split_seg(t3_refine *r, const lh_index *e)
{
    t3_ctx *c = r->c;
    const double *p = lh__t3_pt(c, e[0]), *q = lh__t3_pt(c, e[1]);
    r->why = LH_LEFT_BOUNDARY;
    if (!c->opt->boundary_steiner) return LH_OK;
    double mid[3];
    for (int k = 0; k < 3; k++) mid[k] = p[k] / 2 + q[k] / 2;
    const size_t from = r->reg_count;
    lh_status st = conflict_edge(r, e[0], e[1], mid);
    int ok = 0;
    if (st == LH_OK) st = admit(r, from, mid, &ok);
    if (st != LH_OK || !ok) return st;
    r->why = T3_QUEUED;
    st = lh__t3_split(c, e[2], (size_t)e[3]);
    if (st == LH_OK) unless_refused(r);
    if (st != LH_ERR_STEINER_LIMIT) return st;
    r->why = LH_LEFT_SPACING; /* no double between its ends: left */
    return LH_OK;
}

/* Queues the split of the subface that is face j of tet u: at its circumcentre, or
 * at the subsegment that encroaches. */
static lh_status split_face(t3_refine *r, lh_index u, int j)
{
    t3_ctx *c = r->c;
    const lh_index facet = lh__t3_wall_of(&r->d, (size_t)u, j);
    lh_index f[3];
    for (int a = 0, w = 0; a < 4; a++)
        if (a != j) f[w++] = c->tv[4 * (size_t)u + (size_t)a];
    double x[3], rad;
    r->why = c->opt->boundary_steiner ? LH_LEFT_FACET : LH_LEFT_BOUNDARY;
    if (!c->opt->boundary_steiner || !face_circumcentre(c, f, x, &rad)) return LH_OK;
    const lh_index k = facet < 0 ? -1 : r->facet_patch[facet];
    if (facet >= 0 && k < 0) return LH_OK;
    if (k >= 0 && !in_patch(c, (size_t)k, x)) { /* outside its facet: no walk to it */
        const lh_index *e = patch_encroached_seg(r, (size_t)k, x);
        return e ? split_seg(r, e) : LH_OK;
    }
    /* x's conflict region from where walks from both sides of the subface end */
    const size_t from = r->reg_count;
    const lh_index side[2] = {u, c->tn[4 * (size_t)u + (size_t)j]};
    for (int s = 0; s < 2; s++) {
        int hit;
        const lh_index xu =
            side[s] < 0 || r->d.label[side[s]] == T3_OUT ? -1 : walk(r, side[s], x, &hit);
        if (xu < 0 || (r->reg_count > from && r->reg[from] == xu)) continue;
        lh_status st = lh__t3_room(c, &r->reg, &r->reg_cap, r->reg_count + 1);
        if (st != LH_OK) return st;
        r->reg[r->reg_count++] = xu;
    }
    r->why = LH_LEFT_REGION;
    if (r->reg_count == from) return LH_OK;
    lh_status st = grow(r, from, x);
    if (st != LH_OK) return st;
    const lh_index *e = encroached_seg(r, from, x);
    if (e) return split_seg(r, e);
    if (facet < 0) { /* the convex hull's (-c): its circumcentre, in no facet */
        int ok;
        st = admit(r, from, x, &ok);
        return st != LH_OK || !ok ? st : queue(r, T3_INTERIOR, x);
    }
    int ok;
    st = admit(r, from, x, &ok);
    return st != LH_OK || !ok ? st : queue(r, -1 - k, x);
}

/* Queues the point that splits bad tet b at x (its circumcentre or centroid). */
static lh_status split_at(t3_refine *r, const t3_bad *b, const double *x)
{
    int hit, j;
    r->spacing_now = b->spacing, r->cut = 0, r->why = LH_LEFT_REGION;
    const lh_index u = walk(r, b->t, x, &hit);
    if (u < 0) return LH_OK;
    r->reg_count = 0;
    lh_status st = conflict(r, u, x);
    if (st != LH_OK) return st;
    const lh_index *e = encroached_seg(r, 0, x);
    if (e) return split_seg(r, e);
    if (hit >= 0) return split_face(r, u, hit);
    lh_index t;
    if (encroached_face(r, x, &t, &j)) return split_face(r, t, j);
    int ok;
    st = admit(r, 0, x, &ok);
    return st != LH_OK || !ok ? st : queue(r, T3_INTERIOR, x);
}

/* Queues the centroid g of bad tet b, inside it: in the domain, so that insertion in
 * the mesh as it stands takes it whatever subfaces it encroaches. */
static lh_status split_inside(t3_refine *r, const t3_bad *b, const double *g)
{
    r->spacing_now = b->spacing, r->cut = 0, r->why = LH_LEFT_REGION, r->reg_count = 0;
    int ok;
    lh_status st = conflict(r, b->t, g);
    if (st == LH_OK) st = admit(r, 0, g, &ok);
    return st != LH_OK || !ok ? st : queue(r, T3_INTERIOR, g);
}

lh_status lh__t3_refine_split(t3_refine *r, const t3_bad *b)
{
    lh_status st = split_at(r, b, b->cc);
    const int left =
        r->why == LH_LEFT_SPACING || r->why == LH_LEFT_FACET || r->why == LH_LEFT_REFUSED;
    if (st != LH_OK || !left || !(b->over & 2)) return st;
    /* over its volume bound, its circumcentre too near a point (a mesh that is not
       Delaunay there holds points in circumspheres), or the subface it encroaches
       not to be split: its centroid, as the bound must be met (summed in coordinate
       order, the same whatever the numbering) */
    const double *p[4];
    lh__t3_sorted_points(r->c, r->c->tv + 4 * (size_t)b->t, 4, p);
    double g[3];
    for (int k = 0; k < 3; k++) g[k] = p[0][k] / 4 + p[1][k] / 4 + p[2][k] / 4 + p[3][k] / 4;
    return split_inside(r, b, g);
}
