/*
 * insert.c — lh_tri_insert: more sites into a built triangulation.
 *
 * The handle keeps only its output arrays, so an insertion rebuilds the engine's
 * cell store from them (finite cells from the simplices and neighbours, one infinite
 * cell per hull facet, linked around the hull's ridges) without a predicate, inserts
 * the new distinct sites in spatial order (BRIO, as lh_delaunay), and extracts the
 * output again. Cost: O(n) memory passes per call plus the insertions themselves.
 * The perturbed Delaunay triangulation of a site set is unique, so the result is the
 * one lh_delaunay gives for all the sites at once, byte for byte.
 */
#include "dt.h"

#include <string.h>

/* Exact duplicates by hashing the coordinates' bit patterns (-0.0 read as +0.0,
 * since they compare equal): new site j maps to the first earlier site equal to it. */
typedef struct dup_table {
    lh_index *slot; /* site index or -1 */
    size_t mask;
    const double *xyz;
    int d;
} dup_table;

static size_t site_hash(const double *p, int d)
{
    uint64_t h = UINT64_C(0x9e3779b97f4a7c15);
    for (int j = 0; j < d; j++) {
        double x = p[j] == 0 ? 0.0 : p[j];
        uint64_t b;
        memcpy(&b, &x, sizeof b);
        h = (h ^ b) * UINT64_C(0xff51afd7ed558ccd);
        h ^= h >> 32;
    }
    return (size_t)h;
}

/* The site equal to site i already in the table, else i (now in the table). */
static lh_index dup_find_or_add(dup_table *tb, lh_index i)
{
    const int d = tb->d;
    const double *p = tb->xyz + (size_t)i * d;
    for (size_t h = site_hash(p, d) & tb->mask;; h = (h + 1) & tb->mask) {
        lh_index s = tb->slot[h];
        if (s < 0) {
            tb->slot[h] = i;
            return i;
        }
        const double *o = tb->xyz + (size_t)s * d;
        int j = 0;
        while (j < d && o[j] == p[j]) j++;
        if (j == d) return s;
    }
}

/* dup[n_old..n-1] for the new sites; returns the number merged, or -1 on no memory. */
static long find_duplicates(lh_tri *t, const double *xyz, lh_index *dup, size_t n_old, size_t n)
{
    size_t size = 16;
    while (size < 2 * n) size *= 2;
    dup_table tb = {lh__alloc(&t->alloc, size * sizeof *tb.slot), size - 1, xyz, t->d};
    if (!tb.slot) return -1;
    memset(tb.slot, 0xff, size * sizeof *tb.slot);
    long merged = 0;
    for (size_t i = 0; i < n_old; i++)
        if (dup[i] == (lh_index)i) dup_find_or_add(&tb, (lh_index)i);
    for (size_t i = n_old; i < n; i++) {
        dup[i] = dup_find_or_add(&tb, (lh_index)i);
        merged += dup[i] != (lh_index)i;
    }
    lh__free(&t->alloc, tb.slot);
    return merged;
}

/* The new distinct sites (caller's indices) in BRIO order: lh__eng_order over the
 * new sites alone; *count of them in *out (allocated). */
static lh_status new_site_order(lh_tri *t, const double *xyz, const lh_index *dup, size_t n_old,
                                size_t m, lh_index **out, size_t *count)
{
    lh__eng o;
    lh_index *scratch = lh__alloc(&t->alloc, (m + 1) * sizeof *scratch);
    lh_status st = scratch ? lh__eng_init(&o, &t->alloc, t->d, m, xyz + n_old * t->d, scratch, NULL)
                           : LH_ERR_NOMEM;
    if (scratch && st == LH_OK) st = lh__eng_order(&o);
    if (scratch && st == LH_OK) {
        size_t k = 0;
        for (size_t i = 0; i < o.norder; i++) {
            lh_index s = (lh_index)n_old + o.order[i];
            if (dup[s] == s) o.order[k++] = s;
        }
        *out = o.order;
        *count = k;
        o.order = NULL;
    }
    if (scratch) lh__eng_release(&o);
    lh__free(&t->alloc, scratch);
    return st;
}

/* The position of x in v (x must be there). */
static int index_of(const lh_index *v, lh_index x)
{
    int k = 0;
    while (v[k] != x) k++;
    return k;
}

/* Links infinite cell I (made from hull facet k of finite cell s) across its facet
 * opposite vertex j >= 1: turn around the hull ridge (that facet minus v_j) through
 * finite cells until an infinite cell is entered. */
