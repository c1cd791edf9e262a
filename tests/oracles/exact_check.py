#!/usr/bin/env python3
"""Exact, oracle-free check of a Delaunay simplex list (a diagnostic, not a CTest test).

  exact_check.py POINTS SIMPLICES [--limit K]

POINTS is a Qhull-format point file, SIMPLICES a Qhull `i`-format simplex list for it (what
`lifthull delaunay`, oracle_cgal_delaunay or `qdelaunay Qt i` print). With exact integer
arithmetic (every double is a dyadic rational; the coordinates are scaled by a common power of
two), it checks:

  - every simplex has d+1 distinct indices in range and nonzero volume;
  - every facet (d-subset) belongs to at most two simplices;
  - every interior facet (shared by two simplices) is locally Delaunay: the vertex of one
    simplex opposite the facet is not inside the circumsphere of the other. Exact ties
    (d+2 cospherical points) are counted apart: there the triangulation is not unique;
  - every boundary facet (in one simplex) is a convex hull facet: no input point lies strictly
    on its outer side (a missing simplex leaves a boundary facet that fails this).

The local test: for simplex v0..vd and the opposite vertex q, with rows (p - v0, |p - v0|^2)
for p = v1..vd, q, the determinant equals (height of lifted q above the hyperplane through the
lifted simplex) * det(v1 - v0, ..., vd - v0), so q is outside iff the determinant and the
simplex orientation have the same sign.

Together these make the simplices the Delaunay triangulation, except for coverings that wrap
around more than once, which they do not exclude (compare the simplex count with an oracle).
Pure Python: about 6,000 interior facets per second in 8D (30 points), more in lower
dimensions; --limit K checks at most K interior and K boundary facets. Exit 0 if no violation, 1 if some, 2 on bad input.
"""

import sys
from collections import defaultdict
from fractions import Fraction

sys.path.insert(0, __import__("os").path.dirname(__file__))
import canon  # noqa: E402  (the shared Qhull-format and `i`-format readers)


def det_int(m):
    """Determinant of a square integer matrix (Bareiss, fraction-free)."""
    m = [row[:] for row in m]
    k = len(m)
    if k == 0:
        return 1
    sign, prev = 1, 1
    for i in range(k - 1):
        if m[i][i] == 0:
            for r in range(i + 1, k):
                if m[r][i] != 0:
                    m[i], m[r] = m[r], m[i]
                    sign = -sign
                    break
            else:
                return 0
        for r in range(i + 1, k):
            for c in range(i + 1, k):
                m[r][c] = (m[r][c] * m[i][i] - m[r][i] * m[i][c]) // prev
        prev = m[i][i]
    return sign * m[k - 1][k - 1]


def sgn(x):
    return (x > 0) - (x < 0)


def parse_args(argv):
    """-> (POINTS, SIMPLICES, limit or None), or None on bad usage."""
    args = argv[1:]
    limit = None
    if "--limit" in args:
        i = args.index("--limit")
        limit = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        return None
    return args[0], args[1], limit


def scaled_points(d, n, coords):
    """The points as integers: every double is a dyadic rational, scaled by the largest
    denominator (all powers of two: the largest is a common multiple)."""
    fr = [Fraction(x) for x in coords]
    den = 1
    for f in fr:
        den = max(den, f.denominator)
    return [[int(f * den) for f in fr[i * d:(i + 1) * d]] for i in range(n)]


class Orientation:
    """The sign of det(v1 - v0, ..., vd - v0) of a simplex, cached."""

    def __init__(self, pts, d):
        self.pts, self.d, self.cache = pts, d, {}

    def __call__(self, s):
        if s not in self.cache:
            pts, d = self.pts, self.d
            b = pts[s[0]]
            self.cache[s] = sgn(det_int([[pts[v][j] - b[j] for j in range(d)] for v in s[1:]]))
        return self.cache[s]


