/*
 * refine.c — the rounds of quality refinement (refine.h): scan the domain's
 * tetrahedra against their bounds, queue the worst first as an independent set
 * (refine_split.c), insert, recover the boundary again.
 */
#include "refine.h"

#include "lh_sort.h"

#include <math.h>
#include <string.h>

/* Rounds before refinement stops with tets still over their bounds (counted): each
 * round splits every bad tet whose region no earlier one took, so an input it ends on
 * needs far fewer. */
#define T3_REFINE_ROUNDS 2000

/* The tet's corners in coordinate order. */
static void sorted_corners(const t3_ctx *c, lh_index t, const double *q[4])
{
    lh__t3_sorted_points(c, c->tv + 4 * (size_t)t, 4, q);
}

/* Worst first; ties by circumcentre, then corners: an order of the geometry alone,
 * whatever the tets' numbers (so the output does not depend on the input's order). */
static int cmp_bad(const void *ctx, lh_index i, lh_index j)
{
    const t3_refine *r = ctx;
    const t3_bad *a = r->bad + i, *b = r->bad + j;
    if (a->key != b->key) return a->key > b->key ? -1 : 1;
    int s = lh__t3_cmp_xyz(a->cc, b->cc);
    if (s) return s;
    const double *p[4], *q[4];
    sorted_corners(r->c, a->t, p);
    sorted_corners(r->c, b->t, q);
    for (int k = 0; k < 4; k++)
        if ((s = lh__t3_cmp_xyz(p[k], q[k])) != 0) return s;
    return 0;
}

double lh__t3_volume_bound(const t3_ctx *c, lh_index reg)
{
    double v = c->opt->max_volume > 0 ? c->opt->max_volume : 0;
    if (c->opt->region_volumes && reg >= 0 && (size_t)reg < c->g->region_count) {
        const double rv = c->g->regions[5 * (size_t)reg + 4];
        if (rv > 0 && (v == 0 || rv < v)) v = rv;
    }
    return v;
}

static lh_status bad_room(t3_refine *r)
{
    return lh__t3_grow(r->c, (void **)&r->bad, &r->bad_cap, r->bad_count, r->bad_count + 1,
                       sizeof(t3_bad));
}

/* The slot of tet v (4 points, sorted) in r->gave_up: its entry, else the empty slot
 * where it goes. */
static lh_index *gave_up_slot(const t3_refine *r, const lh_index *v)
{
    size_t h = 0;
    for (int k = 0; k < 4; k++) h = (h ^ (size_t)v[k]) * 0x9e3779b97f4a7c15u;
    h = (h >> 17) & (r->gave_up_cap - 1);
    for (lh_index *e = r->gave_up + 5 * h;;
         h = (h + 1) & (r->gave_up_cap - 1), e = r->gave_up + 5 * h)
        if (e[0] < 0 || !memcmp(e, v, 4 * sizeof(lh_index))) return e;
}

/* Tet t's points, sorted by index. */
static void tet_key(const t3_ctx *c, size_t t, lh_index *v)
{
    memcpy(v, c->tv + 4 * t, 4 * sizeof(lh_index));
    for (int i = 1; i < 4; i++)
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            lh_index x = v[j];
            v[j] = v[j - 1], v[j - 1] = x;
        }
}

/* Records that tet t's split was given up for `why`: later rounds leave it, while it
 * stands (its circumcentre, its subfaces and what lies near them rarely change
 * without a point inserted in its circumsphere, which takes it out). */
static lh_status give_up(t3_refine *r, size_t t, int why)
{
    t3_ctx *c = r->c;
    if (2 * (r->gave_up_count + 1) > r->gave_up_cap) {
        const size_t old = r->gave_up_cap, cap = old ? 2 * old : 1024;
        lh_index *was = r->gave_up, *x = lh__alloc(&c->al, 5 * cap * sizeof(lh_index));
        if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        for (size_t i = 0; i < 5 * cap; i++) x[i] = -1;
        r->gave_up = x, r->gave_up_cap = cap;
        for (size_t i = 0; i < old; i++)
            if (was[5 * i] >= 0)
                memcpy(gave_up_slot(r, was + 5 * i), was + 5 * i, 5 * sizeof(lh_index));
        lh__free(&c->al, was);
    }
    lh_index v[4];
    tet_key(c, t, v);
    lh_index *e = gave_up_slot(r, v);
    r->gave_up_count += e[0] < 0;
    memcpy(e, v, sizeof v);
    e[4] = why;
    return LH_OK;
}

