/*
 * qhull_geom.c — Qhull's G: Geomview pictures in Qhull 2020.2's layout ("%8.4g"
 * numbers, "# f<id>" comments) of 2-d hulls (VECT segments), of 3-d hulls and 2-d
 * Delaunay triangulations (OFF triangles) and of 4-d hulls and 3-d Delaunay
 * triangulations (4OFF: the ridges as triangles, or with GDn one OFF per ridge with
 * coordinate n dropped; Gt, 3-d Delaunay: GD3 without the outer ridges, those to
 * an upper facet, as Qhull's transparent ones). A Delaunay picture is the whole
 * lifted hull with Qhull's Qbb scaling, upper facets too, as Qhull draws it. Each
 * facet is coloured by its unit normal n as (n + 1) / 2 (GDn: that colour without
 * coordinate n, scaled to length 1, as Qhull does when the picture drops a
 * dimension).
 *
 * Vertices are the sites themselves: lifthull's facets are exact, so the inner and
 * outer planes Qhull draws (projecting the vertices onto them) are the facet's own
 * hyperplane. Hence Go draws what G draws, Gi the same facets in the complementary
 * colour (Qhull's colour for inner planes), and Gh (the intersections of neighbouring
 * facets) draws the ridges themselves. Ga adds every input point, Gr the ridges, Gn
 * leaves out the facets (Gr and Gh in 3-d pictures, Ga in 2-d and 3-d ones, as
 * Qhull; lh_cli_qcheck_outputs refuses or notes the others). Gv draws a sphere of
 * radius r at each vertex of the drawn facets, r = 0.02 times the largest absolute
 * coordinate c of the picture's points (Qhull's radius with no roundoff to add), and
 * as Qhull then moves the outer plane out and the inner one in by r + 0.002 c (its
 * qh_GEOMepsilon margin), so that the spheres stay between them: both are drawn
 * unless Gi, Go or Gn says otherwise. Gc draws Qhull's centrum of each drawn facet
 * (centrum()).
 */
#include "qhull.h"
#include "qhull_print.h"
#include "qhull_sides.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct picture {
    FILE *f;
    const lh_cli_qopts *o;
    const lh_cli_qmodel *mo;
    lh_cli_qlift s;
    int lifted, dims; /* dims: the picture's coordinates, d + lifted           */
    double radius;    /* Gv: the spheres' radius; else 0                       */
    double shift;     /* Gv: how far the outer (inner) plane moves out (in)  */
    size_t nf;        /* drawn facets: the model's, then (lifted) the other
                         ones but the vertical, numbered as the model's, m + j */
    lh_index *vert, *nbr;
    size_t *id;
} picture;

/* Site i's coordinates in the picture (lifted; a 2-d hull's third is 0). */
static void coords(const picture *p, size_t i, double *x)
{
    const lh_cli_qmodel *mo = p->mo;
    for (int j = 0; j < 4; j++) x[j] = 0;
    for (int j = 0; j < mo->d && j < 4; j++) x[j] = mo->xyz[i * mo->d + j];
    if (p->lifted) x[mo->d] = lh_cli_qlifted(mo, p->s, i);
}

static void point(FILE *f, const picture *p, size_t i, int count, int drop)
{
    double x[4];
    coords(p, i, x);
    for (int j = 0; j < count; j++)
        if (j != drop) fprintf(f, "%8.4g ", x[j]);
}

/* Site i moved by t along unit normal n (onto a plane moved by t; 2-d: z stays 0). */
static void moved(FILE *f, const picture *p, size_t i, const double *n, double t)
{
    double x[4];
    coords(p, i, x);
    for (int j = 0; j < 3; j++) fprintf(f, "%8.4g ", j < p->dims ? x[j] + t * n[j] : x[j]);
}

/* Drawn facet g's unit normal: qconvex's outward one; qdelaunay's lifted one, away
 * from the lifted hull. */
static void normal_of(const picture *p, size_t g, double *n)
{
    if (p->id[g] < p->mo->m) lh_cli_qfacet_normal(p->mo, p->o, p->s, p->id[g], n);
    else lh_cli_qlifted_normal(p->mo, p->s, p->vert + g * (size_t)p->dims, !p->o->furthest, n);
}

/* The coordinate a 4-d picture leaves out: GDn's n, Gt's 3 (the lifted one); -1. */
static int dropped(const picture *p)
{
    return p->o->geom & LH_QG_TRANSPARENT ? 3 : p->o->geom_drop;
}

