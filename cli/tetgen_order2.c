/* tetgen_order2.c — TetGen's -o2 files (tetgen_io.h), laid out as TetGen 1.5 writes
 * them: .ele rows of ten nodes, the corners and then the midpoints of edges (2 3)
 * (0 3) (0 1) (1 2) (1 3) (0 2); .face rows of six, the corners and then the
 * midpoints opposite corners 0, 1, 2; .edge rows of three, the ends and then the
 * midpoint (lh_tetmesh_tet_midpoints, lh_tetmesh_midpoint). */
#include "tetgen_io.h"

/* lh_tetmesh_tet_midpoints' edges (0 1) (1 2) (0 2) (0 3) (1 3) (2 3) in TetGen's order. */
static const int TETGEN_EDGE[6] = {5, 3, 0, 1, 4, 2};

static lh_status done(FILE *f)
{
    return fflush(f) != 0 || ferror(f) ? LH_ERR_IO : LH_OK;
}

lh_status lh_cli_ele_order2_write(FILE *f, const lh_tetmesh *m, const double *attrs, int first)
{
    const size_t nt = lh_tetmesh_tet_count(m);
    const lh_index *tv = lh_tetmesh_tets(m), *mid = lh_tetmesh_tet_midpoints(m);
    if (nt && !mid) return LH_ERR_INVALID_ARGUMENT;
    fprintf(f, "%zu 10 %d\n", nt, attrs ? 1 : 0);
    for (size_t t = 0; t < nt; t++) {
        fprintf(f, "%zu", t + (size_t)first);
        for (int k = 0; k < 4; k++) fprintf(f, " %lld", (long long)tv[4 * t + (size_t)k] + first);
        for (int k = 0; k < 6; k++)
            fprintf(f, " %lld", (long long)mid[6 * t + (size_t)TETGEN_EDGE[k]] + first);
        if (attrs) fprintf(f, " %.17g", attrs[t]);
        fputc('\n', f);
    }
    return done(f);
}

lh_status lh_cli_simplex_order2_write(FILE *f, const lh_tetmesh *m, size_t count, int corners,
                                      const lh_index *v, const lh_index *markers, int first)
{
    fprintf(f, "%zu %d\n", count, markers ? 1 : 0);
    for (size_t i = 0; i < count; i++) {
        const lh_index *s = v + (size_t)corners * i;
        fprintf(f, "%zu", i + (size_t)first);
        for (int k = 0; k < corners; k++) fprintf(f, " %lld", (long long)s[k] + first);
        for (int k = corners == 2 ? 2 : 0; k < 3; k++) { /* the midpoint opposite corner k */
            const lh_index x = lh_tetmesh_midpoint(m, s[(k + 1) % corners], s[(k + 2) % corners]);
            if (x < 0) return LH_ERR_INVALID_ARGUMENT;
            fprintf(f, " %lld", (long long)x + first);
        }
        if (markers) fprintf(f, " %lld", (long long)markers[i]);
        fputc('\n', f);
    }
    return done(f);
}
