"""qhull_golden.py's runner: runs lifthull and Qhull on one point set, classifies the set
(lower-dimensional, general, degenerate, inexact in Qhull), dispatches to the checks of the
mixins and records each check's PASS/FAIL line and the summary figures."""

import re
import tempfile
import time

from golden_compare import compare_facets
from golden_convex import ConvexChecks
from golden_degenerate import DegenerateChecks
from golden_delaunay import DelaunayChecks
from golden_exact import Exact
from golden_parse import Fail, parse_coords, parse_index_list
from golden_sets import exact_check_i, qhull_error, run
from golden_voronoi import VoronoiChecks


class Runner(DelaunayChecks, VoronoiChecks, ConvexChecks, DegenerateChecks):
    """All the sets of one run. check() and check_upper() run one check and record its line;
    both() runs Qhull and lifthull; the mixins hold the checks of each program."""

    def __init__(self, args, log):
        self.args = args
        self.log = log
        self.fails = 0
        self.passes = 0
        self.rows = []   # summary rows
        self.max_vor_err = 0.0     # lifthull vs exact circumcentre
        self.max_vor_qhull = 0.0   # Qhull vs exact circumcentre
        self.max_vor_diff = 0.0    # lifthull vs Qhull

    def result(self, s, prog, opts, ok, msg):
        tag = "PASS" if ok else "FAIL"
        if ok:
            self.passes += 1
        else:
            self.fails += 1
        self.log("%s  %-34s %-9s %-6s %s" % (tag, s["name"], prog, opts, msg))

    def qhull(self, prog, opts, s):
        exe = {"qdelaunay": self.args.qdelaunay, "qvoronoi": self.args.qvoronoi,
               "qconvex": self.args.qconvex}[prog]
        return run([exe] + opts.split(), s["text"])

    def lift(self, prog, opts, s):
        return run([self.args.lifthull, prog] + opts.split(), s["text"])

    def both(self, prog, opts, s, qt=True):
        """Runs Qhull (with Qt for qdelaunay) and lifthull -> (qhull out, lifthull out)."""
        qopts = opts + (" Qt" if qt and prog == "qdelaunay" else "")
        rc, qo, qe = self.qhull(prog, qopts, s)
        if rc != 0:
            raise Fail("Qhull failed (%s)" % qhull_error(qe))
        rc, lo, le = self.lift(prog, opts, s)
        if rc != 0:
            raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
        return qo, lo

    def upper_exact(self, s):
        """Whether lifthull's furthest-site triangulation passes its exact check (Tv)."""
        rc, out, err = self.lift("qdelaunay", "Qu Tv s", s)
        return rc == 0 and "the exact check passed" in err

    def check_upper(self, s, prog, opts, fn):
        """check() for the outputs that show the upper hull (Qu i, Fn, FN): where they
        differ from Qhull's on nearly cospherical hull sites, Qhull's rounding can be the
        cause; lifthull's passes when its furthest-site triangulation is exactly valid."""
        def guarded():
            try:
                return fn()
            except Fail as e:
                if not self.upper_exact(s):
                    raise
                return "differs from Qhull (%s); lifthull's furthest-site triangulation passes the exact check" % e
        return self.check(s, prog, opts, guarded)

    def check(self, s, prog, opts, fn):
        try:
            msg = fn()
            self.result(s, prog, opts, True, msg)
            return True
        except Fail as e:
            self.result(s, prog, opts, False, str(e))
        except (ValueError, IndexError, KeyError) as e:
            self.result(s, prog, opts, False, "unreadable output (%s: %s)" % (type(e).__name__, e))
        return False

    # -- checks shared by qdelaunay and qconvex ------------------------------------------------

    def compare_i(self, prog, s, st):
        qo, lo = self.both(prog, "i", s)
        st["qi"] = parse_index_list(qo, False, "Qhull i")
        st["li"] = parse_index_list(lo, False, "lifthull i")
        return compare_facets(st["qi"], st["li"], True)

    def both_p(self, prog, s):
        """`p` of both sides -> (Qhull's rows, lifthull's rows), of the same dimension."""
        qo, lo = self.both(prog, "p", s)
        qd, qr = parse_coords(qo, "Qhull p")
        ld, lr = parse_coords(lo, "lifthull p")
        if qd != ld:
            raise Fail("dimension %d in Qhull, %d in lifthull" % (qd, ld))
        return qr, lr

    def compare_fv(self, prog, s):
        qo, lo = self.both(prog, "Fv", s)
        return compare_facets(parse_index_list(qo, True, "Qhull Fv"),
                              parse_index_list(lo, True, "lifthull Fv"), False)

    def compare_fx(self, prog, s):
        qo, lo = self.both(prog, "Fx", s)
        q = sorted(int(t) for t in qo.split()[1:])
        l_ = sorted(int(t) for t in lo.split()[1:])
        if q != l_:
            raise Fail("extreme points differ: %s only in Qhull, %s only in lifthull"
                       % (sorted(set(q) - set(l_))[:5], sorted(set(l_) - set(q))[:5]))
        return "%d extreme points" % len(q)

    # -- classification ------------------------------------------------------------------------

    def classify(self, s, ex, tmp):
        """-> lowdim, general, degenerate or inexact; sets s["qhull_delaunay"]."""
        d = s["d"]
        s["qhull_delaunay"] = "ok"
        if ex.affine_rank() < d:
            rc, out, err = self.qhull("qdelaunay", "Qt i", s)
            s["qhull_delaunay"] = "failed " + qhull_error(err) if rc else "answered"
            return "lowdim"
        rc, out, err = self.qhull("qdelaunay", "s", s)
        text = out + err
        if rc != 0:
            s["qhull_delaunay"] = "failed " + qhull_error(err)
            return "degenerate"
        m = re.search(r"non-simplicial Delaunay regions:\s*(\d+)", text)
        if m and int(m.group(1)) > 0:
            s["qhull_delaunay"] = "merged (%s non-simplicial)" % m.group(1)
            return "degenerate"
        m = re.search(r"Number of merged facets:\s*(\d+)", text)
        if m and int(m.group(1)) > 0:
            # the lower hull is simplicial, the upper one (or a vertical wall over a hull
            # facet with coplanar sites) is not: its negative ids are not comparable
            s["qhull_delaunay"] = "merged upper facets (%s)" % m.group(1)
            return "degenerate"
        if ex.has_duplicates():
            s["qhull_delaunay"] = "duplicates"
            return "degenerate"
        if s.get("hull_coplanar"):
            s["qhull_delaunay"] = "coplanar hull sites"
            return "degenerate"
        rc, qo, qe = self.qhull("qdelaunay", "Qt i", s)
        rc2, lo, le = self.lift("qdelaunay", "i", s)
        if rc != 0:
            s["qhull_delaunay"] = "failed " + qhull_error(qe)
            return "degenerate"
        if rc2 != 0:
            return "general"  # the comparison reports lifthull's failure
        q = {frozenset(r) for r in parse_index_list(qo, False, "Qhull i")}
        l_ = {frozenset(r) for r in parse_index_list(lo, False, "lifthull i")}
        if q == l_:
            return "general"
        missing = len(ex.pts) - len(set().union(*q)) if q else len(ex.pts)
        if missing:
            s["qhull_delaunay"] = "inexact: %d sites missing from Qhull's i" % missing
            return "inexact"
        ok_q, msg_q = exact_check_i(self.args, s["text"], qo, tmp)
        if not ok_q:
            s["qhull_delaunay"] = "inexact: %d simplices differ, Qhull's fail the exact check" \
                % len(q ^ l_)
            return "inexact"
        return "general"  # Qhull's is a Delaunay triangulation too: the comparison decides

    def classify_hull(self, s, ex):
        """Whether the hull is in general position for Qhull: `qconvex Qc s` without merged or
        non-simplicial facets, coplanar points or duplicates."""
        if ex.affine_rank() < s["d"]:
            s["qhull_convex"] = "lowdim"
            return False
        rc, out, err = self.qhull("qconvex", "Qc s", s)
        text = out + err
        if rc != 0:
            s["qhull_convex"] = "failed " + qhull_error(err)
            return False
        for what, pat in (("non-simplicial", r"non-simplicial facets:\s*(\d+)"),
                          ("merged", r"Number of merged facets:\s*(\d+)"),
                          ("coplanar points", r"Number of coplanar points:\s*(\d+)")):
            m = re.search(pat, text)
            if m and int(m.group(1)) > 0:
                s["qhull_convex"] = "%s (%s)" % (what, m.group(1))
                s["hull_coplanar"] = True  # sites on the hull that are no vertices of it
                return False
        if ex.has_duplicates():
            s["qhull_convex"] = "duplicates"
            return False
        s["qhull_convex"] = "ok"
        return True

    # -- one set -------------------------------------------------------------------------------

    def run_set(self, s):
        t0 = time.time()
        ex = Exact(s["pts"])
        with tempfile.TemporaryDirectory(prefix="lh_golden_") as tmp:
            hull_general = self.classify_hull(s, ex)
            kind = self.classify(s, ex, tmp)
            s["kind"] = kind
            f0 = self.fails
            if kind == "lowdim":
                self.lowdim(s)
            elif kind == "general":
                self.general_delaunay(s, ex)
                self.general_voronoi(s, ex)
            else:
                self.degenerate(s, ex, tmp)
            if kind != "lowdim":
                if hull_general:
                    self.general_convex(s, ex)
                elif kind == "general":
                    self.degenerate_hull(s, ex, None)
            s["ok"] = self.fails == f0
        s["seconds"] = time.time() - t0
        self.rows.append(s)
