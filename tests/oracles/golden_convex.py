"""qhull_golden.py's comparison of `lifthull qconvex` with Qhull's on a hull in general position:
i (with parity), o, n, Fn, FN, Fv, Fx, p, FC (planes and centrums to 1e-12).
A mixin of golden_runner.Runner (uses its check, both and the checks shared with qdelaunay)."""

from golden_compare import compare_fn, compare_fN, compare_o_delaunay, compare_point_rows, \
    plane_diff
from golden_parse import Fail, maxdiff, parse_coords, parse_index_list, parse_o


def facet_row_errors(ex, opt, q_i, l_i, qr, lr):
    """Per facet, Qhull's row qr and lifthull's lr of n (planes) or FC (centrums), matched by
    the facets' vertex sets -> (worst error, Qhull's worst plane error, Qhull's planes
    further than 1e-12 from the exact one)."""
    lmap = {frozenset(f): r for f, r in zip(l_i, lr)}
    scale = max(1.0, ex.extent)
    worst = qworst = 0.0
    qoff = 0
    for f, r in zip(q_i, qr):
        b = lmap[frozenset(f)]
        if opt == "n":
            # both against the exact plane: lifthull's within 1e-12, or within
            # 1e-15 x the facet's condition (floating point), or 100 x Qhull's error
            ref, cond = ex.plane(f)
            w = plane_diff(b, ref, scale)
            qw = plane_diff(r, ref, scale)
            if qw > 1e-12:
                qoff += 1
            qworst = max(qworst, qw)
            if w > max(1e-12, 1e-15 * cond, 100 * qw):
                raise Fail("facet %s: lifthull's plane is %.3g from the exact one, "
                           "Qhull's %.3g (condition %.3g)" % (sorted(f), w, qw, cond))
        else:
            w = maxdiff(r, b) / scale
            if w > 1e-12:
                raise Fail("facet %s: centrums differ by %.3g" % (sorted(f), w))
        worst = max(worst, w)
    return worst, qworst, qoff


class ConvexChecks:
    def general_convex(self, s, ex):
        d = s["d"]
        st = {}
        if not self.check(s, "qconvex", "i", lambda: self.compare_i("qconvex", s, st)):
            return
        self.check(s, "qconvex", "o", lambda: self.convex_o(s, ex))
        self.check(s, "qconvex", "n", lambda: self.convex_per_facet(s, ex, st, "n", d + 1))
        self.check(s, "qconvex", "Fn", lambda: self.convex_fn(s, st))
        self.check(s, "qconvex", "FN", lambda: self.convex_fN(s, st))
        self.check(s, "qconvex", "Fv", lambda: self.compare_fv("qconvex", s))
        self.check(s, "qconvex", "Fx", lambda: self.compare_fx("qconvex", s))
        self.check(s, "qconvex", "p", lambda: self.convex_p(s, ex))
        self.check(s, "qconvex", "FC", lambda: self.convex_per_facet(s, ex, st, "FC", d))

    def convex_o(self, s, ex):
        qo, lo = self.both("qconvex", "o", s)
        return compare_o_delaunay(parse_o(qo, "Qhull o"), parse_o(lo, "lifthull o"), ex, False)

    def convex_per_facet(self, s, ex, st, opt, dim):
        """n or FC: one row of dim numbers per facet of `i`."""
        qo, lo = self.both("qconvex", opt, s)
        qd, qr = parse_coords(qo, "Qhull " + opt)
        ld, lr = parse_coords(lo, "lifthull " + opt)
        if qd != dim or ld != dim or len(qr) != len(st["qi"]) or len(lr) != len(st["li"]):
            raise Fail("dimension/count %d/%d in Qhull, %d/%d in lifthull"
                       % (qd, len(qr), ld, len(lr)))
        worst, qworst, qoff = facet_row_errors(ex, opt, st["qi"], st["li"], qr, lr)
        what = "planes" if opt == "n" else "centrums"
        return "%d %s within %.2g%s" % (len(qr), what, worst,
                                        " of the exact planes (Qhull's within %.2g%s)"
                                        % (qworst, ", %d further: its own error" % qoff
                                           if qoff else "") if opt == "n" else "")

    def convex_fn(self, s, st):
        qo, lo = self.both("qconvex", "Fn", s)
        msg, _ = compare_fn(st["qi"], None, parse_index_list(qo, True, "Qhull Fn"), st["li"],
                            None, parse_index_list(lo, True, "lifthull Fn"), False)
        return msg

    def convex_fN(self, s, st):
        qo, lo = self.both("qconvex", "FN", s)
        return compare_fN(st["qi"], parse_index_list(qo, True, "Qhull FN"), st["li"],
                          parse_index_list(lo, True, "lifthull FN"), len(s["pts"]),
                          {}).split(", upper")[0]

    def convex_p(self, s, ex):
        qr, lr = self.both_p("qconvex", s)
        w = compare_point_rows(qr, lr, 1e-15 * ex.extent, "p")
        return "%d vertices within %.2g" % (len(qr), w)
