/* trimesh_test.h — helpers of the 2D meshing tests (test_trimesh*.c): reading a PSLG
 * from tests/data or from text, the exact check of a mesh (lh_cdt_check), meshing
 * with that check asserted, and every input segment kept by the mesh. */
#ifndef LH_TRIMESH_TEST_H
#define LH_TRIMESH_TEST_H

#include "lh_api_test.h"
#include "lh_test.h"
#include "lifthull.h"

typedef lh_test_pslg_reader reader;

/* Meshes g with o (NULL: defaults), asserts the exact check, returns the mesh. */
lh_trimesh *lh_test_mesh_checked(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                                 const char *what);
/* Every non-degenerate input segment is covered by subsegments that name it: their
 * total count at least one per segment, and with no Steiner point exactly one. */
void lh_test_expect_segments_kept(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh *m);

/* The short names the test bodies use. */
static inline lh_status load(reader rd, const char *path, lh_pslg *g)
{
    return lh_test_pslg_file(rd, LH_TEST_DATA_DIR, path, g);
}
static inline lh_status load_text(const char *text, lh_pslg *g) { return lh_test_pslg_text(text, g); }
static inline lh_status check(const lh_trimesh *m, lh_error *err)
{
    return lh_test_check_trimesh(m, err);
}
static inline lh_trimesh *mesh_checked(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh_options *o,
                                       const char *what)
{
    return lh_test_mesh_checked(lh_t_, g, o, what);
}
static inline void expect_segments_kept(lh_test_state *lh_t_, const lh_pslg *g, const lh_trimesh *m)
{
    lh_test_expect_segments_kept(lh_t_, g, m);
}

#endif
