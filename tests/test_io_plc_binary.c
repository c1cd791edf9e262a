/* test_io_plc_binary.c — lh_plc_read's PLY and STL readers: every variant (PLY ascii,
 * binary little- and big-endian; STL ascii and binary, "solid"-headed binary told
 * apart from ascii in a file and through a pipe) read into exactly the lh_plc
 * expected; coincident STL corners merged exactly; every hostile input's exact message,
 * with nothing leaked and nothing allocated for a declared count the data lacks; the
 * real sphere.ply and sphere.stl (tests/data/plc_bin/) as sphere.off: 162 points, 320
 * triangles. */
#define _POSIX_C_SOURCE 200809L /* pipe, fdopen */
#include "lh_test.h"
#include "lifthull.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TEXT(s) s, sizeof(s) - 1

/* ---- reading with a watched allocator ---------------------------------------------- */

typedef struct watch {
    long live;
    size_t biggest; /* the largest single request */
} watch;

static void *watch_alloc(void *user, size_t size)
{
    watch *w = user;
    void *p = malloc(size);
    if (p) w->live++;
    if (size > w->biggest) w->biggest = size;
    return p;
}

static void watch_free(void *user, void *ptr)
{
    watch *w = user;
    if (ptr) w->live--;
    free(ptr);
}

static watch mem;

/* A FILE over data: a temporary file, or the read end of a pipe (not seekable). */
static FILE *open_bytes(const void *data, size_t len, int pipe_it)
{
    if (!pipe_it) return lh_test_file(data, len);
    int fd[2];
    if (len > 60000 || pipe(fd) != 0) return NULL;
    ssize_t w = write(fd[1], data, len);
    close(fd[1]);
    if (w != (ssize_t)len) {
        close(fd[0]);
        return NULL;
    }
    return fdopen(fd[0], "rb");
}

static lh_status rd(const char *name, const void *data, size_t len, int pipe_it, lh_plc *g,
                    char *msg)
{
    lh_allocator a = {watch_alloc, watch_free, &mem};
    lh_error err;
    memset(&mem, 0, sizeof mem);
    FILE *f = open_bytes(data, len, pipe_it);
    if (!f) return LH_ERR_IO;
    lh_status st = lh_plc_read(f, name, LH_PLC_AUTO, &a, g, &err);
    fclose(f);
    snprintf(msg, 300, "%.299s", err.message);
    return st == err.status ? st : LH_ERR_INTERNAL;
}

/* ---- writing binary files ------------------------------------------------------------ */

typedef struct bytes {
    unsigned char b[65536];
    size_t n;
} bytes;

static void put_str(bytes *o, const char *s)
{
    memcpy(o->b + o->n, s, strlen(s));
    o->n += strlen(s);
}

static void put_uint(bytes *o, uint64_t u, size_t k, int big)
{
    for (size_t i = 0; i < k; i++) o->b[o->n + (big ? k - 1 - i : i)] = (unsigned char)(u >> 8 * i);
    o->n += k;
}

static void put_f32(bytes *o, float x, int big)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    put_uint(o, u, 4, big);
}

static void put_f64(bytes *o, double x, int big)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    put_uint(o, u, 8, big);
}

/* ---- the expected PLC ---------------------------------------------------------------- */

/* Checks g: n points xyz, f facets of one polygon each, of sizes size[] and vertices
 * v[] (concatenated), point and facet lines. */
