/* test_natural.c — lh_tri_natural_coords: Sibson's coordinates are positive, sum to
 * 1 and reproduce q (linear precision) for random and degenerate sites in 2D and
 * 3D; they match a brute-force computation of the stolen areas (half-plane clipping)
 * in 2D; sites, the hull's boundary, outside points, small caps, bad dimensions and
 * every allocation failure give what lifthull.h documents. */
#include "lh_api_test.h"
#include "lh_families.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { CAP = 4096 };

/* The largest errors seen, printed by main's last test. */
static double max_sum_err, max_lin_err, max_brute_err;

static double *make_sites(int fam, int d, size_t *n, uint64_t seed)
{
    double *x = malloc(*n * (size_t)d * sizeof *x);
    lh_fam_seed(seed);
    *n = lh_fam_make(fam, d, *n, x);
    return x;
}

/* A random point of simplex s (barycentric weights at least lo). */
static void point_in_simplex(lh_tri *t, const double *x, size_t s, double lo, double *q)
{
    const int d = lh_tri_dim(t);
    const lh_index *v = lh_tri_simplices(t) + s * (size_t)(d + 1);
    double b[4], sum = 0;
    for (int j = 0; j <= d; j++) sum += b[j] = lo + lh_fam_unif();
    for (int c = 0; c < d; c++) {
        q[c] = 0;
        for (int j = 0; j <= d; j++) q[c] += b[j] / sum * x[(size_t)v[j] * d + c];
    }
}

/* The documented properties of m coordinates of q: sites increasing and not merged
 * duplicates, weights positive and summing to 1, sum w_i p_i = q. Returns
 * |sum w_i (p_i - q)| / max |p_i - q|. */
static double lin_tol = 1e-10; /* relative linear-precision tolerance */

static double check_coords(lh_test_state *lh_t_, lh_tri *t, const double *x, const double *q,
                           size_t m, const lh_index *s, const double *w)
{
    const int d = lh_tri_dim(t);
    const lh_index *dup = lh_tri_duplicate_of(t);
    double sum = 0, r[3] = {0, 0, 0}, far = 0;
    LH_EXPECT_TRUE(m >= 1);
    for (size_t i = 0; i < m; i++) {
        LH_EXPECT_TRUE(w[i] > 0);
        LH_EXPECT_TRUE(s[i] >= 0 && (size_t)s[i] < lh_tri_site_count(t) && dup[s[i]] == s[i]);
        if (i) LH_EXPECT_LT_INT(s[i - 1], s[i]);
        sum += w[i];
        double l2 = 0;
        for (int c = 0; c < d; c++) {
            double u = x[(size_t)s[i] * d + c] - q[c];
            r[c] += w[i] * u;
            l2 += u * u;
        }
        far = fmax(far, sqrt(l2));
    }
    double err = 0;
    for (int c = 0; c < d; c++) err += r[c] * r[c];
    err = far > 0 ? sqrt(err) / far : sqrt(err);
    LH_EXPECT_TRUE(fabs(sum - 1) <= 1e-12);
    LH_EXPECT_TRUE(err <= lin_tol);
    if (LH_FAILED()) LH_NOTE("q = (%.17g, %.17g, %.17g), %zu sites, sum-1 = %g, lin = %g", q[0], q[1],
                             d > 2 ? q[2] : 0.0, m, sum - 1, err);
    max_sum_err = fmax(max_sum_err, fabs(sum - 1));
    if (lin_tol == 1e-10) max_lin_err = fmax(max_lin_err, err);
    return err;
}

/* Natural coordinates of q, checked; returns the count (0 if q was outside). */
static size_t coords_checked(lh_test_state *lh_t_, lh_tri *t, const double *x, const double *q,
                             lh_index *s, double *w)
{
    size_t m = 99;
    lh_status st = lh_tri_natural_coords(t, q, -1, CAP, s, w, &m);
    if (st == LH_ERR_INVALID_ARGUMENT) { /* only outside the hull */
        lh_location loc;
        LH_EXPECT_EQ_INT(lh_tri_locate(t, q, -1, &loc), LH_OK);
        LH_EXPECT_EQ_INT(loc.simplex, -1);
        LH_EXPECT_EQ_U64(m, 0);
        return 0;
    }
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st == LH_OK) check_coords(lh_t_, t, x, q, m, s, w);
    return st == LH_OK ? m : 0;
}

