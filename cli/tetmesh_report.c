/* tetmesh_report.c — the quality figures of a tetrahedral mesh (tetgen_io.h) as
 * TetGen's -V prints them: ranges, then histograms in two columns, with the
 * radius-edge ratio's first (lh_tetmesh_measure). */
#include "tetgen_io.h"

/* Bin k's label, "lo - hi", the last bin's hi `top` (0: unbounded, "lo -"). */
static void bin_label(FILE *out, const lh_histogram *h, int k, double top, const char *unit)
{
    char s[48];
    if (k + 1 < h->bins || top > 0)
        snprintf(s, sizeof s, "%g - %g%s", h->lower[k], k + 1 < h->bins ? h->lower[k + 1] : top,
                 unit);
    else
        snprintf(s, sizeof s, "%g -%s", h->lower[k], unit);
    fprintf(out, "%22s: %9zu", s, h->count[k]);
}

static void histogram(FILE *out, const char *title, const lh_histogram *h, double top,
                      const char *unit)
{
    const int rows = (h->bins + 1) / 2;
    fprintf(out, "\n  %s histogram:\n", title);
    for (int r = 0; r < rows; r++) {
        bin_label(out, h, r, top, unit);
        if (r + rows < h->bins) fprintf(out, "   |"), bin_label(out, h, r + rows, top, unit);
        fputc('\n', out);
    }
}

static void pair(FILE *out, const char *lo_name, double lo, const char *hi_name, double hi)
{
    fprintf(out, "  %-22s %13.6g   |  %-20s %13.6g\n", lo_name, lo, hi_name, hi);
}

int lh_cli_tetmesh_quality(FILE *out, const lh_tetmesh *m, const char *cmd)
{
    lh_tetmesh_quality q;
    lh_error err;
    if (lh_tetmesh_measure(lh_tetmesh_point_count(m), lh_tetmesh_points(m), lh_tetmesh_tet_count(m),
                           lh_tetmesh_tets(m), NULL, &q, &err) != LH_OK) {
        fprintf(stderr, "lifthull %s: the quality figures: %s\n", cmd, err.message);
        return 0;
    }
    fprintf(out, "\nMesh quality statistics (%zu tetrahedra, %zu faces):\n\n", q.tets, q.faces);
    pair(out, "Smallest volume:", q.min_volume, "Largest volume:", q.max_volume);
    pair(out, "Shortest edge:", q.min_edge, "Longest edge:", q.max_edge);
    pair(out, "Smallest asp.ratio:", q.min_aspect, "Largest asp.ratio:", q.max_aspect);
    pair(out, "Smallest facangle:", q.min_face_angle, "Largest facangle:", q.max_face_angle);
    pair(out, "Smallest dihedral:", q.min_dihedral, "Largest dihedral:", q.max_dihedral);
    pair(out, "Smallest radius-edge:", q.min_radius_edge,
         "Largest radius-edge:", q.max_radius_edge);
    histogram(out, "Radius-edge ratio", &q.radius_edge, 0, "");
    fprintf(out, "  (a tetrahedron's circumradius divided by its shortest edge)\n");
    histogram(out, "Aspect ratio", &q.aspect, 0, "");
    fprintf(out, "  (a tetrahedron's longest edge divided by its smallest height)\n");
    histogram(out, "Face angle", &q.face_angle, 180, " degrees");
    histogram(out, "Dihedral angle", &q.dihedral, 180, " degrees");
    return 1;
}
