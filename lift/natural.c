/*
 * natural.c — lh_tri_natural_coords: Sibson's natural-neighbour coordinates in 2D
 * and 3D (Sibson 1980, "A vector identity for the Dirichlet tessellation", Math.
 * Proc. Camb. Phil. Soc. 87; Sibson 1981, "A brief description of natural neighbour
 * interpolation"). The weight of site p_i is vol(S_i) / sum_j vol(S_j), where
 * S_i = V(q) ∩ V_old(p_i) is the part of p_i's Voronoi region that q's region takes
 * when q is inserted. Sibson's identity sum_i vol(S_i) (p_i - q) = 0 is the linear
 * precision the tests check.
 *
 * Decisions, exact (lifthull.h, predicates):
 *   - where q is: lh_tri_locate (orient_d); outside the hull is an error; q equal to a
 *     vertex (coordinates compared) is that site; q on the hull's boundary (orient_d
 *     zero against the located simplex's facets, and the face holding q has a hull
 *     facet around it) gets the limit of the coordinates, its barycentric coordinates
 *     in that face (Sukumar, Moran & Belytschko 1998, "The natural element method in
 *     solid mechanics", IJNME 43: linear along a convex boundary).
 *   - the conflict region (Bowyer 1981; Watson 1981): the simplices whose
 *     circumsphere holds q strictly, insphere_d(simplex, q) < 0 for a positively
 *     oriented simplex. It is connected through facets and star-shaped from q (the
 *     lifted lower hull is convex: along a segment from q into a conflict simplex,
 *     every simplex crossed has its lifted hyperplane at least as high above q's
 *     lifted point), so a breadth-first search from the located simplex finds it.
 *     A simplex whose sphere passes exactly through q would steal nothing, so the
 *     strict test is the continuous one (Hiyoshi & Sugihara 2002, "Improving
 *     continuity of Voronoi-based interpolation over Delaunay spheres", CGTA 22).
 *
 * Volumes: natural_volumes.c (Lasserre's pyramids on the faces of S_i, floating
 * point; its header says how and how accurate).
 *
 * Memory: one block per call through t->alloc, sized for a number of conflict
 * simplices; when the region is larger the search restarts with four times that.
 */
#include "natural.h"
#include "geom.h"
#include "lh_alloc.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the workspace ---------------------------------------------------------------- */

/* Reserves count elements of size bytes at *off; 0 on size_t overflow. */
static int reserve(size_t *off, size_t count, size_t size)
{
    if (count > (SIZE_MAX - *off) / size) return 0;
    *off += count * size;
    *off = (*off + 7) & ~(size_t)7;
    return *off != 0;
}

