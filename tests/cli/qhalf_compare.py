#!/usr/bin/env python3
"""`lifthull qhalf` against Qhull 2020.2's qhalf (qhull-bin), issue 30 item 15:

  qhalf_compare.py LIFTHULL [-v]

Every output qhalf prints (s i o p Fp Fx Fv Fn FN FI Fm Fc FP Fs FQ G m FM f FF, and Tv,
Ts, Fd) on the same halfspaces. Intersection points are matched between the programs by
their halfspaces (the 'i' line of each), never by their order; the dual hull's outputs
(o G m FM f FF: every facet a simplex) against qhalf Qt. Then the hostile inputs of the
reader and the interior point. Exit 0 when every check passed, 1 otherwise, 77 when
Qhull's programs are missing.
"""

import argparse
import os
import resource
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import qhull_formats as qf  # noqa: E402  (check, run, rbox, points, same_rows, ...)

check, run, rbox, points, same_rows = qf.check, qf.run, qf.rbox, qf.points, qf.same_rows


def tangent(spec, push=0):
    """Planes tangent to rbox's sphere of radius 0.5 at its points p: p.x - 0.25 <= 0, in
    general position (planes a hull's facets span, as qconvex n writes them, meet only up to
    rounding: lifthull then finds every exact vertex, Qhull merges); `push` of them again,
    moved inwards (redundant)."""
    d, pts = points(rbox(spec))
    rows = [" ".join(repr(x) for x in p) + " " + repr(-0.25) for p in pts]
    rows += [" ".join(repr(x) for x in p) + " " + repr(-0.25 - 0.1) for p in pts[:push]]
    return "%d\n%d\n" % (d + 1, len(rows)) + "\n".join(rows) + "\n"


def body(out):
    lines = out.strip().split("\n")
    return lines[1:1 + int(lines[0].split()[0])]


def keys(i_out):
    """Point id -> its halfspaces (the 'i' output)."""
    return [frozenset(int(x) for x in l.split()) for l in body(i_out)]


