/*
 * squares3.c — every way to write m as a^2 + b^2 + c^2 (squares3.h).
 *
 * For each a with 3a^2 <= m the pairs (b, c) are the representations of k = m - a^2
 * as a sum of two squares, read off its factorisation in the Gaussian integers:
 * k = 2^e prod q^f prod p^g (q = 3 mod 4, p = 1 mod 4) is such a sum iff every f is
 * even, and its representations b + ci are the units times (1+i)^e prod q^(f/2)
 * prod pi^j conj(pi)^(g-j), p = pi conj(pi) (Hardy and Wright, ch. 16.9-16.10).
 * All the k = m - a^2 are factored at once by a sieve on the polynomial: p divides
 * m - a^2 exactly when a is a square root of m modulo p (Tonelli-Shanks), so each
 * prime p <= sqrt(m) visits only the a of its two root classes; what is left of k
 * after them is 1 or one prime above sqrt(m). pi comes from a square root t of -1
 * modulo p: the first remainder below sqrt(p) in Euclid's algorithm on (p, t) is
 * pi's real part (Hermite-Serret; Cornacchia's algorithm).
 *
 * Every product stays below 2^50 in magnitude (m < 2^50, components of divisors of
 * norm <= m below 2^25), and the modular products below 2^64 (mulmod), so the walk is
 * exact and the same on every machine.
 */
#include "squares3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

uint64_t lht_isqrt(uint64_t v)
{
    uint64_t s = (uint64_t)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    return s;
}

/* a b mod p for a, b < p < 2^62 (doubling when the product would pass 64 bits). */
static uint64_t mulmod(uint64_t a, uint64_t b, uint64_t p)
{
    if (p <= UINT32_MAX) return a * b % p;
    uint64_t r = 0;
    for (; b; b >>= 1) {
        if (b & 1) r = r >= p - a ? r - (p - a) : r + a;
        a = a >= p - a ? a - (p - a) : a + a;
    }
    return r;
}

static uint64_t powmod(uint64_t a, uint64_t e, uint64_t p)
{
    uint64_t r = 1 % p;
    for (a %= p; e; e >>= 1, a = mulmod(a, a, p))
        if (e & 1) r = mulmod(r, a, p);
    return r;
}

/* A square root of the quadratic residue x modulo the odd prime p (Tonelli-Shanks). */
static uint64_t sqrt_mod(uint64_t x, uint64_t p)
{
    uint64_t q = p - 1, z = 2;
    int s = 0;
    while (!(q & 1)) q >>= 1, s++;
    while (z < 65536 && powmod(z, (p - 1) / 2, p) != p - 1) z++; /* a non-residue */
    uint64_t c = powmod(z, q, p), r = powmod(x, (q + 1) / 2, p), t = powmod(x, q, p);
    while (t != 1) { /* invariant: r^2 = x t, t of order 2^i with i < s */
        int i = 0;
        for (uint64_t u = t; u != 1 && i < s; u = mulmod(u, u, p)) i++;
        if (i == s) return 0; /* x not a residue: unreachable with exact arithmetic */
        uint64_t b = c;
        for (int j = 0; j < s - i - 1; j++) b = mulmod(b, b, p);
        r = mulmod(r, b, p);
        c = mulmod(b, b, p);
        t = mulmod(t, c, p);
        s = i;
    }
    return r;
}

void lht_gauss_mul(int64_t z[2], int64_t re, int64_t im)
{
    int64_t x = z[0];
    z[0] = x * re - z[1] * im;
    z[1] = x * im + z[1] * re;
}

/* Checked, so that a defect (p not such a prime) cannot go unseen. */
int lht_gauss_split(uint64_t p, int64_t pi[2])
{
    uint64_t r0 = p, r1 = sqrt_mod(p - 1, p), sp = lht_isqrt(p);
    while (r1 > sp) {
        uint64_t r2 = r0 % r1;
        r0 = r1, r1 = r2;
    }
    const int64_t u = (int64_t)r1, v = (int64_t)lht_isqrt(p - r1 * r1);
    pi[0] = u > v ? u : v, pi[1] = u > v ? v : u;
    return (uint64_t)(u * u + v * v) == p && u != v ? 0 : -2;
}

typedef struct factor {
    uint64_t p;
    uint32_t e, next; /* next: the following factor of the same k, or NONE */
} factor;

enum { NONE = UINT32_MAX };

typedef struct sq3 {
    uint64_t m;
    size_t amax;      /* the largest a with 3 a^2 <= m                        */
    uint64_t *rest;   /* rest[a]: m - a^2 without its sieved prime factors     */
    uint32_t *head;   /* head[a]: its first factor in f, or NONE               */
    factor *f;
    size_t nf, capf;
    int64_t *z;       /* Gaussian integers of the current k, then its pairs    */
    size_t capz;
} sq3;

static int add_factor(sq3 *s, size_t a, uint64_t p, uint32_t e)
{
    if (s->nf == s->capf) {
        size_t cap = s->capf ? 2 * s->capf : 1024;
        factor *f = cap < NONE ? realloc(s->f, cap * sizeof *f) : NULL;
        if (!f) return -1;
        s->f = f, s->capf = cap;
    }
    s->f[s->nf] = (factor){p, e, s->head[a]};
    s->head[a] = (uint32_t)s->nf++;
    return 0;
}

/* Divides p out of rest[a] for every a = r mod p; -1 out of memory. */
static int sieve_class(sq3 *s, uint64_t p, uint64_t r)
{
    for (uint64_t a = r; a <= s->amax; a += p) {
        uint32_t e = 0;
        while (s->rest[a] % p == 0) s->rest[a] /= p, e++;
        if (e && add_factor(s, (size_t)a, p, e) != 0) return -1;
    }
    return 0;
}

