/*
 * m2.h — the mutable 2D triangle mesh behind constrained Delaunay triangulation and
 * quality refinement (mesh2d/m2_*.c, cdt_*.c, refine.c).
 *
 * Encoding (the engine's, in 2D): triangle t has vertices v[3t..3t+2] in
 * counterclockwise order (orient_2 > 0, exactly), nb[3t+k] the triangle across the
 * edge opposite v[3t+k] (-1: none — the domain's boundary), sg[3t+k] the subsegment
 * lying on that edge (-1: unconstrained). Both triangles beside a subsegment name it.
 * Edge k of t runs from v[3t+(k+1)%3] to v[3t+(k+2)%3]. A dead triangle has v[3t] = -1
 * and sits on the free list (chained through nb[3t]).
 *
 * Subsegments: the pieces of input segments that are edges of the mesh; subsegment s
 * joins sv[2s], sv[2s+1] and belongs to input segment sp[s] (whose marker it has).
 * Points: the input vertices first, with their indices, then Steiner points; pseg[p]
 * is the parent of the subsegment a Steiner point was put on (an input segment >= 0,
 * or a boundary edge of the mesh being refined, <= -2: refine.h's LH__COVER_PARENT),
 * -1 for a free Steiner point and for input vertices, LH__M2_REMOVED (below every
 * parent) for a Steiner point removed again, which the output leaves out; vt[p] is a
 * triangle incident to p (-1 while p is not a vertex: merged duplicates, points in
 * removed regions, removed Steiner points).
 *
 * Invariants kept by every operation: every live triangle is positively oriented;
 * neighbour links are symmetric; every unconstrained interior edge is locally
 * Delaunay (not strictly inside the opposite circumcircle) — so the mesh is a
 * constrained Delaunay triangulation (Chew 1989) of its points and subsegments.
 */
#ifndef LH_M2_H
#define LH_M2_H

#include "lifthull.h"
#include "lh_alloc.h"

typedef struct lh__m2 {
    lh_allocator al;
    lh_pred *pred;
    /* points */
    size_t np, cap_p;
    double *xy;          /* 2 per point                                       */
    lh_index *pseg;      /* input segment of a Steiner point on a segment, or -1 */
    lh_index *vt;        /* an incident live triangle, or -1                  */
    int attr_count;
    double *attr;        /* attr_count per point (interpolated for Steiner points) */
    lh_index *pmark;     /* per point: boundary marker                        */
    size_t n_input;      /* points 0..n_input-1 are the input vertices        */
    /* triangles */
    size_t nt, cap_t, live;
    lh_index *v, *nb, *sg;
    lh_index free_head;
    double *tattr;       /* per triangle: regional attribute (domain pass), or NULL */
    double *tarea;       /* per triangle: area bound, <= 0 none (domain pass), or NULL */
    uint32_t *mark;      /* per triangle: visit epochs                        */
    uint32_t epoch;
    /* subsegments */
    size_t ns, cap_s;
    lh_index *sv, *sp;
    uint32_t *smul;      /* input segments lying along the subsegment (overlaps: > 1) */
    /* input segments' markers (n of them), borrowed from the caller's PSLG */
    const lh_index *seg_marker;
    lh_index walk_hint;
    double lens;         /* encroachment: 0 diametral circles, else cos^2 2t (lenses) */
    int split_crossings; /* segment insertion: a crossing gets a vertex, not an error */
    const lh_index *in_seg; /* the input segments (2 each), borrowed: an overlap follows
                               a chain bent by crossings (cdt_insert.c, along_chain) */
    struct lh__cover *cover; /* an existing mesh to refine, whose union is the domain */
    size_t crossings;    /* vertices put at crossings                                */
} lh__m2;

/* Growth and storage (m2_store.c). Each returns LH_OK or LH_ERR_NOMEM. */
lh_status lh__m2_init(lh__m2 *m, const lh_allocator *al, size_t n, const double *xy,
                      int attr_count, const double *attr, const lh_index *marker);
