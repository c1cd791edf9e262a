// bench_predicates — ns per call of lifthull's exact predicates next to CGAL's Epick
// predicates, measured in one run over the same pre-generated inputs.
//
// Predicates: orient_2, orient_3, insphere_2, insphere_3, insphere_4 (and orient_4 as
// an extra row, against Epick_d's Orientation_d). Input kinds:
//   random          every coordinate uniform in [0,1)
//   near-degenerate orient_k: k points uniform in [0,1)^k, the last one an affine
//                   combination of them rounded to double, then one of its coordinates
//                   moved by 1 ulp; insphere_d: d+2 points on the unit sphere computed
//                   with cos/sin (d = 2, 3) or a normalized Gaussian vector (d = 4) and
//                   rounded to double — so the determinant is tiny and filters mostly fail.
// For each (predicate, input) a pool of N tuples (2^16 by default) is generated once;
// CGAL points are built from the same doubles once, outside timing. Each side then
// runs R rounds (interleaved L,C / C,L, ...), each round a whole number of passes over
// the pool lasting at least --min-ms; the median round gives ns/call.
//
// Signs: before timing, one pass per side records every sign. lifthull and CGAL may
// use opposite sign conventions, so a global factor per predicate is determined from
// the first tuple where both signs are nonzero and printed; any tuple where
// lifthull != factor * CGAL is a disagreement and is printed with %a coordinates.
// The exact-path fraction is lh_pred_counters exact_exits / calls over that pass.
//
// CGAL's functors are inlined into the timed loop; lifthull is an out-of-line library
// call. For reference, the details table also times CGAL through a noinline wrapper
// (a third interleaved side; --no-ool skips it). The bars use the inlined CGAL time.
//
// Output: Markdown on stdout. Exit status 0, or 2 if any sign disagreement was found.
//
// Files: this one (options, main), bench_predicates.h (what the others share),
// _inputs.cpp (the tuples), _cgal.h (CGAL's functors and the passes of both sides),
// _row.cpp (one row: signs and timing), _report.cpp (the report).

#include "bench_predicates.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

void usage(const char *argv0)
{
    std::fprintf(stderr,
                 "usage: %s [--log2n L] [--rounds R] [--min-ms M] [--seed S] [--quick]\n"
                 "  --log2n L   pool of 2^L tuples per (predicate, input) (default 16)\n"
                 "  --rounds R  timed rounds per side, interleaved (default 7, min 5)\n"
                 "  --min-ms M  minimum duration of one round in ms (default 60)\n"
                 "  --seed S    RNG seed (default 20240611)\n"
                 "  --only P    run only predicate P (e.g. insphere_3)\n"
                 "  --input I   run only input kind I (random or near-degenerate)\n"
                 "  --no-ool    skip timing CGAL through an out-of-line call\n"
                 "  --quick     smoke test: --log2n 12 --rounds 5 --min-ms 5\n",
                 argv0);
}

// Reads the options into *o; false (after the usage) if they are not usable. Exits with
// status 1 if an option lacks its value.
bool parse_options(int argc, char **argv, Options *o)
{
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> const char * {
            if (i + 1 >= argc) {
                usage(argv[0]);
                std::exit(1);
            }
            return argv[++i];
        };
        if (a == "--log2n")
            o->log2n = std::atoi(next());
        else if (a == "--rounds")
            o->rounds = std::atoi(next());
        else if (a == "--min-ms")
            o->min_ms = std::atof(next());
        else if (a == "--seed")
            o->seed = std::strtoull(next(), nullptr, 0);
        else if (a == "--only")
            o->only_pred = next();
        else if (a == "--input")
            o->only_input = next();
        else if (a == "--no-ool")
            o->ool = false;
        else if (a == "--quick") {
            o->log2n = 12;
            o->rounds = 5;
            o->min_ms = 5;
        } else {
            usage(argv[0]);
            return false;
        }
    }
    if (o->log2n < 4 || o->log2n > 24 || o->rounds < 1 || o->min_ms <= 0) {
        usage(argv[0]);
        return false;
    }
    return true;
}

// Every row --only and --input leave, random inputs first, with its bar (0: none).
std::vector<Row> run_rows(Session &s, lh_pred *ctx)
{
    std::vector<Row> rows;
    for (Input in : {Input::random, Input::neardeg}) {
        const bool rnd = in == Input::random;
        if (!s.opt.only_input.empty() && s.opt.only_input != (rnd ? "random" : "near-degenerate"))
            continue;
        auto want = [&](const char *name) {
            return s.opt.only_pred.empty() || s.opt.only_pred == name;
        };
        if (want("orient_2"))
            rows.push_back(run_row(s, ctx, 2, Pred::orient, in, rnd ? 1.3 : 0, false));
        if (want("orient_3"))
            rows.push_back(run_row(s, ctx, 3, Pred::orient, in, rnd ? 1.3 : 0, false));
        if (want("orient_4")) rows.push_back(run_row(s, ctx, 4, Pred::orient, in, 0, true));
        if (want("insphere_2"))
            rows.push_back(run_row(s, ctx, 2, Pred::insphere, in, rnd ? 1.3 : 0, false));
        if (want("insphere_3"))
            rows.push_back(run_row(s, ctx, 3, Pred::insphere, in, rnd ? 1.3 : 3.0, false));
        if (want("insphere_4"))
            rows.push_back(run_row(s, ctx, 4, Pred::insphere, in, rnd ? 1.3 : 0, false));
    }
    return rows;
}

} // namespace

int main(int argc, char **argv)
{
    Session s;
    if (!parse_options(argc, argv, &s.opt)) return 1;
    lh_pred *ctx = nullptr;
    if (lh_pred_create(nullptr, &ctx) != LH_OK) {
        std::fprintf(stderr, "lh_pred_create failed\n");
        return 1;
    }
    std::fprintf(stderr, "bench_predicates: 2^%d tuples, %d rounds, >= %.0f ms per round\n",
                 s.opt.log2n, s.opt.rounds, s.opt.min_ms);
    std::vector<Row> rows = run_rows(s, ctx);
    if (rows.empty()) {
        std::fprintf(stderr, "no row matches --only/--input\n");
        return 1;
    }
    lh_pred_free(ctx);
    return print_report(s, rows);
}
