#!/usr/bin/env python3
"""Writes the constrained-Delaunay benchmark input: a Triangle .poly of random sites and random
non-crossing short segments in the unit square.

  gen_cdt_poly.py [--sites N] [--segments M] [--seed S] OUT.poly

Vertices 1-4 are the corners of the unit square and segments 1-4 its sides, so that the whole
square is the domain (Triangle's -p removes everything a closed boundary does not enclose).
Then N sites, uniform in the open square (random.Random(S), each coordinate a multiple of
2^-53, written with repr: read back as the same doubles).

The M segments cannot cross or touch, by construction: the square is cut into G x G cells
(G = floor(sqrt(N)), about one site a cell; a site's cell is (int(x*G), int(y*G)) in floating
point, which is monotone in x and y, so each cell is a product of two half-open intervals: a
convex set, disjoint from the others); M cells holding at least two sites are drawn at random,
and each gets one segment joining two of its sites. A segment lies inside its (convex) cell,
so segments of different cells never meet; a cell has one segment. A segment is dropped (and another cell drawn) if a third site of its cell lies
exactly on it (exact rational test), so no segment passes through a site. The segments are
short (about 1/G) and spread uniformly; their endpoints are sites, so the CDT has no Steiner
points. N = 10^6, M = 10^4 is the issue's benchmark (about 40 MB, a few seconds).
"""

import argparse
import random
import sys
from fractions import Fraction


def collinear_between(p, a, b):
    F = Fraction
    if (F(b[0]) - F(a[0])) * (F(p[1]) - F(a[1])) != (F(b[1]) - F(a[1])) * (F(p[0]) - F(a[0])):
        return False
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sites', type=int, default=1_000_000)
    ap.add_argument('--segments', type=int, default=10_000)
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('out')
    a = ap.parse_args()
    rng = random.Random(a.seed)
    n, m = a.sites, a.segments
    pts = []
    while len(pts) < n:
        x, y = rng.random(), rng.random()
        if x > 0.0 and y > 0.0:
            pts.append((x, y))
    g = max(1, int(n ** 0.5))
    cells = {}
    for i, (x, y) in enumerate(pts):
        cells.setdefault((min(int(x * g), g - 1), min(int(y * g), g - 1)), []).append(i)
    candidates = sorted(c for c, ids in cells.items() if len(ids) >= 2)
    rng.shuffle(candidates)
    segs = []
    for c in candidates:
        if len(segs) == m:
            break
        ids = cells[c]
        i, j = ids[0], ids[1]
        if any(collinear_between(pts[k], pts[i], pts[j]) for k in ids[2:]):
            continue
        segs.append((i, j))
    if len(segs) < m:
        sys.exit(f'gen_cdt_poly: only {len(segs)} cells can hold a segment; use fewer segments')
    with open(a.out, 'w') as f:
        w = f.write
        w(f'# gen_cdt_poly.py --sites {n} --segments {m} --seed {a.seed}\n')
        w(f'{n + 4} 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n')
        for k, (x, y) in enumerate(pts):
            w(f'{k + 5} {x!r} {y!r}\n')
        w(f'{m + 4} 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n')
        for k, (i, j) in enumerate(segs):
            w(f'{k + 5} {i + 5} {j + 5}\n')
        w('0\n')


if __name__ == '__main__':
    main()
