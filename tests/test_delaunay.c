/* test_delaunay.c — the Delaunay engine: the exact check (lh_tri_check) passes on
 * every output, across the input families of the engine issue, in d = 2..6; the
 * output depends only on the site set; bad input gets its status; every allocation
 * failure is survived without a leak. */
#include "lh_families.h"
#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const size_t size_for_dim[7] = {0, 0, 3000, 1500, 400, 150, 60};

/* The documented canonical form: each simplex increasing but for its last two
 * entries, which may be exchanged (to keep orient_d > 0), and the simplices in
 * strictly increasing lexicographic order. */
static void expect_canonical_order(lh_test_state *lh_t_, const lh_tri *t)
{
    const int m = lh_tri_simplex_dim(t) + 1;
    const lh_index *s = lh_tri_simplices(t);
    size_t bad_rows = 0, bad_order = 0;
    for (size_t i = 0; i < lh_tri_count(t); i++) {
        const lh_index *r = s + i * m;
        for (int k = 0; k + 2 < m; k++) bad_rows += !(r[k] < r[k + 1]);
        bad_rows += !(r[m - 3] < r[m - 1]) + (r[m - 2] == r[m - 1]);
        if (i == 0) continue;
        int k = 0;
        while (k < m && r[k] == r[k - m]) k++;
        bad_order += !(k < m && r[k - m] < r[k]);
    }
    LH_EXPECT_EQ_U64(bad_rows, 0);
    LH_EXPECT_EQ_U64(bad_order, 0);
}

static void check_tri(lh_test_state *lh_t_, int d, size_t n, const double *x, const char *what)
{
    lh_tri *t = NULL;
    lh_status st = lh_delaunay(d, n, x, NULL, &t);
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st != LH_OK) {
        LH_NOTE("%s, d=%d n=%zu: %s", what, d, n, lh_status_message(st));
        return;
    }
    lh_error err;
    st = lh_tri_check(t, &err);
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st != LH_OK) LH_NOTE("%s, d=%d n=%zu: %s", what, d, n, err.message);
    LH_EXPECT_GT_U64(lh_tri_count(t), 0);
    expect_canonical_order(lh_t_, t);
    lh_tri_free(t);
}

LH_TEST(every_family_passes_the_exact_check)
{
    for (int d = 2; d <= 6 && !LH_FAILED(); d++) {
        size_t n = size_for_dim[d];
        double *x = malloc(n * d * sizeof *x);
        LH_ASSERT_TRUE(x != NULL);
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++) {
            lh_fam_seed((uint64_t)(d * 100 + fam));
            size_t m = lh_fam_make(fam, d, n, x);
            check_tri(lh_t_, d, m, x, lh_fam_name[fam]);
        }
        free(x);
    }
}

LH_TEST(smallest_inputs)
{
    for (int d = 2; d <= 8; d++) {
        double x[10 * 8];
        for (int extra = 0; extra <= 1; extra++) {
            lh_fam_seed((uint64_t)d);
            for (int i = 0; i < (d + 1 + extra) * d; i++) x[i] = lh_fam_unif();
            lh_tri *t;
            LH_ASSERT_EQ_INT(lh_delaunay(d, (size_t)(d + 1 + extra), x, NULL, &t), LH_OK);
            size_t want_lo = extra ? 2 : 1, want_hi = extra ? (size_t)d + 1 : 1;
            LH_EXPECT_LE_U64(want_lo, lh_tri_count(t));
            LH_EXPECT_LE_U64(lh_tri_count(t), want_hi);
            LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
            lh_tri_free(t);
        }
    }
}

