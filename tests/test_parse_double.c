/*
 * test_parse_double.c — the readers' decimal conversion (parse_double.c) against the
 * C library's strtod, bit for bit, and whether each string is accepted: random
 * decimal strings of every length, exponents at the edges of the range, subnormals,
 * exact halfway points between neighbouring doubles and strings one digit beside
 * them, 19- and 20-digit significands, the shortest and the 17-digit form of random
 * doubles, and non-plain forms (hexadecimal, inf, nan, malformed). Also: the fast
 * stages decide nearly every 17-digit decimal (so they are really exercised), and
 * every value they decide is strtod's.
 */
#include "io_internal.h"
#include "lh_test.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint64_t next(void) { return lh_test_xorshift(&rng); }

static uint64_t bits_of(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

typedef struct tally {
    long cases, fast;
} tally;

/* One string: lh__parse_double must accept it exactly when strtod consumes all of it,
 * with the same bits; lh__parse_fast, when it decides, must give those bits too. */
static int same_as_strtod(lh_test_state *lh_t_, const char *s, tally *n)
{
    size_t len = strlen(s);
    char *end;
    double want = strtod(s, &end);
    int want_ok = len > 0 && end == s + len;
    double got = 0, fast = 0;
    int ok = lh__parse_double(s, len, &got);
    int decided = lh__parse_fast(s, len, &fast);
    n->cases++;
    n->fast += decided;
    if (ok != want_ok || (ok && bits_of(got) != bits_of(want)) ||
        (decided && (!want_ok || bits_of(fast) != bits_of(want)))) {
        LH_NOTE("'%s': strtod %a (%s), lh__parse_double %a (%s), fast %a (%s)", s, want,
                want_ok ? "whole" : "partial", got, ok ? "ok" : "rejected", fast,
                decided ? "decided" : "undecided");
        LH_EXPECT_TRUE(0);
        return 0;
    }
    return 1;
}

/* A random decimal: sign, ndig digits with a point somewhere (or none), optional exponent. */
static void random_decimal(char *buf, int ndig, int exp_lo, int exp_hi)
{
    char *p = buf;
    uint64_t r = next();
    if (r & 1) *p++ = '-';
    else if (r & 2) *p++ = '+';
    int point = (int)(next() % (uint64_t)(ndig + 2)) - 1; /* -1: no point */
    for (int i = 0; i < ndig; i++) {
        if (i == point) *p++ = '.';
        /* Mostly nonzero leading digits; sometimes leading or trailing zero runs. */
        int z = (next() % 8) == 0;
        *p++ = z ? '0' : (char)('0' + next() % 10);
    }
    if (point == ndig) *p++ = '.';
    if (next() % 4) {
        int e = exp_lo + (int)(next() % (uint64_t)(exp_hi - exp_lo + 1));
        p += sprintf(p, "%c%d", (next() & 1) ? 'e' : 'E', e);
    }
    *p = 0;
}

LH_TEST(random_decimals_of_every_length)
{
    tally n = {0, 0};
    char buf[128];
    for (int ndig = 1; ndig <= 40; ndig++)
        for (int k = 0; k < 6000 && !LH_FAILED(); k++) {
            random_decimal(buf, ndig, -30, 30);
            same_as_strtod(lh_t_, buf, &n);
        }
    LH_EXPECT_GT_INT(n.fast, n.cases / 3);
}

LH_TEST(exponents_at_the_edges)
{
    tally n = {0, 0};
    char buf[128];
    for (int e = -380; e <= 330 && !LH_FAILED(); e++)
        for (int ndig = 1; ndig <= 21; ndig++)
            for (int k = 0; k < 12; k++) {
                random_decimal(buf, ndig, e, e);
                same_as_strtod(lh_t_, buf, &n);
            }
    static const char *const fixed[] = {
        "1e308", "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308",
        "1.797693134862315807e308", "1.7976931348623157e309", "2.2250738585072014e-308",
        "2.2250738585072011e-308", "2.2250738585072012e-308", "4.9406564584124654e-324",
        "2.4703282292062327e-324", "2.4703282292062328e-324", "5e-324", "1e-400", "1e400",
        "0e999999999", "1e-999999999", "-0", "-0.0e5", "+0", "0", "000000000000000000000001",
        "1e-342", "1e-343", "9999999999999999999e-362", "1e308", "99999999999999999999e289"};
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++) same_as_strtod(lh_t_, fixed[i], &n);
}

/* The decimal expansion of a finite double, exact ("%.*e" with enough digits). */
static void exact_decimal(char *buf, size_t size, double x) { snprintf(buf, size, "%.780e", x); }

