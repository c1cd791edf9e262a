/* test_io_tetgen.c — the writers of a tetrahedral mesh's files (lifthull.h, after
 * lh_vtu_write): the exact text of .node with markers, .ele with attributes, .face,
 * .edge, legacy .vtk and Medit .mesh for one tetrahedron, and their argument errors
 * (nothing written then). */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double tet_xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.5};
static const lh_index tet_cells[] = {0, 1, 2, 3};
static const lh_index tet_nbrs[] = {-1, -1, -1, -1};
static const lh_index point_marks[] = {1, 0, 2, -3};
static const double tet_attr[] = {7};
static const double half_attr[] = {2.5};
/* the four faces, outward, and three edges */
static const lh_index faces[] = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1};
static const lh_index face_marks[] = {4, 5, 6, 7};
static const lh_index edges[] = {0, 1, 0, 2, 2, 3};
static const lh_index edge_marks[] = {1, 0, 9};

static lh_mesh_view tet(void)
{
    lh_mesh_view m = {3, 4, tet_xyz, 3, 1, tet_cells, tet_nbrs, NULL, NULL};
    return m;
}

static lh_mesh_view items(int k)
{
    lh_mesh_view m = {3, 4, tet_xyz, k, k == 2 ? 4 : 3, k == 2 ? faces : edges, NULL, NULL, NULL};
    return m;
}

/* What f holds (caller frees). */
static char *contents(FILE *f)
{
    long len = ftell(f);
    rewind(f);
    char *text = calloc((size_t)len + 1, 1);
    if (text && fread(text, 1, (size_t)len, f) != (size_t)len) text[0] = 0;
    fclose(f);
    return text;
}

typedef struct call {
    int which;           /* 0 node, 1 ele, 2 face, 3 edge, 4 vtk, 5 medit */
    lh_mesh_view m;
    const lh_index *marks;
    const double *attrs;
    int first;
    const lh_medit_refs *refs;
    const char *name;
} call;

static lh_status run(const call *c, char **text)
{
    FILE *f = tmpfile();
    *text = NULL;
    if (!f) return LH_ERR_IO;
    lh_status st;
    switch (c->which) {
    case 0: st = lh_node_marker_write(f, &c->m, c->marks, c->first); break;
    case 1: st = lh_ele_attr_write(f, &c->m, c->attrs, c->first); break;
    case 2: st = lh_face_write(f, &c->m, c->marks, c->first); break;
    case 3: st = lh_edge_write(f, &c->m, c->marks, c->first); break;
    case 4: st = lh_vtk_write(f, &c->m, c->attrs, c->name); break;
    default: st = lh_medit_write(f, &c->m, c->refs);
    }
    *text = contents(f);
    return st;
}

static void expect_text(lh_test_state *lh_t_, const call *c, const char *want)
{
    char *text;
    LH_EXPECT_EQ_INT(run(c, &text), LH_OK);
    LH_EXPECT_STREQ(text ? text : "(none)", want);
    free(text);
}

static void expect_error(lh_test_state *lh_t_, const call *c, lh_status want)
{
    char *text;
    LH_EXPECT_EQ_INT(run(c, &text), want);
    LH_EXPECT_STREQ(text ? text : "(none)", ""); /* nothing written */
    free(text);
}

LH_TEST(node_with_markers)
{
    call c = {0, tet(), point_marks, NULL, 1, NULL, NULL};
    expect_text(lh_t_, &c, "4 3 0 1\n1 0 0 0 1\n2 1 0 0 0\n3 0 1 0 2\n4 0 0 1.5 -3\n");
    c.marks = NULL, c.first = 0;
    expect_text(lh_t_, &c, "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1.5\n");
}

/* Coordinates are written as printf's "%.17g" writes them, byte for byte: the
 * writer's own digits (fixed-point range) and printf's (the rest) alike. Doubles of
 * random bits, random mantissas at scales 2^-70..2^70, dyadic fractions (ties of
 * the 17th digit), powers of ten and their neighbours, zeros. */