/* Canonical text of a triangulation with sites renamed through `name`. */
static char *signature(const lh_tri *t, const lh_index *name)
{
    int nv = lh_tri_dim(t) + 1;
    size_t count = lh_tri_count(t);
    lh_index *s = malloc(count * nv * sizeof *s);
    for (size_t i = 0; i < count * nv; i++) s[i] = name ? name[lh_tri_simplices(t)[i]] : lh_tri_simplices(t)[i];
    for (size_t i = 0; i < count; i++) /* sort each simplex (orientation ignored) */
        for (int a = 1; a < nv; a++)
            for (int b = a; b > 0 && s[i * nv + b] < s[i * nv + b - 1]; b--) {
                lh_index tmp = s[i * nv + b];
                s[i * nv + b] = s[i * nv + b - 1];
                s[i * nv + b - 1] = tmp;
            }
    for (size_t i = 1; i < count; i++) /* insertion sort of rows: small inputs only */
        for (size_t j = i; j > 0 && memcmp(s + j * nv, s + (j - 1) * nv, nv * sizeof *s) < 0; j--)
            for (int k = 0; k < nv; k++) {
                lh_index tmp = s[j * nv + k];
                s[j * nv + k] = s[(j - 1) * nv + k];
                s[(j - 1) * nv + k] = tmp;
            }
    char *out = malloc(count * nv * 21 + 1), *o = out;
    for (size_t i = 0; i < count * nv; i++) o += sprintf(o, "%" LH_INDEX_PRI " ", s[i]);
    *o = 0;
    free(s);
    return out;
}

LH_TEST(output_depends_only_on_the_site_set)
{
    for (int d = 2; d <= 4 && !LH_FAILED(); d++) {
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++) {
            if (fam != F_CUBE && fam != F_GRID && fam != F_SPHERE_EXACT && fam != F_DUPLICATES) continue;
            size_t n = d == 2 ? 300 : d == 3 ? 200 : 80;
            double *x = malloc(n * d * sizeof *x), *y = malloc(n * d * sizeof *y);
            lh_index *perm = malloc(n * sizeof *perm), *inv = malloc(n * sizeof *inv);
            lh_fam_seed((uint64_t)(7 * d + fam));
            n = lh_fam_make(fam, d, n, x);
            for (size_t i = 0; i < n; i++) perm[i] = (lh_index)i;
            for (size_t i = n - 1; i > 0; i--) {
                size_t j = lh_fam_rnd() % (i + 1);
                lh_index tmp = perm[i];
                perm[i] = perm[j];
                perm[j] = tmp;
            }
            for (size_t i = 0; i < n; i++) { /* y[i] = x[perm[i]] */
                memcpy(y + i * d, x + (size_t)perm[i] * d, d * sizeof *y);
                inv[i] = perm[i];
            }
            lh_options o1, o2;
            lh_options_default(&o1);
            lh_options_default(&o2);
            o2.seed = 12345;
            lh_tri *a, *b, *c;
            LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, &o1, &a), LH_OK);
            LH_ASSERT_EQ_INT(lh_delaunay(d, n, x, &o2, &b), LH_OK);
            LH_ASSERT_EQ_INT(lh_delaunay(d, n, y, &o1, &c), LH_OK);
            /* Another seed: byte-identical arrays. */
            LH_EXPECT_EQ_U64(lh_tri_count(a), lh_tri_count(b));
            LH_EXPECT_TRUE(memcmp(lh_tri_simplices(a), lh_tri_simplices(b), lh_tri_count(a) * (d + 1) * 4) == 0);
            LH_EXPECT_TRUE(memcmp(lh_tri_neighbors(a), lh_tri_neighbors(b), lh_tri_count(a) * (d + 1) * 4) == 0);
            /* Permuted lines: the same triangulation once renamed (duplicates aside,
             * where the representative legitimately changes with the order). */
            if (fam != F_DUPLICATES) {
                char *sa = signature(a, NULL), *sc = signature(c, inv);
                LH_EXPECT_TRUE(strcmp(sa, sc) == 0);
                if (LH_FAILED()) LH_NOTE("d=%d family %s", d, lh_fam_name[fam]);
                free(sa);
                free(sc);
            }
            lh_tri_free(a);
            lh_tri_free(b);
            lh_tri_free(c);
            free(x);
            free(y);
            free(perm);
            free(inv);
        }
    }
}

