#!/usr/bin/env python3
"""Exact cross-check of `lifthull locate` against CGAL's locate and nearest_vertex (issue #4).

  compare_locate.py --lifthull PATH --oracle PATH [--keep DIR] [--case NAME]...

--oracle is oracle_cgal_locate (CGAL Delaunay_triangulation_2/_3, Epick). The cases are built
here (sites from `lifthull points`, which is deterministic, queries inline), each written as a
pair of Qhull-format files (queries with repr(): they read back as the same doubles); --case
runs only the named ones, --keep keeps the files in DIR.

Every coordinate of a case is a dyadic rational, so after scaling by a common power of two the
checks below are exact integer arithmetic (orientation and in-sphere determinants):

 (a) `in S v.. b.. nearest N`: S is simplex S of `lifthull delaunay SITES` with those vertices
     in that order; q is in it (every orient of q against a facet has the simplex's sign or is
     zero); S is the smallest index among ALL simplices containing q (brute force); the b_i are
     q's barycentric coordinates (within 1e-7 of the exact ones).
     `out f.. distance D nearest N`: no simplex contains q; f is a hull facet (a facet of one
     simplex); dist(q, f's hyperplane) <= D <= |q - N| (floating point, 1e-9 relative).
 (b) The location type: q lies in the relative interior of exactly one face F of the Delaunay
     subdivision (simplices joined across exactly cospherical facets: the cells every Delaunay
     triangulation refines), found exactly from the cell of lifthull's simplex. If F is a
     simplex, every Delaunay triangulation has it as a face, so lifthull's minimal face of q
     (the vertices whose orients are nonzero), CGAL's locate type (VERTEX, EDGE, FACE/FACET,
     CELL) and CGAL's sub-face (li/lj) must all be F. If F is not a simplex (a query inside a
     cocircular polygon, on the diagonal of a grid square, at a grid cube's centre...), the
     two triangulations may legitimately differ there, so both minimal faces need only lie in
     F (vertex sets within F's, dimension at most F's); these are counted as `ambiguous`.
     Outside: lifthull `out` iff CGAL OUTSIDE_CONVEX_HULL; a query on the hull boundary is
     `in` for lifthull and VERTEX/EDGE/FACET for CGAL, never outside. CGAL's answer is itself
     verified exactly when its face/cell is finite (its zero pattern gives its sub-face).
 (c) Strictly interior queries in general position: F is lifthull's simplex, so (b) requires
     CGAL's cell to have the same vertex set. Cases marked general fail if any cospherical
     tie is found, so that the strict comparison is not silently relaxed.
 (d) Nearest site: |q - N|^2 == |q - N_cgal|^2 exactly, and N is the smallest index among the
     sites at the minimum distance (brute force).
 (e) Determinism: the queries located in reverse order (other walks) give the same lines.

Exit 0 if every case passes, 1 if any check fails, 2 on a tool failure or bad usage.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import canon  # noqa: E402  (the shared Qhull-format reader)
from locate_geometry import Tri, dist2, sgn  # noqa: E402  (exact, on integers)


class ToolError(Exception):
    pass


def read_i_text(text):
    """Qhull `i` output (a count line, then one simplex a line) -> list of index tuples."""
    lines = [ln.split() for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    if not lines or len(lines) != int(lines[0][0]) + 1:
        raise ToolError("malformed simplex list")
    return [tuple(int(x) for x in ln) for ln in lines[1:]]


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True)
    if p.returncode != 0:
        raise ToolError("%s: exit %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()[:500]))
    return p.stdout


def write_points(path, d, pts):
    with open(path, "w", encoding="ascii") as f:
        f.write("%d\n%d\n" % (d, len(pts)))
        for p in pts:
            f.write(" ".join(repr(float(x)) for x in p) + "\n")


def read_points(path):
    d, n, c = canon.read_qhull_points(path)
    return d, [tuple(c[i * d:(i + 1) * d]) for i in range(n)]


CGAL_DIM = {"VERTEX": 0, "EDGE": 1, "FACE": 2, "FACET": 2, "CELL": 3}
KINDS = ("vertex", "edge", "facet", "interior")


def kind(k, d):
    """The name of a face of dimension k in dimension d."""
    return "interior" if k == d else KINDS[k] if 0 <= k < len(KINDS) else str(k)


def parse_cgal(line):
    t = line.split()
    i_cell, i_sub, i_near = t.index("cell"), t.index("sub"), t.index("nearest")
    return (t[0], [int(x) for x in t[i_cell + 1:i_sub]], [int(x) for x in t[i_sub + 1:i_near]],
            int(t[i_near + 1]))


class CaseAbort(Exception):
    """A tool's output cannot be checked at all: the case fails with this message alone."""


