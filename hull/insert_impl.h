/*
 * insert_impl.h — the engine's insertion loop as a template: the walk, the conflict
 * region, the cone of new cells and their linking. One source, compiled with the
 * conflict test a caller's function and the dimension a runtime value
 * (hull/insert_generic.c), and by lift/ with its conflict test inline, once with the
 * dimension a runtime value and once per fixed dimension, so that the hot loops see
 * constant sizes there (lift/insert_delaunay.h).
 *
 * Parameters (macros defined before including this file):
 *   LH_T_NAME   the entry function's name (external linkage);
 *   LH_T_D      the dimension, a constant (optional: e->d when undefined);
 *   LH_T_FINITE_CONFLICT(e, v, q)  whether the finite cell with vertices v conflicts
 *               with vertex q (engine.h: the rule);
 *   LH_T_FINITE_CONFLICT2(e, v, w, q, x)  the same for finite cells v and w at
 *               once, into x[0] and x[1] (a test may pair their filters);
 *   LH_T_PLACING(e)  no finite cell conflicts (a placing triangulation);
 *   LH_T_ORIENT(e, pts)  orient_d of pts (insert_orient.h);
 *   LH_T_PREPARE(e)  run once per call before inserting;
 *   LH_T_PARALLEL  (optional) defined: the entry function is a worker of a
 *               parallel phase (parallel.h: it locks every cell before reading it
 *               and defers the sites whose cells another worker holds).
 *
 * Location: a remembering stochastic visibility walk (Devillers, Pion & Teillaud,
 * "Walking in a triangulation", IJFCS 13(2), 2002) from the last new cell. It stops
 * in the closed simplex containing q, or in an infinite cell whose facet q strictly
 * sees. A bound on its length falls back to scanning every cell, so it always ends.
 *
 * Cavity: the conflict region grows depth-first from the located cell through
 * facets (its cells are marked in, the tested neighbours out); each boundary facet
 * (c, k) becomes the new cell c with vertex k replaced by q, which keeps c's
 * orientation (Bowyer 1981; Watson 1981; in the hull view the cone from q to the
 * horizon of the facets it sees).
 *
 * Linking the new cells: the new cell N made from boundary facet (c, k) meets,
 * across its facet opposite vertex v_j (j != k), the new cell made from the other
 * boundary facet that contains the ridge R = c \ {v_k, v_j} (the cavity's boundary
 * is a closed pseudo-manifold: every ridge is in exactly two boundary facets). In
 * 2D and 3D, R is a vertex or an edge, oriented by each cell the opposite way in
 * the other: the two are twins in a table of oriented ridges (link_twins); in 3D
 * that table is indexed by the cavity boundary's own numbering of its vertices,
 * with q moved last in every new cell (cone_local). In 4D and up, a Delaunay
 * insertion keys R on that numbering too, in a hash table (number_boundary,
 * link_numbered), and the dead cells become new cells in place (make_cone); when
 * the boundary has more than 255 vertices, it finds the other cell by turning
 * around R through the dead cells (link_by_turning). The other modes (placing,
 * the furthest-site hull) pair the two through a hash table keyed on R's vertex
 * indices (link_new_cells): each new cell's old vertices are sorted once; a
 * ridge is that list minus one entry. When its vertices fit in 64 bits (t->vbits
 * each: for n below 2^21 in 4D, 2^16 in 5D) the key is the ridge itself, packed;
 * otherwise it is the sum of a mix of its vertices (one subtraction from the
 * cell's sum) and equal keys are confirmed by comparing the sorted lists, so a
 * collision costs a probe, never a wrong link.
 */
#include "engine.h"
#include "lh_exact.h"

#include <string.h>

#ifdef LH_T_D
#define NV (LH_T_D + 1)
#else
#define NV (t->nv) /* every function below has the store t in scope */
#endif
#if !defined(LH_T_NAME) || !defined(LH_T_FINITE_CONFLICT) || !defined(LH_T_FINITE_CONFLICT2) || \
    !defined(LH_T_PLACING) || !defined(LH_T_ORIENT) || !defined(LH_T_PREPARE)
#error "insert_impl.h: define LH_T_NAME, LH_T_FINITE_CONFLICT(2), LH_T_PLACING, LH_T_ORIENT and LH_T_PREPARE first"
#endif

/* HOLD(e, c): whether this computation may read and write cell c; always in a
 * sequential build, once taken in a parallel worker. MARK / SET_MARK: cell c's
 * visit mark, which other workers read and take (parallel.h). */
#ifdef LH_T_PARALLEL
#include "parallel.h"
#define HOLD(e, c) lh__par_lock((e)->par, &(e)->tds, c)
#define MARK(t, c) atomic_load_explicit(lh__par_marks(t) + (c), memory_order_relaxed)
#define SET_MARK(t, c, m) atomic_store_explicit(lh__par_marks(t) + (c), m, memory_order_relaxed)
#else
#define HOLD(e, c) 1
#define MARK(t, c) ((t)->stamp[c])
#define SET_MARK(t, c, m) ((t)->stamp[c] = (m))
#endif

/* What the conflict search reads of cell c first: its visit mark (written: it is
 * set, and in a parallel worker taken by CAS) and its vertices. */
#define PREFETCH_CELL(c) (LH__PREFETCH_W(t->stamp + (c)), LH__PREFETCH(t->vert + (size_t)(c) * NV))

static inline int push(lh__tds *t, lh_index **arr, size_t *cap, size_t *len, lh_index x)
{
    if (*len < *cap) {
        (*arr)[(*len)++] = x;
        return 1;
    }
    return lh__tds_push_slow(t, arr, cap, len, x);
}

/* Whether cell c (held) conflicts with e->q (engine.h: the rule for infinite
 * cells); -1 when a cell it needs is another worker's. */