/* Site 0 at the centre of n - 1 sites on a circle: it is in every triangle and is
 * every triangle's smallest index (the output sort's largest possible bucket:
 * hull/cell_sort.c orders it through positions up to 4096 rows, by heapsort above).
 * Another seed gives the same bytes. */
static void centre_of_a_circle(lh_test_state *lh_t_, int n)
{
    double *x = malloc(2 * (size_t)n * sizeof *x);
    x[0] = x[1] = 0;
    for (int i = 1; i < n; i++) {
        x[2 * i] = cos(6.283185307179586 * i / (n - 1));
        x[2 * i + 1] = sin(6.283185307179586 * i / (n - 1));
    }
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, n, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_count(t), n - 1);
    for (size_t s = 0; s < lh_tri_count(t); s++) LH_EXPECT_EQ_INT(lh_tri_simplices(t)[3 * s], 0);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    expect_canonical_order(lh_t_, t);
    lh_options o;
    lh_options_default(&o);
    o.seed = 99;
    lh_tri *u;
    LH_ASSERT_EQ_INT(lh_delaunay(2, n, x, &o, &u), LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(t, u));
    if (LH_FAILED()) LH_NOTE("n=%d", n);
    lh_tri_free(t);
    lh_tri_free(u);
    free(x);
}

LH_TEST(a_vertex_of_huge_degree)
{
    centre_of_a_circle(lh_t_, 20001); /* heapsort */
    centre_of_a_circle(lh_t_, 3001);  /* sorted positions */
    centre_of_a_circle(lh_t_, 18);    /* just above insertion sort */
}

/* A 4x4x4 grid scaled by 2^40 + 1: its exact zeros (cospherical cube corners,
 * coplanar faces) are too wide for the granularity rule and are proven by residues;
 * every nonzero sign is the filter's. The stages add up to the calls. */
LH_TEST(predicate_counters_report_the_stages)
{
    double x[64 * 3];
    for (int i = 0; i < 64; i++) {
        x[3 * i] = (i % 4) * (0x1p40 + 1);
        x[3 * i + 1] = (i / 4 % 4) * (0x1p40 + 1);
        x[3 * i + 2] = (i / 16) * (0x1p40 + 1);
    }
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(3, 64, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_pred_counters c;
    lh_tri_pred_counters_get(t, &c);
    LH_EXPECT_GT_U64(c.calls, 0);
    LH_EXPECT_EQ_U64(c.filter_exits + c.grid_exits + c.residue_exits + c.exact_exits, c.calls);
    LH_EXPECT_GT_U64(c.residue_exits, 0);
    LH_EXPECT_EQ_U64(c.exact_exits, 0);
    LH_EXPECT_GT_U64(c.zero_results, 0);
    lh_tri_free(t);
    lh_tri_pred_counters_get(NULL, &c);
    LH_EXPECT_EQ_U64(c.calls, 0);
}

LH_TEST(duplicates_are_merged_and_reported)
{
    double x[] = {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 1, 0, 0};
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 7, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_duplicate_count(t), 3);
    const lh_index *dup = lh_tri_duplicate_of(t);
    LH_EXPECT_EQ_INT(dup[3], 1);
    LH_EXPECT_EQ_INT(dup[4], 0);
    LH_EXPECT_EQ_INT(dup[6], 0);
    LH_EXPECT_EQ_INT(dup[5], 5);
    LH_EXPECT_EQ_INT(lh_tri_vertex_simplex(t)[4], -1);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 2); /* the unit square, split in two */
    LH_EXPECT_EQ_U64(lh_tri_hull_count(t), 4);
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_tri_free(t);
}

/* Distinct sites 1e-9 apart share a key cell with the copies of each other:
 * `copies` copies of each of three such sites, interleaved, beside the unit
 * square's corners. A run of at most 8 equal keys is searched pair by pair, a
 * longer one sorted (hull/order.c); both must map every copy to its first
 * occurrence and keep the three sites apart. */
