/*
 * qhull_geom.c — Qhull's G: Geomview pictures of 2-d hulls (VECT segments) and of
 * 3-d hulls and 2-d Delaunay triangulations (OFF triangles, lifted with Qhull's
 * Qbb scaling: the whole lifted hull, upper facets too, as Qhull draws it), each facet coloured by its unit normal n as (n + 1) / 2, in Qhull
 * 2020.2's layout ("%8.4g" numbers, "# f<id>" comments). Vertices are the sites
 * themselves: lifthull's facets are exact, so there are no inner and outer planes to
 * draw (Qhull projects the vertices onto them). Qhull's G suboptions are not
 * supported.
 */
#include "qhull.h"
#include "qhull_print.h"

static void point(FILE *f, const lh_cli_qmodel *mo, lh_cli_qlift s, int lifted, size_t i)
{
    const double *x = mo->xyz + i * mo->d;
    for (int j = 0; j < mo->d; j++) fprintf(f, "%8.4g ", x[j]);
    if (lifted) fprintf(f, "%8.4g ", lh_cli_qlifted(mo, s, i));
    else if (mo->d == 2) fprintf(f, "%8.4g", 0.0);
}

static void colour(FILE *f, const double *n, int dims)
{
    for (int j = 0; j < 3; j++) fprintf(f, "%8.4g ", j < dims ? (n[j] + 1) / 2 : 0.0);
    fputs("1.0", f);
}

/* A triangle's 3-d point (lifted for qdelaunay). */
static void point3(const lh_cli_qmodel *mo, lh_cli_qlift s, size_t i, double *p)
{
    for (int j = 0; j < 3; j++) p[j] = j < mo->d ? mo->xyz[i * mo->d + j] : lh_cli_qlifted(mo, s, i);
}

/* Triangle v, clockwise seen from outside (against its outward normal n), as Qhull
 * orders its facets' vertices (seen on qconvex and qdelaunay, 2020.2). */
static void triangle(FILE *f, const lh_cli_qmodel *mo, lh_cli_qlift s, int lifted,
                     const lh_index *v, const double *n, size_t id)
{
    double a[3], b[3], c[3];
    point3(mo, s, (size_t)v[0], a);
    point3(mo, s, (size_t)v[1], b);
    point3(mo, s, (size_t)v[2], c);
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double turn = n[0] * (u[1] * w[2] - u[2] * w[1]) + n[1] * (u[2] * w[0] - u[0] * w[2]) +
                  n[2] * (u[0] * w[1] - u[1] * w[0]);
    int order[3] = {0, turn > 0 ? 2 : 1, turn > 0 ? 1 : 2};
    fprintf(f, "{ OFF 3 1 1 # f%zu\n", id);
    for (int k = 0; k < 3; k++) {
        point(f, mo, s, lifted, (size_t)v[order[k]]);
        fputc('\n', f);
    }
    fputs("3 0 1 2 ", f);
    colour(f, n, 3);
    fputs(" }\n", f);
}

int lh_cli_qprint_geomview(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    const int lifted = o->prog != LH_QPROG_CONVEX, dims = mo->d + lifted;
    lh_cli_qlift s = lifted ? lh_cli_qlift_scale(mo) : (lh_cli_qlift){0, 1, 0};
    double n[LH_DELAUNAY_MAX_DIM + 1];
    if (dims == 2) {
        fprintf(f, "{appearance {linewidth 3} LIST # %s\n", o->command);
        for (size_t t = 0; t < mo->m; t++) {
            fprintf(f, "VECT 1 2 1 2 1 # f%zu\n", t);
            for (int k = 0; k < 2; k++) {
                point(f, mo, s, 0, (size_t)mo->vert[t * 2 + k]);
                fputc('\n', f);
            }
            lh_cli_qfacet_normal(mo, o, s, t, n);
            colour(f, n, 2);
            fputc('\n', f);
        }
        fputs("}\n", f);
        return 1;
    }
    fprintf(f, "{appearance {+edge -evert linewidth 2} LIST # %s\n", o->command);
    for (size_t t = 0; t < mo->m; t++) {
        lh_cli_qfacet_normal(mo, o, s, t, n);
        triangle(f, mo, s, lifted, mo->vert + t * 3, n, t);
    }
    /* Qhull draws the whole lifted hull: the other facets too (not the vertical
     * ones, which are no facets of lifthull's; their last slot is -1) */
    for (size_t j = 0; lifted && j < mo->m_other; j++) {
        const lh_index *v = mo->other + j * 3;
        if (v[2] < 0) continue;
        lh_cli_qlifted_normal(mo, s, v, !o->furthest, n);
        triangle(f, mo, s, lifted, v, n, mo->m + j);
    }
    fputs("}\n", f);
    return 1;
}
