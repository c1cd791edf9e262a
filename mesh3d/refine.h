/*
 * refine.h — quality refinement of the recovered mesh (docs/meshing3d.md): Shewchuk's
 * Delaunay refinement ("Tetrahedral mesh generation by Delaunay refinement", SoCG
 * 1998; Si, TetGen, ACM TOMS 41(2) 2015, sec. 5). A tetrahedron of the domain whose
 * radius-edge ratio or volume is over its bound is split at its circumcentre, unless
 * that point encroaches a subsegment (lies inside its diametral sphere) or a subface
 * (inside its equatorial sphere) or lies beyond a subface: then that subsegment is
 * split (recover.h: at its midpoint, or on Shewchuk's concentric shells next to an
 * input vertex), or that subface at its circumcentre — unless that encroaches a
 * subsegment, which is split instead. A round takes each bad tetrahedron whose
 * circumsphere's conflict region is disjoint from those taken before it (an
 * independent set, so no two new points crowd each other), worst first, and inserts
 * its points into the mesh as it stands, by Bowyer-Watson bounded by the walls
 * (refine_insert.c), so each round's mesh is valid and conforming; near small input
 * angles the tets whose shortest edge is seditious are left.
 */
#ifndef LH_REFINE_H
#define LH_REFINE_H

#include "carve.h"
#include "tet_geom.h"

/* Points v[0..n) (n <= 4) as coordinates, in coordinate order, into p. */
static inline void lh__t3_sorted_points(const t3_ctx *c, const lh_index *v, int n, const double **p)
{
    for (int i = 0; i < n; i++) p[i] = lh__t3_pt(c, v[i]);
    lh__t3_sort_corners(p, n);
}

/* The largest conflict region looked at: a point with a bigger one (far from its
 * tet in a mesh flips made far from Delaunay) is left this round. Whether a region
 * is that big is of the geometry alone, as the region is. */
#define T3_REGION_MAX 4096

/* A tetrahedron over its bound: tet t, how much (the larger of its ratios to the
 * bounds), its circumcentre. */
typedef struct t3_bad {
    lh_index t;
    double key;
    double cc[3];
    double spacing; /* no point that splits it nearer another (refine_split.c) */
    int why;        /* its split's outcome: T3_QUEUED, T3_CLAIMED or lh_leftover_why */
    int over;       /* the bounds it is over: 1 radius-edge, 2 volume, 4 size      */
} t3_bad;

/* A split's outcome besides lh_leftover_why's: its point queued, or left because a
 * point taken this round holds its region. */
enum { T3_QUEUED = 100, T3_CLAIMED };

typedef struct t3_refine {
    t3_ctx *c;
    t3_domain d;
    size_t d_wall_cap, d_label_cap; /* entries d.wall, d.label have room for */
    int flipped;  /* whether a round's flips ran since the mesh was last made from the
                     Delaunay tetrahedralization (the first looks at every face) */
    double ratio; /* the radius-edge bound, 0 none */
    /* half the distance of the input's closest points: no point refinement adds for
       the radius-edge bound is nearer another (where a volume bound v applies, nor
       nearer than cbrt(v) / 4); the spacing of the bad tet being split */
    double spacing, spacing_now;
    int cut;                /* a conflict region of the bad tet being split was too big */
    int why;                /* the outcome of the split being made (t3_bad.why)          */
    lh_index *claim, round; /* per tet: the round a taken point's region holds it */
    lh_index *claim_by;     /* per claimed tet: the point taken (in taken) */
    double *taken;          /* the round's points taken: x y z, insertion radius */
    size_t taken_count, taken_cap;
    /* subsegments: a hash of (p, q, segment, chain index), p < q, 4 per slot (-1:
       empty); sub_cap slots, a power of 2 */
    lh_index *sub;
    size_t sub_cap, sub_count;
    lh_index *facet_patch; /* per facet: its patch, or -1 */
    lh_index *reg;         /* a conflict region: its tets */
    size_t reg_cap, reg_count;
    t3_bad *bad;
    size_t bad_count, bad_cap;
    size_t over_ratio, over_volume, over_size; /* tets over the bounds at the last scan */
    double *kept_xyz;                          /* the round's queue, kept to insert again in part */
    t3_node *kept_node;
    size_t kept_count, rollbacks;
    /* points whose insertion recovery could not settle around: 3 each, never queued
       again */
    double *refused;
    size_t refused_count, refused_cap;
    /* tets whose split was given up (4 points sorted, why: 5 per slot, -1 empty), a
       hash set of gave_up_cap slots, a power of 2 */
    lh_index *on_seg; /* per point: the segment it lies inside (a chain's node), or -1 */
    lh_index *gave_up;
    size_t gave_up_count, gave_up_cap;
} t3_refine;

