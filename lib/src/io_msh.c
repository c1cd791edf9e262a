/* io_msh.c — Gmsh's MSH file format, version 4.1, ASCII (Gmsh reference manual, "MSH
 * file format"): $MeshFormat "4.1 0 8" (version, ASCII, sizeof(size_t)); $Entities
 * with one entity of dimension k, tag 1, holding every node and element, its bounding
 * box the points'; $Nodes and $Elements as one block each, tags 1..n and 1..count;
 * an optional $NodeData (one string tag, the name; one real tag, the time 0; three
 * integer tags: time step 0, 1 component, n values). Element types: 1 two-node line,
 * 2 three-node triangle, 4 four-node tetrahedron. */
#include "io_internal.h"

static const int element_type[4] = {0, 1, 2, 4}; /* by simplex dimension k */

static void bounding_box(const lh_mesh_view *m, double lo[3], double hi[3])
{
    for (int j = 0; j < 3; j++) lo[j] = hi[j] = 0;
    for (size_t i = 0; i < m->n; i++)
        for (int j = 0; j < m->d; j++) {
            double x = m->xyz[i * (size_t)m->d + j];
            if (i == 0 || x < lo[j]) lo[j] = x;
            if (i == 0 || x > hi[j]) hi[j] = x;
        }
}

static void entities(lh__out *o, const lh_mesh_view *m)
{
    double lo[3], hi[3];
    bounding_box(m, lo, hi);
    lh__outf(o, "$Entities\n%d %d %d %d\n", m->k == 0, m->k == 1, m->k == 2, m->k == 3);
    /* tag, box, no physical tags, no bounding entities */
    lh__outf(o, "1 %.17g %.17g %.17g %.17g %.17g %.17g 0 0\n", lo[0], lo[1], lo[2], hi[0],
             hi[1], hi[2]);
    lh__outf(o, "$EndEntities\n");
}

static void nodes(lh__out *o, const lh_mesh_view *m)
{
    lh__outf(o, "$Nodes\n1 %zu %d %zu\n%d 1 0 %zu\n", m->n, m->n ? 1 : 0, m->n, m->k, m->n);
    for (size_t i = 0; i < m->n; i++) lh__outf(o, "%zu\n", i + 1);
    for (size_t i = 0; i < m->n; i++) {
        lh__out_point3(o, m, i);
        lh__outf(o, "\n");
    }
    lh__outf(o, "$EndNodes\n");
}

static void elements(lh__out *o, const lh_mesh_view *m)
{
    size_t per = (size_t)m->k + 1;
    lh__outf(o, "$Elements\n1 %zu %d %zu\n%d 1 %d %zu\n", m->count, m->count ? 1 : 0,
             m->count, m->k, element_type[m->k], m->count);
    for (size_t i = 0; i < m->count; i++) {
        lh__outf(o, "%zu", i + 1);
        for (size_t j = 0; j < per; j++) lh__outf(o, " %" LH_INDEX_PRI, m->cells[i * per + j] + 1);
        lh__outf(o, "\n");
    }
    lh__outf(o, "$EndElements\n");
}

static void node_data(lh__out *o, const lh_mesh_view *m)
{
    if (!m->values) return;
    lh__outf(o, "$NodeData\n1\n\"%s\"\n1\n0\n3\n0\n1\n%zu\n",
             m->values_name ? m->values_name : "value", m->n);
    for (size_t i = 0; i < m->n; i++) lh__outf(o, "%zu %.17g\n", i + 1, m->values[i]);
    lh__outf(o, "$EndNodeData\n");
}

lh_status lh_msh_write(FILE *f, const lh_mesh_view *m)
{
    lh_status st = lh__view_check(f, m, 1, 3, 1, 3);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    lh__outf(&o, "$MeshFormat\n4.1 0 %zu\n$EndMeshFormat\n", sizeof(size_t));
    entities(&o, m);
    nodes(&o, m);
    elements(&o, m);
    node_data(&o, m);
    return lh__out_status(&o);
}