/* Why tet t's split was given up, or LH_LEFT_STOPPED (not yet tried). */
static int given_up(const t3_refine *r, size_t t)
{
    if (!r->gave_up_count) return LH_LEFT_STOPPED;
    lh_index v[4];
    tet_key(r->c, t, v);
    const lh_index *e = gave_up_slot(r, v);
    return e[0] < 0 ? LH_LEFT_STOPPED : (int)e[4];
}

/* How far tet m is over the size the sizing function asks at its circumcentre (its
 * circumradius over that size: TetGen's -m reads a size as the radius of the ball a
 * point protects), 0 when no size applies there; the spacing that size asks into
 * *spacing (unchanged when none). */
static double over_size(const t3_refine *r, const t3_tet_measure *m, double *spacing)
{
    const lh_tetmesh_options *o = r->c->opt;
    if (!o->sizing) return 0;
    const double h = o->sizing(o->sizing_user, m->cc);
    if (!(h > 0 && isfinite(h))) return 0;
    *spacing = fmin(*spacing, h / 4);
    return m->radius / h;
}

/* Below this angle (degrees) between two segments at a point, refinement leaves the
 * tets whose shortest edge joins them (Shewchuk's analysis needs 60; the cascade of
 * splits near a smaller angle is what would not end). */
#define T3_SMALL_ANGLE 60
/* The ends of a seditious edge are this near to one concentric shell: their
 * distances from the apex within this factor. */
#define T3_SHELL 1.2

/* Whether edge u v is seditious (Shewchuk, "Delaunay refinement algorithms for
 * triangular mesh generation", CGTA 22 (2002), sec. 3.7, in 3D): its ends lie inside
 * two segments that meet at a point at an angle below T3_SMALL_ANGLE, at distances
 * from it within a factor T3_SHELL (the splits' concentric shells put them at equal
 * ones): a split there would make a shorter such edge. */
static int seditious(const t3_refine *r, lh_index u, lh_index v)
{
    const t3_ctx *c = r->c;
    const lh_index s1 = r->on_seg[u], s2 = r->on_seg[v];
    if (s1 < 0 || s2 < 0 || s1 == s2) return 0;
    const t3_seg *a = c->seg + s1, *b = c->seg + s2;
    const lh_index apex = a->a == b->a || a->a == b->b   ? a->a
                          : a->b == b->a || a->b == b->b ? a->b
                                                         : -1;
    if (apex < 0) return 0;
    const double *o = lh__t3_pt(c, apex), *pu = lh__t3_pt(c, u), *pv = lh__t3_pt(c, v);
    double du[3], dv[3];
    for (int k = 0; k < 3; k++) du[k] = pu[k] - o[k], dv[k] = pv[k] - o[k];
    const double lu = lh__t3_dist(pu, o), lv = lh__t3_dist(pv, o);
    if (!(lu > 0 && lv > 0) || lu > T3_SHELL * lv || lv > T3_SHELL * lu) return 0;
    const double cosine = lh__t3_dot(du, dv) / lu / lv;
    return cosine > cos(T3_SMALL_ANGLE * (3.14159265358979323846 / 180));
}

/* Whether tet t's shortest edge (the first in coordinate order among equals) is
 * seditious. */
static int by_small_angle(const t3_refine *r, size_t t)
{
    const t3_ctx *c = r->c;
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    lh_index tv[4];
    memcpy(tv, c->tv + 4 * t, sizeof tv);
    lh__t3_sort_points(c, tv, 4);
    double least = INFINITY;
    int k = 0;
    for (int i = 0; i < 6; i++) {
        const double d = lh__t3_dist(lh__t3_pt(c, tv[e[i][0]]), lh__t3_pt(c, tv[e[i][1]]));
        if (d < least) least = d, k = i;
    }
    return seditious(r, tv[e[k][0]], tv[e[k][1]]);
}

