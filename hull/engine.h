/*
 * engine.h — lifthull's incremental engine, one code path for every dimension.
 *
 * The engine triangulates R^d + {LH__INF} with cells of d+1 vertices (hull/tds.h):
 * a finite cell is a d-simplex of sites, stored positively oriented; an infinite
 * cell joins a facet of the convex hull to LH__INF and is "positively oriented" in
 * that putting a point beyond the facet in LH__INF's place gives orient_d > 0. So
 * the infinite cells carry the convex hull, and every cell has d+1 neighbours.
 *
 * Which cells a new site q conflicts with is the caller's choice, through one test
 * on finite cells, handed in:
 *   - an infinite cell conflicts when q is strictly beyond its facet (orient_d > 0);
 *     when q lies on the facet's hyperplane it conflicts exactly when the finite
 *     cell across the facet does (CGAL's rule), so no flat cell ever appears;
 *   - a finite cell conflicts when the caller's test says so: a function
 *     (finite_conflict, run by the generic loop, insert_generic.c) or a test
 *     compiled inline into the caller's own builds of the loop (insert, insert_par:
 *     insert_impl.h is a template), which read conflict_sign and conflict_eb.
 * With neither, no finite cell conflicts: a placing triangulation, whose infinite
 * cells are the convex hull (qconvex's job); sites inside the current hull are not
 * inserted. With inside_conflicts the cell containing q always conflicts. lift/
 * hands in its test and gets Delaunay triangulations (lift/dt.h); lift/flat.c
 * passes its own test in a k-flat.
 *
 * Steps: sites ordered (order.c: Hilbert radix sort, exact duplicates merged, BRIO
 * rounds), an initial simplex of d+1 affinely independent sites (exact), then for
 * each site a walk to a conflicting cell and a cavity insertion (tds.c).
 */
#ifndef LH_ENGINE_H
#define LH_ENGINE_H

#include "lh_alloc.h"
#include "lifthull.h"
#include "tds.h"
#include "threads.h"

#define LH__ENGINE_MAX_DIM LH_ORIENT_MAX_DIM

/* A hot helper inlined whatever the compiler's size heuristics say (the insertion
 * loop's predicates, insert_orient.h, whose switches on a run-time d look large). */
#if defined(__GNUC__) || defined(__clang__)
#define LH__ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define LH__ALWAYS_INLINE inline
#endif

/* Hints to fetch *p for reading, or for writing (nothing without GCC or Clang). */
#if defined(__GNUC__) || defined(__clang__)
#define LH__PREFETCH(p) __builtin_prefetch(p)
#define LH__PREFETCH_W(p) __builtin_prefetch(p, 1)
#else
#define LH__PREFETCH(p) ((void)(p))
#define LH__PREFETCH_W(p) ((void)(p))
#endif
enum { LH__AHEAD = 16 }; /* iterations of a gather loop between a prefetch and its use */

/* Whether the finite cell with vertices v (positively oriented) conflicts with site q. */
typedef int (*lh__finite_conflict_fn)(void *user, const lh_index *v, lh_index q);

struct lh__eng;
/* An insertion loop (insert_impl.h): inserts vertices list[0..count-1], or
 * first..first+count-1 when list is NULL. */
typedef lh_status (*lh__insert_fn)(struct lh__eng *e, size_t first, size_t count,
                                   const lh_index *list);
/* What a parallel worker's insertion returns when it met a cell that another worker
 * holds (hull/parallel.h): nothing was changed, the site is left for later. Not an
 * lh_status the API returns. */
#define LH__RETRY ((lh_status)-1000)
/* BRIO rounds (order.c); lh__eng.round_end marks them in the insertion order. */
#define LH__BRIO_ROUNDS 24
struct lh__par;

/* Knobs and counters for the tests only: they steer the engine onto paths that
 * large inputs take, at small sizes, and count how often one ran. Zero: the
 * paths every computation takes. They never change the output. */
struct lh__eng_debug {
    size_t par_scratch;   /* a worker's cavity bound in boundary facets (0:
                             parallel.c's), small to make workers defer sites */
    size_t par_blocks;    /* blocks of new cells a phase hands out (0: as many
                             as the store holds), few to make workers stop */
    int hashed_ridges;    /* link new cells as large n does where packed keys
                             fit (insert_link_hashed.h; turning, not twins or
                             the 2D tour, in 2D and 3D), to exercise those
                             paths at small n */
    size_t turned;        /* out: sequential insertions whose new cells were
                             linked by turning (insert_link_turning.h) */
};