def basics(lh):
    """The checks of Fp, i, Fv, Fx and the refusals (from qhull_formats.py)."""
    def sets(out, skip_count=False):
        rows = out.strip().split("\n")[1:]
        return sorted(tuple(sorted(int(x) for x in (r.split()[1:] if skip_count else r.split()))) for r in rows)
    def points_of(out):
        return [tuple(float(x) for x in l.split()) for l in out.strip().split("\n")[2:]]
    cases = []
    for spec in ("40 s D3 t61", "30 s D2 t62", "25 s D4 t63"):
        cases.append((spec + " tangent planes", tangent(spec), ["H0"]))
    n = tangent("30 s D3 t64", 10)  # ten redundant halfspaces, parallel to ten others
    cases.append(("redundant", n, ["H0"]))
    cases.append(("interior point H0.01,0.02,-0.03", n, ["H0.01,0.02,-0.03"]))
    cases.append(("interior point in the input", "3 1\n0.01 0.02 -0.03\n" + n, []))
    _, octa, _ = run(["qconvex", "n"], rbox("d D3"))
    cases.append(("octahedron (4 planes a vertex)", octa, ["H0"]))
    for name, text, h in cases:
        _, a, _ = run([lh, "qhalf"] + h + ["Fp"], text)
        _, b, _ = run(["qhalf"] + h + ["Fp"], text)
        check("qhalf %s Fp" % name, a.split()[:2] == b.split()[:2] and same_rows(points_of(a), points_of(b), 1e-9),
              a[:100] + " / " + b[:100])
        _, a, _ = run([lh, "qhalf"] + h + ["i"], text)
        _, b, _ = run(["qhalf"] + h + ["i"], text)
        check("qhalf %s i" % name, sets(a) == sets(b), a[:100] + " / " + b[:100])
        _, a, _ = run([lh, "qhalf"] + h + ["Fv"], text)
        _, b, _ = run(["qhalf"] + h + ["Fv"], text)
        check("qhalf %s Fv" % name, sets(a, True) == sets(b, True))
        _, a, _ = run([lh, "qhalf"] + h + ["Fx"], text)
        _, b, _ = run(["qhalf"] + h + ["Fx"], text)
        check("qhalf %s Fx" % name, sorted(a.split()) == sorted(b.split()), a + " / " + b)
    # the i and Fp lines belong together: each point is tight on its halfspaces
    text = cases[0][1]
    _, a, _ = run([lh, "qhalf", "H0", "i", "Fp"], text)
    lines = a.strip().split("\n")
    m = int(lines[0])
    hs = [[float(x) for x in l.split()] for l in text.strip().split("\n")[2:]]
    pts = [[float(x) for x in l.split()] for l in lines[m + 3:]]
    tight = all(abs(sum(c * x for c, x in zip(hs[k][:-1], p)) + hs[k][-1]) < 1e-12
                for l, p in zip(lines[1:m + 1], pts) for k in map(int, l.split()))
    check("qhalf i and Fp: each point on its halfspaces", tight and len(pts) == m)
    # exact where the vertices are simple ratios of the coefficients: the square cut by
    # x + y <= 1.5 has vertices (1, 0.5) and (0.5, 1) exactly (qhalf: 0.5000000000000001)
    sq = "3\n5\n1 0 -1\n-1 0 -1\n0 1 -1\n0 -1 -1\n1 1 -1.5\n"
    want = sorted([(1.0, -1.0), (-1.0, 1.0), (0.5, 1.0), (-1.0, -1.0), (1.0, 0.5)])
    for h in (["H0"], ["H0.1,0.2"], ["H-0.3,0.7"]):
        _, a, _ = run([lh, "qhalf"] + h + ["Fp"], sq)
        check("qhalf square cut %s Fp exact" % h[0], sorted(points_of(a)) == want, a)
        _, b, _ = run(["qhalf"] + h + ["Fp"], sq)
        print("note: square cut %s: qhalf %s" % (h[0], sorted(points_of(b))))
    r, a, e = run([lh, "qhalf", "H0", "Qt", "QJ", "Fp"], sq)
    check("qhalf Qt QJ accepted", r == 0 and sorted(points_of(a)) == want and "'QJ' ignored" in e, e)
    _, a, _ = run([lh, "qhalf", "Fp"], sq)
    check("qhalf square cut, the origin by default", sorted(points_of(a)) == want, a)
    shifted = "3\n3\n1 0 -1\n-1 0 2\n0 1 -1\n"  # x >= 2: the origin is outside
    for h, text, msg in ((["Fp"], shifted, "an interior point is needed: the origin is not"),
                         (["H5", "Fp"], n, "(option H) is outside halfspace"),
                         (["H0", "Fp"], "3\n2\n1 0 -1\n-1 0 -1\n", "unbounded"),
                         (["H0", "Fp"], "3\n3\n1 0 -1\n-1 0 -1\n0 1 -1\n", "unbounded"),
                         (["H0,x"], n, "expected Hn,n"),
                         (["H0", "Fp"], "4\n2\n1 0 0 x\n", "expected a coefficient"),
                         (["H0", "Qu"], n, "option 'Qu' is not supported"),
                         (["H0", "TA3"], n, "option 'TA3' is not supported"),
                         (["H0"], "1e300 5\n", "<stdin>:1: expected halfspaces of 3..9 coefficients"),
                         (["Fp"], "2 1\n0 0\n3 2\n1 0 -1\n-1 0 -1\n7\n", "<stdin>:6: more than the 2"),
                         (["Fp"], "2 1\n0 0\n4 2\n", "<stdin>:3: the interior point has 2 coordinates")):
        r, _, e = run([lh, "qhalf"] + h, text)
        check("qhalf %s refused (%s)" % (" ".join(h), msg), r != 0 and msg in e, e)


def octahedron():
    """The octahedron's 8 planes (4 at each vertex: each intersection point merges two
    dual triangles), a redundant plane, one through a vertex (coplanar) and one more."""
    _, octa, _ = run(["qconvex", "n"], rbox("d D3"))
    rows = [l for l in octa.strip().split("\n")[2:]] + ["1 1 1 -5", "0 0 1 -0.5", "1 1 1 -1"]
    return "4\n%d\n" % len(rows) + "\n".join(rows) + "\n"


