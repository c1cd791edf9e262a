#!/usr/bin/env python3
"""seeds.py OUT_DIR — seed inputs for fuzz_hull, fuzz_check, fuzz_query and fuzz_cells
(fuzz/README.md): the degenerate families of tests/harness/lh_families.c that fit small
integers (grids, exactly cospherical sets, points on a hyperplane, duplicates), polytopes
from ../shared/data/degenerate (the 24-cell of scipy's selfdual-4d-polytope, CGAL's
degtri_*), and for the cell reader the .ele files of ../shared/data/triangle and 'i'
lists. Writes OUT_DIR/<target>/<name>; libFuzzer's -merge=1 then keeps what covers code.
"""
import itertools
import os
import sys

SHARED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "data")


def i8(v):
    assert -128 <= v <= 127, v
    return v & 0xFF


def point_sets():
    """(name, d, points): integer coordinates in -128..127."""
    sets = []
    grid = lambda d, k: [list(p) for p in itertools.product(range(k), repeat=d)]
    for d in range(2, 7):
        cube = [list(p) for p in itertools.product((0, 1), repeat=d)]
        sets.append((f"cube{d}", d, cube[:48]))
        sets.append((f"cube_center{d}", d, [[2 * c for c in p] for p in cube[:20]] + [[1] * d]))
        cross = [[(s if j == i else 0) for j in range(d)] for i in range(d) for s in (1, -1)]
        sets.append((f"cross{d}", d, cross + [[0] * d]))
        simplex = [[0] * d] + [[(3 if j == i else 0) for j in range(d)] for i in range(d)]
        sets.append((f"simplex_dups{d}", d, simplex + simplex[:3] + [[1] * d]))
        flat = [p[:-1] + [0] for p in grid(d, 3)][:30]  # all in the hyperplane x_d = 0
        sets.append((f"flat{d}", d, flat))
        sets.append((f"grid{d}", d, grid(d, 3 if d <= 3 else 2)[:40]))
    sets.append(("circle25", 2, [[x, y] for x in range(-5, 6) for y in range(-5, 6) if x * x + y * y == 25]))
    sets.append(("sphere9", 3, [[x, y, z] for x in range(-3, 4) for y in range(-3, 4) for z in range(-3, 4)
                                if x * x + y * y + z * z == 9]))
    sets.append(("line", 2, [[i, 2 * i] for i in range(-4, 5)]))
    sets.append(("plane3", 3, [[x, y, x + y] for x in range(3) for y in range(3)]))
    # scipy's selfdual-4d-polytope: the 24-cell, vertices the permutations of (+-1,+-1,0,0)
    cell24 = sorted({p for s in itertools.product((1, -1), repeat=2)
                     for p in itertools.permutations((s[0], s[1], 0, 0))})
    sets.append(("cell24", 4, [list(p) for p in cell24]))
    for name in ("degtri_three.off", "degtri_four.off"):
        path = os.path.join(SHARED, "degenerate", "cgal", name)
        if os.path.exists(path):
            lines = [l.split() for l in open(path) if l.strip()]
            nv = int(lines[1][0])
            pts = [[int(round(float(c) * 4)) for c in l[:3]] for l in lines[2:2 + nv]]
            sets.append((name.split(".")[0], 3, pts))
            sets.append((name.split(".")[0] + "_xy", 2, [p[:2] for p in pts]))
    return sets


def write(out, target, name, data):
    os.makedirs(os.path.join(out, target), exist_ok=True)
    with open(os.path.join(out, target, name), "wb") as f:
        f.write(bytes(data))


def main(out):
    maxn = {"check": {2: 12, 3: 10, 4: 9}, "query": {2: 16, 3: 12, 4: 10}}
    for name, d, pts in point_sets():
        coords = [i8(c) for p in pts for c in p]
        # fuzz_hull: d-2, flags (2: int8 values as they are), coordinates
        write(out, "hull", name, [d - 2, 2] + coords[:48 * d])
        write(out, "hull", name + "_mod3", [d - 2, 0] + coords[:48 * d])
        if d > 4:
            continue
        for target in ("check", "query"):
            n = min(len(pts), maxn[target][d])
            body = [d - 2, 1, n - 1] + coords[:n * d]
            if target == "check":  # edits: arbitrary list of 2, rotation, shift, two edits
                body += [2, 0, 1, 2, 1, 2, 3, 5, 3, 1, 0, 2, 0, 4, 1, 1, 2, 0]
            else:  # queries: the centre, a vertex, a midpoint, far outside
                body += [0] * d + [i8(2 * c) for c in pts[0]] + \
                        [i8(pts[0][j] + pts[-1][j]) for j in range(d)] + [i8(100)] * d
            write(out, target, name, body)
    # fuzz_cells: byte 0 = n_points choice (4: 10 points) | name choice << 3, then the file
    tri = os.path.join(SHARED, "triangle")
    k = 0
    for root, _, files in os.walk(tri):
        for f in sorted(files):
            if f.endswith(".ele") and os.path.getsize(os.path.join(root, f)) < 1500:
                write(out, "cells", f"ele_{k}", [0x08] + list(open(os.path.join(root, f), "rb").read()))
                k += 1
    write(out, "cells", "i_tri", [0x04] + list(b"3\n0 1 2\n1 2 3\n2 3 0\n"))
    write(out, "cells", "i_tet", [0x02] + list(b"# tets\n2\n0 1 2 3\n3 2 1 0\n"))
    write(out, "cells", "ele_attr", [0x0c] + list(b"2 4 1\n1 1 2 3 4 0.5\n2 4 3 2 1 -1e3\n"))
    write(out, "cells", "i_crlf", [0x10] + list(b"\xef\xbb\xbf2\r\n0 1\r\n1 0 # c\r\n"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "seeds")
