#!/usr/bin/env python3
"""Qhull's output options in `lifthull qdelaunay | qvoronoi | qconvex` against Qhull 2020.2's
programs (qhull-bin), added by issue 30 item 15:

  qhull_formats.py LIFTHULL [--only REGEX] [-v]

On rbox sets in general position the outputs must agree up to facet order (facets matched by
their vertex sets, numbers within 1e-12 relative); on degenerate sets lifthull is exact and
its values are checked against exact rational arithmetic (Qhull's are printed beside, not
asserted). Exit 0 when every check passed, 1 otherwise, 77 when Qhull's programs are missing.
"""

import argparse
import re
import shutil
import sys
from fractions import Fraction
from math import factorial

from qhull_check import FAILS, PASSES, VERBOSE, cdd_rows, check, rbox, run


def points(text):
    toks = text.split("\n")
    d = int(toks[0].split()[0])
    n = int(toks[1].split()[0])
    return d, [tuple(float(x) for x in l.split()) for l in toks[2:2 + n]]


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def facets_i(out):
    lines = out.strip().split("\n")
    return [frozenset(int(x) for x in l.split()) for l in lines[1:1 + int(lines[0])]]


def reals(out):
    """The numbers of a count-then-one-per-line output (Fa)."""
    lines = out.strip().split("\n")
    return [float(l) for l in lines[1:1 + int(lines[0])]]


def det(m):
    """Exact determinant (Fractions), Gaussian elimination."""
    m = [row[:] for row in m]
    n, s = len(m), Fraction(1)
    for c in range(n):
        p = next((r for r in range(c, n) if m[r][c] != 0), None)
        if p is None:
            return Fraction(0)
        if p != c:
            m[c], m[p] = m[p], m[c]
            s = -s
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            for k in range(c, n):
                m[r][k] -= f * m[c][k]
        s *= m[c][c]
    return s


def exact_volume(pts, facets, d):
    """|sum over facets of det(facet - o)| / d!, o the first facet's first vertex."""
    o = [Fraction(x) for x in pts[min(facets[0])]]
    total = Fraction(0)
    for f in facets:
        vs = sorted(f)
        m = [[Fraction(pts[v][j]) - o[j] for j in range(d)] for v in vs]
        total += abs(det(m))  # cone over a facet: each |det|, as o is a hull vertex
    return total / factorial(d)


# ---- general position: agreement with Qhull ------------------------------------------
def general(lh, spec, prog, qopts):
    text = rbox(spec)
    name = "%s %s" % (spec, prog)
    # FS: totals
    _, a, _ = run([lh, prog, "FS"], text)
    _, b, _ = run([prog] + qopts + ["FS"], text)
    la, qa = a.split("\n"), b.split("\n")
    check(name + " FS header", la[0] == qa[0] == "0", a + b)
    lv, qv = [float(x) for x in la[1].split()[1:]], [float(x) for x in qa[1].split()[1:]]
    check(name + " FS values", len(lv) == len(qv) == 2 and all(close(x, y) for x, y in zip(lv, qv)),
          "%s vs %s" % (lv, qv))
    # Fa: per facet, matched by vertex sets
    _, li, _ = run([lh, prog, "i"], text)
    _, lfa, _ = run([lh, prog, "Fa"], text)
    _, qi, _ = run([prog] + qopts + ["i"], text)
    _, qfa, _ = run([prog] + qopts + ["Fa"], text)
    lm = dict(zip(facets_i(li), reals(lfa)))
    qm = dict(zip(facets_i(qi), reals(qfa)))
    check(name + " Fa facets", set(lm) == set(qm), "%d vs %d facets" % (len(lm), len(qm)))
    bad = [k for k in lm if k in qm and not close(lm[k], qm[k], 1e-10)]
    check(name + " Fa values", not bad, "%d differ, e.g. %s" % (len(bad), bad[:1]))
    # Fs: the first eight integers equal (the ninth, vertices Qhull deleted while it
    # built the hull, is 0 here); the reals: lifthull exact 0, Qhull's roundoff
    _, a, _ = run([lh, prog, "Fs"], text)
    _, b, _ = run([prog] + qopts + ["Fs"], text)
    la, qa = a.split("\n"), b.split("\n")
    check(name + " Fs integers", la[0].split()[:9] == qa[0].split()[:9] and la[0].split()[9:] == ["0", "0"],
          "%r vs %r" % (la[0], qa[0]))
    check(name + " Fs reals", la[1] == "2      0      0"
          and all(abs(float(x)) < 1e-12 for x in qa[1].split()[1:]), "%r vs %r" % (la[1], qa[1]))
    # FA: the summary's total lines, Qhull's "%2.8g" strings
    _, a, _ = run([lh, prog, "FA"], text)
    _, b, _ = run([prog] + qopts + ["FA"], text)
    pick = lambda s: [l for l in s.split("\n") if l.startswith("  Total ")]
    check(name + " FA summary", pick(a) == pick(b) and pick(a), "%s vs %s" % (pick(a), pick(b)))


