/* test_datasets.c — real and adversarial 2D point sets from other projects' test
 * suites (tests/data/SOURCES.md): the Delaunay triangulation passes the exact check
 * and has the 2n - b - 2 triangles every triangulation of n distinct sites with b
 * on the hull boundary has; delaunator's robustness set also scaled by 1e-9..1e9. */
#include "lh_test.h"
#include "lifthull.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef LH_TEST_DATA_DIR
#error "LH_TEST_DATA_DIR must name tests/data"
#endif

/* Every number in the file outside '#' comments, in order (JSON, x y pairs, or
 * Qhull's format, whose two header numbers the caller drops). */
static double *read_numbers(const char *name, size_t *count)
{
    char path[512];
    snprintf(path, sizeof path, "%s/points/%s", LH_TEST_DATA_DIR, name);
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    size_t got = fread(text, 1, (size_t)size, f);
    fclose(f);
    text[got] = 0;
    size_t cap = 1024, m = 0;
    double *v = malloc(cap * sizeof *v);
    for (char *s = text; *s;) {
        if (*s == '#') { /* a comment runs to the end of the line */
            while (*s && *s != '\n') s++;
            continue;
        }
        if (strchr("+-.0123456789", *s)) {
            char *end;
            double x = strtod(s, &end);
            if (end != s) {
                if (m == cap) v = realloc(v, (cap *= 2) * sizeof *v);
                v[m++] = x;
                s = end;
                continue;
            }
        }
        s++;
    }
    free(text);
    *count = m;
    return v;
}

static void check_2d(lh_test_state *lh_t_, const char *name, const double *xy, size_t n, double scale)
{
    double *p = malloc((2 * n + 1) * sizeof *p);
    for (size_t i = 0; i < 2 * n; i++) p[i] = xy[i] * scale;
    lh_tri *t;
    lh_status st = lh_delaunay(2, n, p, NULL, &t);
    LH_EXPECT_EQ_INT(st, LH_OK);
    if (st == LH_OK) {
        lh_error err;
        LH_EXPECT_EQ_INT(lh_tri_check(t, &err), LH_OK);
        size_t distinct = n - lh_tri_duplicate_count(t), b = lh_tri_hull_count(t);
        LH_EXPECT_EQ_U64(lh_tri_count(t), 2 * distinct - b - 2);
        if (LH_FAILED()) LH_NOTE("%s scaled by %g: %s", name, scale, err.message);
        lh_tri_free(t);
    } else {
        LH_NOTE("%s scaled by %g: %s", name, scale, lh_status_message(st));
    }
    free(p);
}

LH_TEST(delaunator_and_scipy_sets)
{
    static const char *json[] = {"ukraine.json", "issue13.json", "issue43.json", "issue44.json",
                                 "robustness1.json", "robustness2.json", "robustness3.json",
                                 "robustness4.json", "grid.json", "issue10.json", "issue11js.json",
                                 "issue24.json", "issue24js.json", "robust2.json", "robust6.json",
                                 "layers.xy"};
    for (size_t i = 0; i < LH_COUNT(json); i++) {
        size_t m;
        double *v = read_numbers(json[i], &m);
        LH_ASSERT_TRUE(v != NULL);
        LH_EXPECT_EQ_U64(m % 2, 0);
        check_2d(lh_t_, json[i], v, m / 2, 1.0);
        free(v);
    }
    static const char *qhull[] = {"degenerate_pointset.txt", "pathological_data_1.txt",
                                  "pathological_data_2.txt"};
    for (size_t i = 0; i < LH_COUNT(qhull); i++) {
        size_t m;
        double *v = read_numbers(qhull[i], &m);
        LH_ASSERT_TRUE(v != NULL);
        LH_EXPECT_EQ_INT(v[0], 2); /* dimension, count, coordinates */
        LH_EXPECT_EQ_U64((size_t)v[1], (m - 2) / 2);
        check_2d(lh_t_, qhull[i], v + 2, (m - 2) / 2, 1.0);
        free(v);
    }
}

LH_TEST(robustness_set_at_every_scale)
{
    size_t m;
    double *v = read_numbers("robustness1.json", &m);
    LH_ASSERT_TRUE(v != NULL);
    static const double scales[] = {1e-9, 1e-2, 1e2, 1e9};
    for (size_t i = 0; i < LH_COUNT(scales); i++) check_2d(lh_t_, "robustness1.json", v, m / 2, scales[i]);
    free(v);
}

LH_TEST(all_collinear_is_degenerate)
{
    const double line[] = {0, 0, 1, 0, 3, 0, 2, 0};
    lh_tri *t;
    LH_EXPECT_EQ_INT(lh_delaunay(2, 4, line, NULL, &t), LH_ERR_DEGENERATE);
    int k;
    LH_EXPECT_EQ_INT(lh_coords_affine_dim(2, 4, line, NULL, &k), LH_OK);
    LH_EXPECT_EQ_INT(k, 1);
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {LH_CASE(delaunator_and_scipy_sets),
                                         LH_CASE(robustness_set_at_every_scale),
                                         LH_CASE(all_collinear_is_degenerate)};
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
