/* trimesh_test.c — helpers of the 2D meshing tests (trimesh_test.h). */
#include "trimesh_test.h"

#include <stdlib.h>

/* Meshes g with o (NULL: defaults), asserts the exact check, returns the mesh. */
lh_trimesh *lh_test_mesh_checked(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                                 const char *what)
{
    lh_trimesh *m = NULL;
    lh_error err, cerr;
    lh_status st = lh_pslg_triangulate(g, o, &m, &err);
    if (st != LH_OK) {
        LH_NOTE("%s: %s (%s)", what, lh_status_name(st), err.message);
        LH_EXPECT_EQ_INT(st, LH_OK);
        return NULL;
    }
    st = check(m, &cerr);
    if (st != LH_OK) LH_NOTE("%s: %s", what, cerr.message);
    LH_EXPECT_EQ_INT(st, LH_OK);
    return m;
}

/* Every non-degenerate input segment is covered by subsegments that name it: their
 * total count at least one per segment, and with no Steiner point exactly one. */
void lh_test_expect_segments_kept(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh *m)
{
    size_t *hits = calloc(g->segment_count + 1, sizeof *hits);
    LH_ASSERT_TRUE(hits != NULL);
    const lh_index *par = lh_trimesh_segment_parents(m);
    for (size_t s = 0; s < lh_trimesh_segment_count(m); s++)
        if (par[s] >= 0) hits[par[s]]++;
    lh_trimesh_stats st;
    lh_trimesh_stats_get(m, &st);
    /* a segment with an endpoint in no triangle lay in a hole or outside: removed */
    char *used = calloc(lh_trimesh_point_count(m) + 1, 1);
    LH_ASSERT_TRUE(used != NULL);
    const lh_index *tri = lh_trimesh_triangles(m);
    for (size_t i = 0; i < 3 * lh_trimesh_triangle_count(m); i++) used[tri[i]] = 1;
    size_t missing = 0;
    for (size_t s = 0; s < g->segment_count; s++)
        missing += hits[s] == 0 && used[g->segments[2 * s]] && used[g->segments[2 * s + 1]];
    free(used);
    LH_EXPECT_EQ_U64(missing, st.segments_dropped + st.segments_overlapping);
    free(hits);
}
