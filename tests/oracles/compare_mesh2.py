#!/usr/bin/env python3
"""Checks of 2D meshes (issue #7) against their input and against a reference mesh.

  compare_mesh2.py cdt     INPUT A B
  compare_mesh2.py quality INPUT A B [--angle 30] [--ratio 1.15]

INPUT is the PSLG: a Triangle .poly (with FILE.node beside it when the .poly lists no vertex;
segments; holes), a JSON ring file (earcut fixtures: [[[x,y],...], hole rings...], each ring
closed implicitly) or a CGAL .edg segment file. A and B are Triangle-format output sets,
given as the base name (A.node and A.ele; any numbering base, taken from the first vertex
number; vertices matched across sets by their exact coordinates, so Steiner points may be
numbered anyhow). A is the mesh under test, B the reference (Triangle, CGAL).

cdt: the two triangle sets are identical (each triangle as its set of three coordinate pairs).
  Lines: the counts, the triangles only in A / only in B (first few), the vertices used that are
  not input vertices (a CDT has none). Where they differ only by Delaunay ties — every edge of
  one that the other lacks is the diagonal of two of its triangles whose four corners are
  exactly cocircular — the check passes, saying so (not with --strict): with four cocircular
  points the CDT is not unique.

quality: for A (and, marked `ref`, for information, for B):
  angle    every triangle's smallest angle >= --angle, except the triangles with a corner at
           an input vertex where two input segments meet at less than --angle (listed), and
           those Triangle leaves by its shell rule (Miller, Pav, Walkington): the shortest edge
           joins points inside two segments with a common endpoint, equidistant from it
           within 0.1% (counted);
  segments every input segment is a union of edges of the mesh where it borders the domain
           (pieces inside holes or outside are gone, as in Triangle): each piece between input
           vertices walked from one end to the other along mesh edges whose far ends lie on it,
           exactly or within 8 ulp (Steiner points are rounded), decided in exact arithmetic
           on the doubles, strictly advancing, never past the end;
  holes    no triangle contains a hole point (exact point-in-triangle);
  area     the triangles' total area equals the domain's within 1e-9 relative. The domain
           is computed from INPUT alone: for a .poly by Triangle's rule (the bounded faces of
           the segment arrangement, less the faces that hold a hole point), from the face
           cycles of the planar graph of the segments (split at the input vertices on them);
           for rings and .edg by the even-odd rule (each ring's area with the sign of its
           nesting depth);
  count    triangles(A) / triangles(B) <= --ratio.
  With --convex the domain is Triangle's for -c: the convex hull's edges count as segments.
One summary line a check. Exit status 0 if A passes every check, 1 if one fails, 2 on bad
input or usage. Segments that cross each other are outside what this script handles.
"""

import argparse
import json
import math
import os
import re
import sys
from fractions import Fraction

EPS = 2.0 ** -53
ORIENT_BOUND = (3.0 + 16.0 * EPS) * EPS


class InputError(Exception):
    pass


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


# ---- input PSLG -----------------------------------------------------------------------------

def triangle_rows(path):
    rows = []
    with open(path, encoding='latin-1') as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if line:
                rows.append(line)
    return rows


def num(tok):
    return float(tok)


def inum(tok):
    """C's strtol(tok, NULL, 0) on the token's numeric prefix, as Triangle reads integers."""
    m = re.match(r'([+-]?)(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)', tok)
    if not m:
        raise InputError(f'not an integer: {tok}')
    t = m.group(2)
    v = int(t, 16) if t[:2].lower() == '0x' else int(t, 8) if len(t) > 1 and t[0] == '0' else int(t)
    return -v if m.group(1) == '-' else v


def read_vertex_block(rows, k, name):
    n = inum(rows[k][0])
    if len(rows[k]) > 1 and inum(rows[k][1]) != 2:
        raise InputError(f'{name}: dimension must be 2')
    base = 1
    pts = []
    for i in range(n):
        r = rows[k + 1 + i]
        if i == 0 and inum(r[0]) in (0, 1):
            base = inum(r[0])
        pts.append((num(r[1]), num(r[2])))
    return pts, base, k + 1 + n