LH_TEST(coordinates_are_printf_17g)
{
    enum { N = 60000 };
    double *x = malloc(3 * N * sizeof *x);
    LH_ASSERT_TRUE(x != NULL);
    uint64_t r = 88172645463325252u;
    size_t n = 0;
    static const double tens[] = {1e-5, 1e-4, 1e-3, 0.1, 1, 10, 1e15, 1e16, 1e17, 1e18};
    for (size_t i = 0; i < LH_COUNT(tens); i++)
        for (int k = -2; k <= 2; k++) {
            double y = tens[i];
            for (int j = 0; j < abs(k); j++) y = nextafter(y, k < 0 ? 0 : 2e18);
            x[n++] = y, x[n++] = -y;
        }
    x[n++] = 0, x[n++] = -0.0, x[n++] = 0.3, x[n++] = 2.0 / 3;
    for (long k = 1; n < 3 * N / 2; k += 2) x[n++] = ldexp((double)k, -(int)(k % 67));
    while (n < 3 * N) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        double y;
        memcpy(&y, &r, sizeof y);
        x[n] = (n % 2 && isfinite(y)) ? y : ldexp((double)(r >> 11), (int)(r % 141) - 123);
        n++;
    }
    lh_mesh_view m = {3, N, x, 0, 0, NULL, NULL, NULL, NULL};
    call c = {0, m, NULL, NULL, 0, NULL, NULL};
    char *text, *want = malloc((size_t)N * 96 + 64), *at = want;
    LH_ASSERT_TRUE(want != NULL);
    at += sprintf(at, "%d 3 0 0\n", N);
    for (size_t i = 0; i < N; i++)
        at += sprintf(at, "%zu %.17g %.17g %.17g\n", i, x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    LH_EXPECT_EQ_INT(run(&c, &text), LH_OK);
    LH_EXPECT_TRUE(text && !strcmp(text, want));
    free(text), free(want), free(x);
}

LH_TEST(ele_with_attributes)
{
    call c = {1, tet(), NULL, tet_attr, 1, NULL, NULL};
    expect_text(lh_t_, &c, "1 4 1\n1 1 2 3 4 7\n");
    c.attrs = NULL, c.first = 0;
    expect_text(lh_t_, &c, "1 4 0\n0 0 1 2 3\n");
}

LH_TEST(face_and_edge)
{
    call c = {2, items(2), face_marks, NULL, 1, NULL, NULL};
    expect_text(lh_t_, &c, "4 1\n1 2 3 4 4\n2 1 4 3 5\n3 1 2 4 6\n4 1 3 2 7\n");
    c.marks = NULL;
    expect_text(lh_t_, &c, "4 0\n1 2 3 4\n2 1 4 3\n3 1 2 4\n4 1 3 2\n");
    call e = {3, items(1), edge_marks, NULL, 0, NULL, NULL};
    expect_text(lh_t_, &e, "3 1\n0 0 1 1\n1 0 2 0\n2 2 3 9\n");
}

LH_TEST(vtk_as_tetgen)
{
    call c = {4, tet(), NULL, tet_attr, 0, NULL, NULL};
    expect_text(lh_t_, &c,
                "# vtk DataFile Version 2.0\nUnstructured Grid\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1.5\n\n"
                "CELLS 1 5\n4     0    1    2    3\n\nCELL_TYPES 1\n10\n\n"
                "CELL_DATA 1\nSCALARS cell_scalars int 1\nLOOKUP_TABLE default\n7\n");
    /* a value that is not a whole number makes the field double; a point field */
    static const double pv[] = {0, 0.5, 1, 2};
    c.attrs = half_attr, c.name = "region", c.m.values = pv, c.m.values_name = "h";
    char *text;
    LH_EXPECT_EQ_INT(run(&c, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "\nPOINT_DATA 4\nSCALARS h double 1\nLOOKUP_TABLE default\n0\n0.5\n1\n2\n"));
    LH_EXPECT_TRUE(text && strstr(text, "\nCELL_DATA 1\nSCALARS region double 1\nLOOKUP_TABLE default\n2.5\n"));
    free(text);
    /* triangles: cell type 5 */
    call t = {4, items(2), NULL, NULL, 0, NULL, NULL};
    LH_EXPECT_EQ_INT(run(&t, &text), LH_OK);
    LH_EXPECT_TRUE(text && strstr(text, "\nCELL_TYPES 4\n5\n5\n5\n5\n"));
    free(text);
}

