/*
 * pred.c — the public predicates: filter, then exact stage, then (for *_sos) the
 * perturbation; the context that holds counters and the exact stage's scratch.
 * Stages: lh_filter.gen.h (generated), pred_bound.c, pred_wide.c, pred_exact.c,
 * pred_sos.c.
 */
#include "lh_alloc.h"
#include "lh_filter.gen.h"
#include "pred_internal.h"

#include <string.h>

static void subsets_init(lh__subsets *sub)
{
    memset(sub, 0, sizeof *sub);
    for (int mask = 0; mask < (1 << (LH__MAXN - 1)); mask++) {
        int size = 0;
        for (int b = mask; b; b >>= 1) size += b & 1;
        sub->slot[mask] = sub->count[size];
        sub->by_size[size][sub->count[size]++] = (uint16_t)mask;
    }
}

lh_status lh_pred_create(const lh_allocator *alloc, lh_pred **out)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    *out = NULL;
    lh_allocator a;
    if (!lh__allocator_init(&a, alloc)) return LH_ERR_INVALID_ARGUMENT;
    lh_pred *ctx = lh__alloc(&a, sizeof *ctx);
    if (!ctx) return LH_ERR_NOMEM;
    memset(ctx, 0, sizeof *ctx);
    ctx->alloc = a;
    subsets_init(&ctx->sub);
    ctx->arena = lh__alloc(&a, LH__ARENA_LIMBS * sizeof *ctx->arena);
    ctx->sp_coef = lh__alloc(&a, LH__SP_OFFSETS * sizeof *ctx->sp_coef);
    ctx->sp_flag = lh__alloc(&a, LH__SP_OFFSETS);
    if (!ctx->arena || !ctx->sp_coef || !ctx->sp_flag) {
        lh_pred_free(ctx);
        return LH_ERR_NOMEM;
    }
    memset(ctx->sp_coef, 0, LH__SP_OFFSETS * sizeof *ctx->sp_coef);
    memset(ctx->sp_flag, 0, LH__SP_OFFSETS);
    *out = ctx;
    return LH_OK;
}

void lh_pred_free(lh_pred *ctx)
{
    if (!ctx) return;
    lh_allocator a = ctx->alloc;
    lh__free(&a, ctx->arena);
    lh__free(&a, ctx->sp_coef);
    lh__free(&a, ctx->sp_flag);
    lh__free(&a, ctx);
}

void lh_pred_counters_get(const lh_pred *ctx, lh_pred_counters *out)
{
    if (!out) return;
    if (ctx)
        *out = ctx->count;
    else
        memset(out, 0, sizeof *out);
}

void lh_pred_counters_reset(lh_pred *ctx)
{
    if (ctx) memset(&ctx->count, 0, sizeof ctx->count);
}

/* The stages after a filter that could not decide (det, err its value and bound):
 * granularity rule, the wide filter's first pass, residues (exact zeros), its
 * double-word pass, exact stage; counts the stage when `count` is set. The cheap
 * stages that decide most calls come first: the granularity rule on grids, the
 * first wide pass on mixed magnitudes and clusters; the residues cost less than the
 * double-word pass and decide what it cannot (exact zeros). */
static int after_filter(lh_pred *ctx, int dim, int lifted, const double *const *pts,
                        double det, double err, int count)
{
    int s, stage = lh__bound_sign(&ctx->sub, dim, lifted, pts, det, err, 0, &s);
    int wide = 0;
    if (!stage) wide = lh__wide_sign(&ctx->sub, dim, lifted, pts, 0, &s);
    if (!stage && !wide) stage = lh__bound_sign(&ctx->sub, dim, lifted, pts, det, err, 1, &s);
    if (!stage && !wide) wide = lh__wide_sign(&ctx->sub, dim, lifted, pts, 1, &s);
    if (count && stage == LH__BY_GRANULARITY) ctx->count.grid_exits++;
    if (count && stage == LH__BY_RESIDUES) ctx->count.residue_exits++;
    if (wide) {
        if (count) ctx->count.filter_exits++;
    } else if (!stage) {
        if (count) ctx->count.exact_exits++;
        s = lifted ? lh__insphere_exact(ctx, dim, pts) : lh__orient_exact(ctx, dim, pts);
    }
    if (count && !s) ctx->count.zero_results++;
    return s;
}