def outputs(lh):
    cases = [("3-d tangent planes", tangent("40 s D3 t61"), ["H0"]),
             ("2-d tangent planes", tangent("30 s D2 t62"), ["H0"]),
             ("4-d tangent planes", tangent("25 s D4 t63"), ["H0"]),
             ("3-d redundant", tangent("30 s D3 t64", 10), ["H0.01,0.02,-0.03"]),
             ("octahedron", octahedron(), ["H0"]),
             ("cube, FQ comment and FV point", run(["qconvex", "FQ", "FV", "n"], rbox("c"))[1], [])]
    for name, text, h in cases:
        def both(opts):
            r1, a, e1 = run([lh, "qhalf"] + h + opts, text)
            r2, b, e2 = run(["qhalf"] + h + opts, text)
            check("qhalf %s %s runs" % (name, " ".join(opts)), r1 == 0 and r2 == 0, e1 + e2)
            return a, b
        ia, ib = both(["i"])
        ka, kb = keys(ia), keys(ib)
        check("qhalf %s i" % name, sorted(map(sorted, ka)) == sorted(map(sorted, kb)))
        indexed_outputs(both, name, ka, kb)
        summary_outputs(both, name, h)
        general = name != "octahedron"  # the squares' diagonals are Qhull's choice
        dual_hull_outputs(lh, name, text, h, general)
        d = int(ia and run([lh, "qhalf"] + h + ["Fp"], text)[1].split()[0])
        if d == 3 and general:
            geomview_outputs(lh, name, text, h)
        if general and d <= 4:
            facet_list_outputs(lh, name, text, h)
        r, a, e = run([lh, "qhalf"] + h + ["Tv", "Fp"], text)
        check("qhalf %s Tv" % name, r == 0 and "Tv: the exact check passed" in e and a.startswith("%d\n" % d), e)
        r, a, e = run([lh, "qhalf"] + h + ["Ts", "FI"], text)
        check("qhalf %s Ts" % name, r == 0 and "%10d intersection points\n" % len(ka) in e, e)


def indexed_outputs(both, name, ka, kb):
    """p, Fn, FN, FI, Fm, Fc, FP against Qhull's, the intersection points matched by their
    halfspaces (ka, kb: each side's `i` keys)."""
    a, b = both(["p"])
    check("qhalf %s p" % name, a.split()[:2] == b.split()[:2] and same_rows(
        [tuple(map(float, l.split())) for l in a.strip().split("\n")[2:]],
        [tuple(map(float, l.split())) for l in b.strip().split("\n")[2:]], 1e-9), a[:80] + " / " + b[:80])
    a, b = both(["Fn"])
    na = {ka[g]: frozenset(ka[int(x)] for x in l.split()[1:]) for g, l in enumerate(body(a))}
    nb = {kb[g]: frozenset(kb[int(x)] for x in l.split()[1:]) for g, l in enumerate(body(b))}
    check("qhalf %s Fn" % name, na == nb and len(na) == len(ka))
    a, b = both(["FN"])
    fa = [frozenset(ka[int(x)] for x in l.split()[1:]) for l in body(a)]
    fb = [frozenset(kb[int(x)] for x in l.split()[1:]) for l in body(b)]
    check("qhalf %s FN" % name, fa == fb and a.split()[0] == b.split()[0], a[:80] + " / " + b[:80])
    a, b = both(["FI"])
    check("qhalf %s FI" % name, a.split()[0] == b.split()[0] and a.split()[1:] == [str(g) for g in range(len(ka))])
    a, b = both(["Fm"])
    ma = {ka[g]: l for g, l in enumerate(body(a))}
    mb = {kb[g]: l for g, l in enumerate(body(b))}
    check("qhalf %s Fm" % name, ma == mb, a[:60] + " / " + b[:60])
    a, b = both(["Fc"])
    ca = {int(x) for l in body(a) for x in l.split()[1:]}
    cb = {int(x) for l in body(b) for x in l.split()[1:]}
    check("qhalf %s Fc" % name, ca == cb and a.split()[0] == b.split()[0], a + " / " + b)
    a, b = both(["FP"])
    pa = sorted((int(l.split()[1]), round(float(l.split()[3]), 9)) for l in body(a))
    pb = sorted((int(l.split()[1]), round(float(l.split()[3]), 9)) for l in body(b))
    check("qhalf %s FP" % name, pa == pb, a + " / " + b)


