/*
 * quality.c — the mesh's quality figures in lh_tetmesh_stats: the smallest dihedral
 * angle and the largest radius-edge ratio (circumradius over shortest edge), the
 * measures of Shewchuk's Delaunay refinement (tet_geom.c). Floating point: figures
 * for reports, not decisions.
 */
#include "t3.h"
#include "tet_geom.h"

#include <math.h>

void lh__tetmesh_quality(lh_tetmesh *m, double ratio_bound, double dih_bound)
{
    const double rad = 3.14159265358979323846 / 180;
    double min_dih = INFINITY, max_ratio = 0;
    m->stats.over_radius_edge = m->stats.under_dihedral = 0;
    for (size_t t = 0; t < m->tet_count; t++) {
        const double *p[4];
        for (int j = 0; j < 4; j++) p[j] = m->xyz + 3 * (size_t)m->tets[4 * t + j];
        lh__t3_sort_corners(p, 4); /* as refinement measures: the same figures */
        t3_tet_measure q;
        lh__t3_tet_measure(p, &q);
        min_dih = fmin(min_dih, q.min_dihedral);
        max_ratio = fmax(max_ratio, q.ratio);
        m->stats.over_radius_edge += ratio_bound > 0 && q.ratio > ratio_bound;
        m->stats.under_dihedral += q.min_dihedral < dih_bound * rad;
    }
    m->stats.min_dihedral = m->tet_count ? min_dih / rad : 0;
    m->stats.max_radius_edge = max_ratio;
}