def voronoi_fs(lh, spec):
    text = rbox(spec)
    _, a, _ = run([lh, "qvoronoi", "Fs"], text)
    _, b, _ = run(["qvoronoi", "Fs"], text)
    check(spec + " qvoronoi Fs integers", a.split("\n")[0] == b.split("\n")[0], a + b)


# ---- the summary's stream -------------------------------------------------------------
def summary_streams(lh):
    text = rbox("20 D2 t3")
    for prog in ("qconvex", "qdelaunay", "qvoronoi"):
        for opts in (["s"], ["s", "i"], [], ["i", "s"]):
            lr = run([lh, prog] + opts, text)
            qr = run([prog] + opts, text)
            where = lambda r: ("Number of" in r[1], "Number of" in r[2])
            check("%s %s: summary stream" % (prog, " ".join(opts) or "(none)"),
                  where(lr) == where(qr), "lifthull %s, qhull %s" % (where(lr), where(qr)))


# ---- degenerate: exact where Qhull is not ---------------------------------------------
def degenerate(lh):
    # the cube's corners, points on its faces and inside, translated by 2^30: exactly area 6,
    # volume 1 (Qhull: merged facets, roundoff in its planes)
    pts = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    pts += [(0.5, 0.5, 0), (0.25, 0, 0.75), (1, 0.5, 0.5), (0.5, 0.5, 0.5)]
    off = 2.0 ** 30
    text = "3\n%d\n" % len(pts) + "".join("%r %r %r\n" % (x + off, y + off, z + off) for x, y, z in pts)
    _, a, _ = run([lh, "qconvex", "FS"], text)
    check("cube + 2^30 qconvex FS exact", a == "0\n2      6      1 \n", repr(a))
    _, b, _ = run(["qconvex", "FS"], text)
    print("note: cube + 2^30: lifthull %r, qconvex %r" % (a.split("\n")[1], b.split("\n")[1]))
    _, a, _ = run([lh, "qdelaunay", "FS"], text)
    check("cube + 2^30 qdelaunay FS exact", a == "0\n2      1      0 \n", repr(a))
    # thin tetrahedra far from the origin (rbox's lens points pushed by 1e6): the volume
    # against the exact volume of lifthull's own hull facets, and the Delaunay total
    for spec in ("30 D3 W1e-9 t5 O1e6", "40 D3 s Z1e-9 t2 O3e5", "25 D4 t8 O1e4", "30 D3 y t5 O1e7"):
        text = rbox(spec)
        d, p = points(text)
        _, fi, _ = run([lh, "qconvex", "i"], text)
        exact = exact_volume(p, facets_i(fi), d)
        _, a, _ = run([lh, "qconvex", "FS"], text)
        got = float(a.split("\n")[1].split()[2])
        err = abs(Fraction(got) - exact) / exact
        check(spec + " qconvex FS volume exact (<= 2^-51)", err <= Fraction(1, 2 ** 51), "rel err %g" % err)
        _, a, _ = run([lh, "qdelaunay", "FS"], text)
        got = float(a.split("\n")[1].split()[1])
        err2 = abs(Fraction(got) - exact) / exact
        check(spec + " qdelaunay FS total = hull volume", err2 <= Fraction(1, 2 ** 51), "rel err %g" % err2)
        r, b, _ = run(["qconvex", "FS"], text)
        if r == 0:
            q = float(b.split("\n")[1].split()[2])
            print("note: %s: volume rel. error lifthull %.2g, qconvex %.2g"
                  % (spec, float(err), float(abs(Fraction(q) - exact) / exact)))


