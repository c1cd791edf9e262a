/*
 * io_cells.c — lh_cells_read: simplices as index lists, for checking a triangulation
 * made elsewhere (lifthull.h, "file formats"). Two layouts:
 *
 *   Qhull's 'i' (qdelaunay i, qconvex i, lifthull delaunay):
 *       count
 *       v_0 .. v_k            one cell a line, 0-based point indices
 *   Triangle/TetGen .ele (Shewchuk, Triangle's documentation, ".ele files"):
 *       count nodes_per_cell [attributes]
 *       number v_0 .. v_k [attribute ...]
 *     numbered consecutively from 0 or 1, point indices from the same base; the
 *     attributes kept.
 *
 * The header line tells them apart: one field is 'i', two or three are .ele. The
 * declared count is not trusted for one allocation: the array grows as cells come.
 */
#include "io_internal.h"

#include <string.h>

#define MAX_NV (LH_DELAUNAY_MAX_DIM + 1)

void lh_cells_free(lh_cells *c)
{
    if (!c) return;
    if (c->alloc_.free) lh__free(&c->alloc_, c->v), lh__free(&c->alloc_, c->attr);
    memset(c, 0, sizeof *c);
}

typedef struct cells_ctx {
    lh__scan *s;
    lh_cells *c;
    size_t cap, declared, n_points;
    int ele, attrs;
    double a[100]; /* the cell's attributes, as read */
} cells_ctx;

/* *arr (count items of `per` elements of `size` bytes) moved into room for cap. */
static int grow(lh_cells *c, void **arr, size_t cap, size_t per, size_t size)
{
    if (per == 0) return 1;
    void *na = cap > SIZE_MAX / size / per ? NULL : lh__alloc(&c->alloc_, cap * per * size);
    if (!na) return 0;
    if (c->count) memcpy(na, *arr, c->count * per * size);
    lh__free(&c->alloc_, *arr);
    *arr = na;
    return 1;
}

static lh_status push(cells_ctx *x, const lh__token *at, const lh_index *v)
{
    lh_cells *c = x->c;
    if (c->count == x->cap) {
        size_t cap = x->cap ? 2 * x->cap : 256;
        if (cap > x->declared) cap = x->declared;
        if (cap <= c->count) cap = c->count + 1;
        if (!grow(c, (void **)&c->v, cap, (size_t)c->nv, sizeof *c->v) ||
            !grow(c, (void **)&c->attr, cap, (size_t)c->attr_count, sizeof *c->attr))
            return lh__fail_at(x->s, LH_ERR_NOMEM, at, "out of memory for the cells");
        x->cap = cap;
    }
    memcpy(c->v + c->count * (size_t)c->nv, v, (size_t)c->nv * sizeof *v);
    if (c->attr_count) memcpy(c->attr + c->count * (size_t)c->attr_count, x->a, (size_t)c->attr_count * sizeof *x->a);
    c->count++;
    return LH_OK;
}

/* One point index of cell i (base first_index), in 0..n_points-1 after rebasing. */
static lh_status index_of(cells_ctx *x, const lh__token *t, size_t i, lh_index *v)
{
    long long k;
    long long lo = x->c->first_index, hi = (long long)x->n_points - 1 + lo;
    if (lh__word_integer(t, &k) && k >= lo && (x->n_points == 0 || k <= hi) && k - lo <= LH_INDEX_MAX) {
        *v = (lh_index)(k - lo);
        return LH_OK;
    }
    char what[120];
    if (x->n_points)
        snprintf(what, sizeof what, "a point index of cell %zu (an integer from %lld to %lld)", i + 1, lo, hi);
    else
        snprintf(what, sizeof what, "a point index of cell %zu (an integer from %lld)", i + 1, lo);
    return lh__expected(x->s, LH_ERR_PARSE, t, what, NULL);
}

/* The rest of a line: .ele attributes (finite numbers, as in .node files) into x->a,
 * then its end. */
static lh_status line_end(cells_ctx *x, size_t i)
{
    lh__token t;
    for (int j = 0; j < x->attrs; j++) {
        lh__scan_next(x->s, 0, &t);
        char what[80];
        snprintf(what, sizeof what, "attribute %d of cell %zu", j + 1, i + 1);
        lh_status st = lh__number(x->s, &t, what, "accepted", NULL, &x->a[j]);
        if (st != LH_OK) return st;
    }
    lh__scan_next(x->s, 0, &t);
    if (t.kind == LH__TOK_EOL || t.kind == LH__TOK_EOF) return LH_OK;
    char what[80];
    snprintf(what, sizeof what, "the end of the line after cell %zu (%d indices)", i + 1, x->c->nv);
    return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
}

