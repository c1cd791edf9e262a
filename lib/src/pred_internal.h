/*
 * pred_internal.h — the predicate context and the stages behind lifthull.h's
 * predicates: filter (lh_filter.gen.h), exact (pred_exact.c), perturbation
 * (pred_sos.c).
 *
 * The homogeneous matrix. For points p_0..p_{N-1} in R^dim, row i is
 *     [ 1, p_i[0], ..., p_i[dim-1] ]                 (orient, N = dim + 1)
 *     [ 1, p_i[0], ..., p_i[dim-1], |p_i|^2 ]        (insphere, N = dim + 2)
 * Column 0 is the column of ones, columns 1..dim the coordinates, column dim+1
 * the lifted coordinate. Both predicates are the sign of det of this N x N matrix.
 */
#ifndef LH_PRED_INTERNAL_H
#define LH_PRED_INTERNAL_H

#include "bigint.h"
#include "spint.h"
#include "lh_exact.h"
#include "lifthull.h"

#define LH__MAXN 10 /* largest homogeneous matrix: insphere_8 (orient_8 is 9) */

/* Limbs of one matrix entry: a difference of two doubles (67) or a sum of up to
 * eight squares of such differences (2*67 + 1), with room for a carry. */
#define LH__ENTRY_LIMBS (2 * (LH__BN_DBL_LIMBS + 1) + 2)
/* Limbs of any minor of an (LH__MAXN-1)-square integer matrix built from such
 * entries: (LH__MAXN-2) coordinate columns, one lifted column, carries. */
#define LH__DET_LIMBS \
    ((LH__MAXN - 2) * (LH__BN_DBL_LIMBS + 1) + LH__ENTRY_LIMBS + LH__MAXN + 2)
#define LH__LAYER_SLOTS 126 /* C(9,4): the widest layer of row subsets (m <= 9) */

/* Digit offsets of the sparse exact stage's accumulator (spint.h): every value it
 * forms lies below 2^(32 LH__DET_LIMBS); room for carries. */
#define LH__SP_OFFSETS (LH__DET_LIMBS * 32 / LH__SP_BITS + 8)

#define LH__ARENA_LIMBS                                                       \
    ((size_t)LH__MAXN * LH__MAXN * LH__ENTRY_LIMBS + 4 * LH__ENTRY_LIMBS +   \
     (2 * LH__LAYER_SLOTS + 1) * (size_t)LH__DET_LIMBS)

/* Row subsets of an m x m matrix (m <= 8) as bit masks, grouped by size in
 * increasing order: the masks below 2^m of size s are a prefix of by_size[s], and
 * slot[mask] is a mask's index in its group. Filled by lh_pred_create. */
typedef struct lh__subsets {
    uint16_t by_size[LH__MAXN][LH__LAYER_SLOTS];
    uint8_t count[LH__MAXN];
    uint8_t slot[1 << (LH__MAXN - 1)];
} lh__subsets;

struct lh_pred {
    lh_allocator alloc;
    lh_pred_counters count;
    lh__subsets sub;
    uint32_t *arena; /* LH__ARENA_LIMBS limbs of scratch for the exact stage */
    /* The sparse exact stage's accumulator: LH__SP_OFFSETS coefficients and their
     * flags, all zero between calls. */
    int64_t *sp_coef;
    uint8_t *sp_flag;
    /* Work of the exact stage's sign evaluations (digit or limb pairs multiplied plus
     * digits or limbs written), for tests that bound it: not a public counter. */
    uint64_t exact_work;
};

/* Exact, unperturbed signs (no filter). */
int lh__orient_exact(lh_pred *ctx, int k, const double *const *pts);
int lh__insphere_exact(lh_pred *ctx, int d, const double *const *pts);

/* The stages between the filter and the exact one (pred_bound.c), given the
 * filter's rounded determinant det and its proven error bound err (< 0: none) for
 * orient_dim, or insphere_dim when `lifted`: LH__BY_GRANULARITY or LH__BY_RESIDUES
 * with *sign set when one decides (residues only ever prove 0), else 0. The
 * residues are tried only when `residues` is set. */
enum { LH__BY_GRANULARITY = 1, LH__BY_RESIDUES = 2 };
int lh__bound_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                   double det, double err, int residues, int *sign);

/* The wide-exponent filter (pred_wide.c): 1 with *sign (-1 or +1) when it decides
 * orient_dim (insphere_dim when `lifted`) of pts, else 0. With double_word = 0 its pass
 * in doubles (or numbers with a separate exponent); with double_word = 1 its double-word
 * pass, for calls the first pass left undecided. */
int lh__wide_sign(const lh__subsets *sub, int dim, int lifted, const double *const *pts,
                  int double_word, int *sign);

/* Filtered then exact, unperturbed (the body of lh_orient without the counting of
 * a call; used by the perturbation's fast path). */
int lh__orient_sign(lh_pred *ctx, int k, const double *const *pts);

/* Simulation of Simplicity for a homogeneous matrix whose exact determinant is 0:
 * returns the perturbed sign, -1 or +1. `lifted` selects insphere (1) or orient. */
int lh__sos_sign(lh_pred *ctx, const double *const *pts, int dim, int lifted);

/* a * b + c evaluated as this library's predicate code evaluates it. Compiled with
 * the predicates' flags; with contraction off it rounds twice, never fused
 * (tests/test_pred_fma.c checks it). */
double lh__fp_contract_probe(double a, double b, double c);

#endif
