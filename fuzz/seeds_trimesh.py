#!/usr/bin/env python3
"""seeds_trimesh.py OUT_DIR — hand-made seed PSLGs for fuzz_trimesh, in its byte encoding
(fuzz/fuzz_trimesh.c, decode()): OUT_DIR/seed-<name>. A square with a square hole, a
crossing pair, a vertex on a segment, collinear sets, a small-angle wedge, cocircular
rings, and the hole square again offset by 1e6 and scaled by 2^-30."""
import os
import sys

ANGLES = {0: 0, 20: 1, 25: 2, 30: 3, 33: 4}
AREAS = {0: 0, 0.5: 1, 2: 2, 8: 3}


def encode(verts, ring=0, segs=(), holes=(), regions=(), even_odd=0, convex_hull=0,
           conforming=0, noncrossing=0, angle=0, fail=None, bsteiner=1, area=0,
           steiner=None, region_areas=0, region_attr=0, mode=0, big_offset=0, k=0,
           attr=0, lines=0, split=0, smooth=0, cover=None):
    """verts: (x, y) in -8..8; segs: index pairs; holes, regions: half-integers in
    -8..8 (regions: (x, y, attribute, area index 0..3)); mode: 1 scale 2^k, 2 offset,
    3 both; steiner: None (5000), 'small' (k & 15) or 64; cover: the byte after the
    PSLG that asks for the second stage, refining the mesh made (fuzz_trimesh.c,
    refine_cover), or None."""
    f0 = even_odd | convex_hull << 1 | conforming << 2 | noncrossing << 3 | ANGLES[angle] << 4
    f0 |= (fail is not None) << 7
    f1 = {1: 0, 0: 2, -1: 3}[bsteiner] | AREAS[area] << 2
    f1 |= {None: 0, "small": 1, 64: 2}[steiner] << 4 | region_areas << 6 | region_attr << 7
    f2 = mode | big_offset << 2 | len(holes) << 3 | len(regions) << 5 | attr << 7
    out = [f0, f1, f2, (2 * k) & 0xFF, len(verts) - 3, len(segs), ring | lines << 6 | split << 7]
    fail = (fail or 0) | smooth << 14  # the top two bits of the failure pick: smoothing passes
    out += [fail >> 8 & 0xFF, fail & 0xFF]
    for x, y in verts:
        out += [x + 8, y + 8]
    for a, b in segs:
        out += [a, b]
    for x, y in holes:
        out += [int(2 * (x + 8)), int(2 * (y + 8))]
    for x, y, a, ar in regions:
        out += [int(2 * (x + 8)), int(2 * (y + 8)), a << 2 | ar]
    if cover is not None:
        out.append(cover)
    return bytes(out)


def cover_byte(segments=0, area_start=None, angle=0, area=0):
    """refine_cover's byte: with the old subsegments (-rp), the old triangles' area
    bounds from area_start (1..3, None: none), the angle bound, the global area 2."""
    return 1 | segments << 1 | (area_start or 0) << 2 | ANGLES[angle] << 4 | (area == 2) << 7


