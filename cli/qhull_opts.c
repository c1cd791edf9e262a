/* qhull_opts.c — Qhull's option words for lifthull's qdelaunay, qvoronoi, qconvex. */
#include "cli.h"
#include "qhull.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Output options each program prints (Qhull's manual pages, "Output formats"). */
static const char *const outputs[4] = {
    "i o p s Fn FN Fv Fx FS Fa Fs FI Fm FQ Fc FP m FM G f FF",
    "o p s i Fi Fo Fv Fn FN Fs Fx FI Fc FP G",
    "i o p s n Fn FN Fv Fi Fo FC Ft Fx FS Fa Fs FI Fm FQ Fc FP m FM G f FF",
    "s i o p Fp Fx Fv Fn FN FI Fm Fc FP Fs FQ G m FM f FF",
};

/* Qhull options that change nothing here, with why. */
typedef struct noop {
    const char *word;
    int prefix; /* matches words starting with it (options taking a value) */
    const char *why;
} noop;

static const noop noops[] = {
    {"Qt", 0, NULL}, /* always on, silently */
    {"QJ", 1, "no joggle is needed: every predicate is exact"},
    {"Qbb", 0, "no scaling is needed: every predicate is exact"},
    {"QbB", 0, "no scaling is needed: every predicate is exact"},
    {"Qz", 0, "no point at infinity is needed: cospherical sites are exact input here"},
    {"Qc", 0, "every distinct site is a vertex or a merged duplicate (lifthull reports them)"},
    {"Qx", 0, "no merging happens: exact arithmetic, every facet a simplex"},
    {"Qs", 0, "the initial simplex is chosen exactly"},
    {"Pp", 0, NULL},
    {"Po", 0, NULL},
    {"Q", 1, "Qhull's tuning options do not apply"},
    {"C", 1, "no facet merging happens: exact arithmetic"},
    {"A", 1, "no facet merging happens: exact arithmetic"},
};

static int is_output(lh_cli_qprog prog, const char *w)
{
    size_t len = strlen(w);
    for (const char *s = outputs[prog]; *s;) {
        size_t k = strcspn(s, " ");
        if (k == len && !strncmp(s, w, len)) return 1;
        s += k + (s[k] == ' ');
    }
    return 0;
}

static void help_half(void)
{
    printf("usage: lifthull qhalf [OPTIONS] < HALFSPACES\n"
           "       lifthull qhalf [OPTIONS] TI FILE [TO FILE]\n\n"
           "Qhull's qhalf: the intersection of halfspaces a.x + b <= 0, given as Qhull's\n"
           "input (d+1, count, then a_1 .. a_d b per line; qconvex n writes them), about\n"
           "an interior point: option Hn,n,... (missing coordinates 0), the input's first\n"
           "lines 'd 1' and the point, the origin if every b < 0, or else the halfspaces'\n"
           "Chebyshev centre (max t: a_i.x + |a_i| t + b_i <= 0, named on standard\n"
           "error); it must be strictly inside every halfspace (checked exactly). The dual\n"
           "points a / -(a.c + b) are rounded once; their convex hull is exact.\n\n"
           "outputs, printed in the order given:  %s\n"
           "  s   summary (none asked: on standard output; asked: on standard error)\n"
           "  Fp  the intersection points      Fx  the non-redundant halfspaces\n"
           "  i   the halfspaces through each intersection point (Fv: with counts)\n"
           "  Fn  each point's neighbouring points   FN  each halfspace's points\n"
           "  FI  the points' ids   Fm  their merge counts (dual simplices - 1)\n"
           "  Fc  the coplanar halfspaces of each point (exact; FP: nearest halfspace)\n"
           "  Fs  sizes   FQ  the command   p  the dual points of the non-redundant ones\n"
           "  o G m FM f FF  the dual points' convex hull (as qconvex; every facet a simplex,\n"
           "      as Qhull's qhalf Qt)\n"
           "other options:\n"
           "  Hn,n,...  the interior point      Fd  the input in cdd's format\n"
           "  Tv, Tc    check the dual hull exactly      Ts  statistics on standard error\n"
           "  FO        the options on standard error\n"
           "  TI FILE   read from FILE          TO FILE  write the output to FILE\n"
           "  Qt QJ Qbb Qx and Qhull's tuning options are accepted (a note says why).\n\n"
           "e.g.  rbox c D3 | qconvex n | lifthull qhalf H0 Fp\n",
           outputs[LH_QPROG_HALF]);
}

