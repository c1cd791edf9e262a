/*
 * tds.h — the cell store of lifthull's incremental engine. Its one mutating
 * operation, the insertion of a point into a cavity, is hull/insert_impl.h.
 *
 * A cell is nv vertex indices and nv neighbour indices in two flat arrays:
 * nbr[c*nv + k] is the cell across the facet opposite vert[c*nv + k] (the facet
 * made of the other nv-1 vertices). The store never reads a coordinate; what a
 * vertex index means, and the vertex LH__INF, are the caller's. Cells form a closed
 * pseudo-manifold: every facet has exactly two cells. Freed cells go on a free list
 * (vert[c*nv] == LH__DEAD, the next free cell in nbr[c*nv]).
 */
#ifndef LH_TDS_H
#define LH_TDS_H

#include "lifthull.h"

#define LH__INF (-1)  /* the vertex at infinity (the caller's convention) */
#define LH__DEAD (-2) /* vert[c*nv] of a free cell */
#define LH__TDS_MAX_NV (LH_ORIENT_MAX_DIM + 1)

/* The unsigned type as wide as lh_index (hashes and packed keys of indices), and the
 * bits that hold any vertex index + 1: 32 (as ever) in the 32-bit build, 63 in the
 * 64-bit one. */
#if LH_INDEX_BITS == 64
typedef uint64_t lh__uindex;
#define LH__TDS_VBITS_MAX 63
#else
typedef uint32_t lh__uindex;
#define LH__TDS_VBITS_MAX 32
#endif

/* An entry of the table that pairs new cells across their ridges (insert_link_*.h):
 * 16 bytes, so that the table of an insertion stays in the first-level cache. */
typedef struct lh__ridge {
    uint64_t key;   /* LH__RIDGE_PAIRED once both cells are linked */
    uint32_t round; /* the insertion that wrote the entry (older: a free slot) */
    uint32_t bd;    /* b << 4 | drop: the new cell fresh[b], and the index in its
                       sorted list of the vertex not in the ridge */
} lh__ridge;
#define LH__RIDGE_PAIRED UINT64_MAX /* no exact key is all ones (a vertex + 1 is
                                       below 2^vbits - 1 ... see lh__tds_vertex_bound);
                                       hashed keys that are get compared */
/* The slots an insertion uses for `entries` ridges: a power of two, a prefix of the
 * table, so that a small cavity's entries stay in the first-level cache whatever
 * the largest one was; at most 1/8 full up to 2^16 slots (probes then rarely
 * collide, insert_link_hashed.h), at most 2/3 beyond. */
static inline size_t lh__ridge_slots(size_t entries)
{
    size_t want = 8 * entries < (1u << 16) ? 8 * entries : (1u << 16);
    if (want < entries + entries / 2) want = entries + entries / 2;
    uint64_t v = (uint64_t)(want < 16 ? 16 : want) - 1; /* the next power of two */
    v |= v >> 1, v |= v >> 2, v |= v >> 4, v |= v >> 8, v |= v >> 16, v |= v >> 32;
    return (size_t)v + 1;
}
#define LH__MAX_NEW_CELLS (INT32_C(1) << 27) /* b fits in bd */
/* The numbers a 3D cavity's boundary vertices take (1..LH__EDGE_IDS; 0: none) and
 * the slots of its edge table, one per ordered pair of numbers. */
#define LH__EDGE_BITS 6
#define LH__EDGE_IDS ((1 << LH__EDGE_BITS) - 1)
#define LH__EDGE_SLOTS (1u << (2 * LH__EDGE_BITS))

/* Entries per new cell in lh__tds.sorted: its m old vertices, the 5 that
 * cone_local keeps in 3D, or the m 64-bit ridge keys of
 * number_boundary (insert_link_numbered.h). */
#define LH__SORTED_ROOM(m) ((m) > 2 ? 2 * (m) : 5)

typedef struct lh__tds {
    lh_allocator alloc;
    int nv;           /* vertices (and neighbours) per cell */
    int vbits;        /* bits that hold every vertex index + 1 (LH__INF + 1 = 0): ridge
                         keys pack the vertices exactly when they fit (insert_link_hashed.h);
                         LH__TDS_VBITS_MAX unless the owner knows better
                         (lh__tds_vertex_bound) */
    lh_index *vert;   /* nv per cell */
    lh_index *nbr;    /* nv per cell */
    uint32_t *stamp;  /* per cell: visit marks of the current insertion */
    lh_index cap;     /* cells allocated */
    lh_index top;     /* cells ever used: indices < top are live or free */
    lh_index free_head;
    lh_index live;    /* cells in use */
    uint32_t round;   /* insertion counter behind the stamps */
    /* Scratch of one insertion, kept between insertions (no allocation once warm). */
    lh_index *cells, *bound, *fresh;
    size_t cells_cap, bound_cap, fresh_cap;
    lh__ridge *ridge;        /* open-addressing table of the new cells' ridges */
    size_t ridge_cap;        /* a power of two */
    lh_index *sorted;        /* per new cell: its old vertices, increasing (or
                                what cone_local or number_boundary keeps of it:
                                room for LH__SORTED_ROOM(nv - 1) entries) */
    int8_t *spos;            /* and their positions in the cell */
    size_t sorted_cap;       /* new cells the two have room for */
    size_t vlimit;           /* every vertex index + 1 is below it (0: unknown) */
    uint8_t *vloc;           /* 3D and up, once vlimit is known: per vertex index
                                + 1, its number on the cavity's boundary
                                (insert_link_twins.h: cone_local;
                                insert_link_numbered.h: number_ridges); all
                                zero between insertions */
    uint32_t *edge;          /* 3D: the table of the boundary's directed edges,
                                LH__EDGE_SLOTS entries, all zero between them */
    size_t ncells, nbound; /* conflict cells; boundary facets (pairs cell, index) */
    int frozen;            /* nothing may be allocated (a worker of a parallel phase,
                              hull/parallel.c): growing the scratch or the cells
                              fails, as when memory runs out */
} lh__tds;

