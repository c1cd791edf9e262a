/*
 * test_properties.c — invariants every triangulation must satisfy, on randomized
 * inputs: seeded and reproducible (LH_TEST_SEED=S starts at seed S; the failing seed
 * is printed), every family of lh_families.h, d = 2..5, small n. For each input:
 *   - the exact validity check (lh_tri_check);
 *   - the Euler relation of a triangulated d-ball: sum_k (-1)^k f_k = 1 over all faces;
 *   - hull coverage: the simplices' volumes sum to the convex hull's (lh_convex_hull,
 *     an independent computation) within 1e-9 relative;
 *   - every distinct site is a vertex (vertex_simplex holds it);
 *   - inserting a random part afterwards (lh_tri_insert) gives the batch result.
 */
#include "lh_api_test.h"
#include "lh_families.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAXV = 6 }; /* d <= 5 */

/* A set of sorted vertex tuples of one size (faces), open addressing. */
typedef struct faceset {
    lh_index *key; /* cap * m, first entry -1: empty */
    size_t cap, size;
    int m;
} faceset;

static uint64_t hash(const lh_index *t, int m)
{
    uint64_t h = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < m; i++) h = (h ^ (uint32_t)t[i]) * 0xff51afd7ed558ccdu;
    return h ^ (h >> 31);
}

static void set_add(faceset *s, const lh_index *t);

static void set_grow(faceset *s)
{
    faceset g = {malloc((s->cap ? 2 * s->cap : 1024) * s->m * sizeof(lh_index)), s->cap ? 2 * s->cap : 1024, 0, s->m};
    for (size_t i = 0; i < g.cap; i++) g.key[i * g.m] = -1;
    for (size_t i = 0; i < s->cap; i++)
        if (s->key[i * s->m] >= 0) set_add(&g, s->key + i * s->m);
    free(s->key);
    *s = g;
}

static void set_add(faceset *s, const lh_index *t)
{
    if (2 * (s->size + 1) > s->cap) set_grow(s);
    for (size_t h = hash(t, s->m) & (s->cap - 1);; h = (h + 1) & (s->cap - 1)) {
        lh_index *k = s->key + h * s->m;
        if (k[0] < 0) {
            memcpy(k, t, s->m * sizeof *t);
            s->size++;
            return;
        }
        if (!memcmp(k, t, s->m * sizeof *t)) return;
    }
}

/* sum_k (-1)^k f_k over every face of every simplex (vertices sorted per simplex). */
static long euler(const lh_tri *t)
{
    const int nv = lh_tri_simplex_dim(t) + 1;
    faceset f[MAXV];
    for (int m = 1; m <= nv; m++) f[m - 1] = (faceset){NULL, 0, 0, m};
    for (int m = 1; m <= nv; m++) set_grow(&f[m - 1]);
    for (size_t s = 0; s < lh_tri_count(t); s++) {
        lh_index v[MAXV], sub[MAXV];
        memcpy(v, lh_tri_simplices(t) + s * nv, nv * sizeof *v);
        for (int i = 1; i < nv; i++) /* insertion sort */
            for (int j = i; j > 0 && v[j - 1] > v[j]; j--) {
                lh_index x = v[j];
                v[j] = v[j - 1];
                v[j - 1] = x;
            }
        for (int mask = 1; mask < (1 << nv); mask++) {
            int m = 0;
            for (int i = 0; i < nv; i++)
                if (mask & (1 << i)) sub[m++] = v[i];
            set_add(&f[m - 1], sub);
        }
    }
    long chi = 0;
    for (int m = 1; m <= nv; m++) {
        chi += (m % 2 ? 1 : -1) * (long)f[m - 1].size;
        free(f[m - 1].key);
    }
    return chi;
}

/* |det| of the k vectors rows (k x k, destroyed). */
static double absdet(double *a, int k)
{
    double r = 1;
    for (int c = 0; c < k; c++) {
        int p = c;
        for (int i = c + 1; i < k; i++)
            if (fabs(a[i * k + c]) > fabs(a[p * k + c])) p = i;
        if (a[p * k + c] == 0) return 0;
        for (int j = 0; j < k; j++) {
            double x = a[c * k + j];
            a[c * k + j] = a[p * k + j];
            a[p * k + j] = x;
        }
        r *= a[c * k + c];
        for (int i = c + 1; i < k; i++) {
            double g = a[i * k + c] / a[c * k + c];
            for (int j = c; j < k; j++) a[i * k + j] -= g * a[c * k + j];
        }
    }
    return fabs(r);
}

