#!/usr/bin/env python3
"""Good facets by a point, QGn / QG-n / QVn / QV-n, in `lifthull qconvex | qdelaunay` against
Qhull 2020.2's programs (issue 30 item 15):

  qhull_good.py LIFTHULL [-v]

On rbox sets in general position, 2-d to 4-d: the printed facets (i, as vertex sets), alone
and with PG, PAn and Pdk; the summary's counts (QGn leaves point n out of the hull: n - 1
points); Fx and FN (only the printed facets' vertices); o (every input point). qdelaunay's
QGn: the Delaunay triangles whose circumsphere holds point n; Qhull also prints the upper
Delaunay facets point n sees (not Delaunay triangles, and left out of its own count of
good regions): those are removed from Qhull's side first. Refusals: n out of range (as
Qhull's QH6150), a malformed n (qvoronoi's QGn: qvoronoi_extras.py). Exit 0 when all passed, 1 otherwise, 77
without Qhull's programs.
"""

import re
import sys

from qhull_check import check, main, rbox, run


def facets(out):
    lines = out.strip().split("\n")
    return sorted(tuple(sorted(int(x) for x in l.split())) for l in lines[1:1 + int(lines[0])])


def ids(out):
    lines = out.strip().split("\n")
    return sorted(int(x) for x in lines[1:1 + int(lines[0])])


def fn_vertices(out):
    """FN: the sites with a list (not '0'), and each list's length."""
    lines = out.strip().split("\n")
    return [(i, int(l.split()[0])) for i, l in enumerate(lines[1:]) if l.split()[0] != "0"]


def summary(err):
    err = err.split("Statistics for")[0]
    return re.findall(r"^ *(Number of [^:]+:|Convex hull of|Delaunay triangulation by the convex hull of)"
                      r" *(\d+)", err, re.M)


def qv_not(i):
    """QV-i; Qhull reads QV-0 as QV0 (the sign of -0 is lost), so the test leaves it out."""
    return "QV-%d" % i if i else "QV1"


def interior_point(text, prog):
    """A point that is no hull vertex, and one that is (the first of each)."""
    _, fx, _ = run([prog, "Fx"], text)
    hull = set(ids(fx))
    n = int(text.split("\n")[1].split()[0])
    return next(i for i in range(n) if i not in hull), min(hull)


def same_good(lh, prog, q, text, extra, got, want):
    """Equal facet sets; but where Pd0 leaves none of QGn's good facets, Qhull makes the
    closest one good (qh_findgood; QVn applies after it), picked in qdelaunay among its
    upper facets too, so that it may print another one or none, and then prints no
    neighbours for PG: there lifthull's one closest facet must be one of QGn's."""
    if "Pd0" not in extra or not q.startswith("QG") or got == want:
        return got == want
    _, alone, _ = run([lh, prog, q, "i"], text)
    kept = set(facets(alone))
    if "PG" in extra:
        return prog == "qconvex" and want == [] and 0 < len(got) <= 3 * len(kept)
    return prog == "qdelaunay" and len(want) <= 1 and len(got) == 1 and set(got) <= kept


def qconvex(lh):
    for spec in ("30 D2 t81", "60 D3 t82", "40 D4 t83", "10 D3 z t4"):
        text = rbox(spec)
        inner, corner = interior_point(text, "qconvex")
        for extra in (["Pd0", "PG"], ["PD1", "PG"]):  # PG: the neighbours of Pdk's facets
            _, a, _ = run([lh, "qconvex"] + extra + ["i"], text)
            _, b, _ = run(["qconvex"] + extra + ["i"], text)
            check("%s qconvex %s i" % (spec, " ".join(extra)), facets(a) == facets(b) and facets(a),
                  "%s / %s" % (facets(a)[:3], facets(b)[:3]))
        # point 0 of rbox's cube is usually a corner: then it sees some facets of the rest
        for q in ["QG%d" % corner, "QG-%d" % corner, "QG%d" % inner, "QV%d" % corner, qv_not(corner),
                  "QV%d" % inner]:
            for extra in ([], ["PG"], ["PA1"], ["Pd0"], ["Pd0", "PG"]):
                name = "%s qconvex %s" % (spec, " ".join([q] + extra))
                r, a, _ = run([lh, "qconvex", q] + extra + ["i"], text)
                _, b, _ = run(["qconvex", q] + extra + ["i"], text)
                check(name + " i", r == 0 and same_good(lh, "qconvex", q, text, extra, facets(a), facets(b)),
                      "%s / %s" % (facets(a)[:3], facets(b)[:3]))
            name = "%s qconvex %s" % (spec, q)
            _, _, a = run([lh, "qconvex", q, "s"], text)
            _, _, b = run(["qconvex", q, "s"], text)
            check(name + " s", summary(a) == summary(b) and len(summary(a)) >= 3,
                  "%s / %s" % (summary(a), summary(b)))
            for o in ("Fx", "FN"):
                _, a, _ = run([lh, "qconvex", q, o], text)
                _, b, _ = run(["qconvex", q, o], text)
                got, want = (ids(a), ids(b)) if o == "Fx" else (fn_vertices(a), fn_vertices(b))
                check(name + " " + o, got == want, "%s / %s" % (got[:5], want[:5]))
            _, a, _ = run([lh, "qconvex", q, "FS"], text)
            _, b, _ = run(["qconvex", q, "FS"], text)
            va, vb = [float(x) for x in a.split()[2:]], [float(x) for x in b.split()[2:]]
            check(name + " FS (the hull without QGn's point)",
                  all(abs(x - y) <= 1e-12 * abs(y) for x, y in zip(va, vb)) and len(va) == 2, a + b)




