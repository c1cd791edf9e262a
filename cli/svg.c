/*
 * svg.c — the SVG picture of a 2D triangulation and its Voronoi diagram (svg.h).
 *
 * References:
 *   - G. Voronoi, "Nouvelles applications des parametres continus a la theorie des
 *     formes quadratiques", J. reine angew. Math. 134, 1908; B. Delaunay, "Sur la
 *     sphere vide", 1934: the Voronoi diagram is the dual of the Delaunay
 *     triangulation — a vertex per triangle (its circumcentre), an edge per interior
 *     edge (joining the two circumcentres), a ray per hull edge (from the circumcentre
 *     along the edge's outward normal).
 *   - Y.-D. Liang, B. A. Barsky, "A new concept and method for line clipping", ACM
 *     TOG 3(1), 1984: segments and rays clipped to the picture.
 *   - SVG 1.1, 8.3 and 11.4: path data; a zero-length subpath with round caps is a dot.
 *
 * Canvas: the sites' bounding box plus a 5% margin, scaled so that the box's longer
 * side is 10^4 units, y flipped (canvas y grows downwards); a legend band above
 * (negative canvas y). Every coordinate written is an integer of that canvas. All of
 * it is computed on the sites multiplied by a power of two (lh_cli_svg_shift), so
 * that sites near +-DBL_MAX or 1e-300 draw as the unit-scale ones do.
 */
#include "svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { SEGS_PER_PATH = 2048 }; /* subpaths per <path> element */

#define CANVAS 10000.0 /* the box's longer side in canvas units        */
#define LEGEND 600.0   /* height of the legend band above the box       */

/* World (input) to canvas: X = (x - x0) * scale, Y = (y1 - y) * scale. */
typedef struct view {
    double x0, y1, scale;
    double width, height; /* the box with its margin, in canvas units     */
    double line, dot;     /* stroke width, dot diameter (canvas units)    */
    double cx, cy, reach; /* world: the box's centre, and a length beyond
                             which every ray has left the picture        */
} view;

/* The bounding box of the finite sites (the unit square if none), a 5% margin, stroke
 * widths from the mean spacing of n sites: thin enough for 10^4 sites. */
static view view_fit(const lh_cli_svg *s)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < s->site_count; i++)
        for (int j = 0; j < 2; j++) {
            double v = s->sites[2 * i + j];
            if (!isfinite(v)) continue;
            lo[j] = fmin(lo[j], v);
            hi[j] = fmax(hi[j], v);
        }
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1])) lo[0] = lo[1] = 0, hi[0] = hi[1] = 1;
    double side = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(side > 0) || !isfinite(CANVAS / side) || !isfinite(side)) side = fmax(1, fabs(lo[0]) + fabs(lo[1]));
    double m = 0.05 * side;
    view v;
    v.scale = CANVAS / side;
    v.x0 = lo[0] - m;
    v.y1 = hi[1] + m;
    v.width = (hi[0] - lo[0] + 2 * m) * v.scale;
    v.height = (hi[1] - lo[1] + 2 * m) * v.scale;
    double spacing = sqrt(v.width * v.height / (double)(s->site_count ? s->site_count : 1));
    v.line = fmin(fmax(0.06 * spacing, 1), 25);
    v.dot = fmin(fmax(0.3 * spacing, 3), 120);
    v.cx = (lo[0] + hi[0]) / 2;
    v.cy = (lo[1] + hi[1]) / 2;
    v.reach = 4 * side;
    return v;
}

static void to_canvas(const view *v, const double *w, double *c)
{
    c[0] = (w[0] - v->x0) * v->scale;
    c[1] = (v->y1 - w[1]) * v->scale;
}

/* Liang-Barsky: clips the canvas segment p-q to [0, width] x [0, height] in place;
 * 0 when nothing of it is inside (or it is not finite). */