def run_case_tools(name, d, sites, queries, tools, workdir):
    """Writes the case's files, runs `lifthull delaunay`, `lifthull locate` (in order and in
    reverse order) and the oracle -> (simplices, lines, reversed lines, oracle lines, sites,
    queries as read back)."""
    lifthull, oracle = tools
    sfile = os.path.join(workdir, name + ".sites.txt")
    qfile = os.path.join(workdir, name + ".queries.txt")
    rfile = os.path.join(workdir, name + ".queries_rev.txt")
    write_points(sfile, d, sites)
    write_points(qfile, d, queries)
    write_points(rfile, d, queries[::-1])
    simplices = read_i_text(run([lifthull, "delaunay", sfile]))
    lh = run([lifthull, "locate", sfile, qfile]).splitlines()
    lh_rev = run([lifthull, "locate", sfile, rfile]).splitlines()[::-1]
    cg = run([oracle, sfile, qfile]).splitlines()
    # Re-read what was written (both tools read these exact doubles).
    _, sites = read_points(sfile)
    _, queries = read_points(qfile)
    return simplices, lh, lh_rev, cg, sites, queries


def scale_to_integers(sites, queries):
    """-> (den, sites * den, queries * den): every coordinate a dyadic rational, den the
    largest denominator (powers of two: the largest divides all)."""
    den = 1
    for p in sites + queries:
        for x in p:
            den = max(den, Fraction(x).denominator)
    P = [tuple(int(Fraction(x) * den) for x in p) for p in sites]
    Q = [tuple(int(Fraction(x) * den) for x in p) for p in queries]
    return den, P, Q