static LH__ALWAYS_INLINE int conflict(lh__eng *e, lh_index c)
{
    const lh__tds *t = &e->tds;
    const lh_index *v = t->vert + (size_t)c * NV;
    if (v[0] != LH__INF) return LH_T_FINITE_CONFLICT(e, v, e->q);
    e->pts[0] = lh__eng_site(e, e->q);
    for (int k = 1; k < NV; k++) e->pts[k] = lh__eng_site(e, v[k]);
    int o = LH_T_ORIENT(e, e->pts);
    if (o || LH_T_PLACING(e)) return o > 0;
    lh_index f = t->nbr[(size_t)c * NV];
    if (!HOLD(e, f)) return -1;
    return LH_T_FINITE_CONFLICT(e, t->vert + (size_t)f * NV, e->q);
}

/* orient_d of finite cell v with its vertex k replaced by q. */
static inline int orient_replaced(lh__eng *e, const lh_index *v, int k)
{
    const lh__tds *t = &e->tds;
    (void)t;
    for (int j = 0; j < NV; j++) e->pts[j] = lh__eng_site(e, v[j]);
    e->pts[k] = lh__eng_site(e, e->q); /* after the loop: no branch on j == k in it */
    return LH_T_ORIENT(e, e->pts);
}

#ifndef LH_T_PARALLEL
static lh_index scan_for_conflict(lh__eng *e)
{
    for (lh_index c = 0; c < e->tds.top; c++)
        if (!lh__tds_dead(&e->tds, c) && conflict(e, c)) return c;
    return -1;
}
#endif

/* A cell in conflict with q, or -1 when q is inside the current hull and no finite
 * cell can conflict (placing mode), or -2 when a cell on the way is another
 * worker's. Starts from the hint (held). */
static lh_index locate(lh__eng *e)
{
    const lh__tds *t = &e->tds;
    lh_index c = e->hint, prev = -1;
    size_t limit = 64 + 8 * (size_t)t->live;
    for (size_t step = 0; step < limit; step++) {
        const lh_index *v = t->vert + (size_t)c * NV;
        if (v[0] == LH__INF) {
            if (prev >= 0) return c; /* entered across its facet */
            int x = conflict(e, c);
            if (x) return x > 0 ? c : -2;
            prev = c;
            c = t->nbr[(size_t)c * NV];
            if (!HOLD(e, c)) return -2;
            continue;
        }
        /* the first facet tried: the high half of a random word times NV, over 2^32
           (a multiply, not a division by the runtime NV of the generic build) */
        int s = (int)((lh__rng_next(&e->rng) >> 32) * (uint64_t)NV >> 32), moved = 0;
        for (int i = 0; i < NV && !moved; i++) {
            int k = s + i < NV ? s + i : s + i - NV;
            lh_index n = t->nbr[(size_t)c * NV + k];
            if (n == prev || orient_replaced(e, v, k) >= 0) continue;
            if (!HOLD(e, n)) return -2;
            prev = c;
            c = n;
            moved = 1;
        }
        if (!moved) return e->inside_conflicts ? c : -1; /* q in the closed simplex c */
    }
#ifdef LH_T_PARALLEL
    return -2; /* the cells are shared: left to the sequential pass */
#else
    return scan_for_conflict(e); /* not reached in practice */
#endif
}

/* The conflict tests of c's finite neighbours not yet visited, two cells at a time
 * (LH_T_FINITE_CONFLICT2), into x[k] for the neighbour across facet k; x[k] = -1
 * where grow_region tests it itself (visited, infinite, or the odd one left).
 * Same tests, same answers; measured against one test at a time, one thread: 4D
 * 10^5 sites 5-7% faster (5D 3%, 3D 1-2%), 4D 2*10^4 8% fewer instructions; with
 * two threads no change beyond the noise. Returns 0 when a neighbour is another
 * worker's. */
static LH__ALWAYS_INLINE int pair_tests(lh__eng *e, lh_index c, uint32_t in, uint32_t out, int *x)
{
    const lh__tds *t = &e->tds;
    const lh_index *nb = t->nbr + (size_t)c * NV;
    int wait = -1; /* a facet whose neighbour waits for a second one */
    for (int k = 0; k < NV; k++) {
        x[k] = -1;
        const lh_index n = nb[k];
        if (!HOLD(e, n)) return 0;
        const uint32_t st = MARK(t, n);
        const lh_index *v = t->vert + (size_t)n * NV;
        if (st == in || st == out || v[0] == LH__INF) continue;
        if (wait < 0) {
            wait = k;
            continue;
        }
        int two[2];
        LH_T_FINITE_CONFLICT2(e, t->vert + (size_t)nb[wait] * NV, v, e->q, two);
        x[wait] = two[0], x[k] = two[1];
        wait = -1;
    }
    return 1;
}

/* The conflict region from `start`: t->cells, and its boundary facets as pairs
 * (cell, k) in t->bound. Returns 1; 0 when memory runs out; -1 when a cell it
 * reaches is another worker's. */
