/*
 * qhull_sides.c — pairing facet sides by their vertex sets: facet f's side k is its
 * vertex list without position k. Hull facets find their neighbours this way, and
 * the Delaunay simplices' sides on the convex hull find the upper-hull facet across
 * them (the same (d-1)-simplex, since both triangulate the hull's boundary with the
 * same perturbation).
 */
#include "qhull_sides.h"

#include <stdlib.h>
#include <string.h>

enum { MAXV = LH_DELAUNAY_MAX_DIM + 2 };

typedef struct side {
    lh_index facet; /* -1: empty slot */
    lh_index pos;
    uint64_t hash; /* of its key: a probe rebuilds a stored key only on equal hashes */
} side;

typedef struct table {
    side *slot;
    size_t mask;
    int nv;
    const lh_index *vert;
} table;

/* The sorted vertices of facet f without position k (insertion sort: at most 8),
 * and their hash. */
static uint64_t side_key(const lh_index *vert, int nv, lh_index f, int k, lh_index *key)
{
    int m = 0;
    for (int i = 0; i < nv; i++) {
        if (i == k) continue;
        lh_index x = vert[(size_t)f * nv + i];
        int j = m++;
        for (; j > 0 && key[j - 1] > x; j--) key[j] = key[j - 1];
        key[j] = x;
    }
    uint64_t h = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < m; i++) h = (h ^ (uint64_t)key[i]) * 0xff51afd7ed558ccdu; /* key >= 0 */
    return h ^ (h >> 29);
}

/* The slot holding key (or the empty slot where it would go). */
static side *find(table *t, const lh_index *key, uint64_t h)
{
    lh_index other[MAXV];
    for (size_t i = h & t->mask;; i = (i + 1) & t->mask) {
        side *s = &t->slot[i];
        if (s->facet < 0) return s;
        if (s->hash != h) continue;
        side_key(t->vert, t->nv, s->facet, (int)s->pos, other);
        if (!memcmp(other, key, (size_t)(t->nv - 1) * sizeof *key)) return s;
    }
}

static int table_init(table *t, size_t entries, int nv, const lh_index *vert)
{
    size_t cap = 16;
    while (cap < 2 * entries) cap *= 2;
    t->slot = malloc(cap * sizeof *t->slot);
    if (!t->slot) return 0;
    memset(t->slot, 0xff, cap * sizeof *t->slot);
    t->mask = cap - 1;
    t->nv = nv;
    t->vert = vert;
    return 1;
}

int lh_cli_pair_within(int nv, size_t m, const lh_index *vert, lh_index *nbr)
{
    table t;
    if (!table_init(&t, m * (size_t)nv, nv, vert)) return 0;
    lh_index key[MAXV];
    for (size_t f = 0; f < m; f++)
        for (int k = 0; k < nv; k++) {
            nbr[f * nv + k] = -1;
            uint64_t h = side_key(vert, nv, (lh_index)f, k, key);
            side *s = find(&t, key, h);
            if (s->facet < 0) {
                s->facet = (lh_index)f;
                s->pos = k;
                s->hash = h;
            } else {
                nbr[f * nv + k] = s->facet;
                nbr[(size_t)s->facet * nv + s->pos] = (lh_index)f;
            }
        }
    free(t.slot);
    return 1;
}

int lh_cli_pair_across(int nv, size_t m, const lh_index *vert, lh_index *nbr, size_t mo,
                       const lh_index *overt, const lh_index *onbr)
{
    size_t open = 0;
    for (size_t i = 0; i < mo * (size_t)nv; i++) open += onbr[i] < 0;
    table t;
    if (!table_init(&t, open, nv, overt)) return 0;
    lh_index key[MAXV];
    for (size_t g = 0; g < mo; g++)
        for (int k = 0; k < nv; k++) {
            if (onbr[g * nv + k] >= 0) continue;
            uint64_t h = side_key(overt, nv, (lh_index)g, k, key);
            side *s = find(&t, key, h);
            s->facet = (lh_index)g;
            s->pos = k;
            s->hash = h;
        }
    for (size_t f = 0; f < m; f++)
        for (int k = 0; k < nv; k++) {
            if (nbr[f * nv + k] >= 0) continue;
            side *s = find(&t, key, side_key(vert, nv, (lh_index)f, k, key));
            nbr[f * nv + k] = s->facet >= 0 ? -(s->facet + 1) : LH_CLI_NO_SIDE;
        }
    free(t.slot);
    return 1;
}
