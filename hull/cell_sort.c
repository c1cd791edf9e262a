/*
 * cell_sort.c — the store's finite cells put in the canonical form of lifthull's
 * outputs (canon.c) in place, so that an output's simplex and neighbour arrays are
 * the store's own and the cells are never copied: each finite cell's vertex and
 * neighbour rows are permuted together into canonical order, then the rows are
 * sorted lexicographically, the finite cells first.
 *
 * The sort is an in-place most-significant-digit radix sort on a row's first vertex
 * (American flag sort: McIlroy, Bostic & McIlroy, "Engineering radix sort",
 * Computing Systems 6(1), 1993), with digits of at most DIGIT_BITS bits: a pass
 * writes to as many places at once as it has buckets, so the digits stay narrow
 * enough for those write streams to stay in the cache (docs/bench-engine.md). A
 * bucket small enough for the cache whose remaining key bits are few is finished
 * out of place instead (gather_sort: a counting sort of positions, then one
 * gather); rows with the same first vertex are ordered by the rest of the tuple
 * (order_group; heapsort for the large groups of a degenerate input). With several
 * threads, the canonical forms are split among them, so is the first pass
 * (first_pass), and after it its buckets; the finite rows come out the same.
 * lh__tds_compact_cells only moves the finite cells ahead of the others, as they
 * are, for a caller that needs neither order (lh_tri_insert_unordered).
 */
#include "engine.h"
#include "lh_alloc.h"

#include <string.h>

enum {
    DIGIT_BITS = 8,
    SMALL = 16,           /* rows sorted by insertion */
    GROUP_MAX = 4096,     /* rows of one first vertex sorted through positions (more: heapsort) */
    MAX_LEVELS = 64 / DIGIT_BITS + 1,
    GATHER_BITS = 16,     /* gather_sort: the key bits left, at most */
    GATHER_MAX = 1 << 16, /* and the rows, at most (more: sorted in place, as the
                             gathers of a larger bucket miss the cache) */
    GROUP_SMALL = 32      /* rows of one first vertex ordered by insertion */
};

/* The rows being sorted. Every function below takes the row length nv as an
 * argument, a constant where lh__tds_sort_cells calls them for 2D to 5D
 * (LH__WITH_CONSTANT_M), so that row moves unroll. */
typedef struct rows {
    lh_index *vert, *nbr, *orig; /* rows of nv; orig: one per row */
    size_t n;                    /* the key of a row that is not a finite cell */
    int levels;                  /* digit passes: level i reads key bits lo[i]..hi[i]-1 */
    int lo[MAX_LEVELS], hi[MAX_LEVELS];
    size_t *scratch;             /* per level: bucket heads and ends */
    lh_index *pos;               /* 3 GROUP_MAX: positions of a group being sorted */
    uint64_t *gkey;              /* GROUP_MAX: their packed keys (group_key) */
    int kbits, kwidth;           /* vertices packed in a group key, kbits bits each */
    uint16_t *dig;               /* per row: its digit in the current pass */
    uint32_t *gcount;            /* gather_sort: 2^GATHER_BITS + 1 counts */
    size_t gmax;                 /* and room for gmax rows (at most GATHER_MAX): */
    lh_index *gpos, *gvert, *gnbr, *gorig; /* their positions, copies */
} rows;

/* A row's sort key: its first vertex for a finite cell, n for the others (the
 * vertex at infinity or a free cell's mark comes first in those). */
static inline size_t key_of(const lh_index *v, size_t n) { return v[0] < 0 ? n : (size_t)v[0]; }