static void check_plc(lh_test_state *lh_t_, const lh_plc *g, size_t n, const double *xyz,
                      size_t f, const int *size, const int *v, const size_t *pline,
                      const size_t *fline)
{
    LH_ASSERT_EQ_U64(g->n, n);
    LH_ASSERT_EQ_U64(g->facet_count, f);
    LH_ASSERT_EQ_U64(g->polygon_count, f);
    LH_EXPECT_EQ_INT(g->attr_count, 0);
    LH_EXPECT_EQ_INT(g->first_index, 0);
    LH_EXPECT_EQ_U64(g->segment_count + g->hole_count + g->region_count, 0);
    for (size_t i = 0; i < 3 * n; i++) {
        LH_EXPECT_EQ_DBL(g->xyz[i], xyz[i]);
        LH_EXPECT_EQ_INT(signbit(g->xyz[i]), signbit(xyz[i]));
    }
    for (size_t i = 0; i < n; i++) LH_EXPECT_EQ_U64(g->point_line[i], pline[i]);
    size_t k = 0;
    for (size_t i = 0; i < f; i++) {
        LH_EXPECT_EQ_INT(g->facet_first[i], (lh_index)i);
        LH_EXPECT_EQ_INT(g->facet_hole_first[i], 0);
        LH_EXPECT_EQ_INT(g->facet_marker[i], 0);
        LH_EXPECT_EQ_U64(g->facet_line[i], fline[i]);
        LH_EXPECT_EQ_INT(g->polygon_first[i], (lh_index)k);
        for (int j = 0; j < size[i]; j++, k++) LH_EXPECT_EQ_INT(g->polygon_vertices[k], v[k]);
    }
    LH_EXPECT_EQ_INT(g->facet_first[f], (lh_index)f);
    LH_EXPECT_EQ_INT(g->polygon_first[f], (lh_index)k);
}

/* ---- PLY ----------------------------------------------------------------------------- */

/* A tetrahedron's points as float32, double, uchar (skipped), int16; an edge element
 * with a list (skipped); faces with a flags byte before their index list, the last a
 * quadrilateral. */
static const double ply_xyz[] = {0, 0, 0, 0.5, 0, 0, 0, 0.25, 0, 0, 0, 3};
static const int ply_size[] = {3, 3, 3, 4};
static const int ply_v[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0};

static const char ply_header[] = "property float x\nproperty double y\nproperty uchar red\n"
                                 "property short z\nelement edge 2\n"
                                 "property list uchar int vertex_pair\nelement face 4\n"
                                 "property uchar flags\nproperty list uchar int vertex_indices\n"
                                 "end_header\n";

/* s with its line ends as CRLF when crlf. */
static void put_lines(bytes *o, const char *s, int crlf)
{
    for (; *s; s++) {
        if (*s == '\n' && crlf) o->b[o->n++] = '\r';
        o->b[o->n++] = (unsigned char)*s;
    }
}

/* The tetrahedron as binary PLY; a CRLF header when crlf (Windows' line ends). */
static void ply_binary(bytes *o, int big, int crlf)
{
    o->n = 0;
    put_lines(o, big ? "ply\nformat binary_big_endian 1.0\n" : "ply\nformat binary_little_endian 1.0\n", crlf);
    put_lines(o, "comment a tetrahedron\nelement vertex 4\n", crlf);
    put_lines(o, ply_header, crlf);
    for (int i = 0; i < 4; i++) {
        put_f32(o, (float)ply_xyz[3 * i], big);
        put_f64(o, ply_xyz[3 * i + 1], big);
        put_uint(o, 200, 1, big);
        put_uint(o, (uint64_t)(int64_t)ply_xyz[3 * i + 2], 2, big);
    }
    for (int i = 0; i < 2; i++) {
        put_uint(o, 2, 1, big);
        put_uint(o, 0, 4, big);
        put_uint(o, 1, 4, big);
    }
    for (int i = 0, k = 0; i < 4; i++) {
        put_uint(o, 7, 1, big);
        put_uint(o, (uint64_t)ply_size[i], 1, big);
        for (int j = 0; j < ply_size[i]; j++) put_uint(o, (uint64_t)ply_v[k++], 4, big);
    }
}

LH_TEST(ply_ascii)
{
    static const char text[] = "ply\nformat ascii 1.0\ncomment a tetrahedron\n"
                               "element vertex 4\n"
                               "property float x\nproperty double y\nproperty uchar red\n"
                               "property short z\nelement edge 2\n"
                               "property list uchar int vertex_pair\nelement face 4\n"
                               "property uchar flags\nproperty list uchar int vertex_indices\n"
                               "end_header\n"
                               "0 0 200 0\n0.5 0 200 0\n\n0 0.25 200 0\n0 0 200 3\n"
                               "2 0 1\n2 0 1\n"
                               "7 3 0 2 1\n7 3 0 1 3\n7 3 0 3 2\n7 4 1 2 3 0\n";
    static const size_t pline[] = {15, 16, 18, 19}, fline[] = {22, 23, 24, 25};
    lh_plc g;
    char msg[300];
    LH_ASSERT_EQ_INT(rd("t.ply", TEXT(text), 0, &g, msg), LH_OK);
    LH_EXPECT_STREQ(msg, "");
    check_plc(lh_t_, &g, 4, ply_xyz, 4, ply_size, ply_v, pline, fline);
    lh_plc_free(&g);
    LH_EXPECT_EQ_INT(mem.live, 0);
}

