/* fuzz_trimesh_input.c — fuzz_trimesh's input: exact orientation, crossing and hull
 * area on the integer grid, and the decoding of the fuzzer's bytes into a PSLG and
 * options with what the run must say about them (fuzz_trimesh.c's header). */
#include "fuzz_trimesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


typedef struct src { const uint8_t *p; size_t n, at; } src;

static unsigned get(src *s) { return s->at < s->n ? s->p[s->at++] : 0; }

long long orient(grid a, grid b, grid c)
{
    const long long d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (d > 0) - (d < 0);
}

/* c on the closed segment a-b (exactly). */
int on_segment(grid a, grid b, grid c)
{
    return orient(a, b, c) == 0 && (c.x - a.x) * (c.x - b.x) <= 0 && (c.y - a.y) * (c.y - b.y) <= 0;
}

/* Segments a-b and c-d cross: their interiors meet in one point that is no vertex. */
int cross(const grid *v, size_t n, grid a, grid b, grid c, grid d)
{
    if (orient(a, b, c) * orient(a, b, d) >= 0 || orient(c, d, a) * orient(c, d, b) >= 0) return 0;
    for (size_t i = 0; i < n; i++)
        if (on_segment(a, b, v[i]) && on_segment(c, d, v[i])) return 0;
    return 1;
}

/* Twice the area of the convex hull of v[0..n-1] (Andrew's monotone chain). */
static int grid_cmp(const void *x, const void *y)
{
    const grid *a = x, *b = y;
    return a->x != b->x ? (a->x > b->x) - (a->x < b->x) : (a->y > b->y) - (a->y < b->y);
}