class Pslg:
    def __init__(self):
        self.pts = []        # input vertices (x, y) in file order
        self.segs = []       # (i, j) indices into pts
        self.holes = []      # hole points
        self.even_odd = False
        self.rings = None    # for even-odd inputs: lists of points


def read_input(path):
    g = Pslg()
    if path.endswith('.poly'):
        rows = triangle_rows(path)
        if inum(rows[0][0]) > 0:
            g.pts, base, k = read_vertex_block(rows, 0, path)
        else:
            nrows = triangle_rows(path[:-5] + '.node')
            g.pts, base, _ = read_vertex_block(nrows, 0, path[:-5] + '.node')
            k = 1
        ns = inum(rows[k][0])
        for i in range(ns):
            r = rows[k + 1 + i]
            a, b = inum(r[1]) - base, inum(r[2]) - base
            if not (0 <= a < len(g.pts) and 0 <= b < len(g.pts)):
                raise InputError(f'{path}: segment {i + base} has an endpoint out of range')
            if g.pts[a] != g.pts[b]:
                g.segs.append((a, b))
        k += 1 + ns
        if k < len(rows):
            nh = inum(rows[k][0])
            for i in range(nh):
                r = rows[k + 1 + i]
                g.holes.append((num(r[1]), num(r[2])))
    elif path.endswith('.json'):
        with open(path) as f:
            data = json.load(f)
        g.even_odd = True
        g.rings = []
        for ring in data:
            ring = [(float(p[0]), float(p[1])) for p in ring]
            if len(ring) > 1 and ring[0] == ring[-1]:
                ring.pop()
            first = len(g.pts)
            g.pts.extend(ring)
            m = len(ring)
            if m >= 2:
                for k in range(m if m > 2 else 1):
                    a, b = first + k, first + (k + 1) % m
                    if g.pts[a] != g.pts[b]:
                        g.segs.append((a, b))
            if m >= 3:
                g.rings.append(ring)
    elif path.endswith('.edg'):
        with open(path) as f:
            toks = f.read().split()
        n = int(toks[0])
        index = {}
        g.even_odd = True
        for i in range(n):
            x1, y1, x2, y2 = (float(t) for t in toks[1 + 4 * i: 5 + 4 * i])
            ids = []
            for p in ((x1, y1), (x2, y2)):
                if p not in index:
                    index[p] = len(g.pts)
                    g.pts.append(p)
                ids.append(index[p])
            if ids[0] != ids[1]:
                g.segs.append(tuple(ids))
        g.rings = chain_rings(g)
    else:
        raise InputError(f'INPUT must end in .poly, .json or .edg: {path}')
    return g


def chain_rings(g):
    """The .edg segments as rings, if every vertex has degree 2 (else None)."""
    adj = {}
    for a, b in g.segs:
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    if any(len(v) != 2 for v in adj.values()):
        return None
    seen, rings = set(), []
    for s in adj:
        if s in seen:
            continue
        ring, prev, cur = [], None, s
        while cur not in seen:
            seen.add(cur)
            ring.append(g.pts[cur])
            nxt = adj[cur][0] if adj[cur][0] != prev else adj[cur][1]
            prev, cur = cur, nxt
        rings.append(ring)
    return rings


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


# ---- meshes in Triangle's format -------------------------------------------------------------

class Mesh:
    def __init__(self, base):
        self.base = base
        nrows = triangle_rows(base + '.node')
        n = inum(nrows[0][0])
        first = inum(nrows[1][0]) if n > 0 else 0
        idx = {}
        for r in nrows[1:1 + n]:
            idx[inum(r[0])] = (num(r[1]), num(r[2]))
        erows = triangle_rows(base + '.ele')
        m = inum(erows[0][0])
        self.tris = []
        for r in erows[1:1 + m]:
            t = []
            for tok in r[1:4]:
                k = inum(tok)
                if k not in idx:
                    raise InputError(f'{base}.ele: vertex {k} is not in {base}.node (first number {first})')
                t.append(idx[k])
            self.tris.append(tuple(t))

    def edges(self):
        e = set()
        for a, b, c in self.tris:
            for u, v in ((a, b), (b, c), (c, a)):
                e.add((u, v) if u < v else (v, u))
        return e