static int clip(const view *v, double *p, double *q)
{
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(q[0]) || !isfinite(q[1])) return 0;
    double d[2] = {q[0] - p[0], q[1] - p[1]}, t0 = 0, t1 = 1;
    double lim[2] = {v->width, v->height};
    for (int j = 0; j < 2; j++) {
        double e[2] = {-d[j], d[j]}, f[2] = {p[j], lim[j] - p[j]}; /* e t <= f on each side */
        for (int k = 0; k < 2; k++) {
            if (e[k] == 0) {
                if (f[k] < 0) return 0;
                continue;
            }
            double t = f[k] / e[k];
            if (e[k] < 0) t0 = fmax(t0, t);
            else t1 = fmin(t1, t);
        }
    }
    if (t0 > t1) return 0;
    double a[2] = {p[0] + t0 * d[0], p[1] + t0 * d[1]};
    q[0] = p[0] + t1 * d[0];
    q[1] = p[1] + t1 * d[1];
    p[0] = a[0];
    p[1] = a[1];
    return 1;
}

/* ---- path elements ---------------------------------------------------------------- */

/* Subpaths of one kind, SEGS_PER_PATH to a <path>, inside a styled <g id=...>. */
typedef struct paths {
    FILE *f;
    size_t count; /* subpaths written so far */
} paths;

static paths paths_open(FILE *f, const char *id, const char *style)
{
    fprintf(f, "<g id=\"%s\" %s>\n", id, style);
    return (paths){f, 0};
}

/* Starts a subpath: a new <path> element every SEGS_PER_PATH. */
static void paths_next(paths *p)
{
    if (p->count % SEGS_PER_PATH == 0) fputs(p->count ? "\"/>\n<path d=\"" : "<path d=\"", p->f);
    p->count++;
}

static void paths_close(paths *p)
{
    if (p->count) fputs("\"/>\n", p->f);
    fputs("</g>\n", p->f);
}

/* "M x y l dx dy" in whole canvas units (the end rounded, then differenced). */
static void paths_segment(paths *p, const double *a, const double *b)
{
    long long ax = llround(a[0]), ay = llround(a[1]);
    paths_next(p);
    fprintf(p->f, "M%lld %lldl%lld %lld", ax, ay, llround(b[0]) - ax, llround(b[1]) - ay);
}

/* A world segment, mapped and clipped. */
static void paths_world_segment(paths *p, const view *v, const double *a, const double *b)
{
    double ca[2], cb[2];
    to_canvas(v, a, ca);
    to_canvas(v, b, cb);
    if (clip(v, ca, cb)) paths_segment(p, ca, cb);
}

/* ---- geometry ------------------------------------------------------------------------ */

static const double *site(const lh_cli_svg *s, lh_index i) { return s->sites + 2 * (size_t)i; }

/* Whether triangle t's vertices are valid site indices (a bad caller array is skipped,
 * never read out of bounds). */
static int tri_ok(const lh_cli_svg *s, size_t t)
{
    for (int k = 0; k < 3; k++) {
        lh_index i = s->tris[3 * t + k];
        if (i < 0 || (size_t)i >= s->site_count) return 0;
    }
    return 1;
}

/* Circumcentre of triangle t into c, and its radius; 0 when the double arithmetic
 * gives no finite one (a nearly flat triangle). */
static int circumcentre(const lh_cli_svg *s, size_t t, double *c, double *radius)
{
    const double *a = site(s, s->tris[3 * t]), *b = site(s, s->tris[3 * t + 1]), *e = site(s, s->tris[3 * t + 2]);
    double bx = b[0] - a[0], by = b[1] - a[1], ex = e[0] - a[0], ey = e[1] - a[1];
    double det = 2 * (bx * ey - by * ex), bb = bx * bx + by * by, ee = ex * ex + ey * ey;
    double ux = (ey * bb - by * ee) / det, uy = (bx * ee - ex * bb) / det;
    c[0] = a[0] + ux;
    c[1] = a[1] + uy;
    *radius = sqrt(ux * ux + uy * uy);
    return isfinite(c[0]) && isfinite(c[1]) && isfinite(*radius);
}