/* The domain's tets over their bounds into r->bad, counted by bound. */
static lh_status scan(t3_refine *r)
{
    t3_ctx *c = r->c;
    r->bad_count = 0, r->over_ratio = 0, r->over_volume = 0, r->over_size = 0;
    for (size_t t = 0; t < c->tet_count; t++) {
        if (r->d.label[t] == T3_OUT) continue;
        const double *p[4];
        sorted_corners(c, (lh_index)t, p); /* the same figures whatever the numbering */
        t3_tet_measure m;
        lh__t3_tet_measure(p, &m);
        const double v = lh__t3_volume_bound(c, r->d.label[t]);
        double spacing = v > 0 ? fmin(r->spacing, cbrt(v) / 4) : r->spacing;
        const double size = over_size(r, &m, &spacing);
        const int over_r = r->ratio > 0 && m.ratio > r->ratio;
        const int over_v = v > 0 && lh__t3_volume_over(&m, v);
        const int over_s = size > 1;
        if (!over_r && !over_v && !over_s) continue;
        r->over_ratio += over_r, r->over_volume += over_v, r->over_size += over_s;
        lh_status st = bad_room(r);
        if (st != LH_OK) return st;
        t3_bad *b = r->bad + r->bad_count++;
        b->t = (lh_index)t;
        b->key = over_r ? m.ratio / r->ratio : 0;
        if (over_v) b->key = fmax(b->key, cbrt(m.volume_frac / ldexp(v, -3 * m.scale_exp)));
        if (over_s) b->key = fmax(b->key, size);
        memcpy(b->cc, m.cc, sizeof m.cc);
        b->spacing = spacing;
        b->over = over_r | over_v << 1 | over_s << 2;
        b->why = given_up(r, t); /* LH_LEFT_STOPPED until its split is tried */
        if (b->over == 1 && b->why == LH_LEFT_STOPPED && by_small_angle(r, t))
            b->why = LH_LEFT_ANGLE;
    }
    return LH_OK;
}

static lh_status put_subsegment(t3_ctx *c, lh_index p, lh_index q, lh_index s, size_t i, void *r)
{
    (void)c;
    lh_index *e = lh__t3_sub_slot(r, p, q);
    ((t3_refine *)r)->sub_count += e[0] < 0;
    e[0] = p, e[1] = q, e[2] = s, e[3] = (lh_index)i;
    return LH_OK;
}

/* The subsegments (consecutive points of each segment's chain) into r->sub, with
 * room for `extra` more. */
static lh_status subsegments(t3_refine *r, size_t extra)
{
    t3_ctx *c = r->c;
    size_t count = c->node_count + c->seg_count + extra, cap = 16;
    while (cap < 2 * count) cap *= 2;
    if (cap > r->sub_cap) {
        lh__free(&c->al, r->sub);
        if (!(r->sub = lh__alloc(&c->al, 4 * cap * sizeof(lh_index))))
            return r->sub_cap = 0, lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        r->sub_cap = cap;
    }
    for (size_t i = 0; i < 4 * r->sub_cap; i++) r->sub[i] = -1;
    r->sub_count = 0;
    lh__free(&c->al, r->on_seg);
    if (!(r->on_seg = lh__alloc(&c->al, (c->n + 1) * sizeof(lh_index))))
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t p = 0; p < c->n; p++) r->on_seg[p] = -1;
    for (size_t i = 0; i < c->node_count; i++) r->on_seg[c->node[i].p] = c->node[i].seg;
    return lh__t3_each_subsegment(c, put_subsegment, r);
}

lh_status lh__t3_sub_reserve(t3_refine *r, size_t m)
{
    return 2 * (r->sub_count + m) <= r->sub_cap ? LH_OK : subsegments(r, r->sub_count + m);
}

void lh__t3_sub_put(t3_refine *r, lh_index p, lh_index q, lh_index s)
{
    if (p > q) {
        lh_index x = p;
        p = q, q = x;
    }
    (void)put_subsegment(r->c, p, q, s, (size_t)-1, r);
}

/* Half the shortest mesh edge between two input points: the input's closest pair,
 * an edge of the Delaunay tetrahedralization (up to flips, which only lengthen it). */
static void spacing(t3_refine *r)
{
    const t3_ctx *c = r->c;
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    double least = INFINITY;
    for (size_t t = 0; t < c->tet_count; t++)
        for (int k = 0; k < 6; k++) {
            const lh_index a = c->tv[4 * t + (size_t)e[k][0]], b = c->tv[4 * t + (size_t)e[k][1]];
            if ((size_t)a < c->n_input && (size_t)b < c->n_input)
                least = fmin(least, lh__t3_dist(lh__t3_pt(c, a), lh__t3_pt(c, b)));
        }
    r->spacing = least / 2;
}