def qdelaunay(lh):
    for spec in ("40 D2 t84", "60 D3 t85", "30 D4 t86", "12 D2 z t7"):
        text = rbox(spec)
        inner, corner = interior_point(text, "qdelaunay")
        n = int(text.split("\n")[1].split()[0])
        for q in ["QG%d" % inner, "QG-%d" % inner, "QG%d" % corner, "QV%d" % inner, qv_not(corner)]:
            g = int(q[2:].lstrip("-"))
            # the Delaunay triangles of the points without QGn's point, in input numbering
            rest = text.split("\n")
            kept = [l for i, l in enumerate(rest[2:2 + n]) if not (q.startswith("QG") and i == g)]
            sub = rest[0] + "\n%d\n" % len(kept) + "\n".join(kept) + "\n"
            back = [i for i in range(n) if not (q.startswith("QG") and i == g)]
            _, full, _ = run(["qdelaunay", "Qt", "i"], sub)
            delaunay = set(tuple(sorted(back[v] for v in f)) for f in facets(full))
            for extra in ([], ["PA2"], ["Pd0"]):
                name = "%s qdelaunay %s" % (spec, " ".join([q] + extra))
                r, a, _ = run([lh, "qdelaunay", q] + extra + ["i"], text)
                _, b, _ = run(["qdelaunay", "Qt", q] + extra + ["i"], text)
                want = [f for f in facets(b) if f in delaunay]
                check(name + " i", r == 0 and same_good(lh, "qdelaunay", q, text, extra, facets(a), want)
                      and set(facets(a)) <= delaunay, "%s / %s" % (facets(a)[:3], want[:3]))
            name = "%s qdelaunay %s" % (spec, q)
            _, _, a = run([lh, "qdelaunay", q, "s"], text)
            _, _, b = run(["qdelaunay", "Qt", q, "s"], text)
            check(name + " s", summary(a) == summary(b) and len(summary(a)) >= 3,
                  "%s / %s" % (summary(a), summary(b)))
            if q.startswith("QV"):
                for o in ("Fx", "FN"):
                    _, a, _ = run([lh, "qdelaunay", q, o], text)
                    _, b, _ = run(["qdelaunay", "Qt", q, o], text)
                    got, want = (ids(a), ids(b)) if o == "Fx" else (fn_vertices(a), fn_vertices(b))
                    check(name + " " + o, got == want, "%s / %s" % (got[:5], want[:5]))
        _, a, _ = run([lh, "qdelaunay", "QG%d" % inner, "o"], text)
        check(spec + " QGn o lists every point", a.split("\n")[1].split()[0] == str(n), a[:40])


def refusals(lh):
    text = rbox("10 D3 t87")
    for prog in ("qconvex", "qdelaunay"):
        for q in ("QG10", "QV-12"):
            r, a, e = run([lh, prog, q, "i"], text)
            check("%s %s refused" % (prog, q), r == 2 and a == "" and
                  "option '%s': point %s is not among the 10 input points (0..9)" % (q, q[2:].lstrip("-")) in e, e)
        for q in ("QGx", "QV1.5", "QG-"):
            r, _, e = run([lh, prog, q, "i"], text)
            check("%s %s refused" % (prog, q), r == 2 and "option '%s': expected" % q in e, e)
    tet = "3 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    for prog in ("qconvex", "qdelaunay"):
        r, a, e = run([lh, prog, "QG3", "i"], tet)
        check(prog + " QG3: the rest is flat", r == 1 and a == "" and "option 'QG3' leaves point 3 out of the "
              "hull:" in e and "the 3 sites span an affine subspace of dimension 2" in e, e)


if __name__ == "__main__":
    sys.exit(main(__doc__, ("rbox", "qconvex", "qdelaunay"),
                  [("qconvex", qconvex), ("qdelaunay", qdelaunay), ("refusals", refusals)]))
