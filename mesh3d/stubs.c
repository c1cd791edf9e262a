/* stubs.c — placeholders for mesh3d entry points being written (each moves to its
 * own file). */
#include "t3.h"

lh_status lh_tetmesh_check(size_t n, const double *xyz, size_t tet_count, const lh_index *tets,
                           size_t face_count, const lh_index *faces, const lh_index *face_parents,
                           size_t edge_count, const lh_index *edges, int boundary_free,
                           const lh_plc *g, size_t *off_exact, const lh_allocator *alloc,
                           lh_error *err)
{
    (void)n; (void)xyz; (void)tet_count; (void)tets; (void)face_count; (void)faces;
    (void)face_parents; (void)edge_count; (void)edges; (void)boundary_free; (void)g;
    (void)alloc;
    if (off_exact) *off_exact = 0;
    return lh__error_say(err, LH_ERR_INVALID_ARGUMENT, "lh_tetmesh_check: not written yet");
}
