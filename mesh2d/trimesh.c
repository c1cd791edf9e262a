/*
 * trimesh.c — lh_pslg_triangulate: the 2D meshing pipeline and its result handle.
 *   1. the Delaunay triangulation of the vertices (lh_delaunay, exact; duplicates
 *      merged there);
 *   2. the segments inserted in input order (cdt_insert.c);
 *   3. the domain carved and its regions marked (cdt_domain.c);
 *   4. quality refinement when asked (refine.c);
 *   5. the arrays of the handle, numbered afresh.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "lh_error.h"
#include "m2.h"
#include "m2_geom.h"
#include "refine.h"

struct lh_trimesh {
    lh_allocator al;
    size_t np, nt, ns;
    int na;
    double *xy, *pattr, *tattr;
    lh_index *pmark, *tri, *nbr, *seg, *smark, *spar, *bad;
    lh_trimesh_stats stats;
};

void lh_trimesh_options_default(lh_trimesh_options *o)
{
    if (!o) return;
    memset(o, 0, sizeof *o);
    o->boundary_steiner = 1;
    o->max_steiner = SIZE_MAX;
}

/* err->message = "LINE: text" and err->line = LINE when the item has a line, else
 * "text". */
static void say(lh_error *err, const size_t *lines, size_t item, const char *fmt, ...)
{
    if (!err) return;
    char *msg = err->message;
    const size_t size = sizeof err->message;
    int k = 0;
    if (lines) {
        err->line = lines[item];
        k = snprintf(msg, size, "%zu: ", lines[item]);
    }
    if (k < 0 || (size_t)k >= size) k = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg + k, size - (size_t)k, fmt, ap);
    va_end(ap);
}

/* Counts the mesh's arithmetic can hold: vertices and old triangles are numbered by
 * lh_index (m2_store.c keeps triangles below LH_INDEX_MAX / 4), and n attr_count
 * doubles must be a size. Larger counts cannot describe arrays that exist. */
static lh_status check_counts(const lh_pslg *g, lh_error *err)
{
    const size_t most = (size_t)LH_INDEX_MAX / 4;
    if (g->n >= most || g->cover_count >= most || g->segment_count >= most ||
        (g->attr_count > 0 && g->n > SIZE_MAX / 2 / sizeof(double) / (size_t)g->attr_count)) {
        say(err, NULL, 0,
            "%zu vertices (%d attributes each), %zu segments, %zu triangles to refine: "
            "more than an lh_index can number",
            g->n, g->attr_count, g->segment_count, g->cover_count);
        return LH_ERR_TOO_LARGE;
    }
    return LH_OK;
}

static lh_status check_input(const lh_pslg *g, const lh_trimesh_options *o, lh_error *err)
{
    const long long base = g->first_index, ibase = base + g->item_first_shift;
    const lh_status counted = check_counts(g, err);
    if (counted != LH_OK) return counted;
    if ((g->n && !g->xy) || (g->segment_count && !g->segments) || (g->hole_count && !g->holes) ||
        (g->region_count && !g->regions) || (g->cover_count && !g->cover) || (g->attr_count < 0) ||
        (g->attr_count && g->n && !g->attr)) {
        say(err, NULL, 0, "an array of the PSLG is missing");
        return LH_ERR_INVALID_ARGUMENT;
    }
    if (o->smooth < 0) {
        say(err, NULL, 0, "smoothing passes %d below 0", o->smooth);
        return LH_ERR_INVALID_ARGUMENT;
    }
    /* %.17g: every double's digits, so a value just past a bound never prints as the bound */
    if (!(o->min_angle >= 0 && o->min_angle <= LH_TRIMESH_MAX_ANGLE)) {
        say(err, NULL, 0, "min_angle %.17g outside 0..%g degrees", o->min_angle,
            LH_TRIMESH_MAX_ANGLE);
        return LH_ERR_INVALID_ARGUMENT;
    }
    if (isnan(o->max_area)) {
        say(err, NULL, 0, "max_area is NaN (0 or below: no area bound)");
        return LH_ERR_INVALID_ARGUMENT;
    }
    lh_error bad;
    if (lh_coords_validate(2, g->n, g->xy, &bad) == LH_ERR_NONFINITE) {
        say(err, g->vertex_line, bad.index / 2, "vertex %lld: coordinate is NaN or infinite",
            base + (long long)(bad.index / 2));
        return LH_ERR_NONFINITE;
    }
    for (size_t s = 0; s < g->segment_count; s++)
        for (int j = 0; j < 2; j++) {
            const lh_index v = g->segments[2 * s + j];
            if (v < 0 || (size_t)v >= g->n) {
                if (g->n)
                    say(err, g->segment_line, s,
                        "segment %lld: endpoint %lld is not a vertex (%lld..%lld)",
                        ibase + (long long)s, base + (long long)v, base,
                        base + (long long)g->n - 1);
                else
                    say(err, g->segment_line, s,
                        "segment %lld: endpoint %lld is not a vertex (there are none)",
                        ibase + (long long)s, base + (long long)v);
                return LH_ERR_INVALID_ARGUMENT;
            }
        }
    if (lh_coords_validate(2, g->hole_count, g->holes, &bad) == LH_ERR_NONFINITE) {
        say(err, g->hole_line, bad.index / 2, "hole %lld: coordinate is NaN or infinite",
            ibase + (long long)(bad.index / 2));
        return LH_ERR_NONFINITE;
    }
    if (lh_coords_validate(4, g->region_count, g->regions, &bad) == LH_ERR_NONFINITE) {
        say(err, g->region_line, bad.index / 4, "region %lld: NaN or infinity",
            ibase + (long long)(bad.index / 4));
        return LH_ERR_NONFINITE;
    }
    return LH_OK;
}

