#!/usr/bin/env python3
"""qhull_extreme.py LIFTHULL FILE [SCALE_EXPONENT ...]: the values of qconvex n, Fi, FD n,
qvoronoi p and qdelaunay p (issue 30, items 9: facet planes, and the Voronoi vertices and
lifted coordinates past DBL_MAX) on the sites of FILE (Qhull format), checked in decimal:
every value a finite number (no nan, no inf: beyond DBL_MAX it is still printed as the
number it is); each qconvex facet's normal of length 1 to 1e-14 and n.v + off = 0 at its
vertices (qconvex i) to 1e-12 of the terms' magnitudes; each Voronoi vertex equally far
from the sites of its Delaunay simplex (qdelaunay i) to 1e-9 relative; each lifted
coordinate (|p|^2 - low) max|x| / (high - low) (Qhull's Qbb) to 1e-12 of max |x|. With
SCALE_EXPONENTs k, the sites scaled by 2^k (exact for the sets used) must give the same
facets with the same normals. Exit 1 on any failure."""

import decimal
import subprocess
import sys
from decimal import Decimal

decimal.getcontext().prec = 60
fails = []


def run(lh, text, *args):
    return subprocess.run([lh] + list(args), input=text, capture_output=True, text=True,
                          check=True).stdout


def rows(out, skip):
    """The rows after `skip` header lines, as Decimals; a failure for nan or inf."""
    res = []
    for line in out.split("\n")[skip:]:
        w = line.split()
        if not w or w == ["end"]:
            continue
        if any(x.lower().lstrip("+-") in ("nan", "inf", "-nan") for x in w):
            fails.append("non-finite value: " + line)
        else:
            res.append([Decimal(x) for x in w])
    return res


def read_sites(text):
    lines = [ln for ln in text.split("\n") if ln.strip()]
    head = lines[0].split()
    first = 1 if len(head) == 2 and head[1].isdigit() else 2  # "d n" or "d" then "n"
    return int(head[0]), [[Decimal(float(x)) for x in ln.split()] for ln in lines[first:]]


def check(lh, text, name):
    d, sites = read_sites(text)
    facets = [[int(x) for x in r] for r in rows(run(lh, text, "qconvex", "i"), 1)]
    normals = []
    for opt, skip in (("n", 2), ("Fi", 2), ("FD", 3)):
        planes = rows(run(lh, text, "qconvex", *(["FD", "n"] if opt == "FD" else [opt])), skip)
        if opt == "FD":  # cdd's rows: -off, then -n
            planes = [[-x for x in r[1:]] + [-r[0]] for r in planes if len(r) == d + 1]
        if len(planes) != len(facets):
            fails.append("%s qconvex %s: %d planes for %d facets" % (name, opt, len(planes), len(facets)))
            continue
        for t, (f, p) in enumerate(zip(facets, planes)):
            n, off = p[:d], p[d]
            if abs(sum(x * x for x in n) - 1) > Decimal("1e-14"):
                fails.append("%s qconvex %s facet %d: |n| = %s" % (name, opt, t, sum(x * x for x in n).sqrt()))
            for v in f:
                terms = [a * b for a, b in zip(n, sites[v])] + [off]
                if abs(sum(terms)) > Decimal("1e-12") * sum(abs(x) for x in terms) + Decimal(2) ** -1060:
                    fails.append("%s qconvex %s facet %d: n.p%d + off = %s, off %s"
                                 % (name, opt, t, v, sum(terms), off))
        if opt == "n":
            normals = [p[:d] for p in planes]
    simplices = [[int(x) for x in r] for r in rows(run(lh, text, "qdelaunay", "i"), 1)]
    centres = rows(run(lh, text, "qvoronoi", "p"), 2)
    if len(centres) != len(simplices):
        fails.append("%s qvoronoi p: %d vertices for %d simplices" % (name, len(centres), len(simplices)))
    for s, (c, verts) in enumerate(zip(centres, simplices)):
        r2 = [sum((x - y) ** 2 for x, y in zip(c, sites[v])) for v in verts]
        if max(r2) - min(r2) > Decimal("1e-9") * max(r2):
            fails.append("%s qvoronoi p vertex %d: squared radii %s to %s" % (name, s, min(r2), max(r2)))
    lifted = rows(run(lh, text, "qdelaunay", "p"), 2)
    unique = []  # 'p' leaves out the merged duplicates
    for p in sites:
        if p not in unique:
            unique.append(p)
    z = [sum(x * x for x in p) for p in unique]
    big = max(abs(x) for p in sites for x in p)
    low, high = min(z), max(z)
    if len(lifted) != len(unique):
        fails.append("%s qdelaunay p: %d points for %d distinct sites" % (name, len(lifted), len(unique)))
    for i, p in enumerate(lifted):
        want = (z[i] - low) * big / (high - low) if high > low else 0
        if abs(p[d] - want) > Decimal("1e-12") * big:
            fails.append("%s qdelaunay p site %d: lifted %s, want %s" % (name, i, p[d], want))
    return normals


def main():
    lh, path, exps = sys.argv[1], sys.argv[2], [int(k) for k in sys.argv[3:]]
    text = open(path).read()
    base = check(lh, text, path)
    for k in exps:
        d, sites = read_sites(text)
        stext = "%d\n%d\n" % (d, len(sites)) + "".join(
            " ".join(repr(float(x) * 2.0 ** k) for x in p) + "\n" for p in sites)
        if check(lh, stext, "%s * 2^%d" % (path, k)) != base:
            fails.append("%s * 2^%d: other qconvex normals than at the unit scale" % (path, k))
    for f in fails[:5]:
        print("FAIL", f)
    print("%s: %d failures" % (path, len(fails)))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
