/*
 * qhalf.c — `lifthull qhalf OPTIONS`: Qhull's halfspace intersection. Halfspace i,
 * a_i.x + b_i <= 0 (Qhull's input: d+1 coefficients, the offset last), becomes by
 * polarity about an interior point c the dual point p_i = a_i / s_i with
 * s_i = -(a_i.c + b_i) > 0 (Preparata and Shamos, "Computational Geometry", 1985,
 * sec. 7.2.5). The halfspaces that bound the intersection are the vertices of the
 * dual points' convex hull, and each hull facet n.p + off = 0 is a vertex
 * x = c + n / -off of the intersection, tight on the facet's halfspaces.
 *
 * Precision: s_i is a.c + b in twice the precision, rounded (dot2), each dual
 * coordinate one more rounding; their hull, and which hull facets lie on one
 * hyperplane (merged into one intersection point, as Qhull merges them), are exact
 * for those rounded points; each intersection point is computed from its
 * halfspaces' own coefficients (tight_point): a few ulps from the exact point.
 * The interior point comes from option Hn,n,..., the input's first point, or is the
 * origin when that is strictly inside every halfspace, or else the halfspaces'
 * Chebyshev centre (qhalf_lp.c; Qhull requires one); whichever, it is checked to be
 * strictly inside every halfspace exactly (inside_sign) before it is used.
 */
#include "cli.h"
#include "outfile.h"
#include "qhalf.h"
#include "qhull.h"
#include "qhull_print.h"
#include "qhull_sides.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef lh_cli_halfspaces halfspaces;
typedef lh_cli_hresult result;

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
 * facet with the other's opposite vertex); keeps the facets' neighbours in r->nbr. */
static int merge_coplanar(const halfspaces *hs, result *r, lh_index *up)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    const lh_index *v = lh_hull_facets(r->hull);
    r->nbr = malloc((m ? m : 1) * d * sizeof *r->nbr);
    if (!r->nbr || !lh_cli_pair_within(d, m, v, r->nbr)) return 0;
    for (size_t f = 0; f < m; f++) up[f] = (lh_index)f;
    for (size_t f = 0; f < m; f++)
        for (int k = 0; k < d; k++) {
            lh_index g = r->nbr[f * d + k];
            if (g < 0 || (size_t)g < f) continue;
            const double *p[LH_DELAUNAY_MAX_DIM + 1];
            for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)v[f * d + j] * d;
            for (int j = 0; j < d; j++) { /* g's vertex that f lacks */
                lh_index w = v[(size_t)g * d + j];
                int in = 0;
                for (int i = 0; i < d; i++) in |= v[f * d + i] == w;
                if (!in) p[d] = r->dual + (size_t)w * d;
            }
            if (lh_orient(r->pred, d, p) == 0) up[find(up, (lh_index)f)] = find(up, g);
        }
    return 1;
}

/* The point where the d halfspaces v are tight, from their own coefficients:
 * (t x, t) spans the null space of the rows (a_i, b_i), i.e. is the normal of the
 * hyperplane of R^(d+1) through them and the origin (lh_hyperplane: exact cofactors,
 * each rounded once), so x is within a few ulps of the exact intersection, and
 * exact when its coordinates are simple ratios of the coefficients. x = m 2^e with
 * each m_j = n_j / (n_d 2^-e) rounded once, |m_j| <= 2: finite wherever x passes
 * DBL_MAX. 0 when d + 1 > LH_ORIENT_MAX_DIM (then the dual facet's plane gives x). */