# ---- Fx: extreme points as a set (Qhull lists them in its facets' order) ----------------
def extreme(lh):
    sq = "2 6\n0 0\n2 0\n2 2\n0 2\n1 0\n1 1.1\n"  # site 4 on an edge, not a corner
    for text, name in ((rbox("40 D2 t11"), "40 D2"), (rbox("80 D3 t12"), "80 D3"),
                       (rbox("30 D4 t13"), "30 D4"), (sq, "square + edge site")):
        for prog in ("qdelaunay", "qvoronoi"):
            for qu in ([], ["Qu"]):
                _, a, _ = run([lh, prog, "Fx"] + qu, text)
                _, b, _ = run([prog, "Fx"] + qu, text)
                la, qa = a.split(), b.split()
                check("%s %s Fx %s" % (name, prog, " ".join(qu)),
                      la and la[0] == qa[0] and set(la[1:]) == set(qa[1:])
                      and la[1:] == sorted(la[1:], key=int), "%s vs %s" % (la, qa))


# ---- print filters: the printed facets as vertex sets, Fn's structure -------------------
def neighbours(i_out, fn_out):
    """facet -> (its printed neighbours as vertex sets, how many unprinted: negative ids)."""
    fs = facets_i(i_out)
    rows = fn_out.strip().split("\n")[1:]
    out = {}
    for f, row in zip(fs, rows):
        ids = [int(x) for x in row.split()[1:]]
        out[f] = (frozenset(fs[j] for j in ids if j >= 0), sum(1 for j in ids if j < 0))
    return out


def filters(lh):
    for spec, prog, qopts, opts in (
            ("40 D2 t21", "qconvex", [], ["Pd0", "PD0:0.5", "Pd0d1", "PD1:-0.2d0:0.3", "PA3", "PA3 PG",
                                          "Pg", "PG", "PA4 Pg"]),
            ("80 D3 t22", "qconvex", [], ["Pd2", "PD0:-0.3", "Pd0:0.1D1:0.4", "PA5", "PA5 PG"]),
            ("50 D4 t23", "qconvex", [], ["Pd3:0.2", "PA7 PG"]),
            ("40 D2 t24", "qdelaunay", ["Qt"], ["Pd0", "PD2:-0.9", "PA5", "PA5 PG", "Pd1:0.1"]),
            ("60 D3 t25", "qdelaunay", ["Qt"], ["Pd2", "PD3:-0.95", "PA6 PG"])):
        text = rbox(spec)
        for opt in opts:
            o = opt.split()
            name = "%s %s %s" % (spec, prog, opt)
            _, li, _ = run([lh, prog] + o + ["i"], text)
            _, qi, _ = run([prog] + qopts + o + ["i"], text)
            qset = set(facets_i(qi))
            if prog == "qdelaunay" and "PG" in o:
                # Qhull's PG also prints the upper-Delaunay facets beside the good ones;
                # lifthull prints Delaunay simplices only (docs/lifthull.1)
                _, full, _ = run([prog] + qopts + ["i"], text)
                upper = qset - set(facets_i(full))
                qset -= upper
                if upper:
                    check(name + " i (lower facets)", set(facets_i(li)) == qset)
                    continue
            check(name + " i", set(facets_i(li)) == qset and len(facets_i(li)) == int(li.split()[0]),
                  "%d vs %d facets" % (len(facets_i(li)), len(qset)))
            _, lfn, _ = run([lh, prog] + o + ["Fn"], text)
            _, qfn, _ = run([prog] + qopts + o + ["Fn"], text)
            check(name + " Fn", neighbours(li, lfn) == neighbours(qi, qfn))
            _, lfa, _ = run([lh, prog] + o + ["Fa"], text)
            _, qfa, _ = run([prog] + qopts + o + ["Fa"], text)
            lm, qm = dict(zip(facets_i(li), reals(lfa))), dict(zip(facets_i(qi), reals(qfa)))
            check(name + " Fa", set(lm) == set(qm) and all(close(lm[k], qm[k], 1e-10) for k in lm))
    # degenerate: the unit cube shifted by 2^30 (site i has x = i & 1): the face x = 1 is
    # exactly the facets with normal[0] >= 1, two triangles (Qhull: one merged square)
    off = 2.0 ** 30
    text = "3 8\n" + "".join("%r %r %r\n" % ((i & 1) + off, (i >> 1 & 1) + off, (i >> 2 & 1) + off)
                             for i in range(8))
    _, li, _ = run([lh, "qconvex", "Pd0:1", "i"], text)
    check("cube + 2^30 Pd0:1", sorted(map(sorted, facets_i(li))) == [[1, 3, 5], [3, 5, 7]]
          or sorted(map(sorted, facets_i(li))) == [[1, 3, 7], [1, 5, 7]], li)
    _, qi, _ = run(["qconvex", "Pd0:1", "i"], text)
    print("note: cube + 2^30 Pd0:1: lifthull %s facets, qconvex %s" % (li.split()[0], qi.split()[0]))
    # qvoronoi's Pdk, PG, QGn: tests/cli/qvoronoi_extras.py
    for bad in ("Pd", "PD0:x", "PA0", "PAx", "Pdd1"):
        r, _, e = run([lh, "qconvex", bad, "i"], rbox("10 D2 t1"))
        check("qconvex %s refused" % bad, r == 2 and "option '%s': expected" % bad in e, e)
    r, _, e = run([lh, "qconvex", "Pd3", "i"], rbox("10 D2 t1"))
    check("qconvex Pd3 in 2-d refused", r == 2 and "coordinates 0..1" in e, e)
    # QGn QVn: tests/cli/qhull_good.py (qconvex, qdelaunay), qvoronoi_extras.py (qvoronoi)


