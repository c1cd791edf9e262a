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

/* Why each leftover was left, in words (lh_leftover_why). */
static const char *why_text(int why)
{
    switch (why) {
    case LH_LEFT_SPACING: return "its split point falls nearer another point than refinement's spacing";
    case LH_LEFT_BOUNDARY: return "its split point lies on the boundary (-Y)";
    case LH_LEFT_FACET: return "the subface to split has its circumcentre outside its facet";
    case LH_LEFT_REFUSED: return "recovery could not settle around its split point";
    case LH_LEFT_REGION: return "its split point's conflict region is too large";
    case LH_LEFT_STOPPED: return "refinement stopped before its turn (-S or the rounds' limits)";
    case LH_LEFT_ANGLE: return "its shortest edge spans a small input angle (a seditious edge)";
    default: return "made by the sliver flips after refinement";
    }
}

void lh_cli_tetmesh_leftovers(FILE *out, const lh_tetmesh *m, size_t limit, int first)
{
    size_t n, by[LH_LEFT_ANGLE + 1] = {0};
    const lh_tetmesh_leftover *l = lh_tetmesh_leftovers(m, &n);
    if (!n) return;
    const lh_index *tv = lh_tetmesh_tets(m);
    fprintf(out, "\n  Tetrahedra left over the bounds: %zu\n", n);
    for (size_t i = 0; i < n; i++) by[l[i].why]++;
    for (int w = LH_LEFT_SPACING; w <= LH_LEFT_ANGLE; w++)
        if (by[w]) fprintf(out, "    %zu: %s\n", by[w], why_text(w));
    fprintf(out, "  the worst %zu (radius-edge ratio; tetrahedron: points; why; the nearest input angle below 60 "
                 "degrees, in the tetrahedron's shortest edges from it):\n", n < limit ? n : limit);
    for (size_t i = 0; i < n && i < limit; i++) {
        const lh_index *v = tv + 4 * (size_t)l[i].tet;
        fprintf(out, "    %.4g; %lld: %lld %lld %lld %lld; %s", l[i].radius_edge, (long long)l[i].tet + first,
                (long long)v[0] + first, (long long)v[1] + first, (long long)v[2] + first, (long long)v[3] + first,
                why_text(l[i].why));
        if (l[i].over & 2) fprintf(out, " (over the volume bound)");
        if (l[i].over & 4) fprintf(out, " (over the size)");
        if (l[i].angle_kind == 1)
            fprintf(out, "; %.3g degrees between segments at point %lld, %.3g away\n", l[i].angle,
                    (long long)l[i].angle_at[0] + first, l[i].distance);
        else if (l[i].angle_kind == 2)
            fprintf(out, "; %.3g degrees between facets along segment %lld-%lld, %.3g away\n", l[i].angle,
                    (long long)l[i].angle_at[0] + first, (long long)l[i].angle_at[1] + first, l[i].distance);
        else
            fprintf(out, "; no input angle below 60 degrees\n");
    }
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
