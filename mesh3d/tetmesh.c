/*
 * tetmesh.c — the lh_tetmesh handle: creation, getters, release, options' defaults.
 */
#include "t3.h"

#include <stdint.h>
#include <string.h>

void lh_tetmesh_options_default(lh_tetmesh_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    opt->boundary_steiner = 1;
    opt->max_steiner = SIZE_MAX;
    opt->check_intersections = 1;
    opt->threads = 1;
    opt->optimize_passes = 3;
}

lh_tetmesh *lh__tetmesh_new(const lh_allocator *al)
{
    lh_tetmesh *m = lh__alloc(al, sizeof *m);
    if (!m) return NULL;
    memset(m, 0, sizeof *m);
    m->alloc = *al;
    return m;
}

lh_status lh__tetmesh_array(lh_tetmesh *m, void **arr, size_t count, size_t size)
{
    *arr = NULL;
    if (count == 0) return LH_OK;
    if (count > SIZE_MAX / size) return LH_ERR_TOO_LARGE;
    *arr = lh__alloc(&m->alloc, count * size);
    return *arr ? LH_OK : LH_ERR_NOMEM;
}

void lh_tetmesh_free(lh_tetmesh *m)
{
    if (!m) return;
    void *arrays[] = {m->xyz,      m->point_marker, m->tets,        m->nbr,
                      m->tet_attr, m->faces,        m->face_marker, m->face_parent,
                      m->edges,    m->edge_marker,  m->edge_parent, m->tet_mid,
                      m->mid_edges, m->left};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) lh__free(&m->alloc, arrays[i]);
    lh_allocator al = m->alloc;
    lh__free(&al, m);
}

size_t lh_tetmesh_point_count(const lh_tetmesh *m)
{
    return m ? m->n : 0;
}
const double *lh_tetmesh_points(const lh_tetmesh *m)
{
    return m ? m->xyz : NULL;
}
const lh_index *lh_tetmesh_point_markers(const lh_tetmesh *m)
{
    return m ? m->point_marker : NULL;
}
size_t lh_tetmesh_tet_count(const lh_tetmesh *m)
{
    return m ? m->tet_count : 0;
}
const lh_index *lh_tetmesh_tets(const lh_tetmesh *m)
{
    return m ? m->tets : NULL;
}
const lh_index *lh_tetmesh_neighbors(const lh_tetmesh *m)
{
    return m ? m->nbr : NULL;
}
const double *lh_tetmesh_tet_attrs(const lh_tetmesh *m)
{
    return m ? m->tet_attr : NULL;
}
size_t lh_tetmesh_face_count(const lh_tetmesh *m)
{
    return m ? m->face_count : 0;
}
const lh_index *lh_tetmesh_faces(const lh_tetmesh *m)
{
    return m ? m->faces : NULL;
}
const lh_index *lh_tetmesh_face_markers(const lh_tetmesh *m)
{
    return m ? m->face_marker : NULL;
}
const lh_index *lh_tetmesh_face_parents(const lh_tetmesh *m)
{
    return m ? m->face_parent : NULL;
}
size_t lh_tetmesh_edge_count(const lh_tetmesh *m)
{
    return m ? m->edge_count : 0;
}
const lh_index *lh_tetmesh_edges(const lh_tetmesh *m)
{
    return m ? m->edges : NULL;
}
const lh_index *lh_tetmesh_edge_markers(const lh_tetmesh *m)
{
    return m ? m->edge_marker : NULL;
}
const lh_index *lh_tetmesh_edge_parents(const lh_tetmesh *m)
{
    return m ? m->edge_parent : NULL;
}

void lh_tetmesh_stats_get(const lh_tetmesh *m, lh_tetmesh_stats *out)
{
    if (!out) return;
    if (m)
        *out = m->stats;
    else
        memset(out, 0, sizeof *out);
}