/* Random sites of several families; queries at random points of random simplices. */
LH_TEST(random_sites_linear_precision)
{
    static const int fams[] = {F_CUBE, F_BALL, F_CLUSTERS, F_GRID_JITTER, F_DUPLICATES,
                               F_OFFSET_1E9, F_SPREAD_1E9, F_MIXED, F_NEAR_PLANE};
    lh_index *s = malloc(CAP * sizeof *s);
    double *w = malloc(CAP * sizeof *w);
    for (int d = 2; d <= 3; d++)
        for (size_t f = 0; f < LH_COUNT(fams) && !LH_FAILED(); f++) {
            size_t n = d == 2 ? 400 : 343; /* 7^3: whole grids */
            double *x = make_sites(fams[f], d, &n, 100 + f);
            lh_tri *t;
            LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
            for (int k = 0; k < 1000 && !LH_FAILED(); k++) {
                double q[3];
                point_in_simplex(t, x, lh_fam_rnd() % lh_tri_count(t), k % 2 ? 0.0 : 0.1, q);
                coords_checked(lh_t_, t, x, q, s, w);
            }
            if (LH_FAILED()) LH_NOTE("d = %d, %s", d, lh_fam_name[fams[f]]);
            lh_tri_free(t);
            free(x);
        }
    free(s);
    free(w);
}

/* Queries within 1e-3 .. 1e-15 (relative) of hull facets of sites in a ball: V(q)
 * grows a spike of length ~ 1/distance; the coordinates stay accurate (the fan
 * triangles are measured on their two shortest sides; before that, 3D errors grew
 * as eps / distance). */
LH_TEST(near_the_hull)
{
    for (int d = 2; d <= 3; d++) {
        size_t n = 300;
        double *x = make_sites(F_BALL, d, &n, 31);
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        const lh_index *hf = lh_tri_hull_facets(t);
        lh_index s[CAP];
        double w[CAP];
        for (int k = 0; k < 1300 && !LH_FAILED(); k++) {
            const lh_index *f = hf + (lh_fam_rnd() % lh_tri_hull_count(t)) * (size_t)d;
            const double *a = x + (size_t)f[0] * d, *b = x + (size_t)f[1] * d;
            const double *c = d == 3 ? x + (size_t)f[2] * d : a;
            double u[3] = {0}, v[3] = {0}, nrm[3], q[3], sb = 0, bw[3];
            for (int j = 0; j < d; j++) u[j] = b[j] - a[j], v[j] = c[j] - a[j];
            if (d == 2) nrm[0] = u[1], nrm[1] = -u[0];
            else nrm[0] = u[1] * v[2] - u[2] * v[1], nrm[1] = u[2] * v[0] - u[0] * v[2], nrm[2] = u[0] * v[1] - u[1] * v[0];
            double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + (d == 3 ? nrm[2] * nrm[2] : 0));
            for (int j = 0; j < 3; j++) sb += bw[j] = 0.2 + lh_fam_unif();
            if (d == 2) bw[2] = 0, sb -= bw[2];
            double depth = pow(10, -3 - k / 100) * (1 + lh_fam_unif()); /* outward normals */
            for (int j = 0; j < d; j++) q[j] = (bw[0] * a[j] + bw[1] * b[j] + bw[2] * c[j]) / sb - nrm[j] / len * depth;
            size_t m = coords_checked(lh_t_, t, x, q, s, w);
            LH_EXPECT_TRUE(m > 0 || depth < 1e-13); /* inside, unless rounding put q out */
        }
        lh_tri_free(t);
        free(x);
    }
}

/* The hard case: a jittered grid in 3D whose last layer is one row, so the hull's
 * top is made of sites collinear within 1e-12. Hull triangles of three of them have
 * circumradii ~1e12, V(q) reaches that far, and the construction's rounding (eps
 * times those distances) shows: the properties hold, linear precision only within
 * ~1e-4 (measured 5e-5 at worst over 3000 queries; long double arithmetic gives
 * 1e-7, i.e. conditioning, not a wrong formula). */
LH_TEST(nearly_collinear_hull_sites_3d)
{
    size_t n = 300;
    double *x = make_sites(F_GRID_JITTER, 3, &n, 103);
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, n, x, NULL, &t), LH_OK);
    lh_index s[CAP];
    double w[CAP];
    lin_tol = 1e-3;
    for (int k = 0; k < 1000 && !LH_FAILED(); k++) {
        double q[3];
        point_in_simplex(t, x, lh_fam_rnd() % lh_tri_count(t), 0.0, q);
        coords_checked(lh_t_, t, x, q, s, w);
    }
    lin_tol = 1e-10;
    lh_tri_free(t);
    free(x);
}