/* Filter, then the stages after it. */
static inline int evaluate(lh_pred *ctx, int dim, int lifted, const double *const *pts, int count)
{
    int s;
    double det = 0, err = -1;
    if (!lh__filter_d(lifted, dim, pts, &s, &det, &err))
        return after_filter(ctx, dim, lifted, pts, det, err, count);
    if (count) ctx->count.filter_exits++;
    if (count && !s) ctx->count.zero_results++;
    return s;
}

int lh__orient_sign(lh_pred *ctx, int k, const double *const *pts)
{
    return evaluate(ctx, k, 0, pts, 0);
}

int lh_orient(lh_pred *ctx, int k, const double *const *pts)
{
    if (!ctx || !pts || k < 1 || k > LH_ORIENT_MAX_DIM) return 0;
    ctx->count.calls++;
    return evaluate(ctx, k, 0, pts, 1);
}

int lh_insphere(lh_pred *ctx, int d, const double *const *pts)
{
    if (!ctx || !pts || d < 1 || d > LH_INSPHERE_MAX_DIM) return 0;
    ctx->count.calls++;
    return evaluate(ctx, d, 1, pts, 1);
}

int lh__insphere_sos_fast(lh_pred *ctx, int d, const double *const *pts)
{
    ctx->count.calls++;
    int s = evaluate(ctx, d, 1, pts, 1);
    return s ? s : lh__sos_sign(ctx, pts, d, 1);
}

int lh__insphere_sos_unfiltered(lh_pred *ctx, int d, const double *const *pts, double det,
                                double err)
{
    ctx->count.calls++;
    int s = after_filter(ctx, d, 1, pts, det, err, 1);
    return s ? s : lh__sos_sign(ctx, pts, d, 1);
}

void lh__pred_count_zero(lh_pred *ctx)
{
    ctx->count.calls++;
    ctx->count.grid_exits++;
    ctx->count.zero_results++;
}

int lh__insphere_sos_zero(lh_pred *ctx, int d, const double *const *pts)
{
    lh__pred_count_zero(ctx);
    return lh__sos_sign(ctx, pts, d, 1);
}

int lh__orient_unfiltered(lh_pred *ctx, int k, const double *const *pts, double det,
                          double err)
{
    ctx->count.calls++;
    return after_filter(ctx, k, 0, pts, det, err, 1);
}

int lh_orient_sos(lh_pred *ctx, int k, const double *const *pts)
{
    int s = lh_orient(ctx, k, pts);
    if (s || !ctx || !pts || k < 1 || k > LH_ORIENT_MAX_DIM) return s;
    return lh__sos_sign(ctx, pts, k, 0);
}

int lh_insphere_sos(lh_pred *ctx, int d, const double *const *pts)
{
    int s = lh_insphere(ctx, d, pts);
    if (s || !ctx || !pts || d < 1 || d > LH_INSPHERE_MAX_DIM) return s;
    return lh__sos_sign(ctx, pts, d, 1);
}

void lh__pred_count_filtered(lh_pred *ctx, uint64_t n)
{
    ctx->count.calls += n;
    ctx->count.filter_exits += n;
}

void lh__pred_move_counters(lh_pred *dst, lh_pred *src)
{
    lh_pred_counters *a = &dst->count, *b = &src->count;
    a->calls += b->calls;
    a->filter_exits += b->filter_exits;
    a->grid_exits += b->grid_exits;
    a->residue_exits += b->residue_exits;
    a->exact_exits += b->exact_exits;
    a->zero_results += b->zero_results;
    a->sos_fast += b->sos_fast;
    a->sos_general += b->sos_general;
    memset(b, 0, sizeof *b);
}

double lh__fp_contract_probe(double a, double b, double c) { return a * b + c; }