def summary_outputs(both, name, h):
    """Fs and FQ against Qhull's."""
    a, b = both(["Fs", "Fc"])
    # all but Qhull's count of vertices it deleted while building (none here)
    fs = lambda out: out.split("\n")[0].split()[:9] + out.split("\n")[0].split()[10:]
    check("qhalf %s Fs" % name, fs(a) == fs(b) and a.split("\n")[0].split()[9] == "0", a[:60] + " / " + b[:60])
    a, b = both(["FQ"])
    # Qhull: the input's comment line, " | ", the command
    check("qhalf %s FQ" % name, a.strip().replace("lifthull qhalf", "qhalf") == b.strip().lstrip(" |") and
          a.strip().endswith("lifthull qhalf %s" % " ".join(h + ["FQ"])), a + b)


def dual_hull_outputs(lh, name, text, h, general):
    """o: the dual hull, every facet a simplex: against qhalf Qt (the faces only where
    Qhull's triangulation is unique: general)."""
    r, a, _ = run([lh, "qhalf"] + h + ["o"], text)
    _, b, _ = run(["qhalf", "Qt"] + h + ["o"], text)
    la, lb = a.strip().split("\n"), b.strip().split("\n")
    n = int(la[1].split()[0])
    pts = lambda ls: [tuple(map(float, l.split())) for l in ls[2:2 + n]]
    faces = lambda ls: sorted(tuple(sorted(map(int, l.split()[1:]))) for l in ls[2 + n:])
    check("qhalf %s o" % name, la[:2] == lb[:2] and same_rows(pts(la), pts(lb), 1e-9) and
          (not general or faces(la) == faces(lb)), a[:80] + " / " + b[:80])


def geomview_outputs(lh, name, text, h):
    """3-d: G, m and FM against qhalf Qt, as facet sets and polygons."""
    r, a, _ = run([lh, "qhalf"] + h + ["G"], text)
    _, b, _ = run(["qhalf", "Qt"] + h + ["G"], text)
    check("qhalf %s G" % name, r == 0 and qf.same_geom(qf.geom_facets(a), qf.geom_facets(b)) and
          len(qf.geom_facets(a)) > 0, a[:80] + " / " + b[:80])
    for opt in ("m", "FM"):
        r, a, _ = run([lh, "qhalf"] + h + [opt], text)
        _, b, _ = run(["qhalf", "Qt"] + h + [opt], text)
        def shape(out):
            res = []
            for nums in qf.polygons(out):
                res.append(qf.canon_cycle([tuple(nums[i:i + 3]) for i in range(0, len(nums), 3)]))
            return sorted(res)
        check("qhalf %s %s" % (name, opt), r == 0 and shape(a) == shape(b) and shape(a), a[:80] + " / " + b[:80])


def facet_list_outputs(lh, name, text, h):
    """f and FF (up to 4-d) against qhalf Qt: the vertices and the facet fields."""
    for opt in ("f", "FF"):
        r, a, _ = run([lh, "qhalf"] + h + [opt], text)
        _, b, _ = run(["qhalf", "Qt"] + h + [opt], text)
        (va, fa_, _), (vb, fb_, _) = qf.fields(a), qf.fields(b)
        check("qhalf %s %s" % (name, opt), r == 0 and va == vb and set(fa_) == set(fb_) and fa_,
              "%d vs %d facets" % (len(fa_), len(fb_)))


def cdd(lh):
    plain = tangent("30 s D3 t65").strip().split("\n")
    rows = [l.split() for l in plain[2:]]
    text = "tangent planes\nbegin\n %d 4 real\n" % len(rows) + "".join(
        "%s %s\n" % (repr(-float(r[-1])), " ".join(repr(-float(x)) for x in r[:-1])) for r in rows) + "end\n"
    r, a, e = run([lh, "qhalf", "H0", "Fd", "Fp"], text)
    _, b, _ = run(["qhalf", "H0", "Fd", "Fp"], text)
    rows = lambda out: [tuple(map(float, l.split())) for l in out.strip().split("\n")[2:]]
    check("qhalf Fd Fp (cdd input)", r == 0 and a.split()[:2] == b.split()[:2] and same_rows(rows(a), rows(b), 1e-9),
          e + a[:80] + " / " + b[:80])
    r, _, e = run([lh, "qhalf", "H0", "Fd", "Fp"], "begin\n 2 4 rational\n")
    check("qhalf Fd: rational refused", r == 3 and e == "<stdin>:2: expected cdd's number type 'real' or "
          "'integer', found 'rational'\n", e)
    r, _, e = run([lh, "qhalf", "H0", "Fd", "Fp"], "3\n1\n")
    check("qhalf Fd: no begin", r == 3 and "expected cdd's 'begin' line (option Fd)" in e, e)