class QueryChecks:
    """The checks (a)-(d) of one case's queries, in exact integer arithmetic; errors and the
    counts (st) accumulate here."""

    def __init__(self, d, P, queries, den, tri):
        self.d, self.P, self.queries, self.den, self.tri = d, P, queries, den, tri
        self.errors = []
        self.st = dict(inside=0, outside=0, boundary=0, shared=0, ambiguous=0,
                       ambiguous_differ=0, nearest_ties=0, **{v: 0 for v in KINDS})
        self.bary_err = 0.0

    def err(self, k, msg):
        self.errors.append("query %d (%s): %s"
                           % (k, " ".join(repr(x) for x in self.queries[k]), msg))

    def query(self, k, q, lh_line, lh_rev_line, cg_line):
        line = lh_line.split()
        if lh_line != lh_rev_line:
            self.err(k, "nondeterministic: %r in order, %r in reverse order" % (lh_line, lh_rev_line))
        try:
            ctype, ccell, csub, cnear = parse_cgal(cg_line)
        except ValueError:
            raise CaseAbort("cannot parse oracle line %r" % cg_line)
        try:
            near = int(line[line.index("nearest") + 1])
        except (ValueError, IndexError):
            self.err(k, "cannot parse %r" % lh_line)
            return
        best = self.nearest(k, q, near, cnear)
        inside = self.tri.containing(q)
        if line[0] == "out":
            self.outside(k, q, line, inside, ctype, best)
            return
        if line[0] != "in" or len(line) != 2 * self.d + 6:
            self.err(k, "cannot parse %r" % lh_line)
            return
        self.inside(k, q, line, inside, ctype, ccell, csub)

    def nearest(self, k, q, near, cnear):
        """(d) nearest site -> the smallest squared distance."""
        P, n = self.P, len(self.P)
        d2 = [dist2(q, p) for p in P]
        best = min(d2)
        ties = [i for i in range(n) if d2[i] == best]
        if len(ties) > 1:
            self.st["nearest_ties"] += 1
        if not 0 <= near < n or d2[near] != best:
            self.err(k, "nearest %d is not a nearest site (%s is)" % (near, ties[0]))
        elif near != ties[0]:
            self.err(k, "nearest %d is not the smallest index among the ties %s" % (near, ties))
        if not 0 <= cnear < n or d2[cnear] != d2[near]:
            self.err(k, "nearest %d and CGAL's %d are not equally near" % (near, cnear))
        return best

    def outside(self, k, q, line, inside, ctype, best):
        """(a), (b) for `out f.. distance D nearest N`."""
        d, tri = self.d, self.tri
        self.st["outside"] += 1
        f = [int(x) for x in line[1:1 + d]]
        dist = float(line[line.index("distance") + 1])
        if inside:
            self.err(k, "lifthull says out, but simplices %s contain it" % inside[:5])
        if ctype != "OUTSIDE_CONVEX_HULL":
            self.err(k, "lifthull says out, CGAL says %s" % ctype)
        if not tri.hull_facet(f):
            self.err(k, "out: facet %s is not a hull facet" % f)
            return
        # distance to the facet's hyperplane <= D <= distance to the nearest site
        fp = [[float(Fraction(c, self.den)) for c in self.P[v]] for v in f]
        qf = [float(x) for x in self.queries[k]]
        if d == 2:
            nrm = [-(fp[1][1] - fp[0][1]), fp[1][0] - fp[0][0]]
        else:
            u = [fp[1][j] - fp[0][j] for j in range(3)]
            w = [fp[2][j] - fp[0][j] for j in range(3)]
            nrm = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                   u[0] * w[1] - u[1] * w[0]]
        nn = sum(x * x for x in nrm) ** 0.5
        hd = abs(sum(nrm[j] * (qf[j] - fp[0][j]) for j in range(d))) / nn
        sd = float(Fraction(best, self.den * self.den)) ** 0.5
        if not (dist > 0 and hd <= dist * (1 + 1e-9) + 1e-300 and dist <= sd * (1 + 1e-9)):
            self.err(k, "out: distance %r not in [%r, %r]" % (dist, hd, sd))

    def inside(self, k, q, line, inside, ctype, ccell, csub):
        """(a) containment, the smallest index, barycentric coordinates; then (b), (c)."""
        d, tri = self.d, self.tri
        self.st["inside"] += 1
        S = int(line[1])
        verts = tuple(int(x) for x in line[2:3 + d])
        bary = [float(x) for x in line[3 + d:4 + 2 * d]]
        if not 0 <= S < len(tri.S) or tri.S[S] != verts:
            self.err(k, "simplex %d is not %s in `lifthull delaunay` (it is %s)"
                     % (S, verts, tri.S[S] if 0 <= S < len(tri.S) else "out of range"))
            return
        if S not in inside:
            self.err(k, "simplex %d %s does not contain the query (orients %s)"
                     % (S, verts, tri.orients(S, q)))
            return
        if S != min(inside):
            self.err(k, "simplex %d, but simplex %d (smallest of %s) also contains it"
                     % (S, min(inside), inside[:8]))
        if len(inside) > 1:
            self.st["shared"] += 1
        if any(x == 0 and tri.hull_facet(tri.S[si][:i] + tri.S[si][i + 1:])
               for si in inside for i, x in enumerate(tri.orients(si, q))):
            self.st["boundary"] += 1
            if ctype.startswith("OUTSIDE"):
                self.err(k, "on the hull boundary: lifthull in, CGAL %s" % ctype)
        raw = tri.raw_orients(S, q)
        tot = sum(raw)
        for b, r in zip(bary, raw):
            self.bary_err = max(self.bary_err, abs(b - float(Fraction(r, tot))))
        self.location(k, q, S, verts, ctype, ccell, csub)

    def location(self, k, q, S, verts, ctype, ccell, csub):
        """(b), (c) the location type of q in simplex S against CGAL's."""
        d, tri = self.d, self.tri
        o = tri.orients(S, q)
        lsub = sorted(v for v, x in zip(verts, o) if x != 0)
        lk = len(lsub) - 1
        self.st[kind(lk, d)] += 1
        if ctype.startswith("OUTSIDE") or ctype not in CGAL_DIM:
            self.err(k, "lifthull in simplex %d (on a %s), CGAL says %s" % (S, kind(lk, d), ctype))
            return
        ck = CGAL_DIM[ctype]
        if len(ccell) == d + 1:  # verify CGAL's own answer exactly
            cs = tuple(ccell)
            o2 = [sgn(x) for x in Tri(d, self.P, [cs]).orients(0, q)]
            if min(o2) < 0 or sorted(v for v, x in zip(cs, o2) if x != 0) != csub:
                self.err(k, "oracle inconsistent: %s cell %s sub %s, orients %s"
                         % (ctype, ccell, csub, o2))
        fv, fk, simplex = tri.minimal_face(S, q)
        if simplex:
            if not (lk == ck == fk and lsub == csub == fv):
                self.err(k, "lifthull: on %s %s (simplex %d); CGAL: %s %s; exact face: %s %s"
                         % (kind(lk, d), lsub, S, ctype, csub, kind(fk, d), fv))
        else:
            self.st["ambiguous"] += 1
            if lk != ck or lsub != csub:
                self.st["ambiguous_differ"] += 1
            if not (set(lsub) <= set(fv) and set(csub) <= set(fv) and lk <= fk and ck <= fk):
                self.err(k, "lifthull: on %s %s; CGAL: %s %s; both must lie in the non-simplex "
                         "Delaunay face %s of dimension %d"
                         % (kind(lk, d), lsub, ctype, csub, fv, fk))


