/*
 * refine_insert.c — a round's refinement points inserted into the mesh as it stands,
 * boundary and all: Bowyer-Watson in the constrained mesh (Shewchuk, "Tetrahedral
 * mesh generation by Delaunay refinement", SoCG 1998, sec. 4; Si, TetGen, ACM TOMS
 * 41(2) 2015, sec. 5.2). A point's cavity is the tets whose circumspheres hold it,
 * reached from where it lies (the tet holding it; for a point on a subsegment, every
 * tet around that subsegment) across faces that are no wall, and across the walls of
 * the facets it lies on when the tet beyond holds it too (for a point on a facet's
 * plane that is the subface's circumcircle holding it: the facet's own cavity). The
 * cavity is shrunk until each face of its boundary sees the point (exact orient_3,
 * and no near-flat tet), then replaced by the point's cone over that boundary; the
 * walls inside it are replaced by the point's cone over their boundary edges. A point
 * whose cavity cannot be made so is refused (never queued again). The boundary so
 * stays in the mesh, which the check after the round confirms (recover.c).
 */
#include "refine.h"

#include <stdlib.h>
#include <string.h>

/* Facets whose walls one cavity may take out: a subsegment's. */
#define T3_ALLOW 8

/* The insertion of one point; its tets in r->reg. */
typedef struct t3_cavity {
    t3_refine *r;
    t3_ctx *c;
    lh_index v;      /* the point (its coordinates at c->xyz + 3 v)                 */
    const double *x; /* its coordinates                                             */
    lh_index p, q;   /* the subsegment it splits, else -1                           */
    lh_index patch;  /* the patch it lies in, else -1                               */
    lh_index gen;    /* the tmark of the cavity's tets                              */
    size_t req;      /* r->reg[0..req): the tets it must take out                   */
    lh_index allow[T3_ALLOW];
    int nallow;
    lh_index *face; /* its boundary: tet, corner opposite (2 each) */
    size_t face_count, face_cap;
    lh_index *wedge; /* the edges of the walls inside it: p < q, facet, count (4 each) */
    size_t wedge_count, wedge_cap;
    lh_index *vert; /* scratch: the boundary's points */
    size_t vert_cap;
    lh_index *hash; /* edge to new tet: p, q, tet, slot (4 each; p -1 empty) */
    size_t hash_cap;
} t3_cavity;

static int in_cavity(const t3_cavity *k, lh_index t)
{
    return t >= 0 && k->c->tmark[t] == k->gen;
}

static int required(const t3_cavity *k, lh_index t)
{
    for (size_t i = 0; i < k->req; i++)
        if (k->r->reg[i] == t) return 1;
    return 0;
}

static int allowed(const t3_cavity *k, lh_index facet)
{
    for (int i = 0; i < k->nallow; i++)
        if (k->allow[i] == facet) return 1;
    return 0;
}

static lh_status add(t3_cavity *k, lh_index t)
{
    t3_refine *r = k->r;
    lh_status st = lh__t3_room(k->c, &r->reg, &r->reg_cap, r->reg_count + 1);
    if (st != LH_OK) return st;
    k->c->tmark[t] = k->gen;
    r->reg[r->reg_count++] = t;
    return LH_OK;
}

/* Bowyer-Watson from the tets in r->reg: *ok = 0 when it grows past T3_REGION_MAX. */
static lh_status grow(t3_cavity *k, int *ok)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    for (size_t i = 0; i < r->reg_count; i++) {
        const size_t t = (size_t)r->reg[i];
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * t + (size_t)j], w = lh__t3_wall_of(&r->d, t, j);
            if (u < 0 || in_cavity(k, u)) continue;
            if (w >= 0 ? !allowed(k, w) : r->d.label[u] != r->d.label[t]) continue;
            if (!lh__t3_in_sphere(c, (size_t)u, k->x)) continue;
            lh_status st = add(k, u);
            if (st != LH_OK) return st;
        }
        if (r->reg_count > T3_REGION_MAX) return *ok = 0, LH_OK;
    }
    return *ok = 1, LH_OK;
}

