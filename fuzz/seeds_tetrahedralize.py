#!/usr/bin/env python3
"""Seeds for fuzz_tetrahedralize (fuzz/corpus/tetrahedralize/seed-*): small PLCs in the
target's byte layout (fuzz_tetrahedralize.c): a tetrahedron, a cube of quads with and
without a hole point, Schonhardt's prism, two cubes sharing an edge, two crossing
triangles, each at a few scales. Run from the repository's root."""
import os

OUT = "fuzz/corpus/tetrahedralize"

def plc(flags, pts, facets, holes=()):
    b = bytes([flags, (len(pts) - 4) % 21])
    for p in pts:
        b += bytes(c & 0xff for c in p)
    for i, f in enumerate(facets):
        b += bytes([len(f) - 3]) + bytes(f)
    if holes:
        b += b"\xff"
        for h in holes:
            b += bytes(c & 0xff for c in h)
    return b

CUBE = [(0, 0, 0), (3, 0, 0), (3, 3, 0), (0, 3, 0), (0, 0, 3), (3, 0, 3), (3, 3, 3), (0, 3, 3)]
CUBE_F = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
TET = [(0, 0, 0), (3, 0, 0), (0, 3, 0), (0, 0, 3)]
TET_F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
# Schonhardt's prism (int8 coordinates): a triangle, the one above it turned by 30 degrees
SCH = [(40, 0, 0), (-20, 35, 0), (-20, -35, 0), (35, 20, 60), (-35, 20, 60), (0, -40, 60)]
SCH_F = [(0, 2, 1), (3, 4, 5), (0, 1, 3), (1, 4, 3), (1, 2, 4), (2, 5, 4), (2, 0, 5), (0, 3, 5)]
TWO = CUBE + [(3, 3, 3), (3, 3, 3)]  # duplicate points
CROSS = [(0, 0, 1), (3, 0, 1), (0, 3, 1), (1, 1, 0), (1, 1, 3), (2, 2, 0)]
CROSS_F = [(0, 1, 2), (3, 4, 5)]

def seeds():
    for scale in (0, 1, 2):
        s = scale << 3
        yield f"tet-{scale}", plc(s, TET, TET_F)
        yield f"cube-{scale}", plc(s, CUBE, CUBE_F)
        yield f"cube-hole-{scale}", plc(s, CUBE, CUBE_F, [(3, 3, 3)])
        yield f"schonhardt-{scale}", plc(s | 4, SCH, SCH_F)
    yield "cube-hull", plc(1, CUBE, CUBE_F[:3])
    yield "cube-dups", plc(0, TWO, CUBE_F)
    yield "crossing", plc(0, CROSS, CROSS_F)
    yield "crossing-unchecked", plc(2, CROSS, CROSS_F)

os.makedirs(OUT, exist_ok=True)
for name, data in seeds():
    with open(os.path.join(OUT, "seed-" + name), "wb") as f:
        f.write(data)
