/* io_tetgen.c — the files of a tetrahedral mesh as TetGen and its viewers read them:
 * .node with markers, .ele with a region attribute, .face and .edge with markers
 * (Si, TetGen 1.5 user's manual, section 5.2: a header line of counts, then one
 * numbered line per item, its optional columns announced by the header); legacy VTK
 * ASCII unstructured grids (VTK User's Guide, "VTK File Formats", legacy format:
 * DATASET UNSTRUCTURED_GRID, POINTS, CELLS, CELL_TYPES, POINT_DATA/CELL_DATA
 * SCALARS), laid out as TetGen's -k writes them; Medit .mesh (Frey, "MEDIT: an
 * interactive mesh visualization software", INRIA RT-0253, 2001: keyword sections
 * Vertices, Edges, Triangles, Tetrahedra, each item followed by its integer
 * reference). */
#include "io_internal.h"

#include <math.h>

/* The optional columns checked: finite attributes. */
static lh_status finite_all(const double *a, size_t count)
{
    for (size_t i = 0; a && i < count; i++)
        if (!isfinite(a[i])) return LH_ERR_NONFINITE;
    return LH_OK;
}

/* count rows "i v_0..v_k [attr] [marker]", points numbered from first_index. */
static void cell_rows(lh__out *o, const lh_mesh_view *m, const double *attr, const lh_index *marker,
                      int first_index)
{
    const size_t per = (size_t)m->k + 1;
    lh__row r = {.len = 0};
    for (size_t i = 0; i < m->count; i++) {
        lh__row_int(o, &r, (long long)(i + (size_t)first_index));
        for (size_t j = 0; j < per; j++)
            lh__row_int(o, &r, (long long)m->cells[i * per + j] + first_index);
        if (attr) lh__row_dbl(o, &r, attr[i]);
        if (marker) lh__row_int(o, &r, (long long)marker[i]);
        lh__row_end(o, &r);
    }
}

static lh_status cells_check(FILE *f, const lh_mesh_view *m, int k, int first_index)
{
    lh_status st = lh__view_check(f, m, 1, LH_DELAUNAY_MAX_DIM, k ? k : 1, k ? k : LH_DELAUNAY_MAX_DIM);
    if (st == LH_OK && first_index != 0 && first_index != 1) st = LH_ERR_INVALID_ARGUMENT;
    return st;
}

lh_status lh_node_marker_write(FILE *f, const lh_mesh_view *m, const lh_index *markers, int first_index)
{
    lh_status st = lh__view_check(f, m, LH_DELAUNAY_MIN_DIM, LH_DELAUNAY_MAX_DIM, 0, 8);
    if (st != LH_OK) return st;
    if (first_index != 0 && first_index != 1) return LH_ERR_INVALID_ARGUMENT;
    lh__out o = {f, 0};
    lh__outf(&o, "%zu %d %d %d\n", m->n, m->d, m->values ? 1 : 0, markers ? 1 : 0);
    lh__row r = {.len = 0};
    for (size_t i = 0; i < m->n; i++) {
        lh__row_int(&o, &r, (long long)(i + (size_t)first_index));
        for (int j = 0; j < m->d; j++) lh__row_dbl(&o, &r, m->xyz[i * (size_t)m->d + j]);
        if (m->values) lh__row_dbl(&o, &r, m->values[i]);
        if (markers) lh__row_int(&o, &r, (long long)markers[i]);
        lh__row_end(&o, &r);
    }
    return lh__out_status(&o);
}

lh_status lh_ele_attr_write(FILE *f, const lh_mesh_view *m, const double *attrs, int first_index)
{
    lh_status st = cells_check(f, m, 0, first_index);
    if (st == LH_OK) st = finite_all(attrs, m->count);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    lh__outf(&o, "%zu %d %d\n", m->count, m->k + 1, attrs ? 1 : 0);
    cell_rows(&o, m, attrs, NULL, first_index);
    return lh__out_status(&o);
}

/* .face and .edge: "count 1" with a marker column, "count 0" without. */
static lh_status marked_write(FILE *f, const lh_mesh_view *m, int k, const lh_index *markers, int first_index)
{
    lh_status st = cells_check(f, m, k, first_index);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    lh__outf(&o, "%zu %d\n", m->count, markers ? 1 : 0);
    cell_rows(&o, m, NULL, markers, first_index);
    return lh__out_status(&o);
}

lh_status lh_face_write(FILE *f, const lh_mesh_view *m, const lh_index *markers, int first_index)
{
    return marked_write(f, m, 2, markers, first_index);
}

lh_status lh_edge_write(FILE *f, const lh_mesh_view *m, const lh_index *markers, int first_index)
{
    return marked_write(f, m, 1, markers, first_index);
}

/* Whether every value is a whole number an int holds: then VTK's "int" type. */
static int all_int(const double *v, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (!(v[i] == floor(v[i]) && fabs(v[i]) <= 2147483647.0)) return 0;
    return 1;
}

