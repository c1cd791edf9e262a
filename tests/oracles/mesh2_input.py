"""Readers for compare_mesh2.py: the input PSLG (.poly, JSON rings, .edg) and meshes in
Triangle's format (.node + .ele)."""

import json
import re


class InputError(Exception):
    pass


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
