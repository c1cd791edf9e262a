/*
 * lifthull.h — the whole public API of lifthull.
 *
 * lifthull computes exact Delaunay triangulations in dimensions 2..8 as the lower
 * convex hull of the sites lifted onto the paraboloid z = |x|^2 (Brown 1979;
 * Edelsbrunner & Seidel 1986). If it is not in this header, it is not API.
 *
 * Conventions that hold for every function below:
 *   - Thread rule: every handle is used by one thread at a time ("one handle per
 *     thread"); distinct handles share nothing, there is no global state.
 *   - Failure: functions that can fail return an lh_status; on failure they free
 *     what they built and leave the caller's arrays untouched.
 *   - Freeing NULL is a no-op; every *_default(NULL) does nothing.
 *   - Points are arrays of doubles; a point in R^k is k consecutive doubles.
 *   - Names: lh_<noun>_<verb> for what acts on a thing (lh_tri_locate,
 *     lh_points_read, lh_vtu_write, lh_delaunay_check); lh_<noun>_<property> for
 *     accessors that only read (lh_tri_simplices, lh_hull_facet_count); a struct is
 *     filled by lh_<noun>_<struct>_get(handle, &out), zeros for a NULL handle
 *     (lh_trimesh_stats_get); options by lh_<options>_default(&opt). The predicates
 *     are named for the predicate (lh_orient, lh_insphere) and the computations that
 *     make a handle for what they compute (lh_delaunay, lh_convex_hull).
 *   - Error detail beyond the status: the functions that can say more than their
 *     status (the readers, the checks, the mesher, lh_coords_validate) take an
 *     lh_error *err as their last parameter. err may be NULL (no detail wanted);
 *     otherwise it is written in full on every return: err->status is the returned
 *     status, err->message one line ("" on success), err->line and err->column the
 *     place in the input (0: none), err->index the item at fault (LH_ERROR_NO_INDEX:
 *     none). Each function's comment says which fields it fills (see lh_error).
 *
 * Coordinate range (the "accepted range"):
 *   Every finite double is accepted, subnormals included: the exact stage of the
 *   predicates is integer arithmetic with no exponent limit, so no square or product
 *   can overflow or underflow there. NaN and +-Inf are rejected by
 *   lh_coords_validate() with LH_ERR_NONFINITE. The floating-point filter is used
 *   only where it is proven correct: when every column of a predicate's matrix has
 *   its largest magnitude within [2^-(900/g), 2^(900/g)] (g the predicate's degree,
 *   k for orient_k and d+2 for insphere_d); outside that band the answer comes from
 *   the exact stage, still correct but slower (see docs/predicates.md).
 */
#ifndef LIFTHULL_H
#define LIFTHULL_H

#include <inttypes.h> /* PRId32, PRId64 (LH_INDEX_PRI) */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h> /* FILE, for the file formats */

