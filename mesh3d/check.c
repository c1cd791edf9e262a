/*
 * check.c — lh_tetmesh_check: the exact check of a tetrahedral mesh made by any
 * program; this half checks orientation and topology, check_plc.c conformity to a PLC.
 *
 * Why these local checks show that the mesh covers its domain once. Let f map the
 * abstract complex M (the tets glued along shared faces) to R^3, linearly on each tet.
 *  (1) Every tet has orient_3 > 0: f preserves orientation inside every tet.
 *  (2) Every triangle is in at most two tets, on its two sides: the chain sum of the
 *      tets has as its boundary exactly the faces in one tet (the boundary faces);
 *      shared faces cancel.
 * For a point x in no face's image, the degree of f at x is then both the number of
 * tets containing x (each counts +1 by (1)) and the winding number of the boundary
 * faces around x (the degree of a map equals the winding number of the image of its
 * boundary). When the boundary faces form an embedded surface (they are subfaces, so
 * they lie on the PLC's facets, which meet only as the PLC says), that winding number
 * is 1 inside the domain and 0 outside: every point is covered once, no overlap.
 *  (3) Around every edge the tets turn once: the dihedral sectors of the tets at an
 *      interior edge, chained across shared faces, sum to exactly 2 pi (winding 1),
 *      and the fans at a boundary edge do not overlap. This is the local form of the
 *      same statement (a mesh that wraps twice around an edge has degree 2 near it)
 *      and it holds even where no PLC says that the boundary is embedded.
 * Every decision is an exact orient_3 (lh_orient) or a comparison of indices.
 */
#include "check.h"
#include "lh_sort.h"

#include <stdlib.h>
#include <string.h>

/* A tet's face: its points sorted; side 1 when the tet lies on the positive side
 * of (v[0], v[1], v[2]) (orient_3 > 0 with the tet's fourth point). */
typedef struct frec {
    lh_index v[3], t;
    int side;
} frec;

/* A tet's edge a < b with its other two points ordered so that orient_3(a, b, c, d)
 * > 0: the tet's dihedral sector at the edge turns from half-plane (a b c) to
 * (a b d) in the positive sense about a -> b. */
typedef struct erec {
    lh_index a, b, c, d, t;
    int flag;
} erec;

static int frec_cmp(const void *x, const void *y)
{
    const frec *p = x, *q = y;
    for (int k = 0; k < 3; k++)
        if (p->v[k] != q->v[k]) return p->v[k] < q->v[k] ? -1 : 1;
    return p->t < q->t ? -1 : p->t > q->t;
}

static int erec_cmp(const void *x, const void *y)
{
    const erec *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return p->c < q->c ? -1 : p->c > q->c;
}

/* Sorts count records of size bytes whose first member is an lh_index point number
 * (0..n-1): a counting sort by it, then cmp within each point's run (a few dozen
 * records: the full sort by cmp took half the check's time). */
static lh_status bucket_sort(const lh__tchk *c, void *rec, size_t count, size_t size,
                             int (*cmp)(const void *, const void *))
{
    lh_status st = lh__sort_by_index(&c->al, rec, count, size, 0, c->n);
    unsigned char *r = rec;
    for (size_t start = 0, end; st == LH_OK && start < count; start = end) {
        lh_index a, b;
        memcpy(&a, r + start * size, sizeof a);
        for (end = start + 1; end < count; end++) {
            memcpy(&b, r + end * size, sizeof b);
            if (b != a) break;
        }
        qsort(r + start * size, end - start, size, cmp);
    }
    return st;
}

static void sort3(lh_index *v)
{
    lh_index t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
    if (v[1] > v[2]) t = v[1], v[1] = v[2], v[2] = t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
}

static int orient4(lh__tchk *c, lh_index a, lh_index b, lh_index x, lh_index y)
{
    const double *p[4] = {lh__tchk_pt(c, a), lh__tchk_pt(c, b), lh__tchk_pt(c, x),
                          lh__tchk_pt(c, y)};
    return lh_orient(c->pr, 3, p);
}

