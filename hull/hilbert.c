/* hilbert.c — the tables of hilbert.h, built by following Skilling's transform one
 * level at a time from the first state (no coordinate moved, no parity). */
#include "hilbert.h"

#include <string.h>

/* Below the current level, coordinate j of the transformed cell is coordinate
 * perm[j] of the cell, inverted when bit j of `flip` is set; `parity` flips the
 * current level's key bits (the Gray code's flip). */
typedef struct hstate {
    int perm[3], flip, parity;
} hstate;

static int raw_code(const hstate *s) { return s->perm[0] | s->perm[1] << 2 | s->perm[2] << 4 | s->flip << 6 | s->parity << 9; }

/* One level: its cell bits `in` (coordinate c's at bit d - 1 - c) to its key bits
 * *out; returns the state below. As lh__hilbert_transpose at one level q: each
 * coordinate i in turn inverts coordinate 0 below q when its bit is set, else
 * exchanges itself with coordinate 0 below q; the Gray code x[i] ^= x[i-1]; then
 * the flip by the parity of x[d-1]'s bits above. */
static hstate level(hstate s, int d, unsigned in, unsigned *out)
{
    int y[3], z = 0;
    unsigned o = 0;
    for (int j = 0; j < d; j++) y[j] = (int)(in >> (d - 1 - s.perm[j]) & 1) ^ (s.flip >> j & 1);
    for (int j = 0; j < d; j++) {
        z ^= y[j];
        o |= (unsigned)(z ^ s.parity) << (d - 1 - j);
    }
    *out = o;
    s.parity ^= z; /* x[d-1] after the Gray code, before the flip */
    for (int i = 0; i < d; i++) {
        if (y[i]) {
            s.flip ^= 1;
        } else if (i) {
            const int p = s.perm[0], f0 = s.flip & 1, fi = s.flip >> i & 1;
            s.perm[0] = s.perm[i], s.perm[i] = p;
            s.flip = (s.flip & ~(1 | 1 << i)) | fi | f0 << i;
        }
    }
    return s;
}

int lh__hilbert_init(lh__hilbert *h, int d)
{
    if (d != 2 && d != 3) return 0;
    const int levels = LH__HILBERT_BITS / d, step = levels * d;
    hstate st[LH__HILBERT_STATES];
    int16_t index[1 << 10]; /* raw_code -> state number */
    memset(index, -1, sizeof index);
    st[0] = (hstate){{0, 1, 2}, 0, 0};
    index[raw_code(st)] = 0;
    h->nstates = 1;
    for (int s = 0; s < h->nstates; s++) /* every state one level reaches */
        for (unsigned in = 0; in < 1u << d; in++) {
            unsigned out;
            hstate n = level(st[s], d, in, &out);
            int16_t *x = index + raw_code(&n);
            if (*x < 0) *x = (int16_t)h->nstates, st[h->nstates++] = n;
            h->one[s << d | (int)in] = (uint16_t)(out | (unsigned)*x << 8);
        }
    for (int s = 0; s < h->nstates; s++) /* `levels` steps of `one` */
        for (unsigned in = 0; in < 1u << step; in++) {
            unsigned n = (unsigned)s, key = 0;
            for (int l = levels - 1; l >= 0; l--) {
                const unsigned e = h->one[n << d | (in >> (l * d) & ((1u << d) - 1))];
                key = key << d | (e & 255), n = e >> 8;
            }
            h->many[s << step | (int)in] = (uint16_t)(key | n << 8);
        }
    return 1;
}
