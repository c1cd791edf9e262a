/* lh_exact.h — lib's exact stage for the other modules (cross-module internal). */
#ifndef LH_EXACT_H
#define LH_EXACT_H

#include "lifthull.h"

/* Exact sign of the minor of the homogeneous matrix of pts over the m rows `rows`
 * and m columns `cols`, both strictly increasing. Row i is [1, p_i[0..dim-1]] and,
 * when column dim+1 is asked for, |p_i|^2 there. m <= 10; the empty minor is +1. */
int lh__minor_sign(lh_pred *ctx, const double *const *pts, int dim, int m,
                   const int *rows, const int *cols);

/* The value of such a minor without the lifted column, v * 2^e (*e), from the exact
 * integer determinant rounded once (relative error below 2^-52); m <= 9. */
double lh__minor_value(lh_pred *ctx, const double *const *pts, int dim, int m, const int *rows,
                       const int *cols, int *e);

/*
 * Exact sums of orientation determinants det[[1, p_0], ..., [1, p_d]] (d! times the
 * signed volume), e.g. to compare the volume of a set of simplices with a hull's.
 * Every coordinate that is added must be a multiple of 2^scale (scale at most the
 * exponent of its lowest set bit: lh__dbl_low_exp over all of them).
 */
typedef struct lh__detsum lh__detsum;
lh_status lh__detsum_create(const lh_allocator *alloc, int d, int scale, lh__detsum **out);
/* sum += det (negate: sum -= det) of the d+1 points pts. */
void lh__detsum_add(lh_pred *ctx, lh__detsum *s, const double *const *pts, int negate);
int lh__detsum_sign(const lh__detsum *s); /* -1, 0, +1 */
/* The sum as v * 2^e (*e), the exact integer rounded once (relative error below
 * 2^-52). */
double lh__detsum_value(const lh__detsum *s, int *e);
void lh__detsum_free(lh__detsum *s);
/* Exponent of the lowest set bit of x (finite, nonzero). */
int lh__dbl_low_exp(double x);
/* Whether x (finite) is not an integer: below 2^52, adding and taking away 2^52
 * rounds |x| to an integer (round to nearest), which is |x| only if |x| is one; from
 * 2^52 up every double is. No branch, so a loop over coordinates sums it. */
static inline int lh__dbl_fraction(double x)
{
    const double a = x < 0 ? -x : x;
    return (a < 0x1p52) & ((a + 0x1p52) - 0x1p52 != a);
}

/* lh_insphere_sos without argument checks, for the engine's inner loops (d within
 * range, ctx and pts valid; counted as a public call). */
int lh__insphere_sos_fast(lh_pred *ctx, int d, const double *const *pts);
/* The same, for a caller whose lh_filter.gen.h filter returned 0 with det and err:
 * the stages after the filter, without running it again. */
int lh__insphere_sos_unfiltered(lh_pred *ctx, int d, const double *const *pts, double det,
                                double err);
int lh__orient_unfiltered(lh_pred *ctx, int k, const double *const *pts, double det,
                          double err);
/* For a caller that knows the insphere determinant of pts is exactly 0 (an exact
 * static filter, lift/insert_lifted.h): its perturbed sign; counted as a call
 * settled by granularity with a zero result. */
int lh__insphere_sos_zero(lh_pred *ctx, int d, const double *const *pts);
/* Counts such a call of lh_orient whose exact zero the caller found itself. */
void lh__pred_count_zero(lh_pred *ctx);

/* Counts n calls of lh_orient/lh_insphere that a caller settled with the inline
 * filters of lh_filter.gen.h (hull/insert_orient.h, lift/insert_lifted.h), as
 * filter exits. */
void lh__pred_count_filtered(lh_pred *ctx, uint64_t n);
/* Adds src's counters to dst's and resets src's (the contexts of parallel workers). */
void lh__pred_move_counters(lh_pred *dst, lh_pred *src);

/*
 * The insphere test within a k-flat of R^d (2 <= k < d): pts are k+2 points of R^d
 * in one k-dimensional affine subspace F on which the projection to the k
 * coordinates J (increasing) is one to one. Sign of det [1, p_J, |p|^2] (the
 * lifted column over all d coordinates): with orient_k of the projected first k+1
 * points positive, negative means the last point is inside their circumsphere
 * (within F, in the metric of R^d). The projection is an affine bijection of F, so
 * orientation and this sign change together and the test is the Euclidean one.
 * Exact (no filter); the _sos variant perturbs H's entries as lh_insphere_sos
 * does, with the rows ordered by the points' full coordinates.
 */
int lh__insphere_flat(lh_pred *ctx, int d, int k, const int *J, const double *const *pts);
int lh__insphere_flat_sos(lh_pred *ctx, int d, int k, const int *J, const double *const *pts);

#endif