def check_case(name, d, sites, queries, general, tools, workdir):
    t0 = time.time()
    simplices, lh, lh_rev, cg, sites, queries = run_case_tools(name, d, sites, queries, tools,
                                                               workdir)
    n, m = len(sites), len(queries)
    for what, lines in (("lifthull locate", lh), ("lifthull locate (reversed)", lh_rev),
                        ("oracle", cg)):
        if len(lines) != m:
            return ["%s printed %d lines for %d queries" % (what, len(lines), m)], None
    den, P, Q = scale_to_integers(sites, queries)
    tri = Tri(d, P, simplices)
    qc = QueryChecks(d, P, queries, den, tri)
    if general and tri.ties:
        qc.errors.append("case marked general position, but %d exactly cospherical facets" % tri.ties)
    if any(s == 0 for s in tri.sign):
        qc.errors.append("lifthull delaunay has a flat simplex")
    try:
        for k in range(m):
            qc.query(k, Q[k], lh[k], lh_rev[k], cg[k])
    except CaseAbort as e:
        return [str(e)], None
    errors, st = qc.errors, qc.st
    if qc.bary_err > 1e-7:
        errors.append("barycentric coordinates off by up to %.3g" % qc.bary_err)
    st["bary_err"] = qc.bary_err
    st["time"] = time.time() - t0
    st["n"], st["m"], st["simplices"], st["ties"] = n, m, len(tri.S), tri.ties
    return errors, st


# ---- the cases -------------------------------------------------------------------------------