static int tight_point(const halfspaces *hs, lh_pred *pred, const lh_index *v, double *m, int *e)
{
    const int d = hs->d, D = d + 1;
    if (D > LH_ORIENT_MAX_DIM) return 0;
    const double origin[LH_DELAUNAY_MAX_DIM + 1] = {0};
    const double *p[LH_DELAUNAY_MAX_DIM + 1] = {origin};
    for (int i = 0; i < d; i++) p[i + 1] = hs->h + (size_t)v[i] * D;
    double n[LH_DELAUNAY_MAX_DIM + 1], off;
    if (!lh_hyperplane(pred, D, p, n, &off) || n[d] == 0) return 0;
    int k;
    double top = frexp(n[d], &k); /* n_d = top 2^k, |top| in [0.5, 1) */
    for (int j = 0; j < d; j++) m[j] = n[j] / top;
    *e = -k;
    if (*e < 900) { /* an ordinary point: plain doubles (2^e m exact, finite) */
        for (int j = 0; j < d; j++) m[j] = ldexp(m[j], *e);
        *e = 0;
    }
    return 1;
}

/* The same from the dual facet's hyperplane n.y + o = 0 (n outward, o < 0):
 * x = c + n / -o, as m 2^e with m_j = c_j 2^-e + (n_j / -o) 2^-e, 2^e at least the
 * largest |c_j| and 1 / |o|: one rounding per coordinate, finite everywhere. */
static void dual_point(const halfspaces *hs, const result *r, const lh_index *v, double *m, int *e)
{
    const int d = hs->d;
    const double *p[LH_DELAUNAY_MAX_DIM];
    for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)v[j] * d;
    double n[LH_DELAUNAY_MAX_DIM], om;
    int oe, ce = 0;
    lh_hyperplane_exp(r->pred, d, p, n, &om, &oe);
    double sign = om > 0 ? -1 : 1; /* outward: the duals' origin inside, n.0 + o < 0 */
    for (int j = 0; j < d; j++) {
        int k;
        frexp(hs->c[j], &k);
        if (hs->c[j] != 0 && k > ce) ce = k;
    }
    *e = ce > 1 - oe ? ce : 1 - oe;
    for (int j = 0; j < d; j++)
        m[j] = ldexp(hs->c[j], -*e) + ldexp((sign * n[j]) / -(sign * om), -oe - *e);
    if (*e < 900) {
        for (int j = 0; j < d; j++) m[j] = ldexp(m[j], *e);
        *e = 0;
    }
}

/* Groups (the facets' classes, in the order of their first facet), their points and
 * their halfspaces (increasing). */
static int collect(const halfspaces *hs, result *r, lh_index *up)
{
    const int d = hs->d;
    const size_t m = lh_hull_facet_count(r->hull);
    const lh_index *v = lh_hull_facets(r->hull);
    lh_index *first = malloc((m ? m : 1) * sizeof *first); /* facets by group */
    lh_index *start = calloc(m + 1, sizeof *start);
    r->group_of = malloc((m ? m : 1) * sizeof *r->group_of);
    r->facets = malloc((m ? m : 1) * sizeof *r->facets);
    r->first = malloc((m ? m : 1) * sizeof *r->first);
    r->point = malloc((m ? m : 1) * d * sizeof *r->point);
    r->exp = malloc((m ? m : 1) * sizeof *r->exp);
    r->off = calloc(m + 1, sizeof *r->off);
    r->idx = malloc((m ? m : 1) * d * sizeof *r->idx);
    lh_index *mark = malloc((hs->n ? hs->n : 1) * sizeof *mark);
    int ok = first && start && r->group_of && r->facets && r->first && r->point && r->exp && r->off &&
             r->idx && mark;
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
        r->first[g] = (lh_index)f;
        r->facets[g] = start[g + 1] - start[g];
        if (!tight_point(hs, r->pred, v + f * d, r->point + g * d, &r->exp[g]))
            dual_point(hs, r, v + f * d, r->point + g * d, &r->exp[g]);
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
    lh_pred_free(r->pred);
    free(r->dual);
    free(r->nbr);
    free(r->group_of);
    free(r->facets);
    free(r->first);
    free(r->point);
    free(r->exp);
    free(r->off);
    free(r->idx);
}

