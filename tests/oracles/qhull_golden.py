#!/usr/bin/env python3
"""Golden tests of `lifthull qdelaunay | qvoronoi | qconvex` against Qhull's programs, on the
point sets of Qhull's own tests (issue #4).

  qhull_golden.py --lifthull LIFTHULL [--rbox R] [--qdelaunay Q] [--qvoronoi Q] [--qconvex Q]
                  [--invocations FILE] [--shard K/N] [--only REGEX] [--limit K] [-v]

The sets: the distinct rbox specifications of Section A of tests/data/qhull/rbox_invocations.txt
(extracted from Qhull's eg/q_test, q_eg, q_egtest). A specification is skipped when it is not
a plain rbox command (quotes, `qhull`, `eg-*` words: those lines feed user_eg programs), uses
`h` (Geomview output), fails in this rbox, or makes more than 8 (or fewer than 2) dimensions.
A bare `t` (seed from the clock) becomes `t1`, and the point count is capped per dimension
(CAP below) by editing the count token, so every run sees the same points. Sets with the same
points are run once.

Each set is classified:
  lowdim      the points span less than d dimensions (exact rank): lifthull must refuse with
              its "affine subspace" message (Qhull's failure is recorded);
  general     no duplicate points, `qdelaunay s` (without Qt) succeeds with no non-simplicial
              Delaunay region, and `qdelaunay Qt i` gives the same simplices as lifthull — or,
              when they differ, Qhull's simplices fail the exact check (then: `inexact`);
  degenerate  everything else (Qhull failed, merged facets, duplicates) and `inexact`.
(and separately for the hull: `qconvex s` without non-simplicial facets, no duplicates.)

General sets: Qhull and lifthull run with the same options (Qt added to qdelaunay's) and the
outputs are compared structurally and order-independently:
  qdelaunay  i (vertex sets, and the parity of each facet's vertex order), Fn (neighbours as
             vertex sets; Qhull's negative ids and lifthull's -(j+1) must correspond one to
             one across all hull sides, unless Qhull merged upper facets: then by count),
             FN (per site), o (header, coordinates to 1e-15, lifted coordinate to 1e-12 of
             its maximum, facets), p, Fv, Fx, Qu i (when the furthest-site facets are simplices)
  qvoronoi   o (vertices matched through their Delaunay simplices; each within 1e-12 of the
             exact circumcentre relative to the set's extent; Qhull's own error reported;
             regions per site as vertex sets, bounded/unbounded, cyclic order in 2D), p, Fv,
             Fi, Fo (site pairs, vertex sets, hyperplanes to 1e-12), FN
  qconvex    i (with parity), o, n, Fn, FN, Fv, Fx, p, FC (planes and centrums to 1e-12)
Degenerate sets: lifthull's `qdelaunay i` must pass tests/oracles/exact_check.py (--limit K
facets of each kind), use every distinct site, and its simplices' volumes must add up exactly
to the volume of lifthull's `qconvex i` hull (no double covering); `qconvex i` must have every
input point inside or on every facet's plane (exact), d affinely independent vertices per
facet and every ridge in exactly two facets; where Qhull computed a volume (FA), it agrees.

Prints one line per (set, program, options) with PASS/FAIL/SKIP and a reason, then a summary.
Exit 0 if nothing failed, 1 otherwise, 2 on bad usage. LH_GOLDEN_LIFTHULL in the environment
replaces --lifthull (to run the test against a deliberately broken wrapper).

The code, in this folder: golden_sets (the sets, running programs), golden_parse (Qhull's
formats), golden_compare, golden_exact, golden_runner (classification, the PASS/FAIL lines)
and its checks golden_delaunay, golden_voronoi, golden_convex, golden_degenerate.
"""

import argparse
import os
import re
import sys
import time
from collections import Counter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from golden_runner import Runner  # noqa: E402
from golden_sets import make_sets  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_INVOCATIONS = os.path.join(HERE, "..", "data", "qhull", "rbox_invocations.txt")


def print_summary(r, seconds):
    """The table of sets and the totals, after the PASS/FAIL lines."""
    print("\nsummary (%.1f s):" % seconds)
    print("  %-34s %2s %5s  %-11s %-34s %-22s %-8s %s" % (
        "set", "d", "n", "class", "Qhull qdelaunay", "Qhull qconvex", "lifthull", "seconds"))
    for s in r.rows:
        print("  %-34s %2d %5d  %-11s %-34s %-22s %-8s %.1f" % (
            s["name"], s["d"], len(s["pts"]), s["kind"], s.get("qhull_delaunay", "")[:34],
            s.get("qhull_convex", "")[:22], "ok" if s["ok"] else "FAIL", s["seconds"]))
    kinds = Counter(s["kind"] for s in r.rows)
    qfail = [s for s in r.rows if s["kind"] in ("degenerate", "inexact")]
    print("\n  %d sets: %d general, %d degenerate, %d inexact in Qhull, %d lower-dimensional"
          % (len(r.rows), kinds["general"], kinds["degenerate"], kinds["inexact"], kinds["lowdim"]))
    hard = [s for s in qfail if s["qhull_delaunay"] not in ("ok", "duplicates")]
    print("  Qhull's qdelaunay failed, merged, or was inexact on %d sets; lifthull's `qdelaunay i` "
          "passed the exact check on %d of them, all its checks on %d"
          % (len(hard), len([s for s in hard if s.get("exact_ok")]),
             len([s for s in hard if s["ok"]])))
    print("  Voronoi vertices: lifthull within %.3g of the exact circumcentres, Qhull within %.3g, "
          "apart %.3g (relative to the set's extent)"
          % (r.max_vor_err, r.max_vor_qhull, r.max_vor_diff))
    print("  %d checks passed, %d failed" % (r.passes, r.fails))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lifthull", required=False)
    ap.add_argument("--rbox", default="rbox")
    ap.add_argument("--qdelaunay", default="qdelaunay")
    ap.add_argument("--qvoronoi", default="qvoronoi")
    ap.add_argument("--qconvex", default="qconvex")
    ap.add_argument("--invocations", default=DEFAULT_INVOCATIONS)
    ap.add_argument("--shard", default="1/1", help="K/N: run the sets k with k mod N == K-1")
    ap.add_argument("--only", default=None, help="regular expression on the set's name")
    ap.add_argument("--limit", type=int, default=4000,
                    help="exact_check.py --limit (0: no limit)")
    ap.add_argument("-v", action="store_true", help="print the skipped specifications")
    args = ap.parse_args(argv[1:])
    args.lifthull = os.environ.get("LH_GOLDEN_LIFTHULL") or args.lifthull
    if not args.lifthull:
        ap.error("--lifthull (or LH_GOLDEN_LIFTHULL) is required")
    try:
        k, nshard = (int(x) for x in args.shard.split("/"))
        assert 1 <= k <= nshard
    except (ValueError, AssertionError):
        ap.error("--shard K/N with 1 <= K <= N")

    def log(line):
        print(line, flush=True)

    t0 = time.time()
    sets, skipped = make_sets(args, log if args.v else (lambda line: None))
    sets = [s for j, s in enumerate(sets) if j % nshard == k - 1]
    if args.only:
        sets = [s for s in sets if re.search(args.only, s["name"])]
    print("qhull_golden: %d point sets (shard %s; %d specifications skipped), lifthull %s"
          % (len(sets), args.shard, len(skipped), args.lifthull), flush=True)
    r = Runner(args, log)
    for s in sets:
        r.run_set(s)

    print_summary(r, time.time() - t0)
    return 1 if r.fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
