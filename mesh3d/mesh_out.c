/*
 * mesh_out.c — the lh_tetmesh of the domain's tetrahedra: points (the PLC's, then the
 * Steiner points that are vertices), tetrahedra and neighbours renumbered, the walls
 * beside a kept tetrahedron as subfaces (and the hull's faces with convex_hull), the
 * PLC segments' chains as subsegments, and the statistics.
 */
#include "carve.h"

#include <string.h>

#define ARRAY(m, field, count, type) \
    lh__tetmesh_array((m), (void **)&(m)->field, (count), sizeof(type))

/* Point numbers: the PLC's keep theirs; the Steiner points of the tets kept follow
 * (an interior one that carving left outside the domain is dropped). */
static lh_status number_points(t3_ctx *c, const t3_domain *d, lh_tetmesh *m, lh_index *pmap)
{
    size_t w = c->n_input;
    for (size_t i = 0; i < c->n; i++) pmap[i] = i < c->n_input ? (lh_index)i : -1;
    for (size_t t = 0; t < c->tet_count; t++) /* the Steiner points kept: in a tet kept */
        for (int j = 0; d->label[t] != T3_OUT && j < 4; j++)
            if ((size_t)c->tv[4 * t + j] >= c->n_input) pmap[c->tv[4 * t + j]] = 0;
    for (size_t i = c->n_input; i < c->n; i++)
        if (pmap[i] == 0) pmap[i] = (lh_index)w++;
    m->n = w;
    lh_status st = ARRAY(m, xyz, 3 * w, double);
    if (st == LH_OK) st = ARRAY(m, point_marker, w, lh_index);
    if (st != LH_OK) return st;
    for (size_t i = 0; i < c->n; i++) {
        if (pmap[i] < 0) continue;
        memcpy(m->xyz + 3 * (size_t)pmap[i], c->xyz + 3 * i, 3 * sizeof(double));
        m->point_marker[pmap[i]] = i < c->n_input && c->g->point_marker ? c->g->point_marker[i] : 0;
    }
    for (size_t k = 0; k < c->node_count; k++) { /* a Steiner point: its segment's marker */
        lh_index p = c->node[k].p;
        if ((size_t)p >= c->n_input && pmap[p] >= 0 && m->point_marker[pmap[p]] == 0)
            m->point_marker[pmap[p]] = c->seg[c->node[k].seg].marker;
    }
    return LH_OK;
}

static lh_status write_tets(t3_ctx *c, const t3_domain *d, lh_tetmesh *m, const lh_index *pmap,
                            lh_index *tmap)
{
    size_t count = c->tet_count, w = 0;
    const lh_index *s = c->tv, *nbr = c->tn;
    for (size_t t = 0; t < count; t++) tmap[t] = d->label[t] == T3_OUT ? -1 : (lh_index)w++;
    m->tet_count = w;
    lh_status st = ARRAY(m, tets, 4 * w, lh_index);
    if (st == LH_OK) st = ARRAY(m, nbr, 4 * w, lh_index);
    if (st == LH_OK && c->opt->region_attributes) st = ARRAY(m, tet_attr, w, double);
    if (st != LH_OK) return st;
    for (size_t t = 0; t < count; t++) {
        lh_index o = tmap[t];
        if (o < 0) continue;
        for (int j = 0; j < 4; j++) {
            m->tets[4 * (size_t)o + j] = pmap[s[4 * t + j]];
            m->nbr[4 * (size_t)o + j] = nbr[4 * t + j] < 0 ? -1 : tmap[nbr[4 * t + j]];
        }
        if (m->tet_attr)
            m->tet_attr[o] = d->label[t] >= 0 ? c->g->regions[5 * (size_t)d->label[t] + 3] : 0;
    }
    return LH_OK;
}

/* Face j of kept tet t, ordered so that (a, b, c, apex) is positive: the tet's order
 * without corner j, two swapped when j is even (moving the apex last takes 3 - j
 * transpositions). */
