#!/usr/bin/env python3
"""Qhull's Geomview output G in 4-d pictures and G's suboptions (issue 30 item 15), in
`lifthull qconvex | qdelaunay`, against Qhull 2020.2's programs:

  qhull_geomview.py LIFTHULL [-v]

2-d and 3-d pictures (2-d and 3-d hulls, 2-d Delaunay's lifted hull) with Gi Go Gn Ga Gr
Gh: every line's numbers equal as a multiset to Qhull's within 1e-3 (Qhull projects the
vertices onto its inner and outer planes: differences of 1e-15 there; facet and ridge
order differ). 4-d pictures (4-d hulls, 3-d Delaunay's lifted hull; 4OFF, and GDn): the
same ridges (as sets of vertex positions) and each facet's colour (a facet known by the
vertices of the ridges it names first). Refusals as Qhull's (a 5-d picture, Gn with
nothing to draw) and the suboption lifthull does not draw (Gp). Gt (3-d Delaunay): the inner ridges of GD3,
as Qhull. Gc: the centrums' normals and centres, axes from a vertex. Gv: Qhull's
spheres (as sets of triangles) and planes moved by their radius. Exit 0 when
all passed, 1 otherwise, 77 without Qhull's programs.
"""

import re
import sys

from qhull_check import check, main, rbox, run, same_rows

NUM = re.compile(r"^-?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?$")


def rows(out):
    """Every line's numbers (comments and words left out), the LIST line aside."""
    res = []
    for l in out.split("\n")[1:]:
        nums = [float(t) for t in l.split("#")[0].split() if NUM.match(t)]
        if nums:
            res.append(tuple(nums))
    return res




def key(p):
    return tuple(round(x, 3) + 0.0 for x in p)


def ridges4(out, dropped):
    """4OFF or GDn output: ridge sets, and {facet vertex set: colour}."""
    lines = out.split("\n")
    ridges, colour_of, verts_of, order = [], {}, {}, []
    i = 0
    while i < len(lines):
        m = re.search(r"ridge between f(\d+)(?: f(\d+))?", lines[i])
        if m:
            pts = [key(float(x) for x in lines[i + k].split()) for k in (1, 2, 3)]
            ridges.append(frozenset(pts))
            order.append(m.group(1))
            verts_of.setdefault(m.group(1), set()).update(pts)
            if m.group(2):
                verts_of.setdefault(m.group(2), set()).update(pts)
            if dropped:
                colour_of[m.group(1)] = key(float(x) for x in lines[i + 4].split()[4:7])
            i += 4
            continue
        m = re.match(r"3 \d+ \d+ \d+ +(\S+) +(\S+) +(\S+) 1 # f(\d+)", lines[i])
        if m:
            colour_of[m.group(4)] = key(float(m.group(k)) for k in (1, 2, 3))
        i += 1
    colours = {frozenset(verts_of[f]): c for f, c in colour_of.items()}
    return sorted(map(sorted, ridges)), colours


def pictures(lh):
    cases = [("10 D2 t91", "qconvex", []), ("14 D3 t92", "qconvex", []), ("15 D2 t93", "qdelaunay", ["Qt"])]
    for spec, prog, qopts in cases:
        text = rbox(spec)
        dims = int(spec.split()[1][1:]) + (prog == "qdelaunay")
        for opts in (["Gi"], ["Go"], ["Gi", "Go"], ["Ga"], ["Gan"], ["Gr"], ["Gh"], ["Gn", "Gr"],
                     ["Grh"], ["Gn", "Ga", "Gh"]):
            if dims == 2 and (set("rh") & set("".join(opts))) and "a" not in "".join(opts):
                continue  # Qhull warns: no ridges in 2-d
            name = "%s %s %s" % (spec, prog, " ".join(opts))
            r, a, _ = run([lh, prog] + opts, text)
            _, b, _ = run([prog] + qopts + opts, text)
            check(name, r == 0 and same_rows(rows(a), rows(b), 1e-3) and len(rows(a)) > 3,
                  "%d vs %d rows" % (len(rows(a)), len(rows(b))))
            check(name + " frame", a.split(" LIST")[0] == b.split(" LIST")[0] and a.endswith("}\n"), a[:60])
        r, a, e = run([lh, prog, "Gr"], text)
        if dims == 2:
            check(spec + " Gr in 2-d: a note, then G", r == 0 and "ignored" in e
                  and a.split("\n")[1:] == run([lh, prog, "G"], text)[1].split("\n")[1:], e)


