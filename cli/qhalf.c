/*
 * qhalf.c — `lifthull qhalf OPTIONS`: Qhull's halfspace intersection. Halfspace i,
 * a_i.x + b_i <= 0 (Qhull's input: d+1 coefficients, the offset last), becomes by
 * polarity about an interior point c the dual point p_i = a_i / s_i with
 * s_i = -(a_i.c + b_i) > 0 (Preparata and Shamos, "Computational Geometry", 1985,
 * sec. 7.2.5). The halfspaces that bound the intersection are the vertices of the
 * dual points' convex hull, and each hull facet n.p + off = 0 is a vertex
 * x = c + n / -off of the intersection, tight on the facet's halfspaces.
 *
 * Precision: each dual coordinate is rounded once; their hull, and which hull facets
 * lie on one hyperplane (merged into one intersection point, as Qhull merges them),
 * are exact for those rounded points; each intersection point is computed from its
 * halfspaces' own coefficients (tight_point): a few ulps from the exact point.
 * The interior point comes from option Hn,n,..., the input's first point, or is the
 * origin when that is strictly inside every halfspace (Qhull requires one).
 */
#include "cli.h"
#include "outfile.h"
#include "qhull.h"
#include "qhull_print.h"
#include "qhull_sides.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct halfspaces {
    int d;        /* dimension of the space: d + 1 coefficients per halfspace */
    size_t n;
    double *h;    /* n * (d + 1): a_i, then b_i                              */
    double c[LH_DELAUNAY_MAX_DIM];
    int has_c;    /* from the input's first point                            */
} halfspaces;

/* A token reader over the whole input with line numbers. */
typedef struct scan {
    const char *s, *name;
    size_t line;
} scan;

static void skip_blank(scan *t, int newlines)
{
    for (; *t->s && isspace((unsigned char)*t->s) && (newlines || *t->s != '\n'); t->s++)
        t->line += *t->s == '\n';
}

/* The next number (across lines); 0 after printing an error naming `what`. */
static int number(scan *t, double *v, const char *what)
{
    skip_blank(t, 1);
    char *end;
    errno = 0;
    *v = strtod(t->s, &end);
    if (end == t->s || !isfinite(*v) || (*end && !isspace((unsigned char)*end))) {
        fprintf(stderr, "%s:%zu: expected %s, found %s\n", t->name, t->line, what,
                *t->s ? "text that is not a finite number" : "the end of the input");
        return 0;
    }
    t->s = end;
    return 1;
}

/* A count or a dimension as a long: -1 when it is not a whole number in 0..2^31. */
static long whole(double v)
{
    return v >= 0 && v <= 2147483648.0 && v == floor(v) ? (long)v : -1;
}

/* A header line: an integer, then either a second integer on the same line or a
 * comment (then the count is the next number, on a later line). */
static int header(scan *t, long *dim, long *count)
{
    double v;
    if (!number(t, &v, "a dimension")) return 0;
    *dim = whole(v);
    skip_blank(t, 0);
    char *end;
    double c = *t->s && *t->s != '\n' ? strtod(t->s, &end) : 0;
    if (*t->s && *t->s != '\n' && end != t->s && (!*end || isspace((unsigned char)*end))) {
        t->s = end;
    } else {
        while (*t->s && *t->s != '\n') t->s++; /* a comment, as rbox writes */
        if (!number(t, &c, "the number of halfspaces")) return 0;
    }
    *count = whole(c);
    return 1;
}

static char *slurp(FILE *f, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *b = malloc(cap + 1);
    for (size_t k; b && (k = fread(b + n, 1, cap - n, f)) > 0;) {
        n += k;
        if (n == cap) {
            char *g = realloc(b, 2 * cap + 1);
            if (!g) free(b);
            b = g;
            cap *= 2;
        }
    }
    if (b) b[n] = 0;
    *len = n;
    return b;
}

