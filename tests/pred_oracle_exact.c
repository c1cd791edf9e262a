/*
 * pred_oracle_exact.c — test_pred_oracle's exact signs in GMP: Bareiss elimination on
 * the integers the doubles are exactly, its mpq cross-check, the reference of the
 * perturbation (SoS) lifthull.h defines, and a naive double elimination.
 */
#include "pred_oracle.h"

#include <gmp.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ---- the oracle ----------------------------------------------------------------- */

typedef struct oracle_ws {
    mpz_t X[MAXN][MAXD]; /* coordinates as integers (common power of two removed) */
    mpz_t lift[MAXN];    /* |X_i|^2 */
    mpz_t A[MAXN][MAXN]; /* the matrix being eliminated */
    mpz_t t;
    mpq_t Q[MAXN][MAXN]; /* the homogeneous matrix, for the mpq cross-check */
    mpq_t qt;
} oracle_ws;

oracle_ws *oracle_new(void)
{
    oracle_ws *o = malloc(sizeof *o);
    if (!o) return NULL;
    for (int i = 0; i < MAXN; i++) {
        for (int j = 0; j < MAXD; j++) mpz_init(o->X[i][j]);
        mpz_init(o->lift[i]);
        for (int j = 0; j < MAXN; j++) mpq_init(o->Q[i][j]);
    }
    for (int i = 0; i < MAXN; i++)
        for (int j = 0; j < MAXN; j++) mpz_init(o->A[i][j]);
    mpz_init(o->t);
    mpq_init(o->qt);
    return o;
}

void oracle_free(oracle_ws *o)
{
    if (!o) return;
    for (int i = 0; i < MAXN; i++) {
        for (int j = 0; j < MAXD; j++) mpz_clear(o->X[i][j]);
        mpz_clear(o->lift[i]);
        for (int j = 0; j < MAXN; j++) mpq_clear(o->Q[i][j]);
    }
    for (int i = 0; i < MAXN; i++)
        for (int j = 0; j < MAXN; j++) mpz_clear(o->A[i][j]);
    mpz_clear(o->t);
    mpq_clear(o->qt);
    free(o);
}

/* x = mant * 2^ex exactly, mant an odd integer below 2^53 in magnitude (x != 0),
 * read off the IEEE 754 binary64 encoding (subnormals included). */
static void split_double(double x, int64_t *mant, int *ex)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int biased = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
    int e = -1074;
    if (biased != 0) {
        m |= UINT64_C(1) << 52;
        e = biased - 1075;
    }
    while (!(m & 0xff)) {
        m >>= 8;
        e += 8;
    }
    while (!(m & 1)) {
        m >>= 1;
        e++;
    }
    *mant = bits >> 63 ? -(int64_t)m : (int64_t)m;
    *ex = e;
}

/* z = v, |v| < 2^53. */
static void set_mpz_i53(mpz_t z, int64_t v)
{
#if LONG_MAX >= 9007199254740992L
    mpz_set_si(z, (long)v);
#else
    mpz_set_d(z, (double)v);
#endif
}

/* Sign of the determinant of the m x m integer matrix o->A (destroyed), by
 * fraction-free elimination with a row exchange whenever the pivot is zero. */
static int bareiss_sign(oracle_ws *o, int m)
{
    int sign = 1;
    for (int k = 0; k < m - 1; k++) {
        if (mpz_sgn(o->A[k][k]) == 0) {
            int r = k + 1;
            while (r < m && mpz_sgn(o->A[r][k]) == 0) r++;
            if (r == m) return 0;
            for (int j = k; j < m; j++) mpz_swap(o->A[k][j], o->A[r][j]);
            sign = -sign;
        }
        for (int i = k + 1; i < m; i++) {
            for (int j = k + 1; j < m; j++) {
                mpz_mul(o->t, o->A[i][j], o->A[k][k]);
                mpz_submul(o->t, o->A[i][k], o->A[k][j]);
                if (k > 0) mpz_divexact(o->A[i][j], o->t, o->A[k - 1][k - 1]);
                else mpz_swap(o->A[i][j], o->t);
            }
        }
    }
    return sign * mpz_sgn(o->A[m - 1][m - 1]);
}

/* The exact sign of orient_D / insphere_D of the n points pts[0..n-1]. */
int oracle_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts)
{
    int64_t mant[MAXN][MAXD];
    int ex[MAXN][MAXD], emin = INT_MAX;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < D; j++) {
            if (pts[i][j] == 0.0) {
                mant[i][j] = 0;
                continue;
            }
            split_double(pts[i][j], &mant[i][j], &ex[i][j]);
            if (ex[i][j] < emin) emin = ex[i][j];
        }
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < D; j++) {
            set_mpz_i53(o->X[i][j], mant[i][j]);
            if (mant[i][j] != 0 && ex[i][j] != emin)
                mpz_mul_2exp(o->X[i][j], o->X[i][j], (mp_bitcnt_t)(ex[i][j] - emin));
        }
        if (kind == INSPHERE) {
            mpz_set_ui(o->lift[i], 0);
            for (int j = 0; j < D; j++) mpz_addmul(o->lift[i], o->X[i][j], o->X[i][j]);
        }
    }
    int m = n - 1; /* = D (orient) or D+1 (insphere) */
    for (int i = 1; i < n; i++) {
        for (int j = 0; j < D; j++) mpz_sub(o->A[i - 1][j], o->X[i][j], o->X[0][j]);
        if (kind == INSPHERE) mpz_sub(o->A[i - 1][D], o->lift[i], o->lift[0]);
    }
    return bareiss_sign(o, m);
}

