/* test_io_write.c — the mesh writers: the exact text of each format for a small mesh,
 * every argument error (and nothing written then), write errors, and a bit-exact round
 * trip .node -> lh_points_read. (tests/io/meshio_check.sh reads the files with meshio.) */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *self_path; /* argv[0]: a file that exists, opened read-only below */

/* Two triangles of a square-ish quad, with neighbours and a point field. */
static const double quad_xyz[] = {0, 0, 1, 0, 0, 1, 1, 1.5};
static const lh_index quad_cells[] = {0, 1, 2, 1, 3, 2};
static const lh_index quad_nbrs[] = {1, -1, -1, -1, 0, -1};
static const double quad_values[] = {0, 0.5, 1, 0.1};

static lh_mesh_view quad(void)
{
    lh_mesh_view m = {2, 4, quad_xyz, 2, 2, quad_cells, quad_nbrs, quad_values, "f"};
    return m;
}

typedef lh_status (*writer)(FILE *, const lh_mesh_view *);

/* The ASCII .vtu (lh_vtu_write with ascii set). */
static lh_status vtu_ascii(FILE *f, const lh_mesh_view *m)
{
    const lh_vtu_options o = {1, NULL, NULL};
    return lh_vtu_write(f, m, &o);
}

/* Runs a writer into a temporary file; *text receives what it wrote (caller frees). */
static lh_status capture(writer w, lh_status (*wi)(FILE *, const lh_mesh_view *, int), int first,
                         const lh_mesh_view *m, char **text)
{
    FILE *f = tmpfile();
    *text = NULL;
    if (!f) return LH_ERR_IO;
    lh_status st = w ? w(f, m) : wi(f, m, first);
    long len = ftell(f);
    rewind(f);
    *text = calloc((size_t)len + 1, 1);
    if (*text && fread(*text, 1, (size_t)len, f) != (size_t)len) (*text)[0] = 0;
    fclose(f);
    return st;
}

static void expect_output(lh_test_state *lh_t_, writer w,
                          lh_status (*wi)(FILE *, const lh_mesh_view *, int), int first,
                          const lh_mesh_view *m, const char *want)
{
    char *text;
    LH_EXPECT_EQ_INT(capture(w, wi, first, m, &text), LH_OK);
    LH_EXPECT_STREQ(text ? text : "(none)", want);
    free(text);
}

LH_TEST(vtu_text)
{
    lh_mesh_view m = quad();
    expect_output(lh_t_, vtu_ascii, NULL, 0, &m,
                  "<?xml version=\"1.0\"?>\n"
                  "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                  "  <UnstructuredGrid>\n"
                  "    <Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n"
                  "      <PointData Scalars=\"f\">\n"
                  "        <DataArray type=\"Float64\" Name=\"f\" format=\"ascii\">\n"
                  "          0\n          0.5\n          1\n          0.10000000000000001\n"
                  "        </DataArray>\n      </PointData>\n"
                  "      <Points>\n"
                  "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                  "          0 0 0\n          1 0 0\n          0 1 0\n          1 1.5 0\n"
                  "        </DataArray>\n      </Points>\n"
                  "      <Cells>\n"
                  "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n"
                  "          0 1 2\n          1 3 2\n"
                  "        </DataArray>\n"
                  "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
                  "          3\n          6\n"
                  "        </DataArray>\n"
                  "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"
                  "          5\n          5\n"
                  "        </DataArray>\n      </Cells>\n"
                  "      <CellData>\n"
                  "        <DataArray type=\"Int32\" Name=\"neighbors\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                  "          1 -1 -1\n          -1 0 -1\n"
                  "        </DataArray>\n      </CellData>\n"
                  "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
}

LH_TEST(msh_text)
{
    lh_mesh_view m = quad();
    expect_output(lh_t_, lh_msh_write, NULL, 0, &m,
                  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                  "$Entities\n0 0 1 0\n1 0 0 0 1 1.5 0 0 0\n$EndEntities\n"
                  "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n1 1.5 0\n$EndNodes\n"
                  "$Elements\n1 2 1 2\n2 1 2 2\n1 1 2 3\n2 2 4 3\n$EndElements\n"
                  "$NodeData\n1\n\"f\"\n1\n0\n3\n0\n1\n4\n1 0\n2 0.5\n3 1\n4 0.10000000000000001\n"
                  "$EndNodeData\n");
}

LH_TEST(triangle_text)
{
    lh_mesh_view m = quad();
    expect_output(lh_t_, NULL, lh_node_write, 1, &m,
                  "4 2 1 0\n1 0 0 0\n2 1 0 0.5\n3 0 1 1\n4 1 1.5 0.10000000000000001\n");
    expect_output(lh_t_, NULL, lh_ele_write, 1, &m, "2 3 0\n1 1 2 3\n2 2 4 3\n");
    expect_output(lh_t_, NULL, lh_neigh_write, 1, &m, "2 3\n1 2 -1 -1\n2 -1 1 -1\n");
    expect_output(lh_t_, NULL, lh_ele_write, 0, &m, "2 3 0\n0 0 1 2\n1 1 3 2\n");
    expect_output(lh_t_, NULL, lh_neigh_write, 0, &m, "2 3\n0 1 -1 -1\n1 -1 0 -1\n");
    m.values = NULL;
    expect_output(lh_t_, NULL, lh_node_write, 0, &m, "4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 1 1.5\n");
}

LH_TEST(off_text)
{
    lh_mesh_view m = quad();
    expect_output(lh_t_, lh_off_write, NULL, 0, &m,
                  "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1.5 0\n3 0 1 2\n3 1 3 2\n");
    /* A tetrahedron's boundary in 3D. */
    static const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const lh_index faces[] = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1};
    lh_mesh_view s = {3, 4, xyz, 2, 4, faces, NULL, NULL, NULL};
    expect_output(lh_t_, lh_off_write, NULL, 0, &s,
                  "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 1 2 3\n3 0 3 2\n3 0 1 3\n3 0 2 1\n");
}