void lh__m2_free(lh__m2 *m);
lh_status lh__m2_add_point(lh__m2 *m, const double p[2], lh_index *out);
lh_status lh__m2_reserve_tris(lh__m2 *m, size_t more);
lh_index lh__m2_new_tri(lh__m2 *m); /* after lh__m2_reserve_tris */
void lh__m2_kill_tri(lh__m2 *m, lh_index t);
lh_status lh__m2_add_subseg(lh__m2 *m, lh_index a, lh_index b, lh_index parent,
                            lh_index *out);
uint32_t lh__m2_new_epoch(lh__m2 *m);

static inline const double *lh__m2_pt(const lh__m2 *m, lh_index p) { return m->xy + 2 * (size_t)p; }
/* orient_2 and the incircle test (< 0: d strictly inside circle abc, abc ccw), exact. */
int lh__m2_orient(const lh__m2 *m, lh_index a, lh_index b, lh_index c);
int lh__m2_orient_pt(const lh__m2 *m, lh_index a, lh_index b, const double *c);
int lh__m2_incircle(const lh__m2 *m, lh_index a, lh_index b, lh_index c, const double *d);

/* The position (0..2) of vertex p in triangle t, or -1. */
static inline int lh__m2_vpos(const lh__m2 *m, lh_index t, lh_index p)
{
    const lh_index *v = m->v + 3 * (size_t)t;
    return v[0] == p ? 0 : v[1] == p ? 1 : v[2] == p ? 2 : -1;
}
/* Whether x -> y runs the way a -> b does, the four points collinear (and x != y,
 * a != b): each coordinate's difference has its exact sign after rounding. */
static inline int lh__m2_same_way(const double *x, const double *y, const double *a, const double *b)
{
    for (int j = 0; j < 2; j++)
        if ((y[j] > x[j]) != (b[j] > a[j]) || (y[j] < x[j]) != (b[j] < a[j])) return 0;
    return 1;
}

/* The triangles around vertex a: counterclockwise from vt[a] until back or at the
 * boundary, then clockwise from vt[a]:
 *     lh__m2_fan f;
 *     for (lh_index t = lh__m2_fan_first(m, &f, a); t >= 0; t = lh__m2_fan_next(m, &f)) */
typedef struct lh__m2_fan {
    lh_index a, t0, t;
    int backward;
} lh__m2_fan;

static inline lh_index lh__m2_fan_first(const lh__m2 *m, lh__m2_fan *f, lh_index a)
{
    f->a = a;
    f->t0 = f->t = m->vt[a];
    f->backward = 0;
    return f->t;
}

/* The position in triangle u of its edge shared with triangle t. */
static inline int lh__m2_npos(const lh__m2 *m, lh_index u, lh_index t)
{
    const lh_index *n = m->nb + 3 * (size_t)u;
    return n[0] == t ? 0 : n[1] == t ? 1 : 2;
}

static inline lh_index lh__m2_fan_next(const lh__m2 *m, lh__m2_fan *f)
{
    const int i = lh__m2_vpos(m, f->t, f->a);
    lh_index n = m->nb[3 * (size_t)f->t + (f->backward ? (i + 2) % 3 : (i + 1) % 3)];
    if (!f->backward && n == f->t0) return -1;
    if (n < 0 && !f->backward) {
        f->backward = 1;
        f->t = f->t0;
        const int j = lh__m2_vpos(m, f->t, f->a);
        n = m->nb[3 * (size_t)f->t + (j + 2) % 3];
    }
    f->t = n;
    return n;
}

/*
 * Cavity retriangulation (m2_cavity.c), the one mechanism behind segment insertion,
 * point insertion and vertex removal: the triangles `dead` are replaced by the triangles `tri`
 * (3 vertices each, counterclockwise; `tsg` 3 subsegment ids each, -1 for none, or
 * NULL). Every edge of a new triangle is linked to the new triangle across it, or
 * to the live triangle that was across the same edge of a dead one (taking that
 * edge's subsegment), or else gets -1. Returns LH_OK or LH_ERR_NOMEM (mesh
 * unchanged).
 */
