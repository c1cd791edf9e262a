/* io_pslg_test.c — helpers of the PSLG reader tests (io_pslg_test.h). */
#include "io_pslg_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The reader's status and its lh_error, or LH_ERR_IO for both. */
static lh_status read_text_err(reader rd, const char *name, const char *text, size_t len,
                               const lh_allocator *a, lh_pslg *g, lh_error *err)
{
    const lh_error io = {LH_ERR_IO, 0, 0, LH_ERROR_NO_INDEX, ""};
    *err = io;
    FILE *f = lh_test_file(text, len);
    if (!f) return LH_ERR_IO;
    lh_status st = rd(f, name, a, g, err);
    fclose(f);
    return st;
}

/* The message into msg; the status, or LH_ERR_INTERNAL when err disagrees with it. */
static lh_status hand_back(lh_status st, const lh_error *err, char *msg, size_t size)
{
    if (msg && size) snprintf(msg, size, "%s", err->message);
    return st == err->status ? st : LH_ERR_INTERNAL;
}

lh_status read_text(reader rd, const char *name, const char *text, size_t len,
                    const lh_allocator *a, lh_pslg *g, char *msg, size_t size)
{
    lh_error err;
    lh_status st = read_text_err(rd, name, text, len, a, g, &err);
    return hand_back(st, &err, msg, size);
}

#ifdef LH_TEST_DATA_DIR
lh_status read_file(reader rd, const char *path, const lh_allocator *a, lh_pslg *g,
                    char *msg, size_t size)
{
    char full[512];
    snprintf(full, sizeof full, "%s/%s", LH_TEST_DATA_DIR, path);
    FILE *f = fopen(full, "rb");
    if (!f) return LH_ERR_IO;
    lh_error err;
    lh_status st = rd(f, path, a, g, &err);
    fclose(f);
    return hand_back(st, &err, msg, size);
}

#endif

void check_pslg(lh_test_state *lh_t_, const lh_pslg *g)
{
    LH_EXPECT_TRUE((g->n > 0) == (g->xy != NULL));
    LH_EXPECT_TRUE((g->n > 0 && g->attr_count > 0) == (g->attr != NULL));
    LH_EXPECT_TRUE((g->segment_count > 0) == (g->segments != NULL));
    LH_EXPECT_TRUE((g->segment_count > 0) == (g->segment_line != NULL));
    LH_EXPECT_TRUE((g->hole_count > 0) == (g->holes != NULL && g->hole_line != NULL));
    LH_EXPECT_TRUE((g->region_count > 0) == (g->regions != NULL && g->region_line != NULL));
    LH_EXPECT_TRUE(g->first_index == 0 || g->first_index == 1);
    for (size_t i = 0; i < 2 * g->n; i++) LH_EXPECT_TRUE(isfinite(g->xy[i]));
    for (size_t i = 0; g->n && i < 2 * g->segment_count; i++)
        LH_EXPECT_TRUE(g->segments[i] >= 0 && (size_t)g->segments[i] < g->n);
    for (size_t i = 1; g->vertex_line && i < g->n; i++) LH_EXPECT_TRUE(g->vertex_line[i] >= g->vertex_line[i - 1]);
}

void check_bad_cases(lh_test_state *lh_t_, reader rd, const bad_case *cases, size_t count)
{
    for (size_t i = 0; i < count && !LH_FAILED(); i++) {
        const bad_case *c = &cases[i];
        /* The counts' limit is LH_INDEX_MAX - 1: these messages are the 32-bit build's. */
        if (sizeof(lh_index) != 4 && strstr(c->msg, "2147483646")) continue;
        lh_error err;
        lh_pslg g;
        lh_test_counter k = {0, 0, 0};
        lh_allocator a = {lh_test_counting_alloc, lh_test_counting_free, &k};
        LH_EXPECT_EQ_INT(read_text_err(rd, c->name, c->text, c->len, &a, &g, &err), c->status);
        LH_EXPECT_EQ_INT(err.status, c->status);
        LH_EXPECT_STREQ(err.message, c->msg);
        /* the place in the message is the place in err */
        char place[300];
        snprintf(place, sizeof place, "%s:%zu:%zu: ", c->name ? c->name : "<input>", err.line, err.column);
        LH_EXPECT_TRUE(err.line > 0 && err.column > 0 && strncmp(c->msg, place, strlen(place)) == 0);
        LH_EXPECT_EQ_U64(err.index, LH_ERROR_NO_INDEX);
        LH_EXPECT_TRUE(g.xy == NULL && g.n == 0 && g.segments == NULL && g.segment_count == 0 && g.holes == NULL &&
                       g.regions == NULL && g.vertex_line == NULL && g.alloc_.alloc == NULL);
        LH_EXPECT_EQ_INT(k.live, 0);
        if (LH_FAILED()) LH_NOTE("case %s", c->name);
    }
}