/* A query equal to a site (a merged duplicate included) gets its representative
 * alone, weight 1. */
LH_TEST(query_at_site)
{
    for (int d = 2; d <= 3; d++) {
        size_t n = 200;
        double *x = make_sites(F_DUPLICATES, d, &n, 7);
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        LH_EXPECT_GT_U64(lh_tri_duplicate_count(t), 0);
        for (size_t i = 0; i < n; i++) {
            lh_index s[8];
            double w[8];
            size_t m = 0;
            LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, x + i * d, (lh_index)i % 5, 8, s, w, &m), LH_OK);
            LH_EXPECT_EQ_U64(m, 1);
            LH_EXPECT_EQ_INT(s[0], lh_tri_duplicate_of(t)[i]);
            LH_EXPECT_EQ_DBL(w[0], 1.0);
        }
        lh_tri_free(t);
        free(x);
    }
}

/* Sites in the unit square / cube, its corners among them. A query on a hull edge
 * (2D) gets the edge's two sites, linearly; on the cube's faces and edges, the
 * barycentric coordinates in the hull facet (or edge) holding it. */
LH_TEST(query_on_hull_boundary)
{
    for (int d = 2; d <= 3; d++) {
        size_t n = 60;
        double *x = make_sites(F_CUBE, d, &n, 11);
        for (int c = 0; c < (1 << d); c++) /* the corners */
            for (int j = 0; j < d; j++) x[(size_t)c * d + j] = (c >> j) & 1;
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        for (int k = 0; k < 500; k++) {
            double q[3];
            for (int j = 0; j < d; j++) q[j] = lh_fam_unif();
            int axis = k % d, axis2 = (k / d) % d;
            q[axis] = (k / 7) % 2;            /* on a face (2D: an edge) */
            if (d == 3 && k % 3 == 0 && axis2 != axis) q[axis2] = (k / 5) % 2; /* on an edge */
            lh_index s[CAP];
            double w[CAP];
            size_t m = coords_checked(lh_t_, t, x, q, s, w);
            LH_EXPECT_TRUE(m >= 1 && m <= (size_t)d);
            for (size_t i = 0; i < m; i++) /* every site on the same face */
                LH_EXPECT_EQ_DBL(x[(size_t)s[i] * d + axis], q[axis]);
            /* the boundary value is the limit from inside */
            double qi[3], ws[CAP];
            lh_index ss[CAP];
            memcpy(qi, q, sizeof qi);
            for (int j = 0; j < d; j++) qi[j] += (q[j] == 0 ? 1e-9 : q[j] == 1 ? -1e-9 : 0);
            size_t mi = 0;
            LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, qi, -1, CAP, ss, ws, &mi), LH_OK);
            if (d == 2) { /* in 3D the limit is barycentric only within one hull triangle */
                for (size_t i = 0; i < mi; i++) {
                    double lim = 0;
                    for (size_t j = 0; j < m; j++)
                        if (s[j] == ss[i]) lim = w[j];
                    LH_EXPECT_TRUE(fabs(ws[i] - lim) < 1e-6);
                }
            }
        }
        lh_tri_free(t);
        free(x);
    }
}

LH_TEST(query_outside_and_bad_arguments)
{
    double x[] = {0, 0, 1, 0, 0, 1, 1, 1, 0.3, 0.6};
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 5, x, NULL, &t), LH_OK);
    lh_index s[8];
    double w[8];
    size_t m = 7;
    double out[2] = {1.5, 0.5}, touch[2] = {1 + 0x1p-52, 0.5}, in[2] = {0.5, 0.5};
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, out, -1, 8, s, w, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_U64(m, 0);
    m = 7;
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, touch, 3, 8, s, w, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_U64(m, 0);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(NULL, in, -1, 8, s, w, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, NULL, -1, 8, s, w, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, -1, 8, NULL, w, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, -1, 8, s, NULL, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, -1, 8, s, w, NULL), LH_ERR_INVALID_ARGUMENT);
    double nan[2] = {NAN, 0.5}, inf[2] = {0.5, INFINITY};
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, nan, -1, 8, s, w, &m), LH_ERR_NONFINITE);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, inf, -1, 8, s, w, &m), LH_ERR_NONFINITE);
    /* a hint out of range is ignored */
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, 1 << 30, 8, s, w, &m), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, -7, 8, s, w, &m), LH_OK);
    lh_tri_free(t);

    lh_options opt;
    lh_options_default(&opt);
    opt.furthest_site = 1;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 5, x, &opt, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, in, -1, 8, s, w, &m), LH_ERR_INVALID_ARGUMENT);
    lh_tri_free(t);
}