typedef struct lh__m2_cavity {
    size_t dead_count, dead_cap;
    lh_index *dead;
    size_t tri_count, tri_cap;
    lh_index *tri, *tsg;
    /* scratch: boundary edges (x, y, outside triangle, subsegment, its position
       there, dead triangle: m2_cavity.c) and edge records */
    size_t bnd_count, bnd_cap;
    lh_index *bnd;
    size_t rec_cap;
    lh_index *rec;     /* 3 per record: low vertex, high vertex, who */
    size_t stack_count, stack_cap;
    lh_index *stack;   /* for the callers' searches */
    lh_index *chain[2];/* segment insertion: the vertices left and right of it */
    size_t chain_count[2], chain_cap[2];
    double *reg;       /* scratch: 2 per new triangle, its region's attribute and area
                          bound (m->tattr, m->tarea) while the dead slots are reused */
    size_t reg_cap;
} lh__m2_cavity;

void lh__m2_cavity_free(lh__m2 *m, lh__m2_cavity *c);
lh_status lh__m2_cavity_push_dead(lh__m2 *m, lh__m2_cavity *c, lh_index t);
lh_status lh__m2_cavity_push_tri(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b,
                                 lh_index d, const lh_index sg[3]);
lh_status lh__m2_cavity_apply(lh__m2 *m, lh__m2_cavity *c);
void lh__m2_cavity_clear(lh__m2_cavity *c);
/* The fan case of lh__m2_cavity_apply (m2_cavity.c): every new triangle i is
 * (x, y, p) for one common p, on the boundary edge x->y of dead triangle t at
 * position k recorded by lh__m2_cavity_push_bnd(m, c, t, k) in the same order. */
lh_status lh__m2_cavity_push_bnd(lh__m2 *m, lh__m2_cavity *c, lh_index t, int k);
lh_status lh__m2_cavity_apply_fan(lh__m2 *m, lh__m2_cavity *c);
lh_status lh__m2_stack_push(lh__m2 *m, lh__m2_cavity *c, lh_index t);
/* Grows an array of elements of size esz to hold need (doubling), keeping count;
 * 0 when out of memory. */
int lh__m2_grow_slow(lh__m2 *m, void **arr, size_t count, size_t *cap, size_t need, size_t esz);
static inline int lh__m2_grow(lh__m2 *m, void **arr, size_t count, size_t *cap, size_t need,
                              size_t esz)
{
    return need <= *cap || lh__m2_grow_slow(m, arr, count, cap, need, esz);
}

/* Why a segment could not be inserted (cdt_insert.c). */
typedef struct lh__m2_problem {
    int kind;            /* LH__M2_CROSSING, or 0                                   */
    lh_index seg[2];     /* the input segments involved                             */
    lh_index sub;        /* the subsegment crossed                                  */
} lh__m2_problem;
enum { LH__M2_CROSSING = 1 };

/* Inserts input segment `parent` from vertex a to vertex b (Anglada 1997): the
 * triangles it crosses are replaced by the constrained Delaunay triangulations of
 * the two pseudo-polygons on its sides; vertices lying on it split it. A crossed
 * subsegment: LH_ERR_DEGENERATE with *pb filled, or with m->split_crossings a vertex
 * at the crossing splitting both (cdt_insert.c). */
lh_status lh__m2_insert_segment(lh__m2 *m, lh__m2_cavity *c, lh_index a, lh_index b,
                                lh_index parent, lh__m2_problem *pb);
/* Input segment `parent` runs along subsegment s, a piece of a boundary edge of
 * m->cover: recorded for lh__cover_relabel (cdt_cover.c). LH_OK or LH_ERR_NOMEM. */
lh_status lh__cover_claim(lh__m2 *m, lh_index s, lh_index parent);
/* The triangle holding the edge a->b (a before b counterclockwise), with *pos the
 * edge's index in it; -1 when a->b is not an edge. */
lh_index lh__m2_find_edge(const lh__m2 *m, lh_index a, lh_index b, int *pos);
/* A triangle beside subsegment s (its edge either way round), with *pos the edge's
 * index in it; -1 when s is no edge. */