typedef struct lh__eng {
    /* The input and options, set by lh__eng_init and the caller before building. */
    lh_allocator alloc;
    int d, nv;
    size_t n;
    const double *xyz; /* n*d sites, the caller's */
    lh_index *dup;     /* n, the caller's: filled with the site each one merges into */
    lh_pred *pred;
    int pred_shared;   /* 1: pred is the caller's (lh__eng_init_shared), not freed here */
    lh__finite_conflict_fn finite_conflict;
    void *user;
    lh__insert_fn insert; /* a loop with the caller's conflict test inline, or NULL:
                             lh__eng_insert_generic with finite_conflict */
    lh__insert_fn insert_par; /* the same loop for a worker of a parallel phase
                                 (hull/parallel.c), or NULL: no parallel phases */
    int threads;          /* lh_options.threads, resolved: the parallel phases'
                             workers and the shared loops' threads (1: one) */
    int conflict_sign;    /* for an inline conflict test (insert): the sign of its
                             predicate that means conflict */
    int inside_conflicts; /* 1: the cell containing q always conflicts (Delaunay);
                             0: a site inside the current hull is not inserted */
    void (*progress)(void *user, size_t done, size_t total); /* lh_options */
    void *progress_user;

    /* The state of the computation. */
    const double *site; /* the coordinates of vertex v are site + v*d: while
                          lh__eng_build runs, site_copy (the distinct sites in
                          insertion order; vertex v is the caller's order[v],
                          mapped back at the end) */
    double *site_copy;
    size_t ndup;
    lh__tds tds;
    lh_index *order;   /* distinct sites in insertion order */
    size_t norder;
    size_t round_end[LH__BRIO_ROUNDS]; /* end of each BRIO round in order[] */
    lh_index q, hint;     /* the site being inserted; the cell its walk starts from */
    uint64_t rng;
    double lo[LH__ENGINE_MAX_DIM];   /* per coordinate, the sites' minimum and     */
    double span[LH__ENGINE_MAX_DIM]; /* fl(max - min): Hilbert keys (order.c), the
                                       static filters' bounds (insert_orient.h)  */
    int integer;          /* every coordinate of the sites an integer */
    size_t par_sites, par_deferred; /* sites given to parallel workers, and those
                                       they left to the sequential pass */
    size_t par_stopped;   /* workers stopped early (out of blocks, or no cell to
                             start from), over all phases */

    /* Scratch of one insertion loop (a parallel worker has its own lh__eng). */
    struct lh__par *par;  /* a worker's rounds and deferred sites (NULL: sequential) */
    double orient_eb;     /* orient_d's static filter bound (insert_orient.h), and */
    double conflict_eb;   /* an inline conflict test's, set per insertion call    */
    int orient_exact;     /* orient's, the conflict test's static filter exact: */
    int conflict_exact;   /* its bound is 0 and a 0 from it an exact zero       */
    uint64_t filtered;    /* predicate calls settled by inline filters, not yet
                             added to pred's counters */
    const double *pts[LH__ENGINE_MAX_DIM + 2]; /* predicate arguments, reused */

    struct lh__eng_debug dbg; /* the tests' knobs */
} lh__eng;

/* order.c: cell x[0..d-1] of a grid of 2^bits per side (d bits <= 64) turned in
 * place into the transpose of its index along the Hilbert curve: bit b of x[j] is
 * bit b d + d - 1 - j of the index. */
void lh__hilbert_transpose(uint64_t *x, int d, int bits);

/* The caller's site i. */
static inline const double *lh__eng_input(const lh__eng *e, size_t i)
{
    return e->xyz + i * (size_t)e->d;
}

/* The coordinates of vertex v while building (insertion-order copy: sites close in
 * space are close in memory). */
static inline const double *lh__eng_site(const lh__eng *e, lh_index v)
{
    return e->site + (size_t)v * (size_t)e->d;
}

static inline uint64_t lh__rng_next(uint64_t *s) /* xorshift64* (Vigna 2016) */
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return *s * UINT64_C(2685821657736338717);
}

/* Validates (d, n, xyz, opt) for a computation in dimension lo..hi. */
lh_status lh__eng_check_args(int d, int lo, int hi, size_t n, const double *xyz,
                             const lh_options *opt);
