/*
 * improve.c — flips that raise the worst tetrahedron shape of the domain (Klingner and
 * Shewchuk, "Aggressive tetrahedral mesh improvement", IMR 2007, sec. 3; Shewchuk,
 * "Two discrete optimization algorithms for the topological improvement of
 * tetrahedral meshes", 2002). Each tet over the quality bounds, worst first, has an
 * edge removed or a face 2-3 flipped when every tet made has a better shape
 * (lh__t3_shape: volume over the cube of the edges' root sum of squares) than the
 * worst taken out. The facets' faces and the subsegments stay: every edge of a wall is
 * locked, no locked edge is removed, and no face whose three edges are locked is
 * flipped, so each flip replaces tets of one region by tets of the same region.
 *
 * The worst go first: a Steiner point lies on its segment or facet up to rounding
 * only, so three points of one chain or four of one facet can make a tet that is flat
 * but for rounding, which no point inserted near it takes out and a flip does. Every
 * choice is geometric (tets taken in order of shape, then corners' coordinates), so
 * the result does not depend on the input's order.
 */
#include "refine.h"

#include "lh_sort.h"

#include <math.h>
#include <string.h>

typedef struct t3_work {
    lh_index t, v[4]; /* the tet's slot and its corners in coordinate order */
    double shape;
} t3_work;

typedef struct t3_improve {
    t3_ctx *c;
    double ratio, dihedral; /* the bounds (0: none; dihedral in radians) */
    lh_index *label;        /* per tet slot: T3_OUT or not, kept through the flips */
    size_t label_cap;
    t3_work *work;
    size_t work_count, work_cap;
} t3_improve;

static int cmp_work(const void *ctx, lh_index i, lh_index j)
{
    const t3_improve *m = ctx;
    const t3_work *a = m->work + i, *b = m->work + j;
    if (a->shape != b->shape) return a->shape < b->shape ? -1 : 1;
    for (int k = 0; k < 4; k++) {
        int s = lh__t3_cmp_xyz(lh__t3_pt(m->c, a->v[k]), lh__t3_pt(m->c, b->v[k]));
        if (s) return s;
    }
    return 0;
}

/* Every edge of a wall locked. */
static lh_status lock_walls(t3_ctx *c, const t3_domain *d)
{
    for (size_t t = 0; t < c->tet_count; t++)
        for (int j = 0; j < 4; j++) {
            if (lh__t3_wall_of(d, t, j) < 0) continue;
            const lh_index *tv = c->tv + 4 * t;
            for (int k = 1; k < 4; k++) {
                lh_status st = lh__t3_lock(c, tv[(j + k) % 4], tv[(j + k % 3 + 1) % 4]);
                if (st != LH_OK) return st;
            }
        }
    return LH_OK;
}

/* The domain's tets over the bounds into m->work, worst shape first. */
static lh_status gather(t3_improve *m, lh_index **order)
{
    t3_ctx *c = m->c;
    m->work_count = 0;
    for (size_t t = 0; t < c->tet_count; t++) {
        if (c->tv[4 * t] < 0 || m->label[t] == T3_OUT) continue;
        t3_work w = {(lh_index)t, {0}, 0};
        memcpy(w.v, c->tv + 4 * t, sizeof w.v);
        lh__t3_sort_points(c, w.v, 4); /* the same figures whatever the numbering */
        const double *p[4];
        for (int k = 0; k < 4; k++) p[k] = lh__t3_pt(c, w.v[k]);
        t3_tet_measure q;
        lh__t3_tet_measure(p, &q);
        if (!(m->ratio > 0 && q.ratio > m->ratio) && !(q.min_dihedral < m->dihedral)) continue;
        w.shape = lh__t3_shape(c, w.v[0], w.v[1], w.v[2], w.v[3]);
        if (m->work_count == m->work_cap) {
            size_t cap = 2 * m->work_cap + 64;
            t3_work *x = lh__alloc(&c->al, cap * sizeof(t3_work));
            if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
            if (m->work_count) memcpy(x, m->work, m->work_count * sizeof(t3_work));
            lh__free(&c->al, m->work);
            m->work = x, m->work_cap = cap;
        }
        m->work[m->work_count++] = w;
    }
    *order = lh__alloc(&c->al, (2 * m->work_count + 1) * sizeof(lh_index)); /* and scratch */
    if (!*order) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t i = 0; i < m->work_count; i++) (*order)[i] = (lh_index)i;
    lh__sort_idx(*order, *order + m->work_count, m->work_count, cmp_work, m);
    return LH_OK;
}