lh_index lh__m2_find_subseg(const lh__m2 *m, lh_index s, int *pos);

/* The outcome of a point insertion (m2_insert.c). */
enum {
    LH__M2_INSERTED = 0,  /* vertex is the new point                                  */
    LH__M2_DUPLICATE,     /* p is vertex `vertex` already                             */
    LH__M2_OUTSIDE,       /* the walk left the mesh                                   */
    LH__M2_BLOCKED,       /* the walk met subsegment `blocked` first                  */
    LH__M2_ENCROACHES,    /* p is inside the diametral circles of enc[0..enc_count-1],
                             subsegments on the cavity's boundary (check_encroach)     */
    LH__M2_REFUSED        /* the cavity is not star-shaped from p (rounding put p on
                             or beyond a boundary edge): nothing changed              */
};
typedef struct lh__m2_ins {
    int check_encroach;   /* in: refuse p when it encroaches a boundary subsegment    */
    const double *origin; /* in: walk to p in a straight line from this point of the
                             start triangle (NULL: the visibility walk)               */
    int result;           /* out: LH__M2_*                                            */
    lh_index vertex, blocked;
    size_t enc_count, enc_cap;
    lh_index *enc;        /* scratch owned by the caller (lh__free with m->al)        */
} lh__m2_ins;

/* Inserts point p, found by a walk from triangle start; with split >= 0, p goes on
 * subsegment split (a rounded point of it), which becomes a-p (keeping its id) and
 * p-b. Returns LH_OK with r->result, or LH_ERR_NOMEM / LH_ERR_INTERNAL. */
lh_status lh__m2_insert_point(lh__m2 *m, lh__m2_cavity *c, const double *p, lh_index start,
                              lh_index split, lh__m2_ins *r);
int lh__m2_encroaches(const lh__m2 *m, lh_index s, const double *p);

/* Removes free vertex p (a vertex on no subsegment, inside the mesh): its triangles
 * become the constrained Delaunay triangulation of its link, the new triangles are
 * left in c->stack, and pseg[p] = LH__M2_REMOVED. *removed = 0 when p is not such a
 * vertex or the link's triangulation is blocked (m2_remove.c): the mesh is unchanged.
 * Returns LH_OK or LH_ERR_NOMEM / LH_ERR_INTERNAL. */
/* The least lh_index: a parent LH__COVER_PARENT(i) is -(i + 2) for a boundary edge i
 * that has a subsegment id < LH_INDEX_MAX, so always greater. */
#define LH__M2_REMOVED ((lh_index)(-LH_INDEX_MAX - 1))
lh_status lh__m2_remove_vertex(lh__m2 *m, lh__m2_cavity *c, lh_index p, int *removed);
/* Drops the removed Steiner points, renumbering the later ones down (input vertices
 * keep their indices). Returns LH_OK or LH_ERR_NOMEM (mesh unchanged). */
lh_status lh__m2_drop_removed(lh__m2 *m);

/* Build from the Delaunay triangulation of the input vertices (m2_build.c). */
lh_status lh__m2_from_delaunay(lh__m2 *m, lh_tri *dt); /* takes dt's simplex arrays */

/* Point location (m2_locate.c): a triangle whose closed region holds p, found by a
 * walk from `start` that never crosses a subsegment when `stop_at_segments`; then
 * *blocked is the subsegment met (else -1) and the result the triangle before it. */
lh_index lh__m2_locate(lh__m2 *m, lh_index start, const double *p, int stop_at_segments,
                       lh_index *blocked);
/* Every live triangle in turn: the first holding p (closed), or -1. */
lh_index lh__m2_scan(const lh__m2 *m, const double *p);
/* The straight walk from g, inside triangle t, to p (m2_locate.c): the triangle
 * holding p, or the one before the subsegment crossed (*blocked), or -1 outside. */
lh_index lh__m2_walk_line(lh__m2 *m, lh_index t, const double *g, const double *p,
                          lh_index *blocked);

#endif