def selected(lh):
    """With good facets selected (Pdk, PAn, QVn), G draws the good facets only, as Qhull."""
    for spec, prog, qopts in (("15 D2 t98", "qdelaunay", ["Qt"]), ("30 D3 t99", "qconvex", [])):
        text = rbox(spec)
        # qdelaunay's PAn: lifthull's among the Delaunay simplices, Qhull's among its upper
        # facets too (they are often larger): qconvex only
        for f in (["Pd0"], ["QV3"]) + ((["PA2"],) if prog == "qconvex" else ()):
            r, a, _ = run([lh, prog, "G"] + f, text)
            _, b, _ = run([prog] + qopts + ["G"] + f, text)
            check("%s %s G %s" % (spec, prog, " ".join(f)), r == 0 and same_rows(rows(a), rows(b), 1e-3)
                  and a.count("OFF") == b.count("OFF") > 0, "%d vs %d" % (a.count("OFF"), b.count("OFF")))


def four_d(lh):
    for spec, prog, qopts in (("8 D4 t94", "qconvex", []), ("30 D4 t95", "qconvex", []),
                              ("9 D3 t96", "qdelaunay", ["Qt"]), ("25 D3 t97", "qdelaunay", ["Qt"])):
        text = rbox(spec)
        for opts in ([], ["Gi"], ["GD0"], ["GD3"], ["GD1"]) + ((["Gt"],) if prog == "qdelaunay" else ()):
            name = "%s %s G %s" % (spec, prog, " ".join(opts))
            drop = bool(opts) and opts[0] in ("GD0", "GD1", "GD3", "Gt")
            r, a, _ = run([lh, prog, "G"] + opts, text)
            _, b, _ = run([prog] + qopts + ["G"] + opts, text)
            (ra, ca), (rb, cb) = ridges4(a, drop), ridges4(b, drop)
            common = set(ca) & set(cb)
            check(name + " ridges", r == 0 and ra == rb and len(ra) > 4, "%d vs %d" % (len(ra), len(rb)))
            check(name + " colours", len(common) >= len(cb) // 3 and all(ca[k] == cb[k] for k in common),
                  "%d common of %d" % (len(common), len(cb)))
            head = a.split("\n")[:2]
            check(name + " frame", (head[1] == b.split("\n")[1]) if not drop else
                  head[0] == "{appearance {+edge -evert linewidth 2} LIST # lifthull %s G %s" % (prog, opts[0]), head)
            if drop:  # one LIST of OFFs: a brace closes it at the end only, as Qhull's
                check(name + " braces", a.count("}") == b.count("}") == 2 and a.endswith("\n}\n"), a[-80:])


def sphere_split(out):
    """Gv's picture: (the unit sphere's triangles as sets of corners, the rest's rows)."""
    m = re.search(r"INST geom \{define vsphere OFF\n(\d+) (\d+) (\d+)\n\n(.*?)\n\n(.*?)\n\} transforms", out, re.S)
    if not m:
        return None, rows(out)
    verts = [key(float(x) for x in l.split()) for l in m.group(4).split("\n")]
    tris = sorted(sorted(verts[int(x)] for x in l.split()[1:]) for l in m.group(5).split("\n"))
    return (m.group(1, 2, 3), tris), rows(out[:m.start()] + out[m.end():])


def spheres(lh):
    """Gv: a sphere at each vertex (0.02 times the largest coordinate), the planes moved
    out and in by its radius (Qhull's rows within 1e-3; the sphere as a set of triangles)."""
    for spec, prog, qopts in (("12 D2 t88", "qconvex", []), ("14 D3 t89", "qconvex", []),
                              ("15 D2 t87 B3", "qdelaunay", ["Qt"]), ("10 D3 t86", "qconvex", [])):
        text = rbox(spec)
        for opts in (["Gv"], ["Gv", "Gi"], ["Gv", "Go"], ["Gvn"], ["Gv", "Ga"], ["Gvr"]):
            if spec.split()[1] == "D2" and prog == "qconvex" and "Gvr" in opts:
                continue  # Qhull: no ridges in 2-d
            name = "%s %s %s" % (spec, prog, " ".join(opts))
            r, a, _ = run([lh, prog] + opts, text)
            _, b, _ = run([prog] + qopts + opts, text)
            (sa, ra), (sb, rb) = sphere_split(a), sphere_split(b)
            check(name + " sphere", r == 0 and sa == sb and sa is not None, "%s / %s" % (str(sa)[:80], str(sb)[:80]))
            check(name, same_rows(ra, rb, 1e-3) and len(ra) > 3, "%d vs %d rows" % (len(ra), len(rb)))
    r, a, e = run([lh, "qconvex", "Gv"], rbox("10 D4 t85"))
    check("4-d Gv: a note, then G", r == 0 and "'Gv' and 'Gc' ignored" in e and "vsphere" not in a, e)