# ---- FI Fm FQ FO FD Fc FP m FM ----------------------------------------------------------
def same_rows(a, b, tol=1e-12):
    """Rows of numbers equal as multisets within tol (greedy match after sorting)."""
    if len(a) != len(b):
        return False
    left = sorted(b)
    for r in sorted(a):
        j = next((j for j, q in enumerate(left) if all(abs(x - y) <= tol for x, y in zip(r, q))), None)
        if j is None:
            return False
        left.pop(j)
    return True


def polygons(out):
    """m / FM output as polygons: tuples of points (rounded text -> floats)."""
    body = out.replace("-0.00000000", "0.00000000")
    polys = []
    for chunk in re.split(r"Line|Polygon|\]\],?\s*\n?,?\[\[", body):
        nums = [float(x) for x in re.findall(r"-?\d+\.\d+", chunk)]
        if nums:
            polys.append(nums)
    return polys


def canon_cycle(pts):
    """A polygon up to rotation of its vertex cycle (orientation kept)."""
    rots = [tuple(pts[i:] + pts[:i]) for i in range(len(pts))]
    return min(rots)


def pictures(lh, text, prog, opt, dim):
    _, a, _ = run([lh, prog, opt], text)
    _, b, _ = run([prog, opt], text)
    def shape(out):
        res = []
        for nums in polygons(out):
            pts = [tuple(nums[i:i + dim]) for i in range(0, len(nums), dim)]
            res.append(canon_cycle(pts) if len(pts) > 2 else tuple(sorted(pts)))
        return sorted(res)
    return shape(a), shape(b), a, b


