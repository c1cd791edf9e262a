/* io_triangle.c — Triangle's and TetGen's .node, .ele and .neigh files (Shewchuk,
 * Triangle's documentation, ".node", ".ele", ".neigh files"; Si, TetGen 1.5 manual,
 * section 5.2): a header line of counts, then one numbered line per item. Points are
 * numbered from first_index in all three files; the j-th neighbour of an element is
 * opposite its j-th corner and -1 means none (Triangle writes -1 whatever the first
 * index). Generalised to any d and k: lifthull's own use of the formats. */
#include "io_internal.h"

lh_status lh_node_write(FILE *f, const lh_mesh_view *m, int first_index)
{
    lh_status st = lh__view_check(f, m, LH_DELAUNAY_MIN_DIM, LH_DELAUNAY_MAX_DIM, 0, 8);
    if (st != LH_OK) return st;
    if (first_index != 0 && first_index != 1) return LH_ERR_INVALID_ARGUMENT;
    lh__out o = {f, 0};
    lh__outf(&o, "%zu %d %d 0\n", m->n, m->d, m->values ? 1 : 0);
    for (size_t i = 0; i < m->n; i++) {
        lh__outf(&o, "%zu", i + (size_t)first_index);
        for (int j = 0; j < m->d; j++) lh__outf(&o, " %.17g", m->xyz[i * (size_t)m->d + j]);
        if (m->values) lh__outf(&o, " %.17g", m->values[i]);
        lh__outf(&o, "\n");
    }
    return lh__out_status(&o);
}

/* count rows of k+1 entries from a, each shifted by `add` except -1 (none). */
static lh_status rows(FILE *f, const lh_mesh_view *m, const lh_index *a, int first_index, int header_zero)
{
    size_t per = (size_t)m->k + 1;
    lh__out o = {f, 0};
    if (header_zero) lh__outf(&o, "%zu %zu 0\n", m->count, per);
    else lh__outf(&o, "%zu %zu\n", m->count, per);
    for (size_t i = 0; i < m->count; i++) {
        lh__outf(&o, "%zu", i + (size_t)first_index);
        for (size_t j = 0; j < per; j++) {
            lh_index v = a[i * per + j];
            lh__outf(&o, " %" LH_INDEX_PRI, v < 0 ? v : v + first_index);
        }
        lh__outf(&o, "\n");
    }
    return lh__out_status(&o);
}

lh_status lh_ele_write(FILE *f, const lh_mesh_view *m, int first_index)
{
    lh_status st = lh__view_check(f, m, 1, LH_DELAUNAY_MAX_DIM, 1, LH_DELAUNAY_MAX_DIM);
    if (st != LH_OK) return st;
    if (first_index != 0 && first_index != 1) return LH_ERR_INVALID_ARGUMENT;
    return rows(f, m, m->cells, first_index, 1);
}

lh_status lh_neigh_write(FILE *f, const lh_mesh_view *m, int first_index)
{
    lh_status st = lh__view_check(f, m, 1, LH_DELAUNAY_MAX_DIM, 1, LH_DELAUNAY_MAX_DIM);
    if (st != LH_OK) return st;
    if (first_index != 0 && first_index != 1) return LH_ERR_INVALID_ARGUMENT;
    if (m->count && !m->neighbors) return LH_ERR_INVALID_ARGUMENT;
    return rows(f, m, m->neighbors, first_index, 0);
}
