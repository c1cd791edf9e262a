// bench_predicates.h — what the files of bench_predicates share (bench_predicates.cpp
// describes the program): the options, one row of results, the run's shared state, and
// the entry points of the input generator, the row runner and the report.
#ifndef LH_BENCH_PREDICATES_H
#define LH_BENCH_PREDICATES_H

#include <lifthull.h>

#include "sites.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

enum class Pred { orient, insphere };
enum class Input { random, neardeg };

struct Options {
    int log2n = 16;
    int rounds = 7;
    double min_ms = 60.0;
    uint64_t seed = 20240611;
    int max_print = 5;                 // disagreements printed per row
    bool ool = true;                   // also time CGAL through an out-of-line call (details table)
    std::string only_pred, only_input; // empty: all (for profiling one row)
};

// One (predicate, input) row of the report.
struct Row {
    std::string pred, input, cgal_name;
    double lh_ns = 0, cg_ns = 0;
    double lh_min = 0, lh_max = 0, cg_min = 0, cg_max = 0;
    double ool_ns = 0; // CGAL through an out-of-line call
    int ool_reps = 0;
    double exact_frac = 0, zero_frac = 0, lh_zero_sign_frac = 0;
    double bar = 0; // 0: no bar for this row
    bool extra = false;
    int factor = 0;
    size_t n = 0, disagreements = 0;
    int lh_reps = 0, cg_reps = 0;
    long lh_sum = 0, cg_sum = 0;
    uint64_t calls = 0;
};

// lifthull sign = factor * CGAL sign, one factor per predicate (0: not yet fixed).
struct SignFactor {
    int orient[9] = {0};
    int insphere[9] = {0};
    int &get(Pred p, int d)
    {
        return p == Pred::orient ? orient[d] : insphere[d];
    }
};

// The run: its options, the sign factors fixed so far, and what the report lists after
// the tables.
struct Session {
    Options opt;
    SignFactor factor;
    std::vector<std::string> disagreement_log;
    std::vector<std::string> counter_warnings;
    volatile long sink = 0; // checksums end here so no call can be optimized away
};

// The inputs' random numbers: one stream per row, seeded from the row; tools/sites.h's
// generator (xoshiro256**), shared with the tool, the tests and bench_delaunay.
struct Rng {
    lht_rng g;
    explicit Rng(uint64_t s)
    {
        lht_rng_seed(&g, s);
    }
    double u01()
    {
        return lht_rng_unit(&g);
    } // [0,1), a multiple of 2^-53
    double gauss()
    {
        return lht_rng_normal(&g);
    }
    uint64_t bits()
    {
        return lht_rng_next(&g);
    }
};

// Writes one tuple of the predicate's points (d + 1 for orient, d + 2 for insphere) of
// dimension d into out (bench_predicates_inputs.cpp).
void gen_tuple(Rng &r, Pred p, Input in, int d, double *out);

// Generates the row's pool, checks every sign against CGAL's and times both sides
// (bench_predicates_row.cpp). d: 2..4.
Row run_row(Session &s, lh_pred *ctx, int d, Pred p, Input in, double bar, bool extra);

// The Markdown report on stdout; returns the exit status (bench_predicates_report.cpp).
int print_report(const Session &s, const std::vector<Row> &rows);

#endif
