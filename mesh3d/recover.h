/*
 * recover.h — boundary recovery by flips, then splitting (docs/meshing3d.md).
 *
 * The constraints are the facets, each recovered as a whole (a patch: the region its
 * triangulation in its plane covers), and the segments: the facets' polygon edges and
 * the PLC's free segments. Each round loads the Delaunay tetrahedralization of the
 * points so far (lift/: lh_delaunay, then lh_tri_insert), exact and unique under the
 * lifted perturbation, into a mutable mesh (tets.c) and recovers what it can by flips
 * (recover_flip.c), each checked exactly, so every stage works on a valid
 * tetrahedralization. Then what flips left is split:
 *   - a subsegment (two consecutive points of a segment's chain) that is not an edge
 *     is split: at a point of the mesh lying exactly on it, else at a new point —
 *     its midpoint, or, next to an input vertex, the point at a power-of-two distance
 *     from that vertex between a third and two thirds of the subsegment (Shewchuk's
 *     concentric shells, "Tetrahedral mesh generation by Delaunay refinement", SoCG
 *     1998, sec. 3.2: splits near a small input angle stop);
 *   - when every subsegment is an edge, a facet that is not a union of mesh faces on
 *     its points (recover_faces.c) has its longest uncovered subsegment split, or,
 *     when its faces stop short inside it, a point put in it.
 * With -Y (no Steiner point on the boundary) the split points are then taken off the
 * boundary again, each replaced by points inside (recover_suppress.c).
 * Splitting alone gives a conforming Delaunay tetrahedralization (Murphy, Mount, Gable
 * 2001; Cohen-Steiner, Colin de Verdière, Yvinec 2004 prove such splitting ends for
 * any PLC; this version does not protect every acute facet angle, and caps Steiner
 * points instead), so recovery ends where splitting would. Each round's split points
 * depend only on the mesh and the constraints (segments run from the point first in
 * coordinates), so the result does not depend on input order.
 */
#ifndef LH_RECOVER_H
#define LH_RECOVER_H

#include "t3.h"

#include <stdint.h>

/* recover_flip.c: the edges removed for one constraint that are kept out. */
#define T3_GONE 64

/* tets.c: at most this many tets replaced or made at once. */
#define T3_FLIP_TETS 12

/* A segment: the straight line between input points a and b, split into a chain. */
typedef struct t3_seg {
    lh_index a, b;   /* endpoints, a before b in coordinates (lexicographic)      */
    lh_index parent; /* output segment number: the PLC's segments, then the
                            facets' polygon edges                                     */
    lh_index marker; /* the segment's marker, else its first facet's             */
} t3_seg;

/* A point of a chain: point p at parameter t of segment seg (a + t (b - a)); in the
 * queue of new points, seg < 0 means a point inside patch -1 - seg, and T3_INTERIOR a
 * point inside the domain (quality refinement's). */
#define T3_INTERIOR (-(lh_index)LH_INDEX_MAX)

typedef struct t3_node {
    lh_index seg, p;
    double t;
} t3_node;