#define LH__DEFAULT_SEED UINT64_C(0x5eed) /* lh_options.seed's default */

/* Sets up e (no cells yet) over the caller's sites; dup must hold n entries; the
 * seed comes from opt (NULL: the default). */
lh_status lh__eng_init(lh__eng *e, const lh_allocator *alloc, int d, size_t n,
                       const double *xyz, lh_index *dup, const lh_options *opt);
/* As lh__eng_init with the default options, but e works with the caller's predicate
 * context instead of a new one: for the engines a computation builds one per face
 * (hull/faces.c), so that each costs no context of its own. pred must outlive e and
 * not be used by another thread meanwhile; its counters gather e's work. */
void lh__eng_init_shared(lh__eng *e, const lh_allocator *alloc, int d, size_t n,
                         const double *xyz, lh_index *dup, lh_pred *pred);
void lh__eng_release(lh__eng *e);
/* order.c: duplicates merged into e->dup, insertion order in e->order. */
lh_status lh__eng_order(lh__eng *e);
/* order.c: moves d+1 affinely independent sites to the front of e->order; returns
 * the affine dimension of the distinct sites (-1 if none). */
int lh__eng_initial_simplex(lh__eng *e);
/* order.c: whether pts[k] is outside the affine hull of pts[0..k-1] in R^d. */
int lh__affine_independent(lh_pred *pred, int d, const double *const *pts, int k);
/* order.c: the first k coordinates J (increasing; subsets in bit-mask order) on which
 * pts[0..k] project to a simplex of nonzero volume; 0 if none (then pts[0..k] are
 * affinely dependent). */
int lh__independent_coords(lh_pred *pred, int d, const double *const *pts, int k, int *J);
/* All of the above, then every site inserted. LH_ERR_DEGENERATE when the sites
 * span less than R^d (*affdim tells the dimension). Afterwards the cells hold the
 * caller's site indices. */
lh_status lh__eng_build(lh__eng *e, lh_index cells_hint, int *affdim);
/* The cells_hint of a convex hull of n sites: 4n + 256, at most 4 * 10^6 (the store
 * grows past it by doubling), so the cast never wraps. */
static inline lh_index lh__hull_cells_hint(size_t n)
{
    return (lh_index)(n < 1000000 ? 4 * n + 256 : 4000000);
}

/* order.c: lexicographic order of sites, ties by index; ctx is an lh__lex (for
 * lh__sort_idx). */
typedef struct lh__lex {
    const double *xyz;
    int d;
} lh__lex;
int lh__lex_cmp(const void *ctx, lh_index a, lh_index b);

/* insert_generic.c: the insertion loop with d a runtime value and the conflict
 * test e->finite_conflict. */
lh_status lh__eng_insert_generic(lh__eng *e, size_t first, size_t count, const lh_index *list);
/* parallel.c: inserts order positions at..e->norder-1 as lh__eng_build's loop does,
 * splitting the larger BRIO rounds among e->threads workers (e->insert_par). */
lh_status lh__eng_insert_parallel(lh__eng *e, size_t at);

/* Inserts the vertices list[0..count-1] (distinct, none a vertex yet; coordinates
 * in e->site) into the cells of e->tds, which must hold a triangulation made as
 * lh__eng_build's: LH__INF at position 0 of every infinite cell. */
lh_status lh__eng_insert(lh__eng *e, const lh_index *list, size_t count);

/* v: the infinite cell over the facet of finite cell s (positively oriented) that
 * drops vertex k: LH__INF at position 0 (an invariant the cavity insertion keeps),
 * oriented by an odd permutation of s with LH__INF in place of vertex k. */
static inline void lh__eng_make_infinite(lh_index *v, const lh_index *s, int nv, int k)
{
    for (int j = 0; j < nv; j++) v[j] = s[j];
    if (k > 0) { /* exchange positions 0 and k */
        v[k] = v[0];
        v[0] = LH__INF;
    } else { /* exchange positions 1 and 2 */
        v[0] = LH__INF;
        v[1] = s[2];
        v[2] = s[1];
    }
}

/* Whether cell c is finite. */
int lh__eng_finite(const lh__eng *e, lh_index c);
/* The convex hull facets: d site indices each, ordered so that orient_d(facet, p) > 0
 * for p outside, in canonical order (see lh__canonical), sorted. Allocates *out.
 * They are read from the infinite cells at rows first..top-1 (0: all; after
 * lh__tds_sort_cells, its count: they are all after the finite cells). */