static lh_status check_tets(lh__tchk *c)
{
    for (size_t t = 0; t < c->nt; t++) {
        const lh_index *v = c->tets + 4 * t;
        for (int k = 0; k < 4; k++)
            if (v[k] < 0 || (size_t)v[k] >= c->n)
                return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                     "tet %zu (%lld %lld %lld %lld) names point %lld, not a "
                                     "point (0..%zu)", t, (long long)v[0], (long long)v[1],
                                     (long long)v[2], (long long)v[3], (long long)v[k],
                                     c->n ? c->n - 1 : 0);
        const int o = orient4(c, v[0], v[1], v[2], v[3]);
        if (o <= 0)
            return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                 "tet %zu (%lld %lld %lld %lld) has orient_3 %s", t,
                                 (long long)v[0], (long long)v[1], (long long)v[2],
                                 (long long)v[3], o < 0 ? "< 0 (inverted)" : "= 0 (flat)");
    }
    return LH_OK;
}

/* Inversions of a triple: 0 or 2 for an even order, 1 or 3 for an odd one. */
static int inversions3(const lh_index *v)
{
    return (v[0] > v[1]) + (v[0] > v[2]) + (v[1] > v[2]);
}

/* Face k of a positive tet, ordered so that vertex k lies on its positive side:
 * (v_a, v_b, v_c, v_k) is an even permutation of (v_0, v_1, v_2, v_3). */
static const int face_of[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

static lh_status fill_faces(const lh__tchk *c, frec *f)
{
    for (size_t t = 0; t < c->nt; t++) {
        const lh_index *v = c->tets + 4 * t;
        for (int k = 0; k < 4; k++) {
            frec *r = f + 4 * t + k;
            for (int i = 0; i < 3; i++) r->v[i] = v[face_of[k][i]];
            r->side = inversions3(r->v) % 2 == 0; /* sorting keeps the orientation */
            sort3(r->v);
            r->t = (lh_index)t;
        }
    }
    return bucket_sort(c, f, 4 * c->nt, sizeof *f, frec_cmp);
}

static int same_tet(const lh__tchk *c, lh_index s, lh_index t)
{
    lh_index a[4], b[4];
    memcpy(a, c->tets + 4 * (size_t)s, sizeof a);
    memcpy(b, c->tets + 4 * (size_t)t, sizeof b);
    for (int i = 0; i < 4; i++) {
        int found = 0;
        for (int k = 0; k < 4; k++) found |= a[i] == b[k];
        if (!found) return 0;
    }
    return 1;
}

/* A face group f[0..k): k tets with one face; 1 or 2 (on opposite sides) is right. */
static lh_status face_group(lh__tchk *c, const frec *f, size_t k)
{
    for (size_t i = 0; i < k; i++)
        for (size_t j = i + 1; j < k; j++)
            if (same_tet(c, f[i].t, f[j].t)) {
                const lh_index *v = c->tets + 4 * (size_t)f[i].t;
                return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                     "tets %lld and %lld are the same tet (%lld %lld %lld %lld)",
                                     (long long)f[i].t, (long long)f[j].t, (long long)v[0],
                                     (long long)v[1], (long long)v[2], (long long)v[3]);
            }
    if (k > 2)
        return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                             "face (%lld %lld %lld) is in %zu tets: %lld, %lld, %lld%s",
                             (long long)f->v[0], (long long)f->v[1], (long long)f->v[2], k,
                             (long long)f[0].t, (long long)f[1].t, (long long)f[2].t,
                             k > 3 ? ", ..." : "");
    if (k == 2 && f[0].side == f[1].side)
        return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                             "face (%lld %lld %lld): tets %lld and %lld lie on the same side",
                             (long long)f->v[0], (long long)f->v[1], (long long)f->v[2],
                             (long long)f[0].t, (long long)f[1].t);
    return LH_OK;
}