def seeds():
    sq = [(-8, -8), (8, -8), (8, 8), (-8, 8)]
    inner = [(-3, -3), (3, -3), (3, 3), (-3, 3)]
    hole_segs = [(4, 5), (5, 6), (6, 7), (7, 4)]
    circle = [(x, y) for x in range(-5, 6) for y in range(-5, 6) if x * x + y * y == 25]
    circle.sort(key=lambda p: __import__("math").atan2(p[1], p[0]))
    yield "square_hole", encode(sq + inner, ring=4, segs=hole_segs, holes=[(0, 0)], angle=30)
    yield "square_hole_regions", encode(sq + inner, ring=4, segs=hole_segs, regions=[(0, 0, 2, 1), (6, 6, 1, 2)],
                                        angle=20, region_areas=1, region_attr=1, attr=1, lines=1)
    yield "square_hole_smoothed", encode(sq + inner, ring=4, segs=hole_segs, regions=[(0, 0, 2, 1), (6, 6, 1, 2)],
                                         angle=25, region_areas=1, smooth=3)
    yield "square_hole_offset", encode(sq + inner, ring=4, segs=hole_segs, holes=[(0.5, 0.5)], angle=25,
                                       mode=3, k=-30)
    yield "square_hole_even_odd", encode(sq + inner, ring=4, segs=hole_segs, even_odd=1, angle=33, area=2)
    yield "crossing_pair", encode([(-4, -4), (4, -4), (4, 4), (-4, 4)], segs=[(0, 2), (1, 3)], lines=1)
    yield "crossing_pair_filtered", encode([(-4, -4), (4, -4), (4, 4), (-4, 4)], segs=[(0, 2), (1, 3)],
                                           noncrossing=1, convex_hull=1, angle=30)
    yield "crossing_split", encode([(-4, -4), (4, -4), (4, 4), (-4, 4), (-3, 1), (5, -1), (0, 7)], ring=4,
                                   segs=[(0, 2), (1, 3), (4, 5), (4, 6), (6, 1)], split=1, angle=25, lines=1)
    yield "crossing_at_vertex", encode([(-4, -4), (4, -4), (4, 4), (-4, 4), (0, 0)], ring=4,
                                       segs=[(0, 2), (1, 3)], angle=20)
    yield "vertex_on_segment", encode([(-4, 0), (4, 0), (0, 0), (0, 4), (0, -4)], segs=[(0, 1), (2, 3)],
                                      convex_hull=1, angle=30)
    yield "collinear_only", encode([(i, 2 * i - 1) for i in range(-3, 5)], segs=[(0, 7), (1, 3)])
    yield "collinear_overlaps", encode([(i, 0) for i in range(-6, 7, 2)] + [(0, 5), (0, -5)],
                                       segs=[(0, 6), (1, 3), (2, 5), (0, 7), (6, 8), (7, 8), (8, 0)],
                                       conforming=1)
    yield "duplicates", encode([(0, 0), (5, 0), (0, 5), (0, 0), (5, 0), (2, 2)], ring=3, segs=[(3, 4), (0, 0)],
                               angle=25, bsteiner=0)
    yield "small_angle_wedge", encode([(-8, 0), (8, 0), (8, 1)], ring=3, angle=33)
    yield "small_angle_fan", encode([(0, 0), (8, 1), (8, 2), (8, 3), (1, 8), (-8, -8)],
                                    segs=[(0, 1), (0, 2), (0, 3), (0, 4), (1, 5), (5, 4), (1, 2), (2, 3), (3, 4)],
                                    angle=30, convex_hull=1)
    yield "cocircular_ring", encode(circle, ring=len(circle), even_odd=1, angle=30, area=0.5)
    yield "cocircular_steiner_limit", encode(circle + [(0, 0)], ring=len(circle), angle=33, steiner="small",
                                             k=9, bsteiner=-1)
    # the cover stage: the mesh made, refined with its triangles as the domain (-r)
    yield "cover_square_hole", encode(sq + inner, ring=4, segs=hole_segs, holes=[(0, 0)],
                                      cover=cover_byte(segments=1, area_start=1, angle=30))
    yield "cover_hull_area", encode([(-8, -8), (8, -8), (8, 8), (-8, 8), (0, 3), (-2, -1)], convex_hull=1,
                                    segs=[(4, 5)], cover=cover_byte(area=2))
    yield "cover_wedge_angle", encode([(-8, 0), (8, 0), (8, 3), (0, 6)], ring=4, angle=20, attr=1,
                                      cover=cover_byte(angle=30, area=2, area_start=2))
    yield "cover_offset", encode(sq + inner, ring=4, segs=hole_segs, regions=[(0, 0, 2, 1)], mode=3, k=-30,
                                 cover=cover_byte(segments=1, area_start=3, angle=25, area=2))
    yield "cover_allocation_failure", encode(sq + inner, ring=4, segs=hole_segs, holes=[(0, 0)], fail=700,
                                             cover=cover_byte(area_start=1, angle=20))
    yield "allocation_failure", encode(sq + inner, ring=4, segs=hole_segs, holes=[(0, 0)], angle=20,
                                       fail=300)


def main(out):
    os.makedirs(out, exist_ok=True)
    for name, data in seeds():
        with open(os.path.join(out, "seed-" + name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "seeds")