/* The neighbour across the edge opposite vertex k of t, -1 across the hull, -2 if the
 * caller's value is out of range. */
static lh_index neighbor(const lh_cli_svg *s, const lh_index *nb, size_t t, int k)
{
    lh_index u = nb[3 * t + k];
    return u >= -1 && (u < 0 || (size_t)u < s->tri_count) ? u : -2;
}

/* The Voronoi ray of hull edge k of t: from the circumcentre c along the outward
 * normal of the edge (away from the opposite vertex), long enough to leave the
 * picture. */
static void voronoi_ray(paths *p, const view *v, const lh_cli_svg *s, size_t t, int k, const double *c)
{
    const double *a = site(s, s->tris[3 * t + (k + 1) % 3]), *b = site(s, s->tris[3 * t + (k + 2) % 3]);
    const double *o = site(s, s->tris[3 * t + k]);
    double n[2] = {b[1] - a[1], a[0] - b[0]};
    if (n[0] * (o[0] - a[0]) + n[1] * (o[1] - a[1]) > 0) n[0] = -n[0], n[1] = -n[1];
    double len = hypot(n[0], n[1]);
    if (!(len > 0)) return;
    double far = (hypot(c[0] - v->cx, c[1] - v->cy) + v->reach) / len;
    double end[2] = {c[0] + far * n[0], c[1] + far * n[1]};
    paths_world_segment(p, v, c, end);
}

/* ---- layers ------------------------------------------------------------------------- */

/* Each edge once: from the triangle with the smaller index, or the hull triangle. */
static void draw_delaunay(FILE *f, const view *v, const lh_cli_svg *s, const lh_index *nb)
{
    char style[160];
    snprintf(style, sizeof style, "fill=\"none\" stroke=\"#1f5fa8\" stroke-width=\"%.3g\" stroke-linecap=\"round\"", v->line);
    paths p = paths_open(f, "delaunay", style);
    for (size_t t = 0; t < s->tri_count; t++) {
        if (!tri_ok(s, t)) continue;
        for (int k = 0; k < 3; k++) {
            lh_index u = neighbor(s, nb, t, k);
            if (u == -2 || (u >= 0 && (size_t)u < t)) continue;
            paths_world_segment(&p, v, site(s, s->tris[3 * t + (k + 1) % 3]), site(s, s->tris[3 * t + (k + 2) % 3]));
        }
    }
    paths_close(&p);
}

static void draw_voronoi(FILE *f, const view *v, const lh_cli_svg *s, const lh_index *nb)
{
    char style[160];
    snprintf(style, sizeof style, "fill=\"none\" stroke=\"#c8401a\" stroke-width=\"%.3g\" stroke-linecap=\"round\"", v->line);
    paths p = paths_open(f, "voronoi", style);
    for (size_t t = 0; t < s->tri_count; t++) {
        double c[2], c2[2], r;
        if (!tri_ok(s, t) || !circumcentre(s, t, c, &r)) continue;
        for (int k = 0; k < 3; k++) {
            lh_index u = neighbor(s, nb, t, k);
            if (u == -1) voronoi_ray(&p, v, s, t, k, c);
            else if (u >= 0 && (size_t)u > t && tri_ok(s, (size_t)u) && circumcentre(s, (size_t)u, c2, &r))
                paths_world_segment(&p, v, c, c2);
        }
    }
    paths_close(&p);
}

/* Whether a canvas circle's outline crosses the picture: not wholly outside it, and
 * the picture not wholly inside the circle. */
static int circle_visible(const view *v, const double *c, double r)
{
    double dx = fmax(fmax(-c[0], c[0] - v->width), 0), dy = fmax(fmax(-c[1], c[1] - v->height), 0);
    double fx = fmax(fabs(c[0]), fabs(c[0] - v->width)), fy = fmax(fabs(c[1]), fabs(c[1] - v->height));
    return dx * dx + dy * dy <= r * r && fx * fx + fy * fy >= r * r && r >= 0.5 && r <= 1e9;
}

