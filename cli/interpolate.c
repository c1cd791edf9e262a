/* interpolate.c — `lifthull interpolate SITES QUERIES`: values given at the sites,
 * interpolated at the queries (linear as scipy's LinearNDInterpolator, Sibson's
 * natural neighbours, or the nearest site's). */
#include "args.h"
#include "cli.h"
#include "outfile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: lifthull interpolate [-m linear|natural|nearest] [--values K] [-o FILE [-f]]\n"
    "                            SITES QUERIES\n"
    "\n"
    "Interpolates values given at the sites at each query point, one output line a\n"
    "query (K numbers). The values: with --values K, the last K columns of every line\n"
    "of SITES (e.g. a CSV 'x,y,value' with --values 1; the sites are the other\n"
    "columns); otherwise the attributes of a Triangle/TetGen .node file.\n"
    "  -m linear   (default) barycentric in the Delaunay simplex holding the query,\n"
    "              as scipy's LinearNDInterpolator; exact for affine functions\n"
    "  -m natural  Sibson's natural-neighbour interpolation (2D and 3D)\n"
    "  -m nearest  the value of the nearest site (exact distance comparisons)\n"
    "Queries outside the convex hull get nan (linear, natural).\n"
    "\n"
    "example:\n"
    "  printf 'x,y,v\\n0,0,1\\n1,0,2\\n0,1,3\\n1,1,4\\n' > s.csv\n"
    "  printf '2 1\\n0.5 0.5\\n' > q.txt\n"
    "  lifthull interpolate --values 1 s.csv q.txt  # prints 2.5\n"
    "\n"
    "exit codes: 0 done, 1 the computation failed, 2 usage, 3 bad input file.\n";

/* Splits the last k columns of s off into values (n*k, malloc'ed); s keeps d-k. */
static double *split_values(lh_points *s, int k)
{
    const int d = s->d - k;
    double *v = malloc(s->n * (size_t)k * sizeof *v);
    if (!v) return NULL;
    for (size_t i = 0; i < s->n; i++) {
        memcpy(v + i * k, s->xyz + i * s->d + d, (size_t)k * sizeof *v);
        memmove(s->xyz + i * d, s->xyz + i * s->d, (size_t)d * sizeof *v);
    }
    s->d = d;
    return v;
}

/* The values and their count per site; NULL after printing the problem. */
static double *values_of(const lh_cli_args *a, lh_points *s, const char *name, int *k)
{
    if (a->values) {
        if (s->d - a->values < 2) {
            fprintf(stderr, "%s: %d columns leave %d for the coordinates with --values %d; at least 2 are needed\n",
                    name, s->d, s->d - a->values, a->values);
            return NULL;
        }
        *k = a->values;
        double *v = split_values(s, a->values);
        if (!v) fprintf(stderr, "lifthull interpolate: out of memory\n");
        return v;
    }
    if (s->attr_count == 0) {
        fprintf(stderr, "%s: no values: give --values K (the last K columns) or a .node file with attributes\n", name);
        return NULL;
    }
    *k = s->attr_count;
    double *v = malloc(s->n * (size_t)*k * sizeof *v);
    if (v) memcpy(v, s->attr, s->n * (size_t)*k * sizeof *v);
    else fprintf(stderr, "lifthull interpolate: out of memory\n");
    return v;
}

static int method_of(const char *m, lh_interp_method *out)
{
    if (!m || !strcmp(m, "linear")) *out = LH_INTERP_LINEAR;
    else if (!strcmp(m, "natural")) *out = LH_INTERP_NATURAL;
    else if (!strcmp(m, "nearest")) *out = LH_INTERP_NEAREST;
    else return 0;
    return 1;
}

static int interpolate(const lh_cli_args *a, lh_interp_method m, lh_points *s, const lh_points *q,
                       const double *v, int k, const char **names)
{
    lh_options opt;
    lh_options_default(&opt);
    opt.threads = a->threads;
    lh_tri *t;
    lh_status st = lh_delaunay(s->d, s->n, s->xyz, &opt, &t);
    if (st != LH_OK) {
        lh_cli_report_failure(names[0], s->d, s->n, s->xyz, st);
        return LH_EXIT_FAIL;
    }
    double *out = malloc((q->n ? q->n : 1) * (size_t)k * sizeof *out);
    st = out ? lh_tri_interpolate(t, m, q->n, q->xyz, k, v, out) : LH_ERR_NOMEM;
    int status = LH_EXIT_FAIL;
    lh_cli_out o;
    if (st != LH_OK) {
        fprintf(stderr, "lifthull interpolate: %s\n", st == LH_ERR_DIMENSION ?
                "natural-neighbour interpolation is for 2D and 3D sites" : lh_status_message(st));
    } else if (lh_cli_out_open(&o, "interpolate", a->output, a->force, a->file[1])) {
        for (size_t i = 0; i < q->n; i++)
            for (int c = 0; c < k; c++) fprintf(o.f, c + 1 < k ? "%.17g " : "%.17g\n", out[i * k + c]);
        status = lh_cli_out_close(&o, "interpolate", 1);
    }
    free(out);
    lh_tri_free(t);
    return status;
}

int lh_cli_interpolate(int argc, char **argv)
{
    lh_cli_args a;
    int r = lh_cli_args_parse(&a, "interpolate", "qfomv", 2, 2, argc, argv, help);
    if (r) return r > 0 ? LH_EXIT_OK : LH_EXIT_USAGE;
    lh_interp_method m;
    if (!method_of(a.method, &m)) {
        fprintf(stderr, "lifthull interpolate: unknown method '%s' (linear, natural or nearest)\n", a.method);
        return LH_EXIT_USAGE;
    }
    if (!lh_cli_out_check("interpolate", a.output, a.force, a.file[1]) ||
        !lh_cli_out_check("interpolate", a.output, a.force, a.file[0]))
        return LH_EXIT_FAIL;
    lh_points s, q;
    const char *names[2];
    if (!lh_cli_load_pair(a.file[0], a.file[1], a.format, &s, &q, names)) return LH_EXIT_INPUT;
    int k = 0, status = LH_EXIT_INPUT;
    double *v = values_of(&a, &s, names[0], &k);
    if (v && q.d != s.d)
        fprintf(stderr, "%s: the queries have dimension %d, the sites (%s) %d\n", names[1], q.d, names[0], s.d);
    else if (v)
        status = interpolate(&a, m, &s, &q, v, k, names);
    free(v);
    lh_points_free(&s);
    lh_points_free(&q);
    return status;
}