/* The cap: too small gives LH_ERR_BUFFER_TOO_SMALL and the number needed (cap 0 with NULL
 * arrays asks for it); that many then fit. */
LH_TEST(cap_too_small)
{
    size_t n = 300;
    double *x = make_sites(F_CUBE, 3, &n, 5);
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, n, x, NULL, &t), LH_OK);
    double q[3] = {0.5, 0.5, 0.5};
    lh_index s[CAP];
    double w[CAP];
    size_t need = 0, m = 0;
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, q, -1, 0, NULL, NULL, &need), LH_ERR_BUFFER_TOO_SMALL);
    LH_EXPECT_TRUE(need > 4);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, q, -1, need - 1, s, w, &m), LH_ERR_BUFFER_TOO_SMALL);
    LH_EXPECT_EQ_U64(m, need);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, q, -1, need, s, w, &m), LH_OK);
    LH_EXPECT_EQ_U64(m, need);
    check_coords(lh_t_, t, x, q, m, s, w);
    lh_tri_free(t);
    free(x);
}

/* d = 4, and triangulations of lower-dimensional sites (affine_hull), are refused. */
LH_TEST(unsupported_dimensions)
{
    size_t n = 40;
    double *x = make_sites(F_CUBE, 4, &n, 3);
    lh_tri *t;
    lh_index s[64];
    double w[64], q[4] = {0.5, 0.5, 0.5, 0.5};
    size_t m = 7;
    LH_ASSERT_EQ_INT(lh_delaunay(4, n, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, q, -1, 64, s, w, &m), LH_ERR_DIMENSION);
    LH_EXPECT_EQ_U64(m, 0);
    lh_tri_free(t);
    for (size_t i = 0; i < n; i++) x[i * 3 + 2] = x[i * 3]; /* the plane z = x of R^3 */
    lh_options opt;
    lh_options_default(&opt);
    opt.affine_hull = 1;
    LH_ASSERT_EQ_INT(lh_delaunay(3, n, x, &opt, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_simplex_dim(t), 2);
    q[2] = 1;
    LH_EXPECT_EQ_INT(lh_tri_natural_coords(t, q, -1, 64, s, w, &m), LH_ERR_DIMENSION);
    lh_tri_free(t);
    free(x);
}

/* Integer grids (every cell cospherical) and exactly cocircular / cospherical sites;
 * queries at grid points, on grid lines and faces, at cell centres (the cavity's
 * simplices all share q-containing spheres, its neighbours' pass exactly through
 * q), and at random. */
LH_TEST(degenerate_sites)
{
    lh_index *s = malloc(CAP * sizeof *s);
    double *w = malloc(CAP * sizeof *w);
    for (int d = 2; d <= 3; d++) {
        const int side = d == 2 ? 7 : 5;
        size_t n = d == 2 ? 49 : 125;
        double *x = make_sites(F_GRID, d, &n, 1);
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        static const double frac[] = {0, 0.5, 0.25, 0.125, 0.75};
        for (int k = 0; k < 3000 && !LH_FAILED(); k++) {
            double q[3];
            for (int j = 0; j < d; j++)
                q[j] = (double)(lh_fam_rnd() % (side - 1)) + frac[lh_fam_rnd() % 5];
            if (k % 10 == 9) q[0] = (side - 1) * lh_fam_unif();
            size_t m = coords_checked(lh_t_, t, x, q, s, w);
            int half = 1; /* the cell centre: every corner of the cell, equally */
            for (int j = 0; j < d; j++) half &= q[j] - floor(q[j]) == 0.5;
            if (half) {
                LH_EXPECT_EQ_U64(m, (size_t)1 << d);
                for (size_t i = 0; i < m; i++) LH_EXPECT_TRUE(fabs(w[i] - 1.0 / (double)m) < 1e-14);
            }
        }
        lh_tri_free(t);
        free(x);

        /* cospherical, centred at the origin: everything conflicts at the centre */
        n = d == 2 ? 300 : 200;
        x = make_sites(F_SPHERE_EXACT, d, &n, 2);
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        double o[3] = {0, 0, 0};
        size_t m = coords_checked(lh_t_, t, x, o, s, w);
        if (d == 2) LH_EXPECT_EQ_U64(m, n); /* 3D: a site may steal nothing */
        for (int k = 0; k < 300 && !LH_FAILED(); k++) {
            double q[3];
            point_in_simplex(t, x, lh_fam_rnd() % lh_tri_count(t), 0.0, q);
            coords_checked(lh_t_, t, x, q, s, w);
        }
        lh_tri_free(t);
        free(x);
    }
    free(s);
    free(w);
}

/* ---- the brute force (2D) ------------------------------------------------------- */

/* Clips the convex polygon p (m vertices, room for m+1) to {y : (y - a).u <= 0}. */
static int clip(double (*p)[2], int m, const double *a, const double *u)
{
    double r[64][2];
    int k = 0;
    for (int i = 0; i < m; i++) {
        const double *P = p[i], *Q = p[(i + 1) % m];
        double sp = (P[0] - a[0]) * u[0] + (P[1] - a[1]) * u[1];
        double sq = (Q[0] - a[0]) * u[0] + (Q[1] - a[1]) * u[1];
        if (sp <= 0) r[k][0] = P[0], r[k][1] = P[1], k++;
        if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
            double f = sp / (sp - sq);
            r[k][0] = P[0] + f * (Q[0] - P[0]);
            r[k][1] = P[1] + f * (Q[1] - P[1]);
            k++;
        }
    }
    memcpy(p, r, (size_t)k * sizeof *r);
    return k;
}