lh_status lh__tds_init(lh__tds *t, const lh_allocator *alloc, int nv, lh_index cap_hint);
void lh__tds_release(lh__tds *t);
/* Frees the scratch of the insertions (cells .. edge below), leaving them empty;
 * also a parallel worker's own scratch store (hull/parallel.c). */
void lh__tds_free_scratch(lh__tds *t);
lh_status lh__tds_reserve(lh__tds *t, size_t extra);
/* Declares every vertex index below `bound` (sharper ridge keys). */
static inline void lh__tds_vertex_bound(lh__tds *t, size_t bound)
{
    int b = 1;
    while (b < LH__TDS_VBITS_MAX && ((size_t)1 << b) <= bound) b++;
    t->vbits = b;
    t->vlimit = bound;
}
/* A new cell with unset contents, or -1 when memory runs out. */
static inline lh_index lh__tds_new_cell(lh__tds *t)
{
    lh_index c;
    if (t->free_head >= 0) {
        c = t->free_head;
        t->free_head = t->nbr[(size_t)c * t->nv];
    } else {
        if (t->top == t->cap && lh__tds_reserve(t, 1) != LH_OK) return -1;
        c = t->top++;
    }
    t->live++;
    return c;
}
/* Ends insertions: frees the insertion scratch and hands over an array of t->cap
 * indices for the caller to reuse and free with lh__free(&t->alloc, ...): the stamp
 * array itself (one 32-bit word per cell) with 32-bit indices, a new array in its
 * place with 64-bit ones (NULL when memory runs out). No insertion may follow. */
lh_index *lh__tds_finish(lh__tds *t);
/* cell_sort.c, after lh__tds_finish: the finite cells (vertices below n) in
 * canonical form (canon.c) and lexicographic order at rows 0..*count-1, the other
 * rows after them, in place; orig (t->top entries) receives each row's position
 * before, and neighbour entries still name those positions. `threads` share the
 * work (hull/parallel.c). */
lh_status lh__tds_sort_cells(lh__tds *t, size_t n, lh_index *orig, size_t *count, int threads);
/* The same without the canonical form: the finite cells at rows 0..*count-1 as the
 * store has them (each positively oriented, its vertices in the store's order), in
 * the store's order but for swaps with the other rows, which follow. For a caller
 * that reads only what depends on neither order. */
lh_status lh__tds_compact_cells(lh__tds *t, lh_index *orig, size_t *count);
static inline void lh__tds_kill(lh__tds *t, lh_index c)
{
    size_t base = (size_t)c * t->nv;
    t->vert[base] = LH__DEAD;
    t->nbr[base] = t->free_head;
    t->free_head = c;
    t->live--;
}
static inline int lh__tds_dead(const lh__tds *t, lh_index c) { return t->vert[(size_t)c * t->nv] == LH__DEAD; }
/* Index k with nbr[c][k] == other; -1 if none. */
int lh__tds_mirror(const lh__tds *t, lh_index c, lh_index other);
/* Sets the neighbours of the cells list[0..count-1] by matching shared facets
 * (quadratic: for the first cells of a triangulation only). */
void lh__tds_link_all(lh__tds *t, const lh_index *list, int count);

/* For the insertion (insert_impl.h): growing a scratch array; starting an
 * insertion (new visit marks); room for the new cells of t->nbound boundary facets
 * and their linking, so that nothing fails afterwards. */
int lh__tds_push_slow(lh__tds *t, lh_index **arr, size_t *cap, size_t *len, lh_index x);
void lh__tds_next_round(lh__tds *t);
lh_status lh__tds_room(lh__tds *t);
/* The last round before the visit marks start over (lh__tds_reset_rounds: every
 * stamp and ridge entry cleared, round 0); 4 stamps a round must fit in 32 bits. */
#define LH__TDS_MAX_ROUND (UINT32_MAX / 4 - 1)
void lh__tds_reset_rounds(lh__tds *t);

/* For parallel phases (hull/parallel.c): room for `extra` cells above top (not
 * counting free ones); scratch for insertions of up to `facets` boundary facets,
 * allocated now (a frozen store cannot grow it). */
lh_status lh__tds_reserve_top(lh__tds *t, size_t extra);
lh_status lh__tds_scratch(lh__tds *t, size_t facets);

#endif