static int grow_region(lh__eng *e, lh_index start, uint32_t in, uint32_t out)
{
    lh__tds *t = &e->tds;
    t->ncells = t->nbound = 0;
    size_t nb2 = 0;
    SET_MARK(t, start, in);
    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, start)) return 0;
    for (size_t i = 0; i < t->ncells; i++) {
        lh_index c = t->cells[i];
        /* the misses of c's neighbours overlap; those of the cell two ahead in the
           queue are taken now, to arrive while c and the next are tested (two
           ahead: 4D 1.15x, 5D 1.24x faster than none, one ahead 1.08x, 1.20x) */
        for (int k = 0; k < NV; k++) PREFETCH_CELL(t->nbr[(size_t)c * NV + k]);
        if (i + 2 < t->ncells) {
            const lh_index *nn = t->nbr + (size_t)t->cells[i + 2] * NV;
            for (int k = 0; k < NV; k++) PREFETCH_CELL(nn[k]);
        }
        int paired[LH__TDS_MAX_NV];
        if (!pair_tests(e, c, in, out, paired)) return -1; /* holds every neighbour */
        for (int k = 0; k < NV; k++) {
            lh_index n = t->nbr[(size_t)c * NV + k];
            uint32_t st = MARK(t, n);
            if (st == in) continue;
            if (st != out) {
                int x = paired[k] >= 0 ? paired[k] : conflict(e, n);
                if (x < 0) return -1;
                if (x) {
                    SET_MARK(t, n, in);
                    LH__PREFETCH(t->nbr + (size_t)n * NV); /* read when n is expanded */
                    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, n)) return 0;
                    continue;
                }
                SET_MARK(t, n, out);
            }
            if (!push(t, &t->bound, &t->bound_cap, &nb2, c) || !push(t, &t->bound, &t->bound_cap, &nb2, k))
                return 0;
        }
    }
    t->nbound = nb2 / 2;
    return 1;
}

static inline uint64_t mix(lh_index v) /* one multiply and a fold: nonlinear in v */
{
    uint64_t z = (uint64_t)(lh__uindex)v * UINT64_C(0x9e3779b97f4a7c15);
    return z ^ (z >> 29);
}

/* The old vertices of new cell b (all but position k), increasing, with their
 * positions. */
static inline void sort_old_vertices(lh__tds *t, size_t b, lh_index N, int k)
{
    const lh_index *v = t->vert + (size_t)N * NV;
    lh_index *s = t->sorted + b * (NV - 1);
    int8_t *p = t->spos + b * (NV - 1);
    int n = 0;
    for (int j = 0; j < NV; j++) {
        if (j == k) continue;
        int i = n++;
        for (; i > 0 && s[i - 1] > v[j]; i--) {
            s[i] = s[i - 1];
            p[i] = p[i - 1];
        }
        s[i] = v[j];
        p[i] = (int8_t)j;
    }
}

/* Whether the sorted lists of new cells a and b, minus entries da and db, agree. */
static int same_ridge(const lh__tds *t, size_t a, int da, size_t b, int db)
{
    const int m = NV - 1;
    const lh_index *x = t->sorted + a * m, *y = t->sorted + b * m;
    for (int i = 0, j = 0; i < m; i++, j++) {
        if (i == da) i++;
        if (j == db) j++;
        if (i < m && x[i] != y[j]) return 0;
    }
    return 1;
}

/* The key of the ridge of sorted list s (m entries) without entry drop: packed
 * (vbits per vertex + 1) when exact, else the sum of mixes `sum` minus drop's. */
static inline uint64_t ridge_key(const lh_index *s, int m, int drop, uint64_t sum, int vbits, int exact)
{
    if (!exact) return sum - mix(s[drop]);
    uint64_t k = 0;
    for (int x = 0; x < m; x++)
        if (x != drop) k = k << vbits | (uint64_t)(lh__uindex)(s[x] + 1);
    return k;
}

/* The home slot of a ridge key in the ridge table (Fibonacci hashing), before the
 * mask of lh__ridge_slots. */
static inline size_t ridge_slot(uint64_t key) { return (size_t)((key * UINT64_C(0x9e3779b97f4a7c15)) >> 40); }

/* Pairs the new cells t->fresh[] across their ridges (see the top). */
static void link_new_cells(lh__tds *t)
{
    const int m = NV - 1, vbits = t->vbits, exact = (m - 1) * vbits <= 64;
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots((size_t)m * t->nbound) - 1;
    for (size_t b = 0; b < t->nbound; b++) sort_old_vertices(t, b, t->fresh[b], (int)t->bound[2 * b + 1]);
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index N = t->fresh[b], *s = t->sorted + b * m;
        uint64_t sum = 0;
        if (!exact)
            for (int i = 0; i < m; i++) sum += mix(s[i]);
        for (int i = 0; i < m; i++) {
            uint64_t key = ridge_key(s, m, i, sum, vbits, exact);
            for (size_t h = ridge_slot(key) & mask;; h = (h + 1) & mask) {
                lh__ridge *r = t->ridge + h;
                if (r->round != round) { /* free: the first of the pair */
                    r->key = key;
                    r->round = round;
                    r->bd = (uint32_t)b << 4 | (uint32_t)i;
                    break;
                }
                size_t rb = r->bd >> 4;
                int rd = (int)(r->bd & 15);
                if (r->key == key && (exact || same_ridge(t, b, i, rb, rd))) {
                    lh_index M = t->fresh[rb];
                    t->nbr[(size_t)N * NV + t->spos[b * m + i]] = M;
                    t->nbr[(size_t)M * NV + t->spos[rb * m + rd]] = N;
                    r->key = LH__RIDGE_PAIRED;
                    break;
                }
            }
        }
    }
}

/* The position of x in a row of NV entries holding it once, branch-free. */
static inline int row_pos(const lh__tds *t, const lh_index *row, lh_index x)
{
    (void)t; /* NV reads t->nv in the runtime-dimension build */
    int p = 0;
    for (int i = 1; i < NV; i++) p += i * (row[i] == x);
    return p;
}