LH_TEST(medit)
{
    static const lh_index cell_refs[] = {3};
    const lh_medit_refs r = {point_marks, cell_refs, 4, faces, face_marks};
    call c = {5, tet(), NULL, NULL, 0, &r, NULL};
    expect_text(lh_t_, &c,
                "MeshVersionFormatted 1\n\nDimension 3\n\nVertices\n4\n0 0 0 1\n1 0 0 0\n0 1 0 2\n0 0 1.5 -3\n"
                "Triangles\n4\n2 3 4 4\n1 4 3 5\n1 2 4 6\n1 3 2 7\n"
                "Tetrahedra\n1\n1 2 3 4 3\n\nEnd\n");
    c.refs = NULL;
    expect_text(lh_t_, &c,
                "MeshVersionFormatted 1\n\nDimension 3\n\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1.5 0\n"
                "Tetrahedra\n1\n1 2 3 4 0\n\nEnd\n");
}

LH_TEST(argument_errors)
{
    static const double nan_attr[] = {NAN};
    call c = {1, tet(), NULL, nan_attr, 1, NULL, NULL};
    expect_error(lh_t_, &c, LH_ERR_NONFINITE);
    c.attrs = NULL, c.first = 2;
    expect_error(lh_t_, &c, LH_ERR_INVALID_ARGUMENT);
    call n = {0, tet(), point_marks, NULL, -1, NULL, NULL};
    expect_error(lh_t_, &n, LH_ERR_INVALID_ARGUMENT);
    /* .face wants triangles, .edge segments */
    call f = {2, tet(), face_marks, NULL, 1, NULL, NULL};
    expect_error(lh_t_, &f, LH_ERR_DIMENSION);
    call e = {3, items(2), edge_marks, NULL, 1, NULL, NULL};
    expect_error(lh_t_, &e, LH_ERR_DIMENSION);
    static const lh_index out_of_range[] = {0, 1, 4};
    call o = {2, items(2), NULL, NULL, 1, NULL, NULL};
    o.m.count = 1, o.m.cells = out_of_range;
    expect_error(lh_t_, &o, LH_ERR_INVALID_ARGUMENT);
    call v = {4, tet(), NULL, nan_attr, 0, NULL, NULL};
    expect_error(lh_t_, &v, LH_ERR_NONFINITE);
    v.attrs = tet_attr, v.name = "bad name";
    expect_error(lh_t_, &v, LH_ERR_INVALID_ARGUMENT);
    /* Medit: faces out of range, faces without their array, a 1D view */
    lh_medit_refs r = {NULL, NULL, 1, out_of_range, NULL};
    call m = {5, tet(), NULL, NULL, 0, &r, NULL};
    expect_error(lh_t_, &m, LH_ERR_INVALID_ARGUMENT);
    r.faces = NULL;
    expect_error(lh_t_, &m, LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_medit_write(NULL, &m.m, NULL), LH_ERR_INVALID_ARGUMENT);
    LH_EXPECT_EQ_INT(lh_face_write(stdout, NULL, NULL, 1), LH_ERR_INVALID_ARGUMENT);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(node_with_markers), LH_CASE(coordinates_are_printf_17g),
        LH_CASE(ele_with_attributes), LH_CASE(face_and_edge),
        LH_CASE(vtk_as_tetgen),     LH_CASE(medit),               LH_CASE(argument_errors),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