/* The exact sign of a.c + b for halfspace i: the determinant of the rows (a, b) and
 * (e_j, -c_j), j = 1..d, is (-1)^d (a.c + b) (add c_j times column j to the last
 * one), an orient_(d+1) of those rows about the origin; its sign convention is
 * taken from the same rows with (a, b) = (0, 1). 2 when d + 1 > LH_ORIENT_MAX_DIM. */
static int inside_sign(const halfspaces *hs, lh_pred *pred, size_t i)
{
    const int d = hs->d, D = d + 1;
    if (D > LH_ORIENT_MAX_DIM) return 2;
    double rows[LH_DELAUNAY_MAX_DIM + 1][LH_DELAUNAY_MAX_DIM + 1] = {{0}};
    const double origin[LH_DELAUNAY_MAX_DIM + 1] = {0};
    const double *p[LH_DELAUNAY_MAX_DIM + 2] = {origin};
    for (int j = 0; j < d; j++) {
        rows[j + 1][j] = 1;
        rows[j + 1][d] = -hs->c[j];
    }
    rows[0][d] = 1;
    for (int j = 0; j <= d; j++) p[j + 1] = rows[j];
    int unit = lh_orient(pred, D, p); /* the sign of (-1)^d * 1 */
    memcpy(rows[0], hs->h + i * D, D * sizeof rows[0][0]);
    return unit * lh_orient(pred, D, p);
}

/* a.c + b as if computed in twice the working precision, then rounded (Dot2: Ogita,
 * Rump and Oishi, "Accurate sum and dot product", SIAM J. Sci. Comput. 26, 2005):
 * error-free products (fma) and sums (TwoSum). +-inf where a term or the sum passes
 * DBL_MAX (the plain sum then). */
static double dot2(const double *a, const double *c, int d)
{
    double s = a[d], e = 0, plain = a[d];
    for (int j = 0; j < d; j++) {
        double p = a[j] * c[j], ep = fma(a[j], c[j], -p);
        double t = s + p, z = t - s;
        e += ep + ((s - (t - z)) + (p - z));
        s = t;
        plain += p;
    }
    return isfinite(s + e) ? s + e : plain;
}

/* Halfspace i's dual point a / -(a.c + b); 0 after saying why there is none. */
static int dual_of(const halfspaces *hs, result *r, size_t i, const char *name, const char *from)
{
    const int d = hs->d;
    const double *a = hs->h + i * (d + 1);
    double s = -dot2(a, hs->c, d);
    int sign = inside_sign(hs, r->pred, i);
    if (sign == 2) sign = s > 0 ? -1 : s < 0 ? 1 : 0; /* 8-d: the rounded value */
    const char *where = sign > 0 ? "outside" : sign == 0 ? "on the boundary of" : NULL;
    if (where) {
        char v[40] = "> DBL_MAX";
        if (sign == 0) snprintf(v, sizeof v, "= 0%s", d + 1 <= LH_ORIENT_MAX_DIM ? " exactly" : "");
        else if (isfinite(s)) snprintf(v, sizeof v, "= %.17g", -s);
        fprintf(stderr, "%s:%zu: the interior point (%s) is %s halfspace %zu (a.c + b %s): it "
                "must be strictly inside every halfspace\n", name, hs->line[i], from, where, i, v);
        return 0;
    }
    int finite = s > 0 && isfinite(s);
    for (int j = 0; finite && j < d; j++) finite = isfinite(r->dual[i * d + j] = a[j] / s);
    if (!finite) {
        char v[40] = "|a.c + b| > DBL_MAX: too far from it";
        if (isfinite(s)) snprintf(v, sizeof v, "a.c + b = %.17g", -s);
        fprintf(stderr, "%s:%zu: the interior point (%s) is strictly inside halfspace %zu, but %s%s, "
                "so its dual point a / -(a.c + b) is not a finite double; choose a point %s\n", name,
                hs->line[i], from, i, v, isfinite(s) ? ": too near its boundary" : "",
                isfinite(s) ? "further inside" : "nearer to it");
        return 0;
    }
    return 1;
}

