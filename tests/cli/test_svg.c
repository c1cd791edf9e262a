/* test_svg.c — the CLI's SVG writer (cli/svg.c) on triangulations from lh_delaunay:
 * the number of subpaths of each kind for a known input, the same picture with the
 * neighbours computed by the writer, the size at 10^4 sites, write errors. The
 * pictures are left in the working directory (test_svg_*.svg) for svg_check.py,
 * which checks that they are well-formed XML. */
#include "lh_api_test.h"
#include "lh_families.h"
#include "lifthull.h"
#include "svg.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The file's contents (NUL-terminated, malloc'ed) and size; NULL if unreadable. */
static char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = NULL;
    if (fseek(f, 0, SEEK_END) == 0) {
        long n = ftell(f);
        if (n >= 0 && fseek(f, 0, SEEK_SET) == 0 && (buf = malloc((size_t)n + 1))) {
            *size = fread(buf, 1, (size_t)n, f);
            buf[*size] = 0;
        }
    }
    fclose(f);
    return buf;
}

/* Subpaths ('M' commands) inside <g id="ID">; -1 if there is no such group. */
static long count_subpaths(const char *svg, const char *id)
{
    char open[64];
    snprintf(open, sizeof open, "<g id=\"%s\"", id);
    const char *g = strstr(svg, open), *end = g ? strstr(g, "</g>") : NULL;
    if (!end) return -1;
    long n = 0;
    for (const char *c = g; c < end; c++) n += *c == 'M';
    return n;
}

/* Triangulates the n sites, writes the picture to path (all layers; the handle's
 * neighbours, or NULL to let the writer find them); returns the triangulation. */
static lh_tri *picture(lh_test_state *lh_t_, const char *path, size_t n, const double *xy, int pass_neighbors)
{
    lh_tri *t = NULL;
    if (!lh_test_check_true(lh_t_, __FILE__, __LINE__, "lh_delaunay", lh_delaunay(2, n, xy, NULL, &t) == LH_OK))
        return NULL;
    lh_cli_svg s = {n, xy, lh_tri_count(t), lh_tri_simplices(t), pass_neighbors ? lh_tri_neighbors(t) : NULL,
                    1, 1, 1, 1, "test <&> picture"};
    FILE *f = fopen(path, "w");
    LH_EXPECT_TRUE(f != NULL);
    if (f) {
        LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), 0);
        LH_EXPECT_EQ_INT(fclose(f), 0);
    }
    return t;
}

/* A unit square and its centre: 4 triangles, 8 Delaunay edges (4 on the hull), a
 * Voronoi diamond of 4 edges plus 4 rays, 4 circles, 5 dots. */
LH_TEST(square_with_centre)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    lh_tri *t = picture(lh_t_, "test_svg_square.svg", 5, xy, 1);
    LH_ASSERT_TRUE(t != NULL);
    LH_EXPECT_EQ_U64(lh_tri_count(t), 4);
    lh_tri_free(t);
    size_t size = 0;
    char *svg = slurp("test_svg_square.svg", &size);
    LH_ASSERT_TRUE(svg != NULL);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "delaunay"), 8);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "voronoi"), 8);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "circles"), 4);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "sites"), 5);
    LH_EXPECT_TRUE(strstr(svg, "test &lt;&amp;&gt; picture") != NULL);
    /* The box is 10^4 units with a 500-unit margin; y up: site (0, 0) at the bottom
     * left, (0.5, 0.5) in the middle. */
    LH_EXPECT_TRUE(strstr(svg, "viewBox=\"0 -600 11000 11600\"") != NULL);
    LH_EXPECT_TRUE(strstr(svg, "M500 10500h0") != NULL);
    LH_EXPECT_TRUE(strstr(svg, "M5500 5500h0") != NULL);
    /* The ray below the bottom edge: from its circumcentre (0.5, 0) down to the border. */
    LH_EXPECT_TRUE(strstr(svg, "M5500 10500l0 500") != NULL);
    free(svg);
}