/* The same sign by rational Gaussian elimination on the full homogeneous matrix
 * [1 p_i (|p_i|^2)] in mpq_t: slower, used to cross-check oracle_sign. */
int oracle_ref_sign(oracle_ws *o, int kind, int D, int n, const double *const *pts)
{
    for (int i = 0; i < n; i++) {
        mpq_set_ui(o->Q[i][0], 1, 1);
        for (int j = 0; j < D; j++) mpq_set_d(o->Q[i][1 + j], pts[i][j]);
        if (kind == INSPHERE) {
            mpq_set_ui(o->Q[i][D + 1], 0, 1);
            for (int j = 0; j < D; j++) {
                mpq_mul(o->qt, o->Q[i][1 + j], o->Q[i][1 + j]);
                mpq_add(o->Q[i][D + 1], o->Q[i][D + 1], o->qt);
            }
        }
    }
    int sign = 1;
    for (int k = 0; k < n; k++) {
        int r = k;
        while (r < n && mpq_sgn(o->Q[r][k]) == 0) r++;
        if (r == n) return 0;
        if (r != k) {
            for (int j = k; j < n; j++) mpq_swap(o->Q[k][j], o->Q[r][j]);
            sign = -sign;
        }
        if (mpq_sgn(o->Q[k][k]) < 0) sign = -sign;
        for (int i = k + 1; i < n; i++) {
            if (mpq_sgn(o->Q[i][k]) == 0) continue;
            mpq_div(o->Q[i][k], o->Q[i][k], o->Q[k][k]); /* the multiplier */
            for (int j = k + 1; j < n; j++) {
                mpq_mul(o->qt, o->Q[i][k], o->Q[k][j]);
                mpq_sub(o->Q[i][j], o->Q[i][j], o->qt);
            }
        }
    }
    return sign;
}

/*
 * A reference for the SoS sign, from the definition in lifthull.h (Edelsbrunner &
 * Muecke): entry (r, c) of the homogeneous matrix H, for every perturbed column c,
 * becomes H[r][c] + eps^(2^code(r, c)), codes numbering the entries by significance:
 * the lexicographically largest point first, within a point the lifted column first
 * and then x_0, x_1, ... The perturbed determinant is the sum over sets S of entries
 * (at most one per row and per column) of eps^(sum of 2^code) times det(H with the
 * rows of S replaced by the unit vectors of their columns); its sign for small eps
 * is that of the nonzero term whose code set is least in binary order, i.e. whose
 * largest code is least, then the next largest, and so on. So: find the least K
 * such that det(H + symbols at codes 0..K) is not identically zero; K is in that
 * set; replace its row by its unit vector and repeat below K until the determinant
 * itself is nonzero. "Not identically zero" is decided by evaluation at random
 * points modulo two primes near 2^32 (Schwartz-Zippel: a false "zero" has
 * probability below 2^-54 per decision); the final sign is exact (Bareiss).
 *
 * Uses o->X and o->lift as left by oracle_sign on the same points, which must be
 * pairwise distinct.
 */
enum { NPRIMES = 2 };
static const uint64_t sz_primes[NPRIMES] = {4294967291u, 4294967279u};

/* Is det W != 0 modulo the prime p (W destroyed)? Division-free elimination: row i
 * becomes W[k][k] * row i - W[i][k] * row k, which multiplies the determinant by the
 * nonzero pivot and so keeps it zero or nonzero. */
static int det_mod_nonzero(uint64_t W[MAXN][MAXN], int n, uint64_t p)
{
    for (int k = 0; k < n; k++) {
        int r = k;
        while (r < n && W[r][k] == 0) r++;
        if (r == n) return 0;
        if (r != k)
            for (int j = k; j < n; j++) {
                uint64_t t = W[k][j];
                W[k][j] = W[r][j];
                W[r][j] = t;
            }
        uint64_t piv = W[k][k];
        for (int i = k + 1; i < n; i++) {
            uint64_t f = W[i][k];
            if (f == 0) continue;
            for (int j = k + 1; j < n; j++)
                W[i][j] = (W[i][j] * piv % p + (p - f) * W[k][j] % p) % p;
        }
    }
    return 1;
}

