"""Order-independent comparisons of Qhull's and lifthull's outputs for qhull_golden.py: facet
sets and parities, neighbours (Fn, FN) with their negative ids, o and coordinate rows."""

from collections import Counter
from fractions import Fraction

from golden_parse import Fail, maxdiff, parity


def facet_sets(rows, what):
    fs = [frozenset(r) for r in rows]
    if len(set(fs)) != len(fs):
        raise Fail("%s: a facet is listed twice" % what)
    return fs


def compare_facets(q_rows, l_rows, check_parity):
    qf = facet_sets(q_rows, "Qhull")
    lf = facet_sets(l_rows, "lifthull")
    only_q, only_l = set(qf) - set(lf), set(lf) - set(qf)
    if only_q or only_l:
        ex = sorted(only_q, key=sorted)[:1] or sorted(only_l, key=sorted)[:1]
        raise Fail("facets differ: %d only in Qhull, %d only in lifthull (e.g. %s in %s)"
                   % (len(only_q), len(only_l), sorted(ex[0]),
                      "Qhull" if only_q else "lifthull"))
    if check_parity:
        qp = {frozenset(r): parity(r) for r in q_rows}
        bad = [r for r in l_rows if parity(r) != qp[frozenset(r)]]
        if bad:
            raise Fail("%d of %d facets have the opposite vertex-order parity (e.g. %s)"
                       % (len(bad), len(l_rows), bad[0]))
    return "%d facets%s" % (len(qf), ", parity equal" if check_parity else "")


def neg_bijection(q_neg_of_side, l_neg_of_side):
    """Both: {(facet vertex set, opposite vertex): negative id}. Checks that the ids of the two
    sides correspond one to one; -> (ok, qhull id -> lifthull id)."""
    if set(q_neg_of_side) != set(l_neg_of_side):
        raise Fail("the sides with a negative neighbour differ (%d in Qhull, %d in lifthull)"
                   % (len(q_neg_of_side), len(l_neg_of_side)))
    fwd, back = {}, {}
    for side, q in q_neg_of_side.items():
        lid = l_neg_of_side[side]
        if fwd.setdefault(q, lid) != lid or back.setdefault(lid, q) != q:
            return False, None
    return True, fwd


def sides_of(name, i_rows, align, fn_rows):
    """-> (facet vertex set -> Counter of neighbour vertex sets, {(facet, opposite vertex):
    negative id} or None when `align` (each facet's vertices in the order of its neighbours)
    does not put every main neighbour opposite its vertex, per-facet negative counts)."""
    if len(i_rows) != len(fn_rows) or (align is not None and len(align) != len(fn_rows)):
        raise Fail("%s: Fn has %d facets, i has %d" % (name, len(fn_rows), len(i_rows)))
    sets = [frozenset(r) for r in i_rows]
    pos, negcount, neg = {}, {}, {}
    for f, nb in enumerate(fn_rows):
        s = sets[f]
        if len(nb) != len(i_rows[f]):
            raise Fail("%s: facet %d has %d neighbours" % (name, f, len(nb)))
        for g in nb:
            if g >= len(sets):
                raise Fail("%s: neighbour id %d out of range" % (name, g))
            if g >= 0:
                if len(s & sets[g]) != len(s) - 1:
                    raise Fail("%s: facets %s and %s listed as neighbours share %d vertices"
                               % (name, sorted(s), sorted(sets[g]), len(s & sets[g])))
                pos.setdefault(s, Counter())[sets[g]] += 1
        covered = {next(iter(s - sets[g])) for g in nb if g >= 0}
        negs = [g for g in nb if g < 0]
        if len(s) - len(covered) != len(negs):
            raise Fail("%s: facet %s: %d open sides but %d negative neighbours"
                       % (name, sorted(s), len(s) - len(covered), len(negs)))
        negcount[s] = len(negs)
        if neg is not None and align is not None:
            order = align[f]
            if frozenset(order) != s:
                raise Fail("%s: Fv/i facet %d differs" % (name, f))
            for k, g in enumerate(nb):
                if g >= 0 and s - sets[g] != {order[k]}:
                    neg = None
                    break
                if g < 0:
                    neg[(s, order[k])] = g
    return pos, (neg if align is not None else None), negcount


def compare_fn(q_i, q_align, q_fn, l_i, l_align, l_fn, upper_merged):
    """Fn of both sides, each with its own `i` (same facet order) and the facets' vertices in
    the order of their neighbours (Qhull's Fv, lifthull's i) or None."""
    qp, qn, qc = sides_of("Qhull", q_i, q_align, q_fn)
    lp, ln, lc = sides_of("lifthull", l_i, l_align, l_fn)
    if qp != lp:
        bad = next(k for k in set(qp) | set(lp) if qp.get(k) != lp.get(k))
        raise Fail("the neighbours of facet %s differ" % sorted(bad))
    if qc != lc:
        bad = next(k for k in set(qc) | set(lc) if qc.get(k) != lc.get(k))
        raise Fail("facet %s: %s negative neighbours in Qhull, %s in lifthull"
                   % (sorted(bad), qc.get(bad), lc.get(bad)))
    nneg = sum(qc.values())
    if nneg == 0:
        return "neighbours equal", {}
    why = None
    if qn is None or ln is None:
        why = "%s's neighbours are not opposite their vertices" % ("Qhull" if qn is None else "lifthull")
    else:
        ok, fwd = neg_bijection(qn, ln)
        if ok:
            return "neighbours equal; %d negative ids correspond one to one (%d upper facets)" \
                % (nneg, len(fwd)), fwd
        if not upper_merged:
            raise Fail("Qhull's negative ids and lifthull's do not correspond one to one")
        why = "Qhull merged upper facets"
    return "neighbours equal; %d negative ids equal in count per facet (%s)" % (nneg, why), None