/* Without the neighbour array the writer pairs the edges itself: the same bytes. */
LH_TEST(neighbors_computed)
{
    double xy[2 * 200];
    lh_fam_seed(3);
    LH_ASSERT_EQ_U64(lh_fam_make(F_BALL, 2, 200, xy), 200);
    lh_tri *a = picture(lh_t_, "test_svg_given.svg", 200, xy, 1);
    lh_tri *b = picture(lh_t_, "test_svg_computed.svg", 200, xy, 0);
    lh_tri_free(a);
    lh_tri_free(b);
    size_t na = 0, nb = 0;
    char *sa = slurp("test_svg_given.svg", &na), *sb = slurp("test_svg_computed.svg", &nb);
    LH_EXPECT_TRUE(sa && sb && na == nb && !memcmp(sa, sb, na));
    free(sa);
    free(sb);
}

/* Sites alone (no triangles), one site, and a triangle with a bad index (skipped). */
LH_TEST(no_triangles)
{
    static const double xy[] = {0, 0, 2, 1, 1, 3};
    static const lh_index bad[] = {0, 1, 7};
    lh_cli_svg s = {3, xy, 0, NULL, NULL, 1, 1, 1, 1, NULL};
    FILE *f = fopen("test_svg_sites.svg", "w");
    LH_ASSERT_TRUE(f != NULL);
    LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), 0);
    fclose(f);
    s.site_count = 1;
    f = fopen("test_svg_one.svg", "w");
    LH_ASSERT_TRUE(f != NULL);
    LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), 0);
    fclose(f);
    size_t size = 0;
    char *svg = slurp("test_svg_sites.svg", &size);
    LH_ASSERT_TRUE(svg != NULL);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "sites"), 3);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "delaunay"), 0);
    free(svg);
    lh_cli_svg b = {3, xy, 1, bad, NULL, 1, 1, 1, 1, NULL};
    f = fopen("test_svg_bad.svg", "w");
    LH_ASSERT_TRUE(f != NULL);
    LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &b), 0);
    fclose(f);
    svg = slurp("test_svg_bad.svg", &size);
    LH_ASSERT_TRUE(svg != NULL);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "delaunay"), 0);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "voronoi"), 0);
    free(svg);
}

/* 10^4 uniform sites: every Delaunay edge once, at most one Voronoi edge per Delaunay
 * edge (those wholly outside the picture are dropped: about 0.6% here, between the
 * far circumcentres of thin triangles along the hull), under 2 MB. */
LH_TEST(ten_thousand_sites)
{
    enum { N = 10000 };
    double *xy = malloc(2 * N * sizeof *xy);
    LH_ASSERT_TRUE(xy != NULL);
    lh_fam_seed(7);
    lh_fam_make(F_CUBE, 2, N, xy);
    lh_tri *t = NULL;
    LH_ASSERT_EQ_INT(lh_delaunay(2, N, xy, NULL, &t), LH_OK);
    long edges = (long)(3 * lh_tri_count(t) + lh_tri_hull_count(t)) / 2;
    lh_cli_svg s = {N, xy, lh_tri_count(t), lh_tri_simplices(t), lh_tri_neighbors(t), 1, 1, 0, 1, NULL};
    FILE *f = fopen("test_svg_10k.svg", "w");
    LH_EXPECT_TRUE(f != NULL);
    if (f) {
        LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), 0);
        fclose(f);
    }
    lh_tri_free(t);
    free(xy);
    size_t size = 0;
    char *svg = slurp("test_svg_10k.svg", &size);
    LH_ASSERT_TRUE(svg != NULL);
    LH_NOTE("%zu bytes", size);
    LH_EXPECT_LE_U64(size, 2000000);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "delaunay"), edges);
    LH_EXPECT_LE_INT(count_subpaths(svg, "voronoi"), edges);
    LH_EXPECT_GE_INT(count_subpaths(svg, "voronoi"), edges - edges / 100);
    LH_EXPECT_EQ_INT(count_subpaths(svg, "sites"), N);
    free(svg);
}

/* A full device: the writer reports the failure. */
LH_TEST(write_error)
{
    static const double xy[] = {0, 0, 1, 0, 0, 1};
    static const lh_index tri[] = {0, 1, 2};
    FILE *f = fopen("/dev/full", "w");
    if (!f) return; /* not on this system */
    lh_cli_svg s = {3, xy, 1, tri, NULL, 1, 1, 1, 1, NULL};
    LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), -1);
    fclose(f);
}

