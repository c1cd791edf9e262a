"""Exact 2D predicates on doubles for compare_mesh2.py: a floating-point filter, then Fractions."""

from fractions import Fraction


EPS = 2.0 ** -53


ORIENT_BOUND = (3.0 + 16.0 * EPS) * EPS


# ---- exact predicates on doubles (float filter, then Fractions) ------------------------------

def orient(a, b, c):
    """Sign of the orientation of (a, b, c): +1 counterclockwise, -1 clockwise, 0 collinear."""
    l = (a[0] - c[0]) * (b[1] - c[1])
    r = (a[1] - c[1]) * (b[0] - c[0])
    d = l - r
    bound = ORIENT_BOUND * (abs(l) + abs(r))
    if d > bound:
        return 1
    if -d > bound:
        return -1
    F = Fraction
    e = (F(a[0]) - F(c[0])) * (F(b[1]) - F(c[1])) - (F(a[1]) - F(c[1])) * (F(b[0]) - F(c[0]))
    return (e > 0) - (e < 0)


def dot_sign(a, b, c):
    """Sign of (b - a) . (c - a), exactly."""
    F = Fraction
    e = (F(b[0]) - F(a[0])) * (F(c[0]) - F(a[0])) + (F(b[1]) - F(a[1])) * (F(c[1]) - F(a[1]))
    return (e > 0) - (e < 0)


def incircle(a, b, c, d):
    """Sign of the in-circle determinant of d against the circle through a, b, c (exact)."""
    F = Fraction
    rows = []
    for p in (a, b, c):
        x, y = F(p[0]) - F(d[0]), F(p[1]) - F(d[1])
        rows.append((x, y, x * x + y * y))
    (a1, a2, a3), (b1, b2, b3), (c1, c2, c3) = rows
    e = a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)
    return (e > 0) - (e < 0)


def cocircular_ties(tris, other_edges):
    """The edges of `tris` missing from `other_edges`: how many, and how many of them are interior
    edges whose two triangles have four exactly cocircular corners (a Delaunay tie: either
    diagonal is a valid choice)."""
    around = {}
    for t in tris:
        for i in range(3):
            u, v = t[i], t[(i + 1) % 3]
            around.setdefault((u, v) if u < v else (v, u), []).append(t[(i + 2) % 3])
    diff = [e for e in around if e not in other_edges]
    ties = 0
    for e in diff:
        apexes = around[e]
        if len(apexes) == 2 and incircle(e[0], e[1], apexes[0], apexes[1]) == 0:
            ties += 1
    return len(diff), ties


def on_segment_open(p, a, b):
    """p lies strictly between a and b on segment ab."""
    if p == a or p == b or orient(a, b, p) != 0:
        return False
    return dot_sign(a, b, p) > 0 and dot_sign(b, a, p) > 0
