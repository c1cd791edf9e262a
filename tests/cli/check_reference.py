#!/usr/bin/env python3
"""check_reference.py REF OUT [--same]: a mesh written by `lifthull triangle` (OUT.node,
OUT.ele, OUT.poly if REF.poly exists) against Triangle's output for the same command
(REF.*, the files drufat/triangle ships, tests/data/triangle/reference_outputs).

Always compared: the header lines (attribute and marker columns, with --same the
counts too); every vertex's boundary marker, by Triangle's rule as the reference
shows it: a vertex of OUT at a vertex of REF has REF's marker; else one on a
subsegment of REF.poly has that subsegment's marker (a point inside a subsegment gets
its marker, the same rule); else 0 (.node input: a vertex on REF's boundary edges 1).
Every subsegment of OUT.poly lies along a subsegment of REF.poly (its midpoint on it,
its ends on its line) with the same marker, and they cover the same length; the holes and regions of the .poly are REF's.
--delaunay: every edge of OUT between two triangles is locally Delaunay.
--o2: OUT's quadratic elements are Triangle's (6 nodes, as quadratic() says).
Vertex attributes of the vertices both have are equal. Refined (no --same): vertex
counts within 0.8..1.25 times Triangle's. --same (no refinement, so
the same vertices): the same vertices with the same markers, the same segments as
sets with their markers, and the same triangles (counterclockwise; -o2: with the
midpoint nodes in the same places) unless the vertices are cocircular.
Prints "ok" or the differences (at most 10), exits 1 on any.
"""
import math
import os
import sys

from trifiles import tokens


def read_node(path):
    t = tokens(path)
    n, _, na, nm = (int(x) for x in t[0][:4])
    first = int(t[1][0]) if n else 0
    pts, attrs, marks = [], [], []
    for l in t[1:1 + n]:
        pts.append((float(l[1]), float(l[2])))
        attrs.append(tuple(float(x) for x in l[3:3 + na]))
        marks.append(int(l[3 + na]) if nm else 0)
    return t[0][:4], first, pts, attrs, marks


def read_ele(path, first):
    t = tokens(path)
    n, k = int(t[0][0]), int(t[0][1])
    return t[0][:3], [tuple(int(v) - first for v in l[1:1 + k]) for l in t[1:1 + n]]


def read_poly_out(path, first):
    """An output .poly: (header, segments with markers, holes, regions)."""
    t = tokens(path)
    i = 1 + int(t[0][0])
    ns, sm = int(t[i][0]), int(t[i][1])
    segs = [(int(l[1]) - first, int(l[2]) - first, int(l[3]) if sm else 0) for l in t[i + 1:i + 1 + ns]]
    i += 1 + ns
    nh = int(t[i][0])
    holes = [tuple(float(x) for x in l[1:3]) for l in t[i + 1:i + 1 + nh]]
    i += 1 + nh
    regions = []
    if i < len(t):
        regions = [tuple(float(x) for x in l[1:]) for l in t[i + 1:i + 1 + int(t[i][0])]]
    return t[0][:4] + t[1 + int(t[0][0])][:2], segs, holes, regions


