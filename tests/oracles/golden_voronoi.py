"""qhull_golden.py's comparison of `lifthull qvoronoi` with Qhull's on a set in general position:
o (vertices against the exact circumcentres, regions per site), p, Fv, Fi, Fo and FN.
A mixin of golden_runner.Runner (uses its check, check_upper and both)."""

from collections import Counter

from golden_compare import bisector, compare_facets, compare_fN, plane_diff
from golden_parse import Fail, close, maxdiff, parse_coords, parse_index_list, parse_o, \
    parse_ridges


def vertex_errors(ex, qv, lv, qc, lc):
    """Each Voronoi vertex k >= 1 (the circumcentre of simplex qv[k]) of both sides against the
    exact circumcentre. Relative error: |computed - exact| / max(|exact|, the sites' extent),
    allowed 1e-12 times the simplex's condition max(1, R / diameter) (R: the distance from the
    centre to the simplex; lh_tri_circumcenters is a floating-point solve).
    -> (lifthull's, Qhull's worst error, worst difference, ill-conditioned count)."""
    scale = max(ex.extent, ex.diameter)
    lerr = qerr = diff = 0.0
    ill = 0
    lpos = {f: k for k, f in enumerate(lv) if k}
    for k in range(1, len(qc)):
        f = qv[k]
        c = ex.circumcenter(f)
        sc = max(scale, max(abs(x) for x in c))
        cond = ex.condition(f) / sc
        lk = lpos[f]
        le = maxdiff(lc[lk], c) / sc
        qe = maxdiff(qc[k], c) / sc
        df = maxdiff(lc[lk], qc[k]) / sc
        if cond > 1e2:
            ill += 1
        else:
            lerr, qerr, diff = max(lerr, le), max(qerr, qe), max(diff, df)
        cond = max(1.0, cond)
        if le > 1e-12 * cond:
            raise Fail("lifthull's Voronoi vertex %d is %.3g (relative) from its exact "
                       "circumcentre (condition %.3g)" % (lk, le, cond))
        if df > 1e-12 * cond and qe <= 1e-12 * cond:
            raise Fail("Voronoi vertex %d differs from Qhull's by %.3g relative" % (lk, df))
    return lerr, qerr, diff, ill


def compare_regions(d, nsites, qv, lv, qregions, lregions):
    """Per site, the region's vertex sets (0 = infinity), and the cyclic order in 2D
    -> the number of bounded regions."""
    nb = 0
    for site, (qr, lr) in enumerate(zip(qregions, lregions)):
        qset = Counter(qv[k] if k else 0 for k in qr)
        lset = Counter(lv[k] if k else 0 for k in lr)
        if qset != lset:
            raise Fail("site %d: regions differ (%d vertices in Qhull, %d in lifthull%s)"
                       % (site, len(qr), len(lr),
                          "; bounded in one only" if (0 in qset) != (0 in lset) else ""))
        nb += bool(qr) and 0 not in qset
        if d == 2 and len(qr) > 2:
            a = [qv[k] if k else 0 for k in qr]
            b = [lv[k] if k else 0 for k in lr]
            rots = [b[r:] + b[:r] for r in range(len(b))]
            if a not in rots and a[::-1] not in rots:
                raise Fail("site %d: region vertices not in Qhull's cyclic order" % site)
    if len(qregions) != nsites or len(lregions) != nsites:
        raise Fail("not one region per site")
    return nb


def fv_ridges(name, txt, vmap):
    """One side's qvoronoi Fv -> {(i, j): Counter of its vertices as simplices (0: infinity)}."""
    rows = parse_index_list(txt, True, name + " Fv")
    r = {}
    for row in rows:
        pair = (row[0], row[1])
        if pair in r or pair[0] >= pair[1]:
            raise Fail("%s: ridge %s listed twice or not i < j" % (name, pair))
        verts = Counter(vmap[k] if k else 0 for k in row[2:])
        for f in verts:
            if f and not {pair[0], pair[1]} <= f:
                raise Fail("%s: ridge %s: a vertex's simplex lacks the sites"
                           % (name, pair))
        r[pair] = verts
    return r


def ridge_plane_errors(ex, q, l_):
    """Both sides' Fi/Fo hyperplanes against the bisector of the two sites, normal from i
    towards j -> (lifthull's worst, Qhull's worst within 1e-12, Qhull's further count)."""
    scale = max(1.0, ex.extent)
    lw = qw = 0.0
    qoff = 0
    for (a, b) in q:
        ref = bisector(ex.pts[a], ex.pts[b])
        lw = max(lw, plane_diff(l_[(a, b)], ref, scale))
        e = plane_diff(q[(a, b)], ref, scale)
        if e > 1e-12:
            if plane_diff(q[(a, b)], [-x for x in ref], scale) <= 1e-12:
                raise Fail("ridge %d %d: Qhull's hyperplane has the opposite "
                           "orientation" % (a, b))
            qoff += 1
        else:
            qw = max(qw, e)
    return lw, qw, qoff