static void help(const lh_cli_qopts *o)
{
    if (o->prog == LH_QPROG_HALF) {
        help_half();
        return;
    }
    printf("usage: lifthull %s [OPTIONS] < POINTS\n"
           "       lifthull %s [OPTIONS] TI FILE [TO FILE]\n\n"
           "Qhull's %s, exact: the same options and output formats, every facet a\n"
           "simplex (Qt is always on). Points in Qhull's format (rbox output as it is).\n\n"
           "outputs, printed in the order given:  %s\n"
           "  (none: the summary 's' on standard output; 's' asked for: on standard error)\n"
           "other options:\n"
           "  Qu        furthest-site (upper hull)%s\n"
           "%s"
           "  Tv, Tc    check the result exactly and report on standard error\n"
           "  Ts        statistics on standard error (sizes, time, predicate stages)\n"
           "  FO        the options on standard error%s\n"
           "%s"
           "  TI FILE   read the points from FILE      TO FILE  write the output to FILE\n"
           "  Qt QJ Qbb Qz Qc Qx Pp and Qhull's tuning options are accepted; they\n"
           "  change nothing under exact arithmetic (a note says why).\n\n"
           "e.g.  rbox 1000 D3 | lifthull %s %s\n",
           o->name, o->name, o->name, outputs[o->prog],
           o->prog == LH_QPROG_CONVEX ? " (not for qconvex)" : "",
           o->prog == LH_QPROG_VORONOI ? "" : "  FA        total area (and volume) in the summary 's'\n",
           o->prog == LH_QPROG_VORONOI ? "; FD: cdd's format for p" : "; FD: cdd's format for n, Fi, Fo, p",
           o->prog == LH_QPROG_VORONOI ?
           "  Pdk:n     print the Voronoi vertices whose Delaunay facet's lifted normal has\n"
           "            normal[k] >= n (PDk:n: <= n; n 0 if left out); PAn: the n largest\n"
           "  PG        print the good ones' other neighbours (not good)\n"
           "  QGn       print those of the simplices whose circumsphere holds site n (n is\n"
           "            left out; QG-n: the others)\n"
           "  QVn       print the Voronoi vertices of site n's region (QV-n: the others)\n" :
           "  Pdk:n     print the facets with normal[k] >= n (PDk:n: <= n; n 0 if left out)\n"
           "  PAn       print the n largest facets (Pg); PG: their other neighbours\n"
           "  QGn       print the facets point n sees (n is left out; QG-n: not seen)\n"
           "  QVn       print the facets with vertex n (QV-n: without)\n"
           "  Gi Go Gn Ga Gr Gh GDn  G's inner/outer planes (exact: the facets), no planes,\n"
           "            all points, ridges, intersections; GDn: 4-d pictures without coordinate n\n"
           "  Gv        G's spheres at the vertices (planes moved out and in by their radius)\n"
           "  Gt        qdelaunay, 3-d: the inner ridges only (Qhull's transparent outer ones)\n"
           "  Gc        G's centrums (exact: each facet's centroid)\n",
           o->name,
           o->prog == LH_QPROG_VORONOI ? "o" : o->prog == LH_QPROG_CONVEX ? "i" : "i Qt");
}

/* Qhull's print filters: Pdk[:n]... (several run together), PDk[:n], PAn, Pg, PG.
 * Returns 1 when w is one (recorded), 0 when it is not one, -1 after a usage error. */
static int print_filter(lh_cli_qopts *o, const char *w)
{
    if (w[0] != 'P' || !strchr("dDAgG", w[1]) || !w[1]) return 0;
    if (o->prog == LH_QPROG_HALF) {
        fprintf(stderr, "lifthull %s: option '%s' is not supported (print filters: qconvex, "
                "qdelaunay and qvoronoi)\n", o->name, w);
        return -1;
    }
    if (w[1] == 'g' || w[1] == 'G') {
        if (w[2]) return 0;
        *(w[1] == 'g' ? &o->good : &o->good_nbrs) = 1;
        return 1;
    }
    char *end;
    if (w[1] == 'A') {
        long v = isdigit((unsigned char)w[2]) ? strtol(w + 2, &end, 10) : 0;
        if (v <= 0 || *end) goto bad;
        o->largest = (size_t)v;
        return 1;
    }
    for (const char *s = w + 1; *s;) {
        if ((*s != 'd' && *s != 'D') || !isdigit((unsigned char)s[1]) || o->npd == LH_QOUT_MAX) goto bad;
        struct lh_cli_qpd *f = &o->pd[o->npd++];
        f->ge = *s == 'd';
        f->k = (int)strtol(s + 1, &end, 10);
        f->at = 0;
        s = end;
        if (*s == ':') {
            f->at = strtod(s + 1, &end);
            if (end == s + 1 || f->at != f->at) goto bad;
            s = end;
        }
    }
    return 1;
bad:
    fprintf(stderr, "lifthull %s: option '%s': expected Pdk[:n] or PDk[:n] (k a coordinate, n a "
            "number; several may follow each other), PAn (n > 0), Pg or PG\n", o->name, w);
    return -1;
}

