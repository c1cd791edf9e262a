/* io_vtu.c — VTK's XML UnstructuredGrid file (.vtu), ASCII or binary ("VTK File
 * Formats", VTK User's Guide; "XML File Formats": VTKFile > UnstructuredGrid > Piece
 * with Points, Cells (connectivity, offsets, types) and optional PointData / CellData).
 * VTK points have 3 coordinates; cell types VTK_LINE 3, VTK_TRIANGLE 5, VTK_TETRA 10.
 *
 * Binary: each DataArray has format="binary", its values inline in base64 (RFC 4648),
 * as VTK's own writer does without compression: first the array's length in bytes as
 * a UInt64 (header_type="UInt64", which needs version="1.0"), encoded on its own, then
 * the values, encoded on their own, in this machine's byte order (byte_order says
 * which). The file stays well-formed XML. */
#include "io_internal.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

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

static const char *cell_values_name(const lh_vtu_options *opt)
{
    return opt->cell_values_name ? opt->cell_values_name : "cell_value";
}

static void cells(lh__out *o, const lh_mesh_view *m, const lh_vtu_options *opt)
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
    if (!m->neighbors && !opt->cell_values) return;
    lh__outf(o, "      <CellData>\n");
    if (m->neighbors) {
        lh__outf(o, "        <DataArray type=\"%s\" Name=\"neighbors\" NumberOfComponents=\"%zu\" "
                    "format=\"ascii\">\n", int_type(m->count), per);
        int_rows(o, m->neighbors, m->count, per);
        lh__outf(o, "        </DataArray>\n");
    }
    if (opt->cell_values) {
        lh__outf(o, "        <DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n",
                 cell_values_name(opt));
        for (size_t i = 0; i < m->count; i++) lh__outf(o, "          %.17g\n", opt->cell_values[i]);
        lh__outf(o, "        </DataArray>\n");
    }
    lh__outf(o, "      </CellData>\n");
}

