/*
 * pred_sos.c — Simulation of Simplicity for the homogeneous matrix H of a predicate
 * whose exact determinant is zero.
 *
 * References: H. Edelsbrunner, E. P. Muecke, "Simulation of Simplicity: a technique
 * to cope with degenerate cases in geometric algorithms", ACM TOG 9(1), 1990;
 * O. Devillers, M. Teillaud, "Perturbations for Delaunay and weighted Delaunay 3D
 * triangulations", CGTA 44(3), 2011 (the lifted-coordinate-first order).
 *
 * The perturbation. Every perturbable entry (r, c) of H — the coordinates and, for
 * insphere, the lifted coordinate; never the column of ones — becomes
 * H[r][c] + eps^(2^code(r,c)) for one fixed, sufficiently small eps > 0. Codes
 * order the entries row by row: rows by significance (the lexicographically
 * smallest point is least significant, i.e. has the largest codes), and within a
 * row the lifted column first, then x_0, x_1, ... Since each point carries its own
 * infinitesimals, this is one perturbation of the whole point set; every predicate
 * answer is the sign for that perturbed set, so answers are consistent with each
 * other and flip when two arguments are exchanged.
 *
 * Evaluation. det(H + E) = sum over partial matchings S of perturbed entries of
 * (prod_{(r,c) in S} eps^(2^code)) * det(H with rows r replaced by unit vectors
 * e_c). Distinct S have distinct eps-exponents, so the sign is that of the term
 * whose code set S* is least in binary order. S* is found greedily, row by row from
 * the least significant one, keeping W = the rows kept fixed so far (linearly
 * independent) and the columns not yet used by S*:
 *   - if row r is not in span(W), keep it fixed (W += r);
 *   - otherwise r needs a perturbed entry: the first column c of r, in code order,
 *     whose unit vector e_c is not in span(W); add (r, c) to S* and drop column c.
 * (A term with the remaining rows generic exists iff the fixed rows are
 * independent and the partially perturbed row can leave their span; the first
 * column that allows it is the least code.) Spans are tested with exact minors
 * against a column basis B of W. At the end the kept rows and columns form a
 * nonsingular square minor whose sign, with the cofactor signs of the removed
 * entries, is the answer.
 *
 * Fast path. When the rows of H have rank N-1, the dependency is unique and its
 * coefficients are the cofactors along any column; the greedy search then stops
 * at the most significant row r whose cofactor along the first perturbable column
 * is nonzero, and the answer is (-1)^(r+c) times that cofactor. For insphere the
 * cofactors along the lifted column are orient_d of the other points — the
 * Devillers-Teillaud rule — and for orient the cofactors along x_0 are orient_(k-1)
 * of the other points with x_0 dropped. Only when all of them vanish is the
 * general search run.
 */
#include "pred_internal.h"

/* Lexicographic order of points; equal points by argument position. Branch-free,
 * from the last coordinate up: on grids and spheres of lattice points, leading
 * coordinates are often equal, and an early exit mispredicts. */
static int precedes(const double *const *pts, int dim, int a, int b)
{
    const double *pa = pts[a], *pb = pts[b];
    int lt = a < b;
    for (int c = dim - 1; c >= 0; c--) lt = (pa[c] < pb[c]) | ((pa[c] == pb[c]) & lt);
    return lt;
}

/* order[0] is the least significant row, order[n-1] the most significant. */
static void significance_order(const double *const *pts, int dim, int n, int *order)
{
    for (int i = 0; i < n; i++) {
        int j = i;
        while (j > 0 && precedes(pts, dim, i, order[j - 1])) {
            order[j] = order[j - 1];
            j--;
        }
        order[j] = i;
    }
}

static int cofactor_parity(int r, int c) { return (r + c) & 1 ? -1 : 1; }

/* The most significant of the rows not in `done` (a bit mask). */
static int most_significant(const double *const *pts, int dim, int n, unsigned done)
{
    int best = -1;
    for (int i = 0; i < n; i++) {
        const int take = !(done >> i & 1) & ((best < 0) || precedes(pts, dim, best, i));
        best = take ? i : best;
    }
    return best;
}

