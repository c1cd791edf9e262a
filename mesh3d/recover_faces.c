/*
 * recover_faces.c — is a patch (a facet) a union of mesh faces? Its points are its
 * triangles' corners, the chains of their edges that are segments and the Steiner
 * points put inside it. The candidate faces are the mesh faces on three of those
 * points lying in the patch: the face's centroid, projected along the facet's
 * dominant normal axis, in one of its triangles. A facet whose points are not
 * exactly coplanar is recovered the same way: the faces spanning its polygons are
 * the mesh's, not those of a triangulation fixed beforehand. Where rounded Steiner points make
 * tetrahedra with all four points on the patch (flat ones), only the faces below
 * them count (along the patch's normal): such a stack has one bottom, so it counts
 * once. The patch is recovered when they
 * form a surface bounded by its segments: each subsegment of a segment edge in as
 * many candidate faces as the patch has triangles on that edge (1 on the boundary, 2
 * inside), every other edge of them in two. Mesh faces never cross, so the
 * candidates then tile the patch (up to the rounding of Steiner points).
 */
#include "recover.h"

#include "facets.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A subsegment the patch needs: its points (smaller first), segment, chain index,
 * and how many of the patch's faces must hold it. */
typedef struct need {
    lh_index p, q, seg, i, mult;
} need;

typedef struct patch_scan {
    size_t nv, nf, ne, nn;
    need *needs;
    size_t needs_cap;
} patch_scan;

