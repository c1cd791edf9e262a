/*
 * selfcheck.c — `lifthull selfcheck [FILE]`: runs the exact predicates on cases
 * whose signs are known exactly and prints, beside each, what plain double
 * arithmetic answers. A case line is
 *     orient K SIGN  x_0 ... (K+1 points of K coordinates)
 *     insphere D SIGN  x_0 ... (D+2 points of D coordinates)
 * with SIGN in {-1, 0, 1}; numbers as strtod reads them (hex floats too); '#'
 * starts a comment.
 */
#include "cli.h"
#include "lifthull.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef LH_DEFAULT_SELFCHECK
#define LH_DEFAULT_SELFCHECK "tests/data/near_degenerate.txt"
#endif

enum { MAX_COORDS = (LH_ORIENT_MAX_DIM + 1) * LH_ORIENT_MAX_DIM };

typedef struct sc_case {
    int lifted, dim, expected, npts;
    double x[MAX_COORDS];
} sc_case;

/* Sign of the determinant of the homogeneous matrix in plain doubles (Gaussian
 * elimination with partial pivoting): what a non-exact code would answer. */
static int naive_sign(const sc_case *c)
{
    int n = c->npts, cols = c->dim + 1 + c->lifted;
    double a[LH_ORIENT_MAX_DIM + 1][LH_ORIENT_MAX_DIM + 1];
    for (int i = 0; i < n; i++) {
        const double *p = c->x + i * c->dim;
        a[i][0] = 1;
        double sq = 0;
        for (int j = 0; j < c->dim; j++) {
            a[i][j + 1] = p[j];
            sq += p[j] * p[j];
        }
        if (c->lifted) a[i][cols - 1] = sq;
    }
    int sign = 1;
    for (int k = 0; k < n; k++) {
        int piv = k;
        for (int i = k + 1; i < n; i++)
            if ((a[i][k] < 0 ? -a[i][k] : a[i][k]) > (a[piv][k] < 0 ? -a[piv][k] : a[piv][k])) piv = i;
        if (a[piv][k] == 0) return 0;
        if (piv != k) {
            for (int j = 0; j < n; j++) {
                double t = a[k][j];
                a[k][j] = a[piv][j];
                a[piv][j] = t;
            }
            sign = -sign;
        }
        if (a[k][k] < 0) sign = -sign;
        for (int i = k + 1; i < n; i++) {
            double f = a[i][k] / a[k][k];
            for (int j = k; j < n; j++) a[i][j] -= f * a[k][j];
        }
    }
    return sign;
}

/* Parses one line into *c. Returns 1 for a case, 0 for a blank/comment line, -1 on
 * error with *col set to the 1-based column and *what to the expectation. */
static int parse_line(char *line, sc_case *c, int *col, const char **what)
{
    char *s = line, *end;
    while (isspace((unsigned char)*s)) s++;
    if (!*s || *s == '#') return 0;
    *col = (int)(s - line) + 1;
    if (!strncmp(s, "orient", 6) && isspace((unsigned char)s[6])) {
        c->lifted = 0;
        s += 6;
    } else if (!strncmp(s, "insphere", 8) && isspace((unsigned char)s[8])) {
        c->lifted = 1;
        s += 8;
    } else {
        *what = "'orient' or 'insphere'";
        return -1;
    }
    long v[2];
    for (int i = 0; i < 2; i++) {
        while (isspace((unsigned char)*s)) s++;
        *col = (int)(s - line) + 1;
        errno = 0;
        v[i] = strtol(s, &end, 10);
        if (end == s || errno) {
            *what = i ? "the expected sign (-1, 0 or 1)" : "the dimension";
            return -1;
        }
        s = end;
    }
    int maxd = c->lifted ? LH_INSPHERE_MAX_DIM : LH_ORIENT_MAX_DIM;
    if (v[0] < 1 || v[0] > maxd) {
        *what = c->lifted ? "a dimension in 1..7" : "a dimension in 1..8";
        return -1;
    }
    if (v[1] < -1 || v[1] > 1) {
        *what = "the expected sign (-1, 0 or 1)";
        return -1;
    }
    c->dim = (int)v[0];
    c->expected = (int)v[1];
    c->npts = c->dim + 1 + c->lifted;
    for (int i = 0; i < c->npts * c->dim; i++) {
        while (isspace((unsigned char)*s)) s++;
        *col = (int)(s - line) + 1;
        errno = 0;
        c->x[i] = strtod(s, &end);
        if (end == s || (*end && !isspace((unsigned char)*end))) {
            *what = "a coordinate";
            return -1;
        }
        s = end;
    }
    while (isspace((unsigned char)*s)) s++;
    if (*s && *s != '#') {
        *col = (int)(s - line) + 1;
        *what = "the end of the line";
        return -1;
    }
    return 1;
}