static void crowded_cell(lh_test_state *lh_t_, int copies)
{
    const double near[3][2] = {{0.5, 0.5}, {0.5 + 1e-9, 0.5}, {0.5, 0.5 + 1e-9}};
    double x[2 * (4 + 3 * 10)] = {0, 0, 1, 0, 0, 1, 1, 1};
    const int n = 4 + 3 * copies;
    for (int i = 4; i < n; i++) {
        x[2 * i] = near[(i - 4) % 3][0];
        x[2 * i + 1] = near[(i - 4) % 3][1];
    }
    lh_tri *t;
    LH_ASSERT_EQ_INT(lh_delaunay(2, (size_t)n, x, NULL, &t), LH_OK);
    LH_EXPECT_EQ_U64(lh_tri_duplicate_count(t), (uint64_t)(3 * copies - 3));
    const lh_index *dup = lh_tri_duplicate_of(t);
    for (int i = 0; i < n; i++) LH_EXPECT_EQ_INT(dup[i], i < 7 ? i : 4 + (i - 4) % 3);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 8); /* 7 vertices, 4 on the hull: 2*7 - 4 - 2 */
    LH_EXPECT_EQ_INT(lh_tri_check(t, NULL), LH_OK);
    lh_tri_free(t);
}

LH_TEST(duplicates_in_one_morton_cell_short_and_long_runs)
{
    crowded_cell(lh_t_, 2);  /* a run of 6 */
    crowded_cell(lh_t_, 10); /* a run of 30 */
}

LH_TEST(bad_input_gets_its_status)
{
    double x[4 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}; /* coplanar in 3D */
    lh_tri *t = (lh_tri *)x;
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, x, NULL, &t), LH_ERR_DEGENERATE);
    LH_EXPECT_TRUE(t == NULL);
    int k = 99;
    LH_EXPECT_EQ_INT(lh_coords_affine_dim(3, 4, x, NULL, &k), LH_OK);
    LH_EXPECT_EQ_INT(k, 2);
    double line[6 * 2] = {0, 0, 1, 1, 2, 2, 3, 3, 5, 5, 8, 8};
    LH_EXPECT_EQ_INT(lh_delaunay(2, 6, line, NULL, &t), LH_ERR_DEGENERATE);
    LH_EXPECT_EQ_INT(lh_coords_affine_dim(2, 6, line, NULL, &k), LH_OK);
    LH_EXPECT_EQ_INT(k, 1);
    LH_EXPECT_EQ_INT(lh_delaunay(2, 0, x, NULL, &t), LH_ERR_DEGENERATE); /* empty */
    LH_EXPECT_EQ_INT(lh_delaunay(2, 1, x, NULL, &t), LH_ERR_DEGENERATE); /* one site */
    LH_EXPECT_EQ_INT(lh_delaunay(3, 3, x, NULL, &t), LH_ERR_DEGENERATE); /* n < d+1 */
    LH_EXPECT_EQ_INT(lh_coords_affine_dim(2, 1, x, NULL, &k), LH_OK);
    LH_EXPECT_EQ_INT(k, 0);
    LH_EXPECT_EQ_INT(lh_delaunay(1, 4, x, NULL, &t), LH_ERR_DIMENSION);
    LH_EXPECT_EQ_INT(lh_delaunay(9, 4, x, NULL, &t), LH_ERR_DIMENSION);
    LH_EXPECT_EQ_INT(lh_delaunay(3, SIZE_MAX / 8, x, NULL, &t), LH_ERR_TOO_LARGE);
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, NULL, NULL, &t), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, x, NULL, NULL), LH_ERR_INVALID_ARGUMENT);
    double y[4 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    y[5] = NAN;
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, y, NULL, &t), LH_ERR_NONFINITE);
    y[5] = -INFINITY;
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, y, NULL, &t), LH_ERR_NONFINITE);
    y[5] = 0;
    LH_EXPECT_EQ_INT(lh_delaunay(3, 4, y, NULL, &t), LH_OK);
    lh_tri_free(t);
}