static void link_infinite(lh__tds *t, lh_index I, int j, lh_index s, int k)
{
    const int nv = t->nv;
    lh_index u = t->vert[(size_t)I * nv + j], w = t->vert[(size_t)s * nv + k], cur = s;
    for (;;) {
        const lh_index *cv = t->vert + (size_t)cur * nv;
        lh_index nxt = t->nbr[(size_t)cur * nv + index_of(cv, u)];
        if (t->vert[(size_t)nxt * nv] == LH__INF) { /* nxt = INF + cur \ {u} */
            t->nbr[(size_t)I * nv + j] = nxt;
            t->nbr[(size_t)nxt * nv + index_of(t->vert + (size_t)nxt * nv, w)] = I;
            return;
        }
        lh_index y = t->vert[(size_t)nxt * nv + lh__tds_mirror(t, nxt, cur)];
        u = w;
        w = y;
        cur = nxt;
    }
}

/* The engine's cell store from the handle's arrays: cell s is simplex s; cells
 * count.. are the infinite ones. */
static lh_status rebuild_cells(lh__eng *e, const lh_tri *t)
{
    const int nv = e->nv;
    size_t cells = t->count + t->hull_count;
    if (cells >= LH_INDEX_MAX / 2) return LH_ERR_TOO_LARGE;
    lh_status st = lh__tds_init(&e->tds, &e->alloc, nv, (lh_index)(cells + cells / 4 + 256));
    if (st != LH_OK) return st;
    lh__tds_vertex_bound(&e->tds, e->n + 1);
    lh__tds *tds = &e->tds;
    for (size_t s = 0; s < t->count; s++) {
        lh_index c = lh__tds_new_cell(tds); /* c == s: fresh store, capacity reserved */
        memcpy(tds->vert + (size_t)c * nv, t->simp + s * nv, (size_t)nv * sizeof *tds->vert);
    }
    for (size_t s = 0; s < t->count; s++)
        for (int k = 0; k < nv; k++) {
            lh_index n = t->nbr[s * nv + k];
            if (n < 0) {
                n = lh__tds_new_cell(tds);
                lh__eng_make_infinite(tds->vert + (size_t)n * nv, t->simp + s * nv, nv, k);
                tds->nbr[(size_t)n * nv] = (lh_index)s;
                for (int j = 1; j < nv; j++) tds->nbr[(size_t)n * nv + j] = -1;
            }
            tds->nbr[s * nv + k] = n;
        }
    for (lh_index I = (lh_index)t->count; I < tds->top; I++) {
        lh_index s = tds->nbr[(size_t)I * nv];
        int k = lh__tds_mirror(tds, s, I);
        for (int j = 1; j < nv; j++)
            if (tds->nbr[(size_t)I * nv + j] < 0) link_infinite(tds, I, j, s, k);
    }
    e->hint = 0;
    return LH_OK;
}

/* Moves the arrays and frame of `from` (a scratch handle) into t, freeing t's old
 * ones. */
static void take_arrays(lh_tri *t, lh_tri *from)
{
    t->frame = from->frame;
    lh__free(&t->alloc, t->xyz);
    lh__free(&t->alloc, t->dup);
    lh__free(&t->alloc, t->simp);
    lh__free(&t->alloc, t->nbr);
    lh__free(&t->alloc, t->hull);
    lh__free(&t->alloc, t->vsimp);
    lh__free(&t->alloc, t->cell_off);
    lh__free(&t->alloc, t->cell_vert);
    lh__free(&t->alloc, t->simp_cell);
    lh__free(&t->alloc, t->edges);
    t->cell_off = t->cell_vert = t->simp_cell = t->edges = NULL;
    t->nedges = 0;
    t->ncells = 0;
    lh__free(&t->alloc, t->centers);
    t->centers = NULL;
    t->n = from->n;
    t->xyz = from->xyz;
    t->dup = from->dup;
    t->ndup = from->ndup;
    t->count = from->count;
    t->simp = from->simp;
    t->nbr = from->nbr;
    t->hull_count = from->hull_count;
    t->hull = from->hull;
    t->vsimp = from->vsimp;
}

static void free_arrays(lh_tri *x)
{
    lh__free(&x->alloc, x->xyz);
    lh__free(&x->alloc, x->dup);
    lh__free(&x->alloc, x->simp);
    lh__free(&x->alloc, x->nbr);
    lh__free(&x->alloc, x->hull);
    lh__free(&x->alloc, x->vsimp);
}

