/*
 * fuzz_check.c — libFuzzer target: the exact checker lh_delaunay_check on fuzzer-chosen
 * sites (d = 2..4, small integers: coarse grids, so degenerate, or int8 values, so
 * often in general position) and fuzzer-chosen simplex lists:
 *   A. an arbitrary list (invalid indices -1 and n, repeated vertices, flat simplices,
 *      too few or too many simplices);
 *   B. lh_delaunay's triangulation of the same sites, as it is and with every
 *      simplex's vertices rotated and the simplices in another order;
 *   C. that triangulation with one or two edits (a vertex replaced, a simplex dropped,
 *      doubled or added, two vertices of two simplices exchanged).
 * It must never crash or leak, and:
 *   - the real triangulation, in any vertex and simplex order, is accepted;
 *   - a list equal to it as a multiset of vertex sets is accepted; when the sites are
 *     in general position (distinct, no d+2 of them with insphere 0, so the Delaunay
 *     triangulation is unique) every other list is rejected;
 *   - whatever is accepted passes a brute-force check that does not use the checker's
 *     local arguments: indices valid and distinct, no simplex flat, no site strictly
 *     inside any simplex's circumsphere, every site a vertex or equal to one, and the
 *     volumes (exact integer determinants) summing to those of lh_delaunay's simplices,
 *     i.e. to the convex hull's volume;
 *   - a rejection leaves one printable line in msg, an acceptance "".
 * (Except the known finding check_cover, below.)
 * Anything else aborts. Build as fuzz_delaunay.c (fuzz/README.md).
 */
#include "lifthull.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Finding check_cover (fuzz/findings/check_cover.md): lh_delaunay_check accepted lists
 * whose simplices overlap (a disk immersed in R^d, not embedded, with locally convex
 * boundary and locally Delaunay facets); fixed by its exact volume comparison
 * (lift/check.c, check_volume). An accepted list that fails the brute-force global
 * check aborts. */

#define MAXD 4
#define MAXN 12
#define MAXS 256/* simplices in a list */

typedef struct bytes {
    const uint8_t *p;
    size_t left;
} bytes;

static unsigned next(bytes *b)
{
    if (!b->left) return 0;
    b->left--;
    return *b->p++;
}

typedef struct list {
    size_t count;
    lh_index v[MAXS * (MAXD + 1)];
} list;

static const double *site(const double *x, int d, lh_index i) { return x + (size_t)i * d; }

/* The sign-exact determinant of the d x d matrix [p_i - p_0] for integer sites
 * (|coordinate| <= 128, so |entries| <= 256 and Bareiss's minors fit in int64). */
static int64_t det_int(int d, const double *x, const lh_index *v)
{
    int64_t m[MAXD][MAXD], prev = 1;
    int sign = 1;
    for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++)
            m[i][j] = (int64_t)(site(x, d, v[i + 1])[j] - site(x, d, v[0])[j]);
    for (int k = 0; k < d - 1; k++) {
        if (m[k][k] == 0) {
            int r = k + 1;
            while (r < d && m[r][k] == 0) r++;
            if (r == d) return 0;
            for (int j = 0; j < d; j++) {
                int64_t t = m[k][j];
                m[k][j] = m[r][j];
                m[r][j] = t;
            }
            sign = -sign;
        }
        for (int i = k + 1; i < d; i++)
            for (int j = k + 1; j < d; j++) m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) / prev;
        prev = m[k][k];
    }
    return sign * m[d - 1][d - 1];
}