static int cmp_pair(const void *x, const void *y)
{
    const lh_index *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

static int cmp_triple(const void *x, const void *y)
{
    const lh_index *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

static int cmp_need(const void *x, const void *y)
{
    return cmp_pair(x, y);
}

static lh_status stamp_room(t3_ctx *c)
{
    if (c->stamp_cap >= c->n) return LH_OK;
    lh__free(&c->al, c->stamp);
    c->stamp_cap = 2 * c->n;
    c->stamp = lh__alloc(&c->al, c->stamp_cap * sizeof(lh_index));
    if (!c->stamp) return c->stamp_cap = 0, lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    memset(c->stamp, 0xff, c->stamp_cap * sizeof(lh_index));
    return LH_OK;
}

/* Adds point v to c->vbuf when not stamped yet, stamped `mark`: 2 + s for a point
 * inside segment s's chain, 1 for the others. */
static lh_status add_point(t3_ctx *c, patch_scan *ps, lh_index v, lh_index mark)
{
    if (c->stamp[v] >= 1) return LH_OK;
    lh_status st = lh__t3_room(c, &c->vbuf, &c->vcap, ps->nv + 1);
    if (st != LH_OK) return st;
    c->stamp[v] = mark;
    c->vbuf[ps->nv++] = v;
    return LH_OK;
}

static lh_status add_need(t3_ctx *c, patch_scan *ps, lh_index p, lh_index q, lh_index s, lh_index i)
{
    if (ps->nn == ps->needs_cap) {
        size_t cap = 2 * ps->needs_cap + 32;
        need *x = lh__alloc(&c->al, cap * sizeof(need));
        if (!x) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
        if (ps->nn) memcpy(x, ps->needs, ps->nn * sizeof(need));
        lh__free(&c->al, ps->needs);
        ps->needs = x, ps->needs_cap = cap;
    }
    need n = {p < q ? p : q, p < q ? q : p, s, i, 1};
    ps->needs[ps->nn++] = n;
    return LH_OK;
}

/* The patch's points (stamped) and needed subsegments (merged, sorted). */
static lh_status patch_points(t3_ctx *c, size_t k, patch_scan *ps)
{
    lh_status st = stamp_room(c);
    for (lh_index a = c->patch_first[k]; st == LH_OK && a < c->patch_first[k + 1]; a++) {
        size_t t = (size_t)c->patch_tri[a];
        for (int j = 0; j < 3 && st == LH_OK; j++) {
            st = add_point(c, ps, c->tri[3 * t + j], 1);
            lh_index s = c->tri_seg[3 * t + j];
            if (s < 0 || st != LH_OK) continue;
            size_t first = (size_t)c->node_first[s], cl = (size_t)c->node_first[s + 1] - first + 2;
            for (size_t i = 0; i + 1 < cl && st == LH_OK; i++) {
                lh_index p = i == 0 ? c->seg[s].a : c->node[first + i - 1].p;
                lh_index q = i + 2 == cl ? c->seg[s].b : c->node[first + i].p;
                st = add_point(c, ps, q, i + 2 == cl ? 1 : 2 + s);
                if (st == LH_OK) st = add_need(c, ps, p, q, s, (lh_index)i);
            }
        }
    }
    for (lh_index i = c->pnode_first[k]; st == LH_OK && i < c->pnode_first[k + 1]; i++)
        st = add_point(c, ps, c->pnode[i].p, 1);
    if (st != LH_OK) return st;
    qsort(ps->needs, ps->nn, sizeof(need), cmp_need);
    size_t w = 0;
    for (size_t i = 0; i < ps->nn; i++) {
        if (w && !cmp_need(ps->needs + w - 1, ps->needs + i))
            ps->needs[w - 1].mult++;
        else
            ps->needs[w++] = ps->needs[i];
    }
    ps->nn = w;
    return LH_OK;
}

/* Exact, in the projection dropping axis ax: g in triangle t (boundary included). */
int lh__t3_in_triangle(t3_ctx *c, const lh_index *t, const double *g, int ax)
{
    int i = (ax + 1) % 3, j = (ax + 2) % 3; /* ax: the coordinate dropped */
    double a[2], b[2], d[2], q[2] = {g[i], g[j]};
    const double *A = c->xyz + 3 * (size_t)t[0], *B = c->xyz + 3 * (size_t)t[1],
                 *D = c->xyz + 3 * (size_t)t[2];
    a[0] = A[i], a[1] = A[j], b[0] = B[i], b[1] = B[j], d[0] = D[i], d[1] = D[j];
    const double *abd[3] = {a, b, d}, *abq[3] = {a, b, q}, *bdq[3] = {b, d, q}, *daq[3] = {d, a, q};
    int o = lh_orient(c->pred, 2, abd);
    int s1 = lh_orient(c->pred, 2, abq), s2 = lh_orient(c->pred, 2, bdq),
        s3 = lh_orient(c->pred, 2, daq);
    return s1 * o >= 0 && s2 * o >= 0 && s3 * o >= 0;
}

/* Whether the k points f (stamped) lie on one segment's chain: a face along it is a
 * sliver that rounded Steiner points allow, no part of the patch; an edge along it
 * is no place for a point inside the patch. */
static int along_chain(const t3_ctx *c, const lh_index *f, int k)
{
    for (int a = 0; a < k; a++) {
        if (c->stamp[f[a]] < 2) continue;
        lh_index s = c->stamp[f[a]] - 2;
        int on = 1;
        for (int b = 0; b < k; b++)
            on &= c->stamp[f[b]] == s + 2 || f[b] == c->seg[s].a || f[b] == c->seg[s].b;
        return on;
    }
    return 0;
}

/* Whether face f lies in patch k: not along a chain, with area in the patch's
 * projection (a face of a facet that is not planar may stand edge-on there; the
 * check of the mesh refuses such a subface), and its centroid in one of the
 * patch's triangles (rounded Steiner points can make faces on the patch's points
 * that stick out of it). */
static int face_in_patch(t3_ctx *c, size_t k, const lh_index *f)
{
    if (along_chain(c, f, 3)) return 0;
    const int ax = abs(c->patch_axis[k]) - 1;
    if (!lh__orient2_along(c->pred, ax, c->xyz + 3 * (size_t)f[0], c->xyz + 3 * (size_t)f[1],
                           c->xyz + 3 * (size_t)f[2]))
        return 0;
    double g[3];
    for (int a = 0; a < 3; a++)
        g[a] = c->xyz[3 * (size_t)f[0] + a] / 3 + c->xyz[3 * (size_t)f[1] + a] / 3 +
               c->xyz[3 * (size_t)f[2] + a] / 3; /* no overflow */
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++)
        if (lh__t3_in_triangle(c, c->tri + 3 * (size_t)c->patch_tri[a], g,
                               abs(c->patch_axis[k]) - 1))
            return 1;
    return 0;
}

/* The side of face f its tetrahedron's apex is on, along patch k's normal: +1
 * above, -1 below, 0 when f is edge-on in the patch's projection. */
static int apex_side(t3_ctx *c, size_t k, const lh_index *f, lh_index apex)
{
    int sa = c->patch_axis[k], ax = abs(sa) - 1, i = (ax + 1) % 3, j = (ax + 2) % 3;
    const double *p[4];
    double q[3][2];
    for (int a = 0; a < 3; a++) {
        p[a] = c->xyz + 3 * (size_t)f[a];
        q[a][0] = p[a][i], q[a][1] = p[a][j];
    }
    p[3] = c->xyz + 3 * (size_t)apex;
    const double *pq[3] = {q[0], q[1], q[2]};
    /* f's normal points along the patch's when its projection turns as the normal's
       component along the dropped axis says */
    int turn = lh_orient(c->pred, 2, pq) * (sa < 0 ? -1 : 1);
    return turn * lh_orient(c->pred, 3, p);
}

/* Faces on stamped points found in the stars, 4 indices each into c->fbuf: the
 * sorted triple, then 2 (apex off the patch) or the apex's side (apex on it);
 * *count of them. */
static lh_status face_records(t3_ctx *c, size_t k, patch_scan *ps, size_t *count)
{
    const lh_index *s = c->tv;
    size_t nf = 0;
    for (size_t i = 0; i < ps->nv; i++) {
        lh_index v = c->vbuf[i];
        for (lh_index q = c->star_first[v]; q < c->star_first[v + 1]; q++) {
            const lh_index *t = s + 4 * (size_t)c->star[q];
            int mask = 0, corners = 0; /* those a face from v may have: stamped, not below v */
            for (int j = 0; j < 4; j++) {
                const int may = c->stamp[t[j]] >= 1 && t[j] >= v;
                mask |= may << j, corners += may;
            }
            if (corners < 3) continue;
            for (int o = 0; o < 4; o++) { /* the face opposite corner o, from its
                                             smallest point v, once per tet */
                if (t[o] == v || (mask | 1 << o) != 15) continue;
                lh_index f[4], w = 0;
                for (int j = 0; j < 4; j++)
                    if (j != o) f[w++] = t[j];
                lh__t3_sort3(f);
                if (!face_in_patch(c, k, f)) continue;
                f[3] = c->stamp[t[o]] >= 1 ? apex_side(c, k, f, t[o]) : 2;
                lh_status st = lh__t3_room(c, &c->fbuf, &c->fcap, 4 * (nf + 1));
                if (st != LH_OK) return st;
                memcpy(c->fbuf + 4 * nf++, f, sizeof f);
            }
        }
    }
    *count = nf;
    return LH_OK;
}

/* The candidate faces into c->fbuf, sorted triples, each once: a face counts unless
 * both its tetrahedra are flat, or its one flat tetrahedron is not above it. */
static lh_status patch_faces(t3_ctx *c, size_t k, patch_scan *ps)
{
    size_t nf;
    lh_status st = face_records(c, k, ps, &nf);
    if (st != LH_OK) return st;
    if (nf) qsort(c->fbuf, nf, 4 * sizeof(lh_index), cmp_triple);
    size_t w = 0;
    for (size_t i = 0, run; i < nf; i += run) {
        const lh_index *r = c->fbuf + 4 * i;
        for (run = 1; i + run < nf && !cmp_triple(r, r + 4 * run);) run++;
        int flat = 0, above = 0;
        for (size_t j = 0; j < run; j++) {
            flat += r[4 * j + 3] != 2;
            above += r[4 * j + 3] == 1;
        }
        if (flat == 2 || (flat == 1 && !above)) continue;
        memmove(c->fbuf + 3 * w++, r, 3 * sizeof(lh_index)); /* w <= i: no overlap ahead */
    }
    ps->nf = w;
    return LH_OK;
}

/* The candidates' edges into c->ebuf, sorted pairs. */
static lh_status patch_edges(t3_ctx *c, patch_scan *ps)
{
    lh_status st = lh__t3_room(c, &c->ebuf, &c->ecap, 6 * ps->nf + 2);
    if (st != LH_OK) return st;
    for (size_t f = 0; f < ps->nf; f++)
        for (int j = 0; j < 3; j++) {
            lh_index p = c->fbuf[3 * f + j], q = c->fbuf[3 * f + (j + 1) % 3];
            c->ebuf[6 * f + 2 * j] = p < q ? p : q;
            c->ebuf[6 * f + 2 * j + 1] = p < q ? q : p;
        }
    ps->ne = 3 * ps->nf;
    if (ps->ne) qsort(c->ebuf, ps->ne, 2 * sizeof(lh_index), cmp_pair);
    return LH_OK;
}

/* Gathers patch k: points (stamped until release), needs, candidate faces and their
 * edges. */
static lh_status gather(t3_ctx *c, size_t k, patch_scan *ps)
{
    lh_status st = patch_points(c, k, ps);
    if (st == LH_OK) st = patch_faces(c, k, ps);
    if (st == LH_OK) st = patch_edges(c, ps);
    return st;
}

static void release(t3_ctx *c, patch_scan *ps)
{
    for (size_t i = 0; i < ps->nv; i++) c->stamp[c->vbuf[i]] = -1;
    lh__free(&c->al, ps->needs);
}

/* How many candidate faces hold edge p q (p < q): a run of the sorted edges. */
static size_t uses(const t3_ctx *c, const patch_scan *ps, lh_index p, lh_index q)
{
    lh_index key[2] = {p, q};
    size_t lo = 0, hi = ps->ne;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (cmp_pair(c->ebuf + 2 * mid, key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t n = 0;
    while (lo + n < ps->ne && !cmp_pair(c->ebuf + 2 * (lo + n), key)) n++;
    return n;
}

static int is_need(const patch_scan *ps, const lh_index *e)
{
    return bsearch(e, ps->needs, ps->nn, sizeof(need), cmp_need) != NULL;
}

/* |p - q|^2 times 2^(-2 c->unit_exp): the differences halved (no overflow) and scaled
 * to the points' range (no square over- or underflows), exactly so for a model
 * scaled by a power of two: lengths compare the same at every scale. */
static double len2(const t3_ctx *c, lh_index p, lh_index q)
{
    double s = 0;
    for (int k = 0; k < 3; k++) {
        double d =
            ldexp(c->xyz[3 * (size_t)p + k] / 2 - c->xyz[3 * (size_t)q + k] / 2, -c->unit_exp);
        s += d * d;
    }
    return s;
}

/* What a failed patch needs: the longest need held by too few faces (*short_need), or
 * the longest other edge held by one (*frontier, 2 indices); *ok when neither and no
 * edge is held too often. */
typedef struct verdict {
    int ok;
    const need *short_need, *any_need;
    lh_index frontier[2];
    double short_len, any_len, frontier_len;
} verdict;

static void judge(const t3_ctx *c, const patch_scan *ps, verdict *v)
{
    memset(v, 0, sizeof *v);
    v->frontier[0] = -1;
    v->short_len = v->any_len = v->frontier_len = -1;
    int bad = ps->nf == 0;
    for (size_t i = 0; i < ps->nn; i++) {
        const need *n = ps->needs + i;
        size_t u = uses(c, ps, n->p, n->q);
        double l = len2(c, n->p, n->q);
        if (l > v->any_len) v->any_len = l, v->any_need = n;
        if (u == (size_t)n->mult) continue;
        bad = 1;
        if (u < (size_t)n->mult && l > v->short_len) v->short_len = l, v->short_need = n;
    }
    for (size_t i = 0, run; i < ps->ne; i += run) {
        for (run = 1; i + run < ps->ne && !cmp_pair(c->ebuf + 2 * i, c->ebuf + 2 * (i + run));)
            run++;
        if (run == 2 || is_need(ps, c->ebuf + 2 * i)) continue;
        bad = 1;
        double l = len2(c, c->ebuf[2 * i], c->ebuf[2 * i + 1]);
        if (run == 1 && l > v->frontier_len && !along_chain(c, c->ebuf + 2 * i, 2))
            v->frontier_len = l, v->frontier[0] = c->ebuf[2 * i],
            v->frontier[1] = c->ebuf[2 * i + 1];
    }
    v->ok = !bad;
}

/* The split a failed patch gets (verdict above): a short need's subsegment; else a
 * point inside the patch, the centroid of the face on the longest frontier edge;
 * else the longest need's subsegment. */
static lh_status split(t3_ctx *c, size_t k, const patch_scan *ps, const verdict *v)
{
    if (v->short_need) return lh__t3_split(c, v->short_need->seg, (size_t)v->short_need->i);
    if (v->frontier[0] >= 0) { /* the centroid of the one face on the frontier edge */
        const lh_index *f = c->fbuf;
        for (size_t i = 0; i < ps->nf; i++, f += 3) {
            int has = 0;
            for (int a = 0; a < 3; a++) has += f[a] == v->frontier[0] || f[a] == v->frontier[1];
            if (has == 2) break;
        }
        double x[3];
        for (int a = 0; a < 3; a++)
            x[a] = c->xyz[3 * (size_t)f[0] + a] / 3 + c->xyz[3 * (size_t)f[1] + a] / 3 +
                   c->xyz[3 * (size_t)f[2] + a] / 3; /* no overflow */
        return lh__t3_queue(c, -1 - (lh_index)k, 0, -1, x);
    }
    if (v->any_need) return lh__t3_split(c, v->any_need->seg, (size_t)v->any_need->i);
    return lh__t3_say(c, LH_ERR_INTERNAL, 0, "patch %zu has no segment to split", k);
}

/* The common case: a patch of one triangle, no point on its edges or inside it. Its
 * face, sorted, into *f; 0 when the patch is not that simple. */
static int plain_triangle(const t3_ctx *c, size_t k, lh_index f[3])
{
    if (c->patch_first[k + 1] - c->patch_first[k] != 1 ||
        c->pnode_first[k + 1] != c->pnode_first[k])
        return 0;
    const size_t t = (size_t)c->patch_tri[c->patch_first[k]];
    for (int j = 0; j < 3; j++) {
        lh_index s = c->tri_seg[3 * t + j];
        if (s < 0 || c->node_first[s + 1] != c->node_first[s]) return 0;
        f[j] = c->tri[3 * t + j];
    }
    lh__t3_sort3(f);
    return 1;
}

/* Keeps the nf faces in c->fbuf as patch k's cover (lh__t3_patch_cover). */
static lh_status keep_cover(t3_ctx *c, size_t k, size_t nf)
{
    lh_status st = lh__t3_room(c, &c->cover, &c->cover_cap, c->cover_count + 3 * nf);
    if (st != LH_OK) return st;
    memcpy(c->cover + c->cover_count, c->fbuf, 3 * nf * sizeof(lh_index));
    c->cover_first[k] = (lh_index)c->cover_count, c->cover_len[k] = (lh_index)nf;
    c->cover_count += 3 * nf;
    return LH_OK;
}

lh_status lh__t3_patch_check(t3_ctx *c, size_t k, int want_split, int *ok)
{
    lh_index f[3];
    c->cover_first[k] = -1;
    if (plain_triangle(c, k, f) && lh__t3_has_face(c, f[0], f[1], f[2])) return *ok = 1, LH_OK;
    patch_scan ps;
    memset(&ps, 0, sizeof ps);
    lh_status st = gather(c, k, &ps);
    verdict v;
    if (st == LH_OK) {
        judge(c, &ps, &v);
        *ok = v.ok;
        if (!v.ok && want_split) st = split(c, k, &ps, &v);
        if (v.ok) st = keep_cover(c, k, ps.nf);
    }
    release(c, &ps);
    return st;
}

int lh__t3_patch_changed(const t3_ctx *c, size_t k, uint32_t r)
{
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++) {
        const size_t t = (size_t)c->patch_tri[a];
        for (int j = 0; j < 3; j++) {
            if (c->changed[c->tri[3 * t + j]] > r) return 1;
            lh_index s = c->tri_seg[3 * t + j];
            if (s >= 0 && lh__t3_seg_changed(c, (size_t)s, r)) return 1;
        }
    }
    for (lh_index i = c->pnode_first[k]; i < c->pnode_first[k + 1]; i++)
        if (c->changed[c->pnode[i].p] > r) return 1;
    return 0;
}

lh_status lh__t3_patch_cover(t3_ctx *c, size_t k, const lh_index **faces, size_t *count)
{
    lh_index f[3];
    if (plain_triangle(c, k, f) && lh__t3_has_face(c, f[0], f[1], f[2])) {
        lh_status st = lh__t3_room(c, &c->fbuf, &c->fcap, 3);
        if (st == LH_OK) memcpy(c->fbuf, f, sizeof f);
        *faces = c->fbuf;
        *count = st == LH_OK;
        return st;
    }
    if (c->cover_first[k] >= 0) {
        *faces = c->cover + c->cover_first[k];
        *count = (size_t)c->cover_len[k];
        return LH_OK;
    }
    patch_scan ps;
    memset(&ps, 0, sizeof ps);
    lh_status st = gather(c, k, &ps);
    release(c, &ps);
    *faces = c->fbuf;
    *count = st == LH_OK ? ps.nf : 0;
    return st;
}