static void vtk_scalars(lh__out *o, const char *name, const double *v, size_t count)
{
    const int ints = all_int(v, count);
    lh__outf(o, "SCALARS %s %s 1\nLOOKUP_TABLE default\n", name, ints ? "int" : "double");
    for (size_t i = 0; i < count; i++) lh__outf(o, ints ? "%.0f\n" : "%.17g\n", v[i]);
}

lh_status lh_vtk_write(FILE *f, const lh_mesh_view *m, const double *cell_values, const char *cell_values_name)
{
    static const int cell_type[4] = {0, 3, 5, 10}; /* VTK_LINE, VTK_TRIANGLE, VTK_TETRA */
    lh_status st = lh__view_check(f, m, 1, 3, 1, 3);
    if (st == LH_OK) st = finite_all(cell_values, m->count);
    if (st == LH_OK && cell_values_name && !lh__field_name_ok(cell_values_name)) st = LH_ERR_INVALID_ARGUMENT;
    if (st != LH_OK) return st;
    const size_t per = (size_t)m->k + 1;
    lh__out o = {f, 0};
    lh__outf(&o, "# vtk DataFile Version 2.0\nUnstructured Grid\nASCII\nDATASET UNSTRUCTURED_GRID\n");
    lh__outf(&o, "POINTS %zu double\n", m->n);
    for (size_t i = 0; i < m->n; i++) {
        lh__out_point3(&o, m, i);
        lh__outf(&o, "\n");
    }
    lh__outf(&o, "\nCELLS %zu %zu\n", m->count, m->count * (per + 1));
    for (size_t i = 0; i < m->count; i++) {
        lh__outf(&o, "%zu ", per);
        for (size_t j = 0; j < per; j++) lh__outf(&o, " %4" LH_INDEX_PRI, m->cells[i * per + j]);
        lh__outf(&o, "\n");
    }
    lh__outf(&o, "\nCELL_TYPES %zu\n", m->count);
    for (size_t i = 0; i < m->count; i++) lh__outf(&o, "%d\n", cell_type[m->k]);
    if (m->values) {
        lh__outf(&o, "\nPOINT_DATA %zu\n", m->n);
        vtk_scalars(&o, m->values_name ? m->values_name : "value", m->values, m->n);
    }
    if (cell_values) {
        lh__outf(&o, "\nCELL_DATA %zu\n", m->count);
        vtk_scalars(&o, cell_values_name ? cell_values_name : "cell_scalars", cell_values, m->count);
    }
    return lh__out_status(&o);
}

/* One Medit section: the keyword, the count, then per item its vertices (numbered
 * from 1) and its reference (0 without refs). */
static void medit_section(lh__out *o, const char *keyword, size_t count, size_t per, const lh_index *v,
                          const lh_index *refs)
{
    if (!count) return;
    lh__outf(o, "%s\n%zu\n", keyword, count);
    for (size_t i = 0; i < count; i++) {
        for (size_t j = 0; j < per; j++) lh__outf(o, "%" LH_INDEX_PRI " ", v[i * per + j] + 1);
        lh__outf(o, "%" LH_INDEX_PRI "\n", refs ? refs[i] : 0);
    }
}

lh_status lh_medit_write(FILE *f, const lh_mesh_view *m, const lh_medit_refs *refs)
{
    static const char *const keyword[4] = {NULL, "Edges", "Triangles", "Tetrahedra"};
    lh_status st = lh__view_check(f, m, 2, 3, 1, 3);
    if (st != LH_OK) return st;
    const lh_medit_refs none = {NULL, NULL, 0, NULL, NULL};
    if (!refs) refs = &none;
    if (refs->face_count && (!refs->faces || m->k < 2)) return LH_ERR_INVALID_ARGUMENT;
    for (size_t i = 0; i < refs->face_count * (size_t)m->k; i++)
        if (refs->faces[i] < 0 || (size_t)refs->faces[i] >= m->n) return LH_ERR_INVALID_ARGUMENT;
    lh__out o = {f, 0};
    lh__outf(&o, "MeshVersionFormatted 1\n\nDimension %d\n\nVertices\n%zu\n", m->d, m->n);
    for (size_t i = 0; i < m->n; i++) {
        for (int j = 0; j < m->d; j++) lh__outf(&o, "%.17g ", m->xyz[i * (size_t)m->d + j]);
        lh__outf(&o, "%" LH_INDEX_PRI "\n", refs->point_refs ? refs->point_refs[i] : 0);
    }
    if (refs->face_count) medit_section(&o, keyword[m->k - 1], refs->face_count, (size_t)m->k, refs->faces,
                                        refs->face_refs);
    medit_section(&o, keyword[m->k], m->count, (size_t)m->k + 1, m->cells, refs->cell_refs);
    lh__outf(&o, "\nEnd\n");
    return lh__out_status(&o);
}