static int cmp_rows(const lh_index *a, const lh_index *b, int w)
{
    for (int k = 0; k < w; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

static int row_w;
static int cmp_row(const void *a, const void *b) { return cmp_rows(a, b, row_w); }

/* Each simplex's vertices sorted, then the simplices sorted: the multiset of sets. */
static void canonical(int d, const list *in, list *out)
{
    int w = d + 1;
    out->count = in->count;
    memcpy(out->v, in->v, in->count * (size_t)w * sizeof *in->v);
    for (size_t s = 0; s < out->count; s++) {
        lh_index *v = out->v + s * w;
        for (int a = 1; a < w; a++)
            for (int b = a; b > 0 && v[b] < v[b - 1]; b--) {
                lh_index t = v[b];
                v[b] = v[b - 1];
                v[b - 1] = t;
            }
    }
    row_w = w;
    qsort(out->v, out->count, (size_t)w * sizeof *out->v, cmp_row);
}

static int same_multiset(int d, const list *a, const list *b)
{
    static list ca, cb;
    if (a->count != b->count) return 0;
    canonical(d, a, &ca);
    canonical(d, b, &cb);
    return !memcmp(ca.v, cb.v, a->count * (size_t)(d + 1) * sizeof *ca.v);
}

/* Distinct sites, and no d+2 of them with insphere 0. */
static int general_position(lh_pred *p, int d, size_t n, const double *x)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < i; j++)
            if (!memcmp(site(x, d, (lh_index)i), site(x, d, (lh_index)j), (size_t)d * sizeof *x)) return 0;
    int m = d + 2, idx[MAXD + 2];
    if ((int)n < m) return 1;
    for (int k = 0; k < m; k++) idx[k] = k;
    for (;;) {
        const double *pts[MAXD + 2];
        for (int k = 0; k < m; k++) pts[k] = site(x, d, idx[k]);
        if (lh_insphere(p, d, pts) == 0) return 0;
        int k = m - 1;
        while (k >= 0 && idx[k] == (int)n - m + k) k--;
        if (k < 0) return 1;
        idx[k]++;
        for (int j = k + 1; j < m; j++) idx[j] = idx[j - 1] + 1;
    }
}

/* The brute-force check of an accepted list (see the header comment): aborts when an
 * index is bad, a simplex repeats a site or is flat. Returns 1 when the list is a
 * Delaunay triangulation (empty spheres, every site used, the hull's volume); else
 * aborts. */
static int brute_force(lh_pred *p, int d, size_t n, const double *x, const list *l, int64_t volume)
{
    int w = d + 1;
    uint8_t used[MAXN] = {0};
    int64_t sum = 0;
    int global = 1;
    for (size_t s = 0; s < l->count; s++) {
        lh_index v[MAXD + 1];
        memcpy(v, l->v + s * w, sizeof(lh_index) * (size_t)w);
        for (int k = 0; k < w; k++) {
            if (v[k] < 0 || (size_t)v[k] >= n) abort();
            for (int j = 0; j < k; j++)
                if (v[j] == v[k]) abort();
            used[v[k]] = 1;
        }
        const double *pts[MAXD + 2];
        for (int k = 0; k < w; k++) pts[k] = site(x, d, v[k]);
        int o = lh_orient(p, d, pts);
        int64_t det = det_int(d, x, v);
        if (o == 0 || (det > 0) != (o > 0)) abort(); /* flat, or the predicate disagrees */
        sum += det > 0 ? det : -det;
        if (o < 0) {
            const double *t = pts[0];
            pts[0] = pts[1];
            pts[1] = t;
        }
        for (size_t q = 0; q < n; q++) {
            pts[w] = site(x, d, (lh_index)q);
            global &= lh_insphere(p, d, pts) >= 0; /* q not strictly inside s's sphere */
        }
    }
    for (size_t i = 0; i < n; i++) {
        int ok = used[i];
        for (size_t j = 0; j < n && !ok; j++)
            ok = used[j] && !memcmp(site(x, d, (lh_index)i), site(x, d, (lh_index)j), (size_t)d * sizeof *x);
        global &= ok; /* site i a vertex or a duplicate of one */
    }
    global &= sum == volume; /* the simplices tile the convex hull */
    if (!global) abort();
    return global;
}

/* Runs the checker; checks the message contract; returns 1 when accepted. */
static int run(int d, size_t n, const double *x, const list *l, int with_msg)
{
    lh_error err;
    memset(err.message, 'x', sizeof err.message);
    lh_status st = lh_delaunay_check(d, n, x, l->count, l->v, NULL, with_msg ? &err : NULL);
    if (st != LH_OK && st != LH_ERR_INVALID_MESH) abort();
    if (with_msg) {
        if (err.status != st || err.line || err.column || err.index != LH_ERROR_NO_INDEX) abort();
        if ((st == LH_OK) != (err.message[0] == 0)) abort();
        for (const char *c = err.message; *c; c++)
            if (*c < 0x20 || *c > 0x7e || c - err.message >= (long)sizeof err.message - 1) abort();
    }
    return st == LH_OK;
}