static int read_halfspaces(const char *file, halfspaces *hs, const char **name)
{
    FILE *f = stdin;
    *name = "<stdin>";
    if (file && strcmp(file, "-")) {
        *name = file;
        if (!(f = lh_cli_open_input(file))) return 0; /* said: missing, a directory, ... */
    }
    size_t len;
    char *text = slurp(f, &len);
    int bad = ferror(f);
    if (f != stdin) fclose(f);
    if (!text || bad) {
        fprintf(stderr, "%s: %s\n", *name, text ? "read error" : "out of memory");
        free(text);
        return 0;
    }
    scan t = {text, *name, 1};
    long dim, count;
    int ok = header(&t, &dim, &count);
    if (ok && count == 1 && dim >= 2 && dim <= LH_DELAUNAY_MAX_DIM) { /* the interior point */
        long cdim = dim;
        hs->has_c = 1;
        for (long j = 0; ok && j < dim; j++) ok = number(&t, &hs->c[j], "a coordinate of the interior point");
        if (ok) ok = header(&t, &dim, &count);
        if (ok && dim != cdim + 1) {
            fprintf(stderr, "%s:%zu: the interior point has %ld coordinates, so the halfspaces need "
                    "%ld coefficients, not %ld\n", *name, t.line, cdim, cdim + 1, dim);
            ok = 0;
        }
    }
    if (ok && (dim < 3 || dim > LH_DELAUNAY_MAX_DIM + 1 || count < 1 || count > (1L << 30))) {
        fprintf(stderr, "%s:%zu: expected halfspaces of 3..%d coefficients (2-d..%d-d) and a positive "
                "count, found %ld and %ld\n", *name, t.line, LH_DELAUNAY_MAX_DIM + 1,
                LH_DELAUNAY_MAX_DIM, dim, count);
        ok = 0;
    }
    if (ok) {
        hs->d = (int)dim - 1;
        hs->n = (size_t)count;
        hs->h = malloc(hs->n * (size_t)dim * sizeof *hs->h);
        if (!hs->h) fprintf(stderr, "%s: out of memory\n", *name);
        ok = hs->h != NULL;
    }
    for (size_t i = 0; ok && i < hs->n * (size_t)dim; i++) ok = number(&t, &hs->h[i], "a coefficient");
    if (ok) {
        skip_blank(&t, 1);
        if (*t.s) {
            fprintf(stderr, "%s:%zu: more than the %zu halfspaces announced\n", *name, t.line, hs->n);
            ok = 0;
        }
    }
    free(text);
    return ok;
}

/* The intersection's vertices: groups of dual hull facets on one hyperplane. */
typedef struct result {
    lh_hull *hull;
    double *dual;       /* n * d                                     */
    size_t groups;
    lh_index *group_of; /* per hull facet: its group                */
    double *point;      /* groups * d: the intersection points        */
    lh_index *off, *idx; /* group g's halfspaces: idx[off[g]..off[g+1]) */
} result;

static int increasing(const void *a, const void *b)
{
    lh_index x = *(const lh_index *)a, y = *(const lh_index *)b;
    return (x > y) - (x < y);
}

static lh_index find(lh_index *up, lh_index x)
{
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
}

/* Merges neighbouring facets whose hyperplanes coincide (exact orient_d = 0 of one
 * facet with the other's opposite vertex). */
static int merge_coplanar(const halfspaces *hs, result *r, lh_pred *pred, lh_index *up)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    const lh_index *v = lh_hull_facets(r->hull);
    lh_index *nbr = malloc((m ? m : 1) * d * sizeof *nbr);
    if (!nbr || !lh_cli_pair_within(d, m, v, nbr)) {
        free(nbr);
        return 0;
    }
    for (size_t f = 0; f < m; f++) up[f] = (lh_index)f;
    for (size_t f = 0; f < m; f++)
        for (int k = 0; k < d; k++) {
            lh_index g = nbr[f * d + k];
            if (g < 0 || (size_t)g < f) continue;
            const double *p[LH_DELAUNAY_MAX_DIM + 1];
            for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)v[f * d + j] * d;
            for (int j = 0; j < d; j++) { /* g's vertex that f lacks */
                lh_index w = v[(size_t)g * d + j];
                int in = 0;
                for (int i = 0; i < d; i++) in |= v[f * d + i] == w;
                if (!in) p[d] = r->dual + (size_t)w * d;
            }
            if (lh_orient(pred, d, p) == 0) up[find(up, (lh_index)f)] = find(up, g);
        }
    free(nbr);
    return 1;
}

