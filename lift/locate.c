/*
 * locate.c — lh_tri_locate: a visibility walk over the output simplices (it ends in
 * a Delaunay triangulation: Edelsbrunner, "An acyclicity theorem for cell complexes
 * in d dimensions", Combinatorica 10(3), 1990), deciding sides with exact orient_d.
 * Outside the hull, the nearest point of the hull lies on a facet that q strictly
 * sees (q minus that point is a positive combination of the outward normals of the
 * facets through it, so one of them has a positive product with it); only those
 * facets get the floating-point closest-point computation.
 */
#include "dt.h"
#include "geom.h"
#include "lh_alloc.h"

#include <math.h>
#include <string.h>

enum { MAXV = LH_DELAUNAY_MAX_DIM + 1 };

/* Barycentric coordinates of q in the affine hull of the m points v[0..m-1] of R^d:
 * the least-squares solution (exact when q lies in it). Returns the squared distance
 * from q to its projection onto the hull's affine span; 0 on a degenerate face. */
static double project(const double *const *v, int m, const double *q, int d, double *lam, int *ok)
{
    double g[MAXV * MAXV], r[MAXV];
    int k = m - 1; /* unknowns lam[1..k]; lam[0] = 1 - sum */
    for (int i = 0; i < k; i++) {
        r[i] = 0;
        for (int c = 0; c < d; c++) r[i] += (v[i + 1][c] - v[0][c]) * (q[c] - v[0][c]);
        for (int j = 0; j < k; j++) {
            double s = 0;
            for (int c = 0; c < d; c++) s += (v[i + 1][c] - v[0][c]) * (v[j + 1][c] - v[0][c]);
            g[i * k + j] = s;
        }
    }
    *ok = k == 0 || lh__solve(g, r, k);
    double sum = 0;
    for (int i = 0; i < k; i++) {
        lam[i + 1] = *ok ? r[i] : 0;
        sum += lam[i + 1];
    }
    lam[0] = 1 - sum;
    double dist2 = 0;
    for (int c = 0; c < d; c++) {
        double x = 0;
        for (int i = 0; i < m; i++) x += lam[i] * v[i][c];
        dist2 += (x - q[c]) * (x - q[c]);
    }
    return dist2;
}

/* The point of the simplex v[0..m-1] nearest to q: over all faces, the projections
 * that fall inside their face (all coordinates >= 0); the nearest wins. */
static double nearest_in_simplex(const double *const *v, int m, const double *q, int d, double *bary)
{
    double best = INFINITY;
    for (int mask = 1; mask < (1 << m); mask++) {
        const double *f[MAXV];
        int idx[MAXV], k = 0, ok;
        for (int i = 0; i < m; i++)
            if (mask & (1 << i)) {
                f[k] = v[i];
                idx[k++] = i;
            }
        double lam[MAXV];
        double dist2 = project(f, k, q, d, lam, &ok);
        int inside = ok;
        for (int i = 0; i < k; i++) inside &= lam[i] >= 0;
        if (!inside || dist2 >= best) continue;
        best = dist2;
        memset(bary, 0, (size_t)m * sizeof *bary);
        for (int i = 0; i < k; i++) bary[idx[i]] = lam[i];
    }
    return best;
}

/* The simplex containing q, -1 when q is outside the hull, -2 past the step bound. */
static lh_index walk(lh_tri *t, const double *q, lh_index s)
{
    const int nv = t->frame.k + 1;
    const double *p[MAXV];
    size_t limit = 64 + 4 * t->count;
    lh_index prev = -1;
    for (size_t step = 0; step < limit; step++) {
        const lh_index *v = t->simp + (size_t)s * nv;
        int moved = 0;
        for (int k = 0; k < nv && !moved; k++) {
            lh_index n = t->nbr[(size_t)s * nv + k];
            if (n == prev && n >= 0) continue;
            for (int j = 0; j < nv; j++) p[j] = j == k ? q : t->xyz + (size_t)v[j] * t->d;
            if (lh__frame_orient(t->pred, &t->frame, p) >= 0) continue;
            if (n < 0) return -1;
            prev = s;
            s = n;
            moved = 1;
        }
        if (!moved) return s;
    }
    return -2; /* unreachable in a Delaunay triangulation */
}

/* Among the simplices whose closed region holds q — connected across the facets
 * whose hyperplane holds q (orient_d = 0) — the one with the smallest index, so
 * that the answer depends on q only, not on the walk. Returns -1 when out of
 * memory. */
static lh_index smallest_holder(lh_tri *t, const double *q, lh_index s)
{
    const int nv = t->frame.k + 1;
    lh_index local[64], *seen = local, best = s;
    size_t count = 1, cap = 64;
    seen[0] = s;
    for (size_t i = 0; i < count; i++) {
        lh_index c = seen[i];
        if (c < best) best = c;
        for (int k = 0; k < nv; k++) {
            lh_index n = t->nbr[(size_t)c * nv + k];
            const double *p[MAXV];
            for (int j = 0; j < nv; j++) p[j] = j == k ? q : t->xyz + (size_t)t->simp[(size_t)c * nv + j] * t->d;
            if (n < 0 || lh__frame_orient(t->pred, &t->frame, p) != 0) continue;
            size_t j = 0;
            while (j < count && seen[j] != n) j++;
            if (j < count) continue;
            if (count == cap) {
                lh_index *more = lh__alloc(&t->alloc, 2 * cap * sizeof *more);
                if (!more) {
                    best = -1;
                    goto done;
                }
                memcpy(more, seen, count * sizeof *more);
                if (seen != local) lh__free(&t->alloc, seen);
                seen = more;
                cap *= 2;
            }
            seen[count++] = n;
        }
    }
done:
    if (seen != local) lh__free(&t->alloc, seen);
    return best;
}