def limited(mb):
    return lambda: resource.setrlimit(resource.RLIMIT_AS, (mb << 20, mb << 20))


def hostile(lh):
    # a count of 2^30 halfspaces in a 3-line file: memory follows the input, not the count
    p = subprocess.run([lh, "qhalf", "Fp"], input="3\n1073741824\n1 0 -1\n", capture_output=True, text=True,
                       preexec_fn=limited(1024))
    if "Sanitizer" in p.stderr:  # ASan reserves more address space than the limit: without it
        p = subprocess.run([lh, "qhalf", "Fp"], input="3\n1073741824\n1 0 -1\n", capture_output=True, text=True)
    check("qhalf 2^30 announced, one given", p.returncode == 3 and p.stderr ==
          "<stdin>:4: expected a coefficient, found the end of the input\n", p.stderr)
    sq = "3\n4\n1 0 -1\n-1 0 -1\n0 1 -1\n0 -1 -1\n"
    for h, want in (("H1", "<stdin>:3: the interior point (option H) is on the boundary of halfspace 0 "
                           "(a.c + b = 0 exactly): it must be strictly inside every halfspace\n"),
                    ("H0,-2", "<stdin>:6: the interior point (option H) is outside halfspace 3 "
                              "(a.c + b = 1): it must be strictly inside every halfspace\n")):
        r, a, e = run([lh, "qhalf", h, "Fp"], sq)
        check("qhalf %s: the point's place, exactly" % h, r == 3 and a == "" and e == want, e)
    # exactly outside by 1e-20, where a.c + b rounds to 0 in plain doubles
    r, _, e = run([lh, "qhalf", "H1,1", "Fp"], "3\n3\n1 1e-20 -1\n-1 0 -1\n0 -1 -1\n")
    check("qhalf outside by 1e-20", r == 3 and "is outside halfspace 0 (a.c + b = 9.9999999999999995e-21)" in e, e)
    r, _, e = run([lh, "qhalf", "Fp"], "2 1\n1 1\n3 3\n1 1e-20 -1\n-1 0 -1\n0 -1 -1\n")
    check("qhalf the input's point named", r == 3 and "<stdin>:4: the interior point (the input's first point)" in e, e)
    r, _, e = run([lh, "qhalf", "H0", "Fp"], "3\n4\n1 0 -1e-310\n-1 0 -1\n0 1 -1\n0 -1 -1\n")
    check("qhalf inside, too near for a finite dual", r == 3 and e ==
          "<stdin>:3: the interior point (option H) is strictly inside halfspace 0, but a.c + b = "
          "-9.9999999999999694e-311: too near its boundary, so its dual point a / -(a.c + b) is not a "
          "finite double; choose a point further inside\n", e)
    r, _, e = run([lh, "qhalf", "H-1e10", "Fp"], "3\n4\n1e300 0 -1\n-1 0 -1e308\n0 1 -1\n0 -1 -1\n")
    check("qhalf inside, too far for a finite a.c + b", r == 3 and e ==
          "<stdin>:3: the interior point (option H) is strictly inside halfspace 0, but |a.c + b| > "
          "DBL_MAX: too far from it, so its dual point a / -(a.c + b) is not a finite double; choose a "
          "point nearer to it\n", e)
    r, _, e = run([lh, "qhalf", "H1e10", "Fp"], "3\n4\n1e300 0 -1\n-1 0 -1e308\n0 1 -1\n0 -1 -1\n")
    check("qhalf outside beyond DBL_MAX", r == 3 and "is outside halfspace 0 (a.c + b > DBL_MAX)" in e, e)
    # vertices beyond DBL_MAX: finite text (long double), never inf
    r, a, e = run([lh, "qhalf", "H0", "Fp"], "3\n3\n1e-308 1 -1\n-1e-308 1 -1\n0 -1 -1\n")
    check("qhalf vertices beyond DBL_MAX printed finite", r == 0 and "inf" not in a and
          sorted(a.split()[2:]) == sorted(["2e+308", "-1", "-0", "1", "-2e+308", "-1"]), a + e)
    for what, text in (("empty", "3\n3\n1 0 -1\n-1 0 2\n0 1 -1\n"), ("flat", "3\n3\n1 0 -1\n-1 0 1\n0 1 -1\n"),
                       ("unbounded", "3\n2\n1 0 1\n0 1 1\n")):
        r, _, e = run([lh, "qhalf", "Fp"], text)
        check("qhalf no interior point (%s): the ways to give one" % what, r == 2 and e ==
              "lifthull qhalf: an interior point is needed: the origin is not strictly inside every "
              "halfspace and the linear program for their Chebyshev centre found no ball inside them "
              "(their intersection may be empty, flat or unbounded): prepend a point to the input (a "
              "line 'd 1', then its d coordinates) or give option Hn,n,...\n", e)


