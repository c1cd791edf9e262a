/*
 * parse_double.c — decimal text to the nearest double, as strtod does it, with two
 * fast stages that answer only when they are sure (io_internal.h, lh__parse_double).
 *
 * References:
 *   W. D. Clinger, "How to Read Floating Point Numbers Accurately", PLDI 1990: when
 *   the decimal significand w and 10^|q| are both exact doubles (w <= 2^53,
 *   |q| <= 22), one IEEE multiplication or division rounds w * 10^q correctly.
 *   D. Lemire, "Number Parsing at a Gigabyte per Second", Software: Practice and
 *   Experience 51(8), 2021 (the Eisel–Lemire algorithm): multiply the normalised
 *   64-bit significand by a 128-bit approximation of 5^q and read the rounding from
 *   the leading bits of the product unless the bits below the rounding point are
 *   too close to a boundary for the approximation's error to be excluded.
 *
 * Design. Only the plain form [+-]digits[.digits][(e|E)[+-]digits] with at most 19
 * significant digits reaches the fast stages; everything else (hexadecimal,
 * infinities, NaN, more digits, malformed text) goes to strtod, which also decides
 * what is accepted. The Eisel–Lemire stage here is the conservative variant: the
 * product W * T, T the table's 128-bit value of 5^q, differs from the exact W * X by
 * less than W < 2^64 (lh_pow5.gen.h: |X - T| < 1). Write the 192-bit product as the
 * 53 bits of the significand, the rounding bit, then k >= 137 more bits R. When the
 * bits of R above its lowest 64 are neither all zero nor all one, adding any error
 * of magnitude below 2^64 changes neither the bits above R nor R's being nonzero:
 * the correctly rounded result is the significand plus the rounding bit (a tie is
 * impossible, the remainder being nonzero). Otherwise — exactly representable or
 * halfway decimals, about 2^-72 of random ones, the rest caught by Clinger's stage —
 * and for results that would be subnormal or overflow, strtod decides.
 */
#include "io_internal.h"
#include "lh_pow5.gen.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* The plain form's fields: the value is (neg ? -1 : 1) * w * 10^q. */
typedef struct plain {
    uint64_t w;
    long q;
    int neg;
} plain;

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* Eight ASCII bytes as a little-endian word (one load where the compiler sees it). */
static uint64_t load8(const char *p)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--) v = v << 8 | (unsigned char)p[i];
    return v;
}

/* Whether all eight bytes of v are ASCII digits (Lemire 2021, section 5: a byte is a
 * digit when its high nibble is 3 and adding 6 does not carry into it). */
static int eight_digits(uint64_t v)
{
    const uint64_t hi = 0xF0F0F0F0F0F0F0F0u;
    return ((v & hi) | (((v + 0x0606060606060606u) & hi) >> 4)) == 0x3333333333333333u;
}

/* The value of eight ASCII digits, the first in the lowest byte: pairs, then
 * quadruples, then the whole, each step one multiplication. */
static uint64_t eight_value(uint64_t v)
{
    v = (v & 0x0F0F0F0F0F0F0F0Fu) * 2561 >> 8;           /* 10 * a + b per 16 bits    */
    v = (v & 0x00FF00FF00FF00FFu) * 6553601 >> 16;       /* 100 * a + b per 32 bits   */
    return (v & 0x0000FFFF0000FFFFu) * 42949672960001u >> 32; /* 10^4 * a + b      */
}

/* Appends the digits at *pp (up to end) to *w; *sig counts significant digits, *q
 * is lowered by one per digit when `fraction`. 0 when a 20th significant digit comes. */
static int digits(const char **pp, const char *end, uint64_t *w, int *sig, long *q,
                  int fraction, int *count)
{
    const char *p = *pp;
    for (;;) {
        if (*w && *sig <= 11 && end - p >= 8 && eight_digits(load8(p))) {
            *w = *w * 100000000u + eight_value(load8(p));
            *sig += 8;
            p += 8;
            if (fraction) *q -= 8;
            continue;
        }
        if (p == end || !is_digit(*p)) break;
        if (fraction) (*q)--;
        if (*sig || *p != '0') {
            if (*sig == 19) return 0;
            *w = 10 * *w + (uint64_t)(*p - '0');
            (*sig)++;
        }
        p++;
    }
    *count += (int)(p - *pp);
    *pp = p;
    return 1;
}

/* Reads the plain form spanning all of text[0..len); 0 when text is not of that form
 * or has more than 19 significant digits. */