CENTRUM = re.compile(r"\{appearance \{-normal -edge normscale 0\} \{INST geom \{ (?:define centrum CQUAD  # f\d+\n"
                     r"(?:.*\n){3}.* \} transform \{ \n|: centrum \} transform \{ # f\d+\n)((?:.*\n){4})1 \}\}\}\n")


def centrums(out):
    """Gc: (each centrum's (normal, centre) rows, whether its first two rows are some
    vertex - centre and that x normal, the rest's rows)."""
    cs, fit = [], True
    pts = set(key(r) for r in rows(out))
    for m in CENTRUM.finditer(out):
        a, b, n, c = [tuple(float(x) for x in l.split("#")[0].split()[:3]) for l in m.group(1).strip().split("\n")]
        cs.append((key(n), key(c)))
        cross = (a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0])
        fit = fit and key(x + y for x, y in zip(a, c)) in pts and all(abs(x - y) < 2e-3 for x, y in zip(b, cross))
    return sorted(cs), fit, rows(CENTRUM.sub("", out))


def centrum_pictures(lh):
    """Gc: Qhull's centrum at each facet's centroid (exact: on the facet), same normal
    rows, axes from a vertex (Qhull's first vertex may be another one)."""
    for spec, prog, qopts in (("12 D2 t84", "qconvex", []), ("14 D3 t83", "qconvex", []),
                              ("15 D2 t82", "qdelaunay", ["Qt"])):
        text = rbox(spec)
        for opts in (["Gc"], ["Gcn"], ["Gc", "Ga"]):
            name = "%s %s %s" % (spec, prog, " ".join(opts))
            r, a, _ = run([lh, prog] + opts, text)
            _, b, _ = run([prog] + qopts + opts, text)
            (ca, fa, ra), (cb, fb, rb) = centrums(a), centrums(b)
            check(name + " centrums", r == 0 and ca == cb and len(ca) > 3 and (fa and fb or "n" in opts[0]), "%s / %s" % (ca[:2], cb[:2]))
            check(name, same_rows(ra, rb, 1e-3), "%d vs %d rows" % (len(ra), len(rb)))


def refusals(lh):
    for prog, spec, opts, msg in (("qconvex", "10 D5 t1", ["G"], "only available for 2-d, 3-d and 4-d"),
                                  ("qdelaunay", "10 D4 t1", ["G"], "only available for 2-d, 3-d and 4-d"),
                                  ("qconvex", "10 D3 t1", ["Gn"], "no output specified for Geomview"),
                                  ("qconvex", "10 D4 t1", ["Gr"], "are for 2-d and 3-d pictures"),
                                  ("qconvex", "10 D3 t1", ["Gp"], "'p' is not supported"),
                                  ("qconvex", "10 D3 t1", ["Gt"], "'Gt': transparent outer ridges need"),
                                  ("qdelaunay", "10 D2 t1", ["Gt"], "'Gt': transparent outer ridges need"),
                                  ("qdelaunay", "10 D3 t1", ["Gt", "GD0"], "'Gt': transparent outer ridges need"),
                                  ("qvoronoi", "10 D2 t1", ["Gr"], "G's suboptions are for qconvex and qdelaunay")):
        r, a, e = run([lh, prog] + opts, rbox(spec))
        check("%s %s %s refused" % (spec, prog, " ".join(opts)), r == 2 and a == "" and msg in e, e)


if __name__ == "__main__":
    sys.exit(main(__doc__, ("rbox", "qconvex", "qdelaunay"),
                  [("pictures", pictures), ("selected", selected), ("4-d", four_d), ("spheres", spheres),
                   ("centrums", centrum_pictures),
                   ("refusals", refusals)]))