static void edit(bytes *b, int d, size_t n, list *l)
{
    int w = d + 1;
    unsigned op = next(b) % 5;
    size_t s = l->count ? next(b) % l->count : 0;
    lh_index vtx = (lh_index)(next(b) % (n + 2)) - 1; /* -1 .. n: invalid ones too */
    int k = (int)(next(b) % (unsigned)w);
    switch (op) {
    case 0: /* replace one vertex */
        if (l->count) l->v[s * w + k] = vtx;
        break;
    case 1: /* drop a simplex */
        if (l->count) {
            memmove(l->v + s * w, l->v + (s + 1) * w, (l->count - s - 1) * (size_t)w * sizeof *l->v);
            l->count--;
        }
        break;
    case 2: /* double a simplex */
        if (l->count && l->count < MAXS) {
            memcpy(l->v + l->count * w, l->v + s * w, (size_t)w * sizeof *l->v);
            l->count++;
        }
        break;
    case 3: /* add a simplex */
        if (l->count < MAXS) {
            for (int j = 0; j < w; j++) l->v[l->count * w + j] = (lh_index)(next(b) % (n + 2)) - 1;
            l->count++;
        }
        break;
    default: /* exchange vertices of two simplices */
        if (l->count) {
            size_t s2 = next(b) % l->count;
            int k2 = (int)(next(b) % (unsigned)w);
            lh_index t = l->v[s * w + k];
            l->v[s * w + k] = l->v[s2 * w + k2];
            l->v[s2 * w + k2] = t;
        }
        break;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const int maxn[MAXD + 1] = {0, 0, 12, 10, 9};
    if (size < 3) return 0;
    int d = 2 + data[0] % 3, flags = data[1];
    size_t n = 1 + (size_t)(data[2] % maxn[d]);
    if (n > (size - 3) / (size_t)d) n = (size - 3) / (size_t)d;
    if (n == 0) return 0;
    double x[MAXN * MAXD];
    for (size_t i = 0; i < n * (size_t)d; i++) {
        int8_t v = (int8_t)data[3 + i];
        x[i] = (flags & 1) ? (double)v : (double)(v % 4);
    }
    bytes b = {data + 3 + n * (size_t)d, size - 3 - n * (size_t)d};
    int w = d + 1, with_msg = (flags >> 1) & 1;
    lh_pred *p;
    if (lh_pred_create(NULL, &p) != LH_OK) abort();
    lh_tri *t = NULL;
    lh_status st = lh_delaunay(d, n, x, NULL, &t);
    if (st != LH_OK && st != LH_ERR_DEGENERATE) abort();
    static list real, l;
    real.count = 0;
    int64_t volume = -1;
    if (st == LH_OK) {
        real.count = lh_tri_count(t);
        if (real.count > MAXS) abort(); /* cannot happen for these n */
        memcpy(real.v, lh_tri_simplices(t), real.count * (size_t)w * sizeof *real.v);
        volume = 0;
        for (size_t s = 0; s < real.count; s++) volume += det_int(d, x, real.v + s * w);
    }
    int gp = general_position(p, d, n, x);

    /* A: an arbitrary list */
    l.count = next(&b) % 9;
    for (size_t i = 0; i < l.count * (size_t)w; i++) l.v[i] = (lh_index)(next(&b) % (n + 2)) - 1;
    if (run(d, n, x, &l, with_msg)) {
        if (st != LH_OK) abort(); /* accepted a list for sites with no triangulation */
        if (brute_force(p, d, n, x, &l, volume) && gp && !same_multiset(d, &l, &real)) abort();
    }
    if (st == LH_OK) {
        /* B: the real triangulation, as built and reordered */
        if (!run(d, n, x, &real, with_msg)) abort();
        if (!brute_force(p, d, n, x, &real, volume)) abort();
        unsigned rot = next(&b), shift = next(&b);
        l.count = real.count;
        for (size_t s = 0; s < real.count; s++) {
            size_t to = (s + shift) % real.count;
            for (int k = 0; k < w; k++) l.v[to * w + k] = real.v[s * w + (k + rot + s) % w];
        }
        if (!run(d, n, x, &l, with_msg)) abort();
        /* C: one or two edits */
        l = real;
        unsigned edits = 1 + next(&b) % 2;
        for (unsigned e = 0; e < edits; e++) edit(&b, d, n, &l);
        int accepted = run(d, n, x, &l, with_msg), same = same_multiset(d, &l, &real);
        if (same && !accepted) abort();
        if (accepted && brute_force(p, d, n, x, &l, volume) && gp && !same) abort();
    }
    lh_tri_free(t);
    lh_pred_free(p);
    return 0;
}