/* Copies of the m points v (and q) scaled by 2^-s into buf, vs, qs. */
static void scale_copy(const double *const *v, int m, int d, const double *q, int s, double *buf,
                       const double **vs, double *qs)
{
    for (int i = 0; i < m; i++) {
        for (int j = 0; j < d; j++) buf[i * d + j] = ldexp(v[i][j], -s);
        vs[i] = buf + i * d;
    }
    for (int j = 0; j < d; j++) qs[j] = ldexp(q[j], -s);
}

/* One scale for q and every hull site (lh__scale_exp), so that the facets'
 * distances compare without overflow or underflow. */
static int hull_scale(const lh_tri *t, const double *q)
{
    const int d = t->d, k = t->frame.k;
    double big = 0;
    for (size_t i = 0; i < t->hull_count * (size_t)k; i++)
        for (int j = 0; j < d; j++) big = fmax(big, fabs(t->xyz[(size_t)t->hull[i] * d + j]));
    const double *p[1] = {q};
    int e = lh__scale_exp(p, 1, d, NULL), f = 0;
    if (big > 0) frexp(big, &f);
    return e > f ? e : f;
}

static void locate_outside(lh_tri *t, const double *q, lh_location *out)
{
    const int d = t->d, k = t->frame.k, s = hull_scale(t, q);
    const double *p[MAXV], *ps[MAXV];
    double buf[MAXV * LH_DELAUNAY_MAX_DIM], qs[LH_DELAUNAY_MAX_DIM], best = INFINITY;
    for (size_t f = 0; f < t->hull_count; f++) {
        const lh_index *v = t->hull + f * k;
        for (int j = 0; j < k; j++) p[j] = t->xyz + (size_t)v[j] * d;
        p[k] = q;
        /* not strictly visible (k = 1: the two end sites, which have no orientation) */
        if (k > 1 && lh__frame_orient(t->pred, &t->frame, p) <= 0) continue;
        double bary[MAXV];
        scale_copy(p, k, d, q, s, buf, ps, qs);
        double dist2 = nearest_in_simplex(ps, k, qs, d, bary);
        if (dist2 < best || out->hull_facet < 0) { /* the first visible facet, at least */
            best = dist2;
            out->hull_facet = (lh_index)f;
            memcpy(out->bary, bary, (size_t)k * sizeof *bary);
        }
    }
    out->distance = ldexp(sqrt(best), s);
}

lh_status lh_tri_locate(lh_tri *t, const double *q, lh_index hint, lh_location *out)
{
    if (!t || !q || !out) return LH_ERR_INVALID_ARGUMENT;
    if (lh_coords_validate(t->d, 1, q, NULL) != LH_OK) return LH_ERR_NONFINITE;
    const int nv = t->frame.k + 1;
    if (t->frame.k < t->d) { /* q must lie in the sites' affine hull */
        const double *p[MAXV];
        for (int j = 0; j < nv; j++) p[j] = t->xyz + (size_t)t->simp[j] * t->d;
        p[nv] = q;
        if (lh__affine_independent(t->pred, t->d, p, nv)) return LH_ERR_INVALID_ARGUMENT;
    }
    memset(out, 0, sizeof *out);
    out->simplex = out->hull_facet = -1;
    lh_index start = hint >= 0 && (size_t)hint < t->count ? hint : 0;
    lh_index s = walk(t, q, start);
    for (size_t c = 0; s == -2 && c < t->count; c++) { /* the walk's bound: scan */
        const double *p[MAXV];
        int inside = 1;
        for (int k = 0; k < nv && inside; k++) {
            for (int j = 0; j < nv; j++) p[j] = j == k ? q : t->xyz + (size_t)t->simp[c * nv + j] * t->d;
            inside = lh__frame_orient(t->pred, &t->frame, p) >= 0;
        }
        if (inside) s = (lh_index)c;
    }
    if (s < 0) {
        locate_outside(t, q, out);
        return LH_OK;
    }
    if ((s = smallest_holder(t, q, s)) < 0) return LH_ERR_NOMEM;
    out->simplex = s;
    const double *v[MAXV], *vs[MAXV];
    double buf[MAXV * LH_DELAUNAY_MAX_DIM], qs[LH_DELAUNAY_MAX_DIM];
    for (int k = 0; k < nv; k++) v[k] = t->xyz + (size_t)t->simp[(size_t)s * nv + k] * t->d;
    scale_copy(v, nv, t->d, q, lh__scale_exp(v, nv, t->d, q), buf, vs, qs);
    int ok;
    project(vs, nv, qs, t->d, out->bary, &ok);
    return LH_OK;
}