lh_status lh__eng_hull_facets(lh__eng *e, lh_index first, lh_index **out, size_t *count);

/* hull.c: the hooks handle h allocates with (for queries on it: lh_hull_measures). */
const lh_allocator *lh__hull_allocator(const lh_hull *h);

/* Union-find: the root of x's set, halving the path on the way. */
static inline lh_index lh__uf_find(lh_index *parent, lh_index x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* faces.c: after lh__eng_build, ext[i] (n entries) = whether the caller's site i is
 * a corner (an extreme point) of the hull, exactly: a vertex of the engine's hull
 * that lies on a flat face without being its corner is not. *flat = whether two
 * adjacent hull facets are coplanar (if not, every facet is a face of the hull,
 * every vertex a corner and the triangulation of the boundary unique). */
lh_status lh__eng_hull_corners(lh__eng *e, uint8_t *ext, int *flat);
/* faces.c: calls fn(user, a, b), a < b, for every edge {a, b} of the hull of n
 * sites of R^d (d >= 1) that span R^d and are in convex position (each a corner:
 * cospherical sites are), some edges more than once; pred for small polygons. */
typedef void (*lh__edge_fn)(void *user, lh_index a, lh_index b);
lh_status lh__hull_edges(const lh_allocator *a, lh_pred *pred, int d, size_t n, const double *xyz,
                         lh__edge_fn fn, void *user);

/* Canonical order of an oriented tuple of m distinct entries: increasing, then the
 * last two exchanged if sorting was an odd permutation, so that the orientation is
 * kept. rank[j] is entry j's position in that order: its rank among the entries,
 * with ranks m-2 and m-1 exchanged when the inversions are odd. Branch-free (the
 * entries of a tuple are in random order: a sort's branches would mispredict). */
static inline void lh__canonical_ranks(const lh_index *v, int m, int *rank)
{
    int inv = 0;
    for (int j = 0; j < m; j++) {
        int r = 0;
        for (int i = 0; i < m; i++) r += v[i] < v[j];
        for (int i = 0; i < j; i++) inv += v[i] > v[j];
        rank[j] = r;
    }
    const int odd = inv & 1;
    for (int j = 0; j < m; j++) { /* & (a cmov), not && (a branch) */
        const int flip = odd & (rank[j] >= m - 2), other = 2 * m - 3 - rank[j];
        rank[j] = flip ? other : rank[j];
    }
}

/* call(m) with m a constant when it is 3 to 6 (a simplex in 2D to 5D, the
 * dimensions lift/ compiles the loop for: the hot loops over a tuple unroll), else call(m). */
#define LH__WITH_CONSTANT_M(m, call) \
    do {                             \
        switch (m) {                 \
        case 3: call(3); break;      \
        case 4: call(4); break;      \
        case 5: call(5); break;      \
        case 6: call(6); break;      \
        default: call(m); break;     \
        }                            \
    } while (0)

/* The tuple v (m entries) rewritten in canonical order. */
static inline void lh__canonical(lh_index *v, int m)
{
    int rank[LH__ENGINE_MAX_DIM + 1];
    lh_index c[LH__ENGINE_MAX_DIM + 1];
    for (int j = 0; j < m; j++) c[j] = v[j];
    lh__canonical_ranks(c, m, rank);
    for (int j = 0; j < m; j++) v[rank[j]] = c[j]; /* scattered into v itself, as in cell_sort.c */
}
/* canon.c: sorts count tuples of m site indices (< n) lexicographically from v into
 * out; order[i] = index in v of out's tuple i. Returns 0 on no memory. */
int lh__sort_tuples(const lh_allocator *a, const lh_index *v, int m, size_t count,
                    size_t n, lh_index *out, lh_index *order);
/* canon.c: sorts the tuples (m site indices each, nonnegative) of t within each
 * bucket [start[k], start[k+1]), k < nb, lexicographically, moving payload[] along
 * (insertion sort for small buckets, merge sort for large ones). The tuples of a
 * bucket share their first entry (comparisons start at the second). 0 on no memory. */
int lh__sort_buckets(const lh_allocator *a, lh_index *t, lh_index *payload, const size_t *start,
                     size_t nb, int m);

#endif
