/*
 * pred_oracle.h — test_pred_oracle's parts: the cases (pred_oracle_cases.c), the GMP
 * oracle and the SoS reference (pred_oracle_exact.c), the driver and its checks
 * (test_pred_oracle.c, whose header describes the whole test).
 */
#ifndef LH_TEST_PRED_ORACLE_H
#define LH_TEST_PRED_ORACLE_H

#include "sites.h"

#include <stdint.h>

enum { MAXD = 8, MAXN = 11 }; /* up to 10 points of a call, plus one extra point */
enum { ORIENT = 0, INSPHERE = 1 };
enum { F_UNIFORM, F_NEAR, F_BIG, F_TINY, F_MIXED, F_DEGEN, F_COUNT };

/* ---- PRNG: xoshiro256** (tools/sites.h), the draws the cases need ------------- */

typedef lht_rng rng;

/* Uniform in 0..n-1 (n >= 1). */
static inline int rng_below(rng *r, int n)
{
    return (int)(((lht_rng_next(r) >> 32) * (uint64_t)n) >> 32);
}

/* Uniform in lo..hi inclusive. */
static inline int rng_int(rng *r, int lo, int hi) { return lo + rng_below(r, hi - lo + 1); }

/* Uniform in [-1,1), multiples of 2^-52. */
static inline double rng_sym(rng *r) { return (double)(lht_rng_next(r) >> 11) * 0x1p-52 - 1.0; }

typedef struct pcase {
    int kind; /* ORIENT or INSPHERE */
    int D;    /* dimension of the points */
    int n;    /* points of one call: D+1 (orient) or D+2 (insphere) */
    int fam, var;
    double p[MAXN][MAXD];
} pcase;

/* Case c of family fam (F_*), for c->kind, c->D, c->n set by the caller. */
void gen_case(rng *r, pcase *c, int fam);
/* Whether the n points (D coordinates each) are pairwise distinct. */
int all_distinct(const double *const *pts, int n, int D);

/* The exact oracle's workspace (GMP integers and rationals); NULL out of memory. */
typedef struct oracle_ws oracle_ws;
oracle_ws *oracle_new(void);
void oracle_free(oracle_ws *o);
/* The exact sign of orient (kind ORIENT: n = D+1) or insphere (n = D+2) on pts:
 * Bareiss elimination on integers; the mpq Gaussian elimination of the full
 * homogeneous matrix (the cross-check); the sign of lifthull.h's perturbation when
 * the exact one is zero (pts pairwise distinct; after oracle_sign on the same
 * points); and a naive double-precision elimination (counted, never trusted). */
int oracle_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts);
int oracle_ref_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts);
int sos_reference_sign(oracle_ws *o, rng *r, int kind, int D, int n, const double *const *pts);
int naive_sign(int kind, int D, int n, const double *const *pts);

#endif