/* Steps 1-2: Delaunay of the vertices, then the segments. */
static lh_status constrain(lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g, lh_tri *dt,
                           lh_trimesh_stats *st_out, lh_error *err)
{
    const lh_index *dup = lh_tri_duplicate_of(dt);
    lh_status st = lh__m2_from_delaunay(m, dt);
    if (st != LH_OK) return st;
    const long long base = (long long)g->first_index + g->item_first_shift; /* the segments' */
    lh__m2_problem pb0 = {0, {-1, -1}, -1};
    if (m->cover && (st = lh__cover_segments(m, c, m->cover, &pb0)) != LH_OK) {
        if (st != LH_ERR_DEGENERATE) return st;
        say(err, NULL, 0, "the mesh to refine has crossing edges");
        return LH_ERR_INVALID_MESH;
    }
    for (size_t s = 0; s < g->segment_count; s++) {
        const lh_index a = dup[g->segments[2 * s]], b = dup[g->segments[2 * s + 1]];
        if (a == b) {
            st_out->segments_dropped++;
            continue;
        }
        const size_t before = m->ns;
        lh__m2_problem pb = {0, {-1, -1}, -1};
        st = lh__m2_insert_segment(m, c, a, b, (lh_index)s, &pb);
        if (st == LH_ERR_DEGENERATE && pb.kind == LH__M2_CROSSING) {
            const size_t o = (size_t)pb.seg[1];
            if (g->segment_line)
                say(err, g->segment_line, s, "segment %lld crosses segment %lld (line %zu)",
                    base + (long long)s, base + (long long)o, g->segment_line[o]);
            else
                say(err, NULL, 0, "segment %lld crosses segment %lld", base + (long long)s,
                    base + (long long)o);
            return LH_ERR_CROSSING_SEGMENTS;
        }
        if (st != LH_OK) return st;
        if (m->ns == before) st_out->segments_overlapping++;
    }
    return LH_OK;
}

/* Point markers by Triangle's rule (its "boundary markers" page): a vertex's own
 * nonzero marker; else the marker of an input segment with a nonzero one that it
 * lies on (an endpoint or a point put on it; of several, the first in input order, as
 * Triangle inserts them); else 1 on the domain's boundary; else 0. Steiner points have
 * no own marker. Subsegment markers (r->smark) are already the segments' rule. */
static lh_status point_markers(lh_trimesh *r, const lh__m2 *m)
{
    lh_index *from = lh__alloc(&r->al, (r->np ? r->np : 1) * sizeof *from); /* deciding segment */
    if (!from) return LH_ERR_NOMEM;
    for (size_t p = 0; p < r->np; p++) {
        from[p] = -1;
        if (p >= m->n_input) r->pmark[p] = 0;
    }
    for (size_t s = 0; s < r->ns; s++) {
        const lh_index par = r->spar[s], given = par >= 0 && m->seg_marker ? m->seg_marker[par] : 0;
        for (int j = 0; given && j < 2; j++) {
            const lh_index p = r->seg[2 * s + j];
            if ((r->pmark[p] && from[p] < 0) || (from[p] >= 0 && from[p] < par)) continue; /* own, or earlier */
            r->pmark[p] = given, from[p] = par;
        }
    }
    for (size_t s = 0; s < r->ns; s++) /* a nonzero subsegment marker without a segment's: the boundary */
        for (int j = 0; r->smark[s] && j < 2; j++)
            if (!r->pmark[r->seg[2 * s + j]]) r->pmark[r->seg[2 * s + j]] = 1;
    lh__free(&r->al, from);
    return LH_OK;
}