/* Whether slot t still holds the tet with corners v. */
static int alive(const t3_ctx *c, const t3_work *w)
{
    const lh_index *tv = c->tv + 4 * (size_t)w->t;
    if (tv[0] < 0) return 0;
    for (int k = 0; k < 4; k++)
        if (tv[0] != w->v[k] && tv[1] != w->v[k] && tv[2] != w->v[k] && tv[3] != w->v[k]) return 0;
    return 1;
}

/* The tets the last flip made take the region of the tets it took out. */
static lh_status relabel(t3_improve *m, lh_index region)
{
    t3_ctx *c = m->c;
    lh_status st = lh__t3_room(c, &m->label, &m->label_cap, c->tet_count + 1);
    for (int i = 0; st == LH_OK && i < c->made_count; i++) m->label[c->made[i]] = region;
    return st;
}

/* One flip that takes out tet w: its edges in coordinate order, then its faces. */
static lh_status improve_tet(t3_improve *m, const t3_work *w, int *done)
{
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    t3_ctx *c = m->c;
    const lh_index region = m->label[w->t];
    lh_status st = LH_OK;
    *done = 0;
    c->flip_volume = lh__t3_volume_bound(c, region);
    for (int k = 0; k < 6 && st == LH_OK && !*done; k++) {
        lh__t3_try_begin(c, 1);
        st = lh__t3_improve_edge(c, w->t, w->v[e[k][0]], w->v[e[k][1]], done);
    }
    for (int k = 0; k < 4 && st == LH_OK && !*done; k++) {
        const lh_index *tv = c->tv + 4 * (size_t)w->t;
        int j = 0;
        while (tv[j] != w->v[k]) j++;
        st = lh__t3_improve_face(c, w->t, j, done);
    }
    return st == LH_OK && *done ? relabel(m, region) : st;
}

lh_status lh__t3_improve(t3_ctx *c, const t3_domain *d, double ratio, double dihedral,
                         size_t *flips)
{
    t3_improve m;
    memset(&m, 0, sizeof m);
    m.c = c, m.ratio = ratio, m.dihedral = dihedral;
    c->flip_bounded = 1;
    *flips = 0;
    lh_status st = lock_walls(c, d);
    if (st == LH_OK) st = lh__t3_room(c, &m.label, &m.label_cap, c->tet_count + 1);
    if (st == LH_OK) memcpy(m.label, d->label, c->tet_count * sizeof(lh_index));
    size_t made = 1;
    /* passes over the tets still over the bounds, while a pass flips something */
    for (int pass = 0; pass < c->opt->optimize_passes && made && st == LH_OK; pass++) {
        lh_index *order = NULL;
        made = 0;
        st = gather(&m, &order);
        for (size_t i = 0; st == LH_OK && i < m.work_count; i++) {
            const t3_work *w = m.work + order[i];
            int done = 0;
            if (alive(c, w)) st = improve_tet(&m, w, &done);
            made += (size_t)done;
        }
        lh__free(&c->al, order);
        *flips += made;
    }
    c->flip_bounded = 0, c->flip_volume = 0;
    lh__free(&c->al, m.label);
    lh__free(&c->al, m.work);
    if (st != LH_OK || *flips == 0) return st;
    lh__t3_mesh_compact(c);
    return lh__t3_stars(c);
}