LH_TEST(ply_binary_both_orders)
{
    static const size_t pline[] = {1, 2, 3, 4}, fline[] = {1, 2, 3, 4};
    for (int big = 0; big < 2; big++) {
        for (int pipe_it = 0; pipe_it < 2; pipe_it++) {
            bytes o;
            lh_plc g;
            char msg[300];
            ply_binary(&o, big, pipe_it); /* through the pipe: a CRLF header */
            /* no name: the content says PLY */
            LH_ASSERT_EQ_INT(rd(NULL, o.b, o.n, pipe_it, &g, msg), LH_OK);
            LH_EXPECT_STREQ(msg, "");
            check_plc(lh_t_, &g, 4, ply_xyz, 4, ply_size, ply_v, pline, fline);
            lh_plc_free(&g);
            LH_EXPECT_EQ_INT(mem.live, 0);
        }
    }
}

typedef struct bad_case {
    const char *name;
    const char *text;
    size_t len;
    lh_status status;
    const char *msg;
} bad_case;

static void check_bad(lh_test_state *lh_t_, const bad_case *c)
{
    /* a count past 2^31 - 2 is too large only with 32-bit indices */
    if (sizeof(lh_index) != 4 && strstr(c->msg, "2147483646")) return;
    lh_plc g;
    char msg[300];
    LH_EXPECT_EQ_INT(rd(c->name, c->text, c->len, 0, &g, msg), c->status);
    LH_EXPECT_STREQ(msg, c->msg);
    LH_EXPECT_EQ_U64(g.n + g.facet_count, 0);
    LH_EXPECT_TRUE(g.xyz == NULL && g.facet_first == NULL);
    LH_EXPECT_EQ_INT(mem.live, 0);
}

#define PLY_TETRA "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n" \
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"    \
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"