typedef struct sos_ref {
    int n, P;              /* points, perturbed columns per row */
    int row_at[MAXN];      /* row_at[t]: the row of significance rank t (0 = most) */
    int col_of[MAXD + 1];  /* column of the q-th perturbed entry of a row */
    int repl[MAXN];        /* column of the unit vector replacing a row, or -1 */
    uint64_t Hm[NPRIMES][MAXN][MAXN];
} sos_ref;

/* Is det(H, rows replaced, + random symbols at codes 0..K) nonzero? */
static int sz_nonzero(const sos_ref *s, rng *r, int K)
{
    for (int k = 0; k < NPRIMES; k++) {
        uint64_t p = sz_primes[k], W[MAXN][MAXN];
        for (int i = 0; i < s->n; i++)
            for (int j = 0; j < s->n; j++)
                W[i][j] = s->repl[i] < 0 ? s->Hm[k][i][j] : (uint64_t)(j == s->repl[i]);
        for (int code = 0; code <= K; code++) {
            int row = s->row_at[code / s->P], col = s->col_of[code % s->P];
            if (s->repl[row] < 0) W[row][col] = (W[row][col] + lht_rng_next(r) % p) % p;
        }
        if (det_mod_nonzero(W, s->n, p)) return 1;
    }
    return 0;
}

/* o->A = H with the replaced rows; returns its exact sign. */
static int exact_replaced_sign(oracle_ws *o, const sos_ref *s, int kind, int D)
{
    for (int i = 0; i < s->n; i++) {
        if (s->repl[i] >= 0) {
            for (int j = 0; j < s->n; j++) mpz_set_ui(o->A[i][j], j == s->repl[i]);
            continue;
        }
        mpz_set_ui(o->A[i][0], 1);
        for (int j = 0; j < D; j++) mpz_set(o->A[i][1 + j], o->X[i][j]);
        if (kind == INSPHERE) mpz_set(o->A[i][D + 1], o->lift[i]);
    }
    return bareiss_sign(o, s->n);
}

static int lex_greater(const double *a, const double *b, int D)
{
    for (int j = 0; j < D; j++)
        if (a[j] != b[j]) return a[j] > b[j];
    return 0;
}

int sos_reference_sign(oracle_ws *o, rng *r, int kind, int D, int n,
                       const double *const *pts)
{
    sos_ref s;
    s.n = n;
    s.P = D + (kind == INSPHERE);
    for (int i = 0; i < n; i++) {
        int t = 0;
        for (int j = 0; j < n; j++) t += lex_greater(pts[j], pts[i], D);
        s.row_at[t] = i;
        s.repl[i] = -1;
    }
    for (int q = 0; q < s.P; q++)
        s.col_of[q] = kind == INSPHERE ? (q == 0 ? D + 1 : q) : q + 1;
    for (int k = 0; k < NPRIMES; k++)
        for (int i = 0; i < n; i++) {
            s.Hm[k][i][0] = 1;
            for (int j = 0; j < D; j++)
                s.Hm[k][i][1 + j] = mpz_fdiv_ui(o->X[i][j], (unsigned long)sz_primes[k]);
            if (kind == INSPHERE)
                s.Hm[k][i][D + 1] = mpz_fdiv_ui(o->lift[i], (unsigned long)sz_primes[k]);
        }
    int limit = n * s.P;
    for (int level = 0; level <= n; level++) {
        int sign = exact_replaced_sign(o, &s, kind, D);
        if (sign) return sign;
        if (limit == 0 || !sz_nonzero(&s, r, limit - 1)) return 0; /* cannot happen */
        int lo = 0, hi = limit - 1;
        while (lo < hi) {
            int mid = lo + (hi - lo) / 2;
            if (sz_nonzero(&s, r, mid)) hi = mid;
            else lo = mid + 1;
        }
        s.repl[s.row_at[lo / s.P]] = s.col_of[lo % s.P];
        limit = lo;
    }
    return 0;
}

/* What a naive double-precision evaluation (Gaussian elimination with partial
 * pivoting on the homogeneous matrix, |p|^2 rounded) says: for information only. */
int naive_sign(int kind, int D, int n, const double *const *pts)
{
    double M[MAXN][MAXN];
    for (int i = 0; i < n; i++) {
        double l = 0.0;
        M[i][0] = 1.0;
        for (int j = 0; j < D; j++) {
            M[i][1 + j] = pts[i][j];
            l += pts[i][j] * pts[i][j];
        }
        if (kind == INSPHERE) M[i][D + 1] = l;
    }
    int sign = 1;
    for (int k = 0; k < n; k++) {
        int r = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(M[i][k]) > fabs(M[r][k])) r = i;
        if (M[r][k] == 0.0) return 0;
        if (r != k) {
            for (int j = 0; j < n; j++) {
                double t = M[k][j];
                M[k][j] = M[r][j];
                M[r][j] = t;
            }
            sign = -sign;
        }
        if (M[k][k] < 0.0) sign = -sign;
        for (int i = k + 1; i < n; i++) {
            double f = M[i][k] / M[k][k];
            for (int j = k + 1; j < n; j++) M[i][j] -= f * M[k][j];
        }
    }
    return sign;
}