/* Whether the point splits face j of tet t, a face of the hull, rather than making a
 * tet over it: a face holding the subsegment it splits, or a wall of a facet it lies
 * on that lies in its plane (up to its rounding: the tet it would make is near flat),
 * a subface of the facet's own cavity. The face's parts then stay on the hull. */
static int splits_hull(const t3_cavity *k, size_t t, int j)
{
    t3_ctx *c = k->c;
    const lh_index *tv = c->tv + 4 * t;
    if (c->tn[4 * t + (size_t)j] >= 0) return 0;
    int in = 0;
    for (int a = 0; a < 4; a++) in += a != j && k->p >= 0 && (tv[a] == k->p || tv[a] == k->q);
    if (in == 2) return 1;
    const lh_index w = lh__t3_wall_of(&k->r->d, t, j);
    if (w < 0 || !allowed(k, w)) return 0;
    lh_index v[4];
    memcpy(v, tv, sizeof v);
    v[j] = k->v;
    return lh__t3_shape_sorted(c, v[0], v[1], v[2], v[3]) < T3_SLIVER;
}

/* Whether the point's tet over face j of tet t is positive and not near flat. */
static int sees(const t3_cavity *k, size_t t, int j)
{
    t3_ctx *c = k->c;
    if (lh__t3_mesh_side(c, t, j, k->x) <= 0) return 0;
    lh_index w[4];
    memcpy(w, c->tv + 4 * t, sizeof w);
    w[j] = k->v;
    return lh__t3_shape_sorted(c, w[0], w[1], w[2], w[3]) >= T3_SLIVER;
}

/* Of each two tets of the cavity across a wall it may not take out, the one on the
 * wall's far side from the point goes (both when it lies on the wall's plane), each
 * decided on the cavity as grown, so that the order does not matter; *ok = 0 when
 * both are required. */
static lh_status walls_apart(t3_cavity *k, int *ok)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    size_t n = 0;
    *ok = 1;
    for (size_t i = 0; i < r->reg_count; i++) {
        const lh_index t = r->reg[i];
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * (size_t)t + (size_t)j],
                           w = lh__t3_wall_of(&r->d, (size_t)t, j);
            if (u < t || !in_cavity(k, u) || w < 0 || allowed(k, w)) continue;
            const int side = lh__t3_mesh_side(c, (size_t)t, j, k->x);
            const int rt = required(k, t), ru = required(k, u);
            if (rt && ru) return *ok = 0, LH_OK;
            lh_status st = lh__t3_room(c, &k->face, &k->face_cap, n + 2);
            if (st != LH_OK) return st;
            if (!rt && (ru || side <= 0)) k->face[n++] = t;
            if (!ru && (rt || side >= 0)) k->face[n++] = u;
        }
    }
    for (size_t i = 0; i < n; i++) c->tmark[k->face[i]] = 0;
    return LH_OK;
}

/* One pass of shrinking: takes out each tet with a boundary face the point does not
 * see; *changed says whether; *ok = 0 when a required tet would go. Removals only add
 * boundary faces, so the cavity this ends with is the largest that meets it,
 * whatever the order. */
static void shrink_once(t3_cavity *k, int *changed, int *ok)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    *changed = 0;
    for (size_t i = 0; i < r->reg_count; i++) {
        const lh_index t = r->reg[i];
        if (!in_cavity(k, t)) continue;
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * (size_t)t + (size_t)j];
            if (in_cavity(k, u) || splits_hull(k, (size_t)t, j) || sees(k, (size_t)t, j)) continue;
            if (required(k, t)) {
                *ok = 0;
                return;
            }
            c->tmark[t] = 0;
            *changed = 1;
            break;
        }
    }
}

/* Keeps of the cavity only the tets connected to the required ones (across faces
 * that are no wall or a wall it may take out): a part cut off by a wall would make
 * tets across it. r->reg then lists the kept ones, the required first; *changed
 * whether any went. */