/* The slot of subsegment p q (p < q) in r->sub: its entry, else the empty slot where
 * it goes. */
static inline lh_index *lh__t3_sub_slot(const t3_refine *r, lh_index p, lh_index q)
{
    size_t h = ((size_t)p * 0x9e3779b1u ^ (size_t)q * 0x85ebca6bu) & (r->sub_cap - 1);
    while (r->sub[4 * h] >= 0 && !(r->sub[4 * h] == p && r->sub[4 * h + 1] == q))
        h = (h + 1) & (r->sub_cap - 1);
    return r->sub + 4 * h;
}

/* refine.c: subsegment p q (p < q or not) of segment s added to r->sub, which has
 * room (lh__t3_sub_reserve). */
void lh__t3_sub_put(t3_refine *r, lh_index p, lh_index q, lh_index s);
/* refine.c: room in r->sub for m more subsegments. */
lh_status lh__t3_sub_reserve(t3_refine *r, size_t m);

/* refine.c: the volume bound of a tet of region reg (a domain label): the global one,
 * or the region's when smaller (-a); 0 none. */
double lh__t3_volume_bound(const t3_ctx *c, lh_index reg);

/* refine.c: the rounds, until no tet of the domain is over its bound or no point can
 * be placed; c's statistics then count what is left over. */
lh_status lh__t3_refine(t3_ctx *c);

/* improve.c: flips that raise the worst shape among the tets of domain d over the
 * radius-edge bound ratio (0: none) or under the dihedral bound (radians), each
 * replacing tets of one region by better ones of the same region, no wall or
 * subsegment taken out; *flips of them. When any, the mesh is compacted and its stars
 * rebuilt (d no longer applies). */
lh_status lh__t3_improve(t3_ctx *c, const t3_domain *d, double ratio, double dihedral,
                         size_t *flips);

/* leftover.c: the bad tets as refinement leaves them, each with why it was left, kept
 * in c (by their corners' coordinates) for lh__t3_leftovers. */
lh_status lh__t3_left_record(t3_ctx *c, const t3_bad *bad, size_t count);
/* leftover.c: m's tets over their bounds (lh_tetmesh_leftovers), each with why refinement
 * left it and the nearest small input angle. */
lh_status lh__t3_leftovers(t3_ctx *c, lh_tetmesh *m);

/* refine_split.c: whether x lies inside tet t's circumsphere, exactly and under the
 * symbolic perturbation the Delaunay tetrahedralization uses (lh_insphere_sos), so
 * that insertion in the mesh decides cospherical points as lh_tri_insert does. */
int lh__t3_in_sphere(t3_ctx *c, size_t t, const double *x);
/* refine_insert.c: the round's queue inserted into the mesh as it stands, each point
 * by Bowyer-Watson bounded by the walls (those it cannot be are refused); the
 * constraints are then checked, and recovered only when one is missing. */
lh_status lh__t3_refine_insert(t3_refine *r);

/* refine_insert.c: room in r->d for need tets. */
lh_status lh__t3_domain_room(t3_refine *r, size_t need);
/* refine_flip.c: Lawson's flips of the faces of tets first.. that are not locally
 * Delaunay (no wall, one region), then of those the flips make. */
lh_status lh__t3_refine_flips(t3_refine *r, size_t first);

/* refine_split.c: point x is never queued again. */
lh_status lh__t3_refuse(t3_refine *r, const double *x);
/* refine_split.c: queues the point that splits bad tet b (its circumcentre, or the
 * subsegment's or subface's point it encroaches), unless its conflict region meets one
 * taken this round or the point is refused (-Y: nothing on the boundary); r->why says
 * which. */
lh_status lh__t3_refine_split(t3_refine *r, const t3_bad *b);

#endif