long long hull_area2(const grid *v, size_t n)
{
    grid p[MAXV], h[2 * MAXV + 2];
    memcpy(p, v, n * sizeof *p);
    qsort(p, n, sizeof *p, grid_cmp);
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    for (size_t i = n - 1, t = k + 1; i-- > 0;) {
        while (k >= t && orient(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    long long a = 0;
    for (size_t i = 0; i + 1 < k; i++) a += h[i].x * h[i + 1].y - h[i + 1].x * h[i].y;
    return a;
}

const double angles[8] = {0, 20, 25, 30, 33, 0, 20, 30};

/* The leading bytes: flags, scale exponent, vertex and segment counts, ring. */
typedef struct header {
    unsigned f0, f1, f2, kb, nvb, nsb, ring;
} header;

static const double areas[4] = {0, 0.5, 2, 8};

/* The options and the frame (scale, offset) the header's bits choose. */
static void decode_options(const header *h, input *in)
{
    const unsigned f0 = h->f0, f1 = h->f1, f2 = h->f2;
    const int k = (int8_t)h->kb / 2; /* 2^-64 .. 2^63 */
    const int mode = f2 & 3;
    in->scale = mode & 1 ? ldexp(1.0, k) : 1;
    in->off = mode & 2 ? (f2 & 4 ? 0x1p40 : 1e6) : 0;
    lh_trimesh_options *o = &in->o;
    lh_trimesh_options_default(o);
    in->g.even_odd = f0 & 1;
    o->convex_hull = (f0 >> 1) & 1;
    o->conforming = (f0 >> 2) & 1;
    o->min_angle = angles[(f0 >> 4) & 7];
    const int bs = f1 & 3;
    o->boundary_steiner = bs < 2 ? 1 : bs == 2 ? 0 : -1;
    const double unit = in->scale * in->scale; /* areas scale with 4^k */
    o->max_area = areas[(f1 >> 2) & 3] * unit;
    const int ms = (f1 >> 4) & 3;
    o->max_steiner = ms == 1 ? (size_t)(h->kb & 15) : ms == 2 ? 64 : 5000;
    o->region_areas = (f1 >> 6) & 1;
    o->region_attributes = f1 >> 7;
    o->split_crossings = h->ring >> 7;
    o->smooth = (int)(in->fail_pick >> 14); /* 0..3 passes */
}

/* n vertices on the grid [-8, 8]^2, counting repeats; with an attribute each when
 * f2's top bit is set. */
static void decode_vertices(src *s, const header *h, input *in)
{
    lh_pslg *g = &in->g;
    const size_t n = 3 + h->nvb % (MAXV - 2);
    g->n = n;
    g->xy = in->xy;
    for (size_t i = 0; i < n; i++) {
        in->v[i].x = (long long)(get(s) % 17) - 8;
        in->v[i].y = (long long)(get(s) % 17) - 8;
        in->xy[2 * i] = ((double)in->v[i].x + in->off) * in->scale;
        in->xy[2 * i + 1] = ((double)in->v[i].y + in->off) * in->scale;
        in->attr[i] = (double)i;
        for (size_t j = 0; j < i; j++)
            if (in->v[j].x == in->v[i].x && in->v[j].y == in->v[i].y) {
                in->dups++;
                break;
            }
    }
    if (h->f2 >> 7) {
        g->attr_count = 1;
        g->attr = in->attr;
    }
}

/* Segments: a ring through the first r vertices, then chosen pairs; a pair crossing
 * an earlier segment is dropped when f0 asks for a noncrossing input. */
static void decode_segments(src *s, const header *h, input *in)
{
    lh_pslg *g = &in->g;
    const size_t n = g->n;
    const int noncrossing = (h->f0 >> 3) & 1;
    size_t ns = 0;
    const size_t r = (h->ring & 63) < n ? (h->ring & 63) : n, extra = h->nsb % 61;
    for (size_t i = 0; i < r + extra; i++) {
        lh_index a, b;
        if (i < r) {
            a = (lh_index)i, b = (lh_index)((i + 1) % r);
        } else {
            a = (lh_index)(get(s) % n);
            b = (lh_index)(get(s) % n);
        }
        int c = 0;
        for (size_t j = 0; j < ns && !c; j++)
            c = cross(in->v, n, in->v[a], in->v[b], in->v[in->seg[2 * j]], in->v[in->seg[2 * j + 1]]);
        if (c && noncrossing) continue;
        in->crossing |= c;
        in->seg[2 * ns] = a;
        in->seg[2 * ns++ + 1] = b;
    }
    g->segment_count = ns;
    g->segments = ns ? in->seg : NULL;
    if (h->ring & 64) { /* as from a reader: numbered from 1, each segment with its line */
        g->first_index = 1;
        for (size_t i = 0; i < ns; i++) in->seg_line[i] = 100 + 2 * i;
        g->segment_line = ns ? in->seg_line : NULL;
    }
}

/* Hole and region points on the half-integer grid, regions with an attribute and an
 * area bound (or none). */
static void decode_holes_regions(src *s, const header *h, input *in)
{
    lh_pslg *g = &in->g;
    const double unit = in->scale * in->scale;
    g->hole_count = (h->f2 >> 3) & 3;
    g->holes = g->hole_count ? in->holes : NULL;
    for (size_t i = 0; i < 2 * g->hole_count; i++)
        in->holes[i] = ((double)(get(s) % 33) / 2 - 8 + in->off) * in->scale;
    g->region_count = (h->f2 >> 5) & 3;
    g->regions = g->region_count ? in->regions : NULL;
    for (size_t i = 0; i < g->region_count; i++) {
        double *q = in->regions + 4 * i;
        q[0] = ((double)(get(s) % 33) / 2 - 8 + in->off) * in->scale;
        q[1] = ((double)(get(s) % 33) / 2 - 8 + in->off) * in->scale;
        const unsigned b = get(s);
        q[2] = (double)(b >> 2);
        q[3] = areas[b & 3] * unit - (b & 3 ? 0 : 1);
    }
}

/* What the run must say, from the decoded input: all vertices collinear, the hull
 * kept, the first vertex of odd segment degree (an open chain), refinement asked. */
static void derive_facts(input *in)
{
    const lh_pslg *g = &in->g;
    const lh_trimesh_options *o = &in->o;
    const size_t n = g->n, ns = g->segment_count;
    in->collinear = 1;
    for (size_t i = 2; i < n && in->collinear; i++)
        for (size_t j = 1; j < i && in->collinear; j++)
            if (orient(in->v[0], in->v[j], in->v[i])) in->collinear = 0;
    in->keep_hull = !g->even_odd && (o->convex_hull || ns == 0);
    unsigned char odd[MAXV] = {0};
    for (size_t i = 0; i < 2 * ns; i++) {
        size_t a = (size_t)in->seg[i];
        for (size_t j = 0; j < a; j++)
            if (in->v[j].x == in->v[a].x && in->v[j].y == in->v[a].y) {
                a = j;
                break;
            }
        odd[a] ^= 1;
    }
    in->open = -1;
    for (size_t i = n; i-- > 0;)
        if (odd[i]) in->open = (lh_index)i;
    in->refine = o->min_angle > 0 || o->max_area > 0 || o->region_areas || o->conforming;
}

void decode(const uint8_t *data, size_t size, input *in)
{
    src s = {data, size, 0};
    memset(in, 0, sizeof *in);
    header h;
    h.f0 = get(&s), h.f1 = get(&s), h.f2 = get(&s), h.kb = get(&s), h.nvb = get(&s);
    h.nsb = get(&s), h.ring = get(&s);
    in->fail_mode = h.f0 >> 7;
    in->fail_pick = get(&s) << 8;
    in->fail_pick |= get(&s);
    decode_options(&h, in);
    decode_vertices(&s, &h, in);
    decode_segments(&s, &h, in);
    decode_holes_regions(&s, &h, in);
    derive_facts(in);
    in->cover = get(&s); /* after everything else: the inputs written before it mean the same */
}