def extras(lh):
    for spec, prog, qopts in (("30 D2 t31", "qconvex", []), ("60 D3 t32", "qconvex", []),
                              ("40 D4 t33", "qconvex", []), ("30 D2 t34", "qdelaunay", ["Qt"])):
        text = rbox(spec)
        name = "%s %s" % (spec, prog)
        _, a, _ = run([lh, prog, "FI"], text)
        _, b, _ = run([prog] + qopts + ["FI"], text)
        ids = a.split()[1:]
        check(name + " FI", a.split()[0] == b.split()[0] and len(set(ids)) == len(ids) == int(a.split()[0]))
        _, a, _ = run([lh, prog, "Fm"], text)
        _, b, _ = run([prog] + qopts + ["Fm"], text)
        check(name + " Fm", a == b, a[:60] + " / " + b[:60])
        _, a, _ = run([lh, prog, "FQ", "i"], text)
        check(name + " FQ", a.split("\n")[0] == "lifthull %s FQ i" % prog, a[:60])
        r, a, e = run([lh, prog, "FO", "i"], text)
        check(name + " FO", "Options selected for lifthull %s FO i" % prog in e and a.split()[0] == b.split()[0], e)
        _, a, _ = run([lh, prog, "FD", "p"], text)
        _, b, _ = run([prog] + qopts + ["FD", "p"], text)
        (ha, ra), (hb, rb) = cdd_rows(a), cdd_rows(b)
        check(name + " FD p", ha == hb and same_rows(ra, rb, 1e-9), "%s %s" % (ha, hb))
        if prog == "qconvex":
            for o in ("n", "Fo", "Fi"):
                _, a, _ = run([lh, prog, "FD", o], text)
                _, b, _ = run([prog, "FD", o], text)
                (ha, ra), (hb, rb) = cdd_rows(a), cdd_rows(b)
                check(name + " FD " + o, ha == hb and same_rows(ra, rb, 1e-9), "%s %s" % (ha, hb))
        d = int(spec.split()[1][1:])
        if (prog == "qconvex" and d <= 3) or (prog == "qdelaunay" and d == 2):
            for o in ("m", "FM"):
                la, qa, ta, tb = pictures(lh, text, prog, o, d + (prog == "qdelaunay"))
                check(name + " " + o, la == qa and len(la) > 0, "%d vs %d polygons" % (len(la), len(qa)))
                check(name + " " + o + " frame", ta.split("\n")[0] == tb.split("\n")[0]
                      and ta.rstrip().split("\n")[-1][-4:] == tb.rstrip().split("\n")[-1][-4:], ta[-30:] + tb[-30:])
        else:
            r, _, e = run([lh, prog, "m"], text)
            check(name + " m refused", r == 2 and "Mathematica, Maple and Geomview output are for" in e, e)
    # coplanar points: the cube with sites on its faces (Qhull: merged square facets)
    cube = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    extra = [(0.1, 0.2, 0), (0.7, 1, 0.4), (1, 0.3, 0.9), (0.5, 0.5, 0.5)]
    text = "3 %d\n" % (len(cube) + len(extra)) + "".join("%r %r %r\n" % p for p in cube + extra)
    def fc_points(out):
        return sorted(int(x) for l in out.strip().split("\n")[1:] for x in l.split()[1:])
    # a site inside a face may be one of lifthull's hull vertices (lh_convex_hull): then
    # it is no coplanar point
    _, fx, _ = run([lh, "qconvex", "Fx"], text)
    verts = set(int(x) for x in fx.split()[1:])
    _, a, _ = run([lh, "qconvex", "Fc"], text)
    _, b, _ = run(["qconvex", "Fc"], text)
    check("cube Fc points", fc_points(a) == [p for p in fc_points(b) if p not in verts]
          and fc_points(b) == [8, 9, 10], a + b)
    def fp_rows(out):
        return sorted((int(l.split()[1]), int(l.split()[0]), round(float(l.split()[3]), 12))
                      for l in out.strip().split("\n")[1:])
    _, a, _ = run([lh, "qconvex", "FP"], text)
    _, b, _ = run(["qconvex", "FP"], text)
    check("cube FP", fp_rows(a) == [r for r in fp_rows(b) if r[0] not in verts], a + b)
    # qdelaunay: a duplicate site is the coplanar point of the site it repeats
    text = rbox("20 D2 t35")
    lines = text.split("\n")
    text = "2 21\n" + "\n".join(lines[2:22]) + "\n" + lines[5] + "\n"
    _, a, _ = run([lh, "qdelaunay", "Fc"], text)
    check("qdelaunay duplicate Fc", fc_points(a) == [20], a)
    _, a, _ = run([lh, "qdelaunay", "FP"], text)
    _, b, _ = run(["qdelaunay", "FP"], text)
    check("qdelaunay duplicate FP", fp_rows(a) == fp_rows(b) == [(20, 3, 0.0)], a + b)