/* Output option w, in the order given; 0 after a usage error. */
static int word_output(lh_cli_qopts *o, const char *w)
{
    if (o->nout == LH_QOUT_MAX) {
        fprintf(stderr, "lifthull %s: more than %d output options\n", o->name, LH_QOUT_MAX);
        return 0;
    }
    strcpy(o->out[o->nout++], w);
    return 1;
}

/* QGn / QG-n (good facets: visible from point n, or not) and QVn / QV-n (with
 * vertex n, or without), qconvex, qdelaunay and qvoronoi; 0 after a usage error. */
static int good_point(lh_cli_qopts *o, const char *w)
{
    if (o->prog == LH_QPROG_HALF) {
        fprintf(stderr, "lifthull %s: option '%s' is not supported (good facets by a point: "
                "QGn, QVn; qconvex, qdelaunay and qvoronoi)\n", o->name, w);
        return 0;
    }
    struct lh_cli_qgood *g = w[1] == 'G' ? &o->gpoint : &o->gvertex;
    const char *s = w + 2 + (w[2] == '-');
    char *end;
    unsigned long long v = isdigit((unsigned char)*s) ? strtoull(s, &end, 10) : 0;
    if (!isdigit((unsigned char)*s) || *end || v > (unsigned long long)LH_INDEX_MAX) {
        fprintf(stderr, "lifthull %s: option '%s': expected %.2sn or %.2s-n (n a point's index)\n",
                o->name, w, w, w);
        return 0;
    }
    *g = (struct lh_cli_qgood){1, w[2] == '-', (size_t)v};
    return 1;
}

/* G's suboptions, one or several after a G ("Gr", "Gan", "GD3"): they also ask for
 * the G output. 0 after a usage error. */
static int geom_word(lh_cli_qopts *o, const char *w)
{
    if (o->prog == LH_QPROG_VORONOI) {
        fprintf(stderr, "lifthull qvoronoi: option '%s' is not supported (G's suboptions are for "
                "qconvex and qdelaunay)\n", w);
        return 0;
    }
    static const char letters[] = "ionarhvtc"; /* the LH_QG_* bits in order */
    for (const char *c = w + 1; *c; c++) {
        const char *at = strchr(letters, *c);
        if (at) {
            o->geom |= 1 << (at - letters);
        } else if (*c == 'D' && c[1] >= '0' && c[1] <= '3') {
            o->geom_drop = *++c - '0';
        } else {
            fprintf(stderr, "lifthull %s: option '%s': '%c' is not supported (G suboptions: Gi Go "
                    "Gn Ga Gr Gh Gv Gt Gc GDn, n 0..3; Qhull's projections Gp are not "
                    "drawn)\n", o->name, w, *c);
            return 0;
        }
    }
    for (int i = 0; i < o->nout; i++)
        if (!strcmp(o->out[i], "G")) return 1;
    return word_output(o, "G");
}

/* qhalf's Hn,n,...: the interior point (missing coordinates 0; "H" alone: the
 * origin). */
static int interior(lh_cli_qopts *o, const char *w)
{
    o->ninterior = 1;
    o->interior[0] = 0;
    if (!w[1]) return 1;
    o->ninterior = 0;
    for (const char *s = w + 1;;) {
        char *end;
        double v = strtod(s, &end);
        if (end == s || !isfinite(v) || (*end && *end != ',') || o->ninterior == LH_DELAUNAY_MAX_DIM) {
            fprintf(stderr, "lifthull %s: option '%s': expected Hn,n,... (at most %d coordinates "
                    "of the interior point)\n", o->name, w, LH_DELAUNAY_MAX_DIM);
            return 0;
        }
        o->interior[o->ninterior++] = v;
        if (!*end) return 1;
        s = end + 1;
    }
}

/* One option word; 0 after printing a usage error. `next` is the following word,
 * consumed (*used = 1) by TI and TO. */