static lh_status connected(t3_cavity *k, int *changed)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    lh_status st = lh__t3_room(c, &k->vert, &k->vert_cap, r->reg_count + 1);
    if (st != LH_OK) return st;
    const lh_index reach = lh__t3_mesh_mark(c), gen = k->gen;
    lh_index *q = k->vert;
    size_t n = 0;
    for (size_t i = 0; i < k->req; i++) c->tmark[q[n++] = r->reg[i]] = reach;
    for (size_t i = 0; i < n; i++) {
        const size_t t = (size_t)q[i];
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * t + (size_t)j], f = lh__t3_wall_of(&r->d, t, j);
            if (u < 0 || c->tmark[u] != gen || (f >= 0 && !allowed(k, f))) continue;
            c->tmark[q[n++] = u] = reach;
        }
    }
    size_t before = 0;
    for (size_t i = 0; i < r->reg_count; i++) {
        const lh_index t = r->reg[i];
        before += c->tmark[t] == gen || c->tmark[t] == reach;
        if (c->tmark[t] == gen) c->tmark[t] = 0;
    }
    for (size_t i = 0; i < n; i++) c->tmark[r->reg[i] = q[i]] = gen;
    r->reg_count = n;
    *changed = n < before;
    return LH_OK;
}

/* The cavity shrunk until it is star-shaped from the point (every boundary face
 * seen), with no wall inside it but the allowed facets', in one piece; r->reg then
 * lists its tets only. *ok = 0 when a required tet had to go. */
static lh_status shrink(t3_cavity *k, int *ok)
{
    lh_status st = walls_apart(k, ok);
    int changed = 1;
    while (changed && *ok && st == LH_OK) {
        shrink_once(k, &changed, ok);
        if (!changed && *ok) st = connected(k, &changed);
    }
    return st;
}

static lh_status put_face(t3_cavity *k, lh_index t, int j)
{
    lh_status st = lh__t3_room(k->c, &k->face, &k->face_cap, 2 * k->face_count + 2);
    if (st != LH_OK) return st;
    k->face[2 * k->face_count] = t, k->face[2 * k->face_count + 1] = j;
    k->face_count++;
    return LH_OK;
}

/* Counts edge a b of a wall of facet f inside the cavity. */
static lh_status put_wall_edge(t3_cavity *k, lh_index a, lh_index b, lh_index f)
{
    const lh_index p = a < b ? a : b, q = a < b ? b : a;
    for (size_t i = 0; i < k->wedge_count; i++) {
        lh_index *e = k->wedge + 4 * i;
        if (e[0] == p && e[1] == q && e[2] == f) return e[3]++, LH_OK;
    }
    lh_status st = lh__t3_room(k->c, &k->wedge, &k->wedge_cap, 4 * k->wedge_count + 4);
    if (st != LH_OK) return st;
    lh_index *e = k->wedge + 4 * k->wedge_count++;
    e[0] = p, e[1] = q, e[2] = f, e[3] = 1;
    return LH_OK;
}

/* The cavity's boundary faces into k->face and the edges of its inside walls and of
 * the hull walls the point splits into k->wedge. */
static lh_status boundary(t3_cavity *k)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    k->face_count = 0, k->wedge_count = 0;
    for (size_t i = 0; i < r->reg_count; i++) {
        const lh_index t = r->reg[i], *tv = c->tv + 4 * (size_t)t;
        for (int j = 0; j < 4; j++) {
            const lh_index u = c->tn[4 * (size_t)t + (size_t)j];
            lh_status st = LH_OK;
            if (!in_cavity(k, u) && !splits_hull(k, (size_t)t, j)) {
                st = put_face(k, t, j);
            } else if ((u < 0 || t < u) && lh__t3_wall_of(&r->d, (size_t)t, j) >= 0) {
                const lh_index f = lh__t3_wall_of(&r->d, (size_t)t, j);
                const lh_index a = tv[(j + 1) % 4], b = tv[(j + 2) % 4], d = tv[(j + 3) % 4];
                st = put_wall_edge(k, a, b, f);
                if (st == LH_OK) st = put_wall_edge(k, b, d, f);
                if (st == LH_OK) st = put_wall_edge(k, d, a, f);
            }
            if (st != LH_OK) return st;
        }
    }
    return LH_OK;
}

