/*
 * leftover.c — the tetrahedra quality refinement leaves over its bounds, and why
 * (lh_tetmesh_leftovers). Refinement records each bad tet of its last scan with the
 * outcome of its split (refine_split.c), keyed by its corners' coordinates; the
 * final mesh's tets are looked up by theirs (a tet the sliver flips made is not
 * found: LH_LEFT_FLIPS). Beside each, the nearest input angle below 60 degrees —
 * between two segments at an input point, or two facets along a segment — the
 * angles Shewchuk's analysis needs at least 60 (segments) to bound the radius-edge
 * ratio ("Tetrahedral mesh generation by Delaunay refinement", SoCG 1998, sec. 3).
 * Distances and angles in floating point: a report, not a decision.
 */
#include "lh_sort.h"
#include "refine.h"
#include "t3.h"
#include "tet_geom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SMALL_ANGLE 60.0
#define DEG (180 / 3.14159265358979323846)

/* A recorded bad tet: its corners' coordinates in coordinate order, its outcome. */
typedef struct t3_left {
    double key[12];
    int why, over;
} t3_left;

/* A small input angle: at point a (b -1), or along segment a b. */
typedef struct angle_feature {
    lh_index a, b;
    double angle;
} angle_feature;

static int cmp_left(const void *pa, const void *pb)
{
    const t3_left *a = pa, *b = pb;
    int s = 0;
    for (int k = 0; k < 4 && !s; k++) s = lh__t3_cmp_xyz(a->key + 3 * k, b->key + 3 * k);
    return s;
}

/* The coordinates of corners p[0..3] in coordinate order into key. */
static void corner_key(const double *const *p, double key[12])
{
    const double *q[4];
    memcpy(q, p, sizeof q);
    lh__t3_sort_corners(q, 4);
    for (int i = 0; i < 4; i++) memcpy(key + 3 * i, q[i], 3 * sizeof(double));
}

lh_status lh__t3_left_record(t3_ctx *c, const t3_bad *bad, size_t count)
{
    lh__free(&c->al, c->left);
    c->left = lh__alloc(&c->al, (count + 1) * sizeof *c->left);
    c->left_count = count;
    if (!c->left) return lh__t3_say(c, LH_ERR_NOMEM, 0, "out of memory");
    for (size_t i = 0; i < count; i++) {
        const double *p[4];
        for (int j = 0; j < 4; j++) p[j] = lh__t3_pt(c, c->tv[4 * (size_t)bad[i].t + (size_t)j]);
        corner_key(p, c->left[i].key);
        c->left[i].why = bad[i].why >= T3_QUEUED ? LH_LEFT_STOPPED : bad[i].why;
        c->left[i].over = bad[i].over;
    }
    qsort(c->left, count, sizeof *c->left, cmp_left);
    return LH_OK;
}

static double angle_of(const double *u, const double *v)
{
    double w[3];
    lh__t3_cross(u, v, w);
    return DEG * atan2(sqrt(lh__t3_dot(w, w)), lh__t3_dot(u, v));
}

static lh_status feature_add(t3_ctx *c, angle_feature **f, size_t *count, size_t *cap,
                             angle_feature x)
{
    if (*count == *cap) {
        const size_t nc = 2 * *cap + 16;
        angle_feature *y = lh__alloc(&c->al, nc * sizeof *y);
        if (!y) return LH_ERR_NOMEM;
        if (*count) memcpy(y, *f, *count * sizeof *y);
        lh__free(&c->al, *f);
        *f = y, *cap = nc;
    }
    (*f)[(*count)++] = x;
    return LH_OK;
}

/* The direction from point a to point b, in a frame where no square overflows. */
static void direction(const t3_ctx *c, lh_index a, lh_index b, double u[3])
{
    const double *p[2] = {lh__t3_pt(c, a), lh__t3_pt(c, b)};
    double q[2][3];
    lh__t3_frame(p, 2, q);
    memcpy(u, q[1], sizeof q[1]);
}

/* Segments meeting at an input point at under SMALL_ANGLE: brute force over the
 * segments' ends (each end's other ends gathered by a pass over the segments). */