/* Step 5: the handle's arrays from the mesh's live triangles. The point arrays and,
 * when no triangle slot is free, the triangle arrays are taken over as they are (the
 * mesh's own allocations, same hooks); otherwise the triangles are renumbered. */
static lh_status harvest(lh_trimesh *r, lh__m2 *m)
{
    const int dense = m->live == m->nt;
    lh_index *map = dense ? NULL : lh__alloc(&r->al, (m->nt ? m->nt : 1) * sizeof *map);
    lh_index *smap = lh__alloc(&r->al, (m->ns ? m->ns : 1) * sizeof *smap);
    r->np = m->np, r->nt = m->live, r->na = m->attr_count;
    r->xy = m->xy, m->xy = NULL;
    r->pmark = m->pmark, m->pmark = NULL;
    r->pattr = m->attr, m->attr = NULL;
    if (dense) {
        r->tri = m->v, m->v = NULL;
        r->nbr = m->nb, m->nb = NULL;
        r->tattr = m->tattr, m->tattr = NULL;
    } else {
        r->tri = lh__alloc(&r->al, (r->nt ? r->nt : 1) * 3 * sizeof(lh_index));
        r->nbr = lh__alloc(&r->al, (r->nt ? r->nt : 1) * 3 * sizeof(lh_index));
        if (m->tattr) r->tattr = lh__alloc(&r->al, (r->nt ? r->nt : 1) * sizeof(double));
    }
    r->seg = lh__alloc(&r->al, (m->ns ? m->ns : 1) * 2 * sizeof(lh_index));
    r->smark = lh__alloc(&r->al, (m->ns ? m->ns : 1) * sizeof(lh_index));
    r->spar = lh__alloc(&r->al, (m->ns ? m->ns : 1) * sizeof(lh_index));
    lh_status st = LH_ERR_NOMEM;
    if ((!dense && (!map || (m->tattr && !r->tattr))) || !smap || !r->tri || !r->nbr || !r->seg ||
        !r->smark || !r->spar)
        goto done;
    if (!dense) {
        size_t nt = 0;
        for (size_t t = 0; t < m->nt; t++) map[t] = m->v[3 * t] >= 0 ? (lh_index)nt++ : -1;
    }
    for (size_t s = 0; s < m->ns; s++) smap[s] = -1;
    r->ns = 0;
    const lh_index *sg = m->sg, *v = dense ? r->tri : m->v, *nb = dense ? r->nbr : m->nb;
    for (size_t t = 0; t < m->nt; t++) {
        if (v[3 * t] < 0) continue;
        const size_t u = dense ? t : (size_t)map[t];
        for (int k = 0; k < 3; k++) {
            const lh_index n = nb[3 * t + k], s = sg[3 * t + k];
            if (!dense) {
                r->tri[3 * u + k] = v[3 * t + k];
                r->nbr[3 * u + k] = n >= 0 ? map[n] : -1;
            }
            if (s < 0 || smap[s] >= 0) continue;
            smap[s] = (lh_index)r->ns;
            const lh_index p = m->sp[s], given = p >= 0 && m->seg_marker ? m->seg_marker[p] : 0;
            r->seg[2 * r->ns] = m->sv[2 * (size_t)s];
            r->seg[2 * r->ns + 1] = m->sv[2 * (size_t)s + 1];
            r->smark[r->ns] = given ? given : n < 0 ? 1 : 0;
            r->spar[r->ns++] = p >= 0 ? p : -1; /* hull and old-mesh edges: no input segment */
        }
        if (!dense && r->tattr) r->tattr[u] = m->tattr[t];
    }
    st = point_markers(r, m);
done:
    lh__free(&r->al, map);
    lh__free(&r->al, smap);
    return st;
}

/* The statistics, scale-free (m2_geom.h): each angle atan2(2 area, dot) in the
 * triangle's scaled frame; an area beyond the range of doubles is 0 or infinity. */
