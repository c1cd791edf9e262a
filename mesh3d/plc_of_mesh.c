/*
 * plc_of_mesh.c — lh_plc_from_tetmesh: the PLC a tetrahedral mesh bounds, so that
 * lh_tetrahedralize can refine the mesh (TetGen's -r): its points, a triangle facet
 * for every face of its boundary and every face between tetrahedra of different
 * attributes, and a region point in each part those facets enclose. Meshed with
 * regions_only, the domain is the mesh's own, voids and all: every part has its
 * region point, and no flood from one crosses a facet.
 */
#include "lh_alloc.h"
#include "lh_error.h"
#include "lh_sort.h"
#include "lifthull.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct face_rec {
    lh_index v[3]; /* ascending */
    lh_index t;    /* the tet it is a face of */
} face_rec;

typedef struct from_mesh {
    const lh_allocator *al;
    lh_error *err;
    size_t n, nt;
    const double *xyz, *attr;
    lh_index *tv;     /* the tets, positively oriented */
    face_rec *face;   /* 4 per tet, sorted */
    lh_index *parent; /* union-find over tets: the parts */
    lh_index *seed;   /* per part root: the tet its region point is in, or -1 */
    lh_pred *pred;
} from_mesh;

static const double *pt(const from_mesh *x, lh_index i)
{
    return x->xyz + 3 * (size_t)i;
}

static lh_status check_args(const from_mesh *x, const lh_index *tets)
{
    if ((x->n && !x->xyz) || (x->nt && !tets))
        return lh__error_say(x->err, LH_ERR_INVALID_ARGUMENT, "%s is NULL with a count above 0",
                             x->n && !x->xyz ? "xyz" : "tets");
    if (x->n > (size_t)LH_INDEX_MAX || x->nt > (size_t)LH_INDEX_MAX / 4)
        return lh__error_say(x->err, LH_ERR_TOO_LARGE,
                             "more points or tetrahedra than an lh_index numbers");
    for (size_t i = 0; i < 3 * x->n; i++)
        if (!isfinite(x->xyz[i]))
            return lh__error_say(x->err, LH_ERR_INVALID_ARGUMENT,
                                 "point %zu has a NaN or infinite coordinate", i / 3);
    for (size_t i = 0; x->attr && i < x->nt; i++)
        if (!isfinite(x->attr[i]))
            return lh__error_say(x->err, LH_ERR_INVALID_ARGUMENT,
                                 "tetrahedron %zu has a NaN or infinite attribute", i);
    for (size_t i = 0; i < 4 * x->nt; i++)
        if (tets[i] < 0 || (size_t)tets[i] >= x->n)
            return lh__error_say(x->err, LH_ERR_INVALID_ARGUMENT,
                                 "tetrahedron %zu has point %lld, not one of the %zu points", i / 4,
                                 (long long)tets[i], x->n);
    return LH_OK;
}

/* The tets into x->tv, each turned positive (two corners swapped when negative);
 * a flat one is LH_ERR_INVALID_MESH. */
static lh_status orient_tets(from_mesh *x, const lh_index *tets)
{
    for (size_t t = 0; t < x->nt; t++) {
        lh_index *v = x->tv + 4 * t;
        memcpy(v, tets + 4 * t, 4 * sizeof *v);
        const double *p[4] = {pt(x, v[0]), pt(x, v[1]), pt(x, v[2]), pt(x, v[3])};
        const int o = lh_orient(x->pred, 3, p);
        if (o == 0)
            return lh__error_say(x->err, LH_ERR_INVALID_MESH,
                                 "tetrahedron %zu is flat (its corners are coplanar)", t);
        if (o < 0) {
            const lh_index s = v[2];
            v[2] = v[3], v[3] = s;
        }
    }
    return LH_OK;
}