/* Pairs the new cells by turning around their ridges through the dead cells, for a
 * Delaunay insertion (inside_conflicts): the conflict region is then a ball (it is
 * star-shaped from q), so the dead cells around a ridge R on its boundary form a
 * path from one boundary facet holding R to the other. Each dead cell's boundary
 * facet first points at its new cell; from boundary facet (c, k), the new cell's
 * facet opposite vertex j (R = c minus v_j and v_k) is crossed through c's facet
 * opposite j, R + x with x = v_k; a dead cell R + x + w entered there is left through
 * R + w, until the facet crossed is a boundary facet, whose new cell is the
 * neighbour (the way CGAL's 3D data structure builds a star, Boissonnat, Devillers,
 * Pion, Teillaud & Yvinec 2002, "Triangulations in CGAL", CGTA 22). Every step is in
 * cells just visited by grow_region, and nothing is hashed or sorted. Both cells of
 * a pair are linked at once. The dead cells' rows are overwritten (they are freed
 * next). */
static void link_by_turning(lh__eng *e)
{
    lh__tds *t = &e->tds;
    /* a dead cell's boundary facet holds -2 - b (its new cell is fresh[b]): a
       neighbour >= 0 is then a dead cell, with no look at the stamps */
    for (size_t b = 0; b < t->nbound; b++) t->nbr[(size_t)t->bound[2 * b] * NV + t->bound[2 * b + 1]] = -2 - (lh_index)b;
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index N = t->fresh[b], c = t->bound[2 * b];
        const int k = (int)t->bound[2 * b + 1];
        for (int j = 0; j < NV; j++) {
            if (j == k || t->nbr[(size_t)N * NV + j] >= 0) continue;
            lh_index cur = c, x = t->vert[(size_t)c * NV + k], nx;
            int pos = j;
            while ((nx = t->nbr[(size_t)cur * NV + pos]) >= 0) {
                const lh_index *vv = t->vert + (size_t)nx * NV;
                const int m = row_pos(t, t->nbr + (size_t)nx * NV, cur);
                pos = row_pos(t, vv, x), x = vv[m], cur = nx;
            }
            const lh_index M = t->fresh[-2 - nx];
            t->nbr[(size_t)N * NV + j] = M;
            t->nbr[(size_t)M * NV + row_pos(t, t->vert + (size_t)cur * NV, x)] = N;
        }
    }
}

/* The ridge keys of new cell b into keys[0..NV-2] (the ridge opposite the i-th old
 * vertex, in position order), from the numbers of its old vertices on the cavity's
 * boundary: t->vloc holds a vertex's number (1..255, 0: none yet), seen[0..*nid-1]
 * the vertices numbered. A key is the ridge's numbers, increasing, 8 bits each (56
 * bits at most in 8D): equal keys, equal ridges. Read from the dead cell of
 * boundary facet b, before the cone overwrites it. Returns 0 when the numbers run
 * out. */
static inline int number_ridges(lh__tds *t, size_t b, uint64_t *keys, lh_index *seen, int *nid)
{
    const int M = NV - 1, k = (int)t->bound[2 * b + 1];
    const lh_index *v = t->vert + (size_t)t->bound[2 * b] * NV; /* the dead cell's */
    unsigned id[LH__ENGINE_MAX_DIM], rank[LH__ENGINE_MAX_DIM];
    for (int i = 0; i < M; i++) {
        const lh_index x = v[i + (i >= k)]; /* the i-th old vertex, without a branch on k */
        uint8_t *l = t->vloc + (x + 1);
        const unsigned had = *l;
        seen[*nid] = x;
        *nid += had == 0;
        id[i] = had ? had : (unsigned)*nid;
        *l = (uint8_t)id[i];
        rank[i] = 0;
    }
    if (*nid > 255) return 0;
    for (int a = 0; a < M; a++)
        for (int c = a + 1; c < M; c++) {
            const unsigned above = id[a] > id[c];
            rank[a] += above, rank[c] += !above;
        }
    uint64_t all = 0;
    for (int i = 0; i < M; i++) all |= (uint64_t)id[i] << (8 * rank[i]);
    for (int i = 0; i < M; i++) { /* all without its byte rank[i] */
        const uint64_t low = ((uint64_t)1 << (8 * rank[i])) - 1;
        keys[i] = (all & low) | (all >> 8 & ~low);
    }
    return 1;
}

/* Pairs the new cells of a Delaunay insertion in 4D and up (and in 3D beyond 2^32
 * sites, where link_twins's keys do not fit) by their ridges' keys
 * (number_ridges): the boundary's vertices are numbered as they are met, so a
 * ridge's key is its numbers in order, exact, in one word, with no sort of the
 * cell's vertices (link_new_cells) and no walk through the dead cells
 * (link_by_turning: 1.3x and 1.4x the time in 4D and 5D, timed inside the same
 * runs). number_boundary takes the keys, from the dead cells, before the cone;
 * link_numbered enters them in the ridge table (a prefix at most 1/8 full) in
 * order, each slot prefetched 16 keys ahead. The first of a pair to arrive claims
 * a slot; the second finds it, links both cells, and flags it paired: both
 * without a branch on which one arrives first (such a branch guesses wrong half
 * the time). Every ridge of the closed boundary is in exactly two new cells; the
 * count of pairs checks it. Keys go in t->sorted (LH__SORTED_ROOM). */

/* The keys of every boundary facet's ridges. Returns 1; 0, with t->vloc cleared
 * again, when the boundary has more than 255 vertices (link_by_turning then). */
static int number_boundary(lh__tds *t)
{
    const int M = NV - 1;
    uint64_t *keys = (uint64_t *)t->sorted;
    lh_index seen[255 + LH__ENGINE_MAX_DIM];
    int nid = 0, ok = 1;
    for (size_t b = 0; b < t->nbound && ok; b++) ok = number_ridges(t, b, keys + b * M, seen, &nid);
    for (int i = 0; i < nid; i++) t->vloc[seen[i] + 1] = 0;
    return ok;
}

/* Links the new cells t->fresh[] by the keys of number_boundary. Returns 1; 0
 * when a ridge is not in exactly two cells (as link_twins). */