/* Factors every m - a^2 by the primes up to sqrt(m) (sieve of Eratosthenes). */
static int sieve(sq3 *s)
{
    uint64_t top = lht_isqrt(s->m) < 2 ? 2 : lht_isqrt(s->m); /* 2 too: what is left is odd */
    unsigned char *composite = calloc((size_t)top + 1, 1);
    if (!composite) return -1;
    int st = 0;
    for (uint64_t p = 2; p <= top && st == 0; p++) {
        if (composite[p]) continue;
        for (uint64_t j = p * p; j <= top; j += p) composite[j] = 1;
        uint64_t mp = s->m % p;
        if (p == 2 || mp == 0) st = sieve_class(s, p, mp == 0 ? 0 : mp & 1);
        else if (powmod(mp, (p - 1) / 2, p) == 1) {
            uint64_t r = sqrt_mod(mp, p);
            st = sieve_class(s, p, r);
            if (st == 0) st = sieve_class(s, p, p - r);
        }
    }
    free(composite);
    return st;
}

static int reserve_z(sq3 *s, size_t count)
{
    if (count <= s->capz) return 0;
    int64_t *z = realloc(s->z, 2 * count * sizeof *z);
    if (!z) return -1;
    s->z = z, s->capz = count;
    return 0;
}

/* z[0..*n) times pi^j conj(pi)^(g-j) for j = 0..g, in place (the buffer grows). */
static int spread(sq3 *s, size_t *n, const int64_t pi[2], uint32_t g)
{
    if (reserve_z(s, *n * (g + 1)) != 0) return -1;
    for (uint32_t j = g + 1; j-- > 0;) /* j = 0 last: it overwrites the sources */
        for (size_t i = 0; i < *n; i++) {
            int64_t z[2] = {s->z[2 * i], s->z[2 * i + 1]};
            for (uint32_t t = 0; t < g; t++) lht_gauss_mul(z, pi[0], t < j ? pi[1] : -pi[1]);
            s->z[2 * (j * *n + i)] = z[0], s->z[2 * (j * *n + i) + 1] = z[1];
        }
    *n *= g + 1;
    return 0;
}

static int by_first(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The pairs a <= b <= c with b^2 + c^2 = m - a^2, sorted, into s->z; *n their count.
 * 1 when there are none, -1 out of memory, -2 (unreachable) a prime not split. */
static int pairs(sq3 *s, size_t a, size_t *n)
{
    int64_t base[2] = {1, 0}, pi[2];
    for (uint32_t i = s->head[a]; i != NONE; i = s->f[i].next) {
        const factor *f = &s->f[i];
        if (f->p % 4 == 1) continue; /* spread below */
        if (f->p % 4 == 3 && f->e % 2) return 1;
        for (uint32_t t = 0; t < (f->p == 2 ? f->e : f->e / 2); t++)
            lht_gauss_mul(base, f->p == 2 ? 1 : (int64_t)f->p, f->p == 2 ? 1 : 0); /* 1 + i, or q */
    }
    if (s->rest[a] % 4 == 3) return 1;
    if (reserve_z(s, 4) != 0) return -1;
    *n = 1;
    s->z[0] = base[0], s->z[1] = base[1];
    for (uint32_t i = s->head[a]; i != NONE; i = s->f[i].next)
        if (s->f[i].p % 4 == 1) {
            if (lht_gauss_split(s->f[i].p, pi) != 0) return -2;
            if (spread(s, n, pi, s->f[i].e) != 0) return -1;
        }
    if (s->rest[a] > 1) {
        if (lht_gauss_split(s->rest[a], pi) != 0) return -2;
        if (spread(s, n, pi, 1) != 0) return -1;
    }
    size_t kept = 0;
    for (size_t i = 0; i < *n; i++) { /* at most one of z, iz, -z, -iz: kept <= i + 1 */
        int64_t x = s->z[2 * i], y = s->z[2 * i + 1], t;
        for (int u = 0; u < 4; u++, t = x, x = -y, y = t)
            if ((int64_t)a <= x && x <= y) {
                s->z[2 * kept] = x, s->z[2 * kept + 1] = y, kept++;
                break;
            }
    }
    qsort(s->z, kept, 2 * sizeof *s->z, by_first);
    *n = kept;
    return 0;
}

static int walk(sq3 *s, lht_triple_fn each, void *ctx)
{
    for (size_t a = 0; a <= s->amax; a++) {
        size_t n;
        int st = pairs(s, a, &n);
        if (st < 0) return st;
        for (size_t i = 0; st == 0 && i < n; i++) {
            const int64_t t[3] = {(int64_t)a, s->z[2 * i], s->z[2 * i + 1]};
            int r = each(ctx, t);
            if (r != 0) return r;
        }
    }
    return 0;
}

int lht_squares3_each(uint64_t m, lht_triple_fn each, void *ctx)
{
    sq3 s = {.m = m, .amax = (size_t)lht_isqrt(m / 3)};
    int st = -1;
    s.rest = malloc((s.amax + 1) * sizeof *s.rest);
    s.head = malloc((s.amax + 1) * sizeof *s.head);
    if (s.rest && s.head) {
        for (size_t a = 0; a <= s.amax; a++) s.rest[a] = m - (uint64_t)a * a, s.head[a] = NONE;
        st = sieve(&s);
        if (st == 0) st = walk(&s, each, ctx);
    }
    free(s.rest), free(s.head), free(s.f), free(s.z);
    return st;
}