def geom_facets(out):
    """G output: per facet (its vertex cycle, its colour), numbers as floats."""
    res = []
    for block in re.split(r"\{ OFF 3 1 1 # f\d+\n|VECT 1 2 1 2 1 # f\d+\n", out)[1:]:
        lines = [l for l in block.split("\n") if l.strip() and l.strip() != "}"]
        if lines[-1].startswith("3 0 1 2"):
            pts = [tuple(float(x) for x in l.split()) for l in lines[:-1]]
            col = tuple(float(x) for x in lines[-1].split()[4:7])
        else:
            pts = [tuple(float(x) for x in l.split()) for l in lines[:-1]]
            col = tuple(float(x) for x in lines[-1].split()[:3])
        res.append((pts, col))
    return res


def same_geom(a, b, tol=2e-3):
    def near(p, q):
        return all(abs(x - y) <= tol for x, y in zip(p, q))
    def cyc_eq(p, q):
        return len(p) == len(q) and any(all(near(p[(i + k) % len(p)], q[k]) for k in range(len(q)))
                                        for i in range(len(p)))
    left = list(b)
    for pts, col in a:
        j = next((j for j, (q, c) in enumerate(left)
                  if (cyc_eq(pts, q) or (len(pts) == 2 and cyc_eq(pts[::-1], q))) and near(col, c)), None)
        if j is None:
            return False
        left.pop(j)
    return not left


def geomview(lh):
    for spec, prog in (("30 D2 t51", "qconvex"), ("60 D3 t52", "qconvex"), ("40 D2 t53", "qdelaunay")):
        text = rbox(spec)
        _, a, _ = run([lh, prog, "G"], text)
        _, b, _ = run([prog] + (["Qt"] if prog == "qdelaunay" else []) + ["G"], text)
        check("%s %s G" % (spec, prog), same_geom(geom_facets(a), geom_facets(b)) and len(geom_facets(a)) > 0,
              "%d vs %d facets" % (len(geom_facets(a)), len(geom_facets(b))))
        check("%s %s G frame" % (spec, prog), a.split(" LIST")[0] == b.split(" LIST")[0] and a.endswith("}\n}\n" if "D3" in spec or prog == "qdelaunay" else "1.0\n}\n"),
              a[:60] + " / " + b[:60])
    r, _, e = run([lh, "qconvex", "G"], rbox("10 D5 t1"))  # 4-d: tests/cli/qhull_geomview.py
    check("qconvex G in 5-d refused", r == 2 and "only available for 2-d, 3-d and 4-d" in e, e)
    r, _, e = run([lh, "qconvex", "Gp"], rbox("10 D3 t1"))
    check("qconvex Gp refused", r == 2 and "option 'Gp': 'p' is not supported" in e, e)


def fields(out):
    """f output: vertices {p: coords}, facets {vertex set: (normal, offset, neighbour ids)}
    and facet id -> vertex set."""
    verts, facets, ids, cur = {}, {}, {}, None
    for l in out.split("\n"):
        m = re.match(r"- p(\d+)\(v\d+\):(.*)", l)
        if m:
            verts[int(m.group(1))] = tuple(float(x) for x in m.group(2).split())
        elif re.match(r"- f\d+$", l):
            cur = {"id": l[2:]}
        elif cur is not None and "- normal:" in l:
            cur["normal"] = tuple(float(x) for x in l.split(":")[1].split())
        elif cur is not None and "- offset:" in l:
            cur["offset"] = float(l.split(":")[1])
        elif cur is not None and "- vertices:" in l:
            cur["vertices"] = frozenset(int(x) for x in re.findall(r"p(\d+)\(", l))
        elif cur is not None and "- neighboring facets:" in l:
            cur["nbrs"] = l.split(":")[1].split()
            facets[cur["vertices"]] = cur
            ids[cur["id"]] = cur["vertices"]
    return verts, facets, ids


def nbr_sets(ids, facet):
    """A facet's neighbours as sorted vertex tuples; () for an unprinted (upper) one."""
    return sorted(tuple(sorted(ids.get(x, ()))) for x in facet["nbrs"])


