/*
 * fuzz_delaunay.c — libFuzzer target: the Delaunay engine on small fuzzer-chosen point
 * sets built from small integers (so exactly degenerate ones are common), in d = 2..5,
 * with every option. Whatever lh_delaunay returns must be right: LH_OK and a
 * triangulation that passes the exact check, equal byte for byte to the generic
 * engine's and to the one built by inserting the second half; or LH_ERR_DEGENERATE
 * exactly when the sites span less than R^d (and the option is off). Anything else
 * aborts. Build: cmake -DLH_BUILD_FUZZ=ON with clang (libFuzzer), or with any compiler
 * as a replay driver (fuzz/replay.c) that runs the files named on its command line.
 */
#include "lifthull.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int same(const lh_tri *a, const lh_tri *b)
{
    int k = lh_tri_simplex_dim(a);
    size_t c = lh_tri_count(a), h = lh_tri_hull_count(a), n = lh_tri_site_count(a);
    if (k != lh_tri_simplex_dim(b) || c != lh_tri_count(b) || h != lh_tri_hull_count(b)) return 0;
    size_t s = (size_t)(k + 1) * c * sizeof(lh_index);
    return !memcmp(lh_tri_simplices(a), lh_tri_simplices(b), s) &&
           !memcmp(lh_tri_neighbors(a), lh_tri_neighbors(b), s) &&
           !memcmp(lh_tri_hull_facets(a), lh_tri_hull_facets(b), (size_t)k * h * sizeof(lh_index)) &&
           !memcmp(lh_tri_duplicate_of(a), lh_tri_duplicate_of(b), n * sizeof(lh_index));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    int d = 2 + data[0] % 4, flags = data[1];
    size_t n = (size - 2) / (size_t)d;
    if (n > 80) n = 80;
    double x[80 * 5];
    for (size_t i = 0; i < n * (size_t)d; i++) {
        int8_t v = (int8_t)data[2 + i];
        x[i] = (flags & 16) ? v / 4.0 : (double)(v % 5); /* a coarse grid: degenerate */
    }
    lh_options o;
    lh_options_default(&o);
    o.furthest_site = flags & 1;
    o.affine_hull = (flags >> 1) & 1;
    lh_tri *t = NULL, *g = NULL, *ins = NULL;
    lh_status st = lh_delaunay(d, n, x, &o, &t);
    int dim = -2;
    lh_coords_affine_dim(d, n, x, NULL, &dim);
    if (st == LH_ERR_DEGENERATE) {
        if (dim >= d || (o.affine_hull && dim >= 1)) abort();
        return 0;
    }
    if (st != LH_OK || dim < 1) abort();
    if (lh_tri_check(t, NULL) != LH_OK) abort();
    o.generic_engine = 1;
    if (lh_delaunay(d, n, x, &o, &g) != LH_OK || !same(t, g)) abort();
    o.generic_engine = (flags >> 2) & 1;
    size_t first = n / 2;
    if (lh_delaunay(d, first, x, &o, &ins) == LH_OK) {
        if (lh_tri_insert(ins, n - first, x + first * (size_t)d) != LH_OK || !same(t, ins)) abort();
    }
    lh_tri_free(t);
    lh_tri_free(g);
    lh_tri_free(ins);
    return 0;
}
