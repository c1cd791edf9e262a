#!/usr/bin/env python3
"""check_voronoi.py REF OUT: the Voronoi diagram OUT.v.node + OUT.v.edge written by
`lifthull triangle -v` against Triangle's REF.v.node + REF.v.edge (drufat/triangle's
reference outputs). Voronoi vertices are circumcentres, constructions that differ in
the last bits (and in order) between programs, so each of OUT's is matched to the
nearest of REF's (within 1e-8 of REF's extent); then the headers, the multiset of
finite edges (pairs of matched vertices) and of rays (matched vertex, direction
normalised) must agree. Prints "ok" or the differences, exits 1 on any.
"""
import math
import sys

from trifiles import tokens


def read(base):
    node = tokens(base + '.v.node')
    n = int(node[0][0])
    pts = [(float(l[1]), float(l[2])) for l in node[1:1 + n]]
    first = int(node[1][0]) if n else 0
    edge = tokens(base + '.v.edge')
    edges = []
    for l in edge[1:1 + int(edge[0][0])]:
        a, b = int(l[1]) - first, int(l[2])
        if b == -1:
            edges.append((a, None, (float(l[3]), float(l[4]))))
        else:
            edges.append((a, b - first, None))
    return node[0][:4], edge[0][:2], pts, edges


def main():
    ref, out = sys.argv[1:3]
    rnh, reh, rpts, redges = read(ref)
    onh, oeh, opts, oedges = read(out)
    diffs = []
    if rnh != onh or reh != oeh:
        diffs.append('headers %s / %s, Triangle %s / %s' % (' '.join(onh), ' '.join(oeh), ' '.join(rnh), ' '.join(reh)))
    xs, ys = [p[0] for p in rpts], [p[1] for p in rpts]
    tol = 1e-8 * max(max(xs) - min(xs), max(ys) - min(ys), 1e-300)
    snap = []
    for p in opts:
        q = min(rpts, key=lambda r: math.dist(p, r))
        if math.dist(p, q) > tol:
            diffs.append('Voronoi vertex (%.17g, %.17g) is none of Triangle\'s (nearest %.3g away)' % (p[0], p[1], math.dist(p, q)))
        snap.append(q)
    if sorted(snap) != sorted(rpts):
        diffs.append('the Voronoi vertices are not Triangle\'s (as a multiset)')

    def key(e, at):
        a, b, d = e
        if d is None:
            return ('edge',) + tuple(sorted((at[a], at[b])))
        s = math.hypot(*d)
        return ('ray', at[a], (round(d[0] / s, 9), round(d[1] / s, 9)))

    mine = sorted(key(e, snap) for e in oedges)
    theirs = sorted(key(e, rpts) for e in redges)
    if mine != theirs:
        extra = [k for k in mine if k not in theirs][:3]
        missing = [k for k in theirs if k not in mine][:3]
        diffs.append('other Voronoi edges: %s; Triangle has %s' % (extra, missing))
    for d in diffs[:10]:
        print(d)
    if not diffs:
        print('ok')
    return 1 if diffs else 0


if __name__ == '__main__':
    sys.exit(main())