def all_fields(lh):
    for spec, prog, qopts in (("20 D2 t71", "qconvex", []), ("30 D3 t72", "qconvex", []),
                              ("20 D4 t73", "qconvex", []), ("25 D2 t74", "qdelaunay", ["Qt"])):
        text = rbox(spec)
        for opt in ("f", "FF"):
            _, a, _ = run([lh, prog, opt], text)
            _, b, _ = run([prog] + qopts + [opt], text)
            (va, fa, ia), (vb, fb, ib) = fields(a), fields(b)
            name = "%s %s %s" % (spec, prog, opt)
            check(name + " vertices", va == vb, "%s / %s" % (sorted(va)[:4], sorted(vb)[:4]))
            check(name + " facets", set(fa) == set(fb), "%d vs %d" % (len(fa), len(fb)))
            bad = [k for k in fa if k in fb and not (
                all(abs(x - y) <= 2e-4 for x, y in zip(fa[k]["normal"], fb[k]["normal"]))
                and abs(fa[k]["offset"] - fb[k]["offset"]) <= 1e-7 * max(1, abs(fb[k]["offset"]))
                and nbr_sets(ia, fa[k]) == nbr_sets(ib, fb[k]))]
            check(name + " normals, offsets, neighbours", not bad, str(bad[:1]))


def fields_refused(lh):
    r, a, e = run([lh, "qdelaunay", "f"], rbox("12 D8 t1"))
    check("qdelaunay f in 8-d refused", r == 2 and a == "" and "at most 7-d input" in e, e)


def trace(lh):
    text = rbox("200 D3 t41")
    for prog in ("qdelaunay", "qconvex", "qvoronoi"):
        _, plain, _ = run([lh, prog, "i" if prog != "qvoronoi" else "o"], text)
        r, a, e = run([lh, prog, "Ts", "i" if prog != "qvoronoi" else "o"], text)
        check(prog + " Ts", r == 0 and a == plain and "lifthull statistics: lifthull %s Ts" % prog in e
              and re.search(r"^ +200 input sites in 3-d$", e, re.M), e[:200])
    r, a, e = run([lh, "qdelaunay", "Tc", "i"], text)
    check("qdelaunay Tc", r == 0 and "the exact check passed" in e and "option 'Tc'" in e, e)
    r, _, e = run([lh, "qdelaunay", "Ts", "i"], text)
    calls = re.search(r"^ +(\d+) predicate calls$", e, re.M)
    check("qdelaunay Ts counts predicate calls", calls and int(calls.group(1)) > 200, e[-400:])


def refusals(lh):
    r, _, e = run([lh, "qvoronoi", "FA"], "2 3\n0 0\n1 0\n0 1\n")
    check("qvoronoi FA refused", r == 2 and "option 'FA' is not supported" in e, e)
    r, _, e = run([lh, "qvoronoi", "Fa"], "2 3\n0 0\n1 0\n0 1\n")
    check("qvoronoi Fa refused", r == 2 and "option 'Fa' is not supported" in e, e)


def guard(name, fn, *args):
    """Runs one group of checks; an output too malformed to parse is one failure."""
    try:
        fn(*args)
    except (ValueError, IndexError, ZeroDivisionError) as e:
        check(name + " (output parses)", False, repr(e))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("lifthull")
    ap.add_argument("-v", action="store_true")
    a = ap.parse_args()
    VERBOSE[0] = a.v
    if not all(shutil.which(p) for p in ("rbox", "qconvex", "qdelaunay", "qvoronoi")):
        print("SKIP: Qhull's programs (qhull-bin) not found")
        return 77
    lh = a.lifthull
    for spec in ("50 D2 t1", "200 D3 t2", "60 D4 t3", "300 s D3 t4", "40 D5 t9"):
        guard(spec, general, lh, spec, "qconvex", [])
    for spec in ("50 D2 t5", "200 D3 t6", "60 D4 t7"):
        guard(spec, general, lh, spec, "qdelaunay", ["Qt"])
    for spec in ("50 D2 t5", "100 D3 t6"):
        guard(spec, voronoi_fs, lh, spec)
    guard("summary", summary_streams, lh)
    guard("degenerate", degenerate, lh)
    guard("Fx", extreme, lh)
    guard("filters", filters, lh)
    guard("extras", extras, lh)
    guard("trace", trace, lh)
    guard("geomview", geomview, lh)
    guard("f", all_fields, lh)
    guard("f in 8-d", fields_refused, lh)
    guard("refusals", refusals, lh)
    print("%d passed, %d failed" % (PASSES[0], len(FAILS)))
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
