/* io_off.c — the OFF format (Geomview's "Object File Format", as in OOGL's OFF(5)):
 * "OFF", then "vertices faces edges" (edges 0: readers ignore it), the vertices as
 * x y z, then each face as its vertex count and 0-based vertex indices. Written for
 * triangles: a 2D triangulation (z = 0) or a triangulated surface in 3D. */
#include "io_internal.h"

lh_status lh_off_write(FILE *f, const lh_mesh_view *m)
{
    lh_status st = lh__view_check(f, m, 2, 3, 2, 2);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    lh__outf(&o, "OFF\n%zu %zu 0\n", m->n, m->count);
    for (size_t i = 0; i < m->n; i++) {
        lh__out_point3(&o, m, i);
        lh__outf(&o, "\n");
    }
    for (size_t i = 0; i < m->count; i++)
        lh__outf(&o, "3 %" LH_INDEX_PRI " %" LH_INDEX_PRI " %" LH_INDEX_PRI "\n", m->cells[3 * i],
                 m->cells[3 * i + 1], m->cells[3 * i + 2]);
    return lh__out_status(&o);
}