/* Per facet its patch (recover.h: each facet is one patch). */
static lh_status facet_patches(t3_refine *r)
{
    t3_ctx *c = r->c;
    const size_t nf = c->g->facet_count;
    r->facet_patch = lh__alloc(&c->al, (nf + 1) * sizeof(lh_index));
    if (!r->facet_patch) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t f = 0; f < nf; f++) r->facet_patch[f] = -1;
    for (size_t k = 0; k < c->patch_count; k++)
        if (r->facet_patch[c->patch_facet[k]] < 0) r->facet_patch[c->patch_facet[k]] = (lh_index)k;
    return LH_OK;
}

/* One round: the domain, its bad tets, and their points queued; *more = 0 when none
 * is bad or none could be placed. */
static lh_status round_once(t3_refine *r, int *more)
{
    t3_ctx *c = r->c;
    *more = 0;
    lh_status st = lh__t3_walls(c, &r->d);
    if (st == LH_OK) st = lh__t3_carve(c, &r->d);
    r->d_wall_cap = 4 * c->tet_count, r->d_label_cap = c->tet_count;
    if (st == LH_OK) st = subsegments(r, 0);
    if (st == LH_OK) st = scan(r);
    if (st != LH_OK || r->bad_count == 0) return st;
    lh_index *idx = lh__alloc(&c->al, 2 * r->bad_count * sizeof(lh_index));
    lh__free(&c->al, r->claim);
    lh__free(&c->al, r->claim_by);
    r->claim = lh__alloc(&c->al, (c->tet_count + 1) * sizeof(lh_index));
    r->claim_by = lh__alloc(&c->al, (c->tet_count + 1) * sizeof(lh_index));
    r->taken_count = 0;
    if (!idx || !r->claim || !r->claim_by) {
        lh__free(&c->al, idx);
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    memset(r->claim, 0, (c->tet_count + 1) * sizeof(lh_index));
    r->round = 1;
    for (size_t i = 0; i < r->bad_count; i++) idx[i] = (lh_index)i;
    lh__sort_idx(idx, idx + r->bad_count, r->bad_count, cmp_bad, r);
    for (size_t i = 0; i < r->bad_count && st == LH_OK; i++) {
        t3_bad *b = r->bad + idx[i];
        if (b->why != LH_LEFT_STOPPED) continue; /* given up before */
        st = lh__t3_refine_split(r, b);
        b->why = r->why;
        if (st == LH_OK && (b->why == LH_LEFT_SPACING || b->why == LH_LEFT_FACET ||
                            b->why == LH_LEFT_BOUNDARY || b->why == LH_LEFT_REGION))
            st = give_up(r, (size_t)b->t, b->why);
    }
    lh__free(&c->al, idx);
    *more = c->new_count > 0;
    return st;
}

/* The domain's tets over their bounds counted (r->over_*), in the mesh as it is. */
static lh_status round_count(t3_refine *r)
{
    lh_status st = lh__t3_walls(r->c, &r->d);
    if (st == LH_OK) st = lh__t3_carve(r->c, &r->d);
    if (st == LH_OK) st = scan(r);
    lh__t3_domain_free(r->c, &r->d);
    return st;
}

/* The mesh, points and chains before a round's insertion, to go back to when
 * recovery fails after it (refinement then goes on more cautiously, or stops there,
 * with what is left counted). */
typedef struct t3_snapshot {
    size_t n, steiner, node_count, pnode_count, tet_count;
    t3_node *node, *pnode;
    lh_index *tv, *tn;
} t3_snapshot;

static void snapshot_free(t3_ctx *c, t3_snapshot *s)
{
    void *arrays[] = {s->node, s->pnode, s->tv, s->tn};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) lh__free(&c->al, arrays[i]);
    memset(s, 0, sizeof *s);
}

/* The mesh as it stands (compacted: no dead slots) into s. */
static lh_status snapshot_take(t3_ctx *c, t3_snapshot *s)
{
    snapshot_free(c, s);
    s->node = lh__alloc(&c->al, (c->node_count + 1) * sizeof(t3_node));
    s->pnode = lh__alloc(&c->al, (c->pnode_count + 1) * sizeof(t3_node));
    s->tv = lh__alloc(&c->al, (4 * c->tet_count + 1) * sizeof(lh_index));
    s->tn = lh__alloc(&c->al, (4 * c->tet_count + 1) * sizeof(lh_index));
    if (!s->node || !s->pnode || !s->tv || !s->tn)
        return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    if (c->node_count) memcpy(s->node, c->node, c->node_count * sizeof(t3_node));
    if (c->pnode_count) memcpy(s->pnode, c->pnode, c->pnode_count * sizeof(t3_node));
    memcpy(s->tv, c->tv, 4 * c->tet_count * sizeof(lh_index));
    memcpy(s->tn, c->tn, 4 * c->tet_count * sizeof(lh_index));
    s->n = c->n, s->steiner = c->steiner, s->tet_count = c->tet_count;
    s->node_count = c->node_count, s->pnode_count = c->pnode_count;
    return LH_OK;
}

