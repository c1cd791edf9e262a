"""Exact geometry on integer coordinates for compare_locate.py (and qvoronoi_compare.py's
affine_rank): orientation and in-sphere signs, and Tri, a Delaunay triangulation's simplices
with containment, hull facets and the minimal face of the Delaunay subdivision holding a point."""

from fractions import Fraction

from exact_check import det_int as det  # Bareiss, exact


def sgn(x):
    return (x > 0) - (x < 0)


def orient(pts):
    """Sign-carrying determinant of (p1 - p0, ..., pd - p0) for d + 1 integer points."""
    a = pts[0]
    if len(a) == 2:
        b, c = pts[1], pts[2]
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    b, c, e = pts[1], pts[2], pts[3]
    b0, b1, b2 = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    c0, c1, c2 = c[0] - a[0], c[1] - a[1], c[2] - a[2]
    e0, e1, e2 = e[0] - a[0], e[1] - a[1], e[2] - a[2]
    return b0 * (c1 * e2 - c2 * e1) - b1 * (c0 * e2 - c2 * e0) + b2 * (c0 * e1 - c1 * e0)


def insphere_zero(simplex_pts, q):
    """True iff q is exactly on the circumsphere of the simplex."""
    b = simplex_pts[0]
    rows = []
    for p in list(simplex_pts[1:]) + [q]:
        r = [p[j] - b[j] for j in range(len(b))]
        rows.append(r + [sum(x * x for x in r)])
    return det(rows) == 0


def affine_rank(pts):
    if not pts:
        return -1
    rows = [[Fraction(p[j] - pts[0][j]) for j in range(len(p))] for p in pts[1:]]
    rank, col, d = 0, 0, len(pts[0])
    while rank < len(rows) and col < d:
        piv = next((r for r in range(rank, len(rows)) if rows[r][col] != 0), None)
        if piv is None:
            col += 1
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        for r in range(len(rows)):
            if r != rank and rows[r][col] != 0:
                f = rows[r][col] / rows[rank][col]
                rows[r] = [x - f * y for x, y in zip(rows[r], rows[rank])]
        rank += 1
        col += 1
    return rank


def dist2(a, b):
    return sum((x - y) * (x - y) for x, y in zip(a, b))


class Tri:
    """A simplex list over integer points, with exact containment, facets and Delaunay cells."""

    def __init__(self, d, P, simplices):
        self.d, self.P, self.S = d, P, [tuple(s) for s in simplices]
        self.sign = [sgn(orient([P[v] for v in s])) for s in self.S]
        self.box = []
        for s in self.S:
            cs = [P[v] for v in s]
            self.box.append(([min(c[j] for c in cs) for j in range(d)],
                             [max(c[j] for c in cs) for j in range(d)]))
        self.facets = {}
        for si, s in enumerate(self.S):
            for i in range(d + 1):
                self.facets.setdefault(tuple(sorted(s[:i] + s[i + 1:])), []).append((si, s[i]))
        # The Delaunay cells: union-find across exactly cospherical interior facets.
        parent = list(range(len(self.S)))

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        self.ties = 0
        for f, pair in self.facets.items():
            if len(pair) == 2:
                (a, _), (b, ob) = pair
                if insphere_zero([P[v] for v in self.S[a]], P[ob]):
                    self.ties += 1
                    parent[find(a)] = find(b)
        self.cell_of = [find(i) for i in range(len(self.S))]
        self.members = {}
        for i, c in enumerate(self.cell_of):
            self.members.setdefault(c, []).append(i)
        self._cell_bfacets = {}

    def hull_facet(self, f):
        return len(self.facets.get(tuple(sorted(f)), ())) == 1

    def orients(self, si, q):
        """Signs (relative to the simplex's orientation) of q against each facet of si."""
        s, P = self.S[si], self.P
        o = self.sign[si]
        out = []
        for i in range(self.d + 1):
            pts = [P[v] for v in s]
            pts[i] = q
            out.append(sgn(orient(pts)) * o)
        return out

    def raw_orients(self, si, q):
        s, P = self.S[si], self.P
        out = []
        for i in range(self.d + 1):
            pts = [P[v] for v in s]
            pts[i] = q
            out.append(orient(pts))
        return out

    def containing(self, q):
        res = []
        for si, (lo, hi) in enumerate(self.box):
            if all(lo[j] <= q[j] <= hi[j] for j in range(self.d)):
                if min(self.orients(si, q)) >= 0:
                    res.append(si)
        return res

    def cell_boundary(self, c):
        if c not in self._cell_bfacets:
            count = {}
            for si in self.members[c]:
                s = self.S[si]
                for i in range(self.d + 1):
                    f = tuple(sorted(s[:i] + s[i + 1:]))
                    count[f] = count.get(f, 0) + 1
            self._cell_bfacets[c] = [f for f, k in count.items() if k == 1]
        return self._cell_bfacets[c]

    def minimal_face(self, si, q):
        """The face F of the Delaunay subdivision with q in its relative interior (q in simplex
        si): (sorted vertex list, dimension, is_simplex)."""
        c = self.cell_of[si]
        P = self.P
        if len(self.members[c]) == 1:
            o = self.orients(si, q)
            fv = sorted(v for v, x in zip(self.S[si], o) if x != 0)
            return fv, len(fv) - 1, True
        verts = sorted({v for m in self.members[c] for v in self.S[m]})
        on = [f for f in self.cell_boundary(c) if orient([P[v] for v in f] + [q]) == 0]
        fv = [v for v in verts if all(orient([P[u] for u in f] + [P[v]]) == 0 for f in on)]
        k = affine_rank([P[v] for v in fv])
        return fv, k, len(fv) == k + 1