static int key3_cmp(const void *x, const void *y)
{
    const lh_index *p = x, *q = y;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* The first face record with the points key (sorted), or NULL. */
static const frec *find_face(const frec *f, size_t n, const lh_index *key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (key3_cmp(f[mid].v, key) < 0) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && key3_cmp(f[lo].v, key) == 0 ? f + lo : NULL;
}

/* Subfaces: in range, each a face of a tet; sub receives their sorted keys. */
static lh_status check_subfaces(lh__tchk *c, const frec *f, lh_index *sub)
{
    for (size_t s = 0; s < c->nf; s++) {
        const lh_index *v = c->faces + 3 * s;
        for (int k = 0; k < 3; k++)
            if (v[k] < 0 || (size_t)v[k] >= c->n)
                return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                     "subface %zu (%lld %lld %lld) names point %lld, not a "
                                     "point (0..%zu)", s, (long long)v[0], (long long)v[1],
                                     (long long)v[2], (long long)v[k], c->n ? c->n - 1 : 0);
        memcpy(sub + 3 * s, v, 3 * sizeof *v);
        sort3(sub + 3 * s);
        if (!find_face(f, 4 * c->nt, sub + 3 * s))
            return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                 "subface %zu (%lld %lld %lld) is not a face of a tet", s,
                                 (long long)v[0], (long long)v[1], (long long)v[2]);
    }
    qsort(sub, c->nf, 3 * sizeof *sub, key3_cmp);
    return LH_OK;
}

static lh_status check_faces(lh__tchk *c, frec *f, lh_index *sub)
{
    if (fill_faces(c, f)) return LH_ERR_NOMEM;
    const size_t nr = 4 * c->nt;
    for (size_t i = 0; i < nr;) {
        size_t j = i + 1;
        while (j < nr && key3_cmp(f[j].v, f[i].v) == 0) j++;
        const lh_status st = face_group(c, f + i, j - i);
        if (st) return st;
        i = j;
    }
    lh_status st = check_subfaces(c, f, sub);
    for (size_t i = 0; st == LH_OK && !c->boundary_free && i < nr; i++) {
        const int alone = (i == 0 || key3_cmp(f[i - 1].v, f[i].v) != 0) &&
                          (i + 1 == nr || key3_cmp(f[i + 1].v, f[i].v) != 0);
        if (alone && !bsearch(f[i].v, sub, c->nf, 3 * sizeof *sub, key3_cmp))
            st = lh__error_say(c->err, LH_ERR_INVALID_MESH,
                               "boundary face (%lld %lld %lld) of tet %lld is not a subface",
                               (long long)f[i].v[0], (long long)f[i].v[1],
                               (long long)f[i].v[2], (long long)f[i].t);
    }
    return st;
}

/* Edge (i j) of a tet and its other two corners (x y), with the parity of the
 * permutation (i j x y) of (0 1 2 3): odd ones swap x and y to keep (i j x y) positive. */
static const int edge_of[6][5] = {{0, 1, 2, 3, 0}, {0, 2, 1, 3, 1}, {0, 3, 1, 2, 0},
                                  {1, 2, 0, 3, 0}, {1, 3, 0, 2, 1}, {2, 3, 0, 1, 0}};

static lh_status fill_edges(const lh__tchk *c, erec *e)
{
    for (size_t t = 0; t < c->nt; t++) {
        const lh_index *v = c->tets + 4 * t;
        for (int k = 0; k < 6; k++) {
            const int *q = edge_of[k];
            lh_index a = v[q[0]], b = v[q[1]], x = v[q[2]], y = v[q[3]];
            const int odd = q[4] ^ (a > b); /* a > b: the swap below is one more */
            if (a > b) { const lh_index s = a; a = b; b = s; }
            e[6 * t + k] = (erec){a, b, odd ? y : x, odd ? x : y, (lh_index)t, 0};
        }
    }
    return bucket_sort(c, e, 6 * c->nt, sizeof *e, erec_cmp);
}