def facets_of(simplices, d, orientation):
    """-> (facet (sorted d-subset) -> [(simplex, opposite vertex)], flat or over-shared count);
    prints the first ten of each."""
    problems = 0
    facets = defaultdict(list)
    for s in simplices:
        s = tuple(s)
        if orientation(s) == 0:
            problems += 1
            if problems <= 10:
                print("flat simplex %s" % " ".join(map(str, s)))
        for i in range(d + 1):
            facets[tuple(sorted(s[:i] + s[i + 1:]))].append((s, s[i]))
    over = [f for f, v in facets.items() if len(v) > 2]
    for f in over[:10]:
        print("facet %s in %d simplices" % (" ".join(map(str, f)), len(facets[f])))
    return facets, problems + len(over)


def check_interior(facets, pts, d, orientation, limit):
    """Every interior facet locally Delaunay -> (checked, cospherical ties, violations)."""
    checked = ties = violations = 0
    for f, pair in facets.items():
        if len(pair) != 2:
            continue
        if limit is not None and checked >= limit:
            break
        checked += 1
        (s, _), (_, q) = pair
        b = pts[s[0]]
        rows = []
        for v in list(s[1:]) + [q]:
            r = [pts[v][j] - b[j] for j in range(d)]
            rows.append(r + [sum(x * x for x in r)])
        side = sgn(det_int(rows)) * orientation(s)
        if side == 0:
            ties += 1
        elif side < 0:
            violations += 1
            if violations <= 10:
                print("not locally Delaunay: facet %s (vertex %d inside the sphere of %s)"
                      % (" ".join(map(str, f)), q, " ".join(map(str, s))))
    return checked, ties, violations


def check_boundary(facets, pts, d, limit):
    """Every boundary facet a hull facet: the normal by cofactors, then one integer dot
    product per point -> (checked, facets with a point beyond)."""
    n = len(pts)
    bchecked = outside = 0
    for f, pair in facets.items():
        if len(pair) != 1:
            continue
        if limit is not None and bchecked >= limit:
            break
        bchecked += 1
        _, o = pair[0]
        b = pts[f[0]]
        rows = [[pts[v][j] - b[j] for j in range(d)] for v in f[1:]]
        normal = []
        for j in range(d):
            minor = [r[:j] + r[j + 1:] for r in rows]
            normal.append((-1) ** j * (det_int(minor) if minor else 1))

        def side(p):
            return sgn(sum(normal[j] * (p[j] - b[j]) for j in range(d)))

        inner = side(pts[o])
        for i in range(n):
            if side(pts[i]) == -inner:
                outside += 1
                if outside <= 10:
                    print("boundary facet %s is not on the hull: point %d is beyond it"
                          % (" ".join(map(str, f)), i))
                break
    return bchecked, outside


def main(argv):
    parsed = parse_args(argv)
    if parsed is None:
        sys.stderr.write(__doc__)
        return 2
    points, simplex_file, limit = parsed
    try:
        d, n, coords = canon.read_qhull_points(points)
        simplices = canon.read_i(simplex_file)
    except (canon.CanonError, OSError) as e:
        sys.stderr.write("exact_check.py: %s\n" % e)
        return 2
    pts = scaled_points(d, n, coords)
    for s in simplices:
        if len(s) != d + 1 or len(set(s)) != d + 1 or min(s) < 0 or max(s) >= n:
            print("bad simplex %s" % " ".join(map(str, s)))
            return 1
    orientation = Orientation(pts, d)
    facets, problems = facets_of(simplices, d, orientation)
    checked, ties, violations = check_interior(facets, pts, d, orientation, limit)
    bchecked, outside = check_boundary(facets, pts, d, limit)
    problems += violations + outside
    stopped = limit is not None and (checked >= limit or bchecked >= limit)
    print("exact_check: d=%d n=%d simplices=%d checked %d interior facets: %d not locally "
          "Delaunay, %d cospherical ties; %d boundary facets: %d not on the hull; "
          "%d flat or over-shared%s -> %s"
          % (d, n, len(simplices), checked, violations, ties, bchecked, outside,
             problems - violations - outside, " (stopped at --limit)" if stopped else "",
             "OK" if problems == 0 else "FAIL"))
    return 0 if problems == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