static void put_face(lh_tetmesh *m, size_t f, const lh_index *tet, int j)
{
    lh_index v[3], w = 0;
    for (int k = 0; k < 4; k++)
        if (k != j) v[w++] = tet[k];
    if (j % 2 == 0) {
        lh_index x = v[1];
        v[1] = v[2];
        v[2] = x;
    }
    memcpy(m->faces + 3 * f, v, sizeof v);
}

/* Whether DT tet t's face j is a subface written from t: a wall, or with convex_hull
 * a hull face; written from the kept tet of smaller number. *facet: the wall's. */
static int face_here(const t3_ctx *c, const t3_domain *d, const lh_index *tmap, size_t t, int j,
                     lh_index *facet)
{
    lh_index u = c->tn[4 * t + j];
    if (u >= 0 && tmap[u] >= 0 && (size_t)u < t) return 0;
    *facet = lh__t3_wall_of(d, t, j);
    return *facet >= 0 || (u < 0 && (c->opt->convex_hull || c->g->facet_count == 0));
}

/* Subfaces, counted, then written. */
static lh_status write_faces(t3_ctx *c, const t3_domain *d, lh_tetmesh *m, const lh_index *tmap)
{
    size_t count = c->tet_count, f = 0;
    const lh_index *nbr = c->tn;
    lh_index facet;
    for (size_t t = 0; t < count; t++)
        for (int j = 0; tmap[t] >= 0 && j < 4; j++) f += face_here(c, d, tmap, t, j, &facet);
    m->face_count = f;
    lh_status st = ARRAY(m, faces, 3 * f, lh_index);
    if (st == LH_OK) st = ARRAY(m, face_marker, f, lh_index);
    if (st == LH_OK) st = ARRAY(m, face_parent, f, lh_index);
    if (st != LH_OK) return st;
    f = 0;
    for (size_t t = 0; t < count; t++)
        for (int j = 0; tmap[t] >= 0 && j < 4; j++) {
            if (!face_here(c, d, tmap, t, j, &facet)) continue;
            lh_index u = nbr[4 * t + j];
            int boundary = u < 0 || tmap[u] < 0;
            put_face(m, f, m->tets + 4 * (size_t)tmap[t], j);
            m->face_parent[f] = facet;
            m->face_marker[f] =
                facet >= 0 && c->g->facet_marker ? c->g->facet_marker[facet] : boundary;
            f++;
        }
    return LH_OK;
}

/* Whether the edge p q is in a kept tet. */
static int kept_edge(const t3_ctx *c, const t3_domain *d, lh_index p, lh_index q)
{
    const lh_index *s = c->tv;
    for (lh_index i = c->star_first[p]; i < c->star_first[p + 1]; i++) {
        const lh_index *t = s + 4 * (size_t)c->star[i];
        if ((t[0] == q || t[1] == q || t[2] == q || t[3] == q) && d->label[c->star[i]] != T3_OUT)
            return 1;
    }
    return 0;
}

/* Subsegments: the chains of the PLC's segments, edges of kept tets; two passes. */
static lh_status write_edges(t3_ctx *c, const t3_domain *d, lh_tetmesh *m, const lh_index *pmap)
{
    lh_status st = LH_OK;
    for (int pass = 0; pass < 2 && st == LH_OK; pass++) {
        size_t e = 0;
        for (size_t s = 0; s < c->seg_count && st == LH_OK; s++) {
            if (c->seg[s].parent < 0) continue;
            size_t cl = (size_t)(c->node_first[s + 1] - c->node_first[s]) + 2;
            if ((st = lh__t3_room(c, &c->vbuf, &c->vcap, cl)) != LH_OK) break;
            lh__t3_chain(c, (lh_index)s, c->vbuf, c->vcap);
            for (size_t i = 0; i + 1 < cl; i++) {
                if (!kept_edge(c, d, c->vbuf[i], c->vbuf[i + 1])) continue;
                if (pass) {
                    m->edges[2 * e] = pmap[c->vbuf[i]];
                    m->edges[2 * e + 1] = pmap[c->vbuf[i + 1]];
                    m->edge_marker[e] = c->seg[s].marker;
                    m->edge_parent[e] = c->seg[s].parent;
                }
                e++;
            }
        }
        if (pass == 0 && st == LH_OK) {
            m->edge_count = e;
            st = ARRAY(m, edges, 2 * e, lh_index);
            if (st == LH_OK) st = ARRAY(m, edge_marker, e, lh_index);
            if (st == LH_OK) st = ARRAY(m, edge_parent, e, lh_index);
        }
    }
    return st;
}