/* The point where the d halfspaces v are tight, from their own coefficients:
 * (t x, t) spans the null space of the rows (a_i, b_i), i.e. is the normal of the
 * hyperplane of R^(d+1) through them and the origin (lh_hyperplane: exact cofactors,
 * each rounded once), so x is within a few ulps of the exact intersection, and
 * exact when its coordinates are simple ratios of the coefficients. 0 when
 * d + 1 > LH_ORIENT_MAX_DIM (then the dual facet's plane gives x). */
static int tight_point(const halfspaces *hs, lh_pred *pred, const lh_index *v, double *x)
{
    const int d = hs->d, D = d + 1;
    if (D > LH_ORIENT_MAX_DIM) return 0;
    const double origin[LH_DELAUNAY_MAX_DIM + 1] = {0};
    const double *p[LH_DELAUNAY_MAX_DIM + 1] = {origin};
    for (int i = 0; i < d; i++) p[i + 1] = hs->h + (size_t)v[i] * D;
    double n[LH_DELAUNAY_MAX_DIM + 1], off;
    if (!lh_hyperplane(pred, D, p, n, &off) || n[d] == 0) return 0;
    for (int j = 0; j < d; j++) x[j] = n[j] / n[d];
    return 1;
}

/* Groups (the facets' classes, in the order of their first facet), their points and
 * their halfspaces (increasing). */
static int collect(const halfspaces *hs, result *r, lh_pred *pred, lh_index *up)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    const lh_index *v = lh_hull_facets(r->hull);
    lh_index *first = malloc((m ? m : 1) * sizeof *first); /* facets by group */
    lh_index *start = calloc(m + 1, sizeof *start);
    r->group_of = malloc((m ? m : 1) * sizeof *r->group_of);
    r->point = malloc((m ? m : 1) * d * sizeof *r->point);
    r->off = calloc(m + 1, sizeof *r->off);
    r->idx = malloc((m ? m : 1) * d * sizeof *r->idx);
    lh_index *mark = malloc((hs->n ? hs->n : 1) * sizeof *mark);
    int ok = first && start && r->group_of && r->point && r->off && r->idx && mark;
    r->groups = 0;
    for (size_t f = 0; ok && f < m; f++) /* number the groups by their first facet */
        r->group_of[f] = find(up, (lh_index)f) == (lh_index)f ? (lh_index)r->groups++ : -1;
    for (size_t f = 0; ok && f < m; f++) {
        r->group_of[f] = r->group_of[find(up, (lh_index)f)];
        start[r->group_of[f] + 1]++;
    }
    for (size_t g = 0; ok && g < r->groups; g++) start[g + 1] += start[g];
    for (size_t f = 0; ok && f < m; f++) first[start[r->group_of[f]]++] = (lh_index)f;
    for (size_t g = r->groups; ok && g > 0; g--) start[g] = start[g - 1];
    if (ok) start[0] = 0;
    for (size_t i = 0; ok && i < hs->n; i++) mark[i] = -1;
    for (size_t g = 0; ok && g < r->groups; g++) {
        size_t f = (size_t)first[start[g]];
        const double *p[LH_DELAUNAY_MAX_DIM];
        for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)v[f * d + j] * d;
        if (!tight_point(hs, pred, v + f * d, r->point + g * d)) {
            double n[LH_DELAUNAY_MAX_DIM], o;
            lh_hyperplane(pred, d, p, n, &o);
            double sign = o > 0 ? -1 : 1; /* outward: n.0 + o < 0, the interior point inside */
            for (int j = 0; j < d; j++) r->point[g * d + j] = hs->c[j] + (sign * n[j]) / -(sign * o);
        }
        size_t c = (size_t)r->off[g], from = c;
        for (lh_index e = start[g]; e < start[g + 1]; e++)
            for (int j = 0; j < d; j++) {
                lh_index w = v[(size_t)first[e] * d + j];
                if (mark[w] != (lh_index)g) mark[w] = (lh_index)g, r->idx[c++] = w;
            }
        qsort(r->idx + from, c - from, sizeof *r->idx, increasing);
        r->off[g + 1] = (lh_index)c;
    }
    free(first);
    free(start);
    free(mark);
    return ok;
}

