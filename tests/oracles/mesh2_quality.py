"""The quality checks of compare_mesh2.py on one mesh: angles (with the small-input-angle and
shell exemptions), segments as chains of mesh edges, empty holes, and area."""

import math
from fractions import Fraction

from mesh2_domain import split_segments
from mesh2_exact import dot_sign, orient


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