/* The block for cap conflict simplices, carved into w's arrays; NULL on failure. */
static void *ws_create(const lh_allocator *a, int d, size_t cap, nn_ws *w)
{
    const size_t nv = (size_t)d + 1, ns = cap + (size_t)d;
    size_t entries = nv * cap + 1 + ns, tsize = 16;
    while (tsize < 2 * entries) tsize *= 2;
    size_t off[16], o = 0;
    int i = 0, ok = 1;
    /* doubles and uint64 first: every later offset stays 8-aligned */
    off[i++] = o, ok &= reserve(&o, cap * (size_t)d, sizeof(double));      /* cc   */
    off[i++] = o, ok &= reserve(&o, cap * nv * (size_t)d, sizeof(double)); /* fc   */
    off[i++] = o, ok &= reserve(&o, ns * (size_t)d, sizeof(double));       /* x    */
    off[i++] = o, ok &= reserve(&o, ns, sizeof(double));                   /* vol  */
    off[i++] = o, ok &= reserve(&o, ns, sizeof(double));                   /* aq   */
    off[i++] = o, ok &= reserve(&o, ns * (size_t)d, sizeof(double));       /* root */
    off[i++] = o, ok &= reserve(&o, ns, sizeof(nn_pair));                  /* pair */
    off[i++] = o, ok &= reserve(&o, tsize, sizeof(uint64_t));              /* key  */
    off[i++] = o, ok &= reserve(&o, tsize, sizeof(lh_index));              /* val  */
    off[i++] = o, ok &= reserve(&o, cap, sizeof(lh_index));                /* conf */
    off[i++] = o, ok &= reserve(&o, cap * nv, sizeof(lh_index));           /* lv   */
    off[i++] = o, ok &= reserve(&o, cap * nv, sizeof(lh_index));           /* nb   */
    off[i++] = o, ok &= reserve(&o, ns, sizeof(lh_index));                 /* site */
    off[i++] = o, ok &= reserve(&o, cap, 1);                               /* done */
    off[i++] = o, ok &= reserve(&o, ns, 1);                                /* rooted */
    char *b = ok ? lh__alloc(a, o) : NULL;
    if (!b) return NULL;
    i = 0;
    w->cc = (double *)(b + off[i++]);
    w->fc = (double *)(b + off[i++]);
    w->x = (double *)(b + off[i++]);
    w->vol = (double *)(b + off[i++]);
    w->aq = (double *)(b + off[i++]);
    w->root = (double *)(b + off[i++]);
    w->pair = (nn_pair *)(b + off[i++]);
    w->key = (uint64_t *)(b + off[i++]);
    w->val = (lh_index *)(b + off[i++]);
    w->conf = (lh_index *)(b + off[i++]);
    w->lv = (lh_index *)(b + off[i++]);
    w->nb = (lh_index *)(b + off[i++]);
    w->site = (lh_index *)(b + off[i++]);
    w->done = (uint8_t *)(b + off[i++]);
    w->rooted = (uint8_t *)(b + off[i++]);
    w->cap = cap;
    w->mask = tsize - 1;
    w->nconf = w->nsite = 0;
    memset(w->key, 0xff, tsize * sizeof *w->key);
    memset(w->done, 0, cap);
    memset(w->rooted, 0, ns);
    memset(w->vol, 0, ns * sizeof *w->vol);
    memset(w->aq, 0, ns * sizeof *w->aq);
    return b;
}

/* The slot of key k: where it is, or the empty slot where it goes. */
static size_t slot(const nn_ws *w, uint64_t k)
{
    size_t i = (size_t)((k * 0x9E3779B97F4A7C15u) >> 29) & w->mask;
    while (w->key[i] != NN_EMPTY && w->key[i] != k) i = (i + 1) & w->mask;
    return i;
}

/* ---- the conflict region ---------------------------------------------------------- */

/* insphere_d(s, q) < 0: q strictly inside the circumsphere of the positively
 * oriented simplex s. */
static int in_conflict(lh_tri *t, lh_index s, const double *q)
{
    const int nv = t->d + 1;
    const double *p[NN_MAXV + 1];
    for (int j = 0; j < nv; j++) p[j] = t->xyz + (size_t)t->simp[(size_t)s * nv + j] * t->d;
    p[nv] = q;
    return lh_insphere(t->pred, t->d, p) < 0;
}

static int cmp_index(const void *a, const void *b)
{
    lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return (x > y) - (x < y);
}

/* Breadth-first search from s0 (a conflict simplex) over the neighbours; every
 * simplex tested is in the table (-1 when not in conflict). Returns 0 when more
 * than w->cap simplices conflict. */
static int conflict_region(lh_tri *t, const double *q, lh_index s0, nn_ws *w)
{
    const int nv = t->d + 1;
    w->key[slot(w, 2 * (uint64_t)s0)] = 2 * (uint64_t)s0;
    w->conf[w->nconf++] = s0;
    for (size_t c = 0; c < w->nconf; c++) {
        const lh_index *nbr = t->nbr + (size_t)w->conf[c] * nv;
        for (int k = 0; k < nv; k++) {
            if (nbr[k] < 0) continue;
            uint64_t key = 2 * (uint64_t)nbr[k];
            size_t i = slot(w, key);
            if (w->key[i] == key) continue;
            w->key[i] = key;
            w->val[i] = -1;
            if (!in_conflict(t, nbr[k], q)) continue;
            if (w->nconf == w->cap) return 0;
            w->conf[w->nconf++] = nbr[k];
        }
    }
    return 1;
}