LH_TEST(ply_ascii_errors)
{
    static const bad_case cases[] = {
        {"m.ply", TEXT("plx\n"), LH_ERR_PARSE, "m.ply:1:1: expected 'ply' (the first line of a PLY file), found 'plx'"},
        {"e.ply", TEXT(""), LH_ERR_PARSE, "e.ply:1:1: expected 'ply' (the first line of a PLY file), found the end of the input"},
        {"f.ply", TEXT("ply\nformat binary 1.0\n"), LH_ERR_PARSE,
         "f.ply:2:8: expected ascii, binary_little_endian or binary_big_endian, found 'binary'"},
        {"v.ply", TEXT("ply\nformat ascii 2.0\n"), LH_ERR_PARSE, "v.ply:2:14: expected the version 1.0, found '2.0'"},
        {"h.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\n"), LH_ERR_PARSE,
         "h.ply:4:1: expected a header line (element, property, comment, end_header), found the end of the input"},
        {"z.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n"),
         LH_ERR_PARSE, "z.ply:6:1: the vertex element has no property z"},
        {"nv.ply", TEXT("ply\nformat ascii 1.0\nend_header\n"), LH_ERR_PARSE, "nv.ply:3:1: the header declares no vertex element"},
        {"big.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 3000000000\n"), LH_ERR_TOO_LARGE,
         "big.ply:3:16: expected the number of vertices (an integer from 1 to 2147483646), found '3000000000'"},
        {"lc.ply", TEXT("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n"), LH_ERR_PARSE,
         "lc.ply:4:15: expected the list count's type (an integer type), found 'float'"},
        {"ty.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n"), LH_ERR_PARSE,
         "ty.ply:4:10: expected a type (char, uchar, short, ushort, int, uint, float, double, ...), found 'real'"},
        {"p.ply", TEXT("ply\nformat ascii 1.0\nproperty float x\n"), LH_ERR_PARSE, "p.ply:3:1: a property before any element"},
        {"xx.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\n"), LH_ERR_PARSE,
         "xx.ply:5:16: a second property of this name"},
        {"fi.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 1\nproperty list uchar float vertex_indices\n"), LH_ERR_PARSE,
         "fi.ply:8:21: the vertex indices' type is not an integer type"},
        {"nf.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 1\nproperty int flags\nend_header\n"), LH_ERR_PARSE,
         "nf.ply:9:1: the face element has no property list vertex_indices"},
        {"i.ply", TEXT(PLY_TETRA "3 0 1 4\n"), LH_ERR_PARSE,
         "i.ply:14:7: face 0: vertex index 4 is out of range (4 vertices, numbered from 0)"},
        {"neg.ply", TEXT(PLY_TETRA "3 0 -1 2\n"), LH_ERR_PARSE,
         "neg.ply:14:5: face 0: vertex index -1 is out of range (4 vertices, numbered from 0)"},
        {"two.ply", TEXT(PLY_TETRA "2 0 1\n"), LH_ERR_PARSE, "two.ply:14:1: face 0: 2 vertices (a facet has at least 3)"},
        {"short.ply", TEXT(PLY_TETRA "4 0 1 2\n"), LH_ERR_PARSE,
         "short.ply:14:8: expected vertex_indices[3] of face 0 (an integer), found the end of the line"},
        {"long.ply", TEXT(PLY_TETRA "3 0 1 2 3\n"), LH_ERR_PARSE,
         "long.ply:14:9: expected the end of the line after face 0, found '3'"},
        {"nan.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                         "end_header\n0 nan 0\n"), LH_ERR_NONFINITE,
         "nan.ply:8:3: y of vertex 0 is 'nan': NaN and infinities are not points"},
        {"few.ply", TEXT("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "end_header\n0 0 0\n1 0 0\n"), LH_ERR_PARSE,
         "few.ply:10:1: expected x of vertex 2 (a number), found the end of the input (element vertex 3 in the header)"},
        {"after.ply", TEXT(PLY_TETRA "3 0 1 2\nextra\n"), LH_ERR_PARSE,
         "after.ply:15:1: expected the end of the input after the last element, found 'extra'"},
        {"nul.ply", TEXT(PLY_TETRA "3 0\0 1 2\n"), LH_ERR_PARSE,
         "nul.ply:14:4: expected vertex_indices[1] of face 0 (an integer), found a NUL byte"},
    };
    for (size_t i = 0; i < LH_COUNT(cases); i++) check_bad(lh_t_, &cases[i]);
}

/* A binary PLY of 4 vertices (float x y z) and faces (list COUNT_TYPE int). */
static void ply_small(bytes *o, int big, long long vertices, const char *count_type)
{
    char head[300];
    o->n = 0;
    snprintf(head, sizeof head,
             "ply\nformat %s 1.0\nelement vertex %lld\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list %s int vertex_indices\nend_header\n",
             big ? "binary_big_endian" : "binary_little_endian", vertices, count_type);
    put_str(o, head);
    for (int i = 0; i < 12; i++) put_f32(o, i == 3 || i == 7 || i == 11 ? 1.0f : 0.0f, big);
}