static void measure(const lh_trimesh *r, lh_trimesh_stats *s)
{
    s->triangles = r->nt;
    double amin = INFINITY, amax = 0; /* radians */
    s->min_area = r->nt ? INFINITY : 0;
    s->max_area = 0;
    for (size_t t = 0; t < r->nt; t++) {
        const lh_index *v = r->tri + 3 * t;
        lh__g_tri g;
        lh__g_measure(r->xy + 2 * (size_t)v[0], r->xy + 2 * (size_t)v[1], r->xy + 2 * (size_t)v[2], &g);
        for (int k = 0; k < 3; k++) { /* corner k: its edges d[k+2] and -d[k+1] */
            const double a = atan2(g.area2, -lh__g_dot(g.d[(k + 1) % 3], g.d[(k + 2) % 3]));
            amin = a < amin ? a : amin;
            amax = a > amax ? a : amax;
        }
        const double area = ldexp(g.area2 / 2, 2 * g.e);
        s->min_area = area < s->min_area ? area : s->min_area;
        s->max_area = area > s->max_area ? area : s->max_area;
    }
    const double deg = 180 / 3.14159265358979323846;
    s->min_angle = r->nt ? amin * deg : 0;
    s->max_angle = r->nt ? amax * deg : 0;
}

/* The even-odd rule needs closed rings. The parity of the segments a path crosses
 * is the same for every path between two points exactly when every vertex ends an
 * even number of segments (the segments' mod-2 boundary is empty; merged duplicates
 * are one vertex, a zero-length segment counts twice at it, an overlap or a vertex on
 * a segment changes no parity). cdt_domain.c's parity flood relies on that: with an
 * open chain it would keep a triangle beside a removed one across an edge that is no
 * segment (sealed as a "hull" subsegment), the domain depending on the flood's order.
 * *at: the first vertex ending an odd number of segments, or -1. */
static lh_status open_ring_vertex(const lh_pslg *g, const lh_index *dup, const lh_allocator *al, lh_index *at)
{
    unsigned char *odd = lh__alloc(al, g->n ? g->n : 1);
    if (!odd) return LH_ERR_NOMEM;
    memset(odd, 0, g->n);
    for (size_t i = 0; i < 2 * g->segment_count; i++) odd[dup[g->segments[i]]] ^= 1;
    *at = -1;
    for (size_t v = 0; v < g->n && *at < 0; v++)
        if (odd[v]) *at = (lh_index)v;
    lh__free(al, odd);
    return LH_OK;
}

/* A hole seed on a segment is refused: which side its flood carves would depend on
 * point location (Triangle carves from the triangle its search finds), so the
 * result would not be a function of the input (docs/meshing.md). */
static lh_status holes_off_segments(lh__m2 *m, const lh_pslg *g, lh_error *err)
{
    const long long base = (long long)g->first_index + g->item_first_shift;
    for (size_t h = 0; h < g->hole_count && !g->even_odd; h++) {
        const lh_index s = lh__m2_subseg_at(m, g->holes + 2 * h);
        if (s < 0) continue;
        if (m->sp[s] >= 0)
            say(err, g->hole_line, h, "hole %lld lies on segment %lld", base + (long long)h,
                base + (long long)m->sp[s]);
        else
            say(err, g->hole_line, h, "hole %lld lies on the boundary of the mesh to refine",
                base + (long long)h);
        return LH_ERR_DEGENERATE;
    }
    return LH_OK;
}

