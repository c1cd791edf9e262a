/*
 * check.c — exact validity of a Delaunay triangulation given as sites + simplices.
 *
 * A set of positively oriented simplices where every facet has at most two
 * simplices, the two on opposite sides, that is connected through facets and
 * whose boundary is locally convex, tiles a convex polytope; if moreover every
 * interior facet is locally Delaunay, it is the Delaunay triangulation of its
 * vertices (Delaunay's lemma; see e.g. Edelsbrunner, "Geometry and Topology for
 * Mesh Generation", 2001, ch. 1), and if every site is a vertex or a duplicate of
 * one, of the sites. Each condition is tested with the exact predicates. Local
 * conditions alone admit coverings that wind more than once (found by fuzzing:
 * fuzz/findings/check_cover*), so the total volume is compared with the hull's,
 * exactly (check_volume).
 */
#include "dt.h"
#include "lh_error.h"
#include "lh_exact.h"
#include "lh_sort.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef struct chk {
    lh_allocator alloc;
    int d, nv;       /* coordinates per site; vertices per simplex (f.k + 1) */
    lh__frame f;
    size_t n, count;
    const double *xyz;
    lh_index *simp;  /* oriented copy */
    lh_index *rec;   /* facet records: d sorted vertices, simplex, index */
    lh_index *nbr;   /* computed neighbours */
    lh_pred *pred;
    int furthest;    /* furthest-site: opposite vertices inside, not outside */
    lh_status bad;   /* a failed condition: LH_ERR_INVALID_MESH for the caller's
                        simplices, LH_ERR_INTERNAL for a handle the library built */
    lh_error *err;   /* the caller's, may be NULL */
} chk;

static lh_status fail(chk *c, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static lh_status fail(chk *c, const char *fmt, ...)
{
    if (c->err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(c->err->message, sizeof c->err->message, fmt, ap);
        va_end(ap);
    }
    return c->bad;
}

static const double *site(const chk *c, lh_index v) { return c->xyz + (size_t)v * c->d; }

static int orient_of(chk *c, const lh_index *v, int replace, lh_index by)
{
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (int k = 0; k < c->nv; k++) p[k] = site(c, k == replace ? by : v[k]);
    return lh__frame_orient(c->pred, &c->f, p);
}

/* Indices valid and distinct, volume nonzero; stored positively oriented. */
static lh_status check_simplices(chk *c)
{
    for (size_t s = 0; s < c->count; s++) {
        lh_index *v = c->simp + s * c->nv;
        for (int k = 0; k < c->nv; k++) {
            if (v[k] < 0 || (size_t)v[k] >= c->n)
                return fail(c, "simplex %zu: vertex %" LH_INDEX_PRI " is not a site index", s, v[k]);
            for (int j = 0; j < k; j++)
                if (v[j] == v[k]) return fail(c, "simplex %zu repeats site %" LH_INDEX_PRI, s, v[k]);
        }
        int o = orient_of(c, v, -1, 0);
        if (o == 0) return fail(c, "simplex %zu is flat (zero volume)", s);
        if (o < 0) {
            lh_index x = v[0];
            v[0] = v[1];
            v[1] = x;
        }
    }
    return LH_OK;
}

static void sort_small(lh_index *v, int m)
{
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
            lh_index x = v[j];
            v[j] = v[j - 1];
            v[j - 1] = x;
        }
}

/* Matches records of `keylen` sorted vertices (+ payload up to width w) and calls
 * pair() for each pair; more than two equal keys is an error. Returns the sorted
 * order in *order (caller frees), or NULL on allocation failure. */
static lh_index *sorted_records(chk *c, const lh_index *rec, size_t m, int w, int keylen)
{
    lh_index *idx = lh__alloc(&c->alloc, (m + 1) * sizeof *idx), *tmp = lh__alloc(&c->alloc, (m + 1) * sizeof *tmp);
    if (!idx || !tmp) {
        lh__free(&c->alloc, idx);
        lh__free(&c->alloc, tmp);
        return NULL;
    }
    for (size_t i = 0; i < m; i++) idx[i] = (lh_index)i;
    lh__rows r = {rec, w, keylen};
    lh__sort_idx(idx, tmp, m, lh__rows_cmp, &r);
    lh__free(&c->alloc, tmp);
    return idx;
}

