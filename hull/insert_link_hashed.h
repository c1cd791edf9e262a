/*
 * insert_link_hashed.h — part of the insertion loop template (insert_impl.h):
 * linking the new cells through a hash table of ridges keyed on their vertex
 * indices, for the modes whose conflict region need not be a ball (placing, the
 * furthest-site hull) and for the test knob hashed_ridges.
 *
 * Each new cell's old vertices are sorted once; a ridge is that list minus one
 * entry. When its vertices fit in 64 bits (t->vbits each: for n below 2^21 in 4D,
 * 2^16 in 5D) the key is the ridge itself, packed; otherwise it is the sum of a mix
 * of its vertices (one subtraction from the cell's sum) and equal keys are
 * confirmed by comparing the sorted lists, so a collision costs a probe, never a
 * wrong link. The table is open addressing with linear probing (Knuth, TAOCP 3,
 * 6.4), cleared between insertions by a round number, not by a sweep.
 */

static inline uint64_t mix(lh_index v) /* one multiply and a fold: nonlinear in v */
{
    uint64_t z = (uint64_t)(lh__uindex)v * UINT64_C(0x9e3779b97f4a7c15);
    return z ^ (z >> 29);
}

/* The old vertices of new cell b (all but position k), increasing, with their
 * positions. */
static inline void sort_old_vertices(lh__tds *t, size_t b, lh_index N, int k)
{
    const int nv = LH_T_NV(t);
    const lh_index *v = t->vert + (size_t)N * nv;
    lh_index *s = t->sorted + b * (nv - 1);
    int8_t *p = t->spos + b * (nv - 1);
    int n = 0;
    for (int j = 0; j < nv; j++) {
        if (j == k) continue;
        int i = n++;
        for (; i > 0 && s[i - 1] > v[j]; i--) {
            s[i] = s[i - 1];
            p[i] = p[i - 1];
        }
        s[i] = v[j];
        p[i] = (int8_t)j;
    }
}

/* Whether the sorted lists of new cells a and b, minus entries da and db, agree. */
static int same_ridge(const lh__tds *t, size_t a, int da, size_t b, int db)
{
    const int nv = LH_T_NV(t);
    const int m = nv - 1;
    const lh_index *x = t->sorted + a * m, *y = t->sorted + b * m;
    for (int i = 0, j = 0; i < m; i++, j++) {
        if (i == da) i++;
        if (j == db) j++;
        if (i < m && x[i] != y[j]) return 0;
    }
    return 1;
}

/* The key of the ridge of sorted list s (m entries) without entry drop: packed
 * (vbits per vertex + 1) when exact, else the sum of mixes `sum` minus drop's. */
static inline uint64_t ridge_key(const lh_index *s, int m, int drop, uint64_t sum, int vbits, int exact)
{
    if (!exact) return sum - mix(s[drop]);
    uint64_t k = 0;
    for (int x = 0; x < m; x++)
        if (x != drop) k = k << vbits | (uint64_t)(lh__uindex)(s[x] + 1);
    return k;
}

/* Pairs the new cells t->fresh[] across their ridges (see the top of this file). */
static void link_new_cells(lh__tds *t)
{
    const int nv = LH_T_NV(t);
    const int m = nv - 1, vbits = t->vbits, exact = (m - 1) * vbits <= 64;
    const uint32_t round = t->round;
    const size_t mask = lh__ridge_slots((size_t)m * t->nbound) - 1;
    for (size_t b = 0; b < t->nbound; b++) sort_old_vertices(t, b, t->fresh[b], (int)t->bound[2 * b + 1]);
    for (size_t b = 0; b < t->nbound; b++) {
        const lh_index N = t->fresh[b], *s = t->sorted + b * m;
        uint64_t sum = 0;
        if (!exact)
            for (int i = 0; i < m; i++) sum += mix(s[i]);
        for (int i = 0; i < m; i++) {
            uint64_t key = ridge_key(s, m, i, sum, vbits, exact);
            for (size_t h = ridge_slot(key) & mask;; h = (h + 1) & mask) {
                lh__ridge *r = t->ridge + h;
                if (r->round != round) { /* free: the first of the pair */
                    r->key = key;
                    r->round = round;
                    r->bd = (uint32_t)b << 4 | (uint32_t)i;
                    break;
                }
                size_t rb = r->bd >> 4;
                int rd = (int)(r->bd & 15);
                if (r->key == key && (exact || same_ridge(t, b, i, rb, rd))) {
                    lh_index M = t->fresh[rb];
                    t->nbr[(size_t)N * nv + t->spos[b * m + i]] = M;
                    t->nbr[(size_t)M * nv + t->spos[rb * m + rd]] = N;
                    r->key = LH__RIDGE_PAIRED;
                    break;
                }
            }
        }
    }
}