/* Steps 3-5 on a constrained triangulation. */
static lh_status finish(lh_trimesh *r, lh__m2 *m, lh__m2_cavity *c, const lh_pslg *g,
                        const lh_trimesh_options *o, const lh_index *dup, lh_error *err)
{
    const int keep_hull = o->convex_hull || (g->segment_count == 0 && !g->even_odd);
    lh_index open = -1;
    lh_status st = g->even_odd ? open_ring_vertex(g, dup, &r->al, &open) : LH_OK;
    if (st != LH_OK) return st;
    if (open >= 0) {
        say(err, g->vertex_line, (size_t)open,
            "vertex %lld ends an odd number of segments: the even-odd "
            "rule needs closed rings",
            (long long)g->first_index + (long long)open);
        return LH_ERR_DEGENERATE;
    }
    if ((st = holes_off_segments(m, g, err)) != LH_OK) return st;
    size_t split = 0, unsplit = 0; /* -s: before the carving, as Triangle splits while inserting */
    if (o->split_segments && !m->cover &&
        (st = lh__m2_split_segments(m, c, o->max_steiner, &split, &unsplit)) != LH_OK)
        return st;
    st = lh__m2_domain(m, c, g, keep_hull, &r->stats.holes_ignored, &r->stats.regions_ignored);
    if (st == LH_ERR_DEGENERATE) {
        say(err, NULL, 0,
            g->even_odd ? "no triangle is inside the polygon rings"
                        : "the domain is empty: the flood from the outside or a "
                          "hole reached every triangle (is the boundary closed?)");
        return st;
    }
    if (st != LH_OK) return st;
    if (m->cover) lh__cover_relabel(m, m->cover);
    lh__refine_opts ro = {o->min_angle, o->max_area, o->region_areas, o->conforming,
                          o->boundary_steiner, o->max_steiner - split, g->segments, dup,
                          m->cover ? g->cover_area : NULL, &r->stats};
    if ((o->min_angle > 0 || o->max_area > 0 || o->region_areas || o->conforming) &&
        (st = lh__m2_refine(m, c, &ro)) != LH_OK)
        return st;
    r->stats.segments_unsplit += unsplit;
    if (o->smooth > 0 && (st = lh__m2_smooth(m, c, o->smooth, o->max_area, &r->stats.smoothing_moves)) != LH_OK)
        return st;
    if ((st = lh__m2_drop_removed(m)) != LH_OK) return st;
    /* the triangles still bad, in the handle's numbering (live slots in order), before
       harvest takes the mesh's arrays over */
    const int bounded = o->min_angle > 0 || o->max_area > 0 || o->region_areas;
    size_t nbad = 0;
    if (bounded) lh__m2_bad_triangles(m, &ro, NULL, &nbad);
    r->bad = lh__alloc(&r->al, (nbad ? nbad : 1) * sizeof(lh_index));
    if (!r->bad) return LH_ERR_NOMEM;
    if (bounded) lh__m2_bad_triangles(m, &ro, r->bad, &nbad);
    size_t live = 0, k = 0;
    for (size_t t = 0; t < m->nt && k < nbad; t++) {
        if (m->v[3 * t] < 0) continue;
        if ((size_t)r->bad[k] == t) r->bad[k++] = (lh_index)live;
        live++;
    }
    r->stats.steiner_points = m->np - m->n_input;
    r->stats.crossings_split = m->crossings;
    /* on input segments and on the boundary edges of a mesh being refined (pseg <= -2) */
    for (size_t p = m->n_input; p < m->np; p++) r->stats.steiner_on_segments += m->pseg[p] != -1;
    if ((st = harvest(r, m)) != LH_OK) return st;
    if (!o->region_attributes) {
        lh__free(&r->al, r->tattr);
        r->tattr = NULL;
    } else if (!r->tattr) { /* -A without regions: attribute 0 everywhere, as Triangle */
        r->tattr = lh__alloc(&r->al, (r->nt ? r->nt : 1) * sizeof *r->tattr);
        if (!r->tattr) return LH_ERR_NOMEM;
        for (size_t t = 0; t < r->nt; t++) r->tattr[t] = 0;
    }
    r->stats.bad_triangles = nbad;
    return LH_OK;
}

