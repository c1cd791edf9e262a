"""Exact arithmetic on qhull_golden.py's point sets: rank, simplex volumes, hull planes,
circumcentres, and the exact validity of a hull's facets."""

from collections import Counter
from fractions import Fraction

from exact_check import det_int  # Bareiss, exact
from golden_parse import Fail


def rank_int(rows):
    """Rank of an integer matrix (fraction-free elimination)."""
    m = [r[:] for r in rows if any(r)]
    if not m:
        return 0
    cols = len(m[0])
    rank = 0
    for c in range(cols):
        piv = next((r for r in range(rank, len(m)) if m[r][c] != 0), None)
        if piv is None:
            continue
        m[rank], m[piv] = m[piv], m[rank]
        p = m[rank]
        for r in range(rank + 1, len(m)):
            if m[r][c]:
                f = m[r][c]
                m[r] = [x * p[c] - y * f for x, y in zip(m[r], p)]
        rank += 1
        if rank == len(m):
            break
    return rank


class Exact:
    """The points as integers (a common power-of-two scale)."""

    def __init__(self, pts):
        fr = [[Fraction(x) for x in p] for p in pts]
        self.den = max([1] + [f.denominator for p in fr for f in p])
        self.ip = [[int(f * self.den) for f in p] for p in fr]
        self.d = len(pts[0])
        self.pts = pts
        self.extent = max([1e-300] + [abs(x) for p in pts for x in p])
        lo = [min(p[j] for p in pts) for j in range(self.d)]
        hi = [max(p[j] for p in pts) for j in range(self.d)]
        self.diameter = max(1e-300, sum((h - l) ** 2 for h, l in zip(hi, lo)) ** 0.5)
        self._cc = {}

    def affine_rank(self):
        b = self.ip[0]
        return rank_int([[x - y for x, y in zip(p, b)] for p in self.ip[1:]])

    def has_duplicates(self):
        return len(set(map(tuple, self.ip))) != len(self.ip)

    def vol(self, s):
        b = self.ip[s[0]]
        return det_int([[self.ip[v][j] - b[j] for j in range(self.d)] for v in s[1:]])

    def condition(self, s):
        """R * max(1, maxedge^d / |det|): the error scale of a floating-point solve for the
        circumcentre relative to the first vertex (R: its distance from that vertex)."""
        c = self.circumcenter(s)
        v0 = self.pts[s[0]] if isinstance(s, (list, tuple)) else self.pts[min(s)]
        r = sum((a - b) ** 2 for a, b in zip(c, v0)) ** 0.5
        s = sorted(s)
        e = max(sum((a - b) ** 2 for a, b in zip(self.pts[u], self.pts[v])) ** 0.5
                for u in s for v in s if u < v)
        vol = abs(self.vol(s)) / float(self.den) ** self.d
        return r * max(1.0, e ** self.d / vol if vol else 1e300)

    def plane(self, f):
        """The exact hull plane of facet f (d vertices), outward (the points on its <= 0 side),
        normalized in floating point -> (normal + [offset], condition)."""
        d = self.d
        b = self.ip[f[0]]
        e = [[self.ip[v][j] - b[j] for j in range(d)] for v in f[1:]]
        nrm = [(-1) ** j * det_int([r[:j] + r[j + 1:] for r in e]) for j in range(d)]
        off = -sum(x * y for x, y in zip(nrm, b))
        side = 0
        for p in self.ip:
            side = sum(x * y for x, y in zip(nrm, p)) + off
            if side:
                break
        if side > 0:
            nrm, off = [-x for x in nrm], -off
        length = float(sum(x * x for x in nrm)) ** 0.5
        fe = [[self.pts[v][j] - self.pts[f[0]][j] for j in range(d)] for v in f[1:]]
        emax = max([1e-300] + [sum(x * x for x in r) ** 0.5 for r in fe])
        cond = max(1.0, emax ** (d - 1) / (length / float(self.den) ** (d - 1)))
        return [x / length for x in nrm] + [off / length / self.den], cond

    def circumcenter(self, s):
        """Exact circumcentre of simplex s (sorted tuple) -> list of floats (correctly rounded)."""
        s = tuple(sorted(s))
        if s in self._cc:
            return self._cc[s]
        d = self.d
        b = self.ip[s[0]]
        a = [[self.ip[v][j] - b[j] for j in range(d)] for v in s[1:]]
        rhs = [sum(x * x for x in r) for r in a]
        den = 2 * det_int(a)
        c = []
        for j in range(d):
            m = [r[:j] + [rhs[i]] + r[j + 1:] for i, r in enumerate(a)]
            c.append(float(Fraction(det_int(m) + den * b[j], den * self.den)))
        self._cc[s] = c
        return c


def check_hull_exact(ex, rows):
    """Every point inside or on every facet's plane, d independent vertices a facet, every ridge
    in two facets. -> (sum over facets of |det(facet - p0)|) (d! times the volume)."""
    d = ex.d
    ridges = Counter()
    total = 0
    p0 = ex.ip[0]
    for f in rows:
        if len(f) != d or len(set(f)) != d:
            raise Fail("hull facet %s has not %d distinct vertices" % (f, d))
        b = ex.ip[f[0]]
        e = [[ex.ip[v][j] - b[j] for j in range(d)] for v in f[1:]]
        normal = [(-1) ** j * det_int([r[:j] + r[j + 1:] for r in e]) for j in range(d)]
        if not any(normal):
            raise Fail("hull facet %s: its vertices are affinely dependent" % f)
        sides = set()
        for p in ex.ip:
            s = sum(normal[j] * (p[j] - b[j]) for j in range(d))
            if s:
                sides.add(s > 0)
                if len(sides) == 2:
                    raise Fail("hull facet %s: input points on both sides of its plane" % f)
        total += abs(sum(normal[j] * (p0[j] - b[j]) for j in range(d)))
        for k in range(d):
            ridges[frozenset(f[:k] + f[k + 1:])] += 1
    bad = [r for r, c in ridges.items() if c != 2]
    if bad:
        raise Fail("hull ridge %s is in %d facets" % (sorted(bad[0]), ridges[bad[0]]))
    return total
