/*
 * recover_flip_patch.c — a patch (recover.h) recovered by flips, once every
 * subsegment is an edge: the mesh edges that cross one of its triangles, neither end
 * a point of the patch, are removed (edge removal, recover_flip.c) in coordinate
 * order until none is left. In exact arithmetic that leaves it a union of faces: a
 * tet cutting the patch's plane inside it would hold such an edge, as its boundary's
 * subsegments are edges and no vertex lies inside it. Points rounded onto its edges
 * or into it are the patch's own, so their edges are never candidates; recover_faces.c
 * checks the result. The edges between its points are then locked, so that the
 * patches recovered after it keep it. A try that ends with an edge still crossing is
 * undone. (TetGen, Si 2015, sec. 3.3, recovers facets by flips first too, then
 * retriangulates cavities, which this version leaves to splitting.)
 */
#include "recover.h"

#include <string.h>

/* Patches with more triangles than this are left to splitting: each candidate edge
 * is tested against every triangle. */
#define T3_PATCH_TRIS 64
/* Tets searched for edges crossing one patch. */
#define T3_PATCH_TETS 4096

static lh_status mark_point(t3_ctx *c, lh_index v, size_t *np)
{
    if (c->pmark[v] == c->pgen) return LH_OK;
    lh_status st = lh__t3_room(c, &c->vbuf, &c->vcap, *np + 1);
    if (st != LH_OK) return st;
    c->pmark[v] = c->pgen;
    c->vbuf[(*np)++] = v;
    return LH_OK;
}

/* Patch k's points (its triangles' corners, their edges' chains, the Steiner points
 * inside it) into c->vbuf, marked in c->pmark; *np of them. */
static lh_status patch_points(t3_ctx *c, size_t k, size_t *np)
{
    lh_status st = LH_OK;
    *np = 0;
    if (++c->pgen == 0x7fffffff) { /* the marks wrap: start again */
        memset(c->pmark, 0, c->n * sizeof(lh_index));
        c->pgen = 1;
    }
    for (lh_index a = c->patch_first[k]; st == LH_OK && a < c->patch_first[k + 1]; a++)
        for (int j = 0; st == LH_OK && j < 3; j++) {
            const size_t t = (size_t)c->patch_tri[a];
            lh_index s = c->tri_seg[3 * t + j];
            st = mark_point(c, c->tri[3 * t + j], np);
            for (lh_index i = s < 0 ? 0 : c->node_first[s];
                 s >= 0 && st == LH_OK && i < c->node_first[s + 1]; i++)
                st = mark_point(c, c->node[i].p, np);
        }
    for (lh_index i = c->pnode_first[k]; st == LH_OK && i < c->pnode_first[k + 1]; i++)
        st = mark_point(c, c->pnode[i].p, np);
    return st;
}

/* Slots of the cache of orient_3(facet triangle, point) (t3_ctx.sides). */
#define T3_SIDES (1u << 14)

/* orient_3 of facet triangle `tri` and point p, through the cache: the search below
 * asks it of the same points again after each removal, and an exact evaluation near
 * degeneracy costs thousands of instructions. */
static int tri_side(t3_ctx *c, lh_index tri, lh_index p)
{
    const lh_index *f = c->tri + 3 * (size_t)tri;
    if (!c->sides) return lh__t3_orient4(c, f[0], f[1], f[2], p);
    size_t h = ((size_t)tri * 0x9E3779B97F4A7C15u ^ (size_t)p * 0xC2B2AE3D27D4EB4Fu) >> 7;
    lh_index *e = c->sides + 3 * (h & (c->sides_cap - 1));
    if (e[0] != tri || e[1] != p)
        e[0] = tri, e[1] = p, e[2] = lh__t3_orient4(c, f[0], f[1], f[2], p);
    return (int)e[2];
}

/* Whether edge p q, neither end a point of the patch, crosses one of patch k's
 * triangles: strictly through its plane, inside it or on its boundary (through a
 * diagonal between two of them). */
static int crosses_patch(t3_ctx *c, size_t k, lh_index p, lh_index q)
{
    if (c->pmark[p] == c->pgen || c->pmark[q] == c->pgen) return 0;
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++) {
        const lh_index *f = c->tri + 3 * (size_t)c->patch_tri[a];
        int op = tri_side(c, c->patch_tri[a], p), oq = tri_side(c, c->patch_tri[a], q);
        if (op == 0 || op != -oq) continue;
        int s0 = lh__t3_orient4(c, p, q, f[0], f[1]), s1 = lh__t3_orient4(c, p, q, f[1], f[2]);
        int s2 = lh__t3_orient4(c, p, q, f[2], f[0]);
        if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return 1;
    }
    return 0;
}

/* The edges crossing patch k (its np points in c->vbuf) as candidates in c->fbuf, *ne
 * of them: a search from the tets around its points across the faces of tets that
 * hold such an edge; *big when it meets more than T3_PATCH_TETS tets (what it found
 * would depend on the order it went in) or a locked edge crosses k (facets that
 * intersect: no flip takes it away). */