/* The cofactor signs along the first perturbable column, most significant row
 * first (see above); the rows are picked in that order one at a time, since the
 * first cofactor is nonzero in nearly every call. With a column map (in-flat
 * insphere) the cofactors are exact minors of the mapped columns; otherwise
 * filtered orient signs. */
static int fast_path(lh_pred *ctx, const double *const *pts, int pdim, int dim, int lifted,
                     const int *cmap)
{
    int n = dim + 1 + lifted;
    const double *others[LH__MAXN];
    unsigned done = 0;
    for (int t = n - 1; t >= 0; t--) {
        int r = most_significant(pts, pdim, n, done), m = 0, s;
        done |= 1u << r;
        if (cmap) { /* lifted: the other rows, every column but the lifted one */
            int rows[LH__MAXN];
            for (int i = 0; i < n; i++)
                if (i != r) rows[m++] = i;
            s = lh__minor_sign(ctx, pts, pdim, n - 1, rows, cmap);
        } else {
            for (int i = 0; i < n; i++)
                if (i != r) others[m++] = lifted ? pts[i] : pts[i] + 1; /* x_0 dropped */
            if (lifted)
                s = lh__orient_sign(ctx, dim, others);
            else
                s = dim == 1 ? 1 : lh__orient_sign(ctx, dim - 1, others);
        }
        if (s) return cofactor_parity(r, lifted ? dim + 1 : 1) * s;
    }
    return 0;
}

typedef struct sos_state {
    lh_pred *ctx;
    const double *const *pts;
    int pdim;                              /* coordinates per point */
    int dim, n;                            /* H is n x n, n = dim + 1 + lifted */
    int cmap[LH__MAXN];                    /* H's columns in [1, p, |p|^2] */
    int w[LH__MAXN], basis[LH__MAXN], nw; /* fixed rows, their column basis */
    int alive[LH__MAXN];                   /* columns not used by S*        */
} sos_state;

static void sort_ints(int *a, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && a[j] < a[j - 1]; j--) {
            int t = a[j];
            a[j] = a[j - 1];
            a[j - 1] = t;
        }
}

static int minor_nonzero(sos_state *st, const int *rows, const int *cols, int m)
{
    int r[LH__MAXN], c[LH__MAXN];
    for (int i = 0; i < m; i++) {
        r[i] = rows[i];
        c[i] = st->cmap[cols[i]]; /* increasing map: sorting after it is the same */
    }
    sort_ints(r, m);
    sort_ints(c, m);
    return lh__minor_sign(st->ctx, st->pts, st->pdim, m, r, c) != 0;
}

static int in_basis(const sos_state *st, int c)
{
    for (int i = 0; i < st->nw; i++)
        if (st->basis[i] == c) return i;
    return -1;
}

/* A live column c outside the basis with det(W + extra_row, B' + c) != 0, where B'
 * is the basis with entry `drop` (an index, or -1) removed; -1 if none. */
static int witness(sos_state *st, int extra_row, int drop)
{
    int rows[LH__MAXN], cols[LH__MAXN], m = 0, k = 0;
    for (int i = 0; i < st->nw; i++) rows[m++] = st->w[i];
    if (extra_row >= 0) rows[m++] = extra_row;
    for (int i = 0; i < st->nw; i++)
        if (i != drop) cols[k++] = st->basis[i];
    for (int c = 0; c < st->n; c++) {
        if (!st->alive[c] || in_basis(st, c) >= 0) continue;
        cols[k] = c;
        if (minor_nonzero(st, rows, cols, m)) return c;
    }
    return -1;
}

/* Chooses the perturbed entry of a row dependent on W: the first live perturbable
 * column, in code order, whose unit vector leaves span(W). Updates the basis. */
static int choose_column(sos_state *st, int lifted)
{
    for (int t = 0; t < st->dim + lifted; t++) {
        int c = lifted ? (t == 0 ? st->dim + 1 : t) : t + 1;
        if (!st->alive[c]) continue;
        int b = in_basis(st, c);
        if (b < 0) return c; /* e_c is independent of W on the basis columns */
        int repl = witness(st, -1, b);
        if (repl >= 0) {
            st->basis[b] = repl;
            return c;
        }
    }
    return -1;
}