def on_segment(p, a, b, line=False):
    """p on segment a-b (line: on its line), within 2^-30 of its length (both meshes'
    points on segments are rounded)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    l2 = dx * dx + dy * dy
    if l2 == 0:
        return False
    f = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2
    cr = dx * (p[1] - a[1]) - dy * (p[0] - a[0])
    return (line or -2.0 ** -30 <= f <= 1 + 2.0 ** -30) and cr * cr <= 2.0 ** -60 * l2 * l2


class Cmp:
    def __init__(self):
        self.diffs = []

    def bad(self, what):
        self.diffs.append(what)


def boundary_segments(c, ref, out, rfirst, ofirst, same):
    """REF's boundary subsegments with markers, and OUT's (None for a .node input): the .poly
    files (headers, holes, regions compared), or for a .node input the convex hull, the edges
    on one triangle of REF only (marker 1)."""
    if os.path.exists(ref + '.poly'):
        rph, rsegs, rholes, rregions = read_poly_out(ref + '.poly', rfirst)
        oph, osegs, oholes, oregions = read_poly_out(out + '.poly', ofirst)
        if (rph if same else rph[1:4] + rph[5:]) != (oph if same else oph[1:4] + oph[5:]):
            c.bad('.poly header %s, Triangle %s' % (' '.join(oph), ' '.join(rph)))
        if rholes != oholes or rregions != oregions:
            c.bad('.poly holes/regions %s %s, Triangle %s %s' % (oholes, oregions, rholes, rregions))
        return rsegs, osegs
    _, rtris = read_ele(ref + '.ele', rfirst)
    count = {}
    for (a, b, d) in (t[:3] for t in rtris):
        for u, v in ((a, b), (b, d), (d, a)):
            k = (min(u, v), max(u, v))
            count[k] = count.get(k, 0) + 1
    return [(u, v, 1) for (u, v), n in count.items() if n == 1], None


def check_vertices(c, r, o, ofirst, rsegs):
    """Every vertex of OUT has the marker Triangle's rule gives it, and REF's attributes
    where REF has the vertex. r, o: read_node's (points, attributes, markers)."""
    rpts, rattr, rmark = r
    opts, oattr, omark = o
    rat = {p: i for i, p in enumerate(rpts)}

    def expected_marker(p):
        if p in rat:
            return rmark[rat[p]]
        for (a, b, m) in rsegs:
            if on_segment(p, rpts[a], rpts[b]):
                return m
        return 0

    for i, p in enumerate(opts):
        want = expected_marker(p)
        if omark[i] != want:
            c.bad('vertex %d (%.17g, %.17g): marker %d, Triangle %d' % (i + ofirst, p[0], p[1], omark[i], want))
        if p in rat and oattr[i] != rattr[rat[p]]:
            c.bad('vertex %d: attributes %s, Triangle %s' % (i + ofirst, oattr[i], rattr[rat[p]]))


def check_segments(c, osegs, opts, ofirst, rsegs, rpts):
    """Every subsegment of OUT along one of REF with its marker; the same total length."""
    length = [0.0, 0.0]
    for (a, b, m) in osegs:
        pa, pb = opts[a], opts[b]
        length[0] += math.dist(pa, pb)
        mid = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)  # on the reference subsegment, ends on its line
        host = [r for r in rsegs if on_segment(mid, rpts[r[0]], rpts[r[1]])
                and on_segment(pa, rpts[r[0]], rpts[r[1]], True) and on_segment(pb, rpts[r[0]], rpts[r[1]], True)]
        if not host:
            c.bad('segment %s-%s on no segment of Triangle' % (a + ofirst, b + ofirst))
        elif m != host[0][2]:
            c.bad('segment %s-%s: marker %d, Triangle %d' % (a + ofirst, b + ofirst, m, host[0][2]))
    for (a, b, m) in rsegs:
        length[1] += math.dist(rpts[a], rpts[b])
    if abs(length[0] - length[1]) > 1e-9 * length[1]:
        c.bad('segments: total length %.17g, Triangle %.17g' % tuple(length))


def check_same(c, ref, out, first, pts, segs):
    """--same: the same vertices, segments with markers, .ele header and triangles (unless
    cocircular). first, pts, segs: (REF's, OUT's) each."""
    rfirst, ofirst = first
    rpts, opts = pts
    rsegs, osegs = segs
    if sorted(opts) != sorted(rpts):
        c.bad('other vertices than Triangle')
    elif os.path.exists(ref + '.poly'):
        key = lambda s, pts: (tuple(sorted((pts[s[0]], pts[s[1]]))), s[2])
        mine, theirs = sorted(key(s, opts) for s in osegs), sorted(key(s, rpts) for s in rsegs)
        if mine != theirs:
            c.bad('other segments or segment markers than Triangle: %s, Triangle %s'
                  % (sorted(set(mine) - set(theirs))[:3], sorted(set(theirs) - set(mine))[:3]))
    reh, rtris = read_ele(ref + '.ele', rfirst)
    oeh, otris = read_ele(out + '.ele', ofirst)
    if reh != oeh:
        c.bad('.ele header %s, Triangle %s' % (' '.join(oeh), ' '.join(reh)))
    if not c.diffs and tri_set(otris, opts) != tri_set(rtris, rpts) and not cocircular(rtris, rpts):
        c.bad('other triangles than Triangle')


