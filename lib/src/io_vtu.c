/* io_vtu.c — VTK's XML UnstructuredGrid file (.vtu), ASCII ("VTK File Formats", VTK
 * User's Guide; "XML File Formats": VTKFile > UnstructuredGrid > Piece with Points,
 * Cells (connectivity, offsets, types) and optional PointData / CellData). VTK points
 * have 3 coordinates; cell types VTK_LINE 3, VTK_TRIANGLE 5, VTK_TETRA 10. */
#include "io_internal.h"

static const int cell_type[4] = {0, 3, 5, 10}; /* by simplex dimension k */

/* VTK's integer type for values up to max (above INT32_MAX only in the 64-bit index
 * build). */
static const char *int_type(size_t max) { return max > INT32_MAX ? "Int64" : "Int32"; }

/* `count` rows of `per` indices from a, one row a line. */
static void int_rows(lh__out *o, const lh_index *a, size_t count, size_t per)
{
    for (size_t i = 0; i < count; i++) {
        lh__outf(o, "         ");
        for (size_t j = 0; j < per; j++) lh__outf(o, " %" LH_INDEX_PRI, a[i * per + j]);
        lh__outf(o, "\n");
    }
}

static void point_data(lh__out *o, const lh_mesh_view *m)
{
    const char *name = m->values_name ? m->values_name : "value";
    if (!m->values) return;
    lh__outf(o, "      <PointData Scalars=\"%s\">\n", name);
    lh__outf(o, "        <DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", name);
    for (size_t i = 0; i < m->n; i++) lh__outf(o, "          %.17g\n", m->values[i]);
    lh__outf(o, "        </DataArray>\n      </PointData>\n");
}

static void cells(lh__out *o, const lh_mesh_view *m)
{
    size_t per = (size_t)m->k + 1;
    lh__outf(o, "      <Cells>\n"
                "        <DataArray type=\"%s\" Name=\"connectivity\" format=\"ascii\">\n",
             int_type(m->n));
    int_rows(o, m->cells, m->count, per);
    lh__outf(o, "        </DataArray>\n"
                "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (size_t i = 0; i < m->count; i++) lh__outf(o, "          %zu\n", (i + 1) * per);
    lh__outf(o, "        </DataArray>\n"
                "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (size_t i = 0; i < m->count; i++) lh__outf(o, "          %d\n", cell_type[m->k]);
    lh__outf(o, "        </DataArray>\n      </Cells>\n");
    if (!m->neighbors) return;
    lh__outf(o, "      <CellData>\n        <DataArray type=\"%s\" Name=\"neighbors\" "
                "NumberOfComponents=\"%zu\" format=\"ascii\">\n", int_type(m->count), per);
    int_rows(o, m->neighbors, m->count, per);
    lh__outf(o, "        </DataArray>\n      </CellData>\n");
}

lh_status lh_write_vtu(FILE *f, const lh_mesh_view *m)
{
    lh_status st = lh__view_check(f, m, 1, 3, 1, 3);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    lh__outf(&o, "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", m->n, m->count);
    point_data(&o, m);
    lh__outf(&o, "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                 "format=\"ascii\">\n");
    for (size_t i = 0; i < m->n; i++) {
        lh__outf(&o, "          ");
        lh__out_point3(&o, m, i);
        lh__outf(&o, "\n");
    }
    lh__outf(&o, "        </DataArray>\n      </Points>\n");
    cells(&o, m);
    lh__outf(&o, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return lh__out_status(&o);
}