static int cmp_index(const void *a, const void *b)
{
    const lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return x < y ? -1 : x > y;
}

/* Whether edge p q is an edge of a boundary face. */
static int on_boundary(const t3_cavity *k, lh_index p, lh_index q)
{
    for (size_t i = 0; i < k->face_count; i++) {
        const lh_index *tv = k->c->tv + 4 * (size_t)k->face[2 * i];
        int in = 0;
        for (int a = 0; a < 4; a++)
            if (a != k->face[2 * i + 1]) in += tv[a] == p || tv[a] == q;
        if (in == 2) return 1;
    }
    return 0;
}

/* *ok: every point of the cavity's tets is on its boundary (none is lost); the walls
 * inside it end at its boundary (their boundary edges are on it, the subsegment split
 * aside) and hold no other subsegment inside. */
static lh_status keeps_all(t3_cavity *k, int *ok)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    size_t nv = 0;
    lh_status st = lh__t3_room(c, &k->vert, &k->vert_cap, 3 * k->face_count + 1);
    if (st != LH_OK) return st;
    for (size_t i = 0; i < k->face_count; i++)
        for (int a = 0; a < 4; a++)
            if (a != k->face[2 * i + 1]) k->vert[nv++] = c->tv[4 * (size_t)k->face[2 * i] + a];
    qsort(k->vert, nv, sizeof(lh_index), cmp_index);
    *ok = 0;
    for (size_t i = 0; i < r->reg_count; i++)
        for (int a = 0; a < 4; a++)
            if (!bsearch(c->tv + 4 * (size_t)r->reg[i] + a, k->vert, nv, sizeof(lh_index),
                         cmp_index))
                return LH_OK;
    for (size_t i = 0; i < k->wedge_count; i++) {
        const lh_index *e = k->wedge + 4 * i;
        if ((e[0] == k->p && e[1] == k->q) || (e[0] == k->q && e[1] == k->p)) continue;
        if (e[3] == 1 && !on_boundary(k, e[0], e[1])) return LH_OK;
        if (e[3] > 1 && lh__t3_sub_slot(r, e[0], e[1])[0] >= 0) return LH_OK;
    }
    return *ok = 1, LH_OK;
}

/* The facet of the wall the point makes with edge a b: the facet whose walls inside
 * the cavity end at that edge, else -1. */
static lh_index new_wall(const t3_cavity *k, lh_index a, lh_index b)
{
    const lh_index p = a < b ? a : b, q = a < b ? b : a;
    for (size_t i = 0; i < k->wedge_count; i++) {
        const lh_index *e = k->wedge + 4 * i;
        if (e[0] == p && e[1] == q && e[3] == 1) return e[2];
    }
    return -1;
}

lh_status lh__t3_domain_room(t3_refine *r, size_t need)
{
    t3_ctx *c = r->c;
    lh_status st = lh__t3_room(c, &r->d.wall, &r->d_wall_cap, 4 * need);
    if (st == LH_OK)
        st = lh__t3_grow(c, (void **)&r->d.label, &r->d_label_cap, c->tet_count, need,
                         sizeof(lh_index));
    return st;
}

/* Links slot m of new tet s (the face through the point and edge a b) with the new
 * tet across it, through k->hash. */
static void link(t3_cavity *k, lh_index s, int m, lh_index a, lh_index b)
{
    t3_ctx *c = k->c;
    const lh_index p = a < b ? a : b, q = a < b ? b : a;
    size_t h = ((size_t)p * 0x9e3779b1u ^ (size_t)q * 0x85ebca6bu) & (k->hash_cap - 1);
    for (;; h = (h + 1) & (k->hash_cap - 1)) {
        lh_index *e = k->hash + 4 * h;
        if (e[0] < 0) {
            e[0] = p, e[1] = q, e[2] = s, e[3] = m;
            return;
        }
        if (e[0] == p && e[1] == q) {
            c->tn[4 * (size_t)s + (size_t)m] = e[2];
            c->tn[4 * (size_t)e[2] + (size_t)e[3]] = s;
            return;
        }
    }
}