LH_TEST(segments_and_tetrahedra)
{
    static const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const lh_index tet[] = {0, 1, 2, 3}, nb[] = {-1, -1, -1, -1};
    lh_mesh_view m = {3, 4, xyz, 3, 1, tet, nb, NULL, NULL};
    char *text;
    LH_EXPECT_EQ_INT(capture(vtu_ascii, NULL, 0, &m, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "          10\n") && strstr(text, "          4\n"));
    free(text);
    LH_EXPECT_EQ_INT(capture(lh_msh_write, NULL, 0, &m, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n") &&
                   strstr(text, "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n"));
    free(text);
    static const double line[] = {0, 1, 3};
    static const lh_index segs[] = {0, 1, 1, 2};
    lh_mesh_view l = {1, 3, line, 1, 2, segs, NULL, NULL, NULL};
    LH_EXPECT_EQ_INT(capture(lh_msh_write, NULL, 0, &l, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "$Elements\n1 2 1 2\n1 1 1 2\n1 1 2\n2 2 3\n"));
    LH_EXPECT_TRUE(text && strstr(text, "$Nodes\n1 3 1 3\n1 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n3 0 0\n"));
    free(text);
    LH_EXPECT_EQ_INT(capture(vtu_ascii, NULL, 0, &l, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "          3\n          3\n        </DataArray>\n      </Cells>"));
    free(text);
}

static lh_status vtu_cells_c(FILE *f, const lh_mesh_view *m)
{
    static const double cv[] = {0.5, -2};
    const lh_vtu_options o = {0, cv, "c"};
    return lh_vtu_write(f, m, &o);
}

/* The binary .vtu of two segments with a cell field, byte for byte (on a little-endian
 * machine; base64 decoded: 72 bytes of points 0 0 0 1 0 0 3 0 0, Int32 connectivity
 * 0 1 1 2, offsets 2 4, types 3 3, Float64 0.5 -2, each after its UInt64 length). */
LH_TEST(vtu_binary)
{
    static const double line[] = {0, 1, 3};
    static const lh_index segs[] = {0, 1, 1, 2};
    lh_mesh_view l = {1, 3, line, 1, 2, segs, NULL, NULL, NULL};
    const uint16_t one = 1;
    unsigned char low;
    memcpy(&low, &one, 1);
    char *text;
    LH_EXPECT_EQ_INT(capture(vtu_cells_c, NULL, 0, &l, &text), LH_OK);
    if (low != 1) {
        LH_EXPECT_TRUE(text && strstr(text, "byte_order=\"BigEndian\" header_type=\"UInt64\""));
        free(text);
        return;
    }
    LH_EXPECT_STREQ(text ? text : "(none)",
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        "  <UnstructuredGrid>\n"
        "    <Piece NumberOfPoints=\"3\" NumberOfCells=\"2\">\n"
        "      <Points>\n"
        "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">\n"
        "          SAAAAAAAAAA=AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA8D8AAAAAAAAAAAAAAAAAAAAAAAAAAAAACEAAAAAAAAAAAAAAAAAAAAAA\n"
        "        </DataArray>\n"
        "      </Points>\n"
        "      <Cells>\n"
        "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">\n"
        "          EAAAAAAAAAA=AAAAAAEAAAABAAAAAgAAAA==\n"
        "        </DataArray>\n"
        "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">\n"
        "          CAAAAAAAAAA=AgAAAAQAAAA=\n"
        "        </DataArray>\n"
        "        <DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">\n"
        "          AgAAAAAAAAA=AwM=\n"
        "        </DataArray>\n"
        "      </Cells>\n"
        "      <CellData>\n"
        "        <DataArray type=\"Float64\" Name=\"c\" format=\"binary\">\n"
        "          EAAAAAAAAAA=AAAAAAAA4D8AAAAAAAAAwA==\n"
        "        </DataArray>\n"
        "      </CellData>\n"
        "    </Piece>\n"
        "  </UnstructuredGrid>\n"
        "</VTKFile>\n");
    free(text);
    /* the cell field is checked as the point field is */
    static const double bad[] = {0, NAN};
    lh_vtu_options o = {0, bad, NULL};
    LH_EXPECT_EQ_INT(lh_vtu_write(stdout, &l, &o), LH_ERR_NONFINITE);
    o.cell_values = line, o.cell_values_name = "a<b";
    LH_EXPECT_EQ_INT(lh_vtu_write(stdout, &l, &o), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_vtu_write(NULL, &l, NULL), LH_ERR_INVALID_ARGUMENT);
    FILE *f = fopen("/dev/full", "w");
    if (f) {
        LH_EXPECT_EQ_INT(lh_vtu_write(f, &l, NULL), LH_ERR_IO);
        fclose(f);
    }
}

/* Every bad view: the status, and nothing written. */
LH_TEST(argument_errors)
{
    static const lh_index bad_cell[] = {0, 1, 4, 1, 3, 2}, bad_nbr[] = {1, -2, -1, -1, 0, -1};
    static const double nan_xyz[] = {0, 0, 1, 0, 0, NAN, 1, 1.5}, inf_values[] = {0, INFINITY, 0, 0};
    struct {
        lh_mesh_view m;
        int which; /* 0 vtu, 1 msh, 2 off, 3 node, 4 ele, 5 neigh */
        int first;
        lh_status want;
    } cases[12];
    size_t c = 0;
    lh_mesh_view m = quad();
    for (int i = 0; i < 12; i++) cases[i].m = m, cases[i].first = 0, cases[i].which = 0;
    cases[c].m.d = 4, cases[c++].want = LH_ERR_DIMENSION;
    cases[c].m.k = 4, cases[c].which = 1, cases[c++].want = LH_ERR_DIMENSION;
    cases[c].m.k = 3, cases[c].which = 2, cases[c++].want = LH_ERR_DIMENSION;
    cases[c].m.d = 9, cases[c].which = 3, cases[c++].want = LH_ERR_DIMENSION;
    cases[c].m.cells = bad_cell, cases[c].which = 4, cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    cases[c].m.neighbors = bad_nbr, cases[c].which = 5, cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    cases[c].m.neighbors = NULL, cases[c].which = 5, cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    cases[c].first = 2, cases[c].which = 4, cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    cases[c].m.values_name = "a b", cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    cases[c].m.xyz = nan_xyz, cases[c].which = 1, cases[c++].want = LH_ERR_NONFINITE;
    cases[c].m.values = inf_values, cases[c].which = 3, cases[c++].want = LH_ERR_NONFINITE;
    cases[c].m.cells = NULL, cases[c].which = 2, cases[c++].want = LH_ERR_INVALID_ARGUMENT;
    static const writer plain[] = {vtu_ascii, lh_msh_write, lh_off_write};
    static lh_status (*const numbered[])(FILE *, const lh_mesh_view *, int) = {lh_node_write, lh_ele_write,
                                                                               lh_neigh_write};
    for (size_t i = 0; i < c; i++) {
        char *text;
        int w = cases[i].which;
        lh_status st = capture(w < 3 ? plain[w] : NULL, w < 3 ? NULL : numbered[w - 3], cases[i].first, &cases[i].m, &text);
        LH_EXPECT_EQ_INT(st, cases[i].want);
        LH_EXPECT_STREQ(text ? text : "(none)", "");
        free(text);
        if (LH_FAILED()) {
            LH_NOTE("case %zu", i);
            return;
        }
    }
    LH_EXPECT_EQ_INT(vtu_ascii(NULL, &m), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_off_write(stdout, NULL), LH_ERR_INVALID_ARGUMENT);
}

LH_TEST(write_errors)
{
    lh_mesh_view m = quad();
    FILE *f = fopen(self_path, "rb"); /* writing a read-only stream fails */
    LH_ASSERT_TRUE(f != NULL);
    LH_EXPECT_EQ_INT(vtu_ascii(f, &m), LH_ERR_IO);
    clearerr(f);
    LH_EXPECT_EQ_INT(lh_msh_write(f, &m), LH_ERR_IO);
    clearerr(f);
    LH_EXPECT_EQ_INT(lh_node_write(f, &m, 1), LH_ERR_IO);
    clearerr(f);
    LH_EXPECT_EQ_INT(lh_ele_write(f, &m, 1), LH_ERR_IO);
    clearerr(f);
    LH_EXPECT_EQ_INT(lh_neigh_write(f, &m, 1), LH_ERR_IO);
    clearerr(f);
    LH_EXPECT_EQ_INT(lh_off_write(f, &m), LH_ERR_IO);
    fclose(f);
    f = fopen("/dev/full", "w"); /* buffered writes fail when flushed: ENOSPC */
    if (f) {
        LH_EXPECT_EQ_INT(lh_off_write(f, &m), LH_ERR_IO);
        fclose(f);
    }
}

static uint64_t next_random(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* Doubles of every kind (all bit patterns but NaN and infinities), written with %.17g
 * into a .node and read back: the same bits. */
LH_TEST(node_round_trip_is_bit_exact)
{
    enum { N = 600, D = 3 };
    static double xyz[N * D], values[N];
    uint64_t s = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < N * D + N; i++) {
        double x;
        do {
            uint64_t b = next_random(&s);
            memcpy(&x, &b, sizeof x);
        } while (!isfinite(x));
        if (i % 97 == 0) x = i % 2 ? -0.0 : 5e-324;
        if (i < N * D) xyz[i] = x;
        else values[i - N * D] = x;
    }
    lh_mesh_view m = {D, N, xyz, 0, 0, NULL, NULL, values, NULL};
    for (int first = 0; first <= 1; first++) {
        FILE *f = tmpfile();
        LH_ASSERT_TRUE(f != NULL);
        LH_ASSERT_EQ_INT(lh_node_write(f, &m, first), LH_OK);
        rewind(f);
        lh_points p;
        lh_error err;
        lh_status st = lh_points_read(f, "round.node", LH_FORMAT_AUTO, NULL, &p, &err);
        fclose(f);
        LH_ASSERT_EQ_INT(st, LH_OK);
        LH_EXPECT_EQ_INT(p.format, LH_FORMAT_NODE);
        LH_EXPECT_EQ_INT(p.first_index, first);
        LH_ASSERT_EQ_U64(p.n, N);
        LH_ASSERT_EQ_INT(p.d, D);
        LH_ASSERT_EQ_INT(p.attr_count, 1);
        LH_EXPECT_TRUE(memcmp(p.xyz, xyz, sizeof xyz) == 0);
        LH_EXPECT_TRUE(memcmp(p.attr, values, sizeof values) == 0);
        LH_EXPECT_TRUE(p.marker == NULL);
        lh_points_free(&p);
    }
}

int main(int argc, char **argv)
{
    self_path = argv[0];
    static const lh_test_case cases[] = {
        LH_CASE(vtu_text),       LH_CASE(msh_text),        LH_CASE(triangle_text),
        LH_CASE(off_text),       LH_CASE(segments_and_tetrahedra), LH_CASE(argument_errors),
        LH_CASE(write_errors),   LH_CASE(node_round_trip_is_bit_exact), LH_CASE(vtu_binary),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
