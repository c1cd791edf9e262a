#!/usr/bin/env python3
"""check_regions.py POLY OUT [--areas]: Triangle's regional attributes and area bounds
in the mesh OUT.node + OUT.ele, checked against the input graph POLY (a .poly with
its vertices and a regions section).

Triangle's rule: a region's attribute (and, with -a, its area bound) spreads from
its point over every triangle not separated from it by a segment; a later region
overrides an earlier one in the same face; a triangle no region reaches has
attribute 0 and no bound. The faces are found here from the INPUT segments, not
from the mesh's own subsegments: the mesh's triangles are flooded across every edge
that does not lie along an input segment (an edge lies along one when both its ends
are within 2^-40 of its length from it: Steiner points on segments are rounded
within an ulp), starting from the triangle holding each region point (located with
exact rational orientation tests). Checked: every triangle's attribute equals its
face's region attribute (when the .ele has attributes); with --areas, no triangle's
area exceeds its face's bound. Prints one line "triangles T mismatched M over_area A"
and exits 1 when M or A > 0.
"""
import sys
from fractions import Fraction

from trifiles import tokens


def read_poly(path):
    lines = tokens(path)
    n, _, na, nm = (int(x) for x in lines[0][:4])
    xy = [(float(l[1]), float(l[2])) for l in lines[1:1 + n]]
    first = int(lines[1][0]) if n else 0
    i = 1 + n
    ns = int(lines[i][0])
    segs = [(int(l[1]) - first, int(l[2]) - first) for l in lines[i + 1:i + 1 + ns]]
    i += 1 + ns
    nh = int(lines[i][0])
    i += 1 + nh
    regions = []
    if i < len(lines):
        nr = int(lines[i][0])
        for l in lines[i + 1:i + 1 + nr]:
            x, y, a = float(l[1]), float(l[2]), float(l[3])
            area = float(l[4]) if len(l) > 4 else a
            regions.append((x, y, a, area))
    return xy, segs, regions


def read_mesh(base):
    node = tokens(base + '.node')
    n = int(node[0][0])
    first = int(node[1][0])
    xy = [(float(l[1]), float(l[2])) for l in node[1:1 + n]]
    ele = tokens(base + '.ele')
    nt, _, na = (int(x) for x in ele[0][:3])
    tris, attr = [], []
    for l in ele[1:1 + nt]:
        tris.append(tuple(int(v) - first for v in l[1:4]))
        attr.append(float(l[4]) if na else None)
    return xy, tris, attr


def orient(a, b, c):
    """Exact sign of the orientation of a, b, c (doubles as rationals)."""
    ax, ay, bx, by, cx, cy = (Fraction(v) for v in (*a, *b, *c))
    d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (d > 0) - (d < 0)


def near_segment(p, a, b):
    """Whether p lies on segment a-b within 2^-40 of its length."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    l2 = dx * dx + dy * dy
    if l2 == 0:
        return False
    f = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2
    if f < -2.0 ** -40 or f > 1 + 2.0 ** -40:
        return False
    cr = dx * (p[1] - a[1]) - dy * (p[0] - a[0])
    return cr * cr <= 2.0 ** -80 * l2 * l2


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    areas = '--areas' in sys.argv
    pxy, segs, regions = read_poly(args[0])
    mxy, tris, attr = read_mesh(args[1])
    # candidate segments per mesh vertex, then the edges along a segment
    on = [set() for _ in mxy]
    for s, (a, b) in enumerate(segs):
        pa, pb = pxy[a], pxy[b]
        lo = (min(pa[0], pb[0]), min(pa[1], pb[1]))
        hi = (max(pa[0], pb[0]), max(pa[1], pb[1]))
        tol = 2.0 ** -38 * max(hi[0] - lo[0], hi[1] - lo[1])
        for v, p in enumerate(mxy):
            if lo[0] - tol <= p[0] <= hi[0] + tol and lo[1] - tol <= p[1] <= hi[1] + tol and near_segment(p, pa, pb):
                on[v].add(s)
    edges = {}
    for t, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            edges.setdefault((min(u, v), max(u, v)), []).append(t)
    nbrs = [[] for _ in tris]
    for (u, v), ts in edges.items():
        if len(ts) == 2 and not (on[u] & on[v]):
            nbrs[ts[0]].append(ts[1])
            nbrs[ts[1]].append(ts[0])
    want_attr = [0.0] * len(tris)
    want_area = [-1.0] * len(tris)
    for (x, y, a, area) in regions:
        q = (x, y)
        start = next((t for t, (i, j, k) in enumerate(tris)
                      if orient(mxy[i], mxy[j], q) >= 0 and orient(mxy[j], mxy[k], q) >= 0
                      and orient(mxy[k], mxy[i], q) >= 0), None)
        if start is None:
            continue
        seen = {start}
        stack = [start]
        while stack:
            t = stack.pop()
            want_attr[t], want_area[t] = a, area
            for n in nbrs[t]:
                if n not in seen:
                    seen.add(n)
                    stack.append(n)
    mismatched = sum(1 for t in range(len(tris)) if attr[t] is not None and attr[t] != want_attr[t])
    over = 0
    if areas:
        for t, (i, j, k) in enumerate(tris):
            a, b, c = mxy[i], mxy[j], mxy[k]
            ar = abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2
            over += want_area[t] > 0 and ar > want_area[t] * (1 + 1e-12)
    print('triangles %d mismatched %d over_area %d' % (len(tris), mismatched, over))
    return 1 if mismatched or over else 0


if __name__ == '__main__':
    sys.exit(main())