def compare_fN(q_i, q_fN, l_i, l_fN, n, neg_map):
    if len(q_fN) != n or len(l_fN) != n:
        raise Fail("FN lists %d (Qhull) and %d (lifthull) sites, not %d" % (len(q_fN), len(l_fN), n))
    qs = [frozenset(r) for r in q_i]
    ls = [frozenset(r) for r in l_i]
    npos = 0
    for site in range(n):
        qpos = Counter(qs[g] for g in q_fN[site] if g >= 0)
        lpos = Counter(ls[g] for g in l_fN[site] if g >= 0)
        if any(site not in f for f in qpos) or any(site not in f for f in lpos):
            raise Fail("site %d: a listed facet does not contain it" % site)
        if qpos != lpos:
            raise Fail("site %d: its facets differ (%d in Qhull, %d in lifthull)"
                       % (site, sum(qpos.values()), sum(lpos.values())))
        npos += sum(qpos.values())
        qneg = [g for g in q_fN[site] if g < 0]
        lneg = [g for g in l_fN[site] if g < 0]
        if neg_map is not None:
            image = set(neg_map.values())
            qm = sorted(neg_map[g] for g in qneg if g in neg_map)
            lm = sorted(g for g in lneg if g in image)
            if qm != lm or len(qneg) - len(qm) != len(lneg) - len(lm):
                raise Fail("site %d: its upper facets differ (Qhull %s, lifthull %s)"
                           % (site, qneg, lneg))
        elif len(qneg) != len(lneg):
            raise Fail("site %d: %d upper facets in Qhull, %d in lifthull"
                       % (site, len(qneg), len(lneg)))
    return "%d sites, %d incidences equal, upper facets %s" \
        % (n, npos, "mapped one to one (those next to a Delaunay facet; the others by count)"
           if neg_map is not None else "equal in count")


def compare_o_delaunay(q, l, ex, lifted):
    qdim, qhead, qc, qrows = q
    ldim, lhead, lc, lrows = l
    if qdim != ldim or qhead != lhead:
        raise Fail("header %d / %s in Qhull, %d / %s in lifthull" % (qdim, qhead, ldim, lhead))
    d = ex.d
    tol = 1e-15 * ex.extent
    for i, (a, b) in enumerate(zip(qc, lc)):
        if maxdiff(a[:d], b[:d]) > tol:
            raise Fail("point %d: coordinates differ by %.3g" % (i, maxdiff(a[:d], b[:d])))
    zerr = 0.0
    if lifted:
        zmax = max([1e-300] + [abs(a[d]) for a in qc])
        zerr = max([0.0] + [abs(a[d] - b[d]) for a, b in zip(qc, lc)]) / zmax
        if zerr > lift_tolerance(ex):
            raise Fail("the lifted coordinate differs by %.3g of its maximum (> %.3g)"
                       % (zerr, lift_tolerance(ex)))
    msg = compare_facets(qrows, lrows, False)
    return "header %s, %d points%s, %s" % (qhead, len(qc),
                                           ", lifted coordinate within %.2g" % zerr if lifted else "",
                                           msg)


def lift_tolerance(ex):
    """Relative tolerance of the lifted coordinate: 1e-12, or more when Qbb's scaling
    (extent / (max |p|^2 - min |p|^2)) magnifies the rounding of |p|^2 (nearly cospherical
    sites)."""
    z = [sum(x * x for x in p) for p in ex.pts]
    spread = max(z) - min(z)
    if spread <= 0:
        return 1e-12
    return max(1e-12, 8e-16 * max(z) / spread)


def bisector(a, b):
    """The hyperplane n.x + off = 0 of points equidistant from a and b, n from a to b."""
    n = [Fraction(y) - Fraction(x) for x, y in zip(a, b)]
    mid = [(Fraction(x) + Fraction(y)) / 2 for x, y in zip(a, b)]
    off = -sum(x * y for x, y in zip(n, mid))
    length = float(sum(x * x for x in n)) ** 0.5
    return [float(x) / length for x in n] + [float(off) / length]


def plane_diff(p, ref, scale):
    d = len(ref) - 1
    return max(maxdiff(p[:d], ref[:d]), abs(p[d] - ref[d]) / scale)


def compare_point_rows(qrows, lrows, tol, what):
    """Order-independent equality of coordinate rows (multisets within tol)."""
    if len(qrows) != len(lrows):
        raise Fail("%s: %d rows in Qhull, %d in lifthull" % (what, len(qrows), len(lrows)))
    qs, ls = sorted(qrows), sorted(lrows)
    worst = max([0.0] + [maxdiff(a, b) for a, b in zip(qs, ls)])
    if worst > tol:
        raise Fail("%s: rows differ by %.3g (> %.3g)" % (what, worst, tol))
    return worst