static lh_status write_ascii(lh__out *o, const lh_mesh_view *m, const lh_vtu_options *opt)
{
    lh__outf(o, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                "  <UnstructuredGrid>\n"
                "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", m->n, m->count);
    point_data(o, m);
    lh__outf(o, "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                "format=\"ascii\">\n");
    for (size_t i = 0; i < m->n; i++) {
        lh__outf(o, "          ");
        lh__out_point3(o, m, i);
        lh__outf(o, "\n");
    }
    lh__outf(o, "        </DataArray>\n      </Points>\n");
    cells(o, m, opt);
    lh__outf(o, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return lh__out_status(o);
}

/* ---- binary ----------------------------------------------------------------------- */

/* A base64 encoder writing to o: whole groups of 3 bytes become 4 characters, the
 * last 1 or 2 bytes are padded with '=' by b64_end. */
typedef struct b64 {
    lh__out *o;
    unsigned char rest[3]; /* bytes waiting for a full group */
    int nrest;
    size_t len;
    char buf[4096];        /* encoded characters not yet written */
} b64;

static const char b64_alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

static void b64_flush(b64 *e)
{
    if (e->len && !e->o->failed && fwrite(e->buf, 1, e->len, e->o->f) != e->len) e->o->failed = 1;
    e->len = 0;
}

static void b64_group(b64 *e, const unsigned char *g, int n)
{
    if (e->len + 4 > sizeof e->buf) b64_flush(e);
    const unsigned v = (unsigned)g[0] << 16 | (n > 1 ? (unsigned)g[1] << 8 : 0) | (n > 2 ? g[2] : 0);
    char *c = e->buf + e->len;
    c[0] = b64_alphabet[v >> 18 & 63];
    c[1] = b64_alphabet[v >> 12 & 63];
    c[2] = n > 1 ? b64_alphabet[v >> 6 & 63] : '=';
    c[3] = n > 2 ? b64_alphabet[v & 63] : '=';
    e->len += 4;
}

static void b64_put(b64 *e, const void *data, size_t size)
{
    const unsigned char *p = data;
    while (size && e->nrest) { /* complete a waiting group first */
        e->rest[e->nrest++] = *p++;
        size--;
        if (e->nrest == 3) b64_group(e, e->rest, 3), e->nrest = 0;
    }
    for (; size >= 3; p += 3, size -= 3) b64_group(e, p, 3);
    while (size--) e->rest[e->nrest++] = *p++;
}

/* Ends one encoded block (padding the last group) and writes what is buffered. */
static void b64_end(b64 *e)
{
    if (e->nrest) b64_group(e, e->rest, e->nrest);
    e->nrest = 0;
    b64_flush(e);
}

/* Values converted a block at a time. */
enum { BLOCK = 512 };

static void put_indices(b64 *e, const lh_index *a, size_t count, int wide)
{
    int32_t i32[BLOCK];
    int64_t i64[BLOCK];
    for (size_t i = 0; i < count; i += BLOCK) {
        const size_t k = count - i < BLOCK ? count - i : BLOCK;
        for (size_t j = 0; j < k; j++) {
            if (wide) i64[j] = (int64_t)a[i + j];
            else i32[j] = (int32_t)a[i + j];
        }
        if (wide) b64_put(e, i64, k * sizeof *i64);
        else b64_put(e, i32, k * sizeof *i32);
    }
}

static void put_offsets(b64 *e, size_t count, size_t per, int wide)
{
    int32_t i32[BLOCK];
    int64_t i64[BLOCK];
    for (size_t i = 0; i < count; i += BLOCK) {
        const size_t k = count - i < BLOCK ? count - i : BLOCK;
        for (size_t j = 0; j < k; j++) {
            if (wide) i64[j] = (int64_t)((i + j + 1) * per);
            else i32[j] = (int32_t)((i + j + 1) * per);
        }
        if (wide) b64_put(e, i64, k * sizeof *i64);
        else b64_put(e, i32, k * sizeof *i32);
    }
}

static void put_types(b64 *e, size_t count, uint8_t type)
{
    uint8_t t[BLOCK];
    memset(t, type, sizeof t);
    for (size_t i = 0; i < count; i += BLOCK) b64_put(e, t, count - i < BLOCK ? count - i : BLOCK);
}

static void put_points(b64 *e, const lh_mesh_view *m)
{
    double p[3 * BLOCK];
    for (size_t i = 0; i < m->n; i += BLOCK) {
        const size_t k = m->n - i < BLOCK ? m->n - i : BLOCK;
        for (size_t j = 0; j < k; j++) {
            const double *q = m->xyz + (i + j) * (size_t)m->d;
            for (int c = 0; c < 3; c++) p[3 * j + (size_t)c] = c < m->d ? q[c] : 0.0;
        }
        b64_put(e, p, 3 * k * sizeof *p);
    }
}

/* Opens a DataArray and writes its header (the values' length in bytes). */
static void array_begin(b64 *e, const char *type, const char *name, size_t comps, uint64_t bytes)
{
    lh__outf(e->o, "        <DataArray type=\"%s\"", type);
    if (name) lh__outf(e->o, " Name=\"%s\"", name);
    if (comps > 1) lh__outf(e->o, " NumberOfComponents=\"%zu\"", comps);
    lh__outf(e->o, " format=\"binary\">\n          ");
    b64_put(e, &bytes, sizeof bytes);
    b64_end(e);
}

static void array_end(b64 *e)
{
    b64_end(e);
    lh__outf(e->o, "\n        </DataArray>\n");
}

static int is_little_endian(void)
{
    const uint16_t one = 1;
    unsigned char b;
    memcpy(&b, &one, 1);
    return b == 1;
}

static void binary_cells(b64 *e, const lh_mesh_view *m)
{
    const size_t per = (size_t)m->k + 1, total = m->count * per;
    const int wide = m->n > INT32_MAX, wide_off = total > INT32_MAX;
    lh__outf(e->o, "      <Cells>\n");
    array_begin(e, int_type(m->n), "connectivity", 1, (uint64_t)total * (wide ? 8 : 4));
    put_indices(e, m->cells, total, wide);
    array_end(e);
    array_begin(e, int_type(total), "offsets", 1, (uint64_t)m->count * (wide_off ? 8 : 4));
    put_offsets(e, m->count, per, wide_off);
    array_end(e);
    array_begin(e, "UInt8", "types", 1, m->count);
    put_types(e, m->count, (uint8_t)cell_type[m->k]);
    array_end(e);
    lh__outf(e->o, "      </Cells>\n");
}

static void binary_cell_data(b64 *e, const lh_mesh_view *m, const lh_vtu_options *opt)
{
    const size_t per = (size_t)m->k + 1;
    if (!m->neighbors && !opt->cell_values) return;
    lh__outf(e->o, "      <CellData>\n");
    if (m->neighbors) {
        const int wide = m->count > INT32_MAX;
        array_begin(e, int_type(m->count), "neighbors", per, (uint64_t)m->count * per * (wide ? 8 : 4));
        put_indices(e, m->neighbors, m->count * per, wide);
        array_end(e);
    }
    if (opt->cell_values) {
        array_begin(e, "Float64", cell_values_name(opt), 1, (uint64_t)m->count * 8);
        b64_put(e, opt->cell_values, m->count * sizeof(double));
        array_end(e);
    }
    lh__outf(e->o, "      </CellData>\n");
}

static lh_status write_binary(lh__out *o, const lh_mesh_view *m, const lh_vtu_options *opt)
{
    b64 enc, *e = &enc;
    e->o = o;
    e->nrest = 0;
    e->len = 0;
    lh__outf(o, "<?xml version=\"1.0\"?>\n"
                "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\" "
                "header_type=\"UInt64\">\n"
                "  <UnstructuredGrid>\n"
                "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n",
             is_little_endian() ? "LittleEndian" : "BigEndian", m->n, m->count);
    if (m->values) {
        const char *name = m->values_name ? m->values_name : "value";
        lh__outf(o, "      <PointData Scalars=\"%s\">\n", name);
        array_begin(e, "Float64", name, 1, (uint64_t)m->n * 8);
        b64_put(e, m->values, m->n * sizeof(double));
        array_end(e);
        lh__outf(o, "      </PointData>\n");
    }
    lh__outf(o, "      <Points>\n");
    array_begin(e, "Float64", NULL, 3, (uint64_t)m->n * 24);
    put_points(e, m);
    array_end(e);
    lh__outf(o, "      </Points>\n");
    binary_cells(e, m);
    binary_cell_data(e, m, opt);
    lh__outf(o, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return lh__out_status(o);
}

static lh_status check_cell_values(const lh_mesh_view *m, const lh_vtu_options *opt)
{
    if (opt->cell_values_name && !lh__field_name_ok(opt->cell_values_name)) return LH_ERR_INVALID_ARGUMENT;
    for (size_t i = 0; opt->cell_values && i < m->count; i++)
        if (!isfinite(opt->cell_values[i])) return LH_ERR_NONFINITE;
    return LH_OK;
}

lh_status lh_vtu_write(FILE *f, const lh_mesh_view *m, const lh_vtu_options *opt)
{
    const lh_vtu_options none = {0, NULL, NULL};
    if (!opt) opt = &none;
    lh_status st = lh__view_check(f, m, 1, 3, 1, 3);
    if (st == LH_OK) st = check_cell_values(m, opt);
    if (st != LH_OK) return st;
    lh__out o = {f, 0};
    return opt->ascii ? write_ascii(&o, m, opt) : write_binary(&o, m, opt);
}