LH_TEST(ply_binary_errors)
{
    bytes o;
    lh_plc g;
    char msg[300];
    struct {
        const char *name;
        int vertices, count, cut, extra; /* cut, extra: bytes taken off, added at the end */
        long long list[5];
        lh_status status;
        const char *msg;
    } cases[] = {
        {"i.ply", 4, 3, 0, 0, {0, 1, 9}, LH_ERR_PARSE, "i.ply: face 0: vertex index 9 is out of range (4 vertices, numbered from 0)"},
        {"n.ply", 4, 3, 0, 0, {0, 1, -5}, LH_ERR_PARSE, "n.ply: face 0: vertex index -5 is out of range (4 vertices, numbered from 0)"},
        {"two.ply", 4, 2, 0, 0, {0, 1}, LH_ERR_PARSE, "two.ply: face 0: 2 vertices (a facet has at least 3)"},
        {"len.ply", 4, -1, 0, 0, {0}, LH_ERR_PARSE, "len.ply: face 0: the length of vertex_indices is -1"},
        {"cut.ply", 4, 3, 2, 0, {0, 1, 2}, LH_ERR_PARSE, "cut.ply: face 0: the input ends (1 faces declared)"},
        {"tail.ply", 4, 3, 0, 1, {0, 1, 2}, LH_ERR_PARSE, "tail.ply: the input goes on after the last element"},
        /* 2*10^9 vertices declared, 4 there: nothing allocated for the count */
        {"huge.ply", 2000000000, 3, 13, 0, {0, 1, 2}, LH_ERR_PARSE, "huge.ply: vertex 4: the input ends (2000000000 vertices declared)"},
    };
    for (size_t i = 0; i < LH_COUNT(cases); i++) {
        for (int big = 0; big < 2; big++) {
            ply_small(&o, big, cases[i].vertices, "char");
            put_uint(&o, (uint64_t)cases[i].count, 1, big);
            for (int j = 0; j < cases[i].count; j++) put_uint(&o, (uint64_t)cases[i].list[j], 4, big);
            o.b[o.n] = 0; /* the extra byte, if any */
            o.n += (size_t)cases[i].extra - (size_t)cases[i].cut;
            LH_EXPECT_EQ_INT(rd(cases[i].name, o.b, o.n, big, &g, msg), cases[i].status);
            LH_EXPECT_STREQ(msg, cases[i].msg);
            LH_EXPECT_EQ_U64(g.n + g.facet_count, 0);
            LH_EXPECT_EQ_INT(mem.live, 0);
            LH_EXPECT_LE_U64(mem.biggest, 65536);
        }
    }
    /* a NaN coordinate names the vertex and the coordinate */
    ply_small(&o, 0, 4, "uchar");
    float nan = NAN;
    memcpy(o.b + o.n - 12 + 4, &nan, 4); /* y of vertex 3 (little-endian) */
    LH_EXPECT_EQ_INT(rd("nan.ply", o.b, o.n, 0, &g, msg), LH_ERR_NONFINITE);
    LH_EXPECT_STREQ(msg, "nan.ply: vertex 3: y is nan: NaN and infinities are not points");
}

/* ---- STL ----------------------------------------------------------------------------- */

/* Three triangles: the first corner -0.0 (read as 0.0), the second triangle sharing
 * an edge (one corner written (-0.0, 1, 0): the same point), the third degenerate
 * (its third corner is its first, again as (0, 0, -0.0)): kept as read. */
static const float stl_c[3][9] = {{-0.0f, 0, 0, 0.1f, 0, 0, 0, 1, 0},
                                  {0.1f, 0, 0, -0.0f, 1, 0, 0, 0, 1},
                                  {0, 0, 0, 0.1f, 0, 0, 0, 0, -0.0f}};
static const double stl_xyz[] = {0, 0, 0, (double)0.1f, 0, 0, 0, 1, 0, 0, 0, 1};
static const int stl_size[] = {3, 3, 3};
static const int stl_v[] = {0, 1, 2, 1, 2, 3, 0, 1, 0};

static void stl_write(bytes *o, const char *header, size_t triangles)
{
    o->n = 0;
    memset(o->b, ' ', 80);
    memcpy(o->b, header, strlen(header));
    o->n = 80;
    put_uint(o, triangles, 4, 0);
    for (size_t t = 0; t < triangles; t++) {
        for (int i = 0; i < 3; i++) put_f32(o, i == 2 ? 1.0f : 0.0f, 0); /* the normal */
        for (int i = 0; i < 9; i++) put_f32(o, stl_c[t % 3][i], 0);
        put_uint(o, 0, 2, 0);
    }
}

LH_TEST(stl_ascii)
{
    static const char text[] = "solid t made by hand\n"
                               "facet normal 0 0 1\n outer loop\n  vertex -0.0 0 0\n"
                               "  vertex 0.100000001490116119384765625 0 0\n  vertex 0 1 0\n endloop\nendfacet\n"
                               "FACET NORMAL nan 0 0 OUTER LOOP VERTEX 0.100000001490116119384765625 0 0 "
                               "VERTEX -0 1 0 VERTEX 0 0 1 ENDLOOP ENDFACET\n"
                               "endsolid t\nsolid second\n"
                               "facet normal 0 0 0\n outer loop\n  vertex 0 0 0\n"
                               "  vertex 0.100000001490116119384765625 0 0\n  vertex 0 0 -0.0\n endloop\nendfacet\n"
                               "endsolid\n";
    static const size_t pline[] = {2, 2, 2, 9}, fline[] = {2, 9, 12};
    lh_plc g;
    char msg[300];
    for (int pipe_it = 0; pipe_it < 2; pipe_it++) {
        LH_ASSERT_EQ_INT(rd(NULL, TEXT(text), pipe_it, &g, msg), LH_OK);
        LH_EXPECT_STREQ(msg, "");
        check_plc(lh_t_, &g, 4, stl_xyz, 3, stl_size, stl_v, pline, fline);
        lh_plc_free(&g);
        LH_EXPECT_EQ_INT(mem.live, 0);
    }
}