/* The cone of the point over the boundary replaces the cavity's tets. */
static lh_status fill(t3_cavity *k)
{
    t3_ctx *c = k->c;
    t3_refine *r = k->r;
    const size_t first = c->tet_count, nb = k->face_count;
    lh_status st = lh__t3_mesh_room(c, first + nb);
    if (st == LH_OK) st = lh__t3_domain_room(r, first + nb);
    size_t cap = 16;
    while (cap < 4 * nb) cap *= 2;
    if (st == LH_OK && cap > k->hash_cap) {
        lh__free(&c->al, k->hash);
        k->hash = lh__alloc(&c->al, 4 * cap * sizeof(lh_index));
        k->hash_cap = k->hash ? cap : 0;
        if (!k->hash) st = lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    }
    if (st != LH_OK) return st;
    for (size_t i = 0; i < 4 * k->hash_cap; i += 4) k->hash[i] = -1;
    for (size_t i = 0; i < nb; i++) {
        const lh_index t = k->face[2 * i], s = (lh_index)(first + i);
        const int j = (int)k->face[2 * i + 1];
        lh_index *nv = c->tv + 4 * (size_t)s, *nn = c->tn + 4 * (size_t)s;
        memcpy(nv, c->tv + 4 * (size_t)t, 4 * sizeof(lh_index));
        nv[j] = k->v;
        const lh_index u = c->tn[4 * (size_t)t + (size_t)j];
        nn[j] = u;
        for (int m = 0; u >= 0 && m < 4; m++)
            if (c->tn[4 * (size_t)u + (size_t)m] == t) c->tn[4 * (size_t)u + (size_t)m] = s;
        r->d.label[s] = r->d.label[t];
        r->d.wall[4 * (size_t)s + (size_t)j] = lh__t3_wall_of(&r->d, (size_t)t, j);
        c->tmark[s] = 0;
        for (int m = 0; m < 4; m++) {
            if (m == j) continue;
            lh_index e[2], w = 0;
            for (int a = 0; a < 4; a++)
                if (a != j && a != m) e[w++] = nv[a];
            r->d.wall[4 * (size_t)s + (size_t)m] = new_wall(k, e[0], e[1]);
            nn[m] = -1; /* on the hull unless linked */
            link(k, s, m, e[0], e[1]);
        }
    }
    for (size_t i = 0; i < r->reg_count; i++) c->tv[4 * (size_t)r->reg[i]] = -1; /* dead */
    c->tet_count = first + nb;
    for (size_t s = first; s < c->tet_count; s++)
        for (int a = 0; a < 4; a++) c->vtet[c->tv[4 * s + (size_t)a]] = (lh_index)s;
    return LH_OK;
}

/* The tets around edge p q as the required start, and the facets of the walls
 * between them as those the cavity may take walls of; *ok = 0 when p q is no edge. */
static lh_status start_edge(t3_cavity *k, int *ok)
{
    t3_ctx *c = k->c;
    size_t cnt;
    *ok = 0;
    lh_status st = lh__t3_mesh_star(c, k->p, &cnt);
    if (st != LH_OK) return st;
    k->gen = lh__t3_mesh_mark(c);
    for (size_t i = 0; i < cnt; i++) {
        const lh_index t = c->sbuf[i], *tv = c->tv + 4 * (size_t)t;
        if (tv[0] != k->q && tv[1] != k->q && tv[2] != k->q && tv[3] != k->q) continue;
        if ((st = add(k, t)) != LH_OK) return st;
        for (int j = 0; j < 4; j++) {
            const lh_index w = lh__t3_wall_of(&k->r->d, (size_t)t, j);
            if (tv[j] == k->p || tv[j] == k->q || w < 0 || allowed(k, w)) continue;
            if (k->nallow == T3_ALLOW) return LH_OK;
            k->allow[k->nallow++] = w;
        }
    }
    k->req = k->r->reg_count;
    *ok = k->req > 0;
    return LH_OK;
}