/* The dual points, their hull, its facets grouped by hyperplane. 0 after printing
 * the problem (exit status in *status). */
static int compute(const halfspaces *hs, const lh_cli_qopts *o, const char *name, const char *from,
                   result *r, int *status)
{
    const int d = hs->d;
    memset(r, 0, sizeof *r);
    *status = LH_EXIT_FAIL;
    r->dual = malloc(hs->n * d * sizeof *r->dual);
    if (!r->dual || lh_pred_create(NULL, &r->pred) != LH_OK) {
        fprintf(stderr, "%s: out of memory\n", name);
        return 0;
    }
    for (size_t i = 0; i < hs->n; i++)
        if (!dual_of(hs, r, i, name, from)) {
            *status = LH_EXIT_INPUT;
            return 0;
        }
    double t0 = lh_cli_seconds();
    lh_status st = lh_convex_hull(d, hs->n, r->dual, NULL, &r->hull);
    r->seconds = lh_cli_seconds() - t0;
    if (st == LH_ERR_DEGENERATE) {
        fprintf(stderr, "lifthull %s: the halfspaces' normals span less than R^%d: their "
                "intersection is unbounded\n", o->name, d);
        return 0;
    }
    if (st != LH_OK) {
        fprintf(stderr, "%s: %s\n", name, lh_status_message(st));
        return 0;
    }
    const size_t m = lh_hull_facet_count(r->hull);
    /* bounded: the interior point (the duals' origin) strictly inside every facet */
    const double zero[LH_DELAUNAY_MAX_DIM] = {0};
    for (size_t f = 0; f < m; f++) {
        const double *p[LH_DELAUNAY_MAX_DIM + 1];
        for (int j = 0; j < d; j++) p[j] = r->dual + (size_t)lh_hull_facets(r->hull)[f * d + j] * d;
        p[d] = zero;
        if (lh_orient(r->pred, d, p) >= 0) {
            fprintf(stderr, "lifthull %s: the intersection is unbounded (no halfspace bounds it "
                    "in some direction)\n", o->name);
            return 0;
        }
    }
    lh_index *up = malloc((m ? m : 1) * sizeof *up);
    int ok = up && merge_coplanar(hs, r, up) && collect(hs, r, up);
    if (!ok) fprintf(stderr, "%s: out of memory\n", name);
    free(up);
    return ok;
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

/* Whether an output prints the dual hull (qconvex's printers). */
static int dual_output(const char *w)
{
    static const char *const words[] = {"o", "G", "m", "FM", "f", "FF"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (!strcmp(w, words[i])) return 1;
    return 0;
}

/* The interior point: option H, the input's, or the origin; 0 after the message. */
static int interior_point(const lh_cli_qopts *o, halfspaces *hs, const char **from)
{
    if (o->ninterior) {
        if (o->ninterior > hs->d) {
            fprintf(stderr, "lifthull qhalf: option 'H' gives %d coordinates for %d-d halfspaces\n",
                    o->ninterior, hs->d);
            return 0;
        }
        for (int j = 0; j < hs->d; j++) hs->c[j] = j < o->ninterior ? o->interior[j] : 0;
        *from = "option H";
        return 1;
    }
    *from = hs->has_c ? "the input's first point" : "the origin";
    if (hs->has_c || origin_inside(hs)) return 1;
    *from = "the Chebyshev centre";
    if (lh_cli_qhalf_centre(hs, hs->c)) {
        fprintf(stderr, "lifthull qhalf: no interior point given, the origin not inside: using the "
                "halfspaces' Chebyshev centre H");
        for (int j = 0; j < hs->d; j++) fprintf(stderr, "%s%.17g", j ? "," : "", hs->c[j]);
        fputc('\n', stderr);
        return 1;
    }
    fprintf(stderr, "lifthull qhalf: an interior point is needed: the origin is not strictly "
            "inside every halfspace and the linear program for their Chebyshev centre found no "
            "ball inside them (their intersection may be empty, flat or unbounded): prepend a "
            "point to the input (a line 'd 1', then its d coordinates) or give option Hn,n,...\n");
    return 0;
}

/* Prints every output asked for; 0 after a message. */
static int print_all(FILE *out, const lh_cli_qopts *o, const halfspaces *hs, const result *r,
                     const char *name)
{
    lh_cli_qmodel mo;
    lh_cli_qopts oc = *o; /* the dual points' hull through qconvex's printers */
    oc.prog = LH_QPROG_CONVEX;
    oc.verify = 0;
    int model = 0, ok = 1;
    for (int i = 0; i < o->nout; i++) model |= dual_output(o->out[i]);
    if (model && !lh_cli_qmodel_build(&mo, &oc, hs->d, hs->n, r->dual, name)) return 0;
    for (int i = 0; ok && i < o->nout; i++) {
        FILE *f = !strcmp(o->out[i], "s") && !o->summary_default ? stderr : out;
        if (dual_output(o->out[i])) {
            ok = lh_cli_qprint(f, &oc, &mo, o->out[i]);
            if (!ok) fprintf(stderr, "lifthull qhalf: out of memory\n");
        } else {
            ok = lh_cli_qhalf_print(f, o, hs, r, o->out[i]);
        }
    }
    if (model) lh_cli_qmodel_free(&mo);
    return ok;
}

int lh_cli_qhalf(int argc, char **argv)
{
    lh_cli_qopts o;
    int rc = lh_cli_qparse(&o, LH_QPROG_HALF, argc, argv);
    if (rc != 0) return rc > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    if (!lh_cli_out_check(o.name, o.output, 1, o.input)) return LH_EXIT_FAIL; /* before the input */
    halfspaces hs = {0};
    const char *name, *from;
    if (!lh_cli_qhalf_read(o.input, o.cdd, &hs, &name)) {
        free(hs.h);
        free(hs.line);
        return LH_EXIT_INPUT;
    }
    if (hs.comment[0]) { /* Qhull's FQ, s and G name the input's comment first */
        char cmd[sizeof o.command + sizeof hs.comment + 4];
        snprintf(cmd, sizeof cmd, "%s | %s", hs.comment, o.command);
        memcpy(o.command, cmd, sizeof o.command - 1); /* cut to the buffer */
        o.command[sizeof o.command - 1] = 0;
    }
    lh_cli_qopts oc = o;
    oc.prog = LH_QPROG_CONVEX;
    if (!interior_point(&o, &hs, &from) || !lh_cli_qcheck_outputs(&oc, hs.d, hs.n)) {
        free(hs.h);
        free(hs.line);
        return LH_EXIT_USAGE;
    }
    result r;
    int status;
    if (!compute(&hs, &o, name, from, &r, &status) || (o.verify && !lh_cli_qhalf_verify(&o, &hs, &r))) {
        result_free(&r);
        free(hs.h);
        free(hs.line);
        return status;
    }
    if (o.show_options) fprintf(stderr, "Options selected for %s\n", o.command);
    lh_cli_out out;
    int ok = lh_cli_out_open(&out, o.name, o.output, 1, o.input) && print_all(out.f, &o, &hs, &r, name);
    if (ok && o.stats)
        fprintf(stderr, "\nlifthull statistics: %s\n\n%10zu halfspaces in %d-d\n%10zu non-redundant "
                "(vertices of the dual hull)\n%10zu facets of the dual hull\n%10zu intersection points\n"
                "%10.3g CPU seconds for the dual hull\n\n", o.command, hs.n, hs.d,
                lh_hull_vertex_count(r.hull), lh_hull_facet_count(r.hull), r.groups, r.seconds);
    int status2 = out.f ? lh_cli_out_close(&out, o.name, ok) : LH_EXIT_FAIL;
    result_free(&r);
    free(hs.h);
    free(hs.line);
    return status2;
}