/* Back to snapshot s: its mesh, points and chains; the Delaunay tetrahedralization of
 * its points again, and the caches dropped (the sides cache is keyed by point
 * numbers, which new points will reuse). */
static lh_status snapshot_restore(t3_ctx *c, const t3_snapshot *s)
{
    lh__error_clear(c->err);
    c->n = s->n, c->steiner = s->steiner, c->new_count = 0;
    if (s->node_count) memcpy(c->node, s->node, s->node_count * sizeof(t3_node));
    if (s->pnode_count) memcpy(c->pnode, s->pnode, s->pnode_count * sizeof(t3_node));
    c->node_count = s->node_count, c->pnode_count = s->pnode_count;
    for (size_t i = 0; c->sides && i < c->sides_cap; i++) c->sides[3 * i] = -1;
    lh_status st = lh__t3_mesh_room(c, s->tet_count);
    if (st != LH_OK) return st;
    memcpy(c->tv, s->tv, 4 * s->tet_count * sizeof(lh_index));
    memcpy(c->tn, s->tn, 4 * s->tet_count * sizeof(lh_index));
    c->tet_count = s->tet_count;
    lh__t3_mesh_compact(c); /* no slot to drop: the points' tets noted again */
    lh_options dopt;
    lh_options_default(&dopt);
    dopt.alloc = c->opt->alloc;
    dopt.threads = c->opt->threads;
    lh_tri_free(c->dt);
    c->dt = NULL;
    st = lh_delaunay(3, c->n, c->xyz, &dopt, &c->dt);
    if (st != LH_OK) return lh__t3_say(c, st, 0, "%s", lh_status_message(st));
    c->dup = lh_tri_duplicate_of(c->dt);
    st = lh__t3_chains_sort(c);
    if (st == LH_OK) st = lh__t3_stars(c);
    lh__t3_forget(c);
    return st;
}

static void refine_free(t3_refine *r)
{
    t3_ctx *c = r->c;
    lh__t3_domain_free(c, &r->d);
    void *arrays[] = {r->claim, r->claim_by, r->taken,     r->sub,     r->facet_patch, r->reg,
                      r->bad,   r->kept_xyz, r->kept_node, r->refused, r->gave_up,     r->on_seg};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) lh__free(&c->al, arrays[i]);
}

/* Refinement stops after this many rounds in a row that could split fewer than 1%
 * of the bad tets: the rounds near small input angles and the spacing, a few points
 * each, while each costs a recovery of the whole boundary. */
#define T3_REFINE_STALL 5

/* Rollbacks before refinement stops: each costs a Delaunay tetrahedralization and a
 * recovery from scratch. */
#define T3_REFINE_ROLLBACKS 4

/* The round's queue, kept to insert again in part. */
static lh_status queue_keep(t3_refine *r)
{
    t3_ctx *c = r->c;
    lh__free(&c->al, r->kept_xyz);
    lh__free(&c->al, r->kept_node);
    r->kept_xyz = lh__alloc(&c->al, (3 * c->new_count + 1) * sizeof(double));
    r->kept_node = lh__alloc(&c->al, (c->new_count + 1) * sizeof(t3_node));
    if (!r->kept_xyz || !r->kept_node) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memcpy(r->kept_xyz, c->new_xyz, 3 * c->new_count * sizeof(double));
    memcpy(r->kept_node, c->new_node, c->new_count * sizeof(t3_node));
    r->kept_count = c->new_count;
    return LH_OK;
}

/* Inserts the first m points of the kept queue and recovers the boundary; when that
 * fails (recovery does not settle around them), back to snapshot s, and *ok = 0. */
static lh_status insert(t3_refine *r, t3_snapshot *s, size_t m, int *ok)
{
    t3_ctx *c = r->c;
    *ok = 0;
    memcpy(c->new_xyz, r->kept_xyz, 3 * m * sizeof(double));
    memcpy(c->new_node, r->kept_node, m * sizeof(t3_node));
    c->new_count = m;
    lh_status st = lh__t3_commit(c);
    if (st == LH_OK) st = lh__t3_recover(c);
    if (st != LH_ERR_STEINER_LIMIT) return *ok = st == LH_OK, st;
    r->rollbacks++;
    return snapshot_restore(c, s);
}

