"""qhull_golden.py's comparison of `lifthull qdelaunay` with Qhull's (Qt added) on a set in
general position: i (with parity), Fn, FN, o, p, Fv, Fx and Qu i.
A mixin of golden_runner.Runner (uses its check, check_upper, both, qhull and the checks
shared with qconvex)."""

import re

from golden_compare import compare_facets, compare_fn, compare_fN, compare_o_delaunay, \
    compare_point_rows, lift_tolerance
from golden_parse import parse_index_list, parse_o


class DelaunayChecks:
    def general_delaunay(self, s, ex):
        st = {}
        if not self.check(s, "qdelaunay", "i", lambda: self.compare_i("qdelaunay", s, st)):
            return
        self.check_upper(s, "qdelaunay", "Fn", lambda: self.delaunay_fn(s, st))
        self.check_upper(s, "qdelaunay", "FN", lambda: self.delaunay_fN(s, st))
        self.check(s, "qdelaunay", "o", lambda: self.delaunay_o(s, ex))
        self.check(s, "qdelaunay", "p", lambda: self.delaunay_p(s, ex))
        self.check(s, "qdelaunay", "Fv", lambda: self.compare_fv("qdelaunay", s))
        self.check(s, "qdelaunay", "Fx", lambda: self.compare_fx("qdelaunay", s))
        self.check_upper(s, "qdelaunay", "Qu i", lambda: self.delaunay_qu(s))

    def delaunay_fn(self, s, st):
        qo, lo = self.both("qdelaunay", "Fn", s)
        rc, qv, qe = self.qhull("qdelaunay", "Qt Fv", s)
        qalign = parse_index_list(qv, True, "Qhull Fv") if rc == 0 else None
        msg, st["neg"] = compare_fn(st["qi"], qalign, parse_index_list(qo, True, "Qhull Fn"),
                                    st["li"], st["li"], parse_index_list(lo, True, "lifthull Fn"),
                                    False)
        return msg

    def delaunay_fN(self, s, st):
        qo, lo = self.both("qdelaunay", "FN", s)
        return compare_fN(st["qi"], parse_index_list(qo, True, "Qhull FN"), st["li"],
                          parse_index_list(lo, True, "lifthull FN"), len(s["pts"]), st.get("neg"))

    def delaunay_o(self, s, ex):
        qo, lo = self.both("qdelaunay", "o", s)
        return compare_o_delaunay(parse_o(qo, "Qhull o"), parse_o(lo, "lifthull o"), ex, True)

    def delaunay_p(self, s, ex):
        qr, lr = self.both_p("qdelaunay", s)
        zmax = max([1e-300] + [abs(r[-1]) for r in qr])
        w = compare_point_rows([r[:-1] for r in qr], [r[:-1] for r in lr], 1e-15 * ex.extent, "p")
        z = compare_point_rows(sorted(r[-1:] for r in qr), sorted(r[-1:] for r in lr),
                               lift_tolerance(ex) * zmax, "p (lifted)")
        return "%d vertices, coordinates within %.2g, lifted within %.2g" % (len(qr), w, z)

    def delaunay_qu(self, s):
        rc, out, err = self.qhull("qdelaunay", "Qu s", s)
        m = re.search(r"non-simplicial[^:]*:\s*(\d+)", out + err)
        if rc == 0 and m and int(m.group(1)) > 0:
            return "skipped: Qhull merged furthest-site facets (%s non-simplicial)" % m.group(1)
        qo, lo = self.both("qdelaunay", "Qu i", s)
        return compare_facets(parse_index_list(qo, False, "Qhull Qu i"),
                              parse_index_list(lo, False, "lifthull Qu i"), False)