/* Facet g's colour: (n + 1) / 2 in the first three coordinates (complemented for an
 * inner plane); with GDn, in the three kept, scaled to length 1. */
static void colour_of(const picture *p, size_t g, int inner, double *c)
{
    double n[LH_DELAUNAY_MAX_DIM + 1] = {0}, len = 0;
    normal_of(p, g, n);
    const int drop = p->dims == 4 ? dropped(p) : -1;
    for (int j = 0, w = 0; j < p->dims && w < 3; j++)
        if (j != drop) c[w++] = (n[j] + 1) / 2;
    if (p->dims == 2) c[2] = 0;
    for (int j = 0; j < 3; j++) {
        if (inner) c[j] = 1 - c[j];
        len += c[j] * c[j];
    }
    for (int j = 0; j < 3 && drop >= 0 && len > 0; j++) c[j] /= sqrt(len);
}

static void colour(FILE *f, const double *c, const char *alpha)
{
    fprintf(f, "%8.4g %8.4g %8.4g %s", c[0], c[1], c[2], alpha);
}

/* The facets to draw and their neighbours among them (lh_cli_pair_within). */
static int picture_init(picture *p, FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    memset(p, 0, sizeof *p);
    p->f = f;
    p->o = o;
    p->mo = mo;
    p->lifted = o->prog != LH_QPROG_CONVEX;
    p->dims = mo->d + p->lifted;
    p->s = p->lifted ? lh_cli_qlift_scale(mo) : (lh_cli_qlift){0, 1, 0};
    const size_t nv = (size_t)mo->nv;
    /* with good facets selected, Qhull draws those only; else the lifted hull's
     * upper facets too (the first m_upper others; after them come dropped ones) */
    size_t total = mo->m + (p->lifted && !lh_cli_qselecting(o) ? mo->m_upper : 0);
    p->vert = malloc((total ? total : 1) * nv * sizeof *p->vert);
    p->nbr = malloc((total ? total : 1) * nv * sizeof *p->nbr);
    p->id = malloc((total ? total : 1) * sizeof *p->id);
    if (!p->vert || !p->nbr || !p->id) return 0;
    for (size_t g = 0; g < total; g++) {
        const lh_index *v = g < mo->m ? mo->vert + g * nv : mo->other + (g - mo->m) * nv;
        if (v[nv - 1] < 0) continue; /* a vertical facet: none of the lifted hull's */
        memcpy(p->vert + p->nf * nv, v, nv * sizeof *v);
        p->id[p->nf++] = g;
    }
    for (size_t i = 0; (o->geom & LH_QG_SPHERES) && p->dims <= 3 && i < mo->n; i++) {
        double x[4];
        coords(p, i, x);
        for (int j = 0; j < p->dims; j++) p->shift = fmax(p->shift, fabs(x[j]));
    }
    p->radius = 0.02 * p->shift;
    p->shift *= 0.022;
    return lh_cli_pair_within(mo->nv, p->nf, p->vert, p->nbr);
}

static void picture_free(picture *p)
{
    free(p->vert);
    free(p->nbr);
    free(p->id);
}

/* Ga: every input point, one VECT of dots (Qhull's layout). */
static void all_points(const picture *p)
{
    FILE *f = p->f;
    const size_t n = p->mo->n;
    fprintf(f, "VECT %zu %zu 1\n", n, n);
    for (size_t i = 1; i < n; i++) fputs("1 ", f);
    fputs("\n1 # 1 point per line\n1 ", f);
    for (size_t i = 2; i < n; i++) fputs("0 ", f);
    fputs("\n0 # 1 color for all\n", f);
    for (size_t i = 0; i < n; i++) {
        point(f, p, i, 3, -1);
        fprintf(f, " # p%zu\n", i);
    }
    fputs("0 1 1 1  # color of points\n", f);
}

/* The unit sphere Gv instances: the octahedron's 6 vertices and its 12 edges'
 * midpoints on the sphere; each of its 8 faces split into 4 triangles. */