/* After the search: conflict indices in simplex order, the local sites (relative
 * coordinates), and each conflict simplex's local sites and conflict neighbours. */
static void index_region(const lh_tri *t, const double *q, nn_ws *w)
{
    const int d = t->d, nv = d + 1;
    qsort(w->conf, w->nconf, sizeof *w->conf, cmp_index);
    for (size_t c = 0; c < w->nconf; c++) w->val[slot(w, 2 * (uint64_t)w->conf[c])] = (lh_index)c;
    for (size_t c = 0; c < w->nconf; c++) {
        const lh_index *v = t->simp + (size_t)w->conf[c] * nv, *nbr = t->nbr + (size_t)w->conf[c] * nv;
        for (int j = 0; j < nv; j++) {
            uint64_t key = 2 * (uint64_t)v[j] + 1;
            size_t i = slot(w, key);
            if (w->key[i] != key) {
                w->key[i] = key;
                w->val[i] = (lh_index)w->nsite;
                w->site[w->nsite] = v[j];
                for (int k = 0; k < d; k++)
                    w->x[w->nsite * d + k] = t->xyz[(size_t)v[j] * d + k] - q[k];
                w->nsite++;
            }
            w->lv[c * nv + j] = w->val[i];
            w->nb[c * nv + j] = nbr[j] < 0 ? -1 : w->val[slot(w, 2 * (uint64_t)nbr[j])];
        }
    }
}

/* The local coordinates scaled by a power of two (exactly), the largest to
 * magnitude in [1/2, 1), so that no construction overflows or underflows; the
 * weights are ratios of volumes and do not change. */
static void rescale(nn_ws *w, int d)
{
    double big = 0;
    int e;
    for (size_t i = 0; i < w->nsite * (size_t)d; i++) big = fmax(big, fabs(w->x[i]));
    if (!(big > 0 && big <= DBL_MAX)) return;
    frexp(big, &e);
    for (size_t i = 0; i < w->nsite * (size_t)d; i++) w->x[i] = ldexp(w->x[i], -e);
}

/* ---- results ---------------------------------------------------------------------- */

static int cmp_pair(const void *a, const void *b)
{
    lh_index x = ((const nn_pair *)a)->site, y = ((const nn_pair *)b)->site;
    return (x > y) - (x < y);
}

/* Keeps the pairs with a positive finite weight, normalised to sum 1 and sorted by
 * site; returns how many (0 when none, or their sum is not finite). */
static size_t normalise(nn_pair *p, size_t m)
{
    size_t k = 0;
    double total = 0;
    for (size_t i = 0; i < m; i++)
        if (p[i].w > 0 && p[i].w <= DBL_MAX) {
            total += p[i].w;
            p[k++] = p[i];
        }
    if (!(total > 0 && total <= DBL_MAX)) return 0;
    for (size_t i = 0; i < k; i++) p[i].w /= total;
    qsort(p, k, sizeof *p, cmp_pair);
    return k;
}

static lh_status write_out(const nn_pair *p, size_t m, size_t cap, lh_index *sites,
                           double *weights, size_t *count)
{
    *count = m;
    if (m > cap) return LH_ERR_BUFFER_TOO_SMALL;
    for (size_t i = 0; i < m; i++) {
        sites[i] = p[i].site;
        weights[i] = p[i].w;
    }
    return LH_OK;
}

/* The located simplex's barycentric coordinates (the fallback: linear precision as
 * well); normalised, as above. */