typedef struct t3_ctx {
    lh_allocator al;
    lh_error *err;
    const lh_plc *g;
    const lh_tetmesh_options *opt;
    lh_pred *pred;
    lh_tri *dt;          /* the Delaunay tetrahedralization of every point so far  */
    size_t n_input;      /* points of the PLC                                      */
    size_t n, n_cap;     /* points so far: the PLC's, then the Steiner points      */
    double *xyz;         /* 3n                                                      */
    int unit_exp;        /* 2^unit_exp bounds every input coordinate (lengths are
                               measured in that unit)                                 */
    const lh_index *dup; /* lh_tri_duplicate_of (valid until the next insertion)   */
    /* constraints */
    size_t tri_count;
    lh_index *tri;       /* 3 per facet triangle, representative point indices     */
    lh_index *tri_facet; /* the facet of each                                      */
    lh_index *tri_seg;   /* 3 per triangle: edge k (corner k to k+1)'s segment, -1
                               for a diagonal inside a facet (no constraint)          */
    size_t seg_count;
    t3_seg *seg;
    lh_index *seg_key; /* 3 per segment: its endpoints (smaller index first) and
                               its number, sorted: edge to segment lookup             */
    /* patches: what must be a union of mesh faces — a facet, as its triangles */
    size_t patch_count;
    lh_index *patch_first;   /* patch_count + 1 offsets into patch_tri                 */
    lh_index *patch_tri;     /* triangle indices                                        */
    lh_index *patch_facet;   /* the facet of each patch                                 */
    signed char *patch_axis; /* +-(1 + the coordinate dropped to project the patch to
                               2D), signed as the patch's normal along it             */
    /* Steiner points inside patches: pnode sorted by patch (seg holds the patch) */
    size_t pnode_count, pnode_cap;
    t3_node *pnode;
    lh_index *pnode_first; /* patch_count + 1                                        */
    /* chains: nodes sorted by (seg, t); chain of segment s: node_first[s] .. [s+1] */
    size_t node_count, node_cap;
    t3_node *node;
    lh_index *node_first; /* seg_count + 1                                          */
    /* the round's new points */
    size_t new_count, new_cap;
    double *new_xyz;   /* 3 per new point                                        */
    t3_node *new_node; /* where each goes (p < 0 until numbered)                 */
    /* stars: the tetrahedra around each vertex, rebuilt after each insertion */
    lh_index *star_first; /* n + 1                                                   */
    lh_index *star;
    lh_index *stamp; /* per point, -1 or a mark (recover_faces.c)              */
    size_t stamp_cap;
    lh_index *vbuf, *fbuf, *ebuf; /* scratch: points, faces, edges                    */
    size_t vcap, fcap, ecap;
    /* what changed: a constraint whose points all kept their stars since it was found
       in the mesh is still in it (Bowyer-Watson: a tet destroyed or made by a batch of
       insertions has only points that end up beside an inserted one) */
    uint32_t *changed; /* per point: the round its star last changed (0: never)      */
    size_t changed_cap;
    uint32_t *seg_seen, *patch_seen; /* 1 + the round a segment, a patch was last
                                        found whole in the mesh (0: not)             */
    /* the faces a patch was last found whole with, as sorted triples (still its cover
       while patch_seen holds: no point of it changed since) */
    lh_index *cover; /* the triples, patch after patch as found               */
    size_t cover_count, cover_cap;
    lh_index *cover_first; /* per patch: its triples' first index in cover, or -1    */
    lh_index *cover_len;   /* per patch: their number                                */
    size_t steiner;        /* Steiner points inserted                                */
    size_t refine_points;  /* of them, quality refinement's (refine.c)               */
    size_t over_volume;    /* tets over their volume bound when refinement stopped   */
    size_t over_size;      /* tets larger than the sizing asks, then                 */
    struct t3_left *left;  /* the tets refinement left over its bounds (leftover.c)   */
    size_t left_count;
    size_t rounds;
    /* the mesh the constraints are sought in (tets.c): the Delaunay tetrahedralization
       after the round's insertions, then changed by flips (recover_flip.c) */
    lh_index *tv, *tn; /* 4 per tet: points (orient_3 > 0), the neighbour opposite each
                          (-1: none); tv[4 t] = -1 for a replaced tet */
    size_t tet_count, tet_cap;
    lh_index *vtet; /* per point: a tet holding it, or -1 */
    size_t vtet_cap;
    lh_index *tmark, tgen; /* per tet: visit marks (lh__t3_mesh_mark) */
    lh_index *sbuf;        /* scratch: a star */
    size_t scap;
    lh_index *lock_first; /* n + 1 offsets into lock: per point p, the other ends q > p
                             of the subsegments from it, which flips keep */
    lh_index *lock;
    size_t lock_cap, lock_first_cap;
    size_t flips;   /* flips made this round */
    int journal;    /* whether replacements are journaled, for undoing */
    lh_index *jbuf; /* the journal (tets.c) */
    size_t jlen, jcap;
    lh_index made[T3_FLIP_TETS]; /* the tets the last replacement made */
    lh_index *rbuf;              /* scratch of a replacement: its outer faces and slots */
    size_t rcap;
    int made_count;
    size_t flip_budget;         /* edge removals the current constraint may still try */
    int improving; /* edge removals must make a better worst shape than they take out */
    int flip_bounded;   /* the flips after refinement: no tet one makes may be over the
                           volume bound flip_volume (0: none) or the sizing's size    */
    double flip_volume;
    lh_index gone[2 * T3_GONE]; /* the edges the current constraint's removals took out,
                                   which its later ones do not make again */
    int gone_count;
    lh_index *todo; /* subsegments flips have not recovered yet, 2 each */
    size_t todo_cap;
    lh_index *seg_order, *patch_order; /* segments, patches by their points' coordinates:
                                          the order flips take them in */
    lh_index *pmark, pgen;             /* per point: pgen when it is a point of the patch flips
                              are recovering (recover_flip.c) */
    size_t pmark_cap;
    lh_index *sides; /* a cache of orient_3(facet triangle, point): 3 per slot (the
                        triangle, the point, the sign; triangle -1: empty), sides_cap
                        slots, a power of 2; points never move, so it stays valid */
    size_t sides_cap;
    lh_index *xlock; /* edges of patches flips recovered, which flips keep: a hash set
                        of point pairs (p < q; -1: empty), xlock_cap slots, a power of 2 */
    size_t xlock_cap, xlock_count;
} t3_ctx;