static void sphere(FILE *f)
{
    static const signed char axis[6][3] = {{0, 0, 1},  {1, 0, 0},  {0, 1, 0},
                                           {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    signed char mid[12][3];
    int nm = 0, face[8][3], corner[8][3];
    const double h = sqrt(0.5);
    /* octant (sx, sy, sz): corners +-x (1 or 3), +-y (2 or 4), +-z (0 or 5) */
    for (int q = 0; q < 8; q++) {
        int c[3] = {q & 1 ? 3 : 1, q & 2 ? 4 : 2, q & 4 ? 5 : 0};
        for (int e = 0; e < 3; e++) {
            const signed char *a = axis[c[e]], *b = axis[c[(e + 1) % 3]];
            signed char m[3];
            for (int j = 0; j < 3; j++) m[j] = (signed char)(a[j] + b[j]);
            int k = 0;
            while (k < nm && memcmp(mid[k], m, 3)) k++;
            if (k == nm) memcpy(mid[nm++], m, 3);
            face[q][e] = 6 + k; /* the midpoint of corners e and e + 1 */
            corner[q][e] = c[e];
        }
    }
    fputs("{appearance {-edge -normal normscale 0} {\n"
          "INST geom {define vsphere OFF\n18 32 48\n\n", f);
    for (int i = 0; i < 6; i++) fprintf(f, "%d %d %d\n", axis[i][0], axis[i][1], axis[i][2]);
    for (int i = 0; i < 12; i++)
        fprintf(f, "%g %g %g\n", mid[i][0] * h + 0.0, mid[i][1] * h + 0.0, mid[i][2] * h + 0.0);
    fputc('\n', f);
    for (int q = 0; q < 8; q++) {
        int *m = face[q], *c = corner[q];
        int odd = ((q & 1) + (q >> 1 & 1) + (q >> 2 & 1)) & 1; /* keep them outward */
        int t[4][3] = {
            {c[0], m[0], m[2]}, {c[1], m[1], m[0]}, {c[2], m[2], m[1]}, {m[0], m[1], m[2]}};
        for (int k = 0; k < 4; k++)
            fprintf(f, "3 %d %d %d\n", t[k][0], t[k][odd ? 2 : 1], t[k][odd ? 1 : 2]);
    }
    fputs("} transforms { TLIST\n", f);
}

/* Gv: a sphere of the picture's radius at each vertex of the drawn facets, once. */
static int spheres(const picture *p)
{
    const lh_cli_qmodel *mo = p->mo;
    char *seen = calloc(mo->n ? mo->n : 1, 1);
    if (!seen) return 0;
    sphere(p->f);
    const double r = p->radius;
    for (size_t k = 0; k < p->nf * (size_t)mo->nv; k++) {
        size_t i = (size_t)p->vert[k];
        if (seen[i]) continue;
        seen[i] = 1;
        fprintf(p->f, "%8.4g 0 0 0 # v%zu\n 0 %8.4g 0 0\n0 0 %8.4g 0\n", r, i, r, r);
        point(p->f, p, i, 3, -1);
        fprintf(p->f, " # p%zu\n1\n", i);
    }
    fputs("}}}\n", p->f);
    free(seen);
    return 1;
}

/* Gc: facet g's centrum, Qhull's square in the facet's plane at the centroid c of
 * its vertices (exact: c is on the facet), its axes the first drawn vertex v - c and
 * (v - c) x n, then the centrum as a green dot. */
static void centrum(const picture *p, size_t g)
{
    FILE *f = p->f;
    const int nv = p->mo->nv;
    double n[LH_DELAUNAY_MAX_DIM + 1] = {0}, c[4] = {0}, a[4], b[3];
    normal_of(p, g, n);
    for (int k = 0; k < nv; k++) {
        double x[4];
        coords(p, (size_t)p->vert[g * (size_t)nv + k], x);
        for (int j = 0; j < 3; j++) c[j] += x[j] / nv;
    }
    coords(p, (size_t)p->vert[g * (size_t)nv], a);
    for (int j = 0; j < 3; j++) a[j] -= c[j];
    b[0] = a[1] * n[2] - a[2] * n[1];
    b[1] = a[2] * n[0] - a[0] * n[2];
    b[2] = a[0] * n[1] - a[1] * n[0];
    fputs("{appearance {-normal -edge normscale 0} {INST geom { ", f);
    if (g == 0)
        fprintf(f, "define centrum CQUAD  # f%zu\n-0.3 -0.3 0.0001     0 0 1 1\n"
                " 0.3 -0.3 0.0001     0 0 1 1\n 0.3  0.3 0.0001     0 0 1 1\n"
                "-0.3  0.3 0.0001     0 0 1 1 } transform { \n", p->id[g]);
    else
        fprintf(f, ": centrum } transform { # f%zu\n", p->id[g]);
    const double *rows[3] = {a, b, n};
    for (int r = 0; r < 3; r++)
        fprintf(f, "%8.4g %8.4g %8.4g 0\n", rows[r][0], rows[r][1], rows[r][2]);
    for (int pass = 0; pass < 2; pass++) {
        for (int j = 0; j < 3; j++) fprintf(f, "%8.4g ", c[j]);
        fputs(pass ? " # p-1\n       0        1        0 1\n" : " # p-1\n1 }}}\nVECT 1 1 1 1 1\n",
              f);
    }
}

/* A 2-d hull's edge g as Qhull's VECT. */
static void segment(const picture *p, size_t g, int inner)
{
    double c[3], n[LH_DELAUNAY_MAX_DIM + 1] = {0};
    normal_of(p, g, n);
    fprintf(p->f, "VECT 1 2 1 2 1 # f%zu\n", p->id[g]);
    for (int k = 0; k < 2; k++) { /* Qhull: no blank after the third, 0 */
        double x[4];
        coords(p, (size_t)p->vert[g * 2 + k], x);
        for (int j = 0; j < 2; j++)
            fprintf(p->f, "%8.4g ", x[j] + (inner ? -p->shift : p->shift) * n[j]);
        fprintf(p->f, "%8.4g\n", 0.0);
    }
    colour_of(p, g, inner, c);
    colour(p->f, c, "1.0\n");
}

/* Triangle g, clockwise seen from outside (against its normal n), as Qhull orders
 * its facets' vertices (seen on qconvex and qdelaunay, 2020.2). */
static void triangle(const picture *p, size_t g, int inner)
{
    double x[3][4], n[LH_DELAUNAY_MAX_DIM + 1] = {0}, c[3];
    for (int k = 0; k < 3; k++) coords(p, (size_t)p->vert[g * 3 + k], x[k]);
    normal_of(p, g, n);
    double u[3], w[3];
    for (int j = 0; j < 3; j++) u[j] = x[1][j] - x[0][j], w[j] = x[2][j] - x[0][j];
    double turn = n[0] * (u[1] * w[2] - u[2] * w[1]) + n[1] * (u[2] * w[0] - u[0] * w[2]) +
                  n[2] * (u[0] * w[1] - u[1] * w[0]);
    int order[3] = {0, turn > 0 ? 2 : 1, turn > 0 ? 1 : 2};
    fprintf(p->f, "{ OFF 3 1 1 # f%zu\n", p->id[g]);
    for (int k = 0; k < 3; k++) {
        moved(p->f, p, (size_t)p->vert[g * 3 + order[k]], n, inner ? -p->shift : p->shift);
        fputc('\n', p->f);
    }
    fputs("3 0 1 2 ", p->f);
    colour_of(p, g, inner, c);
    colour(p->f, c, "1.0 }\n");
}

/* Gr and Gh of a 3-d picture: facet g's edges to the facets not drawn yet (each
 * edge once). Gr as Qhull's qh_printline3geom (green; one dot when the ends are
 * within 1e-3), Gh as its intersection of the two facets' planes (black): exactly
 * the edge. */
static void edges(const picture *p, size_t g)
{
    static const double green[3] = {0, 1, 0}, black[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        lh_index u = p->nbr[g * 3 + k];
        if (u >= 0 && (size_t)u < g) continue;
        size_t a = (size_t)p->vert[g * 3 + (k + 1) % 3], b = (size_t)p->vert[g * 3 + (k + 2) % 3];
        double xa[4], xb[4];
        coords(p, a, xa);
        coords(p, b, xb);
        if (p->o->geom & LH_QG_RIDGES) {
            int apart = fabs(xa[0] - xb[0]) > 1e-3 || fabs(xa[1] - xb[1]) > 1e-3 || fabs(xa[2] - xb[2]) > 1e-3;
            fputs(apart ? "VECT 1 2 1 2 1\n" : "VECT 1 1 1 1 1\n", p->f);
            if (apart) {
                point(p->f, p, b, 3, -1);
                fprintf(p->f, " # p%zu\n", b);
            }
            point(p->f, p, a, 3, -1);
            fprintf(p->f, " # p%zu\n", a);
            colour(p->f, green, "1\n");
        }
        if ((p->o->geom & LH_QG_INTERSECT) && u >= 0) {
            fprintf(p->f, "VECT 1 2 1 2 1 # intersect f%zu f%zu\n", p->id[g], p->id[u]);
            point(p->f, p, a, 3, -1);
            fprintf(p->f, "# projected p%zu\n", a);
            point(p->f, p, b, 3, -1);
            fprintf(p->f, "# projected p%zu\n", b);
            colour(p->f, black, "1.0\n");
        }
    }
}

/* 4-d: every ridge (facet g's side opposite vertex k, to a facet not drawn yet) once,
 * coloured by g; 4OFF with the faces listed last, or (GDn) one OFF per ridge. */
static void ridges_4d(const picture *p)
{
    FILE *f = p->f;
    /* Gt: Qhull's GD3 picture without the outer ridges (to an upper facet) */
    const int clear = (p->o->geom & LH_QG_TRANSPARENT) != 0, drop = dropped(p);
    /* Qhull's GDn draws a Delaunay picture's lower facets only (the simplices of
     * the triangulation, seen with the lifted coordinate dropped: GD3); they come
     * first, and the other facets after them, so each ridge is still drawn once */
    const size_t nf = drop >= 0 && p->lifted ? p->mo->m : p->nf;
    size_t count = 0;
    for (size_t g = 0; g < nf; g++)
        for (int k = 0; k < 4; k++) count += p->nbr[g * 4 + k] < 0 || (size_t)p->nbr[g * 4 + k] > g;
    if (drop < 0) fprintf(f, "LIST # %s\n4OFF %zu %zu 1\n", p->o->command, 3 * count, count);
    else fprintf(f, "{appearance {+edge -evert linewidth 2} LIST # %s\n", p->o->command);
    for (int pass = 0; pass < 1 + (drop < 0); pass++) {
        size_t r = 0;
        for (size_t g = 0; g < nf; g++) {
            double c[3];
            colour_of(p, g, 0, c);
            for (int k = 0; k < 4; k++) {
                lh_index u = p->nbr[g * 4 + k];
                if (u >= 0 && (size_t)u < g) continue;
                if (clear && (u < 0 || (size_t)u >= nf)) continue;
                char other[32] = "";
                if (u >= 0) snprintf(other, sizeof other, " f%zu", p->id[u]);
                if (pass == 1) {
                    fprintf(f, "3 %zu %zu %zu ", 3 * r, 3 * r + 1, 3 * r + 2);
                    colour(f, c, "1 # ");
                    fprintf(f, "f%zu%s\n", p->id[g], other);
                    r++;
                    continue;
                }
                fprintf(f, drop < 0 ? "# ridge between f%zu%s\n" : "OFF 3 1 1 # ridge between f%zu%s\n",
                        p->id[g], other);
                for (int j = 0; j < 4; j++) {
                    if (j == k) continue;
                    point(f, p, (size_t)p->vert[g * 4 + j], 4, drop);
                    fputc('\n', f);
                }
                if (drop >= 0) /* Qhull: no blank after the colour, no brace */
                    fprintf(f, "3 0 1 2 %8.4g %8.4g %8.4g\n", c[0], c[1], c[2]);
            }
        }
    }
    if (drop >= 0) fputs("}\n", f);
}

int lh_cli_qprint_geomview(FILE *f, const lh_cli_qopts *o, const lh_cli_qmodel *mo)
{
    picture p;
    if (!picture_init(&p, f, o, mo)) {
        picture_free(&p);
        return 0;
    }
    const int geom = o->geom;
    /* Qhull: outer planes unless Gn or Gi alone; inner ones with Gi (exact: the same
     * plane, never apart from the outer one by more than Qhull's epsilon) */
    const int outer = (geom & LH_QG_OUTER) || !(geom & (LH_QG_NOPLANES | LH_QG_INNER));
    const int inner = (geom & LH_QG_INNER) ||
                      (p.radius > 0 && !(geom & (LH_QG_NOPLANES | LH_QG_INNER | LH_QG_OUTER)));
    if (p.dims == 4) {
        ridges_4d(&p);
        picture_free(&p);
        return 1;
    }
    if (p.dims == 2) fprintf(f, "{appearance {linewidth 3} LIST # %s\n", o->command);
    else fprintf(f, "{appearance {+edge -evert linewidth 2} LIST # %s\n", o->command);
    if (geom & LH_QG_POINTS) all_points(&p);
    if ((geom & LH_QG_SPHERES) && !spheres(&p)) {
        picture_free(&p);
        return 0;
    }
    for (size_t g = 0; (geom & LH_QG_CENTRUMS) && g < p.nf; g++) centrum(&p, g);
    for (size_t g = 0; g < p.nf; g++) {
        for (int in = 0; in < 2; in++) {
            if (!(in ? inner : outer)) continue;
            if (p.dims == 2) segment(&p, g, in);
            else triangle(&p, g, in);
        }
        if (p.dims == 3) edges(&p, g);
    }
    fputs("}\n", f);
    picture_free(&p);
    return 1;
}
