#!/usr/bin/env python3
"""qvoronoi_compare.py LIFTHULL QVORONOI FILE...: `lifthull qvoronoi` against Qhull's qvoronoi on
exactly degenerate point sets (issue 30): Fv, Fi and Fo must list the same site pairs, each Fv
ridge the same Voronoi vertices as points (coordinates from `p`, rounded to 1e-9; several
simplices of one Delaunay cell share one vertex, listed once), each Fi/Fo ridge the same
hyperplane to 1e-12, and no printed value nan or inf. Qhull's bounded ridges that are not of
dimension d-1 (their vertices span less: in 4D and up Qhull prints pairs that share a smaller
face, e.g. across a square of a 4D grid) are left out of Qhull's side first. The regions of `o`:
per site the same Voronoi vertices as points, as many of them (each cell's once). Prints one
line per file and format; exit 1 on any difference."""

import math
import os
import subprocess
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "oracles"))
from locate_geometry import affine_rank  # noqa: E402  (exact, Fractions)


def run(cmd, path):
    with open(path) as f:
        return subprocess.run(cmd, stdin=f, capture_output=True, text=True, check=True).stdout


def vertices(prog, path):
    lines = run(prog + ["p"], path).split("\n")
    m = int(lines[1])
    return [None] + [lines[2 + k].split() for k in range(m)]  # vertex 0: infinity


def fv(prog, path, d, full_only):
    pts = vertices(prog, path)
    out = {}
    for line in run(prog + ["Fv"], path).split("\n")[1:]:
        w = [int(x) for x in line.split()]
        if not w:
            continue
        fin = [[Fraction(x) for x in pts[v]] for v in w[3:] if v]
        if full_only and len(fin) == len(w) - 3 and affine_rank(fin) < d - 1:
            continue
        key = lambda v: (math.inf,) if v == 0 else tuple(round(float(x), 9) + 0.0 for x in pts[v])
        out[(w[1], w[2])] = sorted(set(key(v) for v in w[3:]))
    return out


def regions(prog, path):
    out = run(prog + ["o"], path).split("\n")
    nv, nr = (int(x) for x in out[1].split()[:2])
    pts = [tuple(round(float(x), 9) + 0.0 for x in out[2 + k].split()) for k in range(nv)]
    res = []
    for k in range(nr):
        w = [int(x) for x in out[2 + nv + k].split()]
        res.append((w[0], sorted(set((math.inf,) if v == 0 else pts[v] for v in w[1:]))))
    return res


def planes(prog, path, opt):
    out = {}
    for line in run(prog + [opt], path).split("\n")[1:]:
        w = line.split()
        if w:
            vals = [float(x) for x in w[3:]]
            if any(not math.isfinite(v) for v in vals):
                raise ValueError("%s %s: non-finite value in %r" % (path, opt, line))
            out[(int(w[1]), int(w[2]))] = vals
    return out


def main():
    lh, qv, files = [sys.argv[1], "qvoronoi"], [sys.argv[2]], sys.argv[3:]
    bad = 0
    for path in files:
        d = int(open(path).read().split()[0])
        a, b = fv(lh, path, d, False), fv(qv, path, d, True)
        ok = a == b
        print("%s Fv: %d ridges, qvoronoi %d: %s" % (path, len(a), len(b), "same" if ok else "DIFFER"))
        if not ok:
            bad += 1
            for k in sorted(set(a) | set(b)):
                if a.get(k) != b.get(k):
                    print("  %s: lifthull %s, qvoronoi %s" % (k, a.get(k), b.get(k)))
                    break
        ridges = set(b)
        ok = regions(lh, path) == regions(qv, path)
        print("%s o: regions %s" % (path, "same" if ok else "DIFFER"))
        bad += not ok
        for opt in ("Fi", "Fo"):
            a, b = planes(lh, path, opt), planes(qv, path, opt)
            b = {k: v for k, v in b.items() if k in ridges}
            ok = a.keys() == b.keys() and all(
                max(abs(x - y) for x, y in zip(a[k], b[k])) <= 1e-12 * max(1.0, max(abs(x) for x in b[k]))
                for k in a)
            print("%s %s: %d ridges, qvoronoi %d: %s" % (path, opt, len(a), len(b), "same" if ok else "DIFFER"))
            bad += not ok
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