/* The record of the group e[0..k) (sorted by c) whose c is x, or NULL. */
static erec *by_c(erec *e, size_t k, lh_index x)
{
    size_t lo = 0, hi = k;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (e[mid].c < x) lo = mid + 1;
        else hi = mid;
    }
    return lo < k && e[lo].c == x ? e + lo : NULL;
}

/* How many sectors [c, d) of the group contain the half-plane (a b r): with
 * s(x, y) = orient_3(a, b, x, y), a sector of angle below pi contains it exactly
 * when s(c, r) >= 0 and s(r, d) > 0 (for s(c, r) = 0, r on c's half-plane gives
 * s(r, d) = s(c, d) > 0 and r on the opposite one gives s(r, d) < 0). Sectors that
 * chain around the edge w times cover every half-plane w times. */
static size_t cover_count(lh__tchk *c, const erec *e, size_t k, lh_index r)
{
    size_t w = 0;
    for (size_t i = 0; i < k; i++)
        w += (e[i].c == r || orient4(c, e->a, e->b, e[i].c, r) >= 0) &&
             orient4(c, e->a, e->b, r, e[i].d) > 0;
    return w;
}

/* Marks the component (fan or cycle) that starts at r: flag 2. */
static void walk(erec *e, size_t k, erec *r)
{
    while (r && r->flag != 2) {
        r->flag = 2;
        r = by_c(e, k, r->d);
    }
}

/* The tets around edge e->a e->b: each fan (starting at a half-plane no sector ends
 * at) and each cycle must cover its first half-plane once over all the sectors. */
static lh_status edge_group(lh__tchk *c, erec *e, size_t k)
{
    for (size_t i = 0; i < k; i++) {
        erec *nx = by_c(e, k, e[i].d);
        if (nx) nx->flag = 1; /* has a predecessor */
    }
    for (int pass = 0; pass < 2; pass++)
        for (size_t i = 0; i < k; i++) {
            if (e[i].flag == 2 || (pass == 0 && e[i].flag == 1)) continue;
            walk(e, k, e + i);
            const size_t w = cover_count(c, e, k, e[i].c);
            if (w != 1)
                return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                     "edge (%lld %lld): the tets around it turn %zu times, "
                                     "not once (tets %lld, %lld%s)",
                                     (long long)e->a, (long long)e->b, w, (long long)e[0].t,
                                     (long long)e[k > 1].t, k > 2 ? ", ..." : "");
        }
    return LH_OK;
}

static int edge_key_cmp(const erec *x, lh_index a, lh_index b)
{
    if (x->a != a) return x->a < a ? -1 : 1;
    return x->b < b ? -1 : x->b > b;
}

static lh_status check_subsegments(lh__tchk *c, const erec *e)
{
    const size_t nr = 6 * c->nt;
    for (size_t s = 0; s < c->ne; s++) {
        const lh_index *v = c->edges + 2 * s;
        for (int k = 0; k < 2; k++)
            if (v[k] < 0 || (size_t)v[k] >= c->n)
                return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                     "subsegment %zu (%lld %lld) names point %lld, not a point "
                                     "(0..%zu)", s, (long long)v[0], (long long)v[1],
                                     (long long)v[k], c->n ? c->n - 1 : 0);
        const lh_index a = v[0] < v[1] ? v[0] : v[1], b = v[0] < v[1] ? v[1] : v[0];
        size_t lo = 0, hi = nr;
        while (lo < hi) {
            const size_t mid = lo + (hi - lo) / 2;
            if (edge_key_cmp(e + mid, a, b) < 0) lo = mid + 1;
            else hi = mid;
        }
        if (lo == nr || edge_key_cmp(e + lo, a, b) != 0)
            return lh__error_say(c->err, LH_ERR_INVALID_MESH,
                                 "subsegment %zu (%lld %lld) is not an edge of a tet", s,
                                 (long long)v[0], (long long)v[1]);
    }
    return LH_OK;
}