/* Circumcircles as two arcs each, clipped by the picture's clipPath. */
static void draw_circles(FILE *f, const view *v, const lh_cli_svg *s)
{
    char style[200];
    snprintf(style, sizeof style, "clip-path=\"url(#lh-view)\" fill=\"none\" stroke=\"#2e8b57\" stroke-opacity=\"0.6\" stroke-width=\"%.3g\"", 0.6 * v->line);
    paths p = paths_open(f, "circles", style);
    for (size_t t = 0; t < s->tri_count; t++) {
        double w[2], c[2], r;
        if (!tri_ok(s, t) || !circumcentre(s, t, w, &r)) continue;
        to_canvas(v, w, c);
        r *= v->scale;
        if (!circle_visible(v, c, r)) continue;
        long long x = llround(c[0]), y = llround(c[1]), rr = llround(r);
        paths_next(&p);
        fprintf(f, "M%lld %llda%lld %lld 0 1 0 %lld 0a%lld %lld 0 1 0 %lld 0", x - rr, y, rr, rr, 2 * rr, rr, rr, -2 * rr);
    }
    paths_close(&p);
}

/* A dot per site: a zero-length subpath drawn with round caps. */
static void draw_sites(FILE *f, const view *v, const lh_cli_svg *s)
{
    char style[160];
    snprintf(style, sizeof style, "fill=\"none\" stroke=\"#111111\" stroke-width=\"%.3g\" stroke-linecap=\"round\"", v->dot);
    paths p = paths_open(f, "sites", style);
    for (size_t i = 0; i < s->site_count; i++) {
        double c[2];
        to_canvas(v, s->sites + 2 * i, c);
        if (!(c[0] >= 0 && c[0] <= v->width && c[1] >= 0 && c[1] <= v->height)) continue;
        paths_next(&p);
        fprintf(f, "M%lld %lldh0", llround(c[0]), llround(c[1]));
    }
    paths_close(&p);
}

/* ---- the document --------------------------------------------------------------------- */

static void put_escaped(FILE *f, const char *text)
{
    for (; *text; text++) {
        switch (*text) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default:
            if ((unsigned char)*text >= 0x20 || *text == '\t') putc(*text, f); /* no control chars */
        }
    }
}

/* The legend line: title, counts, then each drawn layer's name in its colour. */
static void put_legend(FILE *f, const lh_cli_svg *s)
{
    fprintf(f, "<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"%g\" fill=\"#333333\">", 0.02 * CANVAS,
            -0.4 * LEGEND, 0.36 * LEGEND);
    put_escaped(f, s->title ? s->title : "lifthull");
    fprintf(f, ": %zu sites, %zu triangles.", s->site_count, s->tri_count);
    if (s->draw_delaunay) fputs(" <tspan fill=\"#1f5fa8\">Delaunay edges</tspan>", f);
    if (s->draw_voronoi) fputs(" <tspan fill=\"#c8401a\">Voronoi diagram</tspan>", f);
    if (s->draw_circles) fputs(" <tspan fill=\"#2e8b57\">circumcircles</tspan>", f);
    if (s->draw_sites) fputs(" <tspan fill=\"#111111\">sites</tspan>", f);
    fputs("</text>\n", f);
}

/* Neighbours from the triangles alone: the two slots 3t+k holding the same edge (as
 * its sorted end points) are each other's neighbours. */
typedef struct edge_key {
    lh_index lo, hi, slot;
} edge_key;