static lh_status patch_crossings(t3_ctx *c, size_t k, size_t np, size_t *ne, int *big)
{
    size_t m = 0;
    *ne = 0;
    for (size_t i = 0; i < np; i++) {
        size_t cnt;
        lh_status st = lh__t3_mesh_star(c, c->vbuf[i], &cnt);
        if (st == LH_OK) st = lh__t3_room(c, &c->ebuf, &c->ecap, m + cnt);
        if (st != LH_OK) return st;
        memcpy(c->ebuf + m, c->sbuf, cnt * sizeof(lh_index));
        m += cnt;
    }
    const lh_index gen = lh__t3_mesh_mark(c);
    size_t w = 0;
    for (size_t i = 0; i < m; i++)
        if (c->tmark[c->ebuf[i]] != gen) c->tmark[c->ebuf[i]] = gen, c->ebuf[w++] = c->ebuf[i];
    *big = w > T3_PATCH_TETS;
    for (size_t i = 0; i < w && !*big; i++) {
        const lh_index t = c->ebuf[i];
        int hit = 0;
        for (int x = 0; x < 4; x++)
            for (int y = x + 1; y < 4; y++) {
                lh_index p = c->tv[4 * (size_t)t + x], q = c->tv[4 * (size_t)t + y];
                if (!crosses_patch(c, k, p, q)) continue;
                hit = 1;
                *big |= lh__t3_locked(c, p, q); /* never removed: flips cannot recover k */
                lh_status st = lh__t3_candidate(c, t, p, q, ne);
                if (st != LH_OK) return st;
            }
        for (int j = 0; hit && j < 4; j++) {
            lh_index u = c->tn[4 * (size_t)t + j];
            if (u < 0 || c->tmark[u] == gen) continue;
            lh_status st = lh__t3_room(c, &c->ebuf, &c->ecap, w + 1);
            if (st != LH_OK) return st;
            c->tmark[u] = gen;
            c->ebuf[w++] = u;
        }
        *big |= w > T3_PATCH_TETS;
    }
    return LH_OK;
}

/* Whether patch k is plainly whole: its triangles, with no other point on them, are
 * faces of the mesh. */
static int patch_plain(const t3_ctx *c, size_t k)
{
    if (c->pnode_first[k + 1] != c->pnode_first[k]) return 0;
    for (lh_index a = c->patch_first[k]; a < c->patch_first[k + 1]; a++) {
        const lh_index *f = c->tri + 3 * (size_t)c->patch_tri[a];
        for (int j = 0; j < 3; j++) {
            lh_index s = c->tri_seg[3 * (size_t)c->patch_tri[a] + j];
            if (s >= 0 && c->node_first[s + 1] != c->node_first[s]) return 0;
        }
        if (!lh__t3_has_face(c, f[0], f[1], f[2])) return 0;
    }
    return 1;
}

/* Locks the edges between patch k's points (in the tets around them): the faces
 * covering it stay, as no flip removes an edge of theirs then, and the faces flips
 * take away (edge removal's around the edge removed, a 2-3 flip's face p q r of the
 * ring of p q) all hold an edge that is not locked. */
static lh_status lock_patch(t3_ctx *c, size_t np)
{
    for (size_t i = 0; i < np; i++) {
        size_t cnt;
        lh_status st = lh__t3_mesh_star(c, c->vbuf[i], &cnt);
        for (size_t a = 0; st == LH_OK && a < cnt; a++)
            for (int j = 0; st == LH_OK && j < 4; j++) {
                lh_index v = c->tv[4 * (size_t)c->sbuf[a] + j];
                if (v > c->vbuf[i] && c->pmark[v] == c->pgen) st = lh__t3_lock(c, c->vbuf[i], v);
            }
        if (st != LH_OK) return st;
    }
    return LH_OK;
}

lh_status lh__t3_flip_patch(t3_ctx *c, size_t k)
{
    size_t np, ne = 0;
    if (c->patch_first[k + 1] - c->patch_first[k] > T3_PATCH_TRIS || patch_plain(c, k))
        return LH_OK;
    if (!c->sides) { /* best effort: without it, each sign is computed afresh */
        c->sides = lh__alloc(&c->al, 3 * T3_SIDES * sizeof(lh_index));
        if (c->sides) memset(c->sides, 0xff, 3 * T3_SIDES * sizeof(lh_index));
        c->sides_cap = T3_SIDES;
    }
    lh_status st = patch_points(c, k, &np);
    int done = 1, big = 0;
    lh__t3_try_begin(c, T3_REMOVALS);
    while (st == LH_OK && done && (st = patch_crossings(c, k, np, &ne, &big)) == LH_OK && ne &&
           !big)
        st = lh__t3_remove_first(c, ne, &done);
    if (st == LH_OK && (ne || big)) lh__t3_mesh_undo(c, 0);
    if (st == LH_OK && !ne && !big) st = lock_patch(c, np);
    c->jlen = 0;
    return st;
}