static lh_status check_edges(lh__tchk *c, erec *e)
{
    if (fill_edges(c, e)) return LH_ERR_NOMEM;
    const size_t nr = 6 * c->nt;
    for (size_t i = 0; i < nr;) {
        size_t j = i + 1;
        while (j < nr && e[j].a == e[i].a && e[j].b == e[i].b) j++;
        const lh_status st = edge_group(c, e + i, j - i);
        if (st) return st;
        i = j;
    }
    return check_subsegments(c, e);
}

/* Faces, then edges (records freed in between: at most one set is live). */
static lh_status check_topology(lh__tchk *c)
{
    lh_status st = check_tets(c);
    if (st) return st;
    frec *f = lh__alloc(&c->al, (4 * c->nt + 1) * sizeof *f);
    lh_index *sub = lh__alloc(&c->al, (3 * c->nf + 1) * sizeof *sub);
    st = f && sub ? check_faces(c, f, sub) : LH_ERR_NOMEM;
    lh__free(&c->al, f);
    lh__free(&c->al, sub);
    if (st) return st;
    erec *e = lh__alloc(&c->al, (6 * c->nt + 1) * sizeof *e);
    st = e ? check_edges(c, e) : LH_ERR_NOMEM;
    lh__free(&c->al, e);
    return st;
}

static lh_status check_args(size_t n, const double *xyz, size_t tet_count, const lh_index *tets,
                            size_t face_count, const lh_index *faces, size_t edge_count,
                            const lh_index *edges, lh_error *err)
{
    if ((n && !xyz) || (tet_count && !tets) || (face_count && !faces) || (edge_count && !edges))
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "%s is NULL with a count above 0",
                             n && !xyz               ? "xyz"
                             : tet_count && !tets    ? "tets"
                             : face_count && !faces  ? "faces"
                                                     : "edges");
    const size_t most = SIZE_MAX / 512; /* above the records' bytes per tet, face, edge */
    if (n > SIZE_MAX / 3 / sizeof(double) || tet_count > most || face_count > most ||
        edge_count > most)
        return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                             "a count is larger than the address space holds");
    for (size_t i = 0; i < 3 * n; i++)
        if (xyz[i] - xyz[i] != 0)
            return lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                 "point %zu has a NaN or infinite coordinate", i / 3);
    return LH_OK;
}

lh_status lh_tetmesh_check(size_t n, const double *xyz, size_t tet_count, const lh_index *tets,
                           size_t face_count, const lh_index *faces, const lh_index *face_parents,
                           size_t edge_count, const lh_index *edges, int boundary_free,
                           const lh_plc *g, size_t *off_exact, const lh_allocator *alloc,
                           lh_error *err)
{
    lh__error_clear(err);
    if (off_exact) *off_exact = 0;
    lh__tchk c = {.err = err, .n = n, .xyz = xyz, .nt = tet_count, .nf = face_count,
                  .ne = edge_count, .tets = tets, .faces = faces, .parents = face_parents,
                  .edges = edges, .boundary_free = boundary_free, .g = g};
    if (!lh__allocator_init(&c.al, alloc))
        return lh__error_done(err, lh__error_say(err, LH_ERR_INVALID_ARGUMENT,
                                                 "the allocator lacks alloc or free"));
    lh_status st = check_args(n, xyz, tet_count, tets, face_count, faces, edge_count, edges, err);
    if (st == LH_OK) st = lh_pred_create(&c.al, &c.pr);
    if (st == LH_OK) st = check_topology(&c);
    if (st == LH_OK && g) {
        c.off = lh__alloc(&c.al, n + 1);
        if (!c.off) st = LH_ERR_NOMEM;
        else memset(c.off, 0, n + 1);
        if (st == LH_OK) st = lh__tchk_plc(&c);
    }
    if (st == LH_OK && off_exact) *off_exact = c.off_count;
    lh__free(&c.al, c.off);
    lh_pred_free(c.pr);
    return lh__error_done(err, st);
}
