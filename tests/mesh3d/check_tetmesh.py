#!/usr/bin/env python3
"""check_tetmesh.py: an independent exact check of a tetrahedral mesh in TetGen's files.

    check_tetmesh.py BASE [--input SURFACE.off] [--doubles] [--boundary-free] [--quiet]

reads BASE.node, BASE.ele, BASE.face (if present) and BASE.edge (if present), points
numbered from 0 or 1 (the .node file's first index says which), and checks, every
number a fractions.Fraction (exact for the decimal text in the files):
  - every tet has positive orientation: det[b-a, c-a, d-a] > 0 (TetGen's and
    lifthull's convention);
  - no two tets are the same; every triangle is in at most two tets, which lie on its
    two sides (the sign of the face's plane at the fourth point, computed, not derived);
  - every triangle of BASE.face is a face of a tet and every face in one tet (the
    boundary) is in BASE.face (unless --boundary-free); every edge of BASE.edge is an
    edge of a tet;
  - volume: the sum of the tets' volumes equals the volume the boundary faces enclose
    (each oriented outward by its tet, coned to a point), exactly; with --input, also
    the volume of the input surface (an OFF file: its closed components, each oriented
    by its own triangles and taken positive; nested cavities are not supported) —
    exactly, so a mesh whose boundary moved (Steiner points rounded to the .node
    file's decimals; TetGen's -p also merges facets that meet at nearly 180 degrees:
    eight.off differs by 7e-7) fails it, the message giving the relative difference.
With --doubles every number is read as the double nearest its text (Python's float,
correctly rounded, as strtod), as the programs that wrote and read the files hold it:
a mesh's 17-digit coordinates and an input's decimals then mean the same points.
The first check that fails is printed as one line and the exit status is 1; 0 when
all pass (a summary line unless --quiet); 2 for unreadable files.
Standard library only, a separate implementation from lh_tetmesh_check (mesh3d/check*.c).
"""
import os
import sys
from fractions import Fraction


class Bad(Exception):
    pass


def records(path):
    """Non-empty, non-comment lines of a TetGen file, as lists of tokens."""
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if line:
                yield line


def read_node(path, num):
    it = records(path)
    head = next(it)
    n = int(head[0])
    pts, first = [], None
    for _ in range(n):
        r = next(it)
        if first is None:
            first = int(r[0])
        pts.append(tuple(num(x) for x in r[1:4]))
    return pts, first if first is not None else 0


def read_cells(path, per, base, n):
    """Cells of `per` points from a .ele/.face/.edge file, renumbered from 0."""
    it = records(path)
    head = next(it)
    count = int(head[0])
    if path.endswith('.ele') and int(head[1]) not in (4, 10):
        raise Bad(f'{path}: {head[1]} points per tet')
    cells = []
    for i in range(count):
        r = next(it)
        c = tuple(int(x) - base for x in r[1:1 + per])
        for v in c:
            if not 0 <= v < n:
                raise Bad(f'{path}: cell {i} names point {v + base}, not a point')
        cells.append(c)
    return cells


def det3(a, b, c, d):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def sign(x):
    return (x > 0) - (x < 0)


def check_tets(pts, tets):
    vol = Fraction(0)
    seen = {}
    for t, v in enumerate(tets):
        d = det3(*(pts[i] for i in v))
        if d <= 0:
            raise Bad(f'tet {t} {v} has orientation {"0 (flat)" if d == 0 else "< 0 (inverted)"}')
        key = tuple(sorted(v))
        if key in seen:
            raise Bad(f'tets {seen[key]} and {t} are the same tet {key}')
        seen[key] = t
        vol += d
    return vol


def face_table(pts, tets):
    """sorted face -> [(tet, side)], side the sign of the sorted face's plane at the
    tet's fourth point."""
    faces = {}
    for t, v in enumerate(tets):
        for k in range(4):
            f = tuple(sorted(v[:k] + v[k + 1:]))
            s = sign(det3(pts[f[0]], pts[f[1]], pts[f[2]], pts[v[k]]))
            faces.setdefault(f, []).append((t, s))
    for f, ts in faces.items():
        if len(ts) > 2:
            raise Bad(f'face {f} is in {len(ts)} tets: {[t for t, _ in ts]}')
        if len(ts) == 2 and ts[0][1] == ts[1][1]:
            raise Bad(f'face {f}: tets {ts[0][0]} and {ts[1][0]} lie on the same side')
    return faces


def boundary_volume(pts, faces):
    """Sum of the boundary faces' cones to the first point, each face oriented with
    its tet on the negative side (outward): equals the tets' volume when the faces
    pair up, as a chain identity evaluated independently."""
    o = pts[0]
    vol = Fraction(0)
    for f, ts in faces.items():
        if len(ts) == 1:
            a, b, c = (pts[i] for i in f)
            d = det3(o, a, b, c)  # the cone from o, positive when abc faces away from o
            vol += d if ts[0][1] < 0 else -d
    return vol