/* Neighbours through shared facets; opposite sides; local Delaunay. */
static lh_status check_facets(chk *c, size_t *boundary)
{
    const int nv = c->nv, d = c->f.k, w = d + 2; /* facet: d vertices, simplex, index */
    size_t m = c->count * nv;
    c->rec = lh__alloc(&c->alloc, (m * w + 1) * sizeof *c->rec);
    c->nbr = lh__alloc(&c->alloc, (m + 1) * sizeof *c->nbr);
    if (!c->rec || !c->nbr) return LH_ERR_NOMEM;
    for (size_t s = 0; s < c->count; s++)
        for (int k = 0; k < nv; k++) {
            lh_index *r = c->rec + (s * nv + k) * w, j = 0;
            for (int i = 0; i < nv; i++)
                if (i != k) r[j++] = c->simp[s * nv + i];
            sort_small(r, d);
            r[d] = (lh_index)s;
            r[d + 1] = k;
            c->nbr[s * nv + k] = -1;
        }
    lh_index *idx = sorted_records(c, c->rec, m, w, d);
    if (!idx) return LH_ERR_NOMEM;
    lh__rows r = {c->rec, w, d};
    lh_status st = LH_OK;
    *boundary = 0;
    for (size_t i = 0; i < m && st == LH_OK;) {
        size_t j = i + 1;
        while (j < m && lh__rows_cmp(&r, idx[i], idx[j]) == 0) j++;
        const lh_index *a = c->rec + (size_t)idx[i] * w;
        if (j - i > 2) {
            st = fail(c, "a facet is shared by %zu simplices (%" LH_INDEX_PRI " and %" LH_INDEX_PRI " among them)", j - i,
                      a[d], c->rec[(size_t)idx[i + 1] * w + d]);
        } else if (j - i == 1) {
            (*boundary)++;
        } else {
            const lh_index *b = c->rec + (size_t)idx[i + 1] * w;
            lh_index sa = a[d], ka = a[d + 1], sb = b[d], kb = b[d + 1];
            c->nbr[(size_t)sa * nv + ka] = sb;
            c->nbr[(size_t)sb * nv + kb] = sa;
            const lh_index *va = c->simp + (size_t)sa * nv, *vb = c->simp + (size_t)sb * nv;
            if (orient_of(c, va, (int)ka, vb[kb]) >= 0) {
                st = fail(c, "simplices %" LH_INDEX_PRI " and %" LH_INDEX_PRI " overlap: they lie on the same side of their common facet", sa, sb);
            } else {
                const double *p[LH_DELAUNAY_MAX_DIM + 2];
                for (int k = 0; k < nv; k++) p[k] = site(c, va[k]);
                p[nv] = site(c, vb[kb]);
                int in = lh__frame_insphere(c->pred, &c->f, p);
                if (!c->furthest && in < 0)
                    st = fail(c, "facet between simplices %" LH_INDEX_PRI " and %" LH_INDEX_PRI " is not locally Delaunay: site %" LH_INDEX_PRI " is inside the circumsphere of %" LH_INDEX_PRI,
                              sa, sb, vb[kb], sa);
                if (c->furthest && in > 0)
                    st = fail(c, "facet between simplices %" LH_INDEX_PRI " and %" LH_INDEX_PRI " is not locally furthest-site Delaunay: site %" LH_INDEX_PRI " is outside the circumsphere of %" LH_INDEX_PRI,
                              sa, sb, vb[kb], sa);
            }
        }
        i = j;
    }
    lh__free(&c->alloc, idx);
    return st;
}