/* Every tet's faces, sorted so that a face shared by two tets comes twice in a row. */
static lh_status sorted_faces(from_mesh *x)
{
    for (size_t t = 0; t < x->nt; t++)
        for (int o = 0; o < 4; o++) {
            face_rec *f = x->face + 4 * t + o;
            f->t = (lh_index)t;
            for (int i = 0, j = 0; i < 4; i++) {
                if (i == o) continue;
                int m = j++;
                for (; m > 0 && f->v[m - 1] > x->tv[4 * t + i]; m--) f->v[m] = f->v[m - 1];
                f->v[m] = x->tv[4 * t + i];
            }
        }
    lh_status st = LH_OK;
    for (int c = 2; c >= 0 && st == LH_OK; c--)
        st = lh__sort_by_index(x->al, x->face, 4 * x->nt, sizeof *x->face,
                               offsetof(face_rec, v) + (size_t)c * sizeof(lh_index), x->n);
    return st;
}

static lh_index root(lh_index *parent, lh_index t)
{
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
}

static int same_face(const face_rec *a, const face_rec *b)
{
    return a->v[0] == b->v[0] && a->v[1] == b->v[1] && a->v[2] == b->v[2];
}

static double attr_of(const from_mesh *x, lh_index t)
{
    return x->attr ? x->attr[t] : 0;
}

/* The facets (3 indices each) and their markers: the faces in one tet (1), those
 * between tets of different attributes (0); tets across the other faces joined into
 * one part. *count of them (facets NULL: only counted). */
static size_t facets(from_mesh *x, lh_index *tri, lh_index *marker)
{
    size_t count = 0;
    for (size_t i = 0; i < 4 * x->nt;) {
        const face_rec *f = x->face + i;
        const int pair = i + 1 < 4 * x->nt && same_face(f, f + 1);
        if (pair && attr_of(x, f[0].t) == attr_of(x, f[1].t)) {
            if (!tri) x->parent[root(x->parent, f[0].t)] = root(x->parent, f[1].t);
        } else {
            if (tri) memcpy(tri + 3 * count, f->v, 3 * sizeof *tri), marker[count] = pair ? 0 : 1;
            count++;
        }
        i += pair ? 2 : 1;
    }
    return count;
}

/* Tet t's centroid into c: 1 when, rounded, it lies strictly inside t. */
static int centroid_inside(const from_mesh *x, size_t t, double c[3])
{
    const lh_index *v = x->tv + 4 * t;
    for (int k = 0; k < 3; k++)
        c[k] = pt(x, v[0])[k] / 4 + pt(x, v[1])[k] / 4 + pt(x, v[2])[k] / 4 + pt(x, v[3])[k] / 4;
    for (int j = 0; j < 4; j++) { /* c in place of corner j: still positive */
        const double *p[4] = {pt(x, v[0]), pt(x, v[1]), pt(x, v[2]), pt(x, v[3])};
        p[j] = c;
        if (lh_orient(x->pred, 3, p) <= 0) return 0;
    }
    return 1;
}

/* Per part, the first tet whose centroid lies inside it: x->seed[root]; the parts'
 * count into *parts. */
static lh_status seeds(from_mesh *x, size_t *parts)
{
    double c[3];
    *parts = 0;
    for (size_t t = 0; t < x->nt; t++) x->seed[t] = -1;
    for (size_t t = 0; t < x->nt; t++) {
        const lh_index r = root(x->parent, (lh_index)t);
        if (r == (lh_index)t) ++*parts;
        if (x->seed[r] < 0 && centroid_inside(x, t, c)) x->seed[r] = (lh_index)t;
    }
    for (size_t t = 0; t < x->nt; t++)
        if (root(x->parent, (lh_index)t) == (lh_index)t && x->seed[t] < 0)
            return lh__error_say(
                x->err, LH_ERR_DEGENERATE,
                "the part of the mesh around tetrahedron %zu has no tetrahedron whose "
                "centroid rounds to a point inside it",
                t);
    return LH_OK;
}