static int link_numbered(lh__tds *t)
{
    const int M = NV - 1;
    const size_t nb = t->nbound, nk = nb * (size_t)M, ahead = 16;
    const uint64_t *keys = (const uint64_t *)t->sorted;
    lh_index sink[2];
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots(nk / 2) - 1; /* nk / 2 ridges */
    size_t paired = 0;
    for (size_t r = 0; r < nk && r < ahead; r++) LH__PREFETCH_W(t->ridge + (ridge_slot(keys[r]) & mask));
    for (size_t b = 0; b < nb; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index N = t->fresh[b];
        for (int i = 0; i < M; i++) {
            const size_t r = b * M + i;
            if (r + ahead < nk) LH__PREFETCH_W(t->ridge + (ridge_slot(keys[r + ahead]) & mask));
            const int j = i + (i >= k);
            const uint64_t key = keys[r];
            size_t h = ridge_slot(key) & mask;
            while ((t->ridge[h].round == round) & (t->ridge[h].key != key)) h = (h + 1) & mask;
            const lh__ridge met = t->ridge[h];
            const int second = met.round == round;
            paired += (size_t)second;
            t->ridge[h] = (lh__ridge){key | (uint64_t)second << 63, round, (uint32_t)b << 4 | (uint32_t)j};
            const lh_index O = t->fresh[second ? met.bd >> 4 : 0];
            *(second ? t->nbr + (size_t)N * NV + j : sink) = O;
            *(second ? t->nbr + (size_t)O * NV + (met.bd & 15) : sink + 1) = N;
        }
    }
    return 2 * paired == nk;
}

/* Pairing the new cells as twins, in 2D and 3D. The new cell made from boundary
 * facet (c, k) carries that facet; the facets tile the cavity's boundary, a closed
 * pseudo-manifold, and each is oriented by its cell (two cells oriented alike
 * induce opposite orientations on the facet they share: the boundary operator of
 * simplicial homology). In 3D the cell's facet opposite position j (j != k) holds q
 * and the boundary triangle's edge TWIN_EDGE[k][j] = (a, b), directed so that the
 * neighbour across that facet holds the same edge as (b, a); in 2D it holds q and
 * the boundary edge's end TWIN_VERTEX[k][j] = a, with a sign (a is the edge's first
 * or last vertex) that is the other one in the neighbour. Every new cell enters its
 * keys in the ridge table (a prefix at most 1/8 full: lh__ridge_slots), then finds
 * its neighbours under the reversed keys. No branch depends on which cell of a
 * pair comes first, unlike turning (link_by_turning: half of a 3D run's
 * mispredicted branches, callgrind) or link_new_cells. In 4D and up, where a
 * ridge's vertices must first be put in a canonical order, number_ridges does
 * that on small numbers. The 3D key needs 2 vbits <= 64. Returns 0 if a key has
 * no twin. */
static const int8_t TWIN_EDGE[4][4][2] = {
    /* positions {0..3} \ {k, j}, increasing, exchanged when j + (k, or k - 1 when
       j < k) is odd: the facet opposite j is (-1)^j times its vertices in order */
    {{0, 0}, {3, 2}, {1, 3}, {2, 1}},
    {{2, 3}, {0, 0}, {3, 0}, {0, 2}},
    {{3, 1}, {0, 3}, {0, 0}, {1, 0}},
    {{1, 2}, {2, 0}, {0, 1}, {0, 0}},
};
static const int8_t TWIN_VERTEX[3][3][2] = { /* position {0..2} \ {k, j}, parity */
    {{0, 0}, {2, 1}, {1, 0}},
    {{2, 0}, {0, 0}, {0, 1}},
    {{1, 1}, {0, 0}, {0, 0}},
};

/* The key of new cell v's ridge opposite position j (its new vertex at k), reversed
 * when `rev`, and its slot. nv: 3 or 4, a constant where link_twins is inlined. */
static inline size_t twin_slot(const lh__tds *t, const lh_index *v, int nv, int k, int j, int rev, uint64_t *key)
{
    if (nv == 3) {
        const int8_t *p = TWIN_VERTEX[k][j];
        *key = (uint64_t)(lh__uindex)(v[p[0]] + 1) << 1 | (uint64_t)(p[1] ^ rev);
    } else {
        const int8_t *e = TWIN_EDGE[k][j];
        *key = (uint64_t)(lh__uindex)(v[e[rev]] + 1) << t->vbits | (uint64_t)(lh__uindex)(v[e[!rev]] + 1);
    }
    return ridge_slot(*key);
}

static inline int link_twins(lh__tds *t, const int nv)
{
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots((size_t)(nv - 1) * t->nbound) - 1;
    for (size_t b = 0; b < t->nbound; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index *v = t->vert + (size_t)t->fresh[b] * nv;
        for (int i = 1; i < nv; i++) {
            const int j = k + i < nv ? k + i : k + i - nv;
            uint64_t key;
            size_t h = twin_slot(t, v, nv, k, j, 0, &key) & mask;
            while (t->ridge[h].round == round) h = (h + 1) & mask;
            t->ridge[h] = (lh__ridge){key, round, (uint32_t)b << 4 | (uint32_t)j};
        }
    }
    for (size_t b = 0; b < t->nbound; b++) {
        const int k = (int)t->bound[2 * b + 1];
        const lh_index N = t->fresh[b], *v = t->vert + (size_t)N * nv;
        for (int i = 1; i < nv; i++) {
            const int j = k + i < nv ? k + i : k + i - nv;
            uint64_t key;
            size_t h = twin_slot(t, v, nv, k, j, 1, &key) & mask;
            for (;; h = (h + 1) & mask) {
                if (t->ridge[h].round != round) return 0;
                if (t->ridge[h].key == key) break;
            }
            t->nbr[(size_t)N * nv + j] = t->fresh[t->ridge[h].bd >> 4];
        }
    }
    return 1;
}