/* The round's points inserted into the mesh as it stands (refine_insert.c); when the
 * check after it finds a constraint missing and recovery cannot settle, back to the
 * snapshot, then all of them by insertion into the Delaunay tetrahedralization and
 * recovery, else (recovery failing around one) the first half, quarter, ... in the
 * round's order, worst first; a single point that fails is refused from then on.
 * *stop when rollbacks ran out. */
static lh_status insert_round(t3_refine *r, t3_snapshot *s, int *stop)
{
    t3_ctx *c = r->c;
    lh_status st = snapshot_take(c, s);
    if (st == LH_OK) st = queue_keep(r);
    if (st == LH_OK) st = lh__t3_refine_insert(r);
    if (st != LH_ERR_STEINER_LIMIT) return st;
    r->rollbacks++, r->flipped = 0; /* the mesh comes from the Delaunay tetrahedralization */
    st = snapshot_restore(c, s);
    int ok = 0;
    for (size_t m = r->kept_count; st == LH_OK && !ok && m > 0; m /= 2) {
        if (r->rollbacks == T3_REFINE_ROLLBACKS) return *stop = 1, LH_OK;
        st = insert(r, s, m, &ok);
        if (st == LH_OK && !ok && m == 1) st = lh__t3_refuse(r, r->kept_xyz);
    }
    return st;
}

/* Below this smallest dihedral angle (degrees) a tet of the refined mesh is a
 * sliver that flips try to take out, when no dihedral bound is asked for. */
#define T3_SLIVER_DEGREES 10

/* The refined mesh's slivers (and tets over the radius-edge bound) improved by flips
 * (improve.c): Delaunay refinement bounds the radius-edge ratio, which slivers meet
 * (Cheng, Dey, Edelsbrunner, Teng, "Sliver exudation", JACM 47(5) 2000, sec. 1), so
 * they are taken out after it, as TetGen's mesh optimization does (Si 2015, sec. 6). */
static lh_status improve_final(t3_refine *r)
{
    t3_ctx *c = r->c;
    const double d = c->opt->min_dihedral > 0 ? c->opt->min_dihedral : T3_SLIVER_DEGREES;
    size_t flips = 0;
    lh_status st = lh__t3_walls(c, &r->d);
    if (st == LH_OK) st = lh__t3_carve(c, &r->d);
    if (st == LH_OK) st = lh__t3_locks(c);
    if (st == LH_OK)
        st = lh__t3_improve(c, &r->d, r->ratio, d * (3.14159265358979323846 / 180), &flips);
    lh__t3_domain_free(c, &r->d);
    return st;
}

lh_status lh__t3_refine(t3_ctx *c)
{
    const lh_tetmesh_options *o = c->opt;
    if (!(o->max_radius_edge > 0) && !(o->max_volume > 0) && !o->region_volumes && !o->sizing)
        return LH_OK;
    t3_refine r;
    memset(&r, 0, sizeof r);
    r.c = c;
    r.ratio = o->max_radius_edge > 0 ? o->max_radius_edge : 0;
    const size_t before = c->steiner;
    t3_snapshot snap;
    memset(&snap, 0, sizeof snap);
    spacing(&r);
    lh_status st = facet_patches(&r);
    for (size_t round = 0, stalled = 0; st == LH_OK; round++) {
        int more, stop = 0;
        st = round_once(&r, &more);
        stalled = 100 * c->new_count < r.bad_count ? stalled + 1 : 0;
        if (st == LH_OK && more &&
            (stalled == T3_REFINE_STALL || round == T3_REFINE_ROUNDS ||
             c->steiner + c->new_count > o->max_steiner))
            more = 0, c->new_count = 0;
        if (st != LH_OK || !more) {
            lh__t3_domain_free(c, &r.d);
            break;
        }
        c->rounds++;
        st = insert_round(&r, &snap, &stop);
        lh__t3_domain_free(c, &r.d);
        if (st != LH_OK || stop) {
            if (st == LH_OK) st = round_count(&r); /* what is left over, as it stands */
            break;
        }
    }
    if (st == LH_OK) st = lh__t3_left_record(c, r.bad, r.bad_count);
    if (st == LH_OK) st = improve_final(&r);
    snapshot_free(c, &snap);
    c->refine_points = c->steiner - before;
    c->over_volume = r.over_volume, c->over_size = r.over_size;
    refine_free(&r);
    return st;
}