static int general_search(lh_pred *ctx, const double *const *pts, int pdim, int dim,
                          int lifted, const int *cmap, const int *order)
{
    sos_state st = {.ctx = ctx, .pts = pts, .pdim = pdim, .dim = dim, .n = dim + 1 + lifted, .nw = 0};
    int frow[LH__MAXN], fcol[LH__MAXN], nf = 0;
    for (int c = 0; c < st.n; c++) {
        st.alive[c] = 1;
        st.cmap[c] = cmap ? cmap[c] : c;
    }
    for (int t = 0; t < st.n; t++) {
        int r = order[t];
        int c = witness(&st, r, -1);
        if (c >= 0) {
            st.w[st.nw] = r;
            st.basis[st.nw++] = c;
            continue;
        }
        c = choose_column(&st, lifted);
        if (c < 0) return 1; /* unreachable: the perturbed determinant is nonzero */
        frow[nf] = r;
        fcol[nf++] = c;
        st.alive[c] = 0;
    }
    /* det(H with rows frow replaced by e_fcol): expand along those rows. */
    int rows[LH__MAXN], cols[LH__MAXN], nr = st.n, nc = st.n, sign = 1;
    for (int i = 0; i < st.n; i++) rows[i] = cols[i] = i;
    for (int f = 0; f < nf; f++) {
        int ri = 0, ci = 0;
        while (rows[ri] != frow[f]) ri++;
        while (cols[ci] != fcol[f]) ci++;
        sign *= cofactor_parity(ri, ci);
        for (int i = ri; i < nr - 1; i++) rows[i] = rows[i + 1];
        for (int i = ci; i < nc - 1; i++) cols[i] = cols[i + 1];
        nr--;
        nc--;
    }
    for (int i = 0; i < nc; i++) cols[i] = st.cmap[cols[i]];
    return sign * lh__minor_sign(ctx, pts, pdim, nr, rows, cols);
}

/* The perturbed sign of H, whose columns are cmap's columns of the homogeneous
 * matrix of pts (points of R^pdim), or all of them when cmap is NULL. */
static int sos_sign(lh_pred *ctx, const double *const *pts, int pdim, int dim, int lifted,
                    const int *cmap)
{
    int s = fast_path(ctx, pts, pdim, dim, lifted, cmap);
    if (s) {
        ctx->count.sos_fast++;
        return s;
    }
    ctx->count.sos_general++;
    int order[LH__MAXN];
    significance_order(pts, pdim, dim + 1 + lifted, order);
    return general_search(ctx, pts, pdim, dim, lifted, cmap, order);
}

int lh__sos_sign(lh_pred *ctx, const double *const *pts, int dim, int lifted)
{
    return sos_sign(ctx, pts, dim, dim, lifted, NULL);
}

/* The in-flat insphere's matrix: the ones, the coordinates J, the lifted column of
 * the full coordinates. */
static void flat_columns(int d, int k, const int *J, int *cols)
{
    cols[0] = 0;
    for (int j = 0; j < k; j++) cols[j + 1] = J[j] + 1;
    cols[k + 1] = d + 1;
}

int lh__insphere_flat(lh_pred *ctx, int d, int k, const int *J, const double *const *pts)
{
    int rows[LH__MAXN], cols[LH__MAXN];
    for (int i = 0; i < k + 2; i++) rows[i] = i;
    flat_columns(d, k, J, cols);
    ctx->count.calls++;
    ctx->count.exact_exits++;
    int s = lh__minor_sign(ctx, pts, d, k + 2, rows, cols);
    if (!s) ctx->count.zero_results++;
    return s;
}

int lh__insphere_flat_sos(lh_pred *ctx, int d, int k, const int *J, const double *const *pts)
{
    int s = lh__insphere_flat(ctx, d, k, J, pts);
    if (s) return s;
    int cols[LH__MAXN];
    flat_columns(d, k, J, cols);
    return sos_sign(ctx, pts, d, k, 1, cols);
}