static lh_status segment_angles(t3_ctx *c, angle_feature **f, size_t *count, size_t *cap)
{
    lh_index *first = lh__alloc(&c->al, (c->n_input + 1) * sizeof *first);
    lh_index *other = lh__alloc(&c->al, (2 * c->seg_count + 1) * sizeof *other);
    lh_status st = first && other ? LH_OK : LH_ERR_NOMEM;
    for (size_t i = 0; st == LH_OK && i <= c->n_input; i++) first[i] = 0;
    for (size_t s = 0; st == LH_OK && s < c->seg_count; s++)
        first[c->seg[s].a + 1]++, first[c->seg[s].b + 1]++;
    for (size_t i = 0; st == LH_OK && i < c->n_input; i++) first[i + 1] += first[i];
    for (size_t s = 0; st == LH_OK && s < c->seg_count; s++) {
        other[first[c->seg[s].a]++] = c->seg[s].b;
        other[first[c->seg[s].b]++] = c->seg[s].a;
    }
    for (size_t i = c->n_input; st == LH_OK && i > 0; i--) first[i] = first[i - 1];
    if (st == LH_OK) first[0] = 0;
    for (size_t p = 0; st == LH_OK && p < c->n_input; p++) {
        double least = 180;
        for (lh_index i = first[p]; i < first[p + 1]; i++)
            for (lh_index j = i + 1; j < first[p + 1]; j++) {
                double u[3], v[3];
                direction(c, (lh_index)p, other[i], u), direction(c, (lh_index)p, other[j], v);
                least = fmin(least, angle_of(u, v));
            }
        if (least < SMALL_ANGLE)
            st = feature_add(c, f, count, cap, (angle_feature){(lh_index)p, -1, least});
    }
    lh__free(&c->al, first);
    lh__free(&c->al, other);
    return st;
}

/* Facets meeting along a segment at under SMALL_ANGLE: for every two facet
 * triangles on one segment from different facets, the angle between their
 * half-planes (their third corners' offsets across the segment). */
static lh_status facet_angles(t3_ctx *c, angle_feature **f, size_t *count, size_t *cap)
{
    lh_index *wing =
        lh__alloc(&c->al, (3 * c->tri_count + 1) * 2 * sizeof *wing); /* (segment, tri edge) */
    size_t wings = 0;
    if (!wing) return LH_ERR_NOMEM;
    for (size_t t = 0; t < c->tri_count; t++)
        for (int e = 0; e < 3; e++)
            if (c->tri_seg[3 * t + (size_t)e] >= 0)
                wing[2 * wings] = c->tri_seg[3 * t + (size_t)e],
                         wing[2 * wings + 1] = (lh_index)(3 * t + (size_t)e), wings++;
    lh_status st = lh__sort_by_index(&c->al, wing, wings, 2 * sizeof *wing, 0, c->seg_count);
    for (size_t i = 0; st == LH_OK && i < wings;) {
        size_t j = i;
        while (j < wings && wing[2 * j] == wing[2 * i]) j++;
        const t3_seg *s = c->seg + wing[2 * i];
        double least = 180, u[3];
        direction(c, s->a, s->b, u);
        const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        for (size_t x = i; x < j; x++)
            for (size_t y = x + 1; y < j; y++) {
                const size_t tx = (size_t)wing[2 * x + 1] / 3, ty = (size_t)wing[2 * y + 1] / 3;
                if (c->tri_facet[tx] == c->tri_facet[ty]) continue;
                double w[2][3];
                for (int k = 0; k < 2; k++) { /* the third corner, less its part along u */
                    const size_t at = k ? (size_t)wing[2 * y + 1] : (size_t)wing[2 * x + 1];
                    direction(c, s->a, c->tri[3 * (at / 3) + (at % 3 + 2) % 3], w[k]);
                    const double along = (w[k][0] * u[0] + w[k][1] * u[1] + w[k][2] * u[2]) / uu;
                    for (int d = 0; d < 3; d++) w[k][d] -= along * u[d];
                }
                least = fmin(least, angle_of(w[0], w[1]));
            }
        if (least < SMALL_ANGLE)
            st = feature_add(c, f, count, cap, (angle_feature){s->a, s->b, least});
        i = j;
    }
    lh__free(&c->al, wing);
    return st;
}