/* Clips p to the points nearer to b than to c. */
static int clip_bisector(double (*p)[2], int m, const double *b, const double *c)
{
    double mid[2] = {(b[0] + c[0]) / 2, (b[1] + c[1]) / 2}, u[2] = {c[0] - b[0], c[1] - b[1]};
    return clip(p, m, mid, u);
}

static double area(double (*p)[2], int m)
{
    double a = 0;
    for (int i = 1; i + 1 < m; i++)
        a += (p[i][0] - p[0][0]) * (p[i + 1][1] - p[0][1]) - (p[i][1] - p[0][1]) * (p[i + 1][0] - p[0][0]);
    return a / 2;
}

/* Sibson's weights by definition: q's Voronoi cell among all sites and q, cut by
 * each old cell; sites assumed distinct. */
static void brute_force(size_t n, const double *x, const double *q, double *bw)
{
    double cell[64][2], p[64][2], r = 1e7;
    int m = 0;
    for (int pass = 0; pass < 2; pass++) { /* the second in a box just round the cell */
        double box[4][2] = {{q[0] - r, q[1] - r}, {q[0] + r, q[1] - r}, {q[0] + r, q[1] + r}, {q[0] - r, q[1] + r}};
        memcpy(cell, box, sizeof box);
        m = 4;
        for (size_t j = 0; j < n; j++) m = clip_bisector(cell, m, q, x + 2 * j);
        r = 0;
        for (int i = 0; i < m; i++) r = fmax(r, 2 * fmax(fabs(cell[i][0] - q[0]), fabs(cell[i][1] - q[1])));
    }
    double total = 0;
    for (size_t i = 0; i < n; i++) {
        int k = m;
        memcpy(p, cell, sizeof cell);
        for (size_t j = 0; j < n && k > 2; j++)
            if (j != i) k = clip_bisector(p, k, x + 2 * i, x + 2 * j);
        bw[i] = k > 2 ? area(p, k) : 0;
        total += bw[i];
    }
    for (size_t i = 0; i < n; i++) bw[i] /= total;
}

LH_TEST(brute_force_2d)
{
    for (int r = 0; r < 40 && !LH_FAILED(); r++) {
        size_t n = 8 + (size_t)r % 25;
        double *x = make_sites(r % 3 ? F_CUBE : F_CLUSTERS, 2, &n, 1000 + r);
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(2, n, x, NULL, &t), LH_OK);
        for (int k = 0; k < 50 && !LH_FAILED(); k++) {
            double q[2], bw[64];
            lh_index s[64];
            double w[64];
            point_in_simplex(t, x, lh_fam_rnd() % lh_tri_count(t), 0.02, q);
            size_t m = coords_checked(lh_t_, t, x, q, s, w);
            brute_force(n, x, q, bw);
            double err = 0;
            for (size_t i = 0, j = 0; i < n; i++) {
                double got = j < m && (size_t)s[j] == i ? w[j++] : 0;
                err = fmax(err, fabs(got - bw[i]));
            }
            LH_EXPECT_TRUE(err < 1e-9);
            if (LH_FAILED()) {
                LH_NOTE("r %d n %zu q = (%.17g, %.17g)", r, n, q[0], q[1]);
                for (size_t i = 0, j = 0; i < n; i++) {
                    double got = j < m && (size_t)s[j] == i ? w[j++] : 0;
                    LH_NOTE("site %zu (%.17g, %.17g) got %.17g brute %.17g", i, x[2*i], x[2*i+1], got, bw[i]);
                }
            }
            max_brute_err = fmax(max_brute_err, err);
        }
        lh_tri_free(t);
        free(x);
    }
}