/* Boundary facets: closed and locally convex. */
static lh_status check_boundary(chk *c, size_t boundary)
{
    const int nv = c->nv, d = c->f.k, w = d + 2; /* ridge: d-1 vertices, facet id, other */
    size_t m = boundary * d;
    lh_index *rec = lh__alloc(&c->alloc, (m * w + 1) * sizeof *rec);
    lh_index *fs = lh__alloc(&c->alloc, (boundary * 2 + 1) * sizeof *fs);
    if (!rec || !fs) {
        lh__free(&c->alloc, rec);
        lh__free(&c->alloc, fs);
        return LH_ERR_NOMEM;
    }
    size_t f = 0;
    for (size_t s = 0; s < c->count; s++)
        for (int k = 0; k < nv; k++) {
            if (c->nbr[s * nv + k] >= 0) continue;
            fs[2 * f] = (lh_index)s;
            fs[2 * f + 1] = k;
            lh_index fv[LH_DELAUNAY_MAX_DIM], j = 0;
            for (int i = 0; i < nv; i++)
                if (i != k) fv[j++] = c->simp[s * nv + i];
            for (int x = 0; x < d; x++) { /* ridge = facet minus fv[x] */
                lh_index *r = rec + (f * d + x) * w, q = 0;
                for (int i = 0; i < d; i++)
                    if (i != x) r[q++] = fv[i];
                sort_small(r, d - 1);
                r[d - 1] = (lh_index)f;
                r[d] = fv[x];
            }
            f++;
        }
    lh_index *idx = sorted_records(c, rec, m, w, d - 1);
    lh_status st = idx ? LH_OK : LH_ERR_NOMEM;
    lh__rows r = {rec, w, d - 1};
    for (size_t i = 0; st == LH_OK && i < m; i += 2) {
        if (i + 1 >= m || lh__rows_cmp(&r, idx[i], idx[i + 1]) != 0 ||
            (i + 2 < m && lh__rows_cmp(&r, idx[i], idx[i + 2]) == 0)) {
            st = fail(c, "the boundary is not a closed surface (a ridge of hull facet %" LH_INDEX_PRI " has %s partner)",
                      fs[2 * rec[(size_t)idx[i] * w + d - 1]], i + 1 >= m || lh__rows_cmp(&r, idx[i], idx[i + 1]) ? "no" : "more than one");
            break;
        }
        for (int side = 0; side < 2 && st == LH_OK; side++) {
            const lh_index *a = rec + (size_t)idx[i + side] * w, *b = rec + (size_t)idx[i + 1 - side] * w;
            lh_index s = fs[2 * a[d - 1]], k = fs[2 * a[d - 1] + 1];
            if (orient_of(c, c->simp + (size_t)s * nv, (int)k, b[d]) < 0)
                st = fail(c, "the boundary is not convex: site %" LH_INDEX_PRI " is outside the hull facet of simplex %" LH_INDEX_PRI, b[d], s);
        }
    }
    lh__free(&c->alloc, idx);
    lh__free(&c->alloc, rec);
    lh__free(&c->alloc, fs);
    return st;
}

/* Whether sites a and b have equal coordinates. */
static int same_coords(const chk *c, lh_index a, lh_index b)
{
    for (int j = 0; j < c->d; j++)
        if (site(c, a)[j] != site(c, b)[j]) return 0;
    return 1;
}

/* Among equal sites (adjacent in lexicographic order) exactly one is a vertex. */
static lh_status check_sites_used(chk *c, const lh_index *used)
{
    lh_index *idx = lh__alloc(&c->alloc, (c->n + 1) * sizeof *idx), *tmp = lh__alloc(&c->alloc, (c->n + 1) * sizeof *tmp);
    lh_status st = idx && tmp ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        for (size_t i = 0; i < c->n; i++) idx[i] = (lh_index)i;
        lh__lex l = {c->xyz, c->d};
        lh__sort_idx(idx, tmp, c->n, lh__lex_cmp, &l);
        for (size_t i = 0; i < c->n && st == LH_OK;) {
            size_t j = i, vertices = 0;
            for (; j < c->n && same_coords(c, idx[i], idx[j]); j++) vertices += used[idx[j]] != 0;
            if (vertices == 0) st = fail(c, "site %" LH_INDEX_PRI " is neither a vertex nor a duplicate of one", idx[i]);
            if (vertices > 1) st = fail(c, "sites %" LH_INDEX_PRI " and %" LH_INDEX_PRI " are equal and both vertices", idx[i], idx[i + 1]);
            i = j;
        }
    }
    lh__free(&c->alloc, idx);
    lh__free(&c->alloc, tmp);
    return st;
}

/* Furthest-site: every site that is not a vertex lies inside or on the boundary of
 * the hull (quadratic: for tests). */
static lh_status check_sites_inside(chk *c, const lh_index *used)
{
    const int nv = c->nv;
    for (size_t s = 0; s < c->count; s++)
        for (int k = 0; k < nv; k++) {
            if (c->nbr[s * nv + k] >= 0) continue;
            for (size_t i = 0; i < c->n; i++)
                if (!used[i] && orient_of(c, c->simp + s * nv, k, (lh_index)i) < 0)
                    return fail(c, "site %zu is outside the hull facet of simplex %zu", i, s);
        }
    return LH_OK;
}