/* QLAST[k]: the positions in old cell c of new cell N's vertices when q, which
 * takes c's position k, is moved last (cone_local): an even permutation, so N keeps
 * c's orientation, that fixes position 0 (LH__INF's) unless k = 0. */
static const int8_t QLAST[4][4] = {{2, 1, 3, 0}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 1, 2, 3}};

/* The cone and its links in 3D without hashing. Each new cell has q at position 3
 * (QLAST), so its boundary triangle (0, 1, 2) is directed by TWIN_EDGE[3]: 1 -> 2,
 * 2 -> 0 and 0 -> 1, opposite positions 0, 1 and 2. The boundary's vertices are
 * numbered 1..LH__EDGE_IDS as they are met (t->vloc), and the directed edge (a, b)
 * is the slot a << LH__EDGE_BITS | b of t->edge, which holds b + 1 for the new cell
 * of boundary facet b until its twin (b, a) reads it. Both arrays are zero between
 * insertions: every number is cleared at the end, and every slot written is
 * cleared by its one reader (3 nbound reads, each clearing a nonzero slot, clear
 * 3 nbound distinct slots: all those written). A closed boundary of V vertices has
 * 2V - 4 triangles, so the numbers suffice for up to 122 new cells.
 * First every boundary facet is read and numbered, and what its new cell needs is
 * kept in t->sorted's room (its three old vertices, the outside cell, the dead
 * cell's position there and the numbers); then the dead cells are reused in place
 * for the first new cells, as many as there are (no free list walked, nothing
 * killed but the rest), and the twins are read. Returns 1; 0 when there are more
 * vertices (nothing changed: the general cone then); -1 when an edge has no twin. */
static int cone_local(lh__eng *e)
{
    lh__tds *t = &e->tds;
    uint8_t *loc = t->vloc;
    uint32_t *edge = t->edge;
    lh_index seen[LH__EDGE_IDS + 3];
    int nid = 0, ok = 1;
    const size_t nb = t->nbound, reuse = t->ncells < nb ? t->ncells : nb;
    for (size_t b = 0; b < nb; b++) {
        const lh_index c = t->bound[2 * b], *cv = t->vert + (size_t)c * 4;
        const int k = (int)t->bound[2 * b + 1];
        lh_index *keep = t->sorted + 5 * b;
        unsigned id[3];
        for (int j = 0; j < 3; j++) {
            const lh_index v = cv[QLAST[k][j]];
            uint8_t *x = loc + (v + 1);
            const uint8_t had = *x;
            seen[nid] = keep[j] = v;
            nid += had == 0;
            id[j] = *x = had ? had : (uint8_t)nid;
        }
        ok = nid <= LH__EDGE_IDS;
        if (!ok) break;
        edge[id[1] << LH__EDGE_BITS | id[2]] = (uint32_t)b + 1;
        edge[id[2] << LH__EDGE_BITS | id[0]] = (uint32_t)b + 1;
        edge[id[0] << LH__EDGE_BITS | id[1]] = (uint32_t)b + 1;
        const lh_index out = t->nbr[(size_t)c * 4 + k];
        keep[3] = out;
        keep[4] = (lh_index)((unsigned)row_pos(t, t->nbr + (size_t)out * 4, c) | id[0] << 2 | id[1] << 10 | id[2] << 18);
    }
    for (size_t b = 0; b < nb && ok; b++) {
        const lh_index *keep = t->sorted + 5 * b;
        const lh_index N = b < reuse ? t->cells[b] : lh__tds_new_cell(t); /* room: lh__tds_room */
        lh_index *nv = t->vert + (size_t)N * 4, *nn = t->nbr + (size_t)N * 4;
        nv[0] = keep[0], nv[1] = keep[1], nv[2] = keep[2], nv[3] = e->q;
        nn[3] = keep[3];
        t->nbr[(size_t)keep[3] * 4 + (keep[4] & 3)] = N;
        t->fresh[b] = N;
    }
    for (size_t b = 0; b < nb && ok; b++) {
        const unsigned w = (unsigned)t->sorted[5 * b + 4], id0 = w >> 2 & 255, id1 = w >> 10 & 255, id2 = w >> 18;
        lh_index *nn = t->nbr + (size_t)t->fresh[b] * 4;
        uint32_t *slot[3] = {edge + (id2 << LH__EDGE_BITS | id1), edge + (id0 << LH__EDGE_BITS | id2),
                             edge + (id1 << LH__EDGE_BITS | id0)};
        for (int j = 0; j < 3; j++) {
            const uint32_t m = *slot[j];
            *slot[j] = 0;
            if (!m) ok = -1;
            else nn[j] = t->fresh[m - 1];
        }
    }
    for (int s = 0; s < nid; s++) loc[seen[s] + 1] = 0; /* nid < LH__EDGE_IDS + 3 */
    if (ok <= 0) memset(edge, 0, LH__EDGE_SLOTS * sizeof *edge);
    if (ok > 0)
        for (size_t i = reuse; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return ok;
}

/* The cone: the new cell t->fresh[b] is boundary facet b's dead cell c with vertex
 * k replaced by q, linked to the outside cell across k and to nothing else yet.
 * grow_region lists the boundary facets cell by cell in the order of t->cells, so
 * once facet b of cells[i] is reached, cells[0..i-1] have been read for the last
 * time: with `reuse`, they are overwritten in place as the next new cells (no free
 * list walked: its pops are a chain of dependent loads), and only the rest come
 * from lh__tds_new_cell. The last dead cell with a boundary facet is never reused
 * (it is still being read when the last new cell is made). Without `reuse`, the
 * dead cells stay as they are (turning walks through them). Returns the number of
 * dead cells reused, the first of t->cells; the caller kills the others. */
static size_t make_cone(lh__eng *e, int reuse)
{
    lh__tds *t = &e->tds;
    size_t done = 0, used = 0;
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index c = t->bound[2 * b], k = t->bound[2 * b + 1];
        while (reuse && t->cells[done] != c) done++;
        /* cannot fail after lh__tds_room */
        const lh_index N = used < done ? t->cells[used++] : lh__tds_new_cell(t);
        lh_index *nvert = t->vert + (size_t)N * NV, *nnbr = t->nbr + (size_t)N * NV;
        const lh_index *cv = t->vert + (size_t)c * NV, outside = t->nbr[(size_t)c * NV + k];
        for (int j = 0; j < NV; j++) nvert[j] = cv[j], nnbr[j] = -1;
        nvert[k] = e->q;
        nnbr[k] = outside;
        lh_index *on = t->nbr + (size_t)outside * NV;
        on[row_pos(t, on, c)] = N;
        t->fresh[b] = N;
    }
    return used;
}