static int word(lh_cli_qopts *o, const char *w, const char *next, int *used)
{
    if (!strcmp(w, "FS") && o->prog != LH_QPROG_VORONOI) o->areas = 1; /* also an output */
    if (is_output(o->prog, w)) return word_output(o, w);
    if (w[0] == 'G' && w[1] && o->prog != LH_QPROG_HALF) return geom_word(o, w);
    if (!strcmp(w, "TI") || !strcmp(w, "TO")) {
        if (!next) {
            fprintf(stderr, "lifthull %s: option '%s' needs a file name\n", o->name, w);
            return 0;
        }
        *(w[1] == 'I' ? &o->input : &o->output) = next;
        return *used = 1;
    }
    const int facets = o->prog == LH_QPROG_CONVEX || o->prog == LH_QPROG_DELAUNAY;
    const int half = o->prog == LH_QPROG_HALF;
    if (!strcmp(w, "FO")) return o->show_options = 1;
    if (half && w[0] == 'H') return interior(o, w);
    if (half && !strcmp(w, "Fd")) return o->cdd = 1; /* cdd's format for the input */
    if (half && ((w[0] == 'T' && strcmp(w, "Tv") && strcmp(w, "Tc") && strcmp(w, "Ts")) ||
                 !strcmp(w, "Qu")))
        goto unknown;
    if (!strcmp(w, "Qu") && o->prog != LH_QPROG_CONVEX) return o->furthest = 1;
    if (!strcmp(w, "FA") && facets) return o->areas = 1;
    if (!strcmp(w, "Tv")) return o->verify = 1;
    if (!strcmp(w, "Ts")) return o->stats = 1;
    if (!strcmp(w, "Tc")) {
        fprintf(stderr, "lifthull %s: option 'Tc': every step is exact; the result is checked "
                "once, exactly, as with 'Tv'\n", o->name);
        return o->verify = 1;
    }
    if (!strcmp(w, "FD") && !half) return o->cdd = 1;
    if ((!strcmp(w, "m") || !strcmp(w, "FM")) && o->prog == LH_QPROG_VORONOI) {
        fprintf(stderr, "lifthull qvoronoi: option '%s' is not used with qvoronoi (as in Qhull: "
                "Mathematica and Maple output are for qconvex and qdelaunay)\n", w);
        return 0;
    }
    int pf = print_filter(o, w);
    if (pf) return pf > 0;
    if ((!strncmp(w, "QG", 2) || !strncmp(w, "QV", 2)) && w[2]) return good_point(o, w);
    for (size_t i = 0; i < sizeof noops / sizeof noops[0]; i++) {
        const noop *p = &noops[i];
        size_t k = strlen(p->word);
        int hit = p->prefix ? !strncmp(w, p->word, k) && (w[k] == 0 || isdigit((unsigned char)w[k]) ||
                                                          w[k] == '-' || w[k] == '.' || p->word[0] != 'Q')
                            : !strcmp(w, p->word);
        if (!hit) continue;
        if (p->why) fprintf(stderr, "lifthull %s: option '%s' ignored: %s\n", o->name, w, p->why);
        return 1;
    }
unknown:
    fprintf(stderr, "lifthull %s: option '%s' is not supported (outputs: %s; %s, TI, TO; "
            "lifthull %s --help)\n", o->name, w, outputs[o->prog],
            o->prog == LH_QPROG_HALF ? "also H, Fd, Tv, Ts" : "also Qu, Tv", o->name);
    return 0;
}

int lh_cli_qparse(lh_cli_qopts *o, lh_cli_qprog prog, int argc, char **argv)
{
    static const char *const names[4] = {"qdelaunay", "qvoronoi", "qconvex", "qhalf"};
    memset(o, 0, sizeof *o);
    o->prog = prog;
    o->name = names[prog];
    o->geom_drop = -1;
    snprintf(o->command, sizeof o->command, "lifthull %s", o->name);
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help(o);
            return 1;
        }
        size_t len = strlen(o->command);
        snprintf(o->command + len, sizeof o->command - len, " %s", argv[i]);
    }
    /* Words split at blanks, across and within arguments ("i Qt" is two words). */
    char *buf = o->words;
    size_t used = 0;
    const char *words[512];
    int nw = 0;
    for (int i = 0; i < argc; i++) {
        size_t len = strlen(argv[i]);
        if (used + len + 1 > sizeof o->words || nw + (int)len / 2 + 1 > 512) {
            fprintf(stderr, "lifthull %s: the options are too long\n", o->name);
            return -1;
        }
        memcpy(buf + used, argv[i], len + 1);
        for (char *s = strtok(buf + used, " \t\n"); s; s = strtok(NULL, " \t\n")) words[nw++] = s;
        used += len + 1;
    }
    for (int i = 0; i < nw; i++) {
        int took = 0;
        if (!word(o, words[i], i + 1 < nw ? words[i + 1] : NULL, &took)) return -1;
        i += took;
    }
    if (o->nout == 0) {
        strcpy(o->out[o->nout++], "s");
        o->summary_default = 1;
    }
    return 0;
}