static size_t simplex_pairs(const lh_tri *t, const lh_location *loc, nn_pair *p)
{
    const int nv = t->d + 1;
    for (int j = 0; j < nv; j++) {
        p[j].site = t->simp[(size_t)loc->simplex * nv + j];
        p[j].w = loc->bary[j];
    }
    return normalise(p, (size_t)nv);
}

/* ---- special positions: a site, the hull's boundary -------------------------------- */

/* 3D: whether the edge a b (sites of tetrahedron s) is on the hull: the walk round it
 * (as edge_face_3d's, over t's arrays) reaches the hull before coming back to s. */
static int edge_on_hull(const lh_tri *t, lh_index s, lh_index a, lh_index b)
{
    const lh_index *v = t->simp + (size_t)s * 4;
    lh_index x = v[0] != a && v[0] != b ? v[0] : v[1] != a && v[1] != b ? v[1] : v[2];
    lh_index cur = s;
    for (size_t steps = 0; steps <= t->count; steps++) {
        v = t->simp + (size_t)cur * 4;
        int p = 0;
        lh_index y = -1;
        for (int j = 0; j < 4; j++) {
            if (v[j] == x) p = j;
            else if (v[j] != a && v[j] != b) y = v[j];
        }
        lh_index n = t->nbr[(size_t)cur * 4 + p];
        if (n < 0) return 1;
        if (n == s) return 0;
        cur = n;
        x = y;
    }
    return 0; /* not reached: the tetrahedra round an edge are finitely many */
}

/* Barycentric coordinates of q in the face v[0..m-1] (m = 2, 3) whose affine hull
 * holds it: the normal equations relative to v[0]. Returns 0 if singular. */
static int face_bary(int d, const double *const *v, int m, const double *q, double *lam)
{
    double g[4], r[2];
    const int k = m - 1;
    for (int i = 0; i < k; i++) {
        r[i] = 0;
        for (int c = 0; c < d; c++) r[i] += (v[i + 1][c] - v[0][c]) * (q[c] - v[0][c]);
        for (int j = 0; j < k; j++) {
            g[i * k + j] = 0;
            for (int c = 0; c < d; c++) g[i * k + j] += (v[i + 1][c] - v[0][c]) * (v[j + 1][c] - v[0][c]);
        }
    }
    if (!lh__solve(g, r, k)) return 0;
    lam[0] = 1;
    for (int i = 0; i < k; i++) {
        lam[i + 1] = r[i];
        lam[0] -= r[i];
    }
    return 1;
}

/* q at a vertex of the located simplex s (coordinates equal), or on the hull's
 * boundary: there q is in the relative interior of the face of s whose vertices
 * have a nonzero orient_d (exact) — a hull facet (its neighbour is -1) or, in 3D,
 * an edge with a hull facet round it. Writes the pairs and returns how many (at
 * most d, normalised); 0 when q is inside the hull and not a site. */
static size_t special_point(lh_tri *t, const double *q, lh_index s, nn_pair *out)
{
    const int d = t->d, nv = d + 1;
    const lh_index *v = t->simp + (size_t)s * nv, *nbr = t->nbr + (size_t)s * nv;
    const double *p[NN_MAXV];
    for (int j = 0; j < nv; j++) {
        const double *x = t->xyz + (size_t)v[j] * d;
        int same = 1;
        for (int c = 0; c < d; c++) same &= x[c] == q[c];
        if (same) {
            out[0].site = v[j];
            out[0].w = 1;
            return 1;
        }
    }
    int zero[NN_MAXV], nz = 0, face[NN_MAXV], m = 0;
    for (int k = 0; k < nv; k++) {
        for (int j = 0; j < nv; j++) p[j] = j == k ? q : t->xyz + (size_t)v[j] * d;
        zero[k] = lh_orient(t->pred, d, p) == 0;
        nz += zero[k];
        if (!zero[k]) face[m++] = k;
    }
    int on_hull = 0;
    if (nz == 1) {
        for (int k = 0; k < nv; k++)
            if (zero[k]) on_hull = nbr[k] < 0;
    } else if (nz == 2 && d == 3) {
        on_hull = edge_on_hull(t, s, v[face[0]], v[face[1]]);
    }
    if (!on_hull) return 0;
    double lam[NN_MAXV];
    for (int j = 0; j < m; j++) p[j] = t->xyz + (size_t)v[face[j]] * d;
    if (!face_bary(d, p, m, q, lam)) return 0; /* not reached: the face is a simplex */
    for (int j = 0; j < m; j++) {
        out[j].site = v[face[j]];
        out[j].w = lam[j];
    }
    return normalise(out, (size_t)m);
}