/* Writes sites xy (n, drawn with the triangles and neighbours of t) to path; returns
 * the file's contents (malloc'ed) and size. */
static char *draw_with(lh_test_state *lh_t_, const char *path, size_t n, const double *xy, const lh_tri *t,
                       size_t *size)
{
    lh_cli_svg s = {n, xy, lh_tri_count(t), lh_tri_simplices(t), lh_tri_neighbors(t), 1, 1, 1, 1, "scaled"};
    FILE *f = fopen(path, "w");
    LH_EXPECT_TRUE(f != NULL);
    if (!f) return NULL;
    LH_EXPECT_EQ_INT(lh_cli_svg_write(f, &s), 0);
    LH_EXPECT_EQ_INT(fclose(f), 0);
    return slurp(path, size);
}

/* The picture is drawn from the sites multiplied by a power of two: the square with
 * its centre scaled by 2^1000 and 2^-1070 (subnormal), and the square of +-DBL_MAX
 * (= +-(1 - 2^-53) 2^1024), draw exactly as their unscaled copies (at DBL_MAX the
 * viewBox was "... -nan" and every path coordinate garbage). The square of +-10^300
 * with a centre at 10^-300 draws the same as with the centre at 0. */
LH_TEST(extreme_scales_draw_as_the_unit_scale)
{
    static const double unit[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    const double c = 0x1.fffffffffffffp-1;
    const double sym[] = {-c, -c, c, -c, c, c, -c, c, 0, 0};
    const double M = DBL_MAX, dmax[] = {-M, -M, M, -M, M, M, -M, M, 0, 0};
    const double e = 1e300, tiny = 1e-300, mixed[] = {-e, -e, e, -e, e, e, -e, e, tiny, tiny},
                 zero[] = {-e, -e, e, -e, e, e, -e, e, 0, 0};
    lh_tri *tu = NULL, *ts = NULL;
    LH_ASSERT_EQ_INT(lh_delaunay(2, 5, unit, NULL, &tu), LH_OK);
    LH_ASSERT_EQ_INT(lh_delaunay(2, 5, sym, NULL, &ts), LH_OK);
    size_t nu = 0, n2 = 0;
    char *ref = draw_with(lh_t_, "test_svg_unit.svg", 5, unit, tu, &nu);
    for (int k = 0; k < 2; k++) {
        double xy[10];
        for (int i = 0; i < 10; i++) xy[i] = ldexp(unit[i], k ? -1070 : 1000);
        char *got = draw_with(lh_t_, k ? "test_svg_2m1070.svg" : "test_svg_2p1000.svg", 5, xy, tu, &n2);
        LH_EXPECT_TRUE(ref && got && nu == n2 && !memcmp(ref, got, nu));
        free(got);
    }
    free(ref);
    ref = draw_with(lh_t_, "test_svg_sym.svg", 5, sym, ts, &nu);
    char *got = draw_with(lh_t_, "test_svg_dblmax.svg", 5, dmax, ts, &n2);
    LH_EXPECT_TRUE(ref && got && nu == n2 && !memcmp(ref, got, nu));
    LH_EXPECT_TRUE(got && strstr(got, "viewBox=\"0 -600 11000 11600\"") != NULL);
    free(ref);
    free(got);
    ref = draw_with(lh_t_, "test_svg_zero.svg", 5, zero, ts, &nu);
    got = draw_with(lh_t_, "test_svg_mixed.svg", 5, mixed, ts, &n2);
    LH_EXPECT_TRUE(ref && got && nu == n2 && !memcmp(ref, got, nu));
    free(ref);
    free(got);
    lh_tri_free(tu);
    lh_tri_free(ts);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(square_with_centre), LH_CASE(neighbors_computed),
                                         LH_CASE(no_triangles), LH_CASE(ten_thousand_sites),
                                         LH_CASE(write_error), LH_CASE(extreme_scales_draw_as_the_unit_scale)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
