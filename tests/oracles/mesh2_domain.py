"""The meshing domain of a PSLG for compare_mesh2.py: segments split at input vertices,
face cycles of the segment graph, and the domain's area by Triangle's rule or the even-odd rule."""

from fractions import Fraction

from mesh2_exact import on_segment_open, orient
from mesh2_input import InputError, Pslg


# ---- the planar graph of the segments, its face cycles, the domain's area ------------------

def split_segments(g):
    """Unique vertices (exact coordinates) and the segments split at every vertex on them."""
    coords = sorted(set(g.pts))
    edges = set()
    for a, b in g.segs:
        p, q = g.pts[a], g.pts[b]
        lox, hix = min(p[0], q[0]), max(p[0], q[0])
        loy, hiy = min(p[1], q[1]), max(p[1], q[1])
        on = [p, q]
        for c in coords:
            if lox <= c[0] <= hix and loy <= c[1] <= hiy and on_segment_open(c, p, q):
                on.append(c)
        d = (q[0] - p[0], q[1] - p[1])
        # sort along the segment: exact, by comparing projections (collinear points)
        on.sort(key=lambda c: (Fraction(c[0]) - Fraction(p[0])) * Fraction(d[0])
                + (Fraction(c[1]) - Fraction(p[1])) * Fraction(d[1]))
        for u, v in zip(on, on[1:]):
            edges.add((u, v) if u < v else (v, u))
    return coords, edges


def angle_key(d):
    """An exact sort key for the direction d (counterclockwise from the +x axis)."""
    x, y = d
    half = 0 if (y > 0 or (y == 0 and x > 0)) else 1
    return (half, Fraction(-x) / Fraction(abs(x) + abs(y)) if half == 0 else Fraction(x) / Fraction(abs(x) + abs(y)))


def face_cycles(edges):
    """The face cycles (lists of points, face on the left) of the planar graph, and the cycle
    of each half-edge (u, v)."""
    out = {}
    for u, v in edges:
        out.setdefault(u, []).append(v)
        out.setdefault(v, []).append(u)
    pos = {}
    for u, nbrs in out.items():
        nbrs.sort(key=lambda w: angle_key((w[0] - u[0], w[1] - u[1])))
        for i, w in enumerate(nbrs):
            pos[(u, w)] = i
    used = {}
    cycles = []
    for u, v in edges:
        for h in ((u, v), (v, u)):
            if h in used:
                continue
            cyc = []
            a, b = h
            while (a, b) not in used:
                used[(a, b)] = len(cycles)
                cyc.append(a)
                nb = out[b]
                i = pos[(b, a)]
                a, b = b, nb[i - 1]       # the first edge clockwise from b->a
            cycles.append(cyc)
    return cycles, used


def shoelace(cyc):
    F = Fraction
    s = F(0)
    n = len(cyc)
    for i in range(n):
        (x0, y0), (x1, y1) = cyc[i], cyc[(i + 1) % n]
        s += F(x0) * F(y1) - F(x1) * F(y0)
    return s / 2


def winding(cyc, p):
    """Winding number of the closed walk cyc around p (p not on it)."""
    w = 0
    n = len(cyc)
    for i in range(n):
        a, b = cyc[i], cyc[(i + 1) % n]
        if a[1] <= p[1]:
            if b[1] > p[1] and orient(a, b, p) > 0:
                w += 1
        elif b[1] <= p[1] and orient(a, b, p) < 0:
            w -= 1
    return w


def on_walk(cyc, p):
    n = len(cyc)
    return any(p == cyc[i] or on_segment_open(p, cyc[i], cyc[(i + 1) % n]) for i in range(n))


def convex_hull(pts):
    """Indices of the convex hull's corners, counterclockwise (monotone chain, exact)."""
    order = sorted(range(len(pts)), key=lambda i: pts[i])
    hull = []
    for seq in (order, order[::-1]):
        part = []
        for i in seq:
            while len(part) >= 2 and orient(pts[part[-2]], pts[part[-1]], pts[i]) <= 0:
                part.pop()
            part.append(i)
        hull.extend(part[:-1])
    return hull


def domain_triangle_rule(g, convex=False):
    """Triangle's domain: the bounded faces of the segment arrangement less the faces holding a
    hole point (with convex, Triangle's -c, the convex hull's edges count as segments).
    Returns its area, the number of faces holed, and the pieces of the input segments (split
    at the input vertices on them) that border it — the others lie in holes or outside, where
    Triangle removes them."""
    _, pieces = split_segments(g)
    if convex:
        h = convex_hull(g.pts)
        g2 = Pslg()
        g2.pts, g2.holes = g.pts, g.holes
        g2.segs = list(g.segs) + [(h[i], h[(i + 1) % len(h)]) for i in range(len(h)) if len(h) >= 3]
        g = g2
    _, edges = split_segments(g)
    if not edges:
        return Fraction(0), 0, set()
    cycles, cycle_of = face_cycles(edges)
    areas = [shoelace(c) for c in cycles]
    outer = [i for i, a in enumerate(areas) if a > 0]      # a bounded face's outer boundary
    inner = [i for i, a in enumerate(areas) if a <= 0]     # a component's outer boundary
    face_area = {i: areas[i] for i in outer}
    face = {i: i for i in outer}                           # cycle -> its face (None: unbounded)
    # each component sits in the innermost bounded face (of another component) around it
    for j in inner:
        p = cycles[j][0]
        best = None
        for i in outer:
            if p in cycles[i] or on_walk(cycles[i], p):
                continue
            if winding(cycles[i], p) != 0 and (best is None or areas[i] < areas[best]):
                best = i
        face[j] = best
        if best is not None:
            face_area[best] += areas[j]
    holed = set()
    for h in g.holes:
        best = None
        for i in outer:
            if on_walk(cycles[i], h):
                best = None
                break
            if winding(cycles[i], h) != 0 and (best is None or areas[i] < areas[best]):
                best = i
        if best is not None:
            holed.add(best)
    inside = lambda c: face[c] is not None and face[c] not in holed  # noqa: E731
    bordering = {e for e in pieces if inside(cycle_of[e]) or inside(cycle_of[(e[1], e[0])])}
    return sum(a for i, a in face_area.items() if i not in holed), len(holed), bordering


def domain_area_even_odd(g):
    """Each ring's area with the sign of its depth (the number of other rings around it)."""
    rings = g.rings
    total = Fraction(0)
    for k, r in enumerate(rings):
        a = abs(shoelace(r))
        # a point of r on no other ring: a vertex, else an edge midpoint
        cands = list(r) + [((r[i][0] + r[(i + 1) % len(r)][0]) / 2, (r[i][1] + r[(i + 1) % len(r)][1]) / 2)
                           for i in range(len(r))]
        depth = None
        for p in cands:
            if any(on_walk(s, p) for j, s in enumerate(rings) if j != k):
                continue
            depth = sum(1 for j, s in enumerate(rings) if j != k and winding(s, p) % 2 != 0)
            break
        if depth is None:
            raise InputError('a ring lies on the others everywhere; no even-odd area')
        total += a if depth % 2 == 0 else -a
    return total