/* Connected through facets, and every site is a vertex or an exact duplicate of one. */
static lh_status check_cover(chk *c)
{
    size_t n = c->n;
    lh_index *mark = lh__alloc(&c->alloc, (c->count + n + 1) * sizeof *mark);
    if (!mark) return LH_ERR_NOMEM;
    lh_index *used = mark + c->count;
    memset(mark, 0, (c->count + n) * sizeof *mark);
    lh_status st = LH_OK;
    if (c->count) { /* flood through neighbours, the mark array doubling as a stack */
        lh_index *stack = lh__alloc(&c->alloc, (c->count + 1) * sizeof *stack);
        if (!stack) {
            lh__free(&c->alloc, mark);
            return LH_ERR_NOMEM;
        }
        size_t top = 0, seen = 1;
        stack[top++] = 0;
        mark[0] = 1;
        while (top) {
            lh_index s = stack[--top];
            for (int k = 0; k < c->nv; k++) {
                lh_index nb = c->nbr[(size_t)s * c->nv + k];
                if (nb >= 0 && !mark[nb]) {
                    mark[nb] = 1;
                    seen++;
                    stack[top++] = nb;
                }
            }
        }
        lh__free(&c->alloc, stack);
        if (seen != c->count) st = fail(c, "the simplices are not connected through facets");
    }
    for (size_t s = 0; s < c->count * c->nv; s++) used[c->simp[s]] = 1;
    if (st == LH_OK && n) st = c->furthest ? check_sites_inside(c, used) : check_sites_used(c, used);
    lh__free(&c->alloc, mark);
    return st;
}

/* The simplices cover the hull exactly once. With every interior facet between two
 * simplices on opposite sides and a locally convex, closed boundary, the simplices
 * cover the hull some number of times, the same almost everywhere (the map can
 * branch only at ridges): a boundary wound twice, or a branch point, passes every
 * local test. The total volume is that degree times the hull's, so exactly equal
 * volumes mean once: sum_s det(s) + sum_f det(f, o) = 0, with the hull's facets f
 * (lh_convex_hull, an independent computation, oriented outward) coned from a site
 * o, every determinant exact (lh__detsum). Full-dimensional frames only. */
static lh_status check_volume(chk *c)
{
    const int d = c->d;
    int scale = 0, any = 0;
    for (size_t i = 0; i < c->n * (size_t)d; i++)
        if (c->xyz[i] != 0) {
            int e = lh__dbl_low_exp(c->xyz[i]);
            scale = any && scale < e ? scale : e;
            any = 1;
        }
    lh_options opt;
    lh_options_default(&opt);
    opt.alloc = &c->alloc;
    lh_hull *h = NULL;
    lh__detsum *sum = NULL;
    lh_status st = lh_convex_hull(d, c->n, c->xyz, &opt, &h);
    if (st == LH_OK) st = lh__detsum_create(&c->alloc, d, scale, &sum);
    const double *p[LH_DELAUNAY_MAX_DIM + 1];
    for (size_t s = 0; st == LH_OK && s < c->count; s++) {
        for (int k = 0; k <= d; k++) p[k] = site(c, c->simp[s * c->nv + k]);
        lh__detsum_add(c->pred, sum, p, 0);
    }
    for (size_t f = 0; st == LH_OK && f < lh_hull_facet_count(h); f++) {
        for (int k = 0; k < d; k++) p[k] = site(c, lh_hull_facets(h)[f * d + k]);
        p[d] = c->xyz;
        lh__detsum_add(c->pred, sum, p, 0);
    }
    if (st == LH_OK && lh__detsum_sign(sum) != 0)
        st = fail(c, "the simplices cover the convex hull more than once (their volume exceeds the hull's)");
    else if (st == LH_ERR_DEGENERATE)
        st = fail(c, "the sites span less than R^%d", d);
    lh__detsum_free(sum);
    lh_hull_free(h);
    return st;
}

static void chk_release(chk *c)
{
    lh__free(&c->alloc, c->simp);
    lh__free(&c->alloc, c->rec);
    lh__free(&c->alloc, c->nbr);
    lh_pred_free(c->pred);
}

/* Whether every array of the check can be sized without wrapping around: sites and
 * facets are numbered by lh_index, the facet records hold count nv (nv + 1) indices
 * (d vertices, simplex, index per facet), the marks count + n. */
static int sizes_fit(size_t n, size_t count, int nv)
{
    const size_t most = SIZE_MAX / sizeof(lh_index) - 1, w = (size_t)nv + 1;
    return n <= (size_t)LH_INDEX_MAX && count <= (size_t)LH_INDEX_MAX / (size_t)nv &&
           count * (size_t)nv <= most / w && n <= most - count;
}

static lh_status run_check(chk *c, const lh_index *simplices)
{
    size_t boundary = 0;
    if (!sizes_fit(c->n, c->count, c->nv)) {
        return lh__error_say(
            c->err, LH_ERR_TOO_LARGE,
            "%zu sites and %zu simplices: more than an lh_index or a size_t can count", c->n,
            c->count);
    }
    c->simp = lh__alloc(&c->alloc, (c->count * c->nv + 1) * sizeof *c->simp);
    if (!c->simp) return LH_ERR_NOMEM;
    if (c->count) memcpy(c->simp, simplices, c->count * c->nv * sizeof *c->simp);
    lh_status st = lh_pred_create(&c->alloc, &c->pred);
    if (st == LH_OK) st = check_simplices(c);
    if (st == LH_OK) st = check_facets(c, &boundary);
    if (st == LH_OK && c->count) st = check_boundary(c, boundary);
    if (st == LH_OK) st = check_cover(c);
    if (st == LH_OK && c->count && c->f.k == c->d) st = check_volume(c);
    return st;
}