def report(c):
    for d in c.diffs[:10]:
        print(d)
    if len(c.diffs) > 10:
        print('... %d differences' % len(c.diffs))
    if not c.diffs:
        print('ok')
    return 1 if c.diffs else 0


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    same = '--same' in sys.argv
    ref, out = args
    c = Cmp()
    rh, rfirst, rpts, rattr, rmark = read_node(ref + '.node')
    oh, ofirst, opts, oattr, omark = read_node(out + '.node')
    if (rh[1:] if same is False else rh) != (oh[1:] if same is False else oh):
        c.bad('.node header %s, Triangle %s' % (' '.join(oh), ' '.join(rh)))
    if not same and '--o2' not in sys.argv and not 0.8 * len(rpts) <= len(opts) <= 1.25 * len(rpts):
        c.bad('%d vertices, Triangle %d (not within 0.8..1.25 times)' % (len(opts), len(rpts)))
    rsegs, osegs = boundary_segments(c, ref, out, rfirst, ofirst, same)
    check_vertices(c, (rpts, rattr, rmark), (opts, oattr, omark), ofirst, rsegs)
    if os.path.exists(ref + '.poly'):
        check_segments(c, osegs, opts, ofirst, rsegs, rpts)
    if same:
        check_same(c, ref, out, (rfirst, ofirst), (rpts, opts), (rsegs, osegs))
    if '--o2' in sys.argv:
        quadratic(c, out, ofirst, opts)
    if '--delaunay' in sys.argv and cocircular(read_ele(out + '.ele', ofirst)[1], opts, strict=True):
        c.bad('an edge of OUT is not locally Delaunay')
    return report(c)


def quadratic(c, out, first, pts):
    """-o2 (Triangle's quadratic elements): six nodes, the corners counterclockwise,
    then the midpoints of the edges opposite corners 1, 2, 3, one node per edge shared
    by its triangles, numbered after every corner."""
    head, tris = read_ele(out + '.ele', first)
    if head[1] != '6':
        c.bad('-o2: %s nodes per triangle' % head[1])
        return
    node = {}
    for t in tris:
        for k in range(3):
            a, b = pts[t[(k + 1) % 3]], pts[t[(k + 2) % 3]]
            if pts[t[3 + k]] != ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2):
                c.bad('-o2: node %d is not the midpoint of its edge' % (t[3 + k] + first))
            node.setdefault((min(t[(k + 1) % 3], t[(k + 2) % 3]), max(t[(k + 1) % 3], t[(k + 2) % 3])), set()).add(t[3 + k])
    mids = [n for ns in node.values() for n in ns]
    corners = {v for t in tris for v in t[:3]}
    if len(mids) != len(node) or len(set(mids)) != len(mids) or min(mids) <= max(corners) or len(pts) != max(corners) + 1 + len(node):
        c.bad('-o2: not one node per edge, numbered after the corners')


def tri_set(tris, pts):
    """The triangles by their points, counterclockwise from the least corner (-o2:
    the midpoint nodes after the corners, turned alike)."""
    keys = []
    for t in tris:
        c, m = [pts[v] for v in t[:3]], [pts[v] for v in t[3:]]
        r = c.index(min(c))
        keys.append(tuple(c[r:] + c[:r] + (m[r:] + m[:r] if m else [])))
    return sorted(keys)


def cocircular(tris, pts, strict=False):
    """Whether two triangles sharing an edge have their four vertices on one circle
    (then the Delaunay triangulation is not unique); strict: whether an apex is
    strictly inside the other triangle's circle (the edge not locally Delaunay).
    Exact, with rationals."""
    from fractions import Fraction as F
    edges = {}
    for t in tris:
        for k in range(3):
            u, v = t[(k + 1) % 3], t[(k + 2) % 3]  # the corners; -o2 nodes after them
            edges.setdefault((min(u, v), max(u, v)), []).append(t[k])
    for (u, v), apex in edges.items():
        if len(apex) != 2:
            continue
        a, b, c, d = (tuple(map(F, pts[i])) for i in (u, v, apex[0], apex[1]))
        rows = [(p[0] - d[0], p[1] - d[1], (p[0] - d[0]) ** 2 + (p[1] - d[1]) ** 2) for p in (a, b, c)]
        det = (rows[0][0] * (rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1])
               - rows[0][1] * (rows[1][0] * rows[2][2] - rows[1][2] * rows[2][0])
               + rows[0][2] * (rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0]))
        turn = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if (det * turn > 0 if strict else det == 0):  # d strictly inside circle abc
            return True
    return False


if __name__ == '__main__':
    sys.exit(main())