def tri_angles(t):
    out = []
    for i in range(3):
        p, q, r = t[i], t[(i + 1) % 3], t[(i + 2) % 3]
        ux, uy, vx, vy = q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1]
        out.append(math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)))
    return out


def tri_area(t):
    (ax, ay), (bx, by), (cx, cy) = t
    return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))


def small_input_angles(g, bound):
    """Input vertices where two segments (angularly adjacent) meet at less than bound degrees."""
    _, edges = split_segments(g)
    dirs = {}
    for u, v in edges:
        dirs.setdefault(u, []).append(math.atan2(v[1] - u[1], v[0] - u[0]))
        dirs.setdefault(v, []).append(math.atan2(u[1] - v[1], u[0] - v[0]))
    small = {}
    for p, ds in dirs.items():
        if len(ds) < 2:
            continue
        ds.sort()
        gaps = [ds[i + 1] - ds[i] for i in range(len(ds) - 1)] + [ds[0] + 2 * math.pi - ds[-1]]
        m = math.degrees(min(gaps))
        if m < bound:
            small[p] = m
    return small


def near_segment(w, p, q, tol2):
    """w projects into the open segment pq and lies within sqrt(tol2) of its line (exactly):
    returns 0 if w is exactly on it, 1 if within the tolerance, None otherwise."""
    if dot_sign(p, q, w) <= 0 or dot_sign(q, p, w) <= 0:
        return None
    if orient(p, q, w) == 0:
        return 0
    F = Fraction
    dx, dy = F(q[0]) - F(p[0]), F(q[1]) - F(p[1])
    e = dx * (F(w[1]) - F(p[1])) - dy * (F(w[0]) - F(p[0]))
    return 1 if e * e <= tol2 * (dx * dx + dy * dy) else None


def check_segments(pieces, mesh, ulps=8):
    """Every piece of an input segment (split at the input vertices on it) that borders the
    domain as a chain of mesh edges from one end to the other, through vertices that lie on
    it: exactly, or (Steiner points computed in floating point) within `ulps` units in the
    last place of its largest coordinate, decided exactly. The walk advances strictly along
    the piece. Returns (missing, vertices exactly on, within the tolerance)."""
    adj = {}
    for u, v in mesh.edges():
        adj.setdefault(u, set()).add(v)
        adj.setdefault(v, set()).add(u)
    missing, exact, close = [], 0, 0
    F = Fraction
    for p, q in sorted(pieces):
        tol = ulps * math.ulp(max(abs(p[0]), abs(p[1]), abs(q[0]), abs(q[1])))
        tol2 = F(tol) ** 2
        dx, dy = F(q[0]) - F(p[0]), F(q[1]) - F(p[1])
        cur = p if p in adj else None
        found = []
        while cur is not None and cur != q:
            nxt = None
            for w in adj[cur]:
                if w == q:
                    nxt = w
                    break
                # on the piece, and strictly further along it than cur
                k = near_segment(w, p, q, tol2)
                if k is not None and (F(w[0]) - F(cur[0])) * dx + (F(w[1]) - F(cur[1])) * dy > 0:
                    nxt = w
                    found.append(k)
                    break
            cur = nxt
        if cur is None:
            missing.append((p, q))
        else:
            exact += found.count(0)
            close += found.count(1)
    return missing, exact, close


def point_in_tri(p, t):
    o = [orient(t[0], t[1], p), orient(t[1], t[2], p), orient(t[2], t[0], p)]
    s = orient(*t)
    return s != 0 and all(x == s or x == 0 for x in o)


def check_holes(g, mesh):
    """The hole points that some triangle contains (exactly)."""
    bad = []
    for h in g.holes:
        for t in mesh.tris:
            if min(v[0] for v in t) <= h[0] <= max(v[0] for v in t) and \
               min(v[1] for v in t) <= h[1] <= max(v[1] for v in t) and point_in_tri(h, t):
                bad.append((h, t))
                break
    return bad


def fmt_pt(p):
    return f'({p[0]!r}, {p[1]!r})'


