/*
 * fmt_number.c — numbers as printf writes them, without printf's cost per call: an
 * integer's "%lld" (lh__fmt_int), and a double's "%.17g" (lh__fmt_g17) where that is
 * quick to do exactly: the 17 significant digits of a finite x with 1e-4 <= |x| < 1e17 (the
 * fixed-point form of %g at precision 17), from the exact product of its integer
 * mantissa and a power of ten in 128-bit arithmetic, rounded half to even as
 * printf rounds in the default mode; any other x goes to snprintf. A double is
 * m 2^e with m < 2^53; for those x, e >= -66 and the product m 10^p (p <= 20) is
 * below 2^120, so the quotient and remainder by 2^-e are exact.
 */
#include "io_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#if defined(__SIZEOF_INT128__)
typedef unsigned __int128 u128;

/* round(m 2^e 10^p), half to even; m < 2^53, 0 <= p <= 20, -66 <= e <= 4. */
static uint64_t scaled_round(uint64_t m, int e, int p)
{
    u128 n = m;
    for (int i = 0; i < p; i++) n *= 10;
    if (e >= 0) return (uint64_t)(n << e);
    const u128 q = n >> -e, rem = n - (q << -e), half = (u128)1 << (-e - 1);
    return (uint64_t)(q + (rem > half || (rem == half && (q & 1))));
}

/* The fixed-point digits of |x| (17 significant, trailing zeros dropped) into out;
 * their length, or 0 when x is not one this handles. */
static size_t fixed17(double x, char *out)
{
    int e2;
    const double f = frexp(x, &e2);            /* x = f 2^e2, 0.5 <= f < 1 */
    const uint64_t m = (uint64_t)ldexp(f, 53); /* exact: f has 53 bits */
    int ex = (int)floor(log10(x));             /* the decimal exponent, maybe one off */
    uint64_t d = 0;
    for (int tries = 0; tries < 3; tries++) {
        if (ex < -4 || ex > 16) return 0;
        d = scaled_round(m, e2 - 53, 16 - ex);
        if (d >= UINT64_C(100000000000000000))
            ex++;
        else if (d < UINT64_C(10000000000000000))
            ex--;
        else
            break;
    }
    if (d < UINT64_C(10000000000000000) || d >= UINT64_C(100000000000000000)) return 0;
    char dig[17];
    for (int i = 16; i >= 0; i--) dig[i] = (char)('0' + d % 10), d /= 10;
    int last = 16; /* the last digit kept: trailing zeros after the point go */
    while (last > ex && last > 0 && dig[last] == '0') last--;
    size_t n = 0;
    if (ex < 0) {
        out[n++] = '0', out[n++] = '.';
        for (int i = -1; i > ex; i--) out[n++] = '0';
        for (int i = 0; i <= last; i++) out[n++] = dig[i];
        return n;
    }
    for (int i = 0; i <= last; i++) {
        out[n++] = dig[i];
        if (i == ex && i < last) out[n++] = '.';
    }
    return n;
}
#endif

size_t lh__fmt_int(long long v, char *out)
{
    char d[24];
    size_t k = 0, n = 0;
    unsigned long long u = v < 0 ? 0ULL - (unsigned long long)v : (unsigned long long)v;
    do {
        d[k++] = (char)('0' + u % 10);
    } while (u /= 10);
    if (v < 0) out[n++] = '-';
    while (k) out[n++] = d[--k];
    out[n] = '\0';
    return n;
}

size_t lh__fmt_g17(double x, char *out, size_t cap)
{
#if defined(__SIZEOF_INT128__)
    const double a = fabs(x);
    if (cap >= 32 && a >= 1e-4 && a < 1e17) {
        size_t n = 0;
        if (x < 0) out[n++] = '-';
        const size_t k = fixed17(a, out + n);
        if (k) {
            out[n + k] = '\0';
            return n + k;
        }
    }
#endif
    const int n = snprintf(out, cap, "%.17g", x);
    return n > 0 ? (size_t)n : 0;
}