/* x's distance to segment a b (clamped to its ends). */
static double to_segment(const double *x, const double *a, const double *b)
{
    const double *p[3] = {a, b, x};
    double q[3][3];
    const int e = lh__t3_frame(p, 3, q);
    const double uu = q[1][0] * q[1][0] + q[1][1] * q[1][1] + q[1][2] * q[1][2];
    double t = uu > 0 ? (q[2][0] * q[1][0] + q[2][1] * q[1][1] + q[2][2] * q[1][2]) / uu : 0;
    t = fmin(fmax(t, 0), 1);
    double d = 0;
    for (int k = 0; k < 3; k++) d += (q[2][k] - t * q[1][k]) * (q[2][k] - t * q[1][k]);
    return ldexp(sqrt(d), e);
}

/* The feature nearest tet p (from its nearest corner) into o. */
static void nearest(const t3_ctx *c, const angle_feature *f, size_t count, const double *const *p,
                    double shortest, lh_tetmesh_leftover *o)
{
    double best = INFINITY;
    for (size_t i = 0; i < count; i++) {
        double d = INFINITY;
        for (int j = 0; j < 4; j++)
            d = fmin(d, f[i].b < 0 ? lh__t3_dist(p[j], lh__t3_pt(c, f[i].a))
                                   : to_segment(p[j], lh__t3_pt(c, f[i].a), lh__t3_pt(c, f[i].b)));
        if (!(d < best)) continue;
        best = d;
        o->angle_kind = f[i].b < 0 ? 1 : 2;
        o->angle_at[0] = f[i].a, o->angle_at[1] = f[i].b, o->angle = f[i].angle;
    }
    o->distance = o->angle_kind ? best / shortest : 0;
}

static int worst_first(const void *pa, const void *pb)
{
    const lh_tetmesh_leftover *a = pa, *b = pb;
    if (a->radius_edge != b->radius_edge) return a->radius_edge > b->radius_edge ? -1 : 1;
    return a->tet < b->tet ? -1 : a->tet > b->tet;
}

/* Tet t of m as a leftover into o, beside the nearest of the count features f: 1
 * when it is one. Measured on its corners in coordinate order, as refinement's scan
 * measures. */
static int leftover_of(const t3_ctx *c, const lh_tetmesh *m, size_t t, const angle_feature *f,
                       size_t count, lh_tetmesh_leftover *o)
{
    const double *p[4];
    for (int j = 0; j < 4; j++) p[j] = m->xyz + 3 * (size_t)m->tets[4 * t + (size_t)j];
    t3_left key;
    corner_key(p, key.key);
    const t3_left *rec = bsearch(&key, c->left, c->left_count, sizeof key, cmp_left);
    const double *q[4] = {key.key, key.key + 3, key.key + 6, key.key + 9};
    t3_tet_measure tm;
    lh__t3_tet_measure(q, &tm);
    const double bound = c->opt->max_radius_edge;
    if (!rec && !(bound > 0 && tm.ratio > bound)) return 0;
    memset(o, 0, sizeof *o);
    o->tet = (lh_index)t, o->radius_edge = tm.ratio, o->angle_at[0] = o->angle_at[1] = -1;
    o->why = rec ? rec->why : LH_LEFT_FLIPS;
    o->over = rec ? rec->over : 1;
    nearest(c, f, count, q, tm.shortest, o);
    return 1;
}

lh_status lh__t3_leftovers(t3_ctx *c, lh_tetmesh *m)
{
    angle_feature *f = NULL;
    size_t count = 0, cap = 0, left = 0;
    lh_status st = segment_angles(c, &f, &count, &cap);
    if (st == LH_OK) st = facet_angles(c, &f, &count, &cap);
    if (st == LH_OK) st = lh__tetmesh_array(m, (void **)&m->left, m->tet_count, sizeof *m->left);
    for (size_t t = 0; st == LH_OK && t < m->tet_count; t++)
        left += leftover_of(c, m, t, f, count, m->left + left);
    lh__free(&c->al, f);
    if (st != LH_OK)
        return lh__t3_say(c, st, 0, st == LH_ERR_NOMEM ? "out of memory" : "too many tetrahedra");
    m->left_count = left;
    qsort(m->left, left, sizeof *m->left, worst_first);
    return LH_OK;
}

const lh_tetmesh_leftover *lh_tetmesh_leftovers(const lh_tetmesh *m, size_t *count)
{
    if (count) *count = m ? m->left_count : 0;
    return m && m->left_count ? m->left : NULL;
}