/* Inserts e->q from `start`, a cell in conflict with it. The new cells are
 * t->fresh[0..nbound-1]. On LH_ERR_NOMEM and LH__RETRY the store is unchanged
 * (but for visit marks). */
static lh_status cavity_insert(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
#ifndef LH_T_PARALLEL
    lh__tds_next_round(t); /* a worker's attempt starts its rounds (lh__par_begin) */
#endif
    uint32_t in = 4 * t->round, out = in + 1;
    int g = grow_region(e, start, in, out);
    if (g <= 0) return g ? LH__RETRY : LH_ERR_NOMEM;
    lh_status st = lh__tds_room(t);
    if (st != LH_OK) return st;
    for (size_t b = 0; b < t->nbound; b++) /* the outside cells' neighbour rows */
        LH__PREFETCH(t->nbr + (size_t)t->nbr[(size_t)t->bound[2 * b] * NV + t->bound[2 * b + 1]] * NV);
    const int twins = (NV == 3 || (NV == 4 && 2 * t->vbits <= 64)) && !e->dbg.hashed_ridges;
    const int local = NV == 4 && twins && t->vloc ? cone_local(e) : 0;
    if (local) return local > 0 ? LH_OK : LH_ERR_INTERNAL;
    const int numbered = !twins && e->inside_conflicts && t->vloc ? number_boundary(t) : 0;
    const size_t reused = make_cone(e, numbered);
    if (numbered) {
        if (!link_numbered(t)) return LH_ERR_INTERNAL;
    } else if (twins) {
        if (!(NV == 3 ? link_twins(t, 3) : link_twins(t, 4))) return LH_ERR_INTERNAL;
    } else if (e->inside_conflicts) {
        link_by_turning(e);
#ifndef LH_T_PARALLEL
        e->dbg.turned++;
#endif
    } else
        link_new_cells(t);
    for (size_t i = reused; i < t->ncells; i++) lh__tds_kill(t, t->cells[i]);
    return LH_OK;
}

#if !defined(LH_T_D) || LH_T_D == 2
/*
 * The 2D cavity of a Delaunay insertion (inside_conflicts): inserting a site never
 * removes a vertex, so no vertex lies inside the conflict region, a triangulated
 * disk whose cells' dual graph is therefore a tree. An Euler tour of that tree from
 * the located cell, taking each cell's edges in order (k, k+1, k+2 cyclically) from
 * the one after its entry edge, meets the boundary edges in order around the disk:
 * edge i = (v[k+1], v[k+2]) of its dead cell ends where edge i+1 starts. The new
 * cell (q, a_i, b_i) on edge i meets the new cells of edges i+1 and i-1 across its
 * other two edges, so the cells are linked without visit stamps or the ridge table.
 * A disk of m triangles has m + 2 boundary edges: the dead cells are reused in
 * place and two more are taken. Same cavity as cavity_insert (the same conflict
 * test on the same cells), so the same triangulation. The runtime-dimension build
 * takes it too when d = 2 (a choice made per insertion on t->nv, like the twins'),
 * except under hashed_ridges, which test_ridges sets to check cavity_insert's
 * 2D linking against it.
 */

/* Cell N := (q, a, b) in this cyclic order with neighbours (o, next, prev) opposite
 * them, rotated so that LH__INF, when present, comes first. */
static inline void set_fan_cell(lh__tds *t, lh_index N, const lh_index v3[3], const lh_index n3[3])
{
    int r = v3[1] == LH__INF ? 1 : v3[2] == LH__INF ? 2 : 0;
    lh_index *v = t->vert + (size_t)N * 3, *n = t->nbr + (size_t)N * 3;
    for (int j = 0; j < 3; j++) {
        int s = j + r < 3 ? j + r : j + r - 3;
        v[j] = v3[s];
        n[j] = n3[s];
    }
}

static const int8_t NEXT_3[3] = {1, 2, 0}; /* the next position, cyclically: a load, not a branch */

/* The tour from `start` (in conflict with q): dead cells in t->cells, boundary
 * edges in t->bound as (a, b, outside cell, index of the dead cell in its row).
 * Returns LH_OK, LH_ERR_NOMEM, LH__RETRY (a cell is another worker's), or
 * LH_ERR_INTERNAL should the region not be a tree. */
