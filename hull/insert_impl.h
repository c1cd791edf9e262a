/*
 * insert_impl.h — the engine's insertion loop as a template: Bowyer–Watson
 * insertion (Bowyer 1981; Watson 1981), in the hull view the cone from each new
 * site to the horizon of the facets it sees. One source, compiled with the
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
 * The stages, one file each, included below in this order:
 *   insert_locate.h        the walk to a cell in conflict with the new site q;
 *   insert_region.h        the conflict region grown from it, and its boundary;
 *   insert_link_hashed.h   linking the new cells through a table of ridges keyed
 *                          on their vertex indices (placing, furthest-site hull);
 *   insert_link_turning.h  linking by turning around each ridge through the dead
 *                          cells (Delaunay, a boundary of more than 255 vertices);
 *   insert_link_numbered.h linking by the boundary's own numbering of its vertices
 *                          (Delaunay in 4D and up);
 *   insert_link_twins.h    linking by oriented twin ridges (2D, 3D), and the 3D
 *                          cone built and linked in one pass (cone_local);
 *   insert_cone.h          the cone of new cells, and the choice of a linking;
 *   insert_tour_2d.h       the 2D Delaunay cavity as an Euler tour, linked as it
 *                          is walked.
 * Which path runs for which mode, dimension and cavity: docs/engine.md, "Paths of
 * the insertion loop".
 *
 * Linking, in general: the new cell N made from boundary facet (c, k) meets, across
 * its facet opposite vertex v_j (j != k), the new cell made from the other boundary
 * facet that contains the ridge R = c \ {v_k, v_j} (the cavity's boundary is a
 * closed pseudo-manifold: every ridge is in exactly two boundary facets). Each
 * linking finds that other facet its own way.
 */
#include "engine.h"
#include "lh_exact.h"

#include <string.h>

#if !defined(LH_T_NAME) || !defined(LH_T_FINITE_CONFLICT) || !defined(LH_T_FINITE_CONFLICT2) || \
    !defined(LH_T_PLACING) || !defined(LH_T_ORIENT) || !defined(LH_T_PREPARE)
#error "insert_impl.h: define LH_T_NAME, LH_T_FINITE_CONFLICT(2), LH_T_PLACING, LH_T_ORIENT and LH_T_PREPARE first"
#endif

/* LH_T_NV(t): the vertices of a cell of store t, d + 1; a constant when the
 * dimension is, so that every `const int nv = LH_T_NV(t);` folds away. */
#ifdef LH_T_D
#define LH_T_NV(t) (LH_T_D + 1)
#else
#define LH_T_NV(t) ((t)->nv)
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

/* x appended to the scratch array *arr (grown when full); 0 when memory runs out. */
static inline int push(lh__tds *t, lh_index **arr, size_t *cap, size_t *len, lh_index x)
{
    if (*len < *cap) {
        (*arr)[(*len)++] = x;
        return 1;
    }
    return lh__tds_push_slow(t, arr, cap, len, x);
}

/* The position of x in a row of nv entries holding it once, branch-free. */
static inline int row_pos(const lh_index *row, int nv, lh_index x)
{
    int p = 0;
    for (int i = 1; i < nv; i++) p += i * (row[i] == x);
    return p;
}

/* The home slot of a ridge key in the ridge table (Fibonacci hashing), before the
 * mask of lh__ridge_slots. */
static inline size_t ridge_slot(uint64_t key) { return (size_t)((key * UINT64_C(0x9e3779b97f4a7c15)) >> 40); }

#include "insert_locate.h"
#include "insert_region.h"
#include "insert_link_hashed.h"
#include "insert_link_turning.h"
#include "insert_link_numbered.h"
#include "insert_link_twins.h"
#include "insert_cone.h"
#if !defined(LH_T_D) || LH_T_D == 2
#include "insert_tour_2d.h"
#endif

/* Inserts e->q from `start`, a cell in conflict with it: the 2D tour for a
 * Delaunay insertion in 2D (unless the test knob hashed_ridges asks for the general
 * path), else the general cavity (insert_cone.h). */
static LH__ALWAYS_INLINE lh_status insert_cavity(lh__eng *e, lh_index start)
{
#if !defined(LH_T_D) || LH_T_D == 2
    return LH_T_NV(&e->tds) == 3 && e->inside_conflicts && !e->dbg.hashed_ridges ? cavity_insert_2(e, start)
                                                                                 : cavity_insert(e, start);
#else
    return cavity_insert(e, start);
#endif
}

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
        st = c >= 0 ? insert_cavity(e, c) : c == -1 ? LH_OK : LH__RETRY; /* -1: not a vertex */
        if (st == LH_ERR_NOMEM && lh__par_refill(p, t)) {
            t->round++; /* fresh marks; the cells taken so far stay held */
            st = insert_cavity(e, c);
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
    LH_T_PREPARE(e);
    for (size_t i = 0; i < count && st == LH_OK; i++) {
        e->q = list ? list[i] : (lh_index)(first + i);
        lh_index c = locate(e);
        if (c < 0) continue; /* inside the current hull: not a vertex (placing modes) */
        st = insert_cavity(e, c);
        if (st == LH_OK) e->hint = e->tds.fresh[0];
    }
    lh__pred_count_filtered(e->pred, e->filtered);
    e->filtered = 0;
    return st;
}
#endif

#undef HOLD
#undef MARK
#undef SET_MARK
#undef LH_T_NV
