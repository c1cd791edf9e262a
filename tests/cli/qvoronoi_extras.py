#!/usr/bin/env python3
"""qvoronoi's FI, FD, Fc, FP and G (issue 30 item 15) against Qhull 2020.2's qvoronoi:

  qvoronoi_extras.py LIFTHULL [-v]

On rbox sets in general position: FI lists one facet id per Voronoi vertex (lifthull's are
the Delaunay facets' numbers 0..m-1, Qhull's its internal ids: only the count is compared);
FD p prints the Voronoi vertices in cdd's format (rows equal as multisets to 1e-9); FD leaves
Fi, Fo and Fv as they are. Fc and FP on a set with a repeated site: the duplicate is the
coplanar point of the site it repeats (the facet it is listed with may differ: Qhull's is
the one its partition ended in; Qhull may keep the later copy as the vertex). G: the same
frame, Voronoi vertices (as a multiset) and regions (as cycles of vertex positions, either
direction) as Qhull's; refused as Qhull does in 3-d; m and FM refused as Qhull does. Print
filters Pdk, PDk, PAn, QVn: the same Voronoi vertices, regions, ridges and good facets;
QGn, QG-n, PG: the same Delaunay facets and their Voronoi vertices, less Qhull's upper ones. Exit 0 when all passed, 1 otherwise, 77 without
Qhull's programs.
"""

import re
import sys

from qhull_check import cdd_rows, check, main, rbox, run, same_rows




def key(p):
    return tuple(round(x, 6) for x in p)


def canon_cycle(c):
    """A cycle up to rotation and direction."""
    if not c:
        return ()
    forms = []
    for seq in (c, c[::-1]):
        forms += [tuple(seq[i:] + seq[:i]) for i in range(len(seq))]
    return min(forms)


def geom(out):
    """qvoronoi G: (header counts, Voronoi vertices, regions as cycles of positions, the
    sites that are 'coplanar or isolated')."""
    lines = out.rstrip("\n").split("\n")
    m = re.match(r"\{appearance \{\+edge -face\} OFF (\d+) (\d+) 1 # Voronoi centers and cells$", lines[1])
    nv, nf = int(m.group(1)), int(m.group(2))
    body = [l for l in lines[2:] if not l.startswith("# ")]
    verts = [tuple(float(x) for x in l.split("#")[0].split()) for l in body[:nv]]
    regions, isolated = [], []
    for l in body[nv:]:
        if l == "}":
            continue
        if "is coplanar or isolated" in l:
            isolated.append(int(re.search(r"p(\d+)", l).group(1)))
            continue
        w = [int(x) for x in l.split("#")[0].split()]
        assert w[0] == len(w) - 1
        site = int(re.search(r"# p(\d+)", l).group(1))
        regions.append((site, canon_cycle([key(verts[v][:2]) for v in w[1:]])))
    assert verts[0] == (0.0, 0.0, 0.0)
    return (nv, nf), sorted(key(v) for v in verts[1:]), sorted(regions), isolated, lines[0], lines[-2:]


def general(lh):
    for spec in ("30 D2 t51", "80 D2 t52", "40 D3 t53", "30 D4 t54"):
        text = rbox(spec)
        _, a, _ = run([lh, "qvoronoi", "FI"], text)
        _, b, _ = run(["qvoronoi", "FI"], text)
        ids = a.split()[1:]
        check(spec + " FI", a.split()[0] == b.split()[0] and ids == [str(k) for k in range(len(ids))],
              a[:40] + " / " + b[:40])
        r, a, _ = run([lh, "qvoronoi", "FD", "p"], text)
        _, b, _ = run(["qvoronoi", "FD", "p"], text)
        (ha, ra), (hb, rb) = cdd_rows(a), cdd_rows(b)
        check(spec + " FD p", r == 0 and ha == hb and same_rows(ra, rb, 1e-9, relative=True)
              and a.split("\n")[0] == "lifthull qvoronoi FD p", "%s %s" % (ha, hb))
        for o in ("Fi", "Fo", "Fv"):
            _, a, _ = run([lh, "qvoronoi", "FD", o], text)
            _, b, _ = run([lh, "qvoronoi", o], text)
            check(spec + " FD " + o + " as " + o, a == b and a != "")
        r, a, e = run([lh, "qvoronoi", "FD", "o"], text)
        _, b, _ = run([lh, "qvoronoi", "o"], text)
        check(spec + " FD o: a note, then o", r == 0 and a == b and "not available for 'o'" in e, e)
        # a set with a repeated site: the duplicate is the one coplanar point
        lines = text.split("\n")
        n = int(lines[1])
        dup = lines[0] + "\n%d\n" % (n + 1) + "\n".join(lines[2:2 + n]) + "\n" + lines[5] + "\n"
        _, a, _ = run([lh, "qvoronoi", "Fc"], dup)
        _, b, _ = run(["qvoronoi", "Fc"], dup)
        fc = lambda out: sorted(int(x) for l in out.strip().split("\n")[1:] for x in l.split()[1:])
        # lifthull keeps the first of equal sites as the vertex (lh_tri_duplicate_of), Qhull
        # the one it happened to insert first
        check(spec + " Fc", a.split()[0] == b.split()[0] and fc(a) == [n] and fc(b) in ([n], [3]),
              a[:80] + " / " + b[:80])
        _, a, _ = run([lh, "qvoronoi", "FP"], dup)
        _, b, _ = run(["qvoronoi", "FP"], dup)
        fp = lambda out: sorted((min(int(l.split()[0]), int(l.split()[1])),
                                 max(int(l.split()[0]), int(l.split()[1])), float(l.split()[3]))
                                for l in out.strip().split("\n")[1:])
        check(spec + " FP", fp(a) == fp(b) == [(3, n, 0.0)] and a.split()[1:3] == ["3", str(n)], a + " / " + b)