static lh_status delaunay_check(int d, size_t n, const double *xyz, size_t count,
                                const lh_index *simplices, const lh_options *opt, lh_error *err)
{
    if (d < LH_DELAUNAY_MIN_DIM || d > LH_DELAUNAY_MAX_DIM) return LH_ERR_DIMENSION;
    if ((!xyz && n) || (!simplices && count)) return LH_ERR_INVALID_ARGUMENT;
    chk c;
    memset(&c, 0, sizeof c);
    if (!lh__allocator_init(&c.alloc, opt ? opt->alloc : NULL)) return LH_ERR_INVALID_ARGUMENT;
    c.d = d;
    c.nv = d + 1;
    c.f.d = c.f.k = d;
    for (int j = 0; j < d; j++) c.f.J[j] = j;
    c.n = n;
    c.count = count;
    c.xyz = xyz;
    c.bad = LH_ERR_INVALID_MESH;
    c.err = err;
    lh_status st = run_check(&c, simplices);
    chk_release(&c);
    return st;
}

lh_status lh_delaunay_check(int d, size_t n, const double *xyz, size_t count,
                            const lh_index *simplices, const lh_options *opt, lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, delaunay_check(d, n, xyz, count, simplices, opt, err));
}

static lh_status tri_check(const lh_tri *t, lh_error *err)
{
    if (!t) return LH_ERR_INVALID_ARGUMENT;
    chk c;
    memset(&c, 0, sizeof c);
    c.alloc = t->alloc; /* the handle's hooks */
    c.d = t->d;
    c.f = t->frame;
    c.nv = t->frame.k + 1;
    c.n = t->n;
    c.count = t->count;
    c.xyz = t->xyz;
    c.bad = LH_ERR_INTERNAL;
    c.err = err;
    c.furthest = t->furthest;
    lh_status st = run_check(&c, t->simp);
    for (size_t i = 0; st == LH_OK && c.f.k < c.d && i < t->n; i++) { /* all in one flat */
        const double *p[LH_DELAUNAY_MAX_DIM + 1];
        for (int j = 0; j < c.nv; j++) p[j] = site(&c, t->simp[j]);
        p[c.nv] = site(&c, (lh_index)i);
        if (lh__affine_independent(c.pred, c.d, p, c.nv))
            st = fail(&c, "site %zu is not in the affine hull of simplex 0", i);
    }
    /* The stored arrays: simplices positively oriented as given, neighbours as
     * computed, one hull facet per boundary facet, incident simplices correct. */
    for (size_t s = 0; st == LH_OK && s < t->count; s++) {
        if (memcmp(c.simp + s * c.nv, t->simp + s * c.nv, (size_t)c.nv * sizeof *c.simp) != 0)
            st = fail(&c, "simplex %zu is stored negatively oriented", s);
        for (int k = 0; st == LH_OK && k < c.nv; k++)
            if (c.nbr[s * c.nv + k] != t->nbr[s * c.nv + k])
                st = fail(&c, "neighbour %d of simplex %zu is %" LH_INDEX_PRI ", should be %" LH_INDEX_PRI, k, s,
                          t->nbr[s * c.nv + k], c.nbr[s * c.nv + k]);
    }
    size_t boundary = 0;
    for (size_t i = 0; st == LH_OK && i < t->count * c.nv; i++) boundary += t->nbr[i] < 0;
    if (st == LH_OK && boundary != t->hull_count)
        st = fail(&c, "%zu hull facets stored, %zu boundary facets found", t->hull_count, boundary);
    for (size_t i = 0; st == LH_OK && i < t->n; i++) {
        lh_index s = t->vsimp[i];
        int vertex = t->dup[i] == (lh_index)i && (!t->furthest || s >= 0), has = 0;
        if (vertex && s >= 0 && (size_t)s < t->count)
            for (int k = 0; k < c.nv; k++) has |= t->simp[(size_t)s * c.nv + k] == (lh_index)i;
        if (vertex ? !has : s != -1) st = fail(&c, "the incident simplex of site %zu is wrong", i);
    }
    chk_release(&c);
    return st;
}

lh_status lh_tri_check(const lh_tri *t, lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, tri_check(t, err));
}