LH_TEST(the_check_rejects_what_is_not_delaunay)
{
    /* A unit square split along the wrong diagonal of a non-cocircular quad. */
    double x[] = {0, 0, 2, 0, 2, 1, 0, 1.2};
    lh_index good[] = {0, 1, 2, 0, 2, 3}, bad[] = {0, 1, 3, 1, 2, 3}, flat[] = {0, 1, 1};
    lh_error err;
    lh_status a = lh_delaunay_check(2, 4, x, 2, good, NULL, &err);
    lh_status b = lh_delaunay_check(2, 4, x, 2, bad, NULL, &err);
    LH_EXPECT_TRUE((a == LH_OK) != (b == LH_OK)); /* exactly one diagonal is Delaunay */
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, 4, x, 1, good, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_TRUE(strstr(err.message, "site 3") != NULL); /* site 3 unused */
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, 4, x, 1, flat, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_TRUE(strstr(err.message, "repeats") != NULL);
    double c[] = {0, 0, 1, 0, 2, 0, 1, 1}; /* a flat triangle along y = 0 */
    lh_index cf[] = {0, 1, 3, 1, 2, 3, 0, 2, 1};
    LH_EXPECT_EQ_INT(lh_delaunay_check(2, 4, c, 3, cf, NULL, &err), LH_ERR_INVALID_MESH);
    LH_EXPECT_TRUE(strstr(err.message, "flat") != NULL);
}


enum { ALLOC_N = 400 };

/* lh_delaunay, then the calls on the handle that allocate (lh_tri_complex). */
static lh_status delaunay_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const double *x = user;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    lh_tri *t = (lh_tri *)x;
    lh_status st = lh_delaunay(3, ALLOC_N, x, &o, &t);
    if (st != LH_OK) {
        LH_EXPECT_TRUE(t == NULL);
        return st;
    }
    size_t count;
    const lh_index *off, *v;
    st = lh_tri_complex(t, &count, &off, &v);
    lh_location loc;
    if (st == LH_OK) st = lh_tri_locate(t, x, -1, &loc);
    if (st == LH_OK) st = lh_tri_check(t, NULL); /* through the handle's hooks too */
    lh_tri_free(t);
    return st;
}

static lh_status hull_run(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const double *x = user;
    lh_options o;
    lh_options_default(&o);
    o.alloc = a;
    lh_hull *h = (lh_hull *)x;
    lh_status st = lh_convex_hull(4, ALLOC_N * 3 / 4, x, &o, &h);
    if (st != LH_OK) {
        LH_EXPECT_TRUE(h == NULL);
        return st;
    }
    LH_EXPECT_GT_U64(lh_hull_facet_count(h), 5);
    lh_hull_free(h);
    return st;
}

LH_TEST(every_allocation_failure_is_survived)
{
    double x[ALLOC_N * 3];
    lh_fam_seed(5);
    for (int i = 0; i < ALLOC_N * 3; i++) x[i] = lh_fam_unif();
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, delaunay_run, x), 10); /* it allocates */
}

LH_TEST(every_allocation_failure_is_survived_by_the_hull)
{
    double x[ALLOC_N * 3]; /* 300 sites in 4D */
    lh_fam_seed(9);
    for (int i = 0; i < ALLOC_N * 3; i++) x[i] = lh_fam_unif();
    LH_EXPECT_GT_INT(lh_test_every_failure(lh_t_, hull_run, x), 10);
}