def segments_through(g, w, ulps=8):
    """The input segments whose open interior holds w (within `ulps`, decided exactly)."""
    out = []
    for a, b in g.segs:
        p, q = g.pts[a], g.pts[b]
        # a cheap filter that rounding cannot fool: inside the box in x or in y
        if not (min(p[0], q[0]) <= w[0] <= max(p[0], q[0]) or min(p[1], q[1]) <= w[1] <= max(p[1], q[1])):
            continue
        tol = ulps * math.ulp(max(abs(p[0]), abs(p[1]), abs(q[0]), abs(q[1])))
        if near_segment(w, p, q, Fraction(tol) ** 2) is not None:
            out.append((p, q))
    return out


def shell_exempt(g, t, angles, inputs):
    """Triangle's rule (Miller, Pav and Walkington): a skinny triangle is not split when its
    shortest edge joins two points inside two segments that share an endpoint, at distances
    from it equal within 0.1%."""
    i = angles.index(min(angles))
    u, v = t[(i + 1) % 3], t[(i + 2) % 3]
    if u in inputs or v in inputs:
        return False
    for s1 in segments_through(g, u):
        for s2 in segments_through(g, v):
            if s1 == s2:
                continue
            for j in set(s1) & set(s2):
                d1 = (u[0] - j[0]) ** 2 + (u[1] - j[1]) ** 2
                d2 = (v[0] - j[0]) ** 2 + (v[1] - j[1]) ** 2
                if 0.999 * d2 < d1 < 1.001 * d2:
                    return True
    return False