class VoronoiChecks:
    def general_voronoi(self, s, ex):
        st = {}
        if not self.check(s, "qvoronoi", "o", lambda: self.voronoi_o(s, ex, st)):
            return
        self.check(s, "qvoronoi", "p", lambda: self.voronoi_p(s, st))
        self.check(s, "qvoronoi", "Fv", lambda: self.voronoi_fv(s, st))
        for opt in ("Fi", "Fo"):
            self.check(s, "qvoronoi", opt, lambda opt=opt: self.voronoi_ridges(s, ex, st, opt))
        self.check_upper(s, "qvoronoi", "FN", lambda: self.voronoi_fN(s, st))

    def voronoi_vertices(self, s, st):
        """Voronoi vertex k >= 1 of each side: the simplex of `qvoronoi i`'s row k - 1."""
        qo, lo = self.both("qvoronoi", "i", s)
        qi = parse_index_list(qo, False, "Qhull qvoronoi i")
        li = parse_index_list(lo, False, "lifthull qvoronoi i")
        compare_facets(qi, li, False)
        st["qv"] = [None] + [frozenset(r) for r in qi]
        st["lv"] = [None] + [frozenset(r) for r in li]
        qo, lo = self.both("qvoronoi", "o", s)
        st["qo"] = parse_o(qo, "Qhull o")
        st["lo"] = parse_o(lo, "lifthull o")
        return qi, li

    def voronoi_o(self, s, ex, st):
        d = s["d"]
        self.voronoi_vertices(s, st)
        (qdim, qhead, qc, qregions), (ldim, lhead, lc, lregions) = st["qo"], st["lo"]
        if qdim != ldim or qhead != lhead:
            raise Fail("header %d / %s in Qhull, %d / %s in lifthull" % (qdim, qhead, ldim, lhead))
        if len(qc) != len(st["qv"]) or len(lc) != len(st["lv"]):
            raise Fail("vertex count is not the simplex count + 1")
        lerr, qerr, diff, ill = vertex_errors(ex, st["qv"], st["lv"], qc, lc)
        self.max_vor_err = max(self.max_vor_err, lerr)
        self.max_vor_qhull = max(self.max_vor_qhull, qerr)
        self.max_vor_diff = max(self.max_vor_diff, diff)
        if qc[0] != [-10.101] * d or lc[0] != [-10.101] * d:
            raise Fail("vertex 0 is not -10.101 (infinity)")
        nb = compare_regions(d, len(s["pts"]), st["qv"], st["lv"], qregions, lregions)
        return ("%d vertices (lifthull within %.2g, Qhull within %.2g of the exact "
                "circumcentres, apart %.2g%s); %d regions equal (%d bounded)%s"
                % (len(qc) - 1, lerr, qerr, diff,
                   "; %d ill-conditioned simplices within their tolerance" % ill if ill else "",
                   len(qregions), nb,
                   ", cyclic order equal" if d == 2 else ""))

    def voronoi_p(self, s, st):
        qo, lo = self.both("qvoronoi", "p", s)
        qd, qr = parse_coords(qo, "Qhull p")
        ld, lr = parse_coords(lo, "lifthull p")
        if qd != ld or len(qr) != len(lr):
            raise Fail("dimension/count %d/%d in Qhull, %d/%d in lifthull"
                       % (qd, len(qr), ld, len(lr)))
        qc, lc = st["qo"][2][1:], st["lo"][2][1:]
        if not all(close(a, b, 0) for a, b in zip(qr, qc)) or \
                not all(close(a, b, 0) for a, b in zip(lr, lc)):
            raise Fail("p and o list different vertices")
        return "%d vertices, as in o" % len(qr)

    def voronoi_fv(self, s, st):
        qo, lo = self.both("qvoronoi", "Fv", s)
        q = fv_ridges("Qhull", qo, st["qv"])
        l_ = fv_ridges("lifthull", lo, st["lv"])
        if set(q) != set(l_):
            raise Fail("ridges differ: %d only in Qhull, %d only in lifthull"
                       % (len(set(q) - set(l_)), len(set(l_) - set(q))))
        bad = [k for k in q if q[k] != l_[k]]
        if bad:
            raise Fail("ridge %s: vertices differ" % (bad[0],))
        st["unbounded"] = {k for k in q if 0 in q[k]}
        return "%d ridges equal (%d unbounded), each dual to a Delaunay facet" \
            % (len(q), len(st["unbounded"]))

    def voronoi_ridges(self, s, ex, st, opt):
        qo, lo = self.both("qvoronoi", opt, s)
        q = parse_ridges(qo, "Qhull " + opt, s["d"])
        l_ = parse_ridges(lo, "lifthull " + opt, s["d"])
        if set(q) != set(l_):
            raise Fail("site pairs differ: %d only in Qhull, %d only in lifthull"
                       % (len(set(q) - set(l_)), len(set(l_) - set(q))))
        if "unbounded" in st:
            want = st["unbounded"] if opt == "Fo" else None
            if want is not None and set(q) != want:
                raise Fail("the unbounded ridges are not those of Fv")
        lw, qw, qoff = ridge_plane_errors(ex, q, l_)
        if lw > 1e-14:
            raise Fail("a lifthull hyperplane is %.3g from the bisector" % lw)
        return "%d %s ridges equal, hyperplanes within %.2g of the bisectors (Qhull's " \
            "within %.2g%s)" % (len(q), "bounded" if opt == "Fi" else "unbounded", lw, qw,
                                ", %d of Qhull's further: its own error" % qoff
                                if qoff else "")

    def voronoi_fN(self, s, st):
        qo, lo = self.both("qvoronoi", "FN", s)
        qi = [sorted(f) for f in st["qv"][1:]]
        li = [sorted(f) for f in st["lv"][1:]]
        return compare_fN(qi, parse_index_list(qo, True, "Qhull FN"), li,
                          parse_index_list(lo, True, "lifthull FN"), len(s["pts"]), None)