/* Cell i; for the first cell of an 'i' file its length sets nv. */
static lh_status read_cell(cells_ctx *x, size_t i)
{
    lh__token t, at;
    lh_index v[MAX_NV + 1];
    lh__scan_next(x->s, 1, &t);
    at = t;
    if (t.kind != LH__TOK_WORD) {
        char what[60], tail[60];
        snprintf(what, sizeof what, "cell %zu", i + 1);
        snprintf(tail, sizeof tail, " (%zu cell%s declared)", x->declared, x->declared == 1 ? "" : "s");
        return lh__expected(x->s, LH_ERR_PARSE, &t, what, t.kind == LH__TOK_EOF ? tail : NULL);
    }
    if (x->ele) {
        long long num, want = x->c->first_index + (long long)i;
        if (!lh__word_integer(&t, &num) || (i ? num != want : num != 0 && num != 1)) {
            char what[80];
            snprintf(what, sizeof what, i ? "cell number %lld" : "the first cell's number (0 or 1)", want);
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        }
        if (i == 0) x->c->first_index = (int)num;
        lh__scan_next(x->s, 0, &t);
    }
    int k = 0;
    for (; x->c->nv ? k < x->c->nv : t.kind == LH__TOK_WORD && k <= MAX_NV; k++) {
        lh_status st = index_of(x, &t, i, &v[k]);
        if (st != LH_OK) return st;
        if (x->c->nv == 0 || k + 1 < x->c->nv) lh__scan_next(x->s, 0, &t);
    }
    if (x->c->nv == 0) { /* the first 'i' line: its length */
        if (t.kind != LH__TOK_EOL && t.kind != LH__TOK_EOF && k <= MAX_NV)
            return lh__expected(x->s, LH_ERR_PARSE, &t, "a point index or the end of the line", NULL);
        if (k < 2 || k > MAX_NV)
            return lh__fail_at(x->s, LH_ERR_PARSE, &at, k > MAX_NV ? "a cell of more than 9 points: lifthull works in 1 to 8 dimensions"
                                                                   : "a cell of fewer than 2 points");
        x->c->nv = k;
    } else {
        lh_status st = line_end(x, i);
        if (st != LH_OK) return st;
    }
    return push(x, &at, v);
}

static lh_status read_header(cells_ctx *x)
{
    lh__token t;
    lh__scan_next(x->s, 1, &t);
    lh_status st = lh__count(x->s, &t, "the number of cells", &x->declared);
    if (st != LH_OK) return st;
    long long f[2];
    int fields = 0;
    for (lh__scan_next(x->s, 0, &t); t.kind == LH__TOK_WORD && fields < 2; lh__scan_next(x->s, 0, &t)) {
        const char *what = fields ? "the number of attributes (an integer from 0 to 100)"
                                  : "the number of points per cell (an integer from 2 to 9)";
        if (!lh__word_integer(&t, &f[fields]) || f[fields] < (fields ? 0 : 2) || f[fields] > (fields ? 100 : MAX_NV))
            return lh__expected(x->s, LH_ERR_PARSE, &t, what, NULL);
        fields++;
    }
    if (t.kind != LH__TOK_EOL && t.kind != LH__TOK_EOF)
        return lh__expected(x->s, LH_ERR_PARSE, &t, "the end of the header line", NULL);
    x->ele = fields > 0;
    x->c->nv = fields ? (int)f[0] : 0;
    x->attrs = x->c->attr_count = fields > 1 ? (int)f[1] : 0;
    return LH_OK;
}

static lh_status read_cells(FILE *f, const char *name, size_t n_points, const lh_allocator *alloc,
                            lh_cells *out, lh_error *err)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (!f || !lh__allocator_init(&out->alloc_, alloc)) return LH_ERR_INVALID_ARGUMENT;
    lh__scan *s = lh__scan_open(f, 0, &out->alloc_, name ? name : "<input>", err);
    if (!s) {
        lh_cells_free(out);
        return LH_ERR_NOMEM;
    }
    cells_ctx x = {s, out, 0, 0, n_points, 0, 0, {0}};
    lh_status st = read_header(&x);
    for (size_t i = 0; st == LH_OK && i < x.declared; i++) {
        st = read_cell(&x, i);
    }
    lh__token t;
    if (st == LH_OK) lh__scan_next(s, 1, &t);
    if (st == LH_OK && t.kind != LH__TOK_EOF) {
        char what[80];
        snprintf(what, sizeof what, "the end of the input after %zu cell%s", x.declared, x.declared == 1 ? "" : "s");
        st = lh__expected(s, LH_ERR_PARSE, &t, what, NULL);
    }
    lh__scan_close(s);
    if (st != LH_OK) lh_cells_free(out);
    return st;
}

lh_status lh_cells_read(FILE *f, const char *name, size_t n_points, const lh_allocator *alloc,
                        lh_cells *out, lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, read_cells(f, name, n_points, alloc, out, err));
}