/* g's arrays from x: the points, the facets, the region points. */
static lh_status fill(from_mesh *x, const lh_index *point_markers, size_t nf, size_t parts,
                      lh_plc *g)
{
    const lh_allocator *al = &g->alloc_;
    g->n = x->n, g->facet_count = g->polygon_count = nf, g->region_count = parts;
    g->xyz = lh__alloc(al, (3 * x->n + 1) * sizeof *g->xyz);
    g->point_marker = point_markers ? lh__alloc(al, (x->n + 1) * sizeof *g->point_marker) : NULL;
    g->facet_first = lh__alloc(al, (nf + 1) * sizeof *g->facet_first);
    g->polygon_first = lh__alloc(al, (nf + 1) * sizeof *g->polygon_first);
    g->polygon_vertices = lh__alloc(al, (3 * nf + 1) * sizeof *g->polygon_vertices);
    g->facet_marker = lh__alloc(al, (nf + 1) * sizeof *g->facet_marker);
    g->regions = lh__alloc(al, (5 * parts + 1) * sizeof *g->regions);
    if (!g->xyz || (point_markers && !g->point_marker) || !g->facet_first || !g->polygon_first ||
        !g->polygon_vertices || !g->facet_marker || !g->regions)
        return LH_ERR_NOMEM;
    if (x->n) memcpy(g->xyz, x->xyz, 3 * x->n * sizeof *g->xyz);
    if (point_markers && x->n)
        memcpy(g->point_marker, point_markers, x->n * sizeof *g->point_marker);
    facets(x, g->polygon_vertices, g->facet_marker);
    for (size_t f = 0; f <= nf; f++)
        g->facet_first[f] = (lh_index)f, g->polygon_first[f] = (lh_index)(3 * f);
    size_t r = 0;
    for (size_t t = 0; t < x->nt; t++) {
        if (root(x->parent, (lh_index)t) != (lh_index)t) continue;
        double *reg = g->regions + 5 * r++;
        centroid_inside(x, (size_t)x->seed[t], reg);
        reg[3] = attr_of(x, x->seed[t]), reg[4] = -1;
    }
    return LH_OK;
}

static lh_status build(from_mesh *x, const lh_index *tets, const lh_index *point_markers, lh_plc *g)
{
    lh_status st = check_args(x, tets);
    if (st != LH_OK) return st;
    x->tv = lh__alloc(x->al, (4 * x->nt + 1) * sizeof *x->tv);
    x->face = lh__alloc(x->al, (4 * x->nt + 1) * sizeof *x->face);
    x->parent = lh__alloc(x->al, (x->nt + 1) * sizeof *x->parent);
    x->seed = lh__alloc(x->al, (x->nt + 1) * sizeof *x->seed);
    if (!x->tv || !x->face || !x->parent || !x->seed) return LH_ERR_NOMEM;
    if ((st = lh_pred_create(x->al, &x->pred)) != LH_OK) return st;
    if ((st = orient_tets(x, tets)) != LH_OK) return st;
    st = lh_tetmesh_check(x->n, x->xyz, x->nt, x->tv, 0, NULL, NULL, 0, NULL, 1, NULL, NULL, x->al,
                          x->err);
    if (st != LH_OK) return st;
    if ((st = sorted_faces(x)) != LH_OK) return st;
    for (size_t t = 0; t < x->nt; t++) x->parent[t] = (lh_index)t;
    const size_t nf = facets(x, NULL, NULL);
    size_t parts;
    if ((st = seeds(x, &parts)) != LH_OK) return st;
    return fill(x, point_markers, nf, parts, g);
}

lh_status lh_plc_from_tetmesh(size_t n, const double *xyz, const lh_index *point_markers,
                              size_t tet_count, const lh_index *tets, const double *tet_attrs,
                              const lh_allocator *alloc, lh_plc *out, lh_error *err)
{
    lh__error_clear(err);
    if (!out)
        return lh__error_done(err, lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "out is NULL"));
    memset(out, 0, sizeof *out);
    if (!lh__allocator_init(&out->alloc_, alloc))
        return lh__error_done(
            err, lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "the allocator lacks alloc or free"));
    from_mesh x = {&out->alloc_, err, n, tet_count, xyz, tet_attrs, NULL, NULL, NULL, NULL, NULL};
    lh_status st = build(&x, tets, point_markers, out);
    void *scratch[] = {x.tv, x.face, x.parent, x.seed};
    for (size_t i = 0; i < sizeof scratch / sizeof scratch[0]; i++) lh__free(x.al, scratch[i]);
    lh_pred_free(x.pred);
    if (st == LH_ERR_NOMEM && !(err && err->message[0])) lh__error_say(err, st, "out of memory");
    if (st != LH_OK) lh_plc_free(out);
    return lh__error_done(err, st);
}
