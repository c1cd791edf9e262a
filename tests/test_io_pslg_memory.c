/* test_io_pslg_memory.c — the PSLG readers' memory: declared counts are not trusted,
 * every allocation failure is survived (texts and files), reading needs little stack,
 * read errors and bad arguments. */
#include "io_pslg_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- memory --------------------------------------------------------------------- */

/* A count far beyond the data must not be allocated up front. */
LH_TEST(declared_counts_are_not_trusted)
{
    lh_test_biggest b;
    lh_allocator a = lh_test_biggest_allocator(&b);
    char msg[256];
    lh_pslg g;
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie.poly", TEXT("2000000000 2 3 1\n1 0 0 1 2 3 4\n"), &a, &g, msg, sizeof msg),
                     LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie.poly:3:1: expected vertex number 2, found the end of the input (2000000000 vertices declared)");
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie2.poly", TEXT("0\n2000000000 1\n1 1 2 3\n"), &a, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie2.poly:4:1: expected segment number 2, found the end of the input (2000000000 segments declared)");
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, "lie3.poly", TEXT("0\n0\n0\n2000000000\n1 0 0 1 1\n"), &a, &g, msg, sizeof msg),
                     LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "lie3.poly:6:1: expected region number 2, found the end of the input (2000000000 regions declared)");
    LH_EXPECT_LE_U64(b.largest, 1u << 16);
    LH_EXPECT_EQ_INT(b.live, 0);
}

/* A .poly of n vertices (2 attributes, markers), n segments with markers, n holes and
 * n regions: every array grows several times. */
static char *big_poly(size_t n, size_t *len)
{
    size_t cap = 200 * n + 100, k = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    k += (size_t)snprintf(s + k, cap - k, "%zu 2 2 1\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu %zu 0.5 1 2 %zu\n", i + 1, i, i % 3);
    k += (size_t)snprintf(s + k, cap - k, "%zu 1\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu %zu %zu 4\n", i + 1, i + 1, (i + 1) % n + 1);
    k += (size_t)snprintf(s + k, cap - k, "%zu\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu 0.5 %zu.5\n", i + 1, i);
    k += (size_t)snprintf(s + k, cap - k, "%zu\n", n);
    for (size_t i = 0; i < n; i++) k += (size_t)snprintf(s + k, cap - k, "%zu 0.5 %zu.5 1 -1\n", i + 1, i);
    *len = k;
    return s;
}

/* Rings: n points in rings of 7. */
static char *big_rings(size_t n, size_t *len)
{
    size_t cap = 40 * n + 100, k = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    s[k++] = '[';
    for (size_t i = 0; i < n; i++) {
        int first = i % 7 == 0, last = i % 7 == 6 || i + 1 == n;
        k += (size_t)snprintf(s + k, cap - k, "%s%s[%zu,%zu]%s", first && i ? "," : "", first ? "[" : ",", i, i % 7,
                              last ? "]" : "");
    }
    s[k++] = ']';
    *len = k;
    return s;
}

typedef struct alloc_case {
    reader rd;
    const char *text;
    size_t len;
} alloc_case;

static lh_status run_read(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const alloc_case *c = user;
    lh_pslg g;
    char msg[256];
    lh_status st = read_text(c->rd, "alloc", c->text, c->len, a, &g, msg, sizeof msg);
    if (st == LH_ERR_NOMEM) {
        LH_EXPECT_TRUE(strstr(msg, "alloc:") == msg && strstr(msg, ": out of memory for "));
        LH_EXPECT_TRUE(g.xy == NULL && g.segments == NULL && g.alloc_.alloc == NULL);
    } else {
        LH_EXPECT_EQ_INT(st, LH_OK);
        check_pslg(lh_t_, &g);
    }
    lh_pslg_free(&g);
    return st;
}

LH_TEST(every_allocation_failure)
{
    alloc_case c;
    size_t len = 0;
    char *s = big_poly(300, &len);
    LH_ASSERT_TRUE(s != NULL);
    c = (alloc_case){lh_poly_read, s, len};
    LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_read, &c), 4 * 2 + 3 * 2 + 2 * 2 + 2 * 2 + 1);
    free(s);
    s = big_rings(1000, &len);
    LH_ASSERT_TRUE(s != NULL);
    c = (alloc_case){lh_rings_read, s, len};
    LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_read, &c), 2 * 4 + 2 * 4);
    free(s);
}

/* The readers' stack stays small (a caller's thread may have a small one): the
 * scanner's block and the attributes' scratch live on the heap. */
