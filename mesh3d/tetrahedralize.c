/*
 * tetrahedralize.c — lh_tetrahedralize: the pipeline (docs/meshing3d.md).
 * For now: the Delaunay tetrahedralization of the PLC's points, its hull faces as the
 * subfaces (boundary recovery lands next).
 */
#include "t3.h"

#include <string.h>

static lh_status copy_points(lh_tetmesh *m, const lh_plc *g)
{
    lh_status st;
    m->n = g->n;
    if ((st = lh__tetmesh_array(m, (void **)&m->xyz, 3 * g->n, sizeof(double)))) return st;
    if ((st = lh__tetmesh_array(m, (void **)&m->point_marker, g->n, sizeof(lh_index)))) return st;
    memcpy(m->xyz, g->xyz, 3 * g->n * sizeof(double));
    for (size_t i = 0; i < g->n; i++) m->point_marker[i] = g->point_marker ? g->point_marker[i] : 0;
    return LH_OK;
}

static lh_status copy_tets(lh_tetmesh *m, const lh_tri *t)
{
    lh_status st;
    size_t c = lh_tri_count(t), h = lh_tri_hull_count(t);
    const lh_index *hull = lh_tri_hull_facets(t);
    m->tet_count = c;
    if ((st = lh__tetmesh_array(m, (void **)&m->tets, 4 * c, sizeof(lh_index)))) return st;
    if ((st = lh__tetmesh_array(m, (void **)&m->nbr, 4 * c, sizeof(lh_index)))) return st;
    memcpy(m->tets, lh_tri_simplices(t), 4 * c * sizeof(lh_index));
    memcpy(m->nbr, lh_tri_neighbors(t), 4 * c * sizeof(lh_index));
    m->face_count = h;
    if ((st = lh__tetmesh_array(m, (void **)&m->faces, 3 * h, sizeof(lh_index)))) return st;
    if ((st = lh__tetmesh_array(m, (void **)&m->face_marker, h, sizeof(lh_index)))) return st;
    if ((st = lh__tetmesh_array(m, (void **)&m->face_parent, h, sizeof(lh_index)))) return st;
    for (size_t i = 0; i < h; i++) { /* outward hull facets, reversed: normals point in */
        m->faces[3 * i] = hull[3 * i];
        m->faces[3 * i + 1] = hull[3 * i + 2];
        m->faces[3 * i + 2] = hull[3 * i + 1];
        m->face_marker[i] = 1;
        m->face_parent[i] = -1;
    }
    return LH_OK;
}

lh_status lh_tetrahedralize(const lh_plc *g, const lh_tetmesh_options *opt, lh_tetmesh **out,
                            lh_error *err)
{
    lh__error_clear(err);
    if (out) *out = NULL;
    lh_tetmesh_options defaults;
    lh_tetmesh_options_default(&defaults);
    if (!opt) opt = &defaults;
    lh_allocator al;
    if (!g || !out || !lh__allocator_init(&al, opt->alloc) || (g->n && !g->xyz))
        return lh__error_done(err, LH_ERR_INVALID_ARGUMENT);
    lh_options dopt;
    lh_options_default(&dopt);
    dopt.alloc = opt->alloc;
    dopt.threads = opt->threads;
    lh_tri *t = NULL;
    lh_status st = lh_delaunay(3, g->n, g->xyz, &dopt, &t);
    if (st != LH_OK) return lh__error_done(err, st);
    lh_tetmesh *m = lh__tetmesh_new(&al);
    if (!m) st = LH_ERR_NOMEM;
    if (st == LH_OK) st = copy_points(m, g);
    if (st == LH_OK) st = copy_tets(m, t);
    if (st == LH_OK) {
        m->stats.input_points = g->n;
        m->stats.duplicates_merged = lh_tri_duplicate_count(t);
        m->stats.tets = m->tet_count;
        m->stats.faces = m->face_count;
    }
    lh_tri_free(t);
    if (st != LH_OK) {
        lh_tetmesh_free(m);
        return lh__error_done(err, st);
    }
    *out = m;
    return lh__error_done(err, LH_OK);
}