static void result_free(result *r)
{
    lh_hull_free(r->hull);
    free(r->dual);
    free(r->group_of);
    free(r->point);
    free(r->off);
    free(r->idx);
}

/* The dual points, their hull, its facets grouped by hyperplane. 0 after printing
 * the problem. */
static int compute(const halfspaces *hs, const lh_cli_qopts *o, const char *name, result *r,
                   double *seconds)
{
    const int d = hs->d;
    memset(r, 0, sizeof *r);
    r->dual = malloc(hs->n * d * sizeof *r->dual);
    if (!r->dual) {
        fprintf(stderr, "%s: out of memory\n", name);
        return 0;
    }
    for (size_t i = 0; i < hs->n; i++) {
        const double *a = hs->h + i * (d + 1);
        double s = -a[d];
        for (int j = 0; j < d; j++) s -= a[j] * hs->c[j];
        if (!(s > 0)) {
            fprintf(stderr, "lifthull %s: the interior point is not strictly inside halfspace %zu "
                    "(a.c + b = %g, must be < 0)\n", o->name, i, -s);
            return 0;
        }
        for (int j = 0; j < d; j++) r->dual[i * d + j] = a[j] / s;
    }
    double t0 = lh_cli_seconds();
    lh_status st = lh_convex_hull(d, hs->n, r->dual, NULL, &r->hull);
    *seconds = lh_cli_seconds() - t0;
    if (st == LH_ERR_DEGENERATE) {
        fprintf(stderr, "lifthull %s: the halfspaces' normals span less than R^%d: their "
                "intersection is unbounded\n", o->name, d);
        return 0;
    }
    if (st != LH_OK) {
        fprintf(stderr, "%s: %s\n", name, lh_status_message(st));
        return 0;
    }
    lh_pred *pred = NULL;
    const size_t m = lh_hull_facet_count(r->hull);
    lh_index *up = malloc((m ? m : 1) * sizeof *up);
    int ok = up && lh_pred_create(NULL, &pred) == LH_OK;
    /* bounded: the interior point (the duals' origin) strictly inside every facet */
    const double zero[LH_DELAUNAY_MAX_DIM] = {0};
    for (size_t f = 0; ok && f < m; f++) {
        const double *p[LH_DELAUNAY_MAX_DIM + 1];
        for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)lh_hull_facets(r->hull)[f * d + j] * d;
        p[d] = zero;
        if (lh_orient(pred, d, p) >= 0) {
            fprintf(stderr, "lifthull %s: the intersection is unbounded (no halfspace bounds it "
                    "in some direction)\n", o->name);
            lh_pred_free(pred);
            free(up);
            return 0;
        }
    }
    ok = ok && merge_coplanar(hs, r, pred, up) && collect(hs, r, pred, up);
    if (!ok) fprintf(stderr, "%s: out of memory\n", name);
    lh_pred_free(pred);
    free(up);
    return ok;
}