static lh_status tour_cavity_2(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
    size_t nb4 = 0, depth = 0;
    t->ncells = 0;
    if (!push(t, &t->cells, &t->cells_cap, &t->ncells, start)) return LH_ERR_NOMEM;
    if (!push(t, &t->fresh, &t->fresh_cap, &depth, start) || !push(t, &t->fresh, &t->fresh_cap, &depth, 3))
        return LH_ERR_NOMEM; /* frames: cell, then next edge << 2 | edges left */
    while (depth) {
        lh_index c = t->fresh[depth - 2], f = t->fresh[depth - 1];
        int k = (int)(f >> 2), left = (int)(f & 3);
        if (!left) {
            depth -= 2;
            continue;
        }
        t->fresh[depth - 1] = (lh_index)(NEXT_3[k] << 2 | (left - 1));
        lh_index n = t->nbr[(size_t)c * 3 + k];
        LH__PREFETCH(t->nbr + (size_t)n * 3);
        int cf = HOLD(e, n) ? conflict(e, n) : -1;
        if (cf < 0) return LH__RETRY;
        if (cf) {
            if (t->ncells >= (size_t)t->live) return LH_ERR_INTERNAL; /* not a tree */
            int j = row_pos(t, t->nbr + (size_t)n * 3, c);
            if (!push(t, &t->cells, &t->cells_cap, &t->ncells, n) ||
                !push(t, &t->fresh, &t->fresh_cap, &depth, n) ||
                !push(t, &t->fresh, &t->fresh_cap, &depth, (lh_index)(NEXT_3[j] << 2 | 2)))
                return LH_ERR_NOMEM;
            continue;
        }
        const lh_index *cv = t->vert + (size_t)c * 3;
        lh_index rec[4] = {cv[NEXT_3[k]], cv[NEXT_3[NEXT_3[k]]], n, row_pos(t, t->nbr + (size_t)n * 3, c)};
        for (int x = 0; x < 4; x++)
            if (!push(t, &t->bound, &t->bound_cap, &nb4, rec[x])) return LH_ERR_NOMEM;
    }
    t->nbound = nb4 / 4;
    return t->nbound == t->ncells + 2 ? LH_OK : LH_ERR_INTERNAL;
}

static lh_status cavity_insert_2(lh__eng *e, lh_index start)
{
    lh__tds *t = &e->tds;
    lh_status st = tour_cavity_2(e, start);
    if (st == LH_OK) st = lh__tds_room(t);
    if (st != LH_OK) return st;
    const size_t nb = t->nbound;
    for (size_t i = 0; i < nb; i++) t->fresh[i] = i < t->ncells ? t->cells[i] : lh__tds_new_cell(t);
    for (size_t i = 0; i < nb; i++) {
        const lh_index *r = t->bound + 4 * i;
        lh_index v3[3] = {e->q, r[0], r[1]};
        lh_index n3[3] = {r[2], t->fresh[i + 1 < nb ? i + 1 : 0], t->fresh[i ? i - 1 : nb - 1]};
        set_fan_cell(t, t->fresh[i], v3, n3);
        t->nbr[(size_t)r[2] * 3 + r[3]] = t->fresh[i];
    }
    return LH_OK;
}
#define CAVITY_INSERT(e, c)                                           \
    (NV == 3 && (e)->inside_conflicts && !(e)->dbg.hashed_ridges ? cavity_insert_2(e, c) \
                                                             : cavity_insert(e, c))
#else
#define CAVITY_INSERT(e, c) cavity_insert(e, c)
#endif

lh_status LH_T_NAME(lh__eng *e, size_t first, size_t count, const lh_index *list);
#ifdef LH_T_PARALLEL
/* A worker: inserts what it can, defers the rest (e->par). It still holds its hint
 * at the end, for the next call (parallel.c lets it go). Fails only on an internal
 * error. */
lh_status LH_T_NAME(lh__eng *e, size_t first, size_t count, const lh_index *list)
{
    lh__par *p = e->par;
    lh__tds *t = &e->tds;
    lh_status st = LH_OK;
    LH_T_PREPARE(e);
    for (size_t i = 0; i < count && (st == LH_OK || st == LH__RETRY || st == LH_ERR_NOMEM); i++) {
        e->q = list ? list[i] : (lh_index)(first + i);
        if (p->stopped) {
            lh__par_defer(p, e->q);
            continue;
        }
        lh__par_begin(p, t, e->hint);
        lh_index c = locate(e);
        st = c >= 0 ? CAVITY_INSERT(e, c) : c == -1 ? LH_OK : LH__RETRY; /* -1: not a vertex */
        if (st == LH_ERR_NOMEM && lh__par_refill(p, t)) {
            t->round++; /* fresh marks; the cells taken so far stay held */
            st = CAVITY_INSERT(e, c);
        }
        if (st == LH_OK && c >= 0) {
            e->hint = t->fresh[0];
            lh__par_keep(t, e->hint);
        } else if (st != LH_OK) {
            lh__par_defer(p, e->q);
        }
    }
    lh__pred_count_filtered(e->pred, e->filtered);
    e->filtered = 0;
    return st == LH__RETRY || st == LH_ERR_NOMEM ? LH_OK : st;
}
#else
lh_status LH_T_NAME(lh__eng *e, size_t first, size_t count, const lh_index *list)
{
    lh_status st = LH_OK;
    const lh__tds *t = &e->tds; /* NV reads t->nv in the runtime-dimension build */
    (void)t;
    LH_T_PREPARE(e);
    for (size_t i = 0; i < count && st == LH_OK; i++) {
        e->q = list ? list[i] : (lh_index)(first + i);
        lh_index c = locate(e);
        if (c < 0) continue; /* inside the current hull: not a vertex (placing modes) */
        st = CAVITY_INSERT(e, c);
        if (st == LH_OK) e->hint = e->tds.fresh[0];
    }
    lh__pred_count_filtered(e->pred, e->filtered);
    e->filtered = 0;
    return st;
}
#endif

#undef CAVITY_INSERT
#undef PREFETCH_CELL
#undef HOLD
#undef MARK
#undef SET_MARK
#undef NV