/* Whether row x comes before row y: keys, then (finite cells) the other vertices. */
static inline int row_less(const lh_index *x, const lh_index *y, int nv, size_t n)
{
    const size_t kx = key_of(x, n), ky = key_of(y, n);
    if (kx != ky) return kx < ky;
    if (kx == n) return 0;
    for (int k = 1; k < nv; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

static inline void copy_row(lh_index *dst, const lh_index *src, int nv)
{
    for (int k = 0; k < nv; k++) dst[k] = src[k];
}

static inline void swap_entries(lh_index *a, lh_index *b, int nv)
{
    for (int k = 0; k < nv; k++) {
        const lh_index x = a[k];
        a[k] = b[k], b[k] = x;
    }
}

static inline void swap_rows(const rows *r, size_t a, size_t b, int nv)
{
    swap_entries(r->vert + a * nv, r->vert + b * nv, nv);
    swap_entries(r->nbr + a * nv, r->nbr + b * nv, nv);
    swap_entries(r->orig + a, r->orig + b, 1);
}

static void insertion_sort(const rows *r, size_t lo, size_t hi, int nv)
{
    for (size_t i = lo + 1; i < hi; i++) {
        lh_index v[LH__TDS_MAX_NV], nb[LH__TDS_MAX_NV], o = r->orig[i];
        copy_row(v, r->vert + i * nv, nv);
        copy_row(nb, r->nbr + i * nv, nv);
        size_t j = i;
        for (; j > lo && row_less(v, r->vert + (j - 1) * nv, nv, r->n); j--) {
            copy_row(r->vert + j * nv, r->vert + (j - 1) * nv, nv);
            copy_row(r->nbr + j * nv, r->nbr + (j - 1) * nv, nv);
            r->orig[j] = r->orig[j - 1];
        }
        copy_row(r->vert + j * nv, v, nv);
        copy_row(r->nbr + j * nv, nb, nv);
        r->orig[j] = o;
    }
}

/* Heapsort of rows lo..hi-1 (Williams 1964): in place and O(k log k) whatever the
 * input, for the many cells around one vertex of cospherical sites. */
static void sift_down(const rows *r, size_t lo, size_t i, size_t k, int nv)
{
    for (size_t c; (c = 2 * i + 1) < k; i = c) {
        if (c + 1 < k && row_less(r->vert + (lo + c) * nv, r->vert + (lo + c + 1) * nv, nv, r->n)) c++;
        if (!row_less(r->vert + (lo + i) * nv, r->vert + (lo + c) * nv, nv, r->n)) return;
        swap_rows(r, lo + i, lo + c, nv);
    }
}

static void heap_sort(const rows *r, size_t lo, size_t hi, int nv)
{
    const size_t k = hi - lo;
    for (size_t i = k / 2; i-- > 0;) sift_down(r, lo, i, k, nv);
    for (size_t end = k; end-- > 1;) {
        swap_rows(r, lo, lo + end, nv);
        sift_down(r, lo, 0, end, nv);
    }
}

static inline void move_row(const rows *r, size_t to, size_t from, int nv)
{
    copy_row(r->vert + to * nv, r->vert + from * nv, nv);
    copy_row(r->nbr + to * nv, r->nbr + from * nv, nv);
    r->orig[to] = r->orig[from];
}

/* A finite row's vertices 1..kwidth packed into one word, so that words compare
 * as those vertices do lexicographically. */
static inline uint64_t group_key(const rows *r, const lh_index *v)
{
    uint64_t key = (uint64_t)v[1];
    for (int k = 2; k <= r->kwidth; k++) key = key << r->kbits | (uint64_t)v[k]; /* kbits <= 32 here */
    return key;
}

/* Whether row x comes before row y of the same group whose keys are equal: the
 * vertices after the packed ones. */
static inline int tail_less(const rows *r, const lh_index *x, const lh_index *y, int nv)
{
    for (int k = r->kwidth + 1; k < nv; k++)
        if (x[k] != y[k]) return x[k] < y[k];
    return 0;
}

/* Whether the row at position x (packed key kx) comes before the row at y (key ky),
 * both of one group. */
static inline int before(const rows *r, uint64_t kx, size_t x, uint64_t ky, size_t y, int nv)
{
    return kx < ky || (kx == ky && tail_less(r, r->vert + x * nv, r->vert + y * nv, nv));
}

/* The positions at[0..m-1] of rows with one first vertex (m at most GROUP_MAX),
 * reordered as their rows are to be: by their other vertices, on keys that pack
 * the next ones (group_key: whole rows in 2D and 3D, the next 3 vertices in 4D and
 * 5D below 2^21 sites), the rest compared only on equal keys. Up to GROUP_SMALL
 * by insertion, else a bottom-up merge sort of local indices (r->pos) with a
 * branch-free merge step: every vertex has such a group, of 30 (4D) to 160 (5D)
 * rows on average, where heapsort's data-dependent branches mispredict. Stable
 * either way. */
static void order_group(const rows *r, lh_index *at, size_t m, int nv)
{
    uint64_t *key = r->gkey;
    for (size_t i = 0; i < m; i++) key[i] = group_key(r, r->vert + (size_t)at[i] * nv);
    if (m <= GROUP_SMALL) {
        for (size_t i = 1; i < m; i++) {
            const uint64_t ki = key[i];
            const lh_index ai = at[i];
            size_t j = i;
            for (; j > 0 && before(r, ki, (size_t)ai, key[j - 1], (size_t)at[j - 1], nv); j--)
                key[j] = key[j - 1], at[j] = at[j - 1];
            key[j] = ki, at[j] = ai;
        }
        return;
    }
    lh_index *a = r->pos, *b = r->pos + GROUP_MAX;
    for (size_t i = 0; i < m; i++) a[i] = (lh_index)i;
    for (size_t w = 1; w < m; w *= 2) {
        for (size_t s = 0; s < m; s += 2 * w) {
            const size_t mid = s + w < m ? s + w : m, e = s + 2 * w < m ? s + 2 * w : m;
            size_t i = s, j = mid, o = s;
            while (i < mid && j < e) {
                const int right = before(r, key[a[j]], (size_t)at[a[j]], key[a[i]], (size_t)at[a[i]], nv);
                b[o++] = right ? a[j] : a[i];
                j += right, i += !right;
            }
            while (i < mid) b[o++] = a[i++];
            while (j < e) b[o++] = a[j++];
        }
        lh_index *x = a;
        a = b, b = x;
    }
    for (size_t i = 0; i < m; i++) b[i] = at[a[i]];
    memcpy(at, b, m * sizeof *at);
}

/* Rows lo..hi-1 (one first vertex, at most GROUP_MAX) sorted in place: their
 * order (order_group), then each row moved once, along the cycles of the
 * permutation. */
static void group_sort(const rows *r, size_t lo, size_t hi, int nv)
{
    const size_t k = hi - lo;
    lh_index *a = r->pos + 2 * GROUP_MAX;
    for (size_t i = 0; i < k; i++) a[i] = (lh_index)(lo + i);
    order_group(r, a, k, nv);
    /* a[i]: the row that goes to lo + i; a done entry becomes -1 */
    lh_index v[LH__TDS_MAX_NV], nb[LH__TDS_MAX_NV];
    for (size_t i = 0; i < k; i++) {
        if (a[i] < 0 || (size_t)a[i] == lo + i) continue;
        copy_row(v, r->vert + (lo + i) * nv, nv);
        copy_row(nb, r->nbr + (lo + i) * nv, nv);
        lh_index o = r->orig[lo + i];
        size_t cur = i;
        for (;;) {
            const size_t src = (size_t)a[cur] - lo;
            a[cur] = -1;
            if (src == i) break;
            move_row(r, lo + cur, lo + src, nv);
            cur = src;
        }
        copy_row(r->vert + (lo + cur) * nv, v, nv);
        copy_row(r->nbr + (lo + cur) * nv, nb, nv);
        r->orig[lo + cur] = o;
    }
}

/* Rows lo..hi-1, whose keys agree above bit r->hi[level], sorted out of place, if
 * they fit the scratch (else 0, nothing moved): their positions by a counting
 * sort on the key's remaining bits, each group of one first vertex ordered
 * (order_group), then the rows copied out and gathered back in order. Each row
 * moves twice, within a bucket that fits in the cache; the digit passes it
 * replaces at the last two levels moved every row twice in place, and the
 * groups' cycles once more. */
static int gather_sort(const rows *r, size_t lo, size_t hi, int level, int nv)
{
    const size_t k = hi - lo, nb = (size_t)1 << r->hi[level], mask = nb - 1;
    if (r->hi[level] > GATHER_BITS || k > r->gmax || k < nb / 8) return 0;
    uint32_t *start = r->gcount;
    memset(start, 0, (nb + 1) * sizeof *start);
    for (size_t i = lo; i < hi; i++) {
        r->dig[i] = (uint16_t)(key_of(r->vert + i * nv, r->n) & mask);
        start[r->dig[i] + 1]++;
    }
    for (size_t b = 0; b < nb; b++) {
        if (start[b + 1] > GROUP_MAX) return 0; /* a large group: heapsort (sort_rows) */
        start[b + 1] += start[b];
    }
    lh_index *pos = r->gpos;
    for (size_t i = lo; i < hi; i++) pos[start[r->dig[i]]++] = (lh_index)i;
    for (size_t b = 0, s = 0; b < nb; s = start[b++]) /* start[b]: now where group b ends */
        if (start[b] - s > 1 && key_of(r->vert + (size_t)pos[s] * nv, r->n) < r->n)
            order_group(r, pos + s, start[b] - s, nv);
    memcpy(r->gvert, r->vert + lo * nv, k * nv * sizeof *r->gvert);
    memcpy(r->gnbr, r->nbr + lo * nv, k * nv * sizeof *r->gnbr);
    memcpy(r->gorig, r->orig + lo, k * sizeof *r->gorig);
    for (size_t i = 0; i < k; i++) {
        const size_t from = (size_t)pos[i] - lo;
        copy_row(r->vert + (lo + i) * nv, r->gvert + from * nv, nv);
        copy_row(r->nbr + (lo + i) * nv, r->gnbr + from * nv, nv);
        r->orig[lo + i] = r->gorig[from];
    }
    return 1;
}

/* Moves the rows of a cycle that starts at row i, whose digit is not b, into their
 * buckets' next free places (head[k], below end[k]), the last into row i. The next
 * place comes from dig, not from the row in hand, so the rows' cache misses
 * overlap. Returns 0 when a row's bucket has no place left below its end (a
 * thread's part of the bucket is full: first_pass); that row then ends in row i,
 * misplaced, its digit in dig. */
static inline int follow_cycle(const rows *r, size_t *head, const size_t *end, size_t i, size_t b, int nv)
{
    lh_index v[LH__TDS_MAX_NV], nb[LH__TDS_MAX_NV], o = r->orig[i];
    copy_row(v, r->vert + i * nv, nv);
    copy_row(nb, r->nbr + i * nv, nv);
    size_t k = r->dig[i];
    do {
        if (head[k] == end[k]) break;
        const size_t j = head[k]++;
        const size_t next = r->dig[j];
        r->dig[j] = (uint16_t)k;
        swap_entries(r->vert + j * nv, v, nv);
        swap_entries(r->nbr + j * nv, nb, nv);
        swap_entries(r->orig + j, &o, 1);
        k = next;
    } while (k != b);
    copy_row(r->vert + i * nv, v, nv);
    copy_row(r->nbr + i * nv, nb, nv);
    r->orig[i] = o;
    r->dig[i] = (uint16_t)k;
    return k == b;
}

/* The rows at places head[b]..end[b]-1 of every bucket b < nb, cycle by cycle,
 * each into a place of its digit's bucket; returns the rows left misplaced (none
 * when each bucket's places are as many as the rows of its digit in all these
 * places). */
static inline size_t place_rows(const rows *r, size_t *head, const size_t *end, size_t nb, int nv)
{
    size_t stuck = 0;
    for (size_t b = 0; b < nb; b++)
        for (; head[b] < end[b]; head[b]++)
            if (r->dig[head[b]] != b) stuck += !follow_cycle(r, head, end, head[b], b, nv);
    return stuck;
}

/* Row v's digit at `level`: bits lo[level]..hi[level]-1 of its key. */
static inline uint16_t digit_at(const rows *r, const lh_index *v, int level)
{
    const size_t mask = ((size_t)1 << (r->hi[level] - r->lo[level])) - 1;
    return (uint16_t)(key_of(v, r->n) >> r->lo[level] & mask);
}

/* The digits of rows lo..hi-1 set, bucket k's size added to ends[k]. */
static inline void count_digits(const rows *r, size_t lo, size_t hi, int level, int nv, size_t *ends)
{
    for (size_t i = lo; i < hi; i++) {
        r->dig[i] = digit_at(r, r->vert + i * nv, level);
        ends[r->dig[i]]++;
    }
}

/* One digit pass over rows lo..hi-1 (their keys agree above bit r->hi[level]):
 * counts, then the rows are permuted into their buckets cycle by cycle, each
 * moving once. Bucket k ends at the returned end[k]; returns the bucket count. */
static inline size_t flag_pass(const rows *r, size_t lo, size_t hi, int level, int nv, size_t **ends)
{
    const size_t nb = (size_t)1 << (r->hi[level] - r->lo[level]);
    size_t *head = r->scratch + (size_t)level * 2 * ((size_t)1 << DIGIT_BITS), *end = head + nb;
    memset(end, 0, nb * sizeof *end);
    count_digits(r, lo, hi, level, nv, end);
    for (size_t b = 0, s = lo; b < nb; b++) {
        head[b] = s;
        s += end[b];
        end[b] = s;
    }
    place_rows(r, head, end, nb, nv);
    *ends = end;
    return nb;
}

/* Rows lo..hi-1, whose keys agree on the digits above `first` level, sorted: a
 * digit pass per level, then each bucket on the next digits, depth first. The
 * recursion is a loop over per-level cursors (no recursive call, so that it
 * inlines with nv constant). */
static inline void sort_rows(const rows *r, size_t lo, size_t hi, int first, int nv)
{
    size_t *end[MAX_LEVELS], nb[MAX_LEVELS], next[MAX_LEVELS], from[MAX_LEVELS];
    int level = first;
    for (;;) {
        if (hi - lo <= SMALL) {
            if (hi - lo > 1) insertion_sort(r, lo, hi, nv);
        } else if (level < r->levels && gather_sort(r, lo, hi, level, nv)) {
            /* sorted on all the bits left */
        } else if (level < r->levels) { /* a pass, then its buckets */
            nb[level] = flag_pass(r, lo, hi, level, nv, &end[level]);
            next[level] = 0;
            from[level] = lo;
            level++;
        } else if (key_of(r->vert + lo * nv, r->n) < r->n) { /* one first vertex */
            if (hi - lo <= GROUP_MAX)
                group_sort(r, lo, hi, nv);
            else
                heap_sort(r, lo, hi, nv);
        }
        while (level > first && next[level - 1] == nb[level - 1]) level--;
        if (level == first) return;
        lo = from[level - 1];
        hi = from[level - 1] = end[level - 1][next[level - 1]++];
    }
}

/* Each finite cell's vertex row among cells lo..hi-1 in canonical order
 * (lh__canonical_ranks), its neighbour row permuted alike; each row's position in
 * orig, its first digit in dig and counted in digits; returns the number of finite
 * cells. */
static size_t canonical_rows(const rows *r, size_t lo, size_t hi, int nv, size_t *digits)
{
    size_t count = 0;
    for (size_t c = lo; c < hi; c++) {
        lh_index *v = r->vert + c * nv, *nb = r->nbr + c * nv;
        r->orig[c] = (lh_index)c;
        if (v[0] >= 0) {
            count++;
            int rank[LH__TDS_MAX_NV];
            lh_index cv[LH__TDS_MAX_NV], cn[LH__TDS_MAX_NV];
            copy_row(cv, v, nv);
            copy_row(cn, nb, nv);
            lh__canonical_ranks(cv, nv, rank);
            /* scattered into the rows themselves: a copy scattered into a local
               array and read back whole would stall on store forwarding */
            for (int k = 0; k < nv; k++) v[rank[k]] = cv[k], nb[rank[k]] = cn[k];
        }
        r->dig[c] = digit_at(r, v, 0);
        digits[r->dig[c]]++;
    }
    return count;
}

/* The work of the threads (lh__par_for): canonical forms and first digits, the
 * first digit pass (first_pass), then the buckets of the first pass, each thread
 * those that start in its share of the rows. */
typedef struct sort_job {
    lh__tds *t;
    const rows *all;             /* the rows, for the first pass */
    rows r[LH__MAX_THREADS];     /* per thread: its scratch */
    size_t counts[LH__MAX_THREADS], stuck[LH__MAX_THREADS];
    size_t digits[LH__MAX_THREADS][(size_t)1 << DIGIT_BITS]; /* per thread: its rows of each first digit */
    size_t *head, *ends, nb;     /* the first pass's buckets: where each starts (then its
                                    first misplaced row), where it ends */
} sort_job;

static void canonical_share(void *ctx, int w, int nw)
{
    sort_job *j = ctx;
    const size_t top = (size_t)j->t->top, lo = lh__share(top, w, nw), hi = lh__share(top, w + 1, nw);
#define CANON(m) j->counts[w] = canonical_rows(j->all, lo, hi, m, j->digits[w])
    LH__WITH_CONSTANT_M(j->t->nv, CANON);
#undef CANON
}

/* Thread w's part of every bucket of the first pass, its share of the bucket's
 * places, filled with the rows found in its parts: a cycle stops where its next
 * row's bucket has no place left in w's part, and leaves that row misplaced. */
static void part_share(void *ctx, int w, int nw)
{
    sort_job *j = ctx;
    size_t head[(size_t)1 << DIGIT_BITS], end[(size_t)1 << DIGIT_BITS];
    for (size_t b = 0; b < j->nb; b++) {
        const size_t size = j->ends[b] - j->head[b];
        head[b] = j->head[b] + lh__share(size, w, nw);
        end[b] = j->head[b] + lh__share(size, w + 1, nw);
    }
#define PART(m) j->stuck[w] = place_rows(j->all, head, end, j->nb, m)
    LH__WITH_CONSTANT_M(j->t->nv, PART);
#undef PART
}

/* Rows lo..hi-1 of bucket b reordered so that those of digit b come first, moving
 * only the misplaced ones; returns where the first misplaced one is then. */
static size_t misplaced_last(const rows *r, size_t lo, size_t hi, size_t b, int nv)
{
    for (;;) {
        while (lo < hi && r->dig[lo] == b) lo++;
        while (lo < hi && r->dig[hi - 1] != b) hi--;
        if (lo >= hi) return lo; /* else dig[lo] != b == dig[hi - 1]: lo < hi - 1 */
        swap_rows(r, lo, hi - 1, nv);
        r->dig[hi - 1] = r->dig[lo];
        r->dig[lo] = (uint16_t)b;
        lo++, hi--;
    }
}

/* The buckets that start in thread w's share of the rows: their misplaced rows
 * moved last, head[b] at the first. */
static void misplaced_share(void *ctx, int w, int nw)
{
    sort_job *j = ctx;
    const size_t top = (size_t)j->t->top, lo = lh__share(top, w, nw), hi = lh__share(top, w + 1, nw);
    for (size_t b = 0, from = 0; b < j->nb; from = j->ends[b++])
        if (from >= lo && from < hi) j->head[b] = misplaced_last(j->all, from, j->ends[b], b, j->t->nv);
}

/* The first digit pass on nw threads, after canonical_share has set and counted
 * the digits: a speculative permutation, then a repair (Cho et al., "PARADIS: an
 * efficient parallel algorithm for in-place radix sort", PVLDB 8(12), 2015, §3).
 * Each bucket's places are cut into nw parts, thread w's part filled from the rows
 * in w's parts (part_share). Where the rows of a digit in w's parts outnumber the
 * places of w's part of its bucket, the extra ones stay misplaced: about the
 * square root of a part's size per bucket for rows in random order (3D 10^6 sites,
 * 2 threads: 33 000 of 6.7 million rows). Each bucket then
 * moves its misplaced rows last (misplaced_share), and one thread places them
 * (place_rows) as the sequential pass would, among those places alone. The order
 * within a bucket depends on nw; the next digits and order_group then order every
 * bucket's finite rows totally, and rows of other cells are not output. */
static void first_pass(sort_job *j, int nw)
{
    const rows *r = j->all;
    const int nv = j->t->nv;
    j->nb = (size_t)1 << (r->hi[0] - r->lo[0]);
    j->head = r->scratch, j->ends = r->scratch + ((size_t)1 << DIGIT_BITS);
    for (size_t b = 0, s = 0; b < j->nb; b++) {
        j->head[b] = s;
        for (int w = 0; w < nw; w++) s += j->digits[w][b];
        j->ends[b] = s;
    }
    lh__par_for(nw, part_share, j);
    size_t stuck = 0;
    for (int w = 0; w < nw; w++) stuck += j->stuck[w];
    if (!stuck) return;
    lh__par_for(nw, misplaced_share, j);
#define PLACE(m) place_rows(r, j->head, j->ends, j->nb, m)
    LH__WITH_CONSTANT_M(nv, PLACE);
#undef PLACE
}

static void bucket_share(void *ctx, int w, int nw)
{
    sort_job *j = ctx;
    const size_t top = (size_t)j->t->top, lo = lh__share(top, w, nw), hi = lh__share(top, w + 1, nw);
    for (size_t b = 0, from = 0; b < j->nb; from = j->ends[b++]) {
        if (from < lo || from >= hi) continue;
#define SORT(m) sort_rows(j->r + w, from, j->ends[b], 1, m)
        LH__WITH_CONSTANT_M(j->t->nv, SORT);
#undef SORT
    }
}

lh_status lh__tds_sort_cells(lh__tds *t, size_t n, lh_index *orig, size_t *count, int threads)
{
    sort_job *job = lh__alloc(&t->alloc, sizeof *job);
    if (!job) return LH_ERR_NOMEM;
    memset(job, 0, sizeof *job);
    job->t = t;
    const int nw = lh__par_width(threads, (size_t)t->top);
    rows r = {.vert = t->vert, .nbr = t->nbr, .orig = orig, .n = n};
    int bits = 1;
    while (bits < 64 && (n >> bits) != 0) bits++; /* keys are 0..n */
    r.levels = (bits + DIGIT_BITS - 1) / DIGIT_BITS;
    const int width = (bits + r.levels - 1) / r.levels;
    for (int i = 0, top = bits; i < r.levels; i++) {
        r.hi[i] = top;
        r.lo[i] = top > width ? top - width : 0;
        top = r.lo[i];
    }
    const size_t per = (size_t)r.levels * 2 * ((size_t)1 << DIGIT_BITS);
    const size_t cper = ((size_t)1 << GATHER_BITS) + 1;
    r.scratch = lh__alloc(&t->alloc, (size_t)nw * per * sizeof *r.scratch);
    r.pos = lh__alloc(&t->alloc, (size_t)nw * 3 * GROUP_MAX * sizeof *r.pos);
    r.gkey = lh__alloc(&t->alloc, (size_t)nw * GROUP_MAX * sizeof *r.gkey);
    r.dig = lh__alloc(&t->alloc, ((size_t)t->top + 1) * sizeof *r.dig);
    r.gcount = lh__alloc(&t->alloc, (size_t)nw * cper * sizeof *r.gcount);
    r.kbits = bits;
    r.kwidth = t->nv - 1 < 64 / bits ? t->nv - 1 : 64 / bits;
    lh_status st = r.scratch && r.pos && r.gkey && r.dig && r.gcount ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) {
        job->all = &r;
        lh__par_for(nw, canonical_share, job);
        *count = 0;
        for (int w = 0; w < nw; w++) *count += job->counts[w];
        first_pass(job, nw); /* the first digit, then its buckets (sort_rows) */
        /* gather_sort's rows: as many as the largest bucket (the first vertex is
           the least, so the first buckets hold more than their share) */
        size_t gmax = 0;
        for (size_t b = 0, from = 0; b < job->nb; from = job->ends[b++])
            gmax = job->ends[b] - from > gmax ? job->ends[b] - from : gmax;
        gmax = gmax < GATHER_MAX ? gmax : GATHER_MAX;
        const size_t gper = gmax * (2 * (size_t)t->nv + 2);
        if (!(r.gpos = lh__alloc(&t->alloc, ((size_t)nw * gper + 1) * sizeof *r.gpos))) st = LH_ERR_NOMEM;
        for (int w = 0; w < nw && st == LH_OK; w++) {
            rows *x = job->r + w;
            *x = r;
            x->scratch = r.scratch + (size_t)w * per;
            x->pos = r.pos + (size_t)w * 3 * GROUP_MAX;
            x->gkey = r.gkey + (size_t)w * GROUP_MAX;
            x->gcount = r.gcount + (size_t)w * cper;
            x->gmax = gmax;
            x->gpos = r.gpos + (size_t)w * gper;
            x->gvert = x->gpos + gmax, x->gnbr = x->gvert + gmax * t->nv, x->gorig = x->gnbr + gmax * t->nv;
        }
        if (st == LH_OK) lh__par_for(nw, bucket_share, job);
    }
    lh__free(&t->alloc, r.scratch);
    lh__free(&t->alloc, r.pos);
    lh__free(&t->alloc, r.gkey);
    lh__free(&t->alloc, r.dig);
    lh__free(&t->alloc, r.gcount);
    lh__free(&t->alloc, r.gpos);
    lh__free(&t->alloc, job);
    return st;
}

lh_status lh__tds_compact_cells(lh__tds *t, lh_index *orig, size_t *count)
{
    const int nv = t->nv;
    const rows r = {.vert = t->vert, .nbr = t->nbr, .orig = orig};
    size_t lo = 0, hi = (size_t)t->top;
    for (size_t c = 0; c < hi; c++) orig[c] = (lh_index)c;
    for (;;) { /* the finite rows first: the first other one swapped with the last finite */
        while (lo < hi && t->vert[lo * nv] >= 0) lo++;
        while (lo < hi && t->vert[(hi - 1) * nv] < 0) hi--;
        if (lo >= hi) break;
        swap_rows(&r, lo++, --hi, nv);
    }
    *count = lo;
    return LH_OK;
}