static int edge_cmp(const void *pa, const void *pb)
{
    const edge_key *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

static lh_index *build_neighbors(const lh_cli_svg *s)
{
    size_t slots = 3 * s->tri_count;
    if (s->tri_count > LH_INDEX_MAX / 3) return NULL;
    lh_index *nb = malloc((slots ? slots : 1) * sizeof *nb);
    edge_key *e = malloc((slots ? slots : 1) * sizeof *e);
    if (!nb || !e) {
        free(nb);
        free(e);
        return NULL;
    }
    for (size_t i = 0; i < slots; i++) {
        lh_index a = s->tris[i - i % 3 + (i + 1) % 3], b = s->tris[i - i % 3 + (i + 2) % 3];
        e[i] = (edge_key){a < b ? a : b, a < b ? b : a, (lh_index)i};
        nb[i] = -1;
    }
    qsort(e, slots, sizeof *e, edge_cmp);
    for (size_t i = 0; i + 1 < slots; i++)
        if (e[i].lo == e[i + 1].lo && e[i].hi == e[i + 1].hi) {
            nb[e[i].slot] = e[i + 1].slot / 3;
            nb[e[i + 1].slot] = e[i].slot / 3;
            i++;
        }
    free(e);
    return nb;
}

int lh_cli_svg_shift(const double lo[2], const double hi[2])
{
    const double big = fmax(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fabs(lo[1]), fabs(hi[1])));
    int e = 0;
    if (big > 0 && isfinite(big)) frexp(big, &e);
    return e;
}

/* s with its sites multiplied by 2^-lh_cli_svg_shift of their finite box, in *copy
 * (malloc'ed): every construction below (circumcentres, rays, the view) then stays
 * finite. NULL when out of memory. */
static double *scaled_sites(const lh_cli_svg *s, lh_cli_svg *copy)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < 2 * s->site_count; i++)
        if (isfinite(s->sites[i])) lo[i % 2] = fmin(lo[i % 2], s->sites[i]), hi[i % 2] = fmax(hi[i % 2], s->sites[i]);
    const int e = lo[0] <= hi[0] && lo[1] <= hi[1] ? lh_cli_svg_shift(lo, hi) : 0;
    double *xy = malloc((s->site_count ? 2 * s->site_count : 1) * sizeof *xy);
    if (!xy) return NULL;
    for (size_t i = 0; i < 2 * s->site_count; i++) xy[i] = ldexp(s->sites[i], -e);
    *copy = *s;
    copy->sites = xy;
    return xy;
}

int lh_cli_svg_write(FILE *f, const lh_cli_svg *orig)
{
    lh_cli_svg scaled;
    double *xy = scaled_sites(orig, &scaled);
    if (!xy) return -1;
    const lh_cli_svg *s = &scaled;
    lh_index *own = NULL;
    const lh_index *nb = s->neighbors;
    if (!nb && s->tri_count && (s->draw_delaunay || s->draw_voronoi)) {
        nb = own = build_neighbors(s);
        if (!own) {
            free(xy);
            return -1;
        }
    }
    view v = view_fit(s);
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 %g %.0f %.0f\" width=\"%.0f\" height=\"%.0f\">\n",
            -LEGEND, ceil(v.width), ceil(v.height + LEGEND), ceil(v.width / 10), ceil((v.height + LEGEND) / 10));
    fputs("<title>", f);
    put_escaped(f, s->title ? s->title : "lifthull");
    fputs("</title>\n", f);
    fprintf(f, "<defs><clipPath id=\"lh-view\"><rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\"/></clipPath></defs>\n",
            ceil(v.width), ceil(v.height));
    fprintf(f, "<rect x=\"0\" y=\"%g\" width=\"%.0f\" height=\"%.0f\" fill=\"#fbfaf5\"/>\n", -LEGEND, ceil(v.width),
            ceil(v.height + LEGEND));
    fprintf(f, "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" fill=\"none\" stroke=\"#dddddd\" stroke-width=\"%.3g\"/>\n",
            ceil(v.width), ceil(v.height), v.line);
    put_legend(f, s);
    if (s->draw_circles) draw_circles(f, &v, s);
    if (s->draw_delaunay) draw_delaunay(f, &v, s, nb);
    if (s->draw_voronoi) draw_voronoi(f, &v, s, nb);
    if (s->draw_sites) draw_sites(f, &v, s);
    fputs("</svg>\n", f);
    free(own);
    free(xy);
    return fflush(f) != 0 || ferror(f) ? -1 : 0;
}