#ifdef __cplusplus
extern "C" {
#endif

/* LH_API marks every function of the API: the shared library exports these and
 * nothing else (it is built with hidden visibility). */
#if defined(__GNUC__) || defined(__clang__)
#define LH_API __attribute__((visibility("default")))
#else
#define LH_API
#endif

/* ---- version -------------------------------------------------------------------- */

#define LH_VERSION_MAJOR 0
#define LH_VERSION_MINOR 1
#define LH_VERSION_PATCH 0
#define LH_VERSION_STRING "0.1.0"

/* The library's version as MAJOR*10000 + MINOR*100 + PATCH, at run time. */
LH_API int lh_version_number(void);
/* The library's version as "MAJOR.MINOR.PATCH", at run time (static storage). */
LH_API const char *lh_version_string(void);

/* ---- status codes --------------------------------------------------------------- */

/* X(name, pinned value, message). Values never change once released. */
#define LH_STATUS_LIST(X)                                                          \
    X(LH_OK, 0, "success")                                                         \
    X(LH_ERR_NOMEM, 1, "out of memory")                                            \
    X(LH_ERR_INVALID_ARGUMENT, 2, "invalid argument")                              \
    X(LH_ERR_NONFINITE, 3, "coordinate is NaN or infinite")                        \
    X(LH_ERR_DIMENSION, 4, "dimension out of the supported range")                 \
    X(LH_ERR_TOO_LARGE, 5, "count too large (size arithmetic would overflow)")     \
    X(LH_ERR_DEGENERATE, 6, "sites span a lower-dimensional affine subspace")      \
    X(LH_ERR_IO, 7, "input/output error")                                          \
    X(LH_ERR_PARSE, 8, "malformed input")                                          \
    X(LH_ERR_INTERNAL, 9, "internal consistency check failed")                    \
    X(LH_ERR_INVALID_MESH, 10, "the given triangulation or mesh is not valid")     \
    X(LH_ERR_BUFFER_TOO_SMALL, 11, "output buffer too small")                      \
    X(LH_ERR_CROSSING_SEGMENTS, 12, "input segments cross")                        \
    X(LH_ERR_INTERSECTING_FACETS, 13, "input facets intersect")                    \
    X(LH_ERR_STEINER_LIMIT, 14, "Steiner point limit reached before recovery ended")

typedef enum lh_status {
#define LH_STATUS_ENUM_(name, value, msg) name = value,
    LH_STATUS_LIST(LH_STATUS_ENUM_)
#undef LH_STATUS_ENUM_
} lh_status;

/* A one-line English message for a status (static storage, never NULL; an unknown
 * value gives "unknown status"). */
LH_API const char *lh_status_message(lh_status status);
/* The enumerator's name, e.g. "LH_ERR_NONFINITE" (static storage, never NULL). */
LH_API const char *lh_status_name(lh_status status);

/* ---- error detail ---------------------------------------------------------------- */

#define LH_ERROR_MESSAGE_MAX 512       /* bytes of lh_error.message, its NUL included */
#define LH_ERROR_NO_INDEX ((size_t)-1) /* lh_error.index when no item is at fault    */

/* The detail of a call's outcome, filled by the functions that take an lh_error *err
 * (NULL: not wanted). On success: status LH_OK, message "", line = column = 0, index
 * LH_ERROR_NO_INDEX. On failure status is the returned status and the others are
 * filled as far as the function knows them:
 *   - message: one line without a line end, cut to LH_ERROR_MESSAGE_MAX - 1 bytes; it
 *     may be "" where the status says all (then print lh_status_message(status)).
 *   - line, column: 1-based place in the input (the readers: both; lh_pslg_triangulate:
 *     the line of the item at fault when the PSLG came from a reader, column 0); 0 when
 *     there is none.
 *   - index: lh_coords_validate: the flat index i*d+j of the first coordinate that is
 *     NaN or infinite; LH_ERROR_NO_INDEX otherwise. */
typedef struct lh_error {
    lh_status status;
    size_t line, column;
    size_t index;
    char message[LH_ERROR_MESSAGE_MAX];
} lh_error;

/* ---- indices ------------------------------------------------------------------- */

/* Site, simplex and cell indices in every array of this API. 32 bits by default
 * (half the memory of 64; at most LH_INDEX_MAX - 1 sites); a build configured with
 * -DLH_INDEX_64=ON makes them 64-bit (lifthull_config.h records the choice, so a
 * program compiled against the installed header matches its library; lh_index_bits
 * says at run time what the library was built with). */
#include "lifthull_config.h"
#if LH_INDEX_BITS == 64
typedef int64_t lh_index;
#define LH_INDEX_MAX INT64_MAX
#define LH_INDEX_PRI PRId64
#else
typedef int32_t lh_index;
#define LH_INDEX_MAX INT32_MAX
#define LH_INDEX_PRI PRId32
#endif
/* LH_INDEX_PRI: printf's conversion for an lh_index, as inttypes.h's PRId32/PRId64:
 * printf("%" LH_INDEX_PRI "\n", lh_tri_simplices(t)[0]). */
/* LH_INDEX_BITS of the library (32 or 64). */
LH_API int lh_index_bits(void);

/* ---- memory --------------------------------------------------------------------- */

/* Allocator hooks, per handle. Passing NULL wherever an allocator is asked for
 * means malloc/realloc/free. `user` is handed back to every call. realloc is not
 * used: handles allocate and free only. */
typedef struct lh_allocator {
    void *(*alloc)(void *user, size_t size); /* NULL on failure */
    void (*free)(void *user, void *ptr);     /* ptr may be NULL */
    void *user;
} lh_allocator;

/* ---- input validation ------------------------------------------------------------ */

/* Dimensions the predicates serve. */
#define LH_ORIENT_MAX_DIM 8   /* orient_k, k = 1..8   */
#define LH_INSPHERE_MAX_DIM 8 /* insphere_d, d = 1..8 (8D Delaunay needs it) */

/* Checks n points of dimension d (row-major, n*d doubles) against the accepted
 * range documented at the top of this header. Returns LH_OK, LH_ERR_NONFINITE
 * (err->index the flat index i*d+j of the first offending coordinate, the message
 * naming it), LH_ERR_INVALID_ARGUMENT (xyz NULL with n > 0, or d < 1) or
 * LH_ERR_TOO_LARGE (n*d overflows size_t). err may be NULL. */
LH_API lh_status lh_coords_validate(int d, size_t n, const double *xyz, lh_error *err);

/* ---- exact predicates ------------------------------------------------------------ */

/*
 * Definitions (homogeneous form; rows are points, the column of ones first):
 *
 *   orient_k(p_0..p_k)      = sign det [ 1  p_i ]            i = 0..k,  p_i in R^k
 *                           = sign det [ p_i - p_0 ]          i = 1..k
 *   insphere_d(p_0..p_{d+1}) = sign det [ 1  p_i  |p_i|^2 ]   i = 0..d+1, p_i in R^d
 *                           = orient_{d+1} of the lifted points (p_i, |p_i|^2).
 *
 * So orient_2 > 0 for a counterclockwise triangle and orient_3 > 0 when p_3 lies on
 * the side of the plane p_0 p_1 p_2 towards which (p_1-p_0) x (p_2-p_0) points.
 * When orient_d(p_0..p_d) > 0, insphere_d(p_0..p_d, q) < 0 exactly when q lies
 * strictly inside the circumsphere of p_0..p_d (q's lifted point is below the lifted
 * simplex's hyperplane) and > 0 when strictly outside. The lifted coordinate |p|^2
 * is never rounded: it is formed in exact arithmetic from the coordinates.
 *
 * Evaluation (docs/predicates.md): a semi-static floating-point filter with a
 * proven error bound; when that is uncertain, the same bound against the
 * determinant's granularity (every coordinate a multiple of a known power of two,
 * as on integer grids, so the determinant is too: exact zeros are recognised here);
 * then residues modulo word-sized coprime moduli, which prove the exact zeros of
 * other degenerate input (lattice points on a sphere, say) when the bound allows;
 * only then exact multi-limb integer arithmetic. Each call counts which stage answered
 * (lh_pred_counters).
 *
 * The *_sos variants apply Simulation of Simplicity (Edelsbrunner & Muecke 1990)
 * and never return 0. Every coordinate of every point (and, for insphere, every
 * lifted coordinate) gets its own infinitesimal; a point's infinitesimals are more
 * significant than those of every point that precedes it in the lexicographic order
 * of coordinates, and within a point the lifted coordinate comes first, then
 * x_0, x_1, ... The result is the sign of the determinant of the perturbed matrix,
 * i.e. the answer for one fixed, infinitesimally perturbed copy of the whole point
 * set. Hence the answers of all calls are mutually consistent, they flip under the
 * exchange of two arguments, and they depend only on the points' coordinates — not
 * on their indices or the order of the input. Precondition: the points of one call
 * are pairwise distinct (merge duplicates first); for equal points the answer is
 * still +1 or -1 but breaks ties by argument position.
 *
 * Arguments: `pts` holds k+1 (orient_k) or d+2 (insphere_d) pointers to points of k
 * (resp. d) finite doubles. Dimensions outside 1..LH_ORIENT_MAX_DIM (orient) or
 * 1..LH_INSPHERE_MAX_DIM (insphere) and NULL handles return 0 (and count nothing).
 */
typedef struct lh_pred lh_pred;

/* Creates a predicate context (counters and a scratch arena of about 1 MiB for the
 * exact stage, allocated once here so that no predicate call allocates).
 * alloc may be NULL. Returns LH_OK, LH_ERR_NOMEM or LH_ERR_INVALID_ARGUMENT. */
LH_API lh_status lh_pred_create(const lh_allocator *alloc, lh_pred **out);
LH_API void lh_pred_free(lh_pred *ctx);

LH_API int lh_orient(lh_pred *ctx, int k, const double *const *pts);       /* -1, 0, +1 */
LH_API int lh_orient_sos(lh_pred *ctx, int k, const double *const *pts);   /* -1, +1    */
LH_API int lh_insphere(lh_pred *ctx, int d, const double *const *pts);     /* -1, 0, +1 */
LH_API int lh_insphere_sos(lh_pred *ctx, int d, const double *const *pts); /* -1, +1    */
/* The hyperplane through the d points pts of R^d (d = 1..8), oriented as orient_d:
 * normal (d doubles, unit length) and offset with normal.x + offset > 0 where
 * orient_d(pts[0..d-1], x) > 0 (up to the rounding of the coefficients). Computed
 * from the exact cofactors, each rounded once, then normalised: a few ulps however
 * thin the simplex. Returns 1; 0 for affinely dependent points (normal all 0).
 * The normal is finite for every finite input (cofactors brought to one exponent
 * before the length is taken: the same unit vector at every power-of-two scale);
 * the offset is a distance to the origin, which may pass DBL_MAX for points near
 * it: then it is +-inf here (never nan) — lh_hyperplane_exp gives it exactly. */
LH_API int lh_hyperplane(lh_pred *ctx, int d, const double *const *pts, double *normal,
                         double *offset);
/* lh_hyperplane with the offset as offset * 2^offset_exp: the mantissa in [0.5, 1)
 * (0 with exponent 0 for a plane through the origin), finite for every finite
 * input, relative error a few ulps. Same normal and return value as lh_hyperplane. */
LH_API int lh_hyperplane_exp(lh_pred *ctx, int d, const double *const *pts, double *normal,
                             double *offset, int *offset_exp);
/* The sign of |q - a| - |q - b| for points q, a, b of R^d (d = 1..8): -1 when a is
 * strictly nearer to q, +1 when b is, 0 when they are exactly as near. Filtered,
 * then exact for every finite double (no perturbation: ties are for the caller). */
LH_API int lh_distance_compare(lh_pred *ctx, int d, const double *q, const double *a,
                               const double *b);

/* How often each stage ran since creation or the last reset. */
typedef struct lh_pred_counters {
    uint64_t calls;         /* predicate calls (all four kinds)                      */
    uint64_t filter_exits;  /* answered by the floating-point filter                 */
    uint64_t grid_exits;    /* answered by the filter's bound against granularity    */
    uint64_t residue_exits; /* proven exactly 0 by residues modulo machine words     */
    uint64_t exact_exits;   /* needed the exact integer stage                        */
    uint64_t zero_results;  /* unperturbed answer was an exact 0 (any stage)         */
    uint64_t sos_fast;      /* perturbation decided by one cofactor scan             */
    uint64_t sos_general;   /* perturbation needed the general (rank-based) search   */
} lh_pred_counters;

LH_API void lh_pred_counters_get(const lh_pred *ctx, lh_pred_counters *out);
LH_API void lh_pred_counters_reset(lh_pred *ctx);

/* ---- Delaunay triangulation ------------------------------------------------------ */

/* Dimensions the triangulation serves. */
#define LH_DELAUNAY_MIN_DIM 2
#define LH_DELAUNAY_MAX_DIM 8

/* Options of lh_delaunay. Initialise with lh_options_default(); every field's default
 * is documented beside it. */
typedef struct lh_options {
    const lh_allocator *alloc; /* NULL: malloc/free                                 */
    uint64_t seed;             /* insertion order and walk randomisation; the output
                                  of lh_delaunay does not depend on it (default
                                  0x5eed; lh_convex_hull: see there)                 */
    int furthest_site;         /* lh_delaunay: 1 for the furthest-site Delaunay
                                  triangulation (the upper lifted hull, Qhull's Qu):
                                  its vertices are the convex hull's and every
                                  simplex's circumsphere encloses every site
                                  (default 0)                                        */
    int affine_hull;           /* lh_delaunay: 1 to triangulate sites that span only
                                  a k-flat, 1 <= k < d, within it (k-simplices; see
                                  lh_tri_simplex_dim; k = 1: the segments between
                                  consecutive sites of the line) instead of failing
                                  with LH_ERR_DEGENERATE (default 0)                 */
    int generic_engine;        /* lh_delaunay: 1 to run the engine with the dimension
                                  a runtime value even where a fixed-dimension
                                  build exists (d = 2..5); the output is the same,
                                  only slower: for comparisons (default 0)           */
    void (*progress)(void *user, size_t done, size_t total);
                               /* lh_delaunay, lh_convex_hull: called by the building
                                  thread after every 2^16 sites inserted, with the
                                  sites done and the distinct sites in all (NULL:
                                  none, the default)                                 */
    void *progress_user;       /* handed back to progress (default NULL)            */
    int threads;               /* lh_delaunay (not furthest_site): threads that insert
                                  the sites, each a region of space at a time; 0 or
                                  less: one per online CPU; at most 64 are used. The
                                  output is the same for every value, byte for byte
                                  (default 1)                                        */
} lh_options;

LH_API void lh_options_default(lh_options *opt);

/*
 * lh_delaunay: the Delaunay triangulation of n sites in R^d (d = 2..8), row-major in
 * xyz (n*d doubles; copied, so the array may be freed afterwards).
 *
 * Exact: every decision is an exact predicate (see above). Cospherical sites are
 * resolved by the symbolic perturbation of the lifted coordinates (lifthull.h,
 * predicates), so the result is a proper triangulation — every simplex has positive
 * volume — that depends only on the set of sites: not on their order, not on
 * opt->seed. Every site is a vertex, those on the boundary of the convex hull
 * included (furthest-site: exactly the hull's vertices are). Exact duplicates are
 * merged: the first occurrence is the vertex, lh_tri_duplicate_of maps each site to
 * it.
 *
 * Output, canonical: each simplex lists its d+1 site indices (input numbering) in
 * increasing order except that the last two are exchanged when needed for positive
 * orientation (orient_d > 0); simplices are sorted lexicographically.
 *
 * Returns LH_OK; LH_ERR_DIMENSION (d outside 2..8); LH_ERR_INVALID_ARGUMENT (out or
 * xyz NULL, or an allocator without hooks); LH_ERR_TOO_LARGE (n*d overflows, or more
 * than LH_INDEX_MAX - 1 sites); LH_ERR_NONFINITE (a NaN or infinity: lh_coords_validate
 * names the coordinate); LH_ERR_DEGENERATE (fewer than d+1 distinct sites, or all
 * sites in an affine subspace of dimension < d — lh_coords_affine_dim tells which; with
 * opt->affine_hull only for a single distinct site);
 * LH_ERR_NOMEM. On failure *out is NULL and nothing is leaked.
 */
typedef struct lh_tri lh_tri;
LH_API lh_status lh_delaunay(int d, size_t n, const double *xyz, const lh_options *opt,
                             lh_tri **out);

/* The affine dimension spanned by n sites in R^d (0 for one distinct site, -1 for
 * none), computed exactly; opt as lh_delaunay's (only alloc is used; NULL:
 * defaults); LH_ERR_* as lh_delaunay for bad arguments. */
LH_API lh_status lh_coords_affine_dim(int d, size_t n, const double *xyz, const lh_options *opt,
                                      int *dim);

/*
 * lh_tri_insert: adds m sites (m*d doubles, copied) to t; they get the indices
 * n..n+m-1 after t's n sites. The result is exactly lh_delaunay's for all n+m sites
 * (same options), byte for byte: a new site equal to an earlier one is merged into
 * it; furthest-site triangulations stay furthest-site. Each call rebuilds the
 * engine's cells from t's arrays in O(n) memory passes, then inserts, so insert in
 * batches. Every array pointer obtained from t before the call is invalid after a
 * successful one. Returns LH_OK; LH_ERR_INVALID_ARGUMENT (t NULL, or xyz NULL with
 * m > 0); LH_ERR_TOO_LARGE; LH_ERR_NONFINITE (lh_coords_validate names the
 * coordinate, counted from the first new site); LH_ERR_NOMEM. On failure t is
 * unchanged.
 */
LH_API lh_status lh_tri_insert(lh_tri *t, size_t m, const double *xyz);
/*
 * lh_tri_insert_unordered: lh_tri_insert for a caller that inserts in rounds and
 * reads, between them, only what does not depend on the order of the simplices (an
 * edge's or a face's presence, a vertex's simplices as a set): the same
 * triangulation, but the simplices in no particular order and each simplex's sites
 * in no particular order either (positively oriented, as the canonical form is),
 * which skips the canonical form's sort per call. Simplex numbers (the neighbours,
 * lh_tri_vertex_simplex, lh_tri_locate's answers) refer to that order.
 * lh_tri_sort (or an lh_tri_insert) puts them in canonical order again; a no-op on a
 * sorted t. Statuses as lh_tri_insert.
 */
LH_API lh_status lh_tri_insert_unordered(lh_tri *t, size_t m, const double *xyz);
LH_API lh_status lh_tri_sort(lh_tri *t);

LH_API int lh_tri_dim(const lh_tri *t);             /* d, coordinates per site               */
/* k, the dimension of the simplices: d, or with lh_options.affine_hull the affine
 * dimension of the sites. Below, "k-simplex" arrays have k+1 entries per simplex.
 * When k < d, orientation means orient_k of the sites projected to k coordinates
 * that are one to one on the sites' affine hull (the same for the whole handle). */
LH_API int lh_tri_simplex_dim(const lh_tri *t);
LH_API size_t lh_tri_site_count(const lh_tri *t);   /* n, duplicates included                */
LH_API size_t lh_tri_count(const lh_tri *t);        /* finite simplices                      */
/* (k+1) * lh_tri_count indices into the sites, canonical order (see lh_delaunay). */
LH_API const lh_index *lh_tri_simplices(const lh_tri *t);
/* (k+1) * lh_tri_count: neighbour j of simplex s is across the facet opposite its
 * j-th vertex; -1 across the convex hull. */
LH_API const lh_index *lh_tri_neighbors(const lh_tri *t);
/* Convex hull facets: lh_tri_hull_count facets of k site indices each, ordered so that
 * orient_k(facet, p) > 0 for points p strictly outside the hull (k = 1: the two end
 * sites of the line, which have no orientation). */
LH_API size_t lh_tri_hull_count(const lh_tri *t);
LH_API const lh_index *lh_tri_hull_facets(const lh_tri *t);
/* Per site: one simplex incident to it (-1 for a merged duplicate, or, furthest-site,
 * for a site that is not a vertex). */
LH_API const lh_index *lh_tri_vertex_simplex(const lh_tri *t);
/* Per site: the index of the earlier equal site it was merged into (itself if none). */
LH_API const lh_index *lh_tri_duplicate_of(const lh_tri *t);
LH_API size_t lh_tri_duplicate_count(const lh_tri *t); /* sites merged into an earlier one */
/* How often each predicate stage ran for t (lh_pred_counters): the whole lh_delaunay
 * run (the fixed-dimension engines' inline filters included), then every query and
 * insertion since. All zero for t NULL. */
LH_API void lh_tri_pred_counters_get(const lh_tri *t, lh_pred_counters *out);
LH_API void lh_tri_free(lh_tri *t);

/*
 * lh_delaunay_check: exact validity check of a triangulation given as sites and
 * simplices (any simplex order, any vertex order): every simplex has positive volume
 * after orienting it; every facet is shared by at most two simplices; every interior
 * facet is locally Delaunay (the opposite vertex is not strictly inside the other
 * simplex's circumsphere); the boundary is locally convex; the simplices' total
 * volume equals the convex hull's, exactly, so they tile it once (local conditions
 * alone admit coverings wound twice); every site is a vertex or an exact duplicate
 * of one. opt: only its allocator is used (NULL: malloc). Returns LH_OK,
 * LH_ERR_NOMEM, or LH_ERR_INVALID_MESH with a one-line reason in err->message (err
 * may be NULL; no line or index); LH_ERR_INVALID_ARGUMENT for a NULL array with a
 * nonzero count or a bad allocator; LH_ERR_TOO_LARGE, with the reason in
 * err->message, for n or count beyond what lh_index and size_t can count (the check's
 * sizes would wrap around).
 */
LH_API lh_status lh_delaunay_check(int d, size_t n, const double *xyz, size_t count,
                                   const lh_index *simplices, const lh_options *opt, lh_error *err);
/* The same for a handle, also verifying its neighbour and hull arrays; for a
 * furthest-site triangulation the conditions are reversed (every interior facet
 * locally furthest-site Delaunay; sites that are not vertices inside the hull). A
 * failed condition is the library's fault here: LH_ERR_INTERNAL with the reason in
 * err->message (err may be NULL). */
LH_API lh_status lh_tri_check(const lh_tri *t, lh_error *err);

/*
 * lh_tri_complex: the Delaunay complex — simplices whose circumspheres coincide
 * (neighbours whose opposite vertex is exactly cospherical, transitively) merged
 * into one cell, as Qhull's qdelaunay reports by default (without Qt). Cell c has the
 * site indices vertices[offsets[c] .. offsets[c+1]-1], increasing; cells are sorted
 * lexicographically by those lists. Computed on the first call and kept by the
 * handle (the pointers stay valid until lh_tri_free). Returns LH_OK, LH_ERR_NOMEM or
 * LH_ERR_INVALID_ARGUMENT.
 */
LH_API lh_status lh_tri_complex(lh_tri *t, size_t *count, const lh_index **offsets,
                                const lh_index **vertices);
/* cell[s] (lh_tri_count entries): the cell of lh_tri_complex that simplex s belongs
 * to; kept by the handle as lh_tri_complex's lists. The Voronoi diagram's vertices are
 * the cells' circumcentres (each cell's simplices share theirs); two sites share a
 * Voronoi ridge of full dimension d-1 exactly when they share an edge of the complex.
 * Returns LH_OK, LH_ERR_NOMEM or LH_ERR_INVALID_ARGUMENT. */
LH_API lh_status lh_tri_complex_cells(lh_tri *t, const lh_index **cell);
/* The edges of the Delaunay complex (the 1-faces of its cells): *count pairs i < j in
 * *edges (2 each), sorted; exactly the pairs of sites whose Voronoi regions share a
 * face of dimension d-1 (a diagonal of a grid square is no edge). Kept by the handle
 * as lh_tri_complex's lists. Returns LH_OK, LH_ERR_NOMEM or LH_ERR_INVALID_ARGUMENT. */
LH_API lh_status lh_tri_complex_edges(lh_tri *t, size_t *count, const lh_index **edges);

/* Where a query point lies in a triangulation. */
typedef struct lh_location {
    lh_index simplex;   /* the simplex whose closed region contains q, or -1 outside  */
    lh_index hull_facet; /* outside: the nearest hull facet (index into
                           lh_tri_hull_facets), -1 inside                            */
    double distance;    /* outside: Euclidean distance from q to the hull, else 0    */
    double bary[LH_DELAUNAY_MAX_DIM + 1];
                        /* inside: q's barycentric coordinates in the simplex (k+1,
                           in lh_tri_simplices order; k = lh_tri_simplex_dim);
                           outside: those of the nearest point of the hull in the
                           facet (k, in facet order)                                */
} lh_location;

/*
 * lh_tri_locate: locates q (d doubles) by a visibility walk from simplex `hint` (any
 * simplex index, or -1). Inside or outside is decided exactly (orient_d); a point on
 * the hull's boundary is inside. A point on a facet shared by several simplices (or
 * at a vertex) is reported in the one with the smallest index among those containing
 * it, whatever the hint: the answer depends on q alone. Barycentric coordinates and
 * distances are computed in floating point. When k < d (see lh_tri_simplex_dim) q
 * must lie exactly in the sites' affine hull. Returns LH_OK, LH_ERR_INVALID_ARGUMENT
 * (t, q or out NULL, or q off that affine hull), LH_ERR_NONFINITE or LH_ERR_NOMEM
 * (a point shared by more than 64 simplices needs memory). Not const: it
 * uses the handle's predicate context (one thread per handle).
 */
LH_API lh_status lh_tri_locate(lh_tri *t, const double *q, lh_index hint, lh_location *out);

/* ---- Voronoi diagram, nearest site, interpolation ---------------------------------- */

/*
 * lh_tri_circumcenters: the Voronoi vertices, dual to the simplices: d doubles per
 * simplex s (lh_tri_simplices order), the centre of the sphere through its k+1
 * vertices (in their k-flat when k < d). Computed in floating point from the exact
 * triangulation (a linear solve relative to the simplex's first vertex: relative
 * error a small multiple of the machine epsilon times the simplex's condition), on
 * the first call, and kept by the handle (valid until lh_tri_free or lh_tri_insert).
 * The Voronoi region of site i is the convex hull of the centres of the simplices
 * incident to it, unbounded exactly when i is a vertex of the convex hull; its ridge
 * with site j is dual to the Delaunay edge ij. Returns LH_OK, LH_ERR_NOMEM or
 * LH_ERR_INVALID_ARGUMENT.
 */
LH_API lh_status lh_tri_circumcenters(lh_tri *t, const double **centers);
/* Simplex s's circumcentre as c * 2^e (d doubles c, and *e): the same construction
 * as lh_tri_circumcenters, whose coordinates are +-inf where a centre's pass DBL_MAX
 * (sites near DBL_MAX, a thin simplex on the hull); c is computed on the sites scaled
 * by 2^-e, so it stays finite there (NaN only where lh_tri_circumcenters' is: an
 * exact zero pivot in the floating-point solve). Returns LH_OK or
 * LH_ERR_INVALID_ARGUMENT (t, c or e NULL, or s >= the number of simplices). */
LH_API lh_status lh_tri_circumcenter_exp(const lh_tri *t, size_t s, double *c, int *e);

/*
 * lh_tri_nearest: the site nearest to q (d doubles): a greedy walk along Delaunay
 * edges from a vertex of the simplex lh_tri_locate finds (hint as there), every
 * distance comparison exact (lh_distance_compare). Among sites exactly equally near, the
 * smallest index is returned (all of them are vertices of one Delaunay cell, so a
 * walk over the ties finds it); never a merged duplicate. Returns LH_OK,
 * LH_ERR_INVALID_ARGUMENT (t, q or site NULL; or a furthest-site handle; or, when
 * k < d, q off the sites' affine hull), LH_ERR_NONFINITE or LH_ERR_NOMEM.
 */
LH_API lh_status lh_tri_nearest(lh_tri *t, const double *q, lh_index hint, lh_index *site);

/*
 * lh_tri_natural_coords: Sibson's natural-neighbour coordinates of q (Sibson 1980,
 * "A vector identity for the Dirichlet tessellation"), d = 2 or 3 with k == d: the
 * sites whose Voronoi regions lose volume when q is inserted, each weighted by the
 * volume it loses over the volume of q's new region. Writes at most `cap` (site,
 * weight) pairs, sites increasing, and their number in *count; the weights are
 * positive and sum to 1, and sum(weight_i * site_i) = q up to rounding (measured:
 * ~1e-13 relative; worse, up to ~1e-4, only next to hull facets whose circumradius
 * is ~1e12 times the sites' spacing). The result does not depend on the hint. A q
 * exactly at a site gives that site with weight 1. A q on the hull's boundary (its
 * region unbounded) gets the barycentric coordinates in the hull facet holding it:
 * in 2D that is the limit from inside; in 3D it is the limit only when the facet is
 * the one hull triangle in its plane (where several coplanar hull triangles tile a
 * face, the limit is the 2D Sibson coordinates within that face, not computed here).
 * cap may be 0 with sites and weights NULL, to ask for the count. Returns LH_OK;
 * LH_ERR_INVALID_ARGUMENT (NULL arguments, furthest-site handle, or q outside the
 * hull: *count = 0); LH_ERR_DIMENSION (d or k not 2 or 3); LH_ERR_BUFFER_TOO_SMALL (more
 * than cap natural neighbours: *count is the number needed, nothing written);
 * LH_ERR_NONFINITE; LH_ERR_NOMEM.
 */
LH_API lh_status lh_tri_natural_coords(lh_tri *t, const double *q, lh_index hint, size_t cap,
                                       lh_index *sites, double *weights, size_t *count);

typedef enum lh_interp_method {
    LH_INTERP_LINEAR = 0,  /* barycentric in the simplex containing q (scipy's
                              LinearNDInterpolator)                               */
    LH_INTERP_NATURAL = 1, /* Sibson's natural neighbours, d = 2, 3 (above)        */
    LH_INTERP_NEAREST = 2  /* the value of the nearest site (lh_tri_nearest)       */
} lh_interp_method;

/*
 * lh_tri_interpolate: values given at the sites (channels doubles per site, in input
 * order; a merged duplicate's values are ignored, its representative's are used),
 * interpolated at m query points q (m*d doubles) into out (m*channels doubles).
 * Queries outside the convex hull get NaN for LINEAR and NATURAL (scipy's default
 * fill value). Linear interpolation reproduces every affine function, and natural
 * neighbours too, up to rounding. Each query's walk starts where the previous one
 * ended, so sorted queries are fast. Returns LH_OK, LH_ERR_INVALID_ARGUMENT (also
 * NATURAL or NEAREST on a furthest-site handle),
 * LH_ERR_DIMENSION (NATURAL outside d = 2, 3), LH_ERR_NONFINITE (a query
 * coordinate) or LH_ERR_NOMEM; on failure out is unspecified.
 */
LH_API lh_status lh_tri_interpolate(lh_tri *t, lh_interp_method method, size_t m,
                                    const double *q, int channels, const double *values,
                                    double *out);

/* ---- convex hull ------------------------------------------------------------------ */

/*
 * lh_convex_hull: the convex hull of n sites in R^d (d = 2..8; qconvex's job), by the
 * same incremental engine, exactly. The vertices are exactly the hull's corners (its
 * extreme points): a site inside the hull, or on its boundary without being a corner
 * (inside an edge, a flat face, ...), is never one. The hull is simplicial: each facet
 * lists d corners in canonical order (as lh_delaunay's simplices), oriented so that
 * orient_d(facet, p) > 0 for every point p strictly outside; facets are sorted; a flat
 * face of the hull (several corners on one hyperplane) is cut into facets by the
 * placing triangulation of its corners in lexicographic order of their coordinates,
 * so the output depends on the set of sites alone — not on their order (up to the
 * renumbering), nor on opt->seed, nor on a scaling by a power of two. Qhull's
 * `qconvex Qt` lists the same vertices where its arithmetic is exact (it may drop a
 * corner on a nearly flat face within its precision), the same number of facets in
 * 2D and 3D; in 4D and up Qt can add flat facets, which lh_convex_hull never makes.
 * Duplicates merge as in lh_delaunay. Statuses as lh_delaunay's (LH_ERR_DEGENERATE
 * when the sites span less than R^d).
 */
typedef struct lh_hull lh_hull;
LH_API lh_status lh_convex_hull(int d, size_t n, const double *xyz, const lh_options *opt,
                                lh_hull **out);
LH_API int lh_hull_dim(const lh_hull *h);
LH_API size_t lh_hull_facet_count(const lh_hull *h);
LH_API const lh_index *lh_hull_facets(const lh_hull *h);    /* d per facet              */
LH_API size_t lh_hull_vertex_count(const lh_hull *h);
LH_API const lh_index *lh_hull_vertices(const lh_hull *h);  /* the corners, increasing  */
LH_API const lh_index *lh_hull_duplicate_of(const lh_hull *h);
LH_API void lh_hull_free(lh_hull *h);

/*
 * Lengths, areas and volumes (Qhull's FA, Fa, FS).
 *
 * lh_simplex_measures: the k-dimensional measure (k = 1: length, 2: area, 3: volume,
 * ...) of m simplices in R^d (1 <= k <= d <= 8), each given by k+1 indices into the
 * n sites xyz (n*d doubles). each (m doubles) and total may be NULL. Each measure is
 * sqrt(det G) / k!, G the Gram matrix of the edges from the first vertex, summed as
 * the squares of exact k x k minors each rounded once (Cauchy-Binet): k = d, one
 * exact determinant, relative error below 2^-51 however thin the simplex; k < d,
 * below (C(d,k) + 3) * 2^-53. total: for k = d the exact sum of the exact volumes,
 * rounded (relative error below 2^-51); for k < d the measures' compensated sum
 * (Neumaier), within a few ulps of their sum. A result beyond DBL_MAX is +inf;
 * below the subnormals 0. Returns LH_OK, LH_ERR_NOMEM or LH_ERR_INVALID_ARGUMENT
 * (an index outside 0..n-1, k or d out of range).
 */
LH_API lh_status lh_simplex_measures(int d, int k, const double *xyz, size_t n, size_t m,
                                     const lh_index *simplices, double *each, double *total);
/* The simplices of t (k = lh_tri_simplex_dim): each (lh_tri_count doubles) and
 * their total, as lh_simplex_measures; for k = d the total is the exact volume of
 * the convex hull rounded once. */
LH_API lh_status lh_tri_measures(const lh_tri *t, double *each, double *total);
/* The hull h of the n sites xyz it was computed from: each facet's (d-1)-measure
 * (lh_hull_facet_count doubles), their total (the surface area; d = 2: the
 * perimeter), and the enclosed volume (d = 2: the area), exact and rounded once.
 * Any pointer but h and xyz may be NULL. */
LH_API lh_status lh_hull_measures(const lh_hull *h, const double *xyz, size_t n, double *each,
                                  double *area, double *volume);

/* ---- file formats ------------------------------------------------------------------ */

/*
 * Readers of point files and writers of meshes (lib/src/io_*.c); they use the FILE the
 * caller opened and never print, seek or close it.
 *
 * Diagnostics: a reader that fails leaves ONE line in err->message (lh_error),
 *     NAME:LINE:COL: expected WHAT, found WHAT-INSTEAD
 * where LINE and COL (1-based, COL counted in bytes; also in err->line and
 * err->column) locate the offending token, or the end of the line or of the input, e.g.
 *     pts.txt:3:3: expected coordinate 2 of point 1 (a number), found 'abc'
 *     pts.txt:5:1: expected coordinate 1 of point 3, found the end of the input (3 points declared)
 * (a non-finite number reads "pts.txt:4:3: coordinate 2 of point 2 is 'nan': NaN and
 * infinities are not points"). A token is shown quoted (its first 20 bytes and "..."
 * when longer); a NUL byte or another byte that is not text (a control byte or one
 * above 0x7e, outside comments) is named, never printed: "found a non-text byte 0x7f".
 * Tokens longer than LH_READ_MAX_TOKEN bytes are errors.
 *
 * Numbers: read with strtod (so hexadecimal floats work) and written with "%.17g", so a
 * written double reads back bit for bit; both follow the C locale's decimal point
 * (lifthull never calls setlocale). Line ends LF or CRLF; a UTF-8 byte order mark at the
 * start is skipped; '#' starts a comment that runs to the end of its line, everywhere.
 *
 * The formats read (the grammar of each as lifthull accepts it):
 *   LH_FORMAT_QHULL   Qhull's and rbox's point format (qhull(1), "Input format"): the
 *                     dimension, then the number of points, then n*d coordinates laid out
 *                     freely over the lines. The count may follow the dimension on its line
 *                     ("d n"). After the dimension or the count, a word that cannot start a
 *                     number begins a comment to the end of that line (rbox writes
 *                     "3 rbox 10 D3"), and lines before the dimension that begin with such
 *                     a word are a title, as in Qhull. Unlike Qhull, the dimension must come
 *                     first (no "n d" order) and text among the coordinates is an error.
 *   LH_FORMAT_NODE    Triangle's and TetGen's .node: a header line "n d [attributes
 *                     [markers]]" (attributes >= 0, markers 0 or 1; omitted fields are 0),
 *                     then one line per point: "number x_1..x_d [attribute...] [marker]".
 *                     The first point is numbered 0 or 1 and the numbers are consecutive.
 *                     Stricter than Triangle: a missing field is an error, not a zero.
 *   LH_FORMAT_COLUMNS one point per line, its d coordinates separated by blanks or by one
 *                     comma (CSV); every line has the same d (2..8). A first line whose first
 *                     field is not a number is a header of column names and is skipped.
 * Every format: d = 2..8 (LH_DELAUNAY_MIN_DIM..LH_DELAUNAY_MAX_DIM), 1 to
 * LH_READ_MAX_POINTS points; NaN and infinities are rejected (coordinates and
 * attributes). A declared count is not trusted: the arrays grow as points arrive.
 */
typedef enum lh_format {
    LH_FORMAT_AUTO = 0,   /* lh_points_read chooses (see there); never an output value */
    LH_FORMAT_QHULL = 1,  /* Qhull / rbox point format                                */
    LH_FORMAT_NODE = 2,   /* Triangle / TetGen .node                                  */
    LH_FORMAT_COLUMNS = 3 /* whitespace- or comma-separated columns, one point a line */
} lh_format;

/* The format's name: "auto", "qhull", "node", "columns" (static storage; "unknown"
 * for other values). */
LH_API const char *lh_format_name(lh_format format);

#define LH_READ_MAX_POINTS (LH_INDEX_MAX - 1) /* as lh_delaunay accepts: 2^31 - 2
                                                (2^63 - 2 with 64-bit indices)   */
#define LH_READ_MAX_TOKEN 255         /* bytes in one number or word                   */

/* Points read from a file. Every array is allocated with the allocator given to
 * lh_points_read and released by lh_points_free. */
typedef struct lh_points {
    int d;                /* coordinates per point, 2..8                                */
    size_t n;             /* points, 1..LH_READ_MAX_POINTS                              */
    double *xyz;          /* n*d coordinates, row-major                                 */
    int attr_count;       /* .node: attributes per point; 0 otherwise                   */
    double *attr;         /* n*attr_count attributes, row-major; NULL when none         */
    lh_index *marker;     /* .node with markers: n boundary markers; NULL otherwise     */
    int first_index;      /* .node: the first point's number (0 or 1); 0 otherwise      */
    lh_format format;     /* the format that was read (never LH_FORMAT_AUTO)           */
    lh_allocator alloc_;  /* private: the hooks that allocated the arrays              */
} lh_points;

/*
 * lh_points_read: reads points from f, which is read to its end (one pass, no seeking:
 * pipes and standard input work). name is used in diagnostics only (NULL: "<input>").
 * With LH_FORMAT_AUTO the format is chosen by the name's extension (".node": NODE;
 * ".csv": COLUMNS) or else by the first 4 KiB of content: a first line (after '#'
 * comments and a title) that holds one integer, or two integers "d n" with d in 2..8,
 * is QHULL, any other numbers COLUMNS (a two-integer line is COLUMNS after all when the
 * whole input fits in those 4 KiB, has exactly two numbers a line and does not hold
 * the declared d*n coordinates); an empty or unrecognised input is QHULL.
 * alloc may be NULL (malloc/free); err (may be NULL) receives the one-line
 * diagnostic "NAME:LINE:COL: expected ..., found ..." in err->message and its place
 * in err->line and err->column (lh_error).
 * Returns LH_OK with *out filled; or, with *out zeroed (lh_points_free accepts it):
 * LH_ERR_PARSE (malformed text), LH_ERR_DIMENSION (d outside 2..8), LH_ERR_NONFINITE,
 * LH_ERR_TOO_LARGE (a count above LH_READ_MAX_POINTS, or an array size that would
 * overflow), LH_ERR_NOMEM, LH_ERR_IO (a read error) or LH_ERR_INVALID_ARGUMENT (f or
 * out NULL, format unknown, or an allocator without hooks).
 */
LH_API lh_status lh_points_read(FILE *f, const char *name, lh_format format,
                                const lh_allocator *alloc, lh_points *out, lh_error *err);
/* Frees the arrays of p (not p itself) and zeroes it; NULL or a zeroed p is a no-op. */
LH_API void lh_points_free(lh_points *p);

/* Cells read from a file (lh_cells_read); the array is released by lh_cells_free. */
typedef struct lh_cells {
    int nv;               /* point indices per cell, 2..9                             */
    size_t count;         /* cells                                                    */
    lh_index *v;          /* count*nv point indices, 0-based                          */
    int first_index;      /* .ele: the first cell's number (0 or 1), the base of its
                             point indices too; 0 for Qhull's 'i'                    */
    int attr_count;       /* .ele: attributes per cell (its header's third field)     */
    double *attr;         /* count*attr_count attributes, or NULL                     */
    lh_allocator alloc_;  /* private: the hooks that allocated v and attr             */
} lh_cells;

/*
 * lh_cells_read: simplices (or any cells of equal size) as index lists, to check a
 * triangulation made elsewhere: Qhull's 'i' format (what qdelaunay i, qconvex i and
 * lifthull delaunay print: the count, then one cell a line, 0-based indices), or a
 * Triangle/TetGen .ele file (header "count points_per_cell [attributes]", then
 * "number v_0..v_k [attributes]" numbered consecutively from 0 or 1, the point
 * indices from the same base; attributes are finite numbers, kept in attr: NaN or
 * infinity is LH_ERR_NONFINITE as in .node files). The header line tells them apart
 * (one field: 'i'). With n_points > 0 every index must name one of n_points points. Diagnostics and
 * statuses as lh_points_read ("NAME:LINE:COL: expected ..., found ...").
 */
LH_API lh_status lh_cells_read(FILE *f, const char *name, size_t n_points,
                               const lh_allocator *alloc, lh_cells *out, lh_error *err);
/* Frees c's array (not c) and zeroes it; NULL or a zeroed c is a no-op. */
LH_API void lh_cells_free(lh_cells *c);

/*
 * A mesh to write, as flat arrays the caller owns: n points of dimension d, and
 * `count` k-simplices (cells of k+1 vertices: k = 1 segments, 2 triangles,
 * 3 tetrahedra, ...) given as 0-based indices into the points — lh_tri_simplices and
 * lh_tri_neighbors fit as they are.
 */
typedef struct lh_mesh_view {
    int d;                   /* coordinates per point                                   */
    size_t n;                /* points                                                  */
    const double *xyz;       /* n*d, row-major                                          */
    int k;                   /* simplex dimension, >= 1                                 */
    size_t count;            /* cells                                                   */
    const lh_index *cells;   /* count*(k+1) point indices; NULL only when count is 0    */
    const lh_index *neighbors;/* count*(k+1): neighbour j of a cell is across the facet
                                opposite its j-th vertex, -1 for none; NULL if unknown    */
    const double *values;    /* n per-point scalars (a point field), or NULL           */
    const char *values_name; /* the field's name (printable ASCII, no blank, none of
                                " & < > '), NULL for "value"                            */
} lh_mesh_view;

/*
 * Writers. Each checks the view first and writes nothing when it is bad: f or m NULL,
 * an array NULL where it is needed, a cell index outside 0..n-1, a neighbour outside
 * -1..count-1, first_index other than 0 or 1, or a bad values_name give
 * LH_ERR_INVALID_ARGUMENT; a d or k the format cannot hold LH_ERR_DIMENSION; a NaN or
 * infinity among the coordinates or values LH_ERR_NONFINITE; more than LH_INDEX_MAX
 * points or cells LH_ERR_TOO_LARGE. A failed write (fprintf or ferror) gives LH_ERR_IO,
 * with the file holding a prefix of the output. Otherwise LH_OK. Doubles as "%.17g".
 *
 * lh_vtu_write   VTK XML UnstructuredGrid (.vtu), binary or ASCII as opt says (below).
 *                d = 1..3 (points padded with zeros to 3 coordinates, as VTK wants),
 *                k = 1..3 (VTK cell types 3 line, 5 triangle, 10 tetra). values: point
 *                data; neighbors: cell data "neighbors" with k+1 components. Indices as
 *                Int32 (Int64 past INT32_MAX points or cells, which only 64-bit indices
 *                allow).
 * lh_msh_write   Gmsh MSH 4.1 ASCII: $MeshFormat "4.1 0 8", $Entities (one entity of
 *                dimension k holding everything, bounding box of the points), $Nodes
 *                and $Elements (element types 1 segment, 2 triangle, 4 tetrahedron),
 *                tags 1-based; values as $NodeData. d = 1..3 (padded to 3), k = 1..3.
 * lh_node_write  Triangle/TetGen .node: "n d attributes 0", then "i x_1..x_d [value]",
 *                numbered from first_index; values become the one attribute. d = 2..8.
 * lh_ele_write   Triangle/TetGen .ele: "count k+1 0", then "i v_0..v_k", points numbered
 *                from first_index (as in the matching .node). k = 1..8.
 * lh_neigh_write Triangle/TetGen .neigh: "count k+1", then "i n_0..n_k", neighbour j
 *                opposite vertex j as in Triangle, -1 for none whatever first_index is.
 *                Needs neighbors. k = 1..8.
 * lh_off_write   OFF: "OFF", "n count 0", the points padded to 3 coordinates, then
 *                "3 a b c" per triangle: k = 2 with d = 2 (a triangulation) or d = 3
 *                (a surface, e.g. a 3D convex hull's facets).
 */
LH_API lh_status lh_msh_write(FILE *f, const lh_mesh_view *m);
LH_API lh_status lh_node_write(FILE *f, const lh_mesh_view *m, int first_index);
LH_API lh_status lh_ele_write(FILE *f, const lh_mesh_view *m, int first_index);
LH_API lh_status lh_neigh_write(FILE *f, const lh_mesh_view *m, int first_index);
LH_API lh_status lh_off_write(FILE *f, const lh_mesh_view *m);

/*
 * The .vtu writer's choices; a zeroed struct (or NULL) gives the defaults: binary,
 * no cell field.
 *
 * Binary: every DataArray format="binary", its values inline in base64 as VTK writes
 * them uncompressed (VTKFile version="1.0", header_type="UInt64": the array's length
 * in bytes as a UInt64, encoded on its own, then the values, encoded on their own, in
 * this machine's byte order, which byte_order names). Under half the ASCII size of a
 * 3D triangulation, written without formatting numbers, still well-formed XML;
 * ParaView/VTK and meshio read it. Offsets are Int32 up to INT32_MAX, else Int64.
 */
typedef struct lh_vtu_options {
    int ascii;                    /* 1: every array as text                                */
    const double *cell_values;    /* m->count per-cell scalars as cell data, or NULL; NaN
                                     or infinity: LH_ERR_NONFINITE                        */
    const char *cell_values_name; /* its name (as values_name), NULL for "cell_value"      */
} lh_vtu_options;
/* The .vtu writer (above) with its choices, opt NULL for the defaults. */
LH_API lh_status lh_vtu_write(FILE *f, const lh_mesh_view *m, const lh_vtu_options *opt);

/*
 * Writers of a tetrahedral mesh's files as TetGen writes them (lifthull tetgen), with
 * the checks and statuses of the writers above; a NULL marker or attribute array
 * leaves its column out (the header says so). Points are numbered from first_index
 * (0 or 1), as in the matching .node.
 * lh_node_marker_write  .node: "n d attributes markers" (values: the one attribute),
 *                       then "i x_1..x_d [value] [marker]". d = 2..8.
 * lh_ele_attr_write     .ele: "count k+1 0|1", then "i v_0..v_k [attribute]" with
 *                       attrs[i] (a region attribute; NaN or infinity:
 *                       LH_ERR_NONFINITE). k = 1..8.
 * lh_face_write         .face: "count 0|1", then "i a b c [marker]" (k = 2).
 * lh_edge_write         .edge: "count 0|1", then "i a b [marker]" (k = 1).
 * lh_vtk_write          legacy VTK ASCII (DataFile Version 2.0) UNSTRUCTURED_GRID as
 *                       TetGen's -k: POINTS (padded to 3 coordinates), CELLS with
 *                       0-based indices, CELL_TYPES (3 line, 5 triangle, 10 tetra),
 *                       then values as POINT_DATA and cell_values (m->count, or NULL)
 *                       as CELL_DATA SCALARS named cell_values_name (NULL:
 *                       "cell_scalars"), of type int when every value is a whole number
 *                       an int holds, else double. d = 1..3, k = 1..3.
 * lh_medit_write        Medit .mesh ASCII: MeshVersionFormatted 1, Dimension d,
 *                       Vertices, then refs' faces (k-simplices of m->k vertices:
 *                       Triangles of a tetrahedral mesh, Edges of a triangle mesh)
 *                       and m's cells (Tetrahedra, Triangles or Edges), every item
 *                       numbered from 1 with its integer reference (0 where refs
 *                       gives none), End. d = 2..3, k = 1..3.
 */
typedef struct lh_medit_refs {
    const lh_index *point_refs; /* m->n references, or NULL                             */
    const lh_index *cell_refs;  /* m->count references, or NULL                         */
    size_t face_count;          /* boundary faces written before the cells (k >= 2)     */
    const lh_index *faces;      /* face_count * m->k point indices                      */
    const lh_index *face_refs;  /* face_count references, or NULL                       */
} lh_medit_refs;
LH_API lh_status lh_node_marker_write(FILE *f, const lh_mesh_view *m, const lh_index *markers,
                                      int first_index);
LH_API lh_status lh_ele_attr_write(FILE *f, const lh_mesh_view *m, const double *attrs,
                                   int first_index);
LH_API lh_status lh_face_write(FILE *f, const lh_mesh_view *m, const lh_index *markers,
                               int first_index);
LH_API lh_status lh_edge_write(FILE *f, const lh_mesh_view *m, const lh_index *markers,
                               int first_index);
LH_API lh_status lh_vtk_write(FILE *f, const lh_mesh_view *m, const double *cell_values,
                              const char *cell_values_name);
LH_API lh_status lh_medit_write(FILE *f, const lh_mesh_view *m, const lh_medit_refs *refs);

/* ---- 2D meshing: constrained Delaunay triangulation and quality refinement -------- */

/*
 * A planar straight-line graph (PSLG), Triangle's .poly in memory. The caller may
 * fill one (every pointer its own; leave alloc_ and the *_line arrays zero) or get
 * one from lh_poly_read / lh_rings_read (lh_pslg_free releases it).
 */
typedef struct lh_pslg {
    size_t n;                  /* vertices                                                */
    double *xy;                /* n*2 coordinates                                         */
    int attr_count;            /* attributes per vertex (interpolated onto new vertices)  */
    double *attr;              /* n*attr_count, or NULL when attr_count is 0               */
    lh_index *vertex_marker;   /* n boundary markers, or NULL                             */
    size_t segment_count;
    lh_index *segments;        /* 2 per segment: 0-based vertex indices                   */
    lh_index *segment_marker;  /* segment_count markers, or NULL                          */
    size_t hole_count;
    double *holes;             /* 2 per hole: a point inside it (Triangle's hole seeds)   */
    size_t region_count;
    double *regions;           /* 4 per region: x, y, attribute, maximum area (<= 0: no
                                  bound) — Triangle's regional attributes and -a bounds   */
    int even_odd;              /* 1: the domain is where a ray to infinity crosses an odd
                                  number of segments (polygon rings: outer + holes; hole
                                  seeds then unneeded); 0: Triangle's rule, the convex
                                  hull minus what a flood from the outside and from each
                                  hole seed reaches without crossing a segment           */
    size_t cover_count;        /* refining an existing mesh (Triangle's -r): its triangles
                                  (3 vertex indices each, either orientation) are the
                                  domain instead of the rules above, and its boundary
                                  edges are segments; 0: none. Caller's arrays (no
                                  reader fills them; lh_pslg_free leaves them)           */
    lh_index *cover;
    double *cover_area;        /* cover_count area bounds (<= 0: none), applied like the
                                  regions' with lh_trimesh_options.region_areas (-ra); or
                                  NULL                                                   */
    int first_index;           /* readers: the file's first number, 0 or 1; else 0        */
    int item_first_shift;      /* readers: segments, holes and regions are numbered from
                                  first_index + item_first_shift (nonzero for a .poly with
                                  n = 0 numbered otherwise than its .node); else 0        */
    /* readers only (NULL otherwise): the line of the file where each item was read,
       so that a diagnostic can name it (1-based lines) */
    size_t *vertex_line, *segment_line, *hole_line, *region_line;
    lh_allocator alloc_;       /* private: the hooks that allocated the arrays            */
} lh_pslg;

/*
 * lh_poly_read: Triangle's .poly file. Header "n 2 attributes markers(0|1)", n vertex
 * lines "i x y [attributes] [marker]"; "segments markers(0|1)", segment lines
 * "i a b [marker]"; "holes", hole lines "i x y"; optionally "regions", region lines
 * "i x y attribute [max_area]" (no max_area: the attribute's value, as Triangle reads
 * it). '#' starts a comment; numbering starts at 0 or 1 (the first vertex's number)
 * and is consecutive, in every section. n = 0 means the vertices are in the
 * .node file of the same name: then out->n is 0, segment endpoints are not range
 * checked (numbered from the file's first number, first_index), and the caller
 * attaches the vertices (lh_pslg_take_points). Diagnostics and statuses as
 * lh_points_read ("NAME:LINE:COL: expected ..., found ...").
 *
 * lh_rings_read: polygons as JSON rings, the earcut fixtures' format:
 * [[[x,y],[x,y],...], [[x,y],...], ...] — an outer ring then hole rings, each ring
 * closed implicitly (a last point equal to the first is dropped). Every ring becomes
 * a cycle of segments (a ring of one point, earcut's Steiner point, a vertex alone),
 * even_odd is set.
 */
LH_API lh_status lh_poly_read(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                              lh_error *err);
LH_API lh_status lh_rings_read(FILE *f, const char *name, const lh_allocator *alloc, lh_pslg *out,
                               lh_error *err);
/* Moves p's coordinates, attributes and markers into g, which has none (g->n == 0),
 * leaving p zeroed; p must have d = 2 and the same allocator hooks as g. g's segment
 * endpoints are renumbered from p's first_index, which g takes (Triangle numbers them
 * as the .node). Returns LH_OK or LH_ERR_INVALID_ARGUMENT. */
LH_API lh_status lh_pslg_take_points(lh_pslg *g, lh_points *p);
/* Frees what a reader allocated (not g) and zeroes g; NULL or a zeroed g is a no-op. */
LH_API void lh_pslg_free(lh_pslg *g);

/* Options of lh_pslg_triangulate; lh_trimesh_options_default sets every default.
 * The letters are Triangle's switches for the same thing. */
typedef struct lh_trimesh_options {
    const lh_allocator *alloc; /* NULL: malloc/free                                   */
    int convex_hull;           /* -c: keep every triangle of the convex hull (holes
                                  still carved); hull edges become segments (default 0) */
    double min_angle;          /* -q: degrees; refine until every triangle's smallest
                                  angle is at least this (0: no angle bound; at most
                                  LH_TRIMESH_MAX_ANGLE) (default 0)                   */
    double max_area;           /* -a<x>: refine until no triangle's area exceeds this
                                  (<= 0: none) (default 0)                           */
    int region_areas;          /* -a: the regions' maximum areas apply (default 0)   */
    int region_attributes;     /* -A: each triangle carries its region's attribute
                                  (default 0)                                        */
    int conforming;            /* -D: split segments until every triangle is Delaunay
                                  (no vertex inside any circumcircle) (default 0)     */
    int boundary_steiner;      /* 1: Steiner points may split every segment (default);
                                  0 (-Y): none on boundary segments; -1 (-YY): none on
                                  any segment                                        */
    size_t max_steiner;        /* -S: at most this many Steiner points (default
                                  SIZE_MAX: no limit)                                */
    int split_crossings;       /* 1: segments that cross get a vertex at their
                                  crossing (the lines' intersection, rounded once) and
                                  are split there; 0: crossing segments are an error
                                  naming both (default 0)                            */
    int smooth;                /* passes of smoothing after refinement: each Steiner
                                  point on no segment moves to its neighbours' centroid
                                  when that raises the smallest angle around it, keeps
                                  every triangle positive and within its area bound;
                                  then flips make the mesh constrained Delaunay again.
                                  The smallest angle never decreases (default 0)      */
    int split_segments;        /* -s: before the domain is carved, every subsegment
                                  that is not locally Delaunay is split at its
                                  midpoint until all are: segments become chains of
                                  Delaunay edges (a conforming Delaunay triangulation
                                  of the graph), counted in steiner_points and within
                                  max_steiner; ignored when refining a given mesh
                                  (cover) (default 0)                              */
} lh_trimesh_options;

#define LH_TRIMESH_MAX_ANGLE 40.0 /* degrees: the largest angle bound accepted */
/* Degrees: up to this angle bound Delaunay refinement provably ends (Ruppert 1995;
 * Shewchuk 2002); above it a Steiner budget from the input stops it
 * (lh_trimesh_stats.steiner_budget). */
#define LH_TRIMESH_PROVABLE_ANGLE 20.7

LH_API void lh_trimesh_options_default(lh_trimesh_options *opt);

/*
 * lh_pslg_triangulate: the constrained Delaunay triangulation (Chew 1989) of a PSLG,
 * restricted to its domain, optionally refined (Ruppert 1995; Shewchuk 2002, "Delaunay
 * refinement algorithms for triangular mesh generation"). Exact: every decision is an
 * exact orient_2 or incircle, so every triangle is positively oriented, every segment
 * is a union of edges, and every edge that is not on a segment is locally Delaunay
 * (lh_cdt_check). Steiner points are constructions, rounded once each: a point
 * put on a segment is within an ulp of it, not necessarily exactly on it.
 *
 * Degenerate input, resolved and reported in lh_trimesh_stats: exact duplicate
 * vertices are merged into the first (each later one stays a point, in no triangle);
 * zero-length segments (after merging) are dropped; a segment overlapping another
 * shares its edges; a vertex lying on a segment splits it; a hole or region seed
 * outside the domain is ignored; segments that cross get a vertex at the crossing
 * with opt->split_crossings. Errors: segments that cross (LH_ERR_CROSSING_SEGMENTS,
 * naming both; also when split_crossings cannot place the rounded crossing), a mesh
 * to refine (cover) naming a point that does not exist, with an edge of three
 * triangles, crossing edges or no triangle of positive area (LH_ERR_INVALID_MESH),
 * all vertices
 * collinear or fewer than 3 distinct (LH_ERR_DEGENERATE),
 * a flood from the outside or a hole that removes every triangle (an unclosed
 * boundary: LH_ERR_DEGENERATE), with even_odd a vertex ending an odd number of
 * segments (rings not closed, the parity undefined: LH_ERR_DEGENERATE, naming it),
 * a hole seed lying exactly on a segment or at its endpoint (the side to carve is
 * undefined: LH_ERR_DEGENERATE, naming both), a segment endpoint out of range, an
 * option out of range (min_angle outside 0..LH_TRIMESH_MAX_ANGLE, max_area NaN,
 * smooth < 0), a count with a NULL array or an allocator without hooks
 * (LH_ERR_INVALID_ARGUMENT), NaN or infinity (LH_ERR_NONFINITE), counts no lh_index
 * can number (n, segment_count or cover_count from LH_INDEX_MAX / 4 up:
 * LH_ERR_TOO_LARGE), LH_ERR_NOMEM.
 * err (may be NULL) receives a one-line reason in err->message; when the PSLG came
 * from a reader and the reason names an item with a line, err->line is that line and
 * the message starts with it and a colon ("17: segment 3 crosses segment 5 (line
 * 19)"), so "FILE:" + message names the place. Items are numbered as in the file
 * (vertices from g->first_index, segments, holes and regions from g->first_index +
 * g->item_first_shift).
 */
typedef struct lh_trimesh lh_trimesh;
LH_API lh_status lh_pslg_triangulate(const lh_pslg *g, const lh_trimesh_options *opt,
                                     lh_trimesh **out, lh_error *err);
LH_API void lh_trimesh_free(lh_trimesh *m);

/* Points: the PSLG's vertices first, with their indices (merged duplicates too), then
 * the Steiner points. Markers, Triangle's rule: a vertex's own nonzero marker; else
 * the nonzero marker of an input segment it lies on (an endpoint, or a Steiner point
 * put on it; of several, the first segment in input order); else 1 on the domain's
 * boundary (holes' too); else 0. */
LH_API size_t lh_trimesh_point_count(const lh_trimesh *m);
LH_API const double *lh_trimesh_points(const lh_trimesh *m);         /* 2 per point          */
LH_API const lh_index *lh_trimesh_point_markers(const lh_trimesh *m);/* 1 per point          */
LH_API int lh_trimesh_point_attr_count(const lh_trimesh *m);
LH_API const double *lh_trimesh_point_attrs(const lh_trimesh *m);    /* interpolated; or NULL */
/* Triangles counterclockwise; neighbour k opposite vertex k, -1 on the boundary. */
LH_API size_t lh_trimesh_triangle_count(const lh_trimesh *m);
LH_API const lh_index *lh_trimesh_triangles(const lh_trimesh *m);
LH_API const lh_index *lh_trimesh_neighbors(const lh_trimesh *m);
LH_API const double *lh_trimesh_triangle_attrs(const lh_trimesh *m); /* region_attributes: 1
                                                                 per triangle; or NULL */
/* Subsegments: the edges that lie on input segments (or, with convex_hull, on the
 * hull), 2 points each, with the segment's marker (1 for hull edges and for segments
 * without markers on the boundary, 0 inside); and the input segment each lies on (-1:
 * a hull edge). */
LH_API size_t lh_trimesh_segment_count(const lh_trimesh *m);
LH_API const lh_index *lh_trimesh_segments(const lh_trimesh *m);
LH_API const lh_index *lh_trimesh_segment_markers(const lh_trimesh *m);
LH_API const lh_index *lh_trimesh_segment_parents(const lh_trimesh *m);

/* What happened, and the quality reached (angles in degrees; the ranges are measured
 * at each call, one pass over the triangles). */
typedef struct lh_trimesh_stats {
    size_t input_vertices, duplicates_merged, segments_dropped, segments_overlapping;
    size_t holes_ignored, regions_ignored;
    size_t steiner_points, steiner_on_segments, crossings_split, smoothing_moves;
    size_t steiner_removed;          /* Steiner points inserted and removed again by
                                        refinement (Chew's rule); not in the output  */
    size_t triangles, bad_triangles; /* bad: below min_angle or above an area bound at
                                        the end (input angles, -S or -Y stopped them)   */
    double min_angle, max_angle, min_area, max_area;
    int steiner_limit_reached;
    size_t segments_unsplit;         /* subsegments refinement had to split and could
                                        not: below the resolution floor (2^-40 of the
                                        domain's size) or their split point refused.
                                        Edges beside them may stay not Delaunay
                                        (conforming) and triangles bad               */
    size_t steiner_budget;           /* above LH_TRIMESH_PROVABLE_ANGLE, where Delaunay
                                        refinement need not end: the Steiner points it
                                        may add, from the input's size (docs/meshing.md);
                                        else 0 (no budget)                           */
    int steiner_budget_reached;      /* refinement stopped there: bad_triangles are left */
} lh_trimesh_stats;
LH_API void lh_trimesh_stats_get(const lh_trimesh *m, lh_trimesh_stats *out);
/* The triangles still bad at the end (lh_trimesh_stats.bad_triangles of them). */
LH_API const lh_index *lh_trimesh_bad_triangles(const lh_trimesh *m);

/* Triangle a, b, c's edge vectors in the frame the mesher measures quality in (its
 * angle and area bounds): d[k] is the edge opposite corner k (corners a, b, c are 0,
 * 1, 2), from corner k+1 to corner k+2, each difference rounded once (all three at
 * half scale when one overflows: both coordinates beyond 2^970), then times 2^-e for
 * the returned e, so that the largest component lies in [1, 2) (all zero: e = 0).
 * That scaling is exact but for components that become subnormal, so a construction
 * on d scaled back by 2^e is the same double as on the plain differences wherever
 * those neither over- nor underflow, and no square or product of d over- or
 * underflows for points near +-DBL_MAX, near 1e-300, or both. For finite points. */
LH_API int lh_triangle_scaled_edges(const double a[2], const double b[2], const double c[2],
                                    double d[3][2]);

/*
 * lh_cdt_check: exact check of a 2D triangulation of a domain — points (n, xy),
 * triangles (3 indices each), subsegments (2 indices each): every triangle
 * counterclockwise with positive area; edges shared by at most two triangles; every subsegment an
 * edge; every edge on the boundary a subsegment (unless boundary_free); every edge
 * not a subsegment locally Delaunay (incircle, exact). Returns LH_OK, or
 * LH_ERR_INVALID_MESH with a reason in err->message (err may be NULL);
 * LH_ERR_INVALID_ARGUMENT (a NULL array with a count, a subsegment endpoint out of
 * range, an allocator lacking alloc or free) or LH_ERR_TOO_LARGE, the argument named
 * in err->message; LH_ERR_NOMEM.
 */
LH_API lh_status lh_cdt_check(size_t n, const double *xy, size_t tri_count, const lh_index *tris,
                              size_t seg_count, const lh_index *segs, int boundary_free,
                              const lh_allocator *alloc, lh_error *err);

/* ---- piecewise linear complexes: the input of 3D meshing ------------------------ */

/*
 * A piecewise linear complex (PLC) in R^3, TetGen's input: points; facets, each a set
 * of polygons lying in one plane (the first usually its outer boundary, the others
 * holes' boundaries, slits — 2 vertices — or lone points — 1 vertex) with hole points
 * in the facet's plane that carve holes out of it; free segments; hole points and
 * region points with an attribute and a volume bound. Arrays are flat, offsets-style:
 * facet f's polygons are facet_first[f] .. facet_first[f+1]-1, polygon p's vertices
 * polygon_vertices[polygon_first[p] .. polygon_first[p+1]-1]. The readers allocate
 * every array (lh_plc_free releases them); a program building its own lh_plc zeroes
 * it and points the arrays at its own memory (never passed to lh_plc_free).
 */
typedef struct lh_plc {
    size_t n;                    /* points                                              */
    double *xyz;                 /* 3n coordinates                                      */
    int attr_count;              /* attributes per point (.node, .poly); 0 otherwise    */
    double *attr;                /* n*attr_count, or NULL                               */
    lh_index *point_marker;      /* n boundary markers, or NULL                         */
    size_t facet_count;
    lh_index *facet_first;       /* facet_count + 1 offsets into the polygons           */
    lh_index *facet_marker;      /* facet_count markers, or NULL                        */
    size_t polygon_count;
    lh_index *polygon_first;     /* polygon_count + 1 offsets into polygon_vertices     */
    lh_index *polygon_vertices;  /* 0-based point indices                               */
    lh_index *facet_hole_first;  /* facet_count + 1 offsets into facet_holes, or NULL   */
    double *facet_holes;         /* 3 per hole point of a facet                         */
    size_t segment_count;        /* free segments (Medit Edges, OBJ l): 2 indices each  */
    lh_index *segments;
    lh_index *segment_marker;    /* segment_count markers, or NULL                      */
    size_t hole_count;
    double *holes;               /* 3 per hole point (x y z)                            */
    size_t region_count;
    double *regions;             /* 5 per region: x y z attribute max_volume (<= 0: no
                                    bound)                                              */
    int first_index;             /* readers: the file's first point number (0 or 1)    */
    /* readers only (NULL otherwise): the 1-based line (binary formats: the record
       number) each item was read from, for diagnostics */
    size_t *point_line, *facet_line, *segment_line, *hole_line, *region_line;
    lh_allocator alloc_;         /* private: the hooks that allocated the arrays        */
} lh_plc;

/* Formats lh_plc_read reads. */
typedef enum lh_plc_format {
    LH_PLC_AUTO = 0,  /* by the name's extension, else by the content's first bytes     */
    LH_PLC_POLY = 1,  /* TetGen .poly (3D): nodes, facets, holes, regions              */
    LH_PLC_SMESH = 2, /* TetGen .smesh: as .poly, facets as one polygon each            */
    LH_PLC_NODE = 3,  /* TetGen .node: points only (a Delaunay tetrahedralization)      */
    LH_PLC_OFF = 4,   /* Geomview OFF                                                   */
    LH_PLC_PLY = 5,   /* Stanford PLY, ascii and binary (little and big endian)         */
    LH_PLC_STL = 6,   /* STL, ascii and binary; coincident corners merged exactly       */
    LH_PLC_MEDIT = 7, /* Medit .mesh (ascii): Vertices, Triangles, Quadrilaterals, Edges */
    LH_PLC_OBJ = 8    /* Wavefront .obj: v, f (v, v/t, v/t/n, v//n; negative indices), l */
} lh_plc_format;

/* The format's name: "auto", "poly", "smesh", "node", "off", "ply", "stl", "medit",
 * "obj" (static storage; "unknown" otherwise). */
LH_API const char *lh_plc_format_name(lh_plc_format format);

/*
 * lh_plc_read: a PLC from f (read to its end, one pass). name is for diagnostics and
 * LH_PLC_AUTO (NULL: "<input>"). Diagnostics as lh_points_read: one line
 * "NAME:LINE:COL: expected ..., found ..." in err->message (binary formats name the
 * record: "NAME: triangle 17: ..."). Every index is range checked; a polygon of no
 * vertex, a facet without a polygon of 3 or more vertices, NaN or infinity are errors.
 * A .poly whose node count is 0 takes its points from the .node of the same name:
 * then out->n is 0 and the caller attaches them (lh_plc_take_points).
 * Returns LH_OK with *out filled, or with *out zeroed: LH_ERR_PARSE, LH_ERR_NONFINITE,
 * LH_ERR_TOO_LARGE, LH_ERR_NOMEM, LH_ERR_IO, LH_ERR_INVALID_ARGUMENT.
 */
LH_API lh_status lh_plc_read(FILE *f, const char *name, lh_plc_format format,
                             const lh_allocator *alloc, lh_plc *out, lh_error *err);
/* Moves p's coordinates (d = 3), attributes and markers into g (g->n == 0), leaving p
 * zeroed; g's indices are renumbered from p's first_index. LH_OK or
 * LH_ERR_INVALID_ARGUMENT. */
LH_API lh_status lh_plc_take_points(lh_plc *g, lh_points *p);
/* Frees what a reader allocated (not g) and zeroes g; NULL or a zeroed g is a no-op. */
LH_API void lh_plc_free(lh_plc *g);

/*
 * lh_plc_intersections: the pairs of facets of g that intersect other than in what
 * they share — TetGen's -d. Exact: facets are triangulated in their planes (as
 * lh_tetrahedralize does) and every pair of triangles from different facets is tested
 * with exact orient3d; two facets sharing a vertex or an edge intersect when they
 * meet elsewhere too, or overlap in a plane. Writes at most cap pairs (facet indices,
 * the smaller first, pairs sorted) into pairs (2*cap lh_index; may be NULL when cap is
 * 0) and the number of intersecting pairs into *count.
 * Returns LH_OK; LH_ERR_INVALID_ARGUMENT, LH_ERR_NONFINITE, LH_ERR_TOO_LARGE, and the
 * facet triangulation's refusals, err->message naming the facet: LH_ERR_DEGENERATE (a
 * facet of collinear points, a hole point carving all of it, a projection merging two
 * points of a facet that is not planar), LH_ERR_CROSSING_SEGMENTS (its edges cross
 * in its plane); LH_ERR_NOMEM.
 */
LH_API lh_status lh_plc_intersections(const lh_plc *g, const lh_allocator *alloc, size_t cap,
                                      lh_index *pairs, size_t *count, lh_error *err);

/* ---- tetrahedral meshes of PLCs --------------------------------------------------- */

/* A sizing function for quality refinement: the size wanted at point xyz (a
 * circumcentre, in or near the domain), from user: the largest circumradius of a
 * tetrahedron there (TetGen's .mtr sizes); 0, below, NaN or infinite: no bound there. Called from the thread that called lh_tetrahedralize, in an order that
 * depends on the geometry alone. */
typedef double (*lh_sizing_fn)(void *user, const double xyz[3]);

/* Options of lh_tetrahedralize; lh_tetmesh_options_default sets every default. The
 * letters are TetGen's switches for the same thing. */
typedef struct lh_tetmesh_options {
    const lh_allocator *alloc; /* NULL: malloc/free                                   */
    int convex_hull;           /* -c: keep every tetrahedron of the convex hull (holes
                                  still carved) (default 0)                          */
    int boundary_steiner;      /* 1: Steiner points may go on segments and facets
                                  (default); 0 (-Y): interior Steiner points only    */
    size_t max_steiner;        /* -S: at most this many Steiner points; more needed is
                                  LH_ERR_STEINER_LIMIT (default SIZE_MAX)            */
    int region_attributes;     /* -A: each tetrahedron carries its region's attribute,
                                  regions without one numbered (default 0)           */
    int regions_only;          /* 1: the domain is its regions: every tetrahedron no
                                  region point's flood reaches is carved too (a mesh
                                  refined through lh_plc_from_tetmesh) (default 0)  */
    int check_intersections;   /* 1: facets that intersect are LH_ERR_INTERSECTING_
                                  FACETS naming the first pairs (default 1)         */
    int threads;               /* as lh_options.threads (default 1)                 */
    /* Quality refinement (Shewchuk's Delaunay refinement: docs/meshing3d.md). */
    double max_radius_edge;    /* -q: refine until every tetrahedron's circumradius over
                                  its shortest edge is at most this, except where
                                  refinement stops (small input angles, no point
                                  nearer another than half the input's closest pair,
                                  max_steiner; docs/meshing3d.md): those are counted
                                  in over_radius_edge; 0: no bound (default);
                                  TetGen's -q default is 2; below 1:
                                  LH_ERR_INVALID_ARGUMENT                            */
    double min_dihedral;       /* -q R/D: degrees; after refinement, tetrahedra with
                                  a smaller dihedral angle (10 when 0) are flipped
                                  away where flips can; those left under it are
                                  counted (under_dihedral) (default 0)               */
    double max_volume;         /* -a V: refine until every tetrahedron's volume is at
                                  most this (strictly; left over: over_volume); 0: no
                                  bound (default)                                    */
    int region_volumes;        /* -a: each region's volume bound (lh_plc.regions)
                                  applies to its tetrahedra too (default 0)          */
    int optimize_passes;       /* -O level: passes of the flips that follow
                                  refinement (edge removal, 2-3 flips), 0..10; 0:
                                  none (default 3)                                  */
    lh_sizing_fn sizing;       /* -m: refine until every tetrahedron's circumradius is
                                  at most sizing(cc), cc its circumcentre; NULL: no
                                  sizing (default)                                   */
    void *sizing_user;         /* passed to sizing                                   */
    int second_order;          /* -o2: a node at the midpoint of every tetrahedron's
                                  edge, appended to the points
                                  (lh_tetmesh_tet_midpoints) (default 0)             */
} lh_tetmesh_options;
LH_API void lh_tetmesh_options_default(lh_tetmesh_options *opt);

/*
 * lh_tetrahedralize: a tetrahedralization of the PLC's domain in which every facet is
 * a union of triangles and every segment (facet edges included) a union of edges
 * (docs/meshing3d.md). Exact: every decision is an exact predicate; Steiner points are
 * floating-point constructions, so one put on a segment or a facet is within a few
 * ulps of it, not necessarily exactly on it (lh_tetmesh_stats counts those that are
 * not). Exact duplicate points are merged into the first; a facet that is not exactly
 * planar is recovered as the mesh faces on its points that span its polygons. Holes
 * are carved by flood fill from the hole points and from outside (unless convex_hull,
 * or the PLC has no facet: then the mesh is the Delaunay tetrahedralization of the
 * points); regions are labelled by flood fill from the region points.
 * Returns LH_OK and *out; else *out NULL and err->message names the fault (with the
 * item's line, "LINE: ...", when the PLC came from a reader):
 * LH_ERR_INVALID_ARGUMENT (an index out of range, a NULL array with a count, a facet
 * without a polygon of 3 or more points), LH_ERR_NONFINITE, LH_ERR_DEGENERATE (all
 * points coplanar, a zero-area facet, a hole or region point on a facet, every
 * tetrahedron carved away), LH_ERR_CROSSING_SEGMENTS (a facet's edges cross in its
 * plane), LH_ERR_INTERSECTING_FACETS (naming the first pairs), LH_ERR_STEINER_LIMIT
 * (max_steiner, -Y, or recovery that does not settle), LH_ERR_TOO_LARGE, LH_ERR_NOMEM.
 */
typedef struct lh_tetmesh lh_tetmesh;
LH_API lh_status lh_tetrahedralize(const lh_plc *g, const lh_tetmesh_options *opt,
                                   lh_tetmesh **out, lh_error *err);
LH_API void lh_tetmesh_free(lh_tetmesh *m);

/* Points: the PLC's first (merged duplicates too, in no tetrahedron), then the Steiner
 * points, then with second_order the edges' midpoints (in the order of their
 * edges' endpoints); markers: a point's own, else its facet's or segment's (a
 * midpoint: its subsegment's, else its subface's), else 0. */
LH_API size_t lh_tetmesh_point_count(const lh_tetmesh *m);
LH_API const double *lh_tetmesh_points(const lh_tetmesh *m);          /* 3 per point  */
LH_API const lh_index *lh_tetmesh_point_markers(const lh_tetmesh *m); /* 1 per point  */
/* Tetrahedra, positively oriented (orient_3 > 0, as lh_orient defines it); neighbour
 * k opposite vertex k, -1 for none. */
LH_API size_t lh_tetmesh_tet_count(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_tets(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_neighbors(const lh_tetmesh *m);
LH_API const double *lh_tetmesh_tet_attrs(const lh_tetmesh *m); /* -A: 1 per tet; or NULL */
/* second_order: each tetrahedron's 6 edge midpoint nodes, of its corners (0 1) (1 2)
 * (0 2) (0 3) (1 3) (2 3) (VTK's quadratic tetrahedron); NULL without. The midpoint
 * node of edge a b (any edge of a tetrahedron, subfaces' and subsegments' too), or
 * -1 (not an edge, or no second_order). */
LH_API const lh_index *lh_tetmesh_tet_midpoints(const lh_tetmesh *m);
LH_API lh_index lh_tetmesh_midpoint(const lh_tetmesh *m, lh_index a, lh_index b);
/* Subfaces: the triangles on facets and on the domain's boundary, 3 points each,
 * ordered so that (a, b, c, apex) is positively oriented for the apex of the first
 * tetrahedron beside it: the normal (b-a) x (c-a) points into it (on the domain's
 * boundary: into the domain); with their facet's marker (1 on the convex hull where
 * no facet is) and facet index (-1: none). */
LH_API size_t lh_tetmesh_face_count(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_faces(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_face_markers(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_face_parents(const lh_tetmesh *m);
/* Subsegments: the edges on segments and facet edges, 2 points each, with their
 * marker and parent segment index (segments numbered: the PLC's free segments, then
 * the facets' polygon edges in order of appearance, each once). */
LH_API size_t lh_tetmesh_edge_count(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_edges(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_edge_markers(const lh_tetmesh *m);
LH_API const lh_index *lh_tetmesh_edge_parents(const lh_tetmesh *m);

typedef struct lh_tetmesh_stats {
    size_t input_points, duplicates_merged;
    size_t steiner_points;       /* all Steiner points of the mesh (one that carving
                                    left outside the domain is not in it)             */
    size_t steiner_on_segments, steiner_on_facets, steiner_interior; /* interior: -Y's */
    size_t steiner_off_exact;    /* on a segment or facet up to rounding only: not
                                    exactly on its line or plane                      */
    size_t facets_nonplanar;     /* facets whose points are not exactly coplanar        */
    size_t tets, faces, edges, regions;
    size_t holes_ignored, regions_ignored; /* seeds outside the domain or on a facet  */
    double min_dihedral, max_radius_edge; /* degrees; circumradius / shortest edge   */
    size_t refine_points;        /* Steiner points of quality refinement (in the counts
                                    above as well)                                     */
    size_t over_radius_edge;     /* tetrahedra over max_radius_edge when refinement
                                    stopped (small input angles, -S, -Y)               */
    size_t over_volume;          /* tetrahedra over their volume bound (-S, -Y)        */
    size_t over_size;            /* tetrahedra larger than the sizing asks (-S, -Y)    */
    size_t under_dihedral;       /* tetrahedra with a dihedral angle below min_dihedral */
} lh_tetmesh_stats;
LH_API void lh_tetmesh_stats_get(const lh_tetmesh *m, lh_tetmesh_stats *out);

/* Why quality refinement left a tetrahedron over a bound (lh_tetmesh_leftover.why). */
typedef enum lh_leftover_why {
    LH_LEFT_SPACING = 1, /* its split point falls nearer another point than the spacing
                            that makes refinement end (half the input's closest pair;
                            under a volume bound v, cbrt(v) / 4): small input angles
                            and features closer than that                         */
    LH_LEFT_BOUNDARY,    /* its split point lies on a segment or facet and
                            boundary_steiner is 0 (-Y)                             */
    LH_LEFT_FACET,       /* the subface to split has its circumcentre outside its
                            facet and encroaches no subsegment                     */
    LH_LEFT_REFUSED,     /* recovery could not settle around its split point       */
    LH_LEFT_REGION,      /* its split point's conflict region is too large to take  */
    LH_LEFT_STOPPED,     /* refinement stopped before its turn: max_steiner, or the
                            rounds' limits (docs/meshing3d.md)                     */
    LH_LEFT_FLIPS,       /* made by the flips after refinement                      */
    LH_LEFT_ANGLE        /* its shortest edge joins two segments where they meet at
                            an angle below 60 degrees, at about the same distance
                            from that point (a seditious edge): splitting it would
                            make a shorter one, without end                        */
} lh_leftover_why;
/* A tetrahedron over its radius-edge or volume bound when refinement ended. */
typedef struct lh_tetmesh_leftover {
    lh_index tet;         /* its index in lh_tetmesh_tets                           */
    int why;              /* lh_leftover_why                                        */
    int over;             /* the bounds it is over: 1 radius-edge, 2 volume, 4 size  */
    double radius_edge;   /* its circumradius over its shortest edge                */
    int angle_kind;       /* the nearest small input angle (below 60 degrees): 0
                             none, 1 two segments (facet edges too) at an input point,
                             2 two facets along a segment                          */
    lh_index angle_at[2]; /* that point (angle_at[1] -1), or the segment's ends      */
    double angle;         /* that angle, degrees                                    */
    double distance;      /* from the tet's nearest corner to that point or segment,
                             in the tet's shortest edges                            */
} lh_tetmesh_leftover;
/* The tetrahedra left over their bounds, worst radius-edge ratio first (ties by
 * index); *count of them. NULL and 0 without refinement or when none is left. */
LH_API const lh_tetmesh_leftover *lh_tetmesh_leftovers(const lh_tetmesh *m, size_t *count);

/* A histogram: count[k] values x with lower[k] <= x < lower[k + 1], the last of the
 * bins unbounded above (infinity and NaN counted there); lower points to the
 * library's constant edges. */
#define LH_HISTOGRAM_MAX 20
typedef struct lh_histogram {
    int bins;
    const double *lower;
    size_t count[LH_HISTOGRAM_MAX];
} lh_histogram;

/* The quality figures of a tetrahedral mesh, TetGen's -V's and the radius-edge ratio
 * (degrees; a flat tetrahedron's aspect and radius-edge ratios are infinite). */
typedef struct lh_tetmesh_quality {
    size_t tets, faces;                   /* faces: each face of the mesh once      */
    double min_volume, max_volume;
    double min_edge, max_edge;
    double min_aspect, max_aspect;        /* longest edge over the smallest height  */
    double min_face_angle, max_face_angle;
    double min_dihedral, max_dihedral;
    double min_radius_edge, max_radius_edge; /* circumradius over shortest edge     */
    lh_histogram radius_edge; /* one per tet: 0 0.7 0.8 0.9 1 1.1 1.2 1.3 1.414 1.5 2
                                 3 5 10 100                                         */
    lh_histogram aspect;      /* one per tet: 0 1.5 2 2.5 3 4 6 10 15 25 50 100     */
    lh_histogram face_angle;  /* three per face: 0 10 20 ... 170                      */
    lh_histogram dihedral;    /* six per tet: 0 5 10 20 30 40 50 60 70 80 110 120 130
                                 140 150 160 170 175                                */
} lh_tetmesh_quality;
/*
 * lh_tetmesh_measure: the quality figures of the tetrahedral mesh of n points and
 * tet_count tetrahedra (4 indices each, any orientation), made by any program (as
 * lh_tetmesh_check takes it); with no tetrahedra, every figure 0. Floating point:
 * figures for reports, the same at every power-of-two scale of the points.
 * Returns LH_OK; LH_ERR_INVALID_ARGUMENT (a NULL array with a count, an index out of
 * range, a NaN or infinite coordinate), LH_ERR_NOMEM.
 */
LH_API lh_status lh_tetmesh_measure(size_t n, const double *xyz, size_t tet_count,
                                    const lh_index *tets, const lh_allocator *alloc,
                                    lh_tetmesh_quality *q, lh_error *err);

/*
 * lh_tetmesh_check: exact check of a tetrahedral mesh made by any program — n points,
 * tets (4 indices each), subfaces (3 each), subsegments (2 each): every tetrahedron
 * positively oriented with nonzero volume; every triangle in at most two tetrahedra,
 * which lie on its two sides; around every interior edge the tetrahedra turn once
 * (the mesh covers its domain once: no overlap); every subface a face of the mesh and
 * every boundary face a subface (unless boundary_free); every subsegment an edge.
 * With g (may be NULL) also conformity to the PLC: every facet is the union of the
 * subfaces whose parent it is (face_parents, one per subface; NULL: subfaces are
 * matched to facets by exact coplanarity), and every segment a union of subsegments;
 * points that make a facet's or segment's union true only up to rounding (a Steiner
 * point not exactly in its plane or on its line) are counted in *off_exact (may be
 * NULL) instead of failing it.
 * Returns LH_OK; LH_ERR_INVALID_MESH with the first fault in err->message;
 * LH_ERR_INVALID_ARGUMENT; LH_ERR_NOMEM.
 */
LH_API lh_status lh_tetmesh_check(size_t n, const double *xyz, size_t tet_count,
                                  const lh_index *tets, size_t face_count,
                                  const lh_index *faces, const lh_index *face_parents,
                                  size_t edge_count, const lh_index *edges,
                                  int boundary_free, const lh_plc *g, size_t *off_exact,
                                  const lh_allocator *alloc, lh_error *err);

/*
 * lh_plc_from_tetmesh: the PLC a tetrahedral mesh made by any program bounds, to refine
 * the mesh with lh_tetrahedralize and regions_only (TetGen's -r): its n points (with
 * point_markers, or NULL); a triangle facet for every face of the mesh's boundary
 * (marker 1) and every face between tetrahedra of different attributes (tet_attrs,
 * one per tetrahedron, or NULL) (marker 0); in each part those facets enclose, a
 * region point at the centroid of its first tetrahedron whose rounded centroid lies
 * strictly inside it, with the part's attribute (0 without tet_attrs) and no volume
 * bound. The result keeps the mesh's points and boundary, not its tetrahedra: they
 * are the constrained Delaunay ones of the refinement. Tetrahedra in either
 * orientation. Returns LH_OK and *out (lh_plc_free releases it); else *out zeroed
 * and: LH_ERR_INVALID_ARGUMENT (a NULL array with a count, an index out of range, a
 * NaN or infinite coordinate or attribute), LH_ERR_INVALID_MESH (a flat tetrahedron,
 * or lh_tetmesh_check's first fault: overlapping tetrahedra, a face in three),
 * LH_ERR_DEGENERATE (a part none of whose tetrahedra has its rounded centroid
 * inside), LH_ERR_TOO_LARGE, LH_ERR_NOMEM; err->message says which.
 */
LH_API lh_status lh_plc_from_tetmesh(size_t n, const double *xyz, const lh_index *point_markers,
                                     size_t tet_count, const lh_index *tets, const double *tet_attrs,
                                     const lh_allocator *alloc, lh_plc *out, lh_error *err);

#ifdef __cplusplus
}
#endif
#endif /* LIFTHULL_H */
