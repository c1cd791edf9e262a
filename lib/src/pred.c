/*
 * pred.c — the public predicates: filter, then exact stage, then (for *_sos) the
 * perturbation; the context that holds counters and the exact stage's scratch.
 * Stages: pred_filter.gen.h (generated), pred_exact.c, pred_sos.c.
 */
#include "alloc.h"
#include "pred_filter.gen.h"
#include "pred_internal.h"

#include <string.h>

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
    ctx->arena = lh__alloc(&a, LH__ARENA_LIMBS * sizeof *ctx->arena);
    if (!ctx->arena) {
        lh__free(&a, ctx);
        return LH_ERR_NOMEM;
    }
    *out = ctx;
    return LH_OK;
}

void lh_pred_free(lh_pred *ctx)
{
    if (!ctx) return;
    lh_allocator a = ctx->alloc;
    lh__free(&a, ctx->arena);
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

static int orient_filter(int k, const double *const *p, int *s)
{
    switch (k) {
    case 1: return lh__orient_filter_1(p, s);
    case 2: return lh__orient_filter_2(p, s);
    case 3: return lh__orient_filter_3(p, s);
    case 4: return lh__orient_filter_4(p, s);
    case 5: return lh__orient_filter_5(p, s);
    case 6: return lh__orient_filter_6(p, s);
    case 7: return lh__orient_filter_7(p, s);
    default: return lh__orient_filter_8(p, s);
    }
}

static int insphere_filter(int d, const double *const *p, int *s)
{
    switch (d) {
    case 1: return lh__insphere_filter_1(p, s);
    case 2: return lh__insphere_filter_2(p, s);
    case 3: return lh__insphere_filter_3(p, s);
    case 4: return lh__insphere_filter_4(p, s);
    case 5: return lh__insphere_filter_5(p, s);
    case 6: return lh__insphere_filter_6(p, s);
    default: return lh__insphere_filter_7(p, s);
    }
}

int lh__orient_sign(lh_pred *ctx, int k, const double *const *pts)
{
    int s;
    if (orient_filter(k, pts, &s)) return s;
    return lh__orient_exact(ctx, k, pts);
}

/* Counts which stage answered a public call. */
static int counted(lh_pred *ctx, int filtered, int s)
{
    if (filtered) {
        ctx->count.filter_exits++;
        return s;
    }
    ctx->count.exact_exits++;
    if (!s) ctx->count.zero_results++;
    return s;
}

int lh_orient(lh_pred *ctx, int k, const double *const *pts)
{
    if (!ctx || !pts || k < 1 || k > LH_ORIENT_MAX_DIM) return 0;
    ctx->count.calls++;
    int s;
    if (orient_filter(k, pts, &s)) return counted(ctx, 1, s);
    return counted(ctx, 0, lh__orient_exact(ctx, k, pts));
}

int lh_insphere(lh_pred *ctx, int d, const double *const *pts)
{
    if (!ctx || !pts || d < 1 || d > LH_INSPHERE_MAX_DIM) return 0;
    ctx->count.calls++;
    int s;
    if (insphere_filter(d, pts, &s)) return counted(ctx, 1, s);
    return counted(ctx, 0, lh__insphere_exact(ctx, d, pts));
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

double lh__fp_contract_probe(double a, double b, double c) { return a * b + c; }