static void print_half(FILE *f, const lh_cli_qopts *o, const halfspaces *hs, const result *r,
                       const char *opt, double seconds)
{
    const int d = hs->d;
    if (!strcmp(opt, "Fp")) {
        fprintf(f, "%d\n%zu\n", d, r->groups);
        for (size_t g = 0; g < r->groups; g++) {
            lh_cli_qcoords(f, r->point + g * d, d);
            fputc('\n', f);
        }
    } else if (!strcmp(opt, "i") || !strcmp(opt, "Fv")) {
        fprintf(f, "%zu\n", r->groups);
        for (size_t g = 0; g < r->groups; g++) {
            if (opt[0] == 'F') fprintf(f, "%" LH_INDEX_PRI, r->off[g + 1] - r->off[g]);
            for (lh_index k = r->off[g]; k < r->off[g + 1]; k++)
                fprintf(f, opt[0] == 'F' ? " %" LH_INDEX_PRI : "%" LH_INDEX_PRI " ", r->idx[k]);
            fputc('\n', f);
        }
    } else if (!strcmp(opt, "Fx")) {
        size_t nv = lh_hull_vertex_count(r->hull);
        fprintf(f, "%zu\n", nv);
        for (size_t i = 0; i < nv; i++) fprintf(f, "%" LH_INDEX_PRI "\n", lh_hull_vertices(r->hull)[i]);
    } else { /* s */
        fprintf(f, "\nHalfspace intersection by the convex hull of %zu points in %d-d:\n\n"
                   "  Number of halfspaces: %zu\n  Number of non-redundant halfspaces: %zu\n"
                   "  Number of intersection points: %zu\n\nStatistics for: %s\n\n"
                   "  Exact arithmetic on the dual points (each rounded once)\n"
                   "  CPU seconds to compute the hull: %.3g\n\n",
                hs->n, d, hs->n, lh_hull_vertex_count(r->hull), r->groups, o->command, seconds);
    }
}

/* Without H or a point in the input, the origin serves when it is strictly inside
 * every halfspace (every b < 0), as for the planes of a hull around it. */
static int origin_inside(halfspaces *hs)
{
    for (size_t i = 0; i < hs->n; i++)
        if (!(hs->h[i * (hs->d + 1) + hs->d] < 0)) return 0;
    memset(hs->c, 0, sizeof hs->c);
    return 1;
}

int lh_cli_qhalf(int argc, char **argv)
{
    lh_cli_qopts o;
    int rc = lh_cli_qparse(&o, LH_QPROG_HALF, argc, argv);
    if (rc != 0) return rc > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check(o.name, o.output, 1, o.input)) return LH_EXIT_FAIL; /* before the input */
    halfspaces hs = {0};
    const char *name;
    if (!read_halfspaces(o.input, &hs, &name)) {
        free(hs.h);
        return LH_EXIT_INPUT;
    }
    if (o.ninterior) {
        if (o.ninterior > hs.d) {
            fprintf(stderr, "lifthull qhalf: option 'H' gives %d coordinates for %d-d halfspaces\n",
                    o.ninterior, hs.d);
            free(hs.h);
            return LH_EXIT_USAGE;
        }
        for (int j = 0; j < hs.d; j++) hs.c[j] = j < o.ninterior ? o.interior[j] : 0;
    } else if (!hs.has_c && !origin_inside(&hs)) {
        fprintf(stderr, "lifthull qhalf: an interior point is needed (the origin is not strictly "
                "inside every halfspace): prepend one to the input (a line 'd 1', then its d "
                "coordinates) or give option Hn,n,...\n");
        free(hs.h);
        return LH_EXIT_USAGE;
    }
    result r;
    double seconds = 0;
    if (!compute(&hs, &o, name, &r, &seconds)) {
        result_free(&r);
        free(hs.h);
        return LH_EXIT_FAIL;
    }
    if (o.show_options) fprintf(stderr, "Options selected for %s\n", o.command);
    lh_cli_out out;
    int ok = lh_cli_out_open(&out, o.name, o.output, 1, o.input);
    for (int i = 0; ok && i < o.nout; i++)
        print_half(!strcmp(o.out[i], "s") && !o.summary_default ? stderr : out.f, &o, &hs, &r,
                   o.out[i], seconds);
    int status = out.f ? lh_cli_out_close(&out, o.name, ok) : LH_EXIT_FAIL;
    result_free(&r);
    free(hs.h);
    return status;
}