/* An ascii STL longer than the 4 KiB read ahead whose name is 120 bytes of UTF-8: still
 * ascii (bytes above 0x7e count only after the first line). */
LH_TEST(stl_ascii_long_utf8_name)
{
    bytes o;
    lh_plc g;
    char msg[300];
    o.n = 0;
    put_str(&o, "solid ");
    for (int i = 0; i < 60; i++) put_str(&o, "\xc3\xa9"); /* U+00E9 */
    put_str(&o, "\n");
    for (int t = 0; t < 60; t++) {
        char line[200];
        put_str(&o, "facet normal 0 0 1\n outer loop\n");
        for (int k = 0; k < 3; k++) {
            snprintf(line, sizeof line, "  vertex %.17g %.17g %.17g\n", (double)stl_c[t % 3][3 * k],
                     (double)stl_c[t % 3][3 * k + 1], (double)stl_c[t % 3][3 * k + 2]);
            put_str(&o, line);
        }
        put_str(&o, " endloop\nendfacet\n");
    }
    put_str(&o, "endsolid\n");
    LH_ASSERT_TRUE(o.n > 4096);
    LH_ASSERT_EQ_INT(rd("long.stl", o.b, o.n, 1, &g, msg), LH_OK);
    LH_EXPECT_STREQ(msg, "");
    LH_EXPECT_EQ_U64(g.n, 4);
    LH_EXPECT_EQ_U64(g.facet_count, 60);
    for (size_t i = 0; i < 12; i++) LH_EXPECT_EQ_DBL(g.xyz[i], stl_xyz[i]);
    lh_plc_free(&g);
}

LH_TEST(stl_binary)
{
    static const size_t pline[] = {1, 1, 1, 2}, fline[] = {1, 2, 3};
    /* a plain header; one starting "solid" (told by the length); one starting "solid"
       longer than the 4 KiB read ahead (told by its bytes), in a file and a pipe; one
       with a line like OBJ's "v x y z" (no name: the NULs say STL) */
    static const char *const headers[] = {"binary STL", "solid t", "solid t", "STL\nv 1 2 3\n"};
    for (int h = 0; h < 4; h++) {
        for (int pipe_it = 0; pipe_it < 2; pipe_it++) {
            bytes o;
            lh_plc g;
            char msg[300];
            size_t triangles = h == 2 ? 99 : 3;
            stl_write(&o, headers[h], triangles);
            LH_ASSERT_EQ_INT(rd(h == 1 || h == 2 ? "t.stl" : NULL, o.b, o.n, pipe_it, &g, msg), LH_OK);
            LH_EXPECT_STREQ(msg, "");
            if (h != 2) check_plc(lh_t_, &g, 4, stl_xyz, 3, stl_size, stl_v, pline, fline);
            LH_EXPECT_EQ_U64(g.n, 4);
            LH_EXPECT_EQ_U64(g.facet_count, triangles);
            LH_EXPECT_EQ_U64(g.facet_line[triangles - 1], triangles);
            LH_EXPECT_EQ_INT(g.polygon_vertices[3 * triangles - 1], 0);
            lh_plc_free(&g);
            LH_EXPECT_EQ_INT(mem.live, 0);
        }
    }
}

#define STL_HEAD "solid t\nfacet normal 0 0 1\nouter loop\n"