def centre(lh):
    """No interior point and the origin outside: the Chebyshev centre, then as qhalf with it."""
    box = "3\n4\n1 0 -3\n-1 0 2\n0 1 -1\n0 -1 -5\n"  # [2,3] x [-5,1]: radius 0.5, x = 2.5
    r, a, e = run([lh, "qhalf", "Fp"], box)
    check("qhalf Chebyshev centre of a box", r == 0 and e.startswith(
        "lifthull qhalf: no interior point given, the origin not inside: using the halfspaces' "
        "Chebyshev centre H2.5,") and len(a.strip().split("\n")) == 6, e + a)
    for spec in ("300 s D3 t66", "200 s D4 t67", "60 s D6 t68"):
        d, pts = points(rbox(spec))
        rows = [" ".join(repr(x) for x in p) + " " + repr(-0.25 - sum(5 * x for x in p)) for p in pts]
        text = "%d\n%d\n" % (d + 1, len(rows)) + "\n".join(rows) + "\n"  # about (5, ..., 5)
        r, a, e = run([lh, "qhalf", "i"], text)
        h = e.split("centre ")[-1].strip()
        c = [float(x) for x in h[1:].split(",")] if h.startswith("H") else []
        check("qhalf %s centre found" % spec, r == 0 and len(c) == d and all(abs(x - 5) < 1e-6 for x in c), e)
        _, b, _ = run(["qhalf", h, "i"], text)
        check("qhalf %s about the centre, i as qhalf's" % spec,
              sorted(map(sorted, keys(a))) == sorted(map(sorted, keys(b))) and keys(a), a[:80] + " / " + b[:80])


def eight(lh):
    """8-d: 9 coefficients, past orient's dimensions (the dual facet's plane gives the point)."""
    _, text, _ = run(["qconvex", "n"], rbox("c D8"))
    r, a, e = run([lh, "qhalf", "H0", "Fp"], text)
    _, b, _ = run(["qhalf", "H0", "Fp"], text)
    rows = lambda out: [tuple(map(float, l.split())) for l in out.strip().split("\n")[2:]]
    check("qhalf 8-d cube Fp", r == 0 and a.split()[:2] == b.split()[:2] and same_rows(rows(a), rows(b), 1e-9),
          e + a[:80] + " / " + b[:80])
    r, _, e = run([lh, "qhalf", "H0.5", "Fp"], text)
    check("qhalf 8-d on the boundary", r == 3 and "on the boundary of halfspace" in e, e)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("lifthull")
    ap.add_argument("-v", action="store_true")
    a = ap.parse_args()
    qf.VERBOSE[0] = a.v
    if not all(shutil.which(p) for p in ("rbox", "qconvex", "qhalf")):
        print("SKIP: Qhull's programs (qhull-bin) not found")
        return 77
    lh = a.lifthull
    for name, fn in (("basics", basics), ("outputs", outputs), ("cdd", cdd), ("hostile", hostile),
                     ("8-d", eight), ("centre", centre)):
        qf.guard(name, fn, lh)
    print("%d passed, %d failed" % (qf.PASSES[0], len(qf.FAILS)))
    return 1 if qf.FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