LH_TEST(halfway_points_and_their_neighbours)
{
    tally n = {0, 0};
    static char buf[1024], cut[64];
    for (int k = 0; k < 20000 && !LH_FAILED(); k++) {
        /* a random double, normal or subnormal, and the midpoint to its successor */
        uint64_t b = next() & 0x7FEFFFFFFFFFFFFFu;
        if (k % 4 == 0) b &= 0x000FFFFFFFFFFFFFu; /* subnormal */
        if (k % 4 == 1) b = (b & 0x000FFFFFFFFFFFFFu) | ((uint64_t)(1023 + (int)(next() % 120) - 60) << 52);
        double x, y;
        memcpy(&x, &b, sizeof x);
        y = nextafter(x, INFINITY);
        /* The midpoint is exact in long double only sometimes; write it from both
         * neighbours' exact expansions instead: x + (y - x) / 2 has one more bit. */
        long double mid = ((long double)x + (long double)y) / 2;
        snprintf(buf, sizeof buf, "%.780Le", mid);
        same_as_strtod(lh_t_, buf, &n); /* exact halfway when long double holds it */
        /* 17, 18, 19 and 20 significant digits of it, truncated and one unit up */
        for (int digits = 17; digits <= 20; digits++) {
            snprintf(cut, sizeof cut, "%.*Le", digits - 1, mid);
            same_as_strtod(lh_t_, cut, &n);
            char *e = strchr(cut, 'e');
            if (e && e[-1] < '9') {
                e[-1]++;
                same_as_strtod(lh_t_, cut, &n);
            }
        }
        exact_decimal(buf, sizeof buf, x);
        same_as_strtod(lh_t_, buf, &n);
    }
}

LH_TEST(significands_of_19_and_20_digits)
{
    tally n = {0, 0};
    char buf[64];
    for (int k = 0; k < 200000 && !LH_FAILED(); k++) {
        uint64_t w = next();
        int e = (int)(next() % 700) - 360;
        snprintf(buf, sizeof buf, "%llue%d", (unsigned long long)(w % 10000000000000000000u), e);
        same_as_strtod(lh_t_, buf, &n); /* 19 digits (or fewer) */
        snprintf(buf, sizeof buf, "%llue%d", (unsigned long long)w, e);
        same_as_strtod(lh_t_, buf, &n); /* 20 digits when w >= 10^19 */
        snprintf(buf, sizeof buf, "%llu", (unsigned long long)w);
        same_as_strtod(lh_t_, buf, &n);
    }
}

LH_TEST(random_doubles_round_trip_and_are_fast)
{
    tally n = {0, 0}, seventeen = {0, 0};
    char buf[64];
    for (int k = 0; k < 300000 && !LH_FAILED(); k++) {
        uint64_t b = next();
        double x;
        memcpy(&x, &b, sizeof x);
        if (!isfinite(x)) continue;
        if (k & 1) x = ldexp((double)(b >> 11), -53) - 0.5; /* as lifthull points writes */
        snprintf(buf, sizeof buf, "%.17g", x);
        same_as_strtod(lh_t_, buf, &seventeen);
        snprintf(buf, sizeof buf, "%.15g", x);
        same_as_strtod(lh_t_, buf, &n);
        snprintf(buf, sizeof buf, "%.6f", x);
        same_as_strtod(lh_t_, buf, &n);
    }
    /* Only exactly representable or halfway-near decimals and subnormal or huge results
     * are left to strtod: under 1% of 17-digit forms of random doubles. */
    LH_EXPECT_GT_INT(seventeen.fast, seventeen.cases * 99 / 100);
}

LH_TEST(other_forms_are_strtod_s)
{
    tally n = {0, 0};
    static const char *const forms[] = {
        "0x1p-3", "0X1.8P1", "inf", "-Infinity", "nan", "NAN(123)", "1e", "1e+", "e5", ".",
        "+", "-", "", "1.2.3", "1..2", "--1", "+-1", "1e5.5", "1,5", "1d5", "0x", "1_000",
        ".5", "5.", "-.5e-3", "00.00", "1e0000000000000000000000001", "١", " 1", "1 "};
    for (size_t i = 0; i < sizeof forms / sizeof *forms; i++) same_as_strtod(lh_t_, forms[i], &n);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(random_decimals_of_every_length),
                                         LH_CASE(exponents_at_the_edges),
                                         LH_CASE(halfway_points_and_their_neighbours),
                                         LH_CASE(significands_of_19_and_20_digits),
                                         LH_CASE(random_doubles_round_trip_and_are_fast),
                                         LH_CASE(other_forms_are_strtod_s)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