/* The result does not depend on the hint (the walk's start): the same bits. */
LH_TEST(independent_of_hint)
{
    for (int d = 2; d <= 3; d++) {
        size_t n = 200;
        double *x = make_sites(F_BALL, d, &n, 17);
        lh_tri *t;
        LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, NULL, &t), LH_OK);
        for (int k = 0; k < 100; k++) {
            double q[3];
            point_in_simplex(t, x, lh_fam_rnd() % lh_tri_count(t), 0.0, q);
            lh_index s0[256], s1[256];
            double w0[256], w1[256];
            size_t m0, m1;
            LH_ASSERT_EQ_INT(lh_tri_natural_coords(t, q, -1, 256, s0, w0, &m0), LH_OK);
            lh_index hint = (lh_index)(lh_fam_rnd() % lh_tri_count(t));
            LH_ASSERT_EQ_INT(lh_tri_natural_coords(t, q, hint, 256, s1, w1, &m1), LH_OK);
            LH_ASSERT_EQ_U64(m0, m1);
            LH_EXPECT_TRUE(!memcmp(s0, s1, m0 * sizeof *s0) && !memcmp(w0, w1, m0 * sizeof *w0));
        }
        lh_tri_free(t);
        free(x);
    }
}

/* ---- allocation failures --------------------------------------------------------- */

typedef struct alloc_case {
    int d, fam;
    size_t n;
    double q[3];
} alloc_case;

/* Builds a triangulation with allocator a and asks for q's coordinates (the
 * cospherical case's cavity outgrows the first workspace: a second allocation). */
static lh_status alloc_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const alloc_case *c = user;
    size_t n = c->n;
    double *x = make_sites(c->fam, c->d, &n, 23);
    lh_options opt;
    lh_options_default(&opt);
    opt.alloc = a;
    lh_tri *t = NULL;
    lh_status st = lh_delaunay(c->d, n, x, &opt, &t);
    if (st == LH_OK) {
        lh_index s[CAP];
        double w[CAP];
        size_t m = 7;
        st = lh_tri_natural_coords(t, c->q, -1, CAP, s, w, &m);
        if (st == LH_OK) check_coords(lh_t_, t, x, c->q, m, s, w);
        else LH_EXPECT_EQ_U64(m, 0);
    } else {
        LH_EXPECT_TRUE(t == NULL);
    }
    lh_tri_free(t);
    free(x);
    return st;
}

LH_TEST(every_allocation_failure)
{
    static const alloc_case cases[] = {
        {2, F_CUBE, 50, {0.5, 0.5, 0}},
        {3, F_CUBE, 50, {0.5, 0.5, 0.5}},
        {2, F_SPHERE_EXACT, 200, {0, 0, 0}},
        {3, F_SPHERE_EXACT, 150, {0, 0, 0}},
    };
    for (size_t i = 0; i < LH_COUNT(cases); i++) LH_EXPECT_TRUE(lh_test_every_failure(lh_t_, alloc_run, &cases[i]) > 1);
}

LH_TEST(report_errors)
{
    (void)lh_t_;
    printf("natural coords: max |sum-1| %.3g, max linear-precision error %.3g, max error against brute force %.3g\n",
           max_sum_err, max_lin_err, max_brute_err);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(random_sites_linear_precision), LH_CASE(nearly_collinear_hull_sites_3d),
        LH_CASE(near_the_hull),                 LH_CASE(query_at_site),
        LH_CASE(query_on_hull_boundary),        LH_CASE(query_outside_and_bad_arguments),
        LH_CASE(cap_too_small),                 LH_CASE(unsupported_dimensions),
        LH_CASE(degenerate_sites),              LH_CASE(brute_force_2d),
        LH_CASE(independent_of_hint),           LH_CASE(every_allocation_failure),
        LH_CASE(report_errors),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
