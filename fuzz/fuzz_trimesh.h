/* fuzz_trimesh.h — what the files of the fuzz_trimesh target share (fuzz_trimesh.c:
 * the target and its contract): the decoded input (fuzz_trimesh_input.c), the checks
 * of a mesh (fuzz_trimesh_checks.c), the cover stage (fuzz_trimesh_refine.c), and the
 * counting allocator's runs. */
#ifndef LH_FUZZ_TRIMESH_H
#define LH_FUZZ_TRIMESH_H

#include "lifthull.h"

#include <stddef.h>
#include <stdint.h>

#define MAXV 40
#define MAXS (MAXV + 60)

/* A counting allocator that fails call number fail_at (0: never). */
typedef struct counter { long live, calls, fail_at, failed; } counter;

typedef struct grid { long long x, y; } grid;

typedef struct input {
    lh_pslg g;
    lh_trimesh_options o;
    grid v[MAXV];
    double xy[2 * MAXV], attr[MAXV], holes[6], regions[12], off, scale;
    lh_index seg[2 * MAXS];
    size_t seg_line[MAXS];
    int crossing, collinear, keep_hull, refine, fail_mode;
    lh_index open;         /* the first vertex ending an odd number of segments, or -1 */
    size_t dups;
    unsigned fail_pick, cover; /* cover: the byte after the PSLG's (refine_cover) */
} input;

/* Shared among the target's files by their plain names: each fuzz target is a
 * program of its own, whose only other symbols are the library's lh_ ones. */

/* The angle bounds a byte picks (decode, refine_cover). */
extern const double angles[8];

/* fuzz_trimesh_input.c: exact predicates on the grid and the input's decoding. */
long long orient(grid a, grid b, grid c);
int on_segment(grid a, grid b, grid c);
int cross(const grid *v, size_t n, grid a, grid b, grid c, grid d);
long long hull_area2(const grid *v, size_t n);
void decode(const uint8_t *data, size_t size, input *in);

/* fuzz_trimesh.c: a run with the counting allocator (msg, size bytes, receives the
 * lh_error's message; aborts when the lh_error disagrees with the status), equal
 * meshes, a failing run. */
lh_status run(const input *in, counter *c, lh_trimesh **m, char *msg, size_t size);
int same(const lh_trimesh *a, const lh_trimesh *b);
void check_failure(const input *in, const lh_trimesh *m, long calls);

/* fuzz_trimesh_checks.c: the checks of a successful run. */
void check_links(const lh_trimesh *m);
void check_bounds(const lh_trimesh_options *o, const lh_trimesh *m, const lh_trimesh_stats *st);
long double grid_area2(const input *in, const lh_trimesh *m, size_t from, size_t *moved);
void check_area(const input *in, long double want, long double got, size_t moved);
void check_mesh(const input *in, const lh_trimesh *m);

/* fuzz_trimesh_refine.c: the cover stage. */
void refine_cover(const input *in, const lh_trimesh *old);

#endif