/* d! times the volume of the simplex with apex o over the m = d points v (or the
 * d+1 points of a full simplex when o is NULL). */
static double cone(int d, const double *x, const double *o, const lh_index *v)
{
    double a[MAXV * MAXV];
    const double *base = o ? o : x + (size_t)v[0] * d;
    for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++) a[i * d + j] = x[(size_t)v[i + !o] * d + j] - base[j];
    return absdet(a, d);
}

static void check_volume(lh_test_state *lh_t_, int d, size_t n, const double *x, const lh_tri *t)
{
    lh_hull *h;
    LH_ASSERT_EQ_INT(lh_convex_hull(d, n, x, NULL, &h), LH_OK);
    double c[MAXV] = {0}, hv = 0, tv = 0;
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < d; j++) c[j] += x[i * d + j] / (double)n;
    for (size_t f = 0; f < lh_hull_facet_count(h); f++) hv += cone(d, x, c, lh_hull_facets(h) + f * d);
    for (size_t s = 0; s < lh_tri_count(t); s++) tv += cone(d, x, NULL, lh_tri_simplices(t) + s * (d + 1));
    lh_hull_free(h);
    LH_EXPECT_LE_DBL(fabs(hv - tv), 1e-9 * hv);
}

/* Inserting the last third afterwards gives the batch triangulation. */
static void check_insert(lh_test_state *lh_t_, int d, size_t n, const double *x, const lh_tri *batch)
{
    size_t first = n - n / 3;
    lh_tri *t;
    if (lh_delaunay(d, first, x, NULL, &t) != LH_OK) return; /* the first part may be flat */
    LH_ASSERT_EQ_INT(lh_tri_insert(t, n - first, x + first * d), LH_OK);
    LH_EXPECT_TRUE(lh_test_same_tri(t, batch));
    lh_tri_free(t);
}

static void one_input(lh_test_state *lh_t_, uint64_t seed)
{
    lh_fam_seed(seed);
    int fam = (int)(seed % F_COUNT), d = 2 + (int)(seed / F_COUNT % 4);
    size_t n = (size_t)(d + 2) + lh_fam_rnd() % (d <= 3 ? 150 : 60);
    double *x = malloc(n * d * sizeof *x);
    n = lh_fam_make(fam, d, n, x);
    lh_tri *t;
    lh_status st = lh_delaunay(d, n, x, NULL, &t);
    long fails = lh_t_->failures;
    if (st == LH_OK) {
        lh_error err;
        LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
        LH_EXPECT_EQ_INT(euler(t), 1);
        check_volume(lh_t_, d, n, x, t);
        for (size_t i = 0; i < n; i++)
            if (lh_tri_duplicate_of(t)[i] == (lh_index)i) LH_EXPECT_TRUE(lh_tri_vertex_simplex(t)[i] >= 0);
        check_insert(lh_t_, d, n, x, t);
        lh_tri_free(t);
    } else {
        int k;
        LH_EXPECT_EQ_INT(st, LH_ERR_DEGENERATE);
        LH_EXPECT_EQ_INT(lh_coords_affine_dim(d, n, x, NULL, &k), LH_OK);
        LH_EXPECT_LT_INT(k, d);
    }
    if (lh_t_->failures != fails)
        LH_NOTE("seed %llu: d=%d, %zu sites of family '%s' (rerun: LH_TEST_SEED=%llu)", (unsigned long long)seed, d, n,
                lh_fam_name[fam], (unsigned long long)seed);
    free(x);
}

LH_TEST(randomized_invariants)
{
    const char *env = getenv("LH_TEST_SEED");
    uint64_t base = env ? strtoull(env, NULL, 10) : 1;
    int count = env ? 1 : 4 * F_COUNT * 4; /* every family in every d, four times */
    for (int i = 0; i < count && lh_t_->failures < 5; i++) one_input(lh_t_, base + (uint64_t)i);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(randomized_invariants)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
