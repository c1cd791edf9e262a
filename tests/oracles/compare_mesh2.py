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

The code, in this folder: mesh2_exact (predicates), mesh2_input (readers), mesh2_domain
(the domain and its area), mesh2_quality (the quality checks).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mesh2_domain import domain_area_even_odd, domain_triangle_rule, split_segments  # noqa: E402
from mesh2_exact import cocircular_ties  # noqa: E402
from mesh2_input import InputError, Mesh, read_input  # noqa: E402
from mesh2_quality import fmt_pt, quality_report, small_input_angles  # noqa: E402


def check_cdt(args, g, A, B, name):
    """cdt: A and B are the same triangles (or differ only by cocircular ties) -> exit status."""
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


def check_quality(args, g, A, B, name):
    """quality: angles, segments, holes and area of A (and B, for information), and the
    triangle count ratio -> exit status."""
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
        return check_cdt(args, g, A, B, name)
    return check_quality(args, g, A, B, name)


if __name__ == '__main__':
    sys.exit(main())
