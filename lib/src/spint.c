/* spint.c — sparse signed-digit integers (spint.h): balanced radix-2^26 digits kept
 * only where nonzero; sums of products accumulated per digit offset and normalised
 * once per value (Knuth, TAOCP vol. 2, 4.1 on balanced number systems, 4.3.1 for the
 * carries). */
#include "spint.h"

#include "bigint.h"

#include <string.h>

#define RADIX (INT64_C(1) << LH__SP_BITS)

void lh__sp_acc_init(lh__sp_acc *a, int64_t *c, uint8_t *flag, int size)
{
    a->c = c;
    a->flag = flag;
    a->size = size;
    a->lo = size;
    a->hi = -1;
    a->load = 0;
    a->failed = 0;
    a->work = 0;
}

/* Whether offsets lo..hi fit, with room for the carries, and `adds` more additions
 * per offset keep every coefficient below 2^62 (see spint.h); marks the range. */
static int reserve(lh__sp_acc *a, int lo, int hi, int adds)
{
    a->load += adds;
    if (hi + 3 >= a->size || a->load > LH__SP_MAX_ADDS) {
        a->failed = 1;
        return 0;
    }
    if (lo < a->lo) a->lo = lo;
    if (hi > a->hi) a->hi = hi;
    return 1;
}

void lh__sp_acc_add_dbl(lh__sp_acc *a, double x, int scale, int neg)
{
    int e, sgn;
    uint64_t m = lh__dbl_decompose(x, &e, &sgn);
    if (!m) return;
    while (!(m & 1)) { /* m odd: e is then the exponent of x's lowest set bit */
        m >>= 1;
        e++;
    }
    int shift = e - scale; /* >= 0 by the precondition */
    int o = shift / LH__SP_BITS, bit = shift % LH__SP_BITS;
    if (!reserve(a, o, o + 2, 1)) return;
    /* m 2^bit < 2^78 (m < 2^53, bit < 26) in three digits' worth of pieces. */
    int64_t s = (sgn ^ neg) ? -1 : 1, mask = RADIX - 1;
    int64_t piece[3] = {(int64_t)((m << bit) & (uint64_t)mask),
                        (int64_t)((m >> (LH__SP_BITS - bit)) & (uint64_t)mask),
                        (int64_t)(m >> (2 * LH__SP_BITS - bit))};
    for (int k = 0; k < 3; k++) {
        a->c[o + k] += s * piece[k];
        a->flag[o + k] = 1;
    }
}

void lh__sp_acc_add_mul(lh__sp_acc *a, const lh__sp *x, const lh__sp *y, int neg)
{
    if (!x->n || !y->n) return;
    /* At most min(x->n, y->n) digit pairs land on one offset. */
    int lo = x->t[0].off + y->t[0].off, hi = x->t[x->n - 1].off + y->t[y->n - 1].off;
    if (!reserve(a, lo, hi, x->n < y->n ? x->n : y->n)) return;
    a->work += (uint64_t)x->n * (uint64_t)y->n;
    /* restrict: the flags are bytes, which may alias anything; without it every flag
     * store would force y's digits to be reloaded. */
    const lh__sd *restrict yt = y->t;
    int yn = y->n;
    for (int i = 0; i < x->n; i++) {
        int64_t xd = neg ? -(int64_t)x->t[i].dig : (int64_t)x->t[i].dig;
        int64_t *restrict ci = a->c + x->t[i].off;
        uint8_t *restrict fi = a->flag + x->t[i].off;
        for (int j = 0; j < yn; j++) {
            int o = yt[j].off;
            ci[o] += xd * yt[j].dig; /* |product| <= 2^50 */
            fi[o] = 1;
        }
    }
}

void lh__sp_acc_add(lh__sp_acc *a, const lh__sp *x, int neg)
{
    if (!x->n || !reserve(a, x->t[0].off, x->t[x->n - 1].off, 1)) return;
    for (int i = 0; i < x->n; i++) {
        a->c[x->t[i].off] += neg ? -(int64_t)x->t[i].dig : x->t[i].dig;
        a->flag[x->t[i].off] = 1;
    }
}

/* The least flagged offset in [o, hi], or -1; whole words of flags at a time. */
static int next_flag(const uint8_t *flag, int o, int hi)
{
    for (; o <= hi && (o & 7); o++)
        if (flag[o]) return o;
    for (; o + 7 <= hi; o += 8) {
        uint64_t w;
        memcpy(&w, flag + o, sizeof w);
        if (w) break;
    }
    for (; o <= hi; o++)
        if (flag[o]) return o;
    return -1;
}

int lh__sp_acc_take(lh__sp_acc *a, lh__sp_pool *pool, lh__sp *r)
{
    lh__sd *out = pool->d + pool->used;
    size_t room = pool->cap - pool->used, n = 0;
    int o = a->lo;
    int64_t carry = 0;
    for (;;) {
        if (!carry && (o = next_flag(a->flag, o, a->hi)) < 0) break;
        /* o <= hi + 2 < size: a carry out of |v| < 2^62 dies within two digits. */
        int64_t v = a->c[o] + carry, d = v & (RADIX - 1);
        a->c[o] = 0;
        a->flag[o] = 0;
        if (d >= RADIX / 2) d -= RADIX; /* balanced: d in [-2^25, 2^25) */
        carry = (v - d) / RADIX;       /* exact */
        if (d) {
            if (n < room) {
                out[n].off = o;
                out[n].dig = (int32_t)d;
            }
            n++;
        }
        o++;
    }
    int ok = !a->failed && n <= room;
    a->lo = a->size;
    a->hi = -1;
    a->load = 0;
    a->failed = 0;
    a->work += n;
    if (!ok) return 0;
    r->t = out;
    r->n = (int)n;
    pool->used += n;
    return 1;
}