def read_off(path, num):
    toks = []
    for line in open(path):
        toks += line.split('#', 1)[0].split()
    if toks[0].upper().endswith('OFF'):
        toks = toks[1:]
    nv, nf = int(toks[0]), int(toks[1])
    pos = 3
    pts = []
    for _ in range(nv):
        pts.append(tuple(num(x) for x in toks[pos:pos + 3]))
        pos += 3
    polys = []
    for _ in range(nf):
        k = int(toks[pos])
        polys.append(tuple(int(x) for x in toks[pos + 1:pos + 1 + k]))
        pos += 1 + k
    return pts, polys


def surface_volume(pts, polys):
    """|volume| of each closed component of a polygon surface, components joined
    across edges of exactly two polygons, each polygon fan-triangulated and oriented
    consistently with its neighbours (flipped where they run an edge the same way)."""
    edges = {}
    for p, poly in enumerate(polys):
        for i in range(len(poly)):
            a, b = poly[i], poly[(i + 1) % len(poly)]
            edges.setdefault((min(a, b), max(a, b)), []).append((p, a < b))
    flip = [None] * len(polys)
    total = Fraction(0)
    for start in range(len(polys)):
        if flip[start] is not None:
            continue
        flip[start] = False
        stack, vol = [start], Fraction(0)
        while stack:
            p = stack.pop()
            poly = polys[p]
            o = pts[poly[0]]
            for i in range(1, len(poly) - 1):
                d = det3(pts[0], o, pts[poly[i]], pts[poly[i + 1]])
                vol += -d if flip[p] else d
            for i in range(len(poly)):
                a, b = poly[i], poly[(i + 1) % len(poly)]
                uses = edges[(min(a, b), max(a, b))]
                if len(uses) != 2:
                    continue
                for q, fwd in uses:
                    if q != p and flip[q] is None:
                        # q runs the edge the same way as p (after p's flip): flip q
                        same = fwd == (a < b)
                        flip[q] = flip[p] if not same else not flip[p]
                        stack.append(q)
        total += abs(vol)
    return total


def check(base, input_off=None, boundary_free=False, num=Fraction):
    pts, first = read_node(base + '.node', num)
    tets = read_cells(base + '.ele', 4, first, len(pts))
    vol = check_tets(pts, tets)
    faces = face_table(pts, tets)
    nsub = nedge = 0
    if os.path.exists(base + '.face'):
        sub = read_cells(base + '.face', 3, first, len(pts))
        nsub = len(sub)
        subset = set()
        for s, f in enumerate(sub):
            key = tuple(sorted(f))
            if key not in faces:
                raise Bad(f'subface {s} {f} is not a face of a tet')
            subset.add(key)
        if not boundary_free:
            for f, ts in faces.items():
                if len(ts) == 1 and f not in subset:
                    raise Bad(f'boundary face {f} of tet {ts[0][0]} is not a subface')
    elif not boundary_free:
        raise Bad(f'{base}.face is missing (give --boundary-free to check without it)')
    if os.path.exists(base + '.edge'):
        tet_edges = set()
        for v in tets:
            for i in range(4):
                for j in range(i + 1, 4):
                    tet_edges.add((min(v[i], v[j]), max(v[i], v[j])))
        for e, (a, b) in enumerate(read_cells(base + '.edge', 2, first, len(pts))):
            nedge += 1
            if (min(a, b), max(a, b)) not in tet_edges:
                raise Bad(f'edge {e} ({a}, {b}) is not an edge of a tet')
    bvol = boundary_volume(pts, faces)
    if bvol != vol:
        raise Bad(f'the tets\' volume {vol / 6} differs from the boundary\'s {bvol / 6}')
    if input_off:
        ipts, polys = read_off(input_off, num)
        ivol = surface_volume(ipts, polys)
        if ivol != vol:
            rel = float(abs(ivol - vol) / ivol) if ivol else float('inf')
            raise Bad(f'the tets\' volume {float(vol / 6)!r} differs from the input surface\'s '
                      f'{float(ivol / 6)!r} (relative difference {rel:.3g}: the boundary is not exactly '
                      f'the input\'s)')
    return len(pts), len(tets), nsub, nedge, vol / 6


def main(argv):
    args = [a for a in argv[1:] if not a.startswith('--')]
    opts = [a for a in argv[1:] if a.startswith('--')]
    input_off = None
    if '--input' in argv:
        i = argv.index('--input')
        input_off = argv[i + 1]
        args.remove(input_off)
        opts.remove('--input')
    if len(args) != 1 or any(o not in ('--boundary-free', '--quiet', '--doubles') for o in opts):
        print(__doc__.strip().split('\n\n')[1], file=sys.stderr)
        return 2
    base = args[0]
    for ext in ('.node', '.ele', '.face', '.edge'):
        if base.endswith(ext):
            base = base[:-len(ext)]
    try:
        num = (lambda x: Fraction(float(x))) if '--doubles' in opts else Fraction
        n, nt, nf, ne, vol = check(base, input_off, '--boundary-free' in opts, num)
    except Bad as e:
        print(f'{base}: {e}')
        return 1
    except (OSError, ValueError, IndexError, StopIteration) as e:
        print(f'{base}: cannot read: {e!r}', file=sys.stderr)
        return 2
    if '--quiet' not in opts:
        print(f'{base}: valid: {n} points, {nt} tets, {nf} subfaces, {ne} edges, volume {vol}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