def points(lifthull, args, workdir):
    path = os.path.join(workdir, "gen.txt")
    with open(path, "w") as f:
        f.write(run([lifthull, "points"] + args))
    return read_points(path)[1]


def near_faces(lifthull, workdir, d, sites, step):
    """Queries at and near the faces of the triangulation: the midpoint of an edge and the
    centroid of every step-th simplex, and of every step/10-th hull facet its first vertex (a
    hull vertex) and its centroid (rounded: on, just inside or just outside the hull)."""
    path = os.path.join(workdir, "tmp_sites.txt")
    write_points(path, d, sites)
    simplices = read_i_text(run([lifthull, "delaunay", path]))
    out = []
    for s in simplices[::step]:
        a, b = sites[s[0]], sites[s[1]]
        out.append(tuple((x + y) / 2 for x, y in zip(a, b)))
        out.append(tuple(sum(sites[v][j] for v in s) / (d + 1) for j in range(d)))
    count = {}
    for s in simplices:
        for i in range(d + 1):
            f = tuple(sorted(s[:i] + s[i + 1:]))
            count[f] = count.get(f, 0) + 1
    hull = sorted(f for f, k in count.items() if k == 1)
    for f in hull[::max(1, step // 10)]:
        out.append(sites[f[0]])
        out.append(tuple(sum(sites[v][j] for v in f) / d for j in range(d)))
    return out


def grid_queries(K, d):
    """Grid {0..K-1}^d: vertices, edge midpoints, face and cell centres, the hull boundary,
    and outside."""
    import itertools
    q = []
    for c in itertools.product(*[[x / 2 for x in range(2 * K - 1)]] * d):
        q.append(c)  # every half-integer point: vertices, midpoints, face/cell centres
    h = K - 1
    if d == 2:
        q += [(0, 0.25), (h, 3.3), (1.7, 0), (2.5, h), (h, h), (0, h)]
        q += [(-1, 4), (K, K), (4.5, -0.001), (h + 1e-9, 2), (-0.5, -0.5), (h / 2, 2 * K)]
    else:
        q += [(0, 1.25, 2.5), (h, 0.3, 1.7), (1.5, 0, 2.5), (0.5, 1.5, h), (0, 0, 1.5),
              (h, h, 0.5), (0, 2, 2)]
        q += [(-1, 2, 2), (K, K, K), (2, -1e-9, 2), (h + 0.5, h / 2, 1), (-0.5, -0.5, -0.5)]
    return q


def sphere_queries(sites, d, extra_pairs):
    M = sum(x * x for x in sites[0])
    r = int(M ** 0.5) + 1
    present = set(sites)
    q = [tuple([0.0] * d)] + list(sites)
    n = len(sites)
    for i in range(0, n, max(1, n // extra_pairs)):
        for j in (i + 1, i + n // 2, i + n // 3):
            a, b = sites[i], sites[j % n]
            q.append(tuple((x + y) / 2 for x, y in zip(a, b)))
    # integer points of the same sphere that are not sites: outside the hull
    import itertools
    missing = []
    for c in itertools.product(range(-r, r + 1), repeat=d):
        if sum(x * x for x in c) == M and tuple(float(x) for x in c) not in present:
            missing.append(tuple(float(x) for x in c))
    return q + missing[:20]


def build_cases(lifthull, workdir):
    cases = []
    # 2D uniform: 1000 sites in the cube; random queries inside and outside the hull, sites,
    # Delaunay edge midpoints and centroids (floating-point: near, not on, the edges), far out.
    s2 = points(lifthull, ["1000", "-d", "2", "--seed", "11"], workdir)
    qr = points(lifthull, ["400", "-d", "2", "--seed", "12"], workdir)
    q2 = [tuple(1.2 * x for x in p) for p in qr] + s2[::50] + [tuple(3 * x for x in p)
                                                               for p in qr[:20]]
    q2 += near_faces(lifthull, workdir, 2, s2, 100)
    cases.append(("uniform_d2", 2, s2, q2, True))
    s3 = points(lifthull, ["500", "-d", "3", "--seed", "21"], workdir)
    qr = points(lifthull, ["400", "-d", "3", "--seed", "22"], workdir)
    q3 = [tuple(1.2 * x for x in p) for p in qr] + s3[::25] + [tuple(3 * x for x in p)
                                                               for p in qr[:20]]
    q3 += near_faces(lifthull, workdir, 3, s3, 150)
    cases.append(("uniform_d3", 3, s3, q3, True))
    # Integer grids: every face is exactly degenerate.
    # Integer grids: every face is exactly degenerate. Queries: all half-integer points, the
    # hull boundary, outside, and 60 random points of the grid's box.
    for K, d in ((10, 2), (5, 3)):
        qr = points(lifthull, ["60", "-d", str(d), "--seed", "31"], workdir)
        qr = [tuple((x + 0.5) * (K - 1) for x in p) for p in qr]
        cases.append(("grid%d_d%d" % (K, d), d,
                      points(lifthull, ["--grid", str(K), "-d", str(d)], workdir),
                      grid_queries(K, d) + qr, False))
    # Exactly cocircular / cospherical sites: the centre, the sites, chord midpoints, and
    # integer points of the same circle/sphere that are not sites.
    sc = points(lifthull, ["40", "-d", "2", "--exact-sphere", "--seed", "3"], workdir)
    cases.append(("sphere40_d2", 2, sc, sphere_queries(sc, 2, 20), False))
    ss = points(lifthull, ["60", "-d", "3", "--exact-sphere", "--seed", "3"], workdir)
    cases.append(("sphere60_d3", 3, ss, sphere_queries(ss, 3, 20), False))
    return cases


def main(argv):
    ap = argparse.ArgumentParser(description="lifthull locate vs CGAL locate, exactly")
    ap.add_argument("--lifthull", required=True)
    ap.add_argument("--oracle", required=True)
    ap.add_argument("--keep")
    ap.add_argument("--case", action="append")
    a = ap.parse_args(argv[1:])
    workdir = a.keep or tempfile.mkdtemp(prefix="lh_locate_")
    os.makedirs(workdir, exist_ok=True)
    status = 0
    try:
        t0 = time.time()
        for name, d, sites, queries, general in build_cases(a.lifthull, workdir):
            if a.case and name not in a.case:
                continue
            errors, st = check_case(name, d, sites, queries, general,
                                    (a.lifthull, a.oracle), workdir)
            if st:
                print("locate %-12s d=%d n=%d simplices=%d queries=%d: in=%d (vertex %d, edge %d, "
                      "facet %d, interior %d; on the hull %d; in >1 simplex %d; non-simplex face %d, "
                      "types differing there %d) out=%d; nearest ties %d; cospherical facets %d; "
                      "bary err %.1e; %.1f s -> %s"
                      % (name, d, st["n"], st["simplices"], st["m"], st["inside"], st["vertex"],
                         st["edge"], st["facet"], st["interior"], st["boundary"], st["shared"],
                         st["ambiguous"], st["ambiguous_differ"], st["outside"],
                         st["nearest_ties"], st["ties"], st["bary_err"], st["time"],
                         "FAIL" if errors else "OK"))
            else:
                print("locate %-12s -> FAIL" % name)
            for e in errors[:15]:
                print("  " + e)
            if len(errors) > 15:
                print("  ... %d more" % (len(errors) - 15))
            if errors:
                status = 1
        print("compare_locate: %s in %.1f s"
              % ("OK" if status == 0 else "FAIL", time.time() - t0))
    except (ToolError, canon.CanonError, OSError) as e:
        print("compare_locate: %s" % e)
        status = 2
    finally:
        if not a.keep:
            shutil.rmtree(workdir, ignore_errors=True)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