/* The sites and duplicate map of t followed by the m new sites. */
static lh_status grow_sites(lh_tri *t, size_t m, const double *xyz, lh_tri *nt)
{
    const size_t d = (size_t)t->d, n = t->n + m;
    memset(nt, 0, sizeof *nt);
    nt->alloc = t->alloc;
    nt->d = t->d;
    nt->frame = t->frame;
    nt->n = n;
    nt->xyz = lh__alloc(&t->alloc, (n * d + 1) * sizeof *nt->xyz);
    nt->dup = lh__alloc(&t->alloc, (n + 1) * sizeof *nt->dup);
    if (!nt->xyz || !nt->dup) return LH_ERR_NOMEM;
    memcpy(nt->xyz, t->xyz, t->n * d * sizeof *nt->xyz);
    if (m) memcpy(nt->xyz + t->n * d, xyz, m * d * sizeof *nt->xyz);
    memcpy(nt->dup, t->dup, t->n * sizeof *nt->dup);
    long merged = find_duplicates(t, nt->xyz, nt->dup, t->n, n);
    if (merged < 0) return LH_ERR_NOMEM;
    nt->ndup = t->ndup + (size_t)merged;
    return LH_OK;
}

/* lh_delaunay of all the sites, moved into t. */
static lh_status rebuild(lh_tri *t, size_t m, const double *xyz)
{
    const size_t d = (size_t)t->d, n = t->n + m;
    double *all = lh__alloc(&t->alloc, (n * d + 1) * sizeof *all);
    if (!all) return LH_ERR_NOMEM;
    memcpy(all, t->xyz, t->n * d * sizeof *all);
    memcpy(all + t->n * d, xyz, m * d * sizeof *all);
    lh_options o;
    lh_options_default(&o);
    o.alloc = &t->alloc;
    o.furthest_site = t->furthest;
    o.affine_hull = t->affine_hull;
    o.generic_engine = t->generic;
    lh_tri *nt;
    lh_status st = lh_delaunay(t->d, n, all, &o, &nt);
    lh__free(&t->alloc, all);
    if (st != LH_OK) return st;
    take_arrays(t, nt);
    nt->xyz = NULL;
    nt->dup = nt->simp = nt->nbr = nt->hull = nt->vsimp = NULL;
    lh_tri_free(nt);
    return LH_OK;
}

/* lh_tri_insert, lh_tri_insert_unordered and (m = 0, sorted) lh_tri_sort. */
static lh_status insert(lh_tri *t, size_t m, const double *xyz, int sorted)
{
    if (!t || (!xyz && m > 0)) return LH_ERR_INVALID_ARGUMENT;
    if (m == 0 && (!sorted || !t->unordered)) return LH_OK;
    if (m >= (size_t)LH_INDEX_MAX - t->n || t->n + m > SIZE_MAX / ((size_t)t->d * sizeof(double)))
        return LH_ERR_TOO_LARGE;
    lh_status st = lh_coords_validate(t->d, m, xyz, NULL);
    if (st != LH_OK) return st;
    lh_tri nt;
    lh_index *list = NULL;
    size_t count = 0;
    lh__eng e;
    int engine = 0;
    st = grow_sites(t, m, xyz, &nt);
    if (st == LH_OK && t->frame.k < t->d) { /* new sites may leave the flat: rebuild */
        free_arrays(&nt);
        st = rebuild(t, m, xyz);
        if (st == LH_OK) t->unordered = 0;
        return st;
    }
    if (st == LH_OK && m) st = new_site_order(t, nt.xyz, nt.dup, t->n, m, &list, &count);
    if (st == LH_OK) {
        st = lh__eng_init(&e, &t->alloc, t->d, nt.n, nt.xyz, nt.dup, NULL);
        engine = 1;
    }
    if (st == LH_OK) {
        lh__dt_conflicts(&e, t->furthest, t->generic);
        e.site = nt.xyz; /* vertex v is site v */
        st = rebuild_cells(&e, t);
    }
    if (st == LH_OK && count) st = lh__eng_insert(&e, list, count);
    if (st == LH_OK) st = lh__dt_extract_as(&e, &nt, sorted);
    if (engine) lh__eng_release(&e);
    lh__free(&t->alloc, list);
    if (st != LH_OK) {
        free_arrays(&nt);
        return st;
    }
    take_arrays(t, &nt);
    t->unordered = !sorted;
    return LH_OK;
}

lh_status lh_tri_insert(lh_tri *t, size_t m, const double *xyz)
{
    return insert(t, m, xyz, 1);
}

lh_status lh_tri_insert_unordered(lh_tri *t, size_t m, const double *xyz)
{
    return insert(t, m, xyz, 0);
}

lh_status lh_tri_sort(lh_tri *t)
{
    return insert(t, 0, NULL, 1);
}