def geomview(lh):
    for spec in ("20 D2 t61", "100 D2 t62", "12 D2 s t63"):
        text = rbox(spec)
        r, a, _ = run([lh, "qvoronoi", "G"], text)
        _, b, _ = run(["qvoronoi", "G"], text)
        ga, gb = geom(a), geom(b)
        check(spec + " G counts", r == 0 and ga[0] == gb[0], "%s %s" % (ga[0], gb[0]))
        if "s" not in spec.split():  # cospherical: Qhull merges the centres, lifthull keeps them
            check(spec + " G vertices", ga[1] == gb[1], "%s / %s" % (ga[1][:3], gb[1][:3]))
            check(spec + " G regions", ga[2] == gb[2], "%s / %s" % (ga[2][:2], gb[2][:2]))
        check(spec + " G frame", ga[4] == "{appearance {linewidth 3} LIST # lifthull qvoronoi G"
              and gb[4].startswith("{appearance {linewidth 3} LIST # ") and ga[5] == gb[5] == ["}", "}"])
    # a repeated site: Qhull's "coplanar or isolated" line, the faces counted without it
    text = "2\n6\n0 0\n1 0\n0 1\n1 0\n0.3 0.3\n1 1\n"
    _, a, _ = run([lh, "qvoronoi", "G"], text)
    _, b, _ = run(["qvoronoi", "G"], text)
    ga, gb = geom(a), geom(b)
    check("duplicate G", ga[:4] == gb[:4] and ga[3] == [3], a + b)
    r, a, e = run([lh, "qvoronoi", "G"], rbox("20 D3 t64"))
    check("qvoronoi G in 3-d refused", r == 2 and a == "" and "only for 2-d" in e, e)
    for opt in ("m", "FM"):
        r, _, e = run([lh, "qvoronoi", opt], rbox("20 D2 t65"))
        check("qvoronoi %s refused" % opt, r == 2 and "option '%s' is not used with qvoronoi" % opt in e, e)


def vertices(out, full):
    """p or o: the Voronoi vertices by number (1..), rounded positions."""
    lines = out.split("\n")
    d = int(lines[0])
    count = int(lines[1].split()[0]) - (1 if full else 0)
    first = 3 if full else 2
    return {v + 1: key(float(x) / (1 + abs(float(x))) for x in lines[first + v].split()[:d])
            for v in range(count)}, lines[first + count:]


def regions(out):
    """o: per site its region's vertex positions and whether it is unbounded (0)."""
    verts, rest = vertices(out, True)
    res = []
    for l in rest:
        w = [int(x) for x in l.split()]
        if w:
            res.append((frozenset(verts[v] for v in w[1:] if v), 0 in w[1:]))
    return res


def ridge_sets(out, verts):
    """Fv: {site pair: (vertex positions, unbounded)}."""
    res = {}
    for l in out.strip().split("\n")[1:]:
        w = [int(x) for x in l.split()]
        res[(w[1], w[2])] = (frozenset(verts[v] for v in w[3:] if v), 0 in w[3:])
    return res


def neighbour_sets(out, verts):
    """FN: per site the positions of its printed Voronoi vertices (ids >= 0: 'o' less one)."""
    return [frozenset(verts[int(x) + 1] for x in l.split()[1:] if int(x) >= 0)
            for l in out.strip().split("\n")[1:]]