/* Point i's coordinates. */
static inline const double *lh__t3_pt(const t3_ctx *c, lh_index i)
{
    return c->xyz + 3 * (size_t)i;
}

/* Points compared in coordinate order (lexicographic). */
static inline int lh__t3_cmp_xyz(const double *x, const double *y)
{
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* Points v[0..n) (a handful) put in coordinate order, in place. */
static inline void lh__t3_sort_points(const t3_ctx *c, lh_index *v, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && lh__t3_cmp_xyz(lh__t3_pt(c, v[j]), lh__t3_pt(c, v[j - 1])) < 0;
             j--) {
            lh_index x = v[j];
            v[j] = v[j - 1];
            v[j - 1] = x;
        }
}

/* Sorts three indices in place (faces compared as sets). */
static inline void lh__t3_sort3(lh_index *f)
{
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2 - a; b++)
            if (f[b] > f[b + 1]) {
                lh_index x = f[b];
                f[b] = f[b + 1];
                f[b + 1] = x;
            }
}

/* recover.c: err->message = "LINE: " (when line > 0) + the formatted text; returns st. */
lh_status lh__t3_say(t3_ctx *c, lh_status st, size_t line, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* Room for need elements of size bytes in *buf (capacity *cap, in elements), its
 * first count kept; it grows to twice need and more. */
lh_status lh__t3_grow(t3_ctx *c, void **buf, size_t *cap, size_t count, size_t need, size_t size);
/* Room for need indices in *buf (capacity *cap), its contents kept. */
lh_status lh__t3_room(t3_ctx *c, lh_index **buf, size_t *cap, size_t need);
/* The rounds, until every constraint is in the mesh. */
lh_status lh__t3_recover(t3_ctx *c);
/* Drops what rounds cache of constraints found whole: the next checks them afresh. */
void lh__t3_forget(t3_ctx *c);
/* The constraints checked in the mesh as it is (through the rounds' caches), and the
 * rounds run only when one is missing. */
lh_status lh__t3_recover_check(t3_ctx *c);

/* plc_check.c: the PLC's arrays, indices and coordinates. */
lh_status lh__t3_plc_check(t3_ctx *c);

/* recover_setup.c: the triangles (on representative points, checked, without
 * repeats) and the segments: the triangles' edges and the PLC's segments. */
struct lh__facet_tris;
lh_status lh__t3_constraints(t3_ctx *c, const struct lh__facet_tris *ft);
/* Exact: p, q, r on one line. */
int lh__t3_collinear(lh_pred *pred, const double *p, const double *q, const double *r);

/* recover_star.c: the stars of the current mesh; edge and face membership. */
lh_status lh__t3_stars(t3_ctx *c);
int lh__t3_has_edge(const t3_ctx *c, lh_index p, lh_index q);
int lh__t3_has_face(const t3_ctx *c, lh_index a, lh_index b, lh_index d);

/* recover_split.c: queues a split of subsegment (i, i+1) of segment s's chain. */
lh_status lh__t3_split(t3_ctx *c, lh_index s, size_t i);
/* The chain of segment s as point indices: a, its nodes' points in order, b; written
 * into buf as far as cap allows; returns the chain's length. */
size_t lh__t3_chain(const t3_ctx *c, lh_index s, lh_index *buf, size_t cap);
/* Calls f(c, p, q, s, i, arg) for every subsegment p q (p < q): subsegment i of
 * segment s's chain; stops at the first status that is not LH_OK. c->vbuf holds the
 * chain meanwhile. */
typedef lh_status (*t3_subsegment_fn)(t3_ctx *c, lh_index p, lh_index q, lh_index s, size_t i,
                                      void *arg);
lh_status lh__t3_each_subsegment(t3_ctx *c, t3_subsegment_fn f, void *arg);
/* Room for m more points in c->xyz. */
lh_status lh__t3_xyz_room(t3_ctx *c, size_t m);
/* Inserts the queued split points, merges them into the chains, rebuilds the stars. */
lh_status lh__t3_commit(t3_ctx *c);
/* Marks as changed this round the points first_new.. and the points of their stars,
 * and the points of the m nodes. */
lh_status lh__t3_mark_changed(t3_ctx *c, size_t first_new, const t3_node *nodes, size_t m);
/* Whether a point of segment s's chain changed since round r. */
int lh__t3_seg_changed(const t3_ctx *c, size_t s, uint32_t r);
/* Room for m more nodes in *nodes (count of them now, capacity *cap). */
lh_status lh__t3_node_room(t3_ctx *c, t3_node **nodes, size_t count, size_t *cap, size_t m);
/* Per queued point (c->new_*), the first queued point with p < 0 and its
 * coordinates (itself when none, and for a point with p >= 0); idx: scratch of 2
 * new_count. */
void lh__t3_queue_firsts(t3_ctx *c, lh_index *first, lh_index *idx);
/* Sorts the chains' nodes (by segment, then parameter) and rebuilds node_first. */
lh_status lh__t3_chains_sort(t3_ctx *c);

/* recover_suppress.c: once every constraint is in the mesh, each Steiner point on a
 * segment or inside a facet taken off the boundary, its star refilled from its own
 * points or new points inside: in the sectors outside the domain (carved: out[t] for
 * tet t, or NULL) always, in the domain when allow_new (-Y). With allow_new,
 * LH_ERR_STEINER_LIMIT naming the first that cannot be. *taken: the points taken off;
 * when any, compacts the mesh and rebuilds the stars. */
lh_status lh__t3_suppress(t3_ctx *c, int allow_new, const unsigned char *out, size_t *taken);
/* recover.c: lh__t3_suppress with -Y's allow_new, then every constraint checked again. */
lh_status lh__t3_recover_suppress(t3_ctx *c, const unsigned char *out, size_t *taken);

/* Queues new point x (p < 0) or existing point p for segment seg at parameter t, or
 * (seg < 0) inside patch -1 - seg. */
lh_status lh__t3_queue(t3_ctx *c, lh_index seg, double t, lh_index p, const double x[3]);
/* The segment of edge p q, or -1. */
lh_index lh__t3_seg_of(const t3_ctx *c, lh_index p, lh_index q);

/* recover_faces.c: *ok = 1 if patch k is a union of mesh faces; else *ok = 0 and,
 * when split is set, a split queued: its longest uncovered subsegment, else a point
 * inside it where its faces stop short. */
lh_status lh__t3_patch_check(t3_ctx *c, size_t k, int split, int *ok);
/* Exact, in the projection dropping axis ax: g in triangle t (3 points; boundary
 * included). */
int lh__t3_in_triangle(t3_ctx *c, const lh_index *t, const double *g, int ax);
/* Whether a point of patch k (corners, chains, points inside) changed since round r. */
int lh__t3_patch_changed(const t3_ctx *c, size_t k, uint32_t r);
/* The faces covering patch k (once lh__t3_patch_check said ok), as sorted triples:
 * those it was found whole with, else gathered again; *faces is valid until the next
 * call. */
lh_status lh__t3_patch_cover(t3_ctx *c, size_t k, const lh_index **faces, size_t *count);

/* tets.c: the mesh (t3_ctx.tv, tn). At most this many tets replaced or made at once. */
/* Loads the Delaunay tetrahedralization. */
lh_status lh__t3_mesh_load(t3_ctx *c);
/* Room for need tets (tv, tn, tmark) and for every point in vtet. */
lh_status lh__t3_mesh_room(t3_ctx *c, size_t need);
/* A fresh visit mark for tmark. */
lh_index lh__t3_mesh_mark(t3_ctx *c);
/* The tets holding point v into c->sbuf, *count of them. */
lh_status lh__t3_mesh_star(t3_ctx *c, lh_index v, size_t *count);
/* Replaces the nold tets old by the nnew tets nv (any orientation; made positive), which
 * the caller has checked fill the same region; *ok = 0 and nothing changed when one of
 * them is flat. New tet i takes old[i]'s slot when i < nold, else slot tet_count + i -
 * nold (tet_count before the call); old tets beyond nnew die. c->made lists the new tets
 * when there are at most T3_FLIP_TETS (a flip's), else none. */
lh_status lh__t3_mesh_replace(t3_ctx *c, const lh_index *old, int nold, lh_index (*nv)[4], int nnew,
                              int *ok);
/* Undoes the journaled replacements back to journal length mark. */
void lh__t3_mesh_undo(t3_ctx *c, size_t mark);
/* Drops the replaced tets' slots, renumbering the rest in order. */
void lh__t3_mesh_compact(t3_ctx *c);
/* orient_3 of tet t with its corner j replaced by q: > 0 when q is on t's side of
 * the face opposite j. */
int lh__t3_mesh_side(t3_ctx *c, size_t t, int j, const double *q);
/* The tet holding q (closed), -1 outside the mesh: a walk from tet t0. */
lh_index lh__t3_mesh_walk(t3_ctx *c, lh_index t0, const double *q);

/* recover_flip.c: recovers by flips the subsegments that are not edges of the mesh
 * and, when every one is, the facets (recover_flip_patch.c) (Si 2015, sec. 3; Shewchuk,
 * "Updating and constructing constrained Delaunay and constrained regular
 * triangulations by flips", SoCG 2003); then compacts the mesh and rebuilds the stars. */
lh_status lh__t3_flip(t3_ctx *c);
/* Exact orientation of the four points. */
int lh__t3_orient4(t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e);
/* A tet's shape in floating point, for choosing among valid tets only (never for
 * validity): its volume over the cube of the root of its squared edges' sum (0 when
 * flat); the edge vectors scaled by a power of two first, so that the figure is the
 * same at every scale. */
double lh__t3_shape(const t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e);
/* Flips and refills make no tet flatter than this shape: a few ulps of a rounded
 * Steiner point would make such a tet out of points that lie on one facet. It only
 * steers choices; the mesh is valid either way. */
#define T3_SLIVER 0x1p-40
/* Edge removals a constraint's try may make (recover_flip.c). */
#define T3_REMOVALS 300
/* Starts a constraint's try: an empty journal, a budget of edge removals, no edges
 * gone. */
void lh__t3_try_begin(t3_ctx *c, size_t budget);
/* Edge p q of tet t as a candidate for removal, in c->fbuf (3 each), *ne of them. */
lh_status lh__t3_candidate(t3_ctx *c, lh_index t, lh_index p, lh_index q, size_t *ne);
/* Removes the first of the ne candidates in coordinate order that edge removal takes
 * out, trying every one without lowering its ring's degree, then one level deeper,
 * and so on (iterative deepening); *done says whether one went. */
lh_status lh__t3_remove_first(t3_ctx *c, size_t ne, int *done);
/* Locks edge p q for the rest of the round's flips. */
lh_status lh__t3_lock(t3_ctx *c, lh_index p, lh_index q);
/* Whether edge p q is locked: a subsegment, or an edge of a patch flips recovered. */
int lh__t3_locked(const t3_ctx *c, lh_index p, lh_index q);

/* The locks made afresh: the subsegments of the chains as they are, no other edge. */
lh_status lh__t3_locks(t3_ctx *c);
/* lh__t3_shape of the four points taken in coordinate order: the same figure
 * whatever order they come in. */
double lh__t3_shape_sorted(const t3_ctx *c, lh_index a, lh_index b, lh_index d, lh_index e);
/* Mesh improvement (improve.c): edge p q of tet t removed when its ring has a
 * triangulation whose worst tet shape beats the worst of the tets around it now;
 * never a locked edge. *done says whether. */
lh_status lh__t3_improve_edge(t3_ctx *c, lh_index t, lh_index p, lh_index q, int *done);
/* The 2-3 flip of face j of tet t when the three tets it makes all have a better shape
 * than the worse of the two it takes out; never a face whose three edges are locked. */
lh_status lh__t3_improve_face(t3_ctx *c, lh_index t, int j, int *done);

/* recover_flip_patch.c: recovers patch k by flips, when every subsegment is an edge. */
lh_status lh__t3_flip_patch(t3_ctx *c, size_t k);

#endif