def quality_report(label, g, mesh, bound, dom_area, small, required):
    failed = []
    inputs = set(g.pts)
    at_small, shell, bad, worst, worst_all = 0, 0, 0, 180.0, 180.0
    exempt_vertices = set()
    for t in mesh.tris:
        angles = tri_angles(t)
        a = min(angles)
        worst_all = min(worst_all, a)
        if a >= bound:
            continue
        if any(v in small for v in t):
            at_small += 1
            exempt_vertices.update(v for v in t if v in small)
        elif shell_exempt(g, t, angles, inputs):
            shell += 1
        else:
            bad += 1
            worst = min(worst, a)
    ok = bad == 0
    shown = sorted(exempt_vertices)
    listed = ', '.join(f'{fmt_pt(v)} {small[v]:.2f} deg' for v in shown[:8])
    if len(shown) > 8:
        listed += f' and {len(shown) - 8} more'
    print(f'{label}angle: {"ok" if ok else "FAIL"}: {len(mesh.tris)} triangles, smallest angle {worst_all:.4f}; '
          f'{bad} below {bound:g} deg' + (f' (smallest {worst:.4f})' if bad else '') +
          f', besides {at_small} at input angles below it' + (f' at {listed}' if listed else '') +
          f' and {shell} by the shell rule (shortest edge across two segments, equidistant from their common end)')
    if not ok:
        failed.append('angle')
    missing, exact, close = check_segments(required, mesh)
    print(f'{label}segments: {"ok" if not missing else "FAIL"}: {len(required) - len(missing)} of {len(required)} '
          f'pieces of the {len(g.segs)} input segments that border the domain are chains of mesh edges '
          f'(split at {exact} vertices exactly on them, {close} within 8 ulp)' +
          ('' if not missing else '; missing: ' + ', '.join(f'{fmt_pt(p)}-{fmt_pt(q)}' for p, q in missing[:5])))
    if missing:
        failed.append('segments')
    if g.holes:
        holes = check_holes(g, mesh)
        print(f'{label}holes: {"ok" if not holes else "FAIL"}: {len(g.holes) - len(holes)} of {len(g.holes)} '
              f'hole points in no triangle' +
              ('' if not holes else '; covered: ' + ', '.join(fmt_pt(h) for h, _ in holes[:5])))
        if holes:
            failed.append('holes')
    area = math.fsum(tri_area(t) for t in mesh.tris)
    if dom_area is None:
        print(f'{label}area: skipped: {area!r} (the domain area of this input is not computed)')
    else:
        dom = float(dom_area)
        rel = abs(area - dom) / abs(dom) if dom != 0 else abs(area)
        ok = rel <= 1e-9
        print(f'{label}area: {"ok" if ok else "FAIL"}: triangles {area!r}, domain {dom!r}, relative difference {rel:.3g}')
        if not ok:
            failed.append('area')
    return failed


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('mode', choices=['cdt', 'quality'])
    ap.add_argument('input')
    ap.add_argument('a', help='mesh under test: A.node + A.ele')
    ap.add_argument('b', help='reference mesh: B.node + B.ele')
    ap.add_argument('--angle', type=float, default=30.0, help='quality: the angle bound, degrees')
    ap.add_argument('--ratio', type=float, default=1.15, help='quality: the largest triangles(A)/triangles(B)')
    ap.add_argument('--convex', action='store_true',
                    help="quality: the domain keeps the convex hull (Triangle's -c)")
    ap.add_argument('--strict', action='store_true',
                    help='cdt: fail on differences that are only cocircular ties')
    args = ap.parse_args()
    try:
        g = read_input(args.input)
        A, B = Mesh(args.a), Mesh(args.b)
    except (OSError, InputError, ValueError, IndexError) as e:
        print(f'compare_mesh2: {e}', file=sys.stderr)
        return 2
    name = os.path.basename(args.input)
    if args.mode == 'cdt':
        sa = {frozenset(t) for t in A.tris}
        sb = {frozenset(t) for t in B.tris}
        only_a, only_b = sa - sb, sb - sa
        inputs = set(g.pts)
        steiner_a = {v for t in A.tris for v in t} - inputs
        steiner_b = {v for t in B.tris for v in t} - inputs
        ok = not only_a and not only_b and len(sa) == len(A.tris) and len(sb) == len(B.tris)
        verdict = 'ok' if ok else 'FAIL'
        tie_note = ''
        if (only_a or only_b) and len(sa) == len(A.tris) and len(sb) == len(B.tris):
            da, ta = cocircular_ties(A.tris, B.edges())
            db, tb = cocircular_ties(B.tris, A.edges())
            tie_note = (f'; differing edges: A {da} ({ta} diagonals of exactly cocircular quadrilaterals), '
                        f'B {db} ({tb})')
            if da == ta and db == tb and not args.strict:
                ok, verdict = True, 'ok (cocircular ties only)'
        print(f'{name}: cdt: {verdict}: A {len(A.tris)} triangles, B {len(B.tris)}, '
              f'{len(only_a)} only in A, {len(only_b)} only in B; vertices not in the input: '
              f'A {len(steiner_a)}, B {len(steiner_b)}' + tie_note)
        for lab, s in (('A', only_a), ('B', only_b)):
            for t in sorted(tuple(sorted(x)) for x in s)[:5]:
                print(f'  only in {lab}: ' + ' '.join(fmt_pt(p) for p in t))
        return 0 if ok else 1
    # quality
    small = small_input_angles(g, args.angle)
    try:
        if g.even_odd:
            dom = domain_area_even_odd(g) if g.rings is not None else None
            nholes, required = 0, split_segments(g)[1]
        else:
            dom, nholes, required = domain_triangle_rule(g, args.convex)
    except InputError as e:
        print(f'compare_mesh2: {e}', file=sys.stderr)
        return 2
    print(f'{name}: quality: {len(g.pts)} input vertices, {len(g.segs)} segments, {len(g.holes)} hole points '
          f'({nholes} faces holed), {len(small)} input angles below {args.angle:g} deg')
    failed = quality_report('', g, A, args.angle, dom, small, required)
    quality_report('ref ', g, B, args.angle, dom, small, required)
    ratio = len(A.tris) / len(B.tris) if B.tris else float('inf')
    ok = ratio <= args.ratio
    print(f'count: {"ok" if ok else "FAIL"}: {len(A.tris)} / {len(B.tris)} = {ratio:.4f} (at most {args.ratio:g})')
    if not ok:
        failed.append('count')
    print(f'{name}: {"PASS" if not failed else "FAIL: " + ", ".join(failed)}')
    return 0 if not failed else 1


if __name__ == '__main__':
    sys.exit(main())