static lh_status triangulate(const lh_pslg *g, const lh_trimesh_options *opt, lh_trimesh **out,
                             lh_error *err)
{
    if (!out) return LH_ERR_INVALID_ARGUMENT;
    *out = NULL;
    lh_trimesh_options o;
    if (opt) o = *opt; else lh_trimesh_options_default(&o);
    lh_allocator al;
    if (!g) return LH_ERR_INVALID_ARGUMENT;
    if (!lh__allocator_init(&al, o.alloc)) {
        say(err, NULL, 0, "the allocator lacks its alloc or free hook");
        return LH_ERR_INVALID_ARGUMENT;
    }
    lh_status st = check_input(g, &o, err);
    if (st != LH_OK) return st;
    lh_options dopt;
    lh_options_default(&dopt);
    dopt.alloc = &al;
    lh_tri *dt = NULL;
    if ((st = lh_delaunay(2, g->n, g->xy, &dopt, &dt)) != LH_OK) {
        if (st == LH_ERR_DEGENERATE)
            say(err, NULL, 0,
                "the vertices are all collinear or fewer than 3 distinct: no triangle");
        return st;
    }
    lh_trimesh *r = lh__alloc(&al, sizeof *r);
    lh__m2 m;
    lh__m2_cavity c;
    memset(&c, 0, sizeof c);
    memset(&m, 0, sizeof m);
    if (!r) {
        lh_tri_free(dt);
        return LH_ERR_NOMEM;
    }
    memset(r, 0, sizeof *r);
    r->al = al;
    r->stats.input_vertices = g->n;
    r->stats.duplicates_merged = lh_tri_duplicate_count(dt);
    st = lh__m2_init(&m, &al, g->n, g->xy, g->attr_count, g->attr, g->vertex_marker);
    m.seg_marker = g->segment_marker;
    m.split_crossings = o.split_crossings;
    m.in_seg = g->segments;
    lh__cover cover;
    memset(&cover, 0, sizeof cover);
    if (st == LH_OK && g->cover_count) {
        st = lh__cover_build(&cover, &al, g, lh_tri_duplicate_of(dt));
        if (st == LH_ERR_INVALID_ARGUMENT || st == LH_ERR_DEGENERATE)
            say(err, NULL, 0,
                st == LH_ERR_DEGENERATE ? "the mesh to refine has no triangle of positive area"
                                        : "the mesh to refine names a point that does not exist, "
                                          "or has an edge of three triangles");
        if (st == LH_ERR_INVALID_ARGUMENT || st == LH_ERR_DEGENERATE) st = LH_ERR_INVALID_MESH;
        m.cover = &cover;
    }
    if (st == LH_OK) st = constrain(&m, &c, g, dt, &r->stats, err);
    if (st == LH_OK) st = finish(r, &m, &c, g, &o, lh_tri_duplicate_of(dt), err);
    lh__m2_cavity_free(&m, &c);
    lh__m2_free(&m);
    lh__cover_free(&cover);
    lh_tri_free(dt);
    if (st != LH_OK) {
        if (st == LH_ERR_INTERNAL && err && !err->message[0])
            say(err, NULL, 0, "internal consistency check failed");
        lh_trimesh_free(r);
        return st;
    }
    *out = r;
    return LH_OK;
}

void lh_trimesh_free(lh_trimesh *r)
{
    if (!r) return;
    void *a[] = {r->xy, r->pattr, r->tattr, r->pmark, r->tri, r->nbr, r->seg, r->smark, r->spar, r->bad};
    for (size_t i = 0; i < sizeof a / sizeof a[0]; i++) lh__free(&r->al, a[i]);
    const lh_allocator al = r->al;
    lh__free(&al, r);
}

size_t lh_trimesh_point_count(const lh_trimesh *m) { return m ? m->np : 0; }
const double *lh_trimesh_points(const lh_trimesh *m) { return m ? m->xy : NULL; }
const lh_index *lh_trimesh_point_markers(const lh_trimesh *m) { return m ? m->pmark : NULL; }
int lh_trimesh_point_attr_count(const lh_trimesh *m) { return m ? m->na : 0; }
const double *lh_trimesh_point_attrs(const lh_trimesh *m) { return m ? m->pattr : NULL; }
size_t lh_trimesh_triangle_count(const lh_trimesh *m) { return m ? m->nt : 0; }
const lh_index *lh_trimesh_triangles(const lh_trimesh *m) { return m ? m->tri : NULL; }
const lh_index *lh_trimesh_neighbors(const lh_trimesh *m) { return m ? m->nbr : NULL; }
const double *lh_trimesh_triangle_attrs(const lh_trimesh *m) { return m ? m->tattr : NULL; }
size_t lh_trimesh_segment_count(const lh_trimesh *m) { return m ? m->ns : 0; }
const lh_index *lh_trimesh_segments(const lh_trimesh *m) { return m ? m->seg : NULL; }
const lh_index *lh_trimesh_segment_markers(const lh_trimesh *m) { return m ? m->smark : NULL; }
const lh_index *lh_trimesh_segment_parents(const lh_trimesh *m) { return m ? m->spar : NULL; }
const lh_index *lh_trimesh_bad_triangles(const lh_trimesh *m) { return m ? m->bad : NULL; }

void lh_trimesh_stats_get(const lh_trimesh *m, lh_trimesh_stats *out)
{
    if (!out) return;
    if (!m) {
        memset(out, 0, sizeof *out);
        return;
    }
    *out = m->stats;
    measure(m, out);
}

lh_status lh_pslg_triangulate(const lh_pslg *g, const lh_trimesh_options *opt, lh_trimesh **out,
                              lh_error *err)
{
    lh__error_clear(err);
    return lh__error_done(err, triangulate(g, opt, out, err));
}