def filters(lh):
    """Pdk, PDk, PAn and QVn select Voronoi vertices (good Delaunay facets) as Qhull."""
    for spec in ("40 D2 t71", "60 D3 t72"):
        text = rbox(spec)
        for f in (["Pd0"], ["PD1"], ["Pd0", "Pd1:0.1"], ["PA5"], ["QV3"], ["QV-3"], ["Pd0", "QV4"]):
            name = "%s qvoronoi %s" % (spec, " ".join(f))
            r, la, _ = run([lh, "qvoronoi"] + f + ["o"], text)
            _, qa, _ = run(["qvoronoi"] + f + ["o"], text)
            lv, qv = vertices(la, True)[0], vertices(qa, True)[0]
            check(name + " o vertices", r == 0 and sorted(lv.values()) == sorted(qv.values()) and (lv or len(f) > 1),
                  "%d vs %d" % (len(lv), len(qv)))
            check(name + " o regions", regions(la) == regions(qa))
            _, lp, _ = run([lh, "qvoronoi"] + f + ["p"], text)
            check(name + " p = o's vertices", sorted(vertices(lp, False)[0].values()) == sorted(lv.values()))
            _, lf, _ = run([lh, "qvoronoi"] + f + ["Fv"], text)
            _, qf, _ = run(["qvoronoi"] + f + ["Fv"], text)
            check(name + " Fv", ridge_sets(lf, lv) == ridge_sets(qf, qv),
                  "%s / %s" % (sorted(ridge_sets(lf, lv))[:4], sorted(ridge_sets(qf, qv))[:4]))
            for o in ("Fi", "Fo"):
                _, lf, _ = run([lh, "qvoronoi"] + f + [o], text)
                _, qf, _ = run(["qvoronoi"] + f + [o], text)
                pairs = lambda out: sorted(tuple(l.split()[1:3]) for l in out.strip().split("\n")[1:])
                check(name + " " + o, pairs(lf) == pairs(qf), "%s / %s" % (pairs(lf)[:4], pairs(qf)[:4]))
            _, lf, _ = run([lh, "qvoronoi"] + f + ["FN"], text)
            _, qf, _ = run(["qvoronoi"] + f + ["FN"], text)
            check(name + " FN", neighbour_sets(lf, lv) == neighbour_sets(qf, qv))
            _, li, _ = run([lh, "qvoronoi"] + f + ["i"], text)
            _, qi, _ = run(["qvoronoi"] + f + ["i"], text)
            sets = lambda out: sorted(tuple(sorted(l.split())) for l in out.strip().split("\n")[1:])
            check(name + " i", sets(li) == sets(qi))
            _, _, ls = run([lh, "qvoronoi"] + f + ["s"], text)
            _, _, qs = run(["qvoronoi"] + f + ["s"], text)
            count = lambda err: re.findall(r"Number of .*Voronoi vertices: \d+", err)
            check(name + " s", count(ls) == count(qs) and count(ls), "%s / %s" % (count(ls), count(qs)))
        if "D2" in spec:
            _, la, _ = run([lh, "qvoronoi", "Pd0", "G"], text)
            _, qa, _ = run(["qvoronoi", "Pd0", "G"], text)
            ga, gb = geom(la), geom(qa)
            check(spec + " Pd0 G", ga[1] == gb[1] and [r for r in ga[2]] == [r for r in gb[2] if r[1]],
                  "%s / %s" % (ga[2][:3], gb[2][:3]))


def facet_sets(out):
    return sorted(tuple(sorted(int(x) for x in l.split())) for l in out.strip().split("\n")[1:] if l.strip())


def good_by_point(lh):
    """QGn, QG-n and PG: the Voronoi vertices of the Delaunay facets point n sees (n an
    interior site: left out, as Qhull does, the hull is the same), or not, or the good
    facets' other neighbours. Qhull also prints its upper Delaunay facets there (for
    PG, those next to a good one): lifthull prints Delaunay simplices only, as its
    qdelaunay does, so those are taken from Qhull's side first (qdelaunay Qu i)."""
    for spec in ("40 D2 t73", "50 D3 t74"):
        text = rbox(spec)
        _, fx, _ = run(["qconvex", "Fx"], text)
        hull = set(int(x) for x in fx.split()[1:])
        inner = min(set(range(int(text.split("\n")[1]))) - hull)
        _, up, _ = run(["qdelaunay", "Qu", "i"], text)
        upper = set(facet_sets(up))
        for f in (["QG%d" % inner], ["QG-%d" % inner], ["Pd0", "PG"], ["QG%d" % inner, "PG"], ["PD1", "PG"]):
            name = "%s qvoronoi %s" % (spec, " ".join(f))
            r, li, _ = run([lh, "qvoronoi"] + f + ["i"], text)
            _, qi, _ = run(["qvoronoi", "Pp"] + f + ["i"], text)
            want = [t for t in facet_sets(qi) if t not in upper]
            check(name + " i", r == 0 and facet_sets(li) == want and want, "%s / %s" % (facet_sets(li)[:3], want[:3]))
            r, lp, _ = run([lh, "qvoronoi"] + f + ["p"], text)
            _, qp, _ = run(["qvoronoi"] + f + ["p"], text)
            lv, qv = vertices(lp, False)[0], vertices(qp, False)[0]
            check(name + " p", r == 0 and len(lv) == len(want) and set(lv.values()) <= set(qv.values()),
                  "%d vertices, %d of Qhull's (%d Delaunay)" % (len(lv), len(qv), len(want)))
            _, _, le = run([lh, "qvoronoi"] + f + ["s"], text)
            _, _, qe = run(["qvoronoi"] + f + ["s"], text)
            head = lambda err: re.findall(r"(?:convex hull of|Number of .*:) \d+", err)[:3]
            check(name + " s", head(le) == head(qe) and "'good'" in le, "%s / %s" % (head(le), head(qe)))


if __name__ == "__main__":
    sys.exit(main(__doc__, ("rbox", "qvoronoi"),
                  [("general", general), ("geomview", geomview), ("filters", filters),
                   ("good_by_point", good_by_point)]))