LH_TEST(furthest_site_triangulation)
{
    for (int d = 2; d <= 5 && !LH_FAILED(); d++) {
        for (int fam = 0; fam < F_COUNT && !LH_FAILED(); fam++) {
            if (fam != F_CUBE && fam != F_GRID && fam != F_SPHERE_EXACT && fam != F_DUPLICATES) continue;
            size_t n = d == 2 ? 400 : d == 3 ? 200 : d == 4 ? 90 : 100; /* > side^(d-1) */
            double *x = malloc(n * d * sizeof *x);
            lh_fam_seed((uint64_t)(31 * d + fam));
            n = lh_fam_make(fam, d, n, x);
            lh_options o;
            lh_options_default(&o);
            o.furthest_site = 1;
            lh_tri *t;
            lh_status st = lh_delaunay(d, n, x, &o, &t);
            LH_EXPECT_EQ_INT(st, LH_OK);
            if (st != LH_OK) {
                LH_NOTE("d=%d %s n=%zu: %s", d, lh_fam_name[fam], n, lh_status_message(st));
                free(x);
                return;
            }
            lh_error err;
            LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
            if (LH_FAILED()) LH_NOTE("d=%d %s: %s", d, lh_fam_name[fam], err.message);
            if (fam == F_CUBE) { /* general position: the vertices are the hull's */
                lh_hull *h;
                LH_ASSERT_EQ_INT(lh_convex_hull(d, n, x, NULL, &h), LH_OK);
                size_t used = 0;
                for (size_t i = 0; i < n; i++) used += lh_tri_vertex_simplex(t)[i] >= 0;
                LH_EXPECT_EQ_U64(used, lh_hull_vertex_count(h));
                for (size_t i = 0; i < lh_hull_vertex_count(h); i++)
                    LH_EXPECT_GE_INT(lh_tri_vertex_simplex(t)[lh_hull_vertices(h)[i]], 0);
                lh_hull_free(h);
            }
            lh_tri_free(t);
            free(x);
        }
    }
}

typedef struct progress_log {
    size_t calls, last, total;
    int monotone;
} progress_log;

static void on_progress(void *user, size_t done, size_t total)
{
    progress_log *p = user;
    p->monotone &= done > p->last && done <= total;
    p->calls++;
    p->last = done;
    p->total = total;
}

/* The progress hook: called every 2^16 sites, increasing, ending at the number of
 * distinct sites; the output is the same as without it. */
LH_TEST(progress_is_reported_and_changes_nothing)
{
    size_t n = 150000;
    double *x = malloc(n * 2 * sizeof *x);
    lh_fam_seed(3);
    n = lh_fam_make(F_DUPLICATES, 2, n, x);
    lh_options o;
    lh_options_default(&o);
    progress_log log = {0, 0, 0, 1};
    o.progress = on_progress;
    o.progress_user = &log;
    lh_tri *a, *b;
    LH_ASSERT_EQ_INT(lh_delaunay(2, n, x, &o, &a), LH_OK);
    LH_ASSERT_EQ_INT(lh_delaunay(2, n, x, NULL, &b), LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(a, b));
    LH_EXPECT_TRUE(log.monotone);
    LH_EXPECT_EQ_U64(log.calls, (n - lh_tri_duplicate_count(a) - 3 + 65535) / 65536);
    LH_EXPECT_EQ_U64(log.last, n - lh_tri_duplicate_count(a));
    LH_EXPECT_EQ_U64(log.total, log.last);
    lh_tri_free(a);
    lh_tri_free(b);
    free(x);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(furthest_site_triangulation),LH_CASE(every_allocation_failure_is_survived_by_the_hull),
        LH_CASE(every_family_passes_the_exact_check), LH_CASE(smallest_inputs),
        LH_CASE(output_depends_only_on_the_site_set), LH_CASE(a_vertex_of_huge_degree),
        LH_CASE(duplicates_are_merged_and_reported), LH_CASE(duplicates_in_one_morton_cell_short_and_long_runs), LH_CASE(predicate_counters_report_the_stages),
        LH_CASE(bad_input_gets_its_status), LH_CASE(the_check_rejects_what_is_not_delaunay),
        LH_CASE(every_allocation_failure_is_survived), LH_CASE(progress_is_reported_and_changes_nothing)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