/* Whether the point, projected along patch k's axis, lies in face j of tet t (closed;
 * exact orient_2 of the projected doubles). */
static int in_face(const t3_cavity *k, size_t t, int j)
{
    lh_index f[3];
    for (int a = 0, w = 0; a < 4; a++)
        if (a != j) f[w++] = k->c->tv[4 * t + (size_t)a];
    return lh__t3_in_triangle(k->c, f, k->x, abs(k->c->patch_axis[k->patch]) - 1);
}

/* Whether the point is a patch's that rounding put just outside the mesh, over the
 * hull wall that is face j of tet t (splits_hull, in the face's projection). */
static int over_hull(const t3_cavity *k, size_t t, int j)
{
    return k->patch >= 0 && splits_hull(k, t, j) && in_face(k, t, j);
}

/* The hull tets around the points of tet t that the point is over (over_hull), each
 * once, into k->vert: *n of them. */
static lh_status hull_near(t3_cavity *k, lh_index t, size_t *n)
{
    t3_ctx *c = k->c;
    lh_index v[4];
    memcpy(v, c->tv + 4 * (size_t)t, sizeof v);
    *n = 0;
    for (int a = 0; a < 4; a++) {
        size_t cnt;
        lh_status st = lh__t3_mesh_star(c, v[a], &cnt);
        for (size_t i = 0; st == LH_OK && i < cnt; i++) {
            const lh_index u = c->sbuf[i];
            int over = 0, seen = 0;
            for (int j = 0; j < 4; j++)
                over |= c->tn[4 * (size_t)u + (size_t)j] < 0 && over_hull(k, (size_t)u, j);
            for (size_t m = 0; m < *n; m++) seen |= k->vert[m] == u;
            if (!over || seen) continue;
            st = lh__t3_room(c, &k->vert, &k->vert_cap, *n + 1);
            if (st == LH_OK) k->vert[(*n)++] = u;
        }
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

/* A walk from tet t towards the point, across faces it lies beyond (each step from
 * another face first, so that it cannot cycle for long in a mesh flips made
 * non-Delaunay): the tet holding it (*over = 0), or the tet it leaves the mesh from,
 * for a patch's point that rounding put just outside the mesh (*over = 1); -1 when it
 * leaves the mesh for another point or runs long. */
static lh_index walk(t3_cavity *k, lh_index t, int *over)
{
    t3_ctx *c = k->c;
    for (size_t step = 0; t >= 0 && step < 4 * c->tet_count + 64; step++) {
        int out = -1, beyond = 0;
        for (int i = 0; i < 4 && out < 0; i++) {
            const int j = (int)((step + (size_t)i) % 4);
            if (lh__t3_mesh_side(c, (size_t)t, j, k->x) >= 0) continue;
            beyond = 1;
            if (c->tn[4 * (size_t)t + (size_t)j] >= 0) out = j;
        }
        *over = beyond;
        if (out < 0) return !beyond || k->patch >= 0 ? t : -1;
        t = c->tn[4 * (size_t)t + out];
    }
    return -1;
}

/* The required start: the tet holding the point, or for a patch's point just outside
 * the mesh every hull tet around where it left the mesh that it lies over (so that
 * the start is the same whichever way the walk came), found by a walk from the
 * Delaunay tetrahedralization's simplex or hull facet nearest it; *ok = 0 when there
 * is none or, for a point that is not on a facet, it is outside the domain. */
static lh_status start_point(t3_cavity *k, int *ok)
{
    t3_ctx *c = k->c;
    lh_location loc;
    *ok = 0;
    if (lh_tri_locate(c->dt, k->x, -1, &loc) != LH_OK) return LH_OK;
    lh_index v = -1;
    if (loc.simplex >= 0)
        v = lh_tri_simplices(c->dt)[4 * (size_t)loc.simplex];
    else if (loc.hull_facet >= 0)
        v = lh_tri_hull_facets(c->dt)[3 * (size_t)loc.hull_facet];
    int over = 0;
    const lh_index t = v < 0 ? -1 : walk(k, c->vtet[v], &over);
    if (t < 0 || (k->patch < 0 && k->r->d.label[t] == T3_OUT)) return LH_OK;
    size_t n = 1;
    lh_status st = over ? hull_near(k, t, &n) : LH_OK;
    if (st != LH_OK || n == 0) return st;
    k->gen = lh__t3_mesh_mark(c);
    for (size_t i = 0; i < n && st == LH_OK; i++) st = add(k, over ? k->vert[i] : t);
    k->req = n;
    *ok = st == LH_OK;
    return st;
}

/* Inserts point v (its coordinates at c->xyz + 3 v, v == c->n) of kind nd (seg >= 0
 * on subsegment p q, a patch's, or T3_INTERIOR); *ok = 0, nothing changed, when its
 * cavity cannot be made. */
static lh_status insert_point(t3_cavity *k, const t3_node *nd, lh_index p, lh_index q, int *ok)
{
    t3_ctx *c = k->c;
    k->v = (lh_index)c->n, k->x = lh__t3_pt(c, k->v), k->p = p, k->q = q;
    k->nallow = 0, k->req = 0, k->r->reg_count = 0, k->patch = -1;
    lh_status st;
    if (nd->seg >= 0) {
        st = start_edge(k, ok);
    } else {
        if (nd->seg != T3_INTERIOR) k->patch = -1 - nd->seg;
        if (k->patch >= 0) k->allow[k->nallow++] = c->patch_facet[k->patch];
        st = start_point(k, ok);
    }
    if (st == LH_OK && *ok) st = grow(k, ok);
    if (st == LH_OK && *ok) st = shrink(k, ok);
    if (st == LH_OK && *ok) st = boundary(k);
    if (st == LH_OK && *ok) st = keeps_all(k, ok);
    if (st != LH_OK || !*ok) return st;
    c->n++;
    return fill(k);
}

/* The ends of the subsegment of segment s that parameter t falls in: the chain as the
 * round began, with the points this round put on it (nodes[0..m)). */
static void subsegment_of(const t3_ctx *c, lh_index s, double t, const t3_node *nodes, size_t m,
                          lh_index *p, lh_index *q)
{
    double tp = 0, tq = 1;
    *p = c->seg[s].a, *q = c->seg[s].b;
    for (lh_index i = c->node_first[s]; i < c->node_first[s + 1]; i++) {
        const t3_node *n = c->node + i;
        if (n->t < t && n->t > tp) tp = n->t, *p = n->p;
        if (n->t > t && n->t < tq) tq = n->t, *q = n->p;
    }
    for (size_t i = 0; i < m; i++) {
        if (nodes[i].seg != s) continue;
        if (nodes[i].t < t && nodes[i].t > tp) tp = nodes[i].t, *p = nodes[i].p;
        if (nodes[i].t > t && nodes[i].t < tq) tq = nodes[i].t, *q = nodes[i].p;
    }
}

static void cavity_free(t3_cavity *k)
{
    lh__free(&k->c->al, k->face);
    lh__free(&k->c->al, k->wedge);
    lh__free(&k->c->al, k->vert);
    lh__free(&k->c->al, k->hash);
}

/* Each queued point in queue order: inserted (a point already in the mesh, or equal to
 * one inserted before it, only joins its chain), else refused; the nodes of those in
 * place into nodes[0..*m). */
static lh_status insert_all(t3_refine *r, t3_node *nodes, size_t *m, lh_index *first)
{
    t3_ctx *c = r->c;
    t3_cavity k;
    memset(&k, 0, sizeof k);
    k.r = r, k.c = c;
    lh_status st = LH_OK;
    *m = 0;
    for (size_t i = 0; i < c->new_count && st == LH_OK; i++) {
        t3_node nd = c->new_node[i];
        const double *x = c->new_xyz + 3 * i;
        if (nd.p < 0 && first[i] != (lh_index)i) nd.p = c->new_node[first[i]].p;
        if (nd.p < 0 && first[i] == (lh_index)i) {
            int ok;
            lh_index p = -1, q = -1;
            if (nd.seg >= 0) subsegment_of(c, nd.seg, nd.t, nodes, *m, &p, &q);
            if ((st = lh__t3_xyz_room(c, 1)) != LH_OK) break;
            memcpy(c->xyz + 3 * c->n, x, 3 * sizeof(double));
            st = insert_point(&k, &nd, p, q, &ok);
            if (st == LH_OK && !ok) st = lh__t3_refuse(r, x);
            if (st != LH_OK || !ok) continue;
            nd.p = (lh_index)c->n - 1;
            c->new_node[i].p = nd.p;
            if (nd.seg >= 0) lh__t3_sub_put(r, p, nd.p, nd.seg), lh__t3_sub_put(r, nd.p, q, nd.seg);
        }
        if (nd.p >= 0 && nd.seg != T3_INTERIOR) nodes[(*m)++] = nd;
    }
    cavity_free(&k);
    return st;
}

/* The round's new points n0.. into the Delaunay tetrahedralization too (the fallback
 * recovery and locating start from it); the nodes into the chains. */
static lh_status settle(t3_refine *r, size_t n0, const t3_node *nodes, size_t m)
{
    t3_ctx *c = r->c;
    lh_status st = lh_tri_insert(c->dt, c->n - n0, c->xyz + 3 * n0);
    if (st != LH_OK)
        return lh__t3_say(c, st, 0, "inserting Steiner points: %s", lh_status_message(st));
    c->dup = lh_tri_duplicate_of(c->dt);
    for (size_t v = n0; v < c->n; v++)
        if (c->dup[v] != (lh_index)v)
            return lh__t3_say(c, LH_ERR_INTERNAL, 0, "a refinement point inserted twice");
    c->steiner += c->n - n0;
    st = lh__t3_node_room(c, &c->node, c->node_count, &c->node_cap, m);
    if (st == LH_OK) st = lh__t3_node_room(c, &c->pnode, c->pnode_count, &c->pnode_cap, m);
    if (st != LH_OK) return st;
    for (size_t i = 0; i < m; i++) {
        t3_node nd = nodes[i];
        if (nd.seg >= 0) {
            c->node[c->node_count++] = nd;
        } else {
            nd.seg = -1 - nd.seg;
            c->pnode[c->pnode_count++] = nd;
        }
    }
    st = lh__t3_chains_sort(c);
    if (st != LH_OK) return st;
    lh__t3_mesh_compact(c);
    st = lh__t3_stars(c);
    if (st == LH_OK) st = lh__t3_mark_changed(c, n0, nodes, m);
    return st;
}

lh_status lh__t3_refine_insert(t3_refine *r)
{
    t3_ctx *c = r->c;
    const size_t m = c->new_count, n0 = c->n;
    lh_index *first = lh__alloc(&c->al, (3 * m + 1) * sizeof(lh_index));
    t3_node *nodes = lh__alloc(&c->al, (m + 1) * sizeof(t3_node));
    lh_status st = first && nodes ? LH_OK : lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    size_t nm = 0;
    if (st == LH_OK) lh__t3_queue_firsts(c, first, first + m);
    if (st == LH_OK) st = lh__t3_sub_reserve(r, 2 * m);
    const size_t before = r->flipped ? c->tet_count : 0; /* the first round: every face */
    if (st == LH_OK) st = insert_all(r, nodes, &nm, first);
    if (st == LH_OK) st = lh__t3_refine_flips(r, before);
    r->flipped = 1;
    c->new_count = 0;
    if (st == LH_OK) st = settle(r, n0, nodes, nm);
    lh__free(&c->al, first);
    lh__free(&c->al, nodes);
    if (st == LH_OK) st = lh__t3_recover_check(c);
    return st;
}
