"""qhull_golden.py's checks of lifthull alone where Qhull's answer cannot serve as a reference:
degenerate sets (`qdelaunay i` exact and covering, `qdelaunay Fn` consistent, `qconvex i`
exact with the Delaunay volume and Qhull's FA) and lower-dimensional sets (refused).
A mixin of golden_runner.Runner (uses its check, check_upper, lift and args)."""

import re
from fractions import Fraction

from golden_compare import sides_of
from golden_exact import check_hull_exact
from golden_parse import Fail, parse_index_list
from golden_sets import exact_check_i, qhull_volume


class DegenerateChecks:
    def degenerate(self, s, ex, tmp):
        st = {}
        if not self.check(s, "qdelaunay", "i", lambda: self.degenerate_i(s, ex, tmp, st)):
            return
        self.check_upper(s, "qdelaunay", "Fn", lambda: self.degenerate_fn(s))
        self.degenerate_hull(s, ex, st.get("vol"))

    def degenerate_i(self, s, ex, tmp, st):
        rc, lo, le = self.lift("qdelaunay", "i", s)
        if rc != 0:
            raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
        rows = parse_index_list(lo, False, "lifthull i")
        ok, msg = exact_check_i(self.args, s["text"], lo, tmp)
        if not ok:
            raise Fail(msg)
        used = {v for r in rows for v in r}
        have = {tuple(ex.ip[v]) for v in used}
        missing = [k for k, p in enumerate(ex.ip) if tuple(p) not in have]
        if missing:
            raise Fail("site %d is neither a vertex nor a duplicate of one" % missing[0])
        if len(have) != len(used):
            raise Fail("two vertices are the same point")
        s["exact_ok"] = True
        st["vol"] = sum(abs(ex.vol(r)) for r in rows)
        st["n"] = len(rows)
        return "exact check OK (%d simplices%s), every distinct site a vertex" \
            % (len(rows), ", --limit %d" % self.args.limit if self.args.limit else "")

    def degenerate_fn(self, s):
        """lifthull's Fn alone: main neighbours share a side, every hull side has one of
        the other facets (a negative id) across."""
        rc, li, le = self.lift("qdelaunay", "i", s)
        rc2, lo, le2 = self.lift("qdelaunay", "Fn", s)
        if rc or rc2:
            raise Fail("lifthull failed: %s" % (le + le2).strip()[:100])
        if re.search(r"(^|\s)-0(\s|$)", lo):
            raise Fail("a hull side has no facet across: printed as -0 (%d times)"
                       % len(re.findall(r"(?:^|\s)-0(?=\s|$)", lo)))
        rows = parse_index_list(li, False, "lifthull i")
        pos, neg, count = sides_of("lifthull", rows, rows, parse_index_list(lo, True, "Fn"))
        if neg is None:
            raise Fail("a neighbour is not opposite its vertex")
        return "consistent: %d hull sides, each with a negative id (%d distinct)" \
            % (sum(count.values()), len(set(neg.values())))

    def degenerate_hull(self, s, ex, dvol):
        self.check(s, "qconvex", "i", lambda: self.exact_hull(s, ex, dvol))

    def exact_hull(self, s, ex, dvol):
        """lifthull's `qconvex i` exactly valid; its volume equal to the Delaunay simplices'
        (dvol, when known) and to Qhull's FA (when Qhull computed one)."""
        rc, lo, le = self.lift("qconvex", "i", s)
        if rc != 0:
            raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
        rows = parse_index_list(lo, False, "lifthull qconvex i")
        hvol = check_hull_exact(ex, rows)
        msg = "%d facets: every point inside or on every plane, ridges in two facets" % len(rows)
        if dvol is not None:
            if dvol != hvol:
                raise Fail("the Delaunay simplices' volume %.17g != the hull's %.17g"
                           % (dvol / ex.den ** ex.d, hvol / ex.den ** ex.d))
            msg += "; Delaunay volume = hull volume (exact)"
        qv = qhull_volume(self.args, s["text"])
        if qv is not None:
            fact = 1
            for k in range(2, ex.d + 1):
                fact *= k
            mine = float(Fraction(hvol, ex.den ** ex.d * fact))
            if abs(mine - qv) > 1e-7 * max(abs(qv), 1e-300) + 1e-12:  # FA has 8 digits
                raise Fail("hull volume %.17g, Qhull's FA %.17g" % (mine, qv))
            msg += "; = Qhull's FA volume"
        return msg

    def lowdim(self, s):
        self.check(s, "qdelaunay", "i", lambda: self.refuse_lowdim(s))

    def refuse_lowdim(self, s):
        rc, lo, le = self.lift("qdelaunay", "i", s)
        if rc == 0:
            raise Fail("lifthull answered for a lower-dimensional set")
        if "affine subspace" not in le:
            raise Fail("no 'affine subspace' message: %s" % le.strip()[:120])
        return "refused: %s" % le.strip().splitlines()[-1][:100]
