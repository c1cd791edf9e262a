/*
 * hilbert.h — Hilbert keys in 2D and 3D by a state machine: the same keys as
 * Skilling's transform (order.c, lh__hilbert_transpose), from tables.
 *
 * Skilling's transform ("Programming the Hilbert curve", AIP Conf. Proc. 707,
 * 2004) goes down the levels; at each it reads the cell's d bits there and changes
 * only the levels below, by inverting coordinate 0 or exchanging it with another:
 * below any level the coordinates are a signed permutation of the cell's. Its Gray
 * code then works within a level, but for a flip of each level by the parity of the
 * last coordinate's bits above. So a level's d key bits depend only on its d cell
 * bits and a state (the signed permutation and that parity), which also gives the
 * next level's state: the Hilbert curve as a state machine (Griffiths, "Table-driven
 * algorithms for generating space-filling curves", 1985). A step of the table
 * `many` takes LH__HILBERT_BITS / d levels at once (4 in 2D, 2 in 3D), from the
 * Morton code (the cell's bits interleaved as the key's are).
 */
#ifndef LH_HILBERT_H
#define LH_HILBERT_H

#include <stdint.h>

enum {
    LH__HILBERT_STATES = 96, /* 3! permutations x 2^3 signs x 2 parities, at most */
    LH__HILBERT_BITS = 8     /* key bits a step of `many` takes, at most */
};

typedef struct lh__hilbert {
    int nstates;          /* those reached from the first */
    /* entry [state << b | b cell bits] (b = d in `one`, a step's in `many`): the
       b key bits | the next state << 8 */
    uint16_t one[LH__HILBERT_STATES << 3];
    uint16_t many[LH__HILBERT_STATES << 6];
} lh__hilbert;

/* The tables for dimension d (2 or 3); 0 for another d. */
int lh__hilbert_init(lh__hilbert *h, int d);

/* The key of the cell whose Morton code is m (`bits` levels; coordinate j's bit b
 * at bit b d + d - 1 - j, as the key's): lh__hilbert_transpose's key, interleaved
 * the same way. d is the tables' (lh__hilbert_init), passed so that a caller's
 * constant folds; the first levels beyond a multiple of a step's go one at a time. */
static inline uint64_t lh__hilbert_key(const lh__hilbert *h, uint64_t m, int bits, const int d)
{
    const int levels = LH__HILBERT_BITS / d, step = levels * d;
    const uint64_t one_mask = (UINT64_C(1) << d) - 1, many_mask = (UINT64_C(1) << step) - 1;
    uint64_t k = 0;
    unsigned s = 0;
    int b = bits;
    for (; b % levels; b--) {
        const unsigned e = h->one[s << d | (unsigned)(m >> ((b - 1) * d) & one_mask)];
        k = k << d | (e & 255), s = e >> 8;
    }
    for (; b > 0; b -= levels) {
        const unsigned e = h->many[s << step | (unsigned)(m >> ((b - levels) * d) & many_mask)];
        k = k << step | (e & 255), s = e >> 8;
    }
    return k;
}

#endif