/* Steiner points by kind, and those not exactly on their segment's line; seen: one
 * byte per point, 1 for the points not kept, else 0. */
static void count_steiner(const t3_ctx *c, lh_tetmesh *m, unsigned char *seen)
{
    lh_tetmesh_stats *S = &m->stats;
    size_t kept = 0;
    for (size_t i = c->n_input; i < c->n; i++) kept += !seen[i];
    for (size_t k = 0; k < c->node_count; k++) {
        const t3_node *nd = c->node + k;
        if ((size_t)nd->p < c->n_input || seen[nd->p]) continue;
        seen[nd->p] = 1; /* a point on two chains counts once */
        const t3_seg *sg = c->seg + nd->seg;
        if (sg->parent >= 0)
            S->steiner_on_segments++;
        else
            S->steiner_on_facets++;
        if (!lh__t3_collinear(c->pred, c->xyz + 3 * (size_t)sg->a, c->xyz + 3 * (size_t)sg->b,
                              c->xyz + 3 * (size_t)nd->p))
            S->steiner_off_exact++;
    }
    for (size_t k = 0; k < c->pnode_count; k++) {
        const t3_node *nd = c->pnode + k;
        if (seen[nd->p]) continue;
        seen[nd->p] = 1;
        S->steiner_on_facets++;
        const lh_index *t = c->tri + 3 * (size_t)c->patch_tri[c->patch_first[nd->seg]];
        const double *p[4] = {c->xyz + 3 * (size_t)t[0], c->xyz + 3 * (size_t)t[1],
                              c->xyz + 3 * (size_t)t[2], c->xyz + 3 * (size_t)nd->p};
        S->steiner_off_exact += lh_orient(c->pred, 3, p) != 0;
    }
    S->steiner_points = kept;
    S->steiner_interior = kept - S->steiner_on_segments - S->steiner_on_facets;
}

lh_status lh__t3_output(t3_ctx *c, const t3_domain *d, lh_tetmesh *m)
{
    size_t count = c->tet_count;
    lh_index *pmap = lh__alloc(&c->al, (c->n + 1) * sizeof(lh_index));
    lh_index *tmap = lh__alloc(&c->al, (count + 1) * sizeof(lh_index));
    lh_status st = pmap && tmap ? LH_OK : LH_ERR_NOMEM;
    if (st == LH_OK) st = number_points(c, d, m, pmap);
    if (st == LH_OK) st = write_tets(c, d, m, pmap, tmap);
    if (st == LH_OK) st = write_faces(c, d, m, tmap);
    if (st == LH_OK) st = write_edges(c, d, m, pmap);
    if (st == LH_OK) {
        unsigned char *seen = lh__alloc(&c->al, c->n + 1);
        if (!seen) st = LH_ERR_NOMEM;
        for (size_t i = 0; seen && i < c->n; i++) seen[i] = pmap[i] < 0;
        if (seen) count_steiner(c, m, seen);
        lh__free(&c->al, seen);
        m->stats.input_points = c->n_input;
        m->stats.duplicates_merged = 0;
        for (size_t i = 0; i < c->n_input; i++)
            m->stats.duplicates_merged += c->dup[i] != (lh_index)i;
        m->stats.tets = m->tet_count;
        m->stats.faces = m->face_count;
        m->stats.edges = m->edge_count;
        m->stats.regions = c->g->region_count - d->regions_ignored;
        m->stats.holes_ignored = d->holes_ignored;
        m->stats.regions_ignored = d->regions_ignored;
    }
    lh__free(&c->al, pmap);
    lh__free(&c->al, tmap);
    if (st == LH_ERR_NOMEM) return lh__t3_say(c, st, 0, "out of memory");
    return st;
}