static int read_plain(const char *text, size_t len, plain *out)
{
    const char *p = text, *end = text + len;
    out->neg = 0;
    if (p < end && (*p == '+' || *p == '-')) out->neg = *p++ == '-';
    uint64_t w = 0;
    int sig = 0, count = 0;
    long q = 0;
    if (!digits(&p, end, &w, &sig, &q, 0, &count)) return 0;
    if (p < end && *p == '.') {
        p++;
        if (!digits(&p, end, &w, &sig, &q, 1, &count)) return 0;
    }
    if (count == 0) return 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        p++;
        int eneg = 0;
        if (p < end && (*p == '+' || *p == '-')) eneg = *p++ == '-';
        if (p == end || !is_digit(*p)) return 0;
        long e = 0;
        for (; p < end && is_digit(*p); p++)
            if (e < 100000) e = 10 * e + (*p - '0'); /* beyond, the value is 0 or inf */
        q += eneg ? -e : e;
    }
    if (p != end) return 0;
    out->w = w;
    out->q = q;
    return 1;
}

static double with_sign(double x, int neg) { return neg ? -x : x; }

/* Clinger's stage; 1 when it applies. Needs evaluation in double precision itself
 * (FLT_EVAL_METHOD 0): an extended intermediate would round twice. */
static int clinger(const plain *v, double *x)
{
#if FLT_EVAL_METHOD == 0
    static const double pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    if (v->w > ((uint64_t)1 << 53) || v->q < -22 || v->q > 22) return 0;
    double m = (double)v->w;
    *x = with_sign(v->q < 0 ? m / pow10[-v->q] : m * pow10[v->q], v->neg);
    return 1;
#else
    (void)v;
    (void)x;
    return 0;
#endif
}

/* hi:lo = a * b. */
static void mul_64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#ifdef __SIZEOF_INT128__
    unsigned __int128 p = (unsigned __int128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
#else
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10; /* < 3 * 2^32 */
    *lo = (mid << 32) | (uint32_t)p00;
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

/* The number of leading zero bits of w != 0. */
static int leading_zeros(uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_clzll(w);
#else
    int n = 0;
    for (; !(w >> 63); w <<= 1) n++;
    return n;
#endif
}

/* The Eisel–Lemire stage (see the design note above); 1 when it decided. */
static int eisel_lemire(const plain *v, double *x)
{
    if (v->w == 0 || v->q < LH__POW5_MIN || v->q > LH__POW5_MAX) return 0;
    const lh__pow5 *t = &lh__pow5_table[v->q - LH__POW5_MIN];
    int lz = leading_zeros(v->w);
    uint64_t w = v->w << lz, h1, l1, h2, l2;
    mul_64(w, t->lo, &h1, &l1);
    mul_64(w, t->hi, &h2, &l2);
    uint64_t p1 = h1 + l2, p2 = h2 + (p1 < h1); /* p2:p1:l1 = w * T, in [2^190, 2^192) */
    int top = (int)(p2 >> 63);             /* the leading bit is 190 + top          */
    int low = 9 + top;                      /* bits of p2 below the rounding bit     */
    uint64_t r = p2 & (((uint64_t)1 << low) - 1);
    if ((r == 0 && p1 == 0) || (r == ((uint64_t)1 << low) - 1 && p1 == UINT64_MAX)) return 0;
    /* value = W * X * 2^(e + q - lz) and W * X ~ m * 2^(138 + top) */
    uint64_t m = p2 >> (low + 1); /* 53 bits */
    long e2 = 138 + top + t->e + v->q - lz;
    m += (p2 >> low) & 1; /* round: the remainder below the rounding bit is nonzero */
    if (m >> 53) {
        m >>= 1;
        e2++;
    }
    long biased = e2 + 52 + 1023; /* value = m * 2^e2, 2^52 <= m < 2^53 */
    if (biased < 1 || biased > 2046) return 0;
    uint64_t bits = ((uint64_t)biased << 52) | (m & (((uint64_t)1 << 52) - 1));
    bits |= (uint64_t)v->neg << 63;
    memcpy(x, &bits, sizeof *x);
    return 1;
}

int lh__parse_fast(const char *text, size_t len, double *x)
{
    plain v;
    if (!read_plain(text, len, &v)) return 0;
    if (v.w == 0) {
        *x = with_sign(0.0, v.neg);
        return 1;
    }
    return clinger(&v, x) || eisel_lemire(&v, x);
}

int lh__parse_double(const char *text, size_t len, double *x)
{
    if (len == 0) return 0;
    if (lh__parse_fast(text, len, x)) return 1;
    char *end;
    *x = strtod(text, &end);
    return end == text + len;
}