LH_TEST(stl_ascii_errors)
{
    static const bad_case cases[] = {
        {"k.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendlop\n"), LH_ERR_PARSE,
         "k.stl:7:1: expected 'endloop' (triangle 1), found 'endlop'"},
        {"four.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n"), LH_ERR_PARSE,
         "four.stl:7:1: expected 'endloop' (triangle 1), found 'vertex'"},
        {"nan.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 NaN 0\n"), LH_ERR_NONFINITE,
         "nan.stl:5:10: y of corner 2 of triangle 1 is 'NaN': NaN and infinities are not points"},
        {"x.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 0\nvertex 0 1 0\n"), LH_ERR_PARSE,
         "x.stl:6:1: expected z of corner 2 of triangle 1 (a number), found 'vertex'"},
        {"eof.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 0\n"), LH_ERR_PARSE,
         "eof.stl:6:1: expected z of corner 2 of triangle 1, found the end of the input"},
        {"n.stl", TEXT("solid t\nfacet normal 0 zero 1\n"), LH_ERR_PARSE,
         "n.stl:2:16: expected the normal's y of triangle 1 (a number), found 'zero'"},
        {"end.stl", TEXT(STL_HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"), LH_ERR_PARSE,
         "end.stl:9:1: expected 'facet' or 'endsolid', found the end of the input"},
        {"more.stl", TEXT("solid t\nendsolid t\nfacet\n"), LH_ERR_PARSE,
         "more.stl:3:1: expected the end of the input or 'solid' after 'endsolid', found 'facet'"},
        {"none.stl", TEXT("solid t\nendsolid t\n"), LH_ERR_PARSE, "none.stl:3:1: no triangle in the file"},
    };
    for (size_t i = 0; i < LH_COUNT(cases); i++) check_bad(lh_t_, &cases[i]);
}