/* ---- the entry point --------------------------------------------------------------- */

/* Sibson's weights of q inside the hull (not a site, not on the boundary) into the
 * workspace's pairs; returns how many, 0 if the constructions failed. */
static size_t sibson(nn_ws *w, int d)
{
    if (!lh__nn_volumes(w, d)) return 0;
    for (size_t i = 0; i < w->nsite; i++) {
        w->pair[i].site = w->site[i];
        w->pair[i].w = w->vol[i];
    }
    return normalise(w->pair, w->nsite);
}

static lh_status interior(lh_tri *t, const double *q, const lh_location *loc, size_t cap,
                          lh_index *sites, double *weights, size_t *count)
{
    const int d = t->d;
    if (!in_conflict(t, loc->simplex, q)) return LH_ERR_INTERNAL; /* not reached */
    for (size_t cap_c = NN_FIRST_CAP;; cap_c = cap_c > t->count / 4 ? t->count : 4 * cap_c) {
        if (cap_c > t->count) cap_c = t->count;
        nn_ws w;
        void *block = ws_create(&t->alloc, d, cap_c, &w);
        if (!block) return LH_ERR_NOMEM;
        if (!conflict_region(t, q, loc->simplex, &w)) {
            lh__free(&t->alloc, block);
            continue;
        }
        index_region(t, q, &w);
        rescale(&w, d);
        size_t m = sibson(&w, d);
        lh_status st;
        if (m) {
            st = write_out(w.pair, m, cap, sites, weights, count);
        } else {
            nn_pair p[NN_MAXV];
            m = simplex_pairs(t, loc, p);
            st = m ? write_out(p, m, cap, sites, weights, count) : LH_ERR_INTERNAL;
        }
        lh__free(&t->alloc, block);
        return st;
    }
}

lh_status lh_tri_natural_coords(lh_tri *t, const double *q, lh_index hint, size_t cap,
                                lh_index *sites, double *weights, size_t *count)
{
    if (!count) return LH_ERR_INVALID_ARGUMENT;
    *count = 0;
    if (!t || !q || (cap > 0 && (!sites || !weights))) return LH_ERR_INVALID_ARGUMENT;
    if ((t->d != 2 && t->d != 3) || t->frame.k != t->d) return LH_ERR_DIMENSION;
    if (t->furthest) return LH_ERR_INVALID_ARGUMENT;
    if (lh_coords_validate(t->d, 1, q, NULL) != LH_OK) return LH_ERR_NONFINITE;
    lh_location loc;
    lh_status st = lh_tri_locate(t, q, hint, &loc);
    if (st != LH_OK) return st;
    if (loc.simplex < 0) return LH_ERR_INVALID_ARGUMENT;
    nn_pair p[NN_MAXV];
    size_t m = special_point(t, q, loc.simplex, p);
    if (m) return write_out(p, m, cap, sites, weights, count);
    st = interior(t, q, &loc, cap, sites, weights, count);
    if (st != LH_OK && st != LH_ERR_BUFFER_TOO_SMALL) *count = 0;
    return st;
}