static int run_case(lh_pred *ctx, const sc_case *c, const char *file, int line,
                    long *naive_wrong)
{
    const double *pts[LH_ORIENT_MAX_DIM + 1];
    size_t bad;
    if (lh_coords_validate(c->dim, (size_t)c->npts, c->x, &bad) != LH_OK) {
        fprintf(stderr, "%s:%d: coordinate %zu: %s\n", file, line, bad + 1,
                lh_status_message(LH_ERR_NONFINITE));
        return -1;
    }
    for (int i = 0; i < c->npts; i++) pts[i] = c->x + i * c->dim;
    int got = c->lifted ? lh_insphere(ctx, c->dim, pts) : lh_orient(ctx, c->dim, pts);
    int naive = naive_sign(c);
    if (naive != c->expected) (*naive_wrong)++;
    printf("%s:%d %s_%d expected %+d exact %+d double %+d%s\n", file, line,
           c->lifted ? "insphere" : "orient", c->dim, c->expected, got, naive,
           got == c->expected ? "" : "  MISMATCH");
    return got == c->expected;
}

int lh_cli_selfcheck(int argc, char **argv)
{
    const char *file = argc > 0 ? argv[0] : LH_DEFAULT_SELFCHECK;
    FILE *f = fopen(file, "r");
    if (!f) {
        fprintf(stderr, "lifthull selfcheck: %s: %s\n", file, strerror(errno));
        return LH_EXIT_INPUT;
    }
    lh_pred *ctx;
    lh_status st = lh_pred_create(NULL, &ctx);
    if (st != LH_OK) {
        fclose(f);
        fprintf(stderr, "lifthull selfcheck: %s\n", lh_status_message(st));
        return LH_EXIT_FAIL;
    }
    char buf[8192];
    int line = 0, rc = LH_EXIT_OK;
    long cases = 0, wrong = 0, naive_wrong = 0;
    while (fgets(buf, sizeof buf, f)) {
        line++;
        sc_case c;
        int col = 0;
        const char *what = "";
        int r = parse_line(buf, &c, &col, &what);
        if (r < 0) {
            fprintf(stderr, "%s:%d:%d: expected %s\n", file, line, col, what);
            rc = LH_EXIT_INPUT;
            break;
        }
        if (r == 0) continue;
        int ok = run_case(ctx, &c, file, line, &naive_wrong);
        if (ok < 0) {
            rc = LH_EXIT_INPUT;
            break;
        }
        cases++;
        wrong += !ok;
    }
    if (rc == LH_EXIT_OK && ferror(f)) {
        fprintf(stderr, "%s: read error\n", file);
        rc = LH_EXIT_INPUT;
    }
    fclose(f);
    if (rc == LH_EXIT_OK && cases == 0) {
        fprintf(stderr, "%s: no case found\n", file);
        rc = LH_EXIT_INPUT;
    }
    if (rc == LH_EXIT_OK) {
        lh_pred_counters cnt;
        lh_pred_counters_get(ctx, &cnt);
        printf("selfcheck: %ld cases, %ld wrong (exact predicates); plain doubles got %ld "
               "wrong; of %llu calls, %llu were settled by the filter, %llu by the "
               "granularity rule, %llu by residues, %llu by the exact stage\n",
               cases, wrong, naive_wrong, (unsigned long long)cnt.calls,
               (unsigned long long)cnt.filter_exits, (unsigned long long)cnt.grid_exits,
               (unsigned long long)cnt.residue_exits, (unsigned long long)cnt.exact_exits);
        if (wrong) rc = LH_EXIT_FAIL;
    }
    lh_pred_free(ctx);
    return rc;
}