LH_TEST(stl_binary_errors)
{
    bytes o;
    lh_plc g;
    char msg[300];
    /* truncated inside the second record */
    stl_write(&o, "x", 2);
    LH_EXPECT_EQ_INT(rd("cut.stl", o.b, o.n - 10, 0, &g, msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "cut.stl: triangle 2: the input ends (2 triangles declared)");
    /* 2^32 - 1 triangles declared, 1 there: nothing allocated for the count */
    stl_write(&o, "solid x", 1);
    o.b[80] = o.b[81] = o.b[82] = o.b[83] = 0xff;
    LH_EXPECT_EQ_INT(rd("huge.stl", o.b, o.n, 1, &g, msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "huge.stl: triangle 2: the input ends (4294967295 triangles declared)");
    LH_EXPECT_LE_U64(mem.biggest, 65536);
    LH_EXPECT_EQ_INT(mem.live, 0);
    /* a NaN corner */
    stl_write(&o, "x", 1);
    float nan = NAN;
    memcpy(o.b + 84 + 12 + 16, &nan, 4); /* y of corner 2 */
    LH_EXPECT_EQ_INT(rd("nan.stl", o.b, o.n, 0, &g, msg), LH_ERR_NONFINITE);
    LH_EXPECT_STREQ(msg, "nan.stl: triangle 1: y of corner 2 is nan: NaN and infinities are not points");
    /* bytes after the last record */
    stl_write(&o, "x", 1);
    LH_EXPECT_EQ_INT(rd("tail.stl", o.b, o.n + 1, 0, &g, msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "tail.stl: the input goes on after triangle 1, the last declared");
    /* no triangle; a header cut short */
    stl_write(&o, "x", 0);
    LH_EXPECT_EQ_INT(rd("zero.stl", o.b, o.n, 0, &g, msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "zero.stl: no triangle in the file");
    LH_EXPECT_EQ_INT(rd("head.stl", o.b, 50, 0, &g, msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "head.stl: the input ends inside the 84-byte header of a binary STL file");
    LH_EXPECT_EQ_INT(mem.live, 0);
}

/* ---- allocation failures ------------------------------------------------------------- */

/* data read with the k-th allocation failing, for k = 1, 2, ... until the read succeeds:
 * each failure LH_ERR_NOMEM with a message and nothing left allocated. Returns the
 * number of allocations a success makes. */
static long fail_each_allocation(lh_test_state *lh_t_, const char *name, const void *data,
                                 size_t len)
{
    for (long k = 1; k < 1000; k++) {
        lh_test_counter c = {0, k, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &c};
        lh_error err;
        lh_plc g;
        FILE *f = lh_test_file(data, len);
        if (!f) return 0;
        lh_status st = lh_plc_read(f, name, LH_PLC_AUTO, &a, &g, &err);
        fclose(f);
        lh_plc_free(&g);
        LH_EXPECT_EQ_INT(c.live, 0);
        if (st == LH_OK) return k;
        LH_EXPECT_EQ_INT(st, LH_ERR_NOMEM);
        LH_EXPECT_TRUE(strstr(err.message, "out of memory") != NULL);
        if (LH_FAILED()) return 0;
    }
    return 0;
}

/* A 25 x 25 grid of points (676, more than half the merging table's first 1024 slots:
 * it grows) as a binary STL of 1152 triangles. */
static void stl_grid(bytes *o)
{
    o->n = 80;
    memset(o->b, ' ', 80);
    put_uint(o, 2 * 24 * 24, 4, 0);
    for (int i = 0; i < 24; i++) {
        for (int j = 0; j < 24; j++) {
            float q[4][3] = {{i, j, 0}, {i + 1, j, 0}, {i, j + 1, 0}, {i + 1, j + 1, 1}};
            static const int t[2][3] = {{0, 1, 2}, {1, 3, 2}};
            for (int h = 0; h < 2; h++) {
                for (int k = 0; k < 3; k++) put_f32(o, 0, 0);
                for (int k = 0; k < 9; k++) put_f32(o, q[t[h][k / 3]][k % 3], 0);
                put_uint(o, 0, 2, 0);
            }
        }
    }
}

LH_TEST(allocation_failures_free_everything)
{
    static bytes o;
    static const char ply[] = PLY_TETRA "3 0 1 2\n";
    static const char stl[] = STL_HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                                       "endfacet\nendsolid\n";
    LH_EXPECT_GT_INT(fail_each_allocation(lh_t_, "a.ply", TEXT(ply)), 5);
    LH_EXPECT_GT_INT(fail_each_allocation(lh_t_, "a.stl", TEXT(stl)), 5);
    ply_binary(&o, 1, 0);
    LH_EXPECT_GT_INT(fail_each_allocation(lh_t_, "b.ply", o.b, o.n), 5);
    stl_grid(&o);
    LH_EXPECT_GT_INT(fail_each_allocation(lh_t_, "b.stl", o.b, o.n), 20);
}

/* ---- real files ---------------------------------------------------------------------- */

static lh_status read_data(const char *path, lh_plc *g, char *msg)
{
    char full[1024];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_error err;
    lh_status st = lh_plc_read(f, path, LH_PLC_AUTO, NULL, g, &err);
    snprintf(msg, 300, "%.299s", err.message);
    fclose(f);
    return st;
}

/* CGAL's sphere: ascii PLY and binary STL, as sphere.off (162 points, 320 triangles);
 * the STL's corners merged to the PLY's points rounded to float. */
LH_TEST(sphere_files)
{
    lh_plc ply, stl;
    char msg[300];
    LH_ASSERT_EQ_INT(read_data("plc_bin/sphere.ply", &ply, msg), LH_OK);
    LH_ASSERT_EQ_INT(read_data("plc_bin/sphere.stl", &stl, msg), LH_OK);
    LH_EXPECT_EQ_U64(ply.n, 162);
    LH_EXPECT_EQ_U64(ply.facet_count, 320);
    LH_EXPECT_EQ_U64(stl.n, 162);
    LH_EXPECT_EQ_U64(stl.facet_count, 320);
    /* every STL point is a PLY point rounded to float */
    size_t found = 0;
    for (size_t i = 0; i < stl.n; i++) {
        for (size_t j = 0; j < ply.n; j++) {
            int same = 1;
            for (int k = 0; k < 3; k++)
                same &= stl.xyz[3 * i + k] == (double)(float)ply.xyz[3 * j + k];
            if (same) {
                found++;
                break;
            }
        }
    }
    LH_EXPECT_EQ_U64(found, 162);
    lh_plc_free(&ply);
    lh_plc_free(&stl);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
        LH_CASE(ply_ascii),        LH_CASE(ply_binary_both_orders), LH_CASE(ply_ascii_errors),
        LH_CASE(ply_binary_errors), LH_CASE(stl_ascii),             LH_CASE(stl_ascii_long_utf8_name), LH_CASE(stl_binary),
        LH_CASE(stl_ascii_errors), LH_CASE(stl_binary_errors), LH_CASE(allocation_failures_free_everything),      LH_CASE(sphere_files)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