LH_TEST(reading_needs_little_stack)
{
    for (int k = 0; k < 2; k++) {
        alloc_case c = {k ? lh_rings_read : lh_poly_read, NULL, 0};
        char *text = k ? big_rings(1000, &c.len) : big_poly(300, &c.len);
        LH_ASSERT_TRUE(text != NULL);
        c.text = text;
        size_t used;
        LH_EXPECT_EQ_INT(lh_test_run_on_thread(lh_t_, run_read, &c, &used), LH_OK);
        LH_EXPECT_GT_INT(used, 0);
        LH_EXPECT_LE_U64(used, 12288); /* under the 16 KiB block alone; sanitizers widen frames */
        if (LH_FAILED()) LH_NOTE("%s: %zu bytes of stack", k ? "rings" : ".poly", used);
        free(text);
    }
}

#ifdef LH_TEST_DATA_DIR
typedef struct file_case {
    reader rd;
    const char *path;
} file_case;

static lh_status run_file(lh_test_state *lh_t_, const lh_allocator *a, const void *user)
{
    const file_case *c = user;
    lh_pslg g;
    char msg[256];
    lh_status st = read_file(c->rd, c->path, a, &g, msg, sizeof msg);
    if (st == LH_ERR_NOMEM) LH_EXPECT_TRUE(strstr(msg, ": out of memory for ") != NULL);
    else LH_EXPECT_EQ_INT(st, LH_OK);
    lh_pslg_free(&g);
    return st;
}

LH_TEST(every_allocation_failure_files)
{
    static const file_case files[] = {
        {lh_poly_read, "triangle/A.poly"}, {lh_poly_read, "triangle/box.poly"}, {lh_poly_read, "triangle/la.poly"},
        {lh_poly_read, "triangle/reference_outputs/double_hex3.1.poly"}, {lh_rings_read, "polygons/dude.json"},
        {lh_rings_read, "polygons/steiner.json"},
    };
    for (size_t k = 0; k < LH_COUNT(files) && !LH_FAILED(); k++) {
        LH_EXPECT_GE_INT(lh_test_every_failure(lh_t_, run_file, &files[k]), 3);
        if (LH_FAILED()) LH_NOTE("file %s", files[k].path);
    }
}
#endif

LH_TEST(read_error_and_arguments)
{
    char msg[256];
    lh_error err;
    lh_pslg g;
    FILE *w = fopen("/dev/null", "w");
    if (w) { /* reading a write-only stream fails with an error, not an end */
        LH_EXPECT_EQ_INT(lh_poly_read(w, "wo", NULL, &g, &err), LH_ERR_IO);
        LH_EXPECT_STREQ(err.message, "wo:1:1: expected the number of vertices, found a read error");
        LH_EXPECT_EQ_INT(lh_rings_read(w, "wo", NULL, &g, &err), LH_ERR_IO);
        LH_EXPECT_STREQ(err.message, "wo:1:1: expected '[' (a polygon: a list of rings), found a read error");
        fclose(w);
    }
    FILE *f = lh_test_file(TEXT("0\n0\n0\n"));
    LH_ASSERT_TRUE(f != NULL);
    lh_allocator half = {lh_test_counting_alloc, NULL, NULL};
    reader rds[] = {lh_poly_read, lh_rings_read};
    for (int k = 0; k < 2; k++) {
        memset(&g, 0xff, sizeof g);
        LH_EXPECT_EQ_INT(rds[k](NULL, "x", NULL, &g, &err), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_TRUE(g.xy == NULL && g.n == 0 && g.alloc_.alloc == NULL); /* zeroed */
        LH_EXPECT_EQ_INT(err.status, LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_EQ_INT(rds[k](f, "x", NULL, NULL, &err), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_EQ_INT(rds[k](f, "x", &half, &g, &err), LH_ERR_INVALID_ARGUMENT);
        LH_EXPECT_TRUE(g.alloc_.alloc == NULL);
    }
    fclose(f);
    /* No name, no message wanted. */
    LH_EXPECT_EQ_INT(read_text(lh_poly_read, NULL, TEXT("3 x"), NULL, &g, NULL, 0), LH_ERR_PARSE);
    LH_EXPECT_EQ_INT(read_text(lh_rings_read, NULL, TEXT("x"), NULL, &g, msg, sizeof msg), LH_ERR_PARSE);
    LH_EXPECT_STREQ(msg, "<input>:1:1: expected '[' (a polygon: a list of rings), found 'x'");
}

int main(int argc, char **argv)
{
    static const lh_test_case cases[] = {
#ifdef LH_TEST_DATA_DIR
        LH_CASE(every_allocation_failure_files),
#endif
        LH_CASE(declared_counts_are_not_trusted), LH_CASE(every_allocation_failure),
        LH_CASE(reading_needs_little_stack), LH_CASE(read_error_and_arguments),
    };
    return lh_test_main(cases, LH_COUNT(cases), argc, argv);
}
