#!/usr/bin/env python3
"""Golden tests of `lifthull qdelaunay | qvoronoi | qconvex` against Qhull's programs, on the
point sets of Qhull's own tests (issue #4).

  qhull_golden.py --lifthull LIFTHULL [--rbox R] [--qdelaunay Q] [--qvoronoi Q] [--qconvex Q]
                  [--invocations FILE] [--shard K/N] [--only REGEX] [--limit K] [-v]

The sets: the distinct rbox specifications of Section A of tests/data/qhull/rbox_invocations.txt
(extracted from Qhull's eg/q_test, q_eg, q_egtest). A specification is skipped when it is not
a plain rbox command (quotes, `qhull`, `eg-*` words: those lines feed user_eg programs), uses
`h` (Geomview output), fails in this rbox, or makes more than 8 (or fewer than 2) dimensions.
A bare `t` (seed from the clock) becomes `t1`, and the point count is capped per dimension
(CAP below) by editing the count token, so every run sees the same points. Sets with the same
points are run once.

Each set is classified:
  lowdim      the points span less than d dimensions (exact rank): lifthull must refuse with
              its "affine subspace" message (Qhull's failure is recorded);
  general     no duplicate points, `qdelaunay s` (without Qt) succeeds with no non-simplicial
              Delaunay region, and `qdelaunay Qt i` gives the same simplices as lifthull — or,
              when they differ, Qhull's simplices fail the exact check (then: `inexact`);
  degenerate  everything else (Qhull failed, merged facets, duplicates) and `inexact`.
(and separately for the hull: `qconvex s` without non-simplicial facets, no duplicates.)

General sets: Qhull and lifthull run with the same options (Qt added to qdelaunay's) and the
outputs are compared structurally and order-independently:
  qdelaunay  i (vertex sets, and the parity of each facet's vertex order), Fn (neighbours as
             vertex sets; Qhull's negative ids and lifthull's -(j+1) must correspond one to
             one across all hull sides, unless Qhull merged upper facets: then by count),
             FN (per site), o (header, coordinates to 1e-15, lifted coordinate to 1e-12 of
             its maximum, facets), p, Fv, Fx, Qu i (when the furthest-site facets are simplices)
  qvoronoi   o (vertices matched through their Delaunay simplices; each within 1e-12 of the
             exact circumcentre relative to the set's extent; Qhull's own error reported;
             regions per site as vertex sets, bounded/unbounded, cyclic order in 2D), p, Fv,
             Fi, Fo (site pairs, vertex sets, hyperplanes to 1e-12), FN
  qconvex    i (with parity), o, n, Fn, FN, Fv, Fx, p, FC (planes and centrums to 1e-12)
Degenerate sets: lifthull's `qdelaunay i` must pass tests/oracles/exact_check.py (--limit K
facets of each kind), use every distinct site, and its simplices' volumes must add up exactly
to the volume of lifthull's `qconvex i` hull (no double covering); `qconvex i` must have every
input point inside or on every facet's plane (exact), d affinely independent vertices per
facet and every ridge in exactly two facets; where Qhull computed a volume (FA), it agrees.

Prints one line per (set, program, options) with PASS/FAIL/SKIP and a reason, then a summary.
Exit 0 if nothing failed, 1 otherwise, 2 on bad usage. LH_GOLDEN_LIFTHULL in the environment
replaces --lifthull (to run the test against a deliberately broken wrapper).
"""

import argparse
import hashlib
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_check import det_int  # noqa: E402  (Bareiss, exact)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_INVOCATIONS = os.path.join(HERE, "..", "data", "qhull", "rbox_invocations.txt")
EXACT_CHECK = os.path.join(HERE, "exact_check.py")

# Largest point count per dimension (keeps a run of all sets at about a minute on one core).
CAP = {2: 2000, 3: 1000, 4: 400, 5: 150, 6: 80, 7: 50, 8: 30}
# LH_TEST_SCALE (the sanitizer run sets 0.2) shrinks the caps, never below 2d + 2 points.
_SCALE = float(os.environ.get("LH_TEST_SCALE", "1"))
CAP = {d: max(2 * d + 2, int(c * _SCALE)) for d, c in CAP.items()}
TIMEOUT = 120


class Fail(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# running programs


def run(cmd, data, timeout=TIMEOUT):
    """Runs cmd (a list) with data on standard input -> (returncode, stdout, stderr)."""
    try:
        p = subprocess.run(cmd, input=data, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=timeout, universal_newlines=True)
    except subprocess.TimeoutExpired:
        return 124, "", "timed out after %d s" % timeout
    return p.returncode, p.stdout, p.stderr


def qhull_error(err):
    m = re.search(r"QH(\d{4})", err)
    return ("QH" + m.group(1)) if m else (err.strip().splitlines() or ["failed"])[0][:60]


# ---------------------------------------------------------------------------------------------
# the sets


def read_specs(path):
    specs, in_a = [], False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("# === Section A"):
                in_a = True
                continue
            if line.startswith("# === Section"):
                if in_a:
                    break
                continue
            if not in_a or line.startswith("#") or not line.strip():
                continue
            parts = line.rstrip("\n").split("\t", 1)
            if len(parts) == 2:
                specs.append(parts[1].strip())
    return specs


TOKEN = re.compile(r"^([0-9]+|[A-Za-z][-+0-9.,eE]*)$")


def normalize(spec):
    """-> (tokens after 'rbox', None) or (None, why skipped)."""
    toks = spec.split()
    if not toks or toks[0] != "rbox":
        return None, "not an rbox command"
    toks = toks[1:]
    if any(c in spec for c in "'\"|"):
        return None, "quoted arguments (a user_eg pipeline)"
    for t in toks:
        if not TOKEN.match(t) or (t[0].isalpha() and len(t) > 1 and t[1].isalpha()):
            return None, "not an rbox option: %s" % t
        if t[0] == "h":
            return None, "h (Geomview/homogeneous output)"
    return ["t1" if t == "t" else t for t in toks], None


def cap_count(toks, d):
    out = []
    for t in toks:
        if t.isdigit() and int(t) > CAP[d]:
            t = str(CAP[d])
        out.append(t)
    return out


def parse_points(text):
    lines = text.split("\n")
    head = lines[0].split()
    d = int(head[0])
    n = int(lines[1].split()[0])
    pts = []
    for ln in lines[2:2 + n]:
        pts.append([float(x) for x in ln.split()])
    if len(pts) != n or any(len(p) != d for p in pts):
        raise ValueError("malformed rbox output")
    return d, pts


def make_sets(args, log):
    sets, seen, skipped = [], {}, []
    for spec in read_specs(args.invocations):
        toks, why = normalize(spec)
        if toks is None:
            skipped.append((spec, why))
            continue
        rc, out, err = run([args.rbox] + toks, "")
        if rc != 0 or not out.strip():
            skipped.append((spec, "rbox failed: %s" % (err.strip().splitlines() or ["?"])[0]))
            continue
        try:
            d = int(out.split()[0])
        except ValueError:
            skipped.append((spec, "unreadable rbox output"))
            continue
        if d < 2 or d > 8:
            skipped.append((spec, "%d dimensions" % d))
            continue
        capped = cap_count(toks, d)
        if capped != toks:
            rc, out, err = run([args.rbox] + capped, "")
            if rc != 0:
                skipped.append((spec, "rbox failed after capping"))
                continue
        try:
            d, pts = parse_points(out)
        except (ValueError, IndexError):
            skipped.append((spec, "unreadable rbox output"))
            continue
        body = "\n".join(out.split("\n")[1:])
        key = hashlib.sha1(("%d\n" % d + body).encode()).hexdigest()
        name = "rbox " + " ".join(capped)
        if key in seen:
            continue
        seen[key] = name
        # the point file as lifthull and Qhull read it (rbox's own text)
        sets.append({"name": name, "spec": spec, "d": d, "pts": pts, "text": out})
    for spec, why in skipped:
        log("SKIP  %-34s %s" % (spec, why))
    return sets, skipped


# ---------------------------------------------------------------------------------------------
# exact arithmetic on the points


def rank_int(rows):
    """Rank of an integer matrix (fraction-free elimination)."""
    m = [r[:] for r in rows if any(r)]
    if not m:
        return 0
    cols = len(m[0])
    rank = 0
    for c in range(cols):
        piv = next((r for r in range(rank, len(m)) if m[r][c] != 0), None)
        if piv is None:
            continue
        m[rank], m[piv] = m[piv], m[rank]
        p = m[rank]
        for r in range(rank + 1, len(m)):
            if m[r][c]:
                f = m[r][c]
                m[r] = [x * p[c] - y * f for x, y in zip(m[r], p)]
        rank += 1
        if rank == len(m):
            break
    return rank


class Exact:
    """The points as integers (a common power-of-two scale)."""

    def __init__(self, pts):
        fr = [[Fraction(x) for x in p] for p in pts]
        self.den = max([1] + [f.denominator for p in fr for f in p])
        self.ip = [[int(f * self.den) for f in p] for p in fr]
        self.d = len(pts[0])
        self.pts = pts
        self.extent = max([1e-300] + [abs(x) for p in pts for x in p])
        lo = [min(p[j] for p in pts) for j in range(self.d)]
        hi = [max(p[j] for p in pts) for j in range(self.d)]
        self.diameter = max(1e-300, sum((h - l) ** 2 for h, l in zip(hi, lo)) ** 0.5)
        self._cc = {}

    def affine_rank(self):
        b = self.ip[0]
        return rank_int([[x - y for x, y in zip(p, b)] for p in self.ip[1:]])

    def has_duplicates(self):
        return len(set(map(tuple, self.ip))) != len(self.ip)

    def vol(self, s):
        b = self.ip[s[0]]
        return det_int([[self.ip[v][j] - b[j] for j in range(self.d)] for v in s[1:]])

    def condition(self, s):
        """R * max(1, maxedge^d / |det|): the error scale of a floating-point solve for the
        circumcentre relative to the first vertex (R: its distance from that vertex)."""
        c = self.circumcenter(s)
        v0 = self.pts[s[0]] if isinstance(s, (list, tuple)) else self.pts[min(s)]
        r = sum((a - b) ** 2 for a, b in zip(c, v0)) ** 0.5
        s = sorted(s)
        e = max(sum((a - b) ** 2 for a, b in zip(self.pts[u], self.pts[v])) ** 0.5
                for u in s for v in s if u < v)
        vol = abs(self.vol(s)) / float(self.den) ** self.d
        return r * max(1.0, e ** self.d / vol if vol else 1e300)

    def plane(self, f):
        """The exact hull plane of facet f (d vertices), outward (the points on its <= 0 side),
        normalized in floating point -> (normal + [offset], condition)."""
        d = self.d
        b = self.ip[f[0]]
        e = [[self.ip[v][j] - b[j] for j in range(d)] for v in f[1:]]
        nrm = [(-1) ** j * det_int([r[:j] + r[j + 1:] for r in e]) for j in range(d)]
        off = -sum(x * y for x, y in zip(nrm, b))
        side = 0
        for p in self.ip:
            side = sum(x * y for x, y in zip(nrm, p)) + off
            if side:
                break
        if side > 0:
            nrm, off = [-x for x in nrm], -off
        length = float(sum(x * x for x in nrm)) ** 0.5
        fe = [[self.pts[v][j] - self.pts[f[0]][j] for j in range(d)] for v in f[1:]]
        emax = max([1e-300] + [sum(x * x for x in r) ** 0.5 for r in fe])
        cond = max(1.0, emax ** (d - 1) / (length / float(self.den) ** (d - 1)))
        return [x / length for x in nrm] + [off / length / self.den], cond

    def circumcenter(self, s):
        """Exact circumcentre of simplex s (sorted tuple) -> list of floats (correctly rounded)."""
        s = tuple(sorted(s))
        if s in self._cc:
            return self._cc[s]
        d = self.d
        b = self.ip[s[0]]
        a = [[self.ip[v][j] - b[j] for j in range(d)] for v in s[1:]]
        rhs = [sum(x * x for x in r) for r in a]
        den = 2 * det_int(a)
        c = []
        for j in range(d):
            m = [r[:j] + [rhs[i]] + r[j + 1:] for i, r in enumerate(a)]
            c.append(float(Fraction(det_int(m) + den * b[j], den * self.den)))
        self._cc[s] = c
        return c


# ---------------------------------------------------------------------------------------------
# parsers of Qhull's formats


def lines_of(text):
    return [ln for ln in text.split("\n") if ln.strip()]


def parse_index_list(text, first_is_width, what):
    """`i` (first_is_width False) or Fv/Fn/FN (each line starts with its length)."""
    ls = lines_of(text)
    if not ls:
        raise Fail("%s: empty output" % what)
    count = int(ls[0])
    rows = []
    for ln in ls[1:]:
        v = [int(t) for t in ln.split()]
        if first_is_width:
            if not v or v[0] != len(v) - 1:
                raise Fail("%s: line %r: wrong length" % (what, ln))
            v = v[1:]
        rows.append(v)
    if len(rows) != count:
        raise Fail("%s: count %d but %d lines" % (what, count, len(rows)))
    return rows


def parse_coords(text, what):
    """p, n, FC: dim, count, rows of floats."""
    ls = lines_of(text)
    dim, count = int(ls[0]), int(ls[1])
    rows = [[float(t) for t in ln.split()] for ln in ls[2:]]
    if len(rows) != count or any(len(r) != dim for r in rows):
        raise Fail("%s: malformed (dim %d, count %d, %d rows)" % (what, dim, count, len(rows)))
    return dim, rows


def parse_o(text, what):
    """-> (dim, header ints, coordinate rows, index rows)."""
    ls = lines_of(text)
    dim = int(ls[0])
    head = [int(t) for t in ls[1].split()]
    npts = head[0]
    coords = [[float(t) for t in ln.split()] for ln in ls[2:2 + npts]]
    if any(len(r) != dim for r in coords):
        raise Fail("%s: coordinate rows are not %d wide" % (what, dim))
    rows = []
    for ln in ls[2 + npts:]:
        v = [int(t) for t in ln.split()]
        if not v or v[0] != len(v) - 1:
            raise Fail("%s: line %r: wrong length" % (what, ln))
        rows.append(v[1:])
    return dim, head, coords, rows


def parse_ridges(text, what, d):
    """qvoronoi Fi/Fo: count, then "d+3 i j coeffs" -> {(i, j): coeffs}."""
    ls = lines_of(text)
    count = int(ls[0])
    out = {}
    for ln in ls[1:]:
        t = ln.split()
        if int(t[0]) != len(t) - 1 or len(t) != d + 4:
            raise Fail("%s: line %r: wrong length" % (what, ln))
        out[(int(t[1]), int(t[2]))] = [float(x) for x in t[3:]]
    if len(out) != count or len(ls) - 1 != count:
        raise Fail("%s: count %d but %d distinct ridges" % (what, count, len(out)))
    return out


def parity(seq):
    """0 for an even permutation of sorted(seq), 1 for odd."""
    seq = list(seq)
    p = 0
    for i in range(len(seq)):
        for j in range(i + 1, len(seq)):
            p ^= seq[i] > seq[j]
    return p


def close(a, b, tol):
    return all(abs(x - y) <= tol for x, y in zip(a, b)) and len(a) == len(b)


def maxdiff(a, b):
    return max([0.0] + [abs(x - y) for x, y in zip(a, b)])


# ---------------------------------------------------------------------------------------------
# comparisons


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


# ---------------------------------------------------------------------------------------------
# the degenerate checks


def exact_check_i(args, set_text, i_text, tmp):
    pf = os.path.join(tmp, "pts.txt")
    sf = os.path.join(tmp, "simp.txt")
    with open(pf, "w") as f:
        f.write(set_text)
    with open(sf, "w") as f:
        f.write(i_text)
    cmd = [sys.executable, EXACT_CHECK, pf, sf]
    if args.limit:
        cmd += ["--limit", str(args.limit)]
    rc, out, err = run(cmd, "")
    last = (out.strip().splitlines() or [err.strip()])[-1]
    return rc == 0, last


def check_hull_exact(ex, rows):
    """Every point inside or on every facet's plane, d independent vertices a facet, every ridge
    in two facets. -> (sum over facets of |det(facet - p0)|) (d! times the volume)."""
    d = ex.d
    ridges = Counter()
    total = 0
    p0 = ex.ip[0]
    for f in rows:
        if len(f) != d or len(set(f)) != d:
            raise Fail("hull facet %s has not %d distinct vertices" % (f, d))
        b = ex.ip[f[0]]
        e = [[ex.ip[v][j] - b[j] for j in range(d)] for v in f[1:]]
        normal = [(-1) ** j * det_int([r[:j] + r[j + 1:] for r in e]) for j in range(d)]
        if not any(normal):
            raise Fail("hull facet %s: its vertices are affinely dependent" % f)
        sides = set()
        for p in ex.ip:
            s = sum(normal[j] * (p[j] - b[j]) for j in range(d))
            if s:
                sides.add(s > 0)
                if len(sides) == 2:
                    raise Fail("hull facet %s: input points on both sides of its plane" % f)
        total += abs(sum(normal[j] * (p0[j] - b[j]) for j in range(d)))
        for k in range(d):
            ridges[frozenset(f[:k] + f[k + 1:])] += 1
    bad = [r for r, c in ridges.items() if c != 2]
    if bad:
        raise Fail("hull ridge %s is in %d facets" % (sorted(bad[0]), ridges[bad[0]]))
    return total


def qhull_volume(args, text):
    rc, out, err = run([args.qconvex, "FA", "s"], text)
    m = re.search(r"Total volume:\s*([-+0-9.eE]+)", out + err)
    return float(m.group(1)) if rc == 0 and m else None


# ---------------------------------------------------------------------------------------------
# one set


class Runner:
    def __init__(self, args, log):
        self.args = args
        self.log = log
        self.fails = 0
        self.passes = 0
        self.rows = []   # summary rows
        self.max_vor_err = 0.0     # lifthull vs exact circumcentre
        self.max_vor_qhull = 0.0   # Qhull vs exact circumcentre
        self.max_vor_diff = 0.0    # lifthull vs Qhull

    def result(self, s, prog, opts, ok, msg):
        tag = "PASS" if ok else "FAIL"
        if ok:
            self.passes += 1
        else:
            self.fails += 1
        self.log("%s  %-34s %-9s %-6s %s" % (tag, s["name"], prog, opts, msg))

    def qhull(self, prog, opts, s):
        exe = {"qdelaunay": self.args.qdelaunay, "qvoronoi": self.args.qvoronoi,
               "qconvex": self.args.qconvex}[prog]
        return run([exe] + opts.split(), s["text"])

    def lift(self, prog, opts, s):
        return run([self.args.lifthull, prog] + opts.split(), s["text"])

    def both(self, prog, opts, s, qt=True):
        """Runs Qhull (with Qt for qdelaunay) and lifthull -> (qhull out, lifthull out)."""
        qopts = opts + (" Qt" if qt and prog == "qdelaunay" else "")
        rc, qo, qe = self.qhull(prog, qopts, s)
        if rc != 0:
            raise Fail("Qhull failed (%s)" % qhull_error(qe))
        rc, lo, le = self.lift(prog, opts, s)
        if rc != 0:
            raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
        return qo, lo

    def upper_exact(self, s):
        """Whether lifthull's furthest-site triangulation passes its exact check (Tv)."""
        rc, out, err = self.lift("qdelaunay", "Qu Tv s", s)
        return rc == 0 and "the exact check passed" in err

    def check_upper(self, s, prog, opts, fn):
        """check() for the outputs that show the upper hull (Qu i, Fn, FN): where they
        differ from Qhull's on nearly cospherical hull sites, Qhull's rounding can be the
        cause; lifthull's passes when its furthest-site triangulation is exactly valid."""
        def guarded():
            try:
                return fn()
            except Fail as e:
                if not self.upper_exact(s):
                    raise
                return "differs from Qhull (%s); lifthull's furthest-site triangulation passes the exact check" % e
        return self.check(s, prog, opts, guarded)

    def check(self, s, prog, opts, fn):
        try:
            msg = fn()
            self.result(s, prog, opts, True, msg)
            return True
        except Fail as e:
            self.result(s, prog, opts, False, str(e))
        except (ValueError, IndexError, KeyError) as e:
            self.result(s, prog, opts, False, "unreadable output (%s: %s)" % (type(e).__name__, e))
        return False

    # -- classification ------------------------------------------------------------------------

    def classify(self, s, ex, tmp):
        """-> lowdim, general, degenerate or inexact; sets s["qhull_delaunay"]."""
        d = s["d"]
        s["qhull_delaunay"] = "ok"
        if ex.affine_rank() < d:
            rc, out, err = self.qhull("qdelaunay", "Qt i", s)
            s["qhull_delaunay"] = "failed " + qhull_error(err) if rc else "answered"
            return "lowdim"
        rc, out, err = self.qhull("qdelaunay", "s", s)
        text = out + err
        if rc != 0:
            s["qhull_delaunay"] = "failed " + qhull_error(err)
            return "degenerate"
        m = re.search(r"non-simplicial Delaunay regions:\s*(\d+)", text)
        if m and int(m.group(1)) > 0:
            s["qhull_delaunay"] = "merged (%s non-simplicial)" % m.group(1)
            return "degenerate"
        m = re.search(r"Number of merged facets:\s*(\d+)", text)
        if m and int(m.group(1)) > 0:
            # the lower hull is simplicial, the upper one (or a vertical wall over a hull
            # facet with coplanar sites) is not: its negative ids are not comparable
            s["qhull_delaunay"] = "merged upper facets (%s)" % m.group(1)
            return "degenerate"
        if ex.has_duplicates():
            s["qhull_delaunay"] = "duplicates"
            return "degenerate"
        if s.get("hull_coplanar"):
            s["qhull_delaunay"] = "coplanar hull sites"
            return "degenerate"
        rc, qo, qe = self.qhull("qdelaunay", "Qt i", s)
        rc2, lo, le = self.lift("qdelaunay", "i", s)
        if rc != 0:
            s["qhull_delaunay"] = "failed " + qhull_error(qe)
            return "degenerate"
        if rc2 != 0:
            return "general"  # the comparison reports lifthull's failure
        q = {frozenset(r) for r in parse_index_list(qo, False, "Qhull i")}
        l_ = {frozenset(r) for r in parse_index_list(lo, False, "lifthull i")}
        if q == l_:
            return "general"
        missing = len(ex.pts) - len(set().union(*q)) if q else len(ex.pts)
        if missing:
            s["qhull_delaunay"] = "inexact: %d sites missing from Qhull's i" % missing
            return "inexact"
        ok_q, msg_q = exact_check_i(self.args, s["text"], qo, tmp)
        if not ok_q:
            s["qhull_delaunay"] = "inexact: %d simplices differ, Qhull's fail the exact check" \
                % len(q ^ l_)
            return "inexact"
        return "general"  # Qhull's is a Delaunay triangulation too: the comparison decides

    def classify_hull(self, s, ex):
        """Whether the hull is in general position for Qhull: `qconvex Qc s` without merged or
        non-simplicial facets, coplanar points or duplicates."""
        if ex.affine_rank() < s["d"]:
            s["qhull_convex"] = "lowdim"
            return False
        rc, out, err = self.qhull("qconvex", "Qc s", s)
        text = out + err
        if rc != 0:
            s["qhull_convex"] = "failed " + qhull_error(err)
            return False
        for what, pat in (("non-simplicial", r"non-simplicial facets:\s*(\d+)"),
                          ("merged", r"Number of merged facets:\s*(\d+)"),
                          ("coplanar points", r"Number of coplanar points:\s*(\d+)")):
            m = re.search(pat, text)
            if m and int(m.group(1)) > 0:
                s["qhull_convex"] = "%s (%s)" % (what, m.group(1))
                s["hull_coplanar"] = True  # sites on the hull that are no vertices of it
                return False
        if ex.has_duplicates():
            s["qhull_convex"] = "duplicates"
            return False
        s["qhull_convex"] = "ok"
        return True

    # -- general position ----------------------------------------------------------------------

    def general_delaunay(self, s, ex):
        n = len(s["pts"])
        st = {}

        def i():
            qo, lo = self.both("qdelaunay", "i", s)
            st["qi"] = parse_index_list(qo, False, "Qhull i")
            st["li"] = parse_index_list(lo, False, "lifthull i")
            return compare_facets(st["qi"], st["li"], True)

        if not self.check(s, "qdelaunay", "i", i):
            return

        def fn():
            qo, lo = self.both("qdelaunay", "Fn", s)
            rc, qv, qe = self.qhull("qdelaunay", "Qt Fv", s)
            qalign = parse_index_list(qv, True, "Qhull Fv") if rc == 0 else None
            msg, st["neg"] = compare_fn(st["qi"], qalign, parse_index_list(qo, True, "Qhull Fn"),
                                        st["li"], st["li"], parse_index_list(lo, True, "lifthull Fn"),
                                        False)
            return msg

        self.check_upper(s, "qdelaunay", "Fn", fn)

        def fN():
            qo, lo = self.both("qdelaunay", "FN", s)
            return compare_fN(st["qi"], parse_index_list(qo, True, "Qhull FN"), st["li"],
                              parse_index_list(lo, True, "lifthull FN"), n, st.get("neg"))

        self.check_upper(s, "qdelaunay", "FN", fN)

        def o():
            qo, lo = self.both("qdelaunay", "o", s)
            return compare_o_delaunay(parse_o(qo, "Qhull o"), parse_o(lo, "lifthull o"), ex, True)

        self.check(s, "qdelaunay", "o", o)

        def p():
            qo, lo = self.both("qdelaunay", "p", s)
            qd, qr = parse_coords(qo, "Qhull p")
            ld, lr = parse_coords(lo, "lifthull p")
            if qd != ld:
                raise Fail("dimension %d in Qhull, %d in lifthull" % (qd, ld))
            zmax = max([1e-300] + [abs(r[-1]) for r in qr])
            w = compare_point_rows([r[:-1] for r in qr], [r[:-1] for r in lr], 1e-15 * ex.extent, "p")
            z = compare_point_rows(sorted(r[-1:] for r in qr), sorted(r[-1:] for r in lr),
                                   lift_tolerance(ex) * zmax, "p (lifted)")
            return "%d vertices, coordinates within %.2g, lifted within %.2g" % (len(qr), w, z)

        self.check(s, "qdelaunay", "p", p)

        def fv():
            qo, lo = self.both("qdelaunay", "Fv", s)
            return compare_facets(parse_index_list(qo, True, "Qhull Fv"),
                                  parse_index_list(lo, True, "lifthull Fv"), False)

        self.check(s, "qdelaunay", "Fv", fv)

        def fx():
            qo, lo = self.both("qdelaunay", "Fx", s)
            q = sorted(int(t) for t in qo.split()[1:])
            l_ = sorted(int(t) for t in lo.split()[1:])
            if q != l_:
                raise Fail("extreme points differ: %s only in Qhull, %s only in lifthull"
                           % (sorted(set(q) - set(l_))[:5], sorted(set(l_) - set(q))[:5]))
            return "%d extreme points" % len(q)

        self.check(s, "qdelaunay", "Fx", fx)

        def qu():
            rc, out, err = self.qhull("qdelaunay", "Qu s", s)
            m = re.search(r"non-simplicial[^:]*:\s*(\d+)", out + err)
            if rc == 0 and m and int(m.group(1)) > 0:
                return "skipped: Qhull merged furthest-site facets (%s non-simplicial)" % m.group(1)
            qo, lo = self.both("qdelaunay", "Qu i", s)
            return compare_facets(parse_index_list(qo, False, "Qhull Qu i"),
                                  parse_index_list(lo, False, "lifthull Qu i"), False)

        self.check_upper(s, "qdelaunay", "Qu i", qu)

    def general_voronoi(self, s, ex):
        d = s["d"]
        st = {}

        def vertices():
            """Voronoi vertex k >= 1 of each side: the simplex of `qvoronoi i`'s row k - 1."""
            qo, lo = self.both("qvoronoi", "i", s)
            qi = parse_index_list(qo, False, "Qhull qvoronoi i")
            li = parse_index_list(lo, False, "lifthull qvoronoi i")
            compare_facets(qi, li, False)
            st["qv"] = [None] + [frozenset(r) for r in qi]
            st["lv"] = [None] + [frozenset(r) for r in li]
            qo, lo = self.both("qvoronoi", "o", s)
            st["qo"] = parse_o(qo, "Qhull o")
            st["lo"] = parse_o(lo, "lifthull o")
            return qi, li

        def o():
            qi, li = vertices()
            (qdim, qhead, qc, qregions), (ldim, lhead, lc, lregions) = st["qo"], st["lo"]
            if qdim != ldim or qhead != lhead:
                raise Fail("header %d / %s in Qhull, %d / %s in lifthull" % (qdim, qhead, ldim, lhead))
            if len(qc) != len(st["qv"]) or len(lc) != len(st["lv"]):
                raise Fail("vertex count is not the simplex count + 1")
            # relative error: |computed - exact| / max(|exact|, the sites' extent), allowed
            # 1e-12 times the simplex's condition max(1, R / diameter) (R: the distance
            # from the centre to the simplex; lh_tri_circumcenters is a floating-point solve)
            scale = max(ex.extent, ex.diameter)
            lerr = qerr = diff = 0.0
            ill = 0
            lpos = {f: k for k, f in enumerate(st["lv"]) if k}
            for k in range(1, len(qc)):
                f = st["qv"][k]
                c = ex.circumcenter(f)
                sc = max(scale, max(abs(x) for x in c))
                cond = ex.condition(f) / sc
                lk = lpos[f]
                le = maxdiff(lc[lk], c) / sc
                qe = maxdiff(qc[k], c) / sc
                df = maxdiff(lc[lk], qc[k]) / sc
                if cond > 1e2:
                    ill += 1
                else:
                    lerr, qerr, diff = max(lerr, le), max(qerr, qe), max(diff, df)
                cond = max(1.0, cond)
                if le > 1e-12 * cond:
                    raise Fail("lifthull's Voronoi vertex %d is %.3g (relative) from its exact "
                               "circumcentre (condition %.3g)" % (lk, le, cond))
                if df > 1e-12 * cond and qe <= 1e-12 * cond:
                    raise Fail("Voronoi vertex %d differs from Qhull's by %.3g relative" % (lk, df))
            self.max_vor_err = max(self.max_vor_err, lerr)
            self.max_vor_qhull = max(self.max_vor_qhull, qerr)
            self.max_vor_diff = max(self.max_vor_diff, diff)
            if qc[0] != [-10.101] * d or lc[0] != [-10.101] * d:
                raise Fail("vertex 0 is not -10.101 (infinity)")
            # regions: per site, the vertex sets (0 = infinity), and the cyclic order in 2D
            nb = 0
            for site, (qr, lr) in enumerate(zip(qregions, lregions)):
                qset = Counter(st["qv"][k] if k else 0 for k in qr)
                lset = Counter(st["lv"][k] if k else 0 for k in lr)
                if qset != lset:
                    raise Fail("site %d: regions differ (%d vertices in Qhull, %d in lifthull%s)"
                               % (site, len(qr), len(lr),
                                  "; bounded in one only" if (0 in qset) != (0 in lset) else ""))
                nb += bool(qr) and 0 not in qset
                if d == 2 and len(qr) > 2:
                    a = [st["qv"][k] if k else 0 for k in qr]
                    b = [st["lv"][k] if k else 0 for k in lr]
                    rots = [b[r:] + b[:r] for r in range(len(b))]
                    if a not in rots and a[::-1] not in rots:
                        raise Fail("site %d: region vertices not in Qhull's cyclic order" % site)
            if len(qregions) != len(s["pts"]) or len(lregions) != len(s["pts"]):
                raise Fail("not one region per site")
            return ("%d vertices (lifthull within %.2g, Qhull within %.2g of the exact "
                    "circumcentres, apart %.2g%s); %d regions equal (%d bounded)%s"
                    % (len(qc) - 1, lerr, qerr, diff,
                       "; %d ill-conditioned simplices within their tolerance" % ill if ill else "",
                       len(qregions), nb,
                       ", cyclic order equal" if d == 2 else ""))

        if not self.check(s, "qvoronoi", "o", o):
            return

        def p():
            qo, lo = self.both("qvoronoi", "p", s)
            qd, qr = parse_coords(qo, "Qhull p")
            ld, lr = parse_coords(lo, "lifthull p")
            if qd != ld or len(qr) != len(lr):
                raise Fail("dimension/count %d/%d in Qhull, %d/%d in lifthull"
                           % (qd, len(qr), ld, len(lr)))
            qc, lc = st["qo"][2][1:], st["lo"][2][1:]
            if not all(close(a, b, 0) for a, b in zip(qr, qc)) or \
                    not all(close(a, b, 0) for a, b in zip(lr, lc)):
                raise Fail("p and o list different vertices")
            return "%d vertices, as in o" % len(qr)

        self.check(s, "qvoronoi", "p", p)

        def fv():
            qo, lo = self.both("qvoronoi", "Fv", s)
            out = []
            for name, txt, vmap in (("Qhull", qo, st["qv"]), ("lifthull", lo, st["lv"])):
                rows = parse_index_list(txt, True, name + " Fv")
                r = {}
                for row in rows:
                    pair = (row[0], row[1])
                    if pair in r or pair[0] >= pair[1]:
                        raise Fail("%s: ridge %s listed twice or not i < j" % (name, pair))
                    verts = Counter(vmap[k] if k else 0 for k in row[2:])
                    for f in verts:
                        if f and not {pair[0], pair[1]} <= f:
                            raise Fail("%s: ridge %s: a vertex's simplex lacks the sites"
                                       % (name, pair))
                    r[pair] = verts
                out.append(r)
            q, l_ = out
            if set(q) != set(l_):
                raise Fail("ridges differ: %d only in Qhull, %d only in lifthull"
                           % (len(set(q) - set(l_)), len(set(l_) - set(q))))
            bad = [k for k in q if q[k] != l_[k]]
            if bad:
                raise Fail("ridge %s: vertices differ" % (bad[0],))
            st["unbounded"] = {k for k in q if 0 in q[k]}
            return "%d ridges equal (%d unbounded), each dual to a Delaunay facet" \
                % (len(q), len(st["unbounded"]))

        self.check(s, "qvoronoi", "Fv", fv)

        for opt in ("Fi", "Fo"):
            def ridges(opt=opt):
                qo, lo = self.both("qvoronoi", opt, s)
                q = parse_ridges(qo, "Qhull " + opt, d)
                l_ = parse_ridges(lo, "lifthull " + opt, d)
                if set(q) != set(l_):
                    raise Fail("site pairs differ: %d only in Qhull, %d only in lifthull"
                               % (len(set(q) - set(l_)), len(set(l_) - set(q))))
                if "unbounded" in st:
                    want = st["unbounded"] if opt == "Fo" else None
                    if want is not None and set(q) != want:
                        raise Fail("the unbounded ridges are not those of Fv")
                # both against the bisector of the two sites, normal from i towards j
                scale = max(1.0, ex.extent)
                lw = qw = 0.0
                qoff = 0
                for (a, b) in q:
                    ref = bisector(ex.pts[a], ex.pts[b])
                    lw = max(lw, plane_diff(l_[(a, b)], ref, scale))
                    e = plane_diff(q[(a, b)], ref, scale)
                    if e > 1e-12:
                        if plane_diff(q[(a, b)], [-x for x in ref], scale) <= 1e-12:
                            raise Fail("ridge %d %d: Qhull's hyperplane has the opposite "
                                       "orientation" % (a, b))
                        qoff += 1
                    else:
                        qw = max(qw, e)
                if lw > 1e-14:
                    raise Fail("a lifthull hyperplane is %.3g from the bisector" % lw)
                return "%d %s ridges equal, hyperplanes within %.2g of the bisectors (Qhull's " \
                    "within %.2g%s)" % (len(q), "bounded" if opt == "Fi" else "unbounded", lw, qw,
                                        ", %d of Qhull's further: its own error" % qoff
                                        if qoff else "")

            self.check(s, "qvoronoi", opt, ridges)

        def fN():
            qo, lo = self.both("qvoronoi", "FN", s)
            qi = [sorted(f) for f in st["qv"][1:]]
            li = [sorted(f) for f in st["lv"][1:]]
            return compare_fN(qi, parse_index_list(qo, True, "Qhull FN"), li,
                              parse_index_list(lo, True, "lifthull FN"), len(s["pts"]), None)

        self.check_upper(s, "qvoronoi", "FN", fN)

    def general_convex(self, s, ex):
        d = s["d"]
        n = len(s["pts"])
        st = {}

        def i():
            qo, lo = self.both("qconvex", "i", s)
            st["qi"] = parse_index_list(qo, False, "Qhull i")
            st["li"] = parse_index_list(lo, False, "lifthull i")
            return compare_facets(st["qi"], st["li"], True)

        if not self.check(s, "qconvex", "i", i):
            return

        def o():
            qo, lo = self.both("qconvex", "o", s)
            return compare_o_delaunay(parse_o(qo, "Qhull o"), parse_o(lo, "lifthull o"), ex, False)

        self.check(s, "qconvex", "o", o)

        def per_facet(opt, dim):
            def fn():
                qo, lo = self.both("qconvex", opt, s)
                qd, qr = parse_coords(qo, "Qhull " + opt)
                ld, lr = parse_coords(lo, "lifthull " + opt)
                if qd != dim or ld != dim or len(qr) != len(st["qi"]) or len(lr) != len(st["li"]):
                    raise Fail("dimension/count %d/%d in Qhull, %d/%d in lifthull"
                               % (qd, len(qr), ld, len(lr)))
                lmap = {frozenset(f): r for f, r in zip(st["li"], lr)}
                scale = max(1.0, ex.extent)
                worst = qworst = 0.0
                qoff = 0
                for f, r in zip(st["qi"], qr):
                    b = lmap[frozenset(f)]
                    if opt == "n":
                        # both against the exact plane: lifthull's within 1e-12, or within
                        # 1e-15 x the facet's condition (floating point), or 100 x Qhull's error
                        ref, cond = ex.plane(f)
                        w = plane_diff(b, ref, scale)
                        qw = plane_diff(r, ref, scale)
                        if qw > 1e-12:
                            qoff += 1
                        qworst = max(qworst, qw)
                        if w > max(1e-12, 1e-15 * cond, 100 * qw):
                            raise Fail("facet %s: lifthull's plane is %.3g from the exact one, "
                                       "Qhull's %.3g (condition %.3g)" % (sorted(f), w, qw, cond))
                    else:
                        w = maxdiff(r, b) / scale
                        if w > 1e-12:
                            raise Fail("facet %s: centrums differ by %.3g" % (sorted(f), w))
                    worst = max(worst, w)
                what = "planes" if opt == "n" else "centrums"
                return "%d %s within %.2g%s" % (len(qr), what, worst,
                                                " of the exact planes (Qhull's within %.2g%s)"
                                                % (qworst, ", %d further: its own error" % qoff
                                                   if qoff else "") if opt == "n" else "")
            return fn

        self.check(s, "qconvex", "n", per_facet("n", d + 1))

        def fn():
            qo, lo = self.both("qconvex", "Fn", s)
            msg, _ = compare_fn(st["qi"], None, parse_index_list(qo, True, "Qhull Fn"), st["li"],
                                None, parse_index_list(lo, True, "lifthull Fn"), False)
            return msg

        self.check(s, "qconvex", "Fn", fn)

        def fN():
            qo, lo = self.both("qconvex", "FN", s)
            return compare_fN(st["qi"], parse_index_list(qo, True, "Qhull FN"), st["li"],
                              parse_index_list(lo, True, "lifthull FN"), n, {}).split(", upper")[0]

        self.check(s, "qconvex", "FN", fN)

        def fv():
            qo, lo = self.both("qconvex", "Fv", s)
            return compare_facets(parse_index_list(qo, True, "Qhull Fv"),
                                  parse_index_list(lo, True, "lifthull Fv"), False)

        self.check(s, "qconvex", "Fv", fv)

        def fx():
            qo, lo = self.both("qconvex", "Fx", s)
            q = sorted(int(t) for t in qo.split()[1:])
            l_ = sorted(int(t) for t in lo.split()[1:])
            if q != l_:
                raise Fail("extreme points differ: %s only in Qhull, %s only in lifthull"
                           % (sorted(set(q) - set(l_))[:5], sorted(set(l_) - set(q))[:5]))
            return "%d extreme points" % len(q)

        self.check(s, "qconvex", "Fx", fx)

        def p():
            qo, lo = self.both("qconvex", "p", s)
            qd, qr = parse_coords(qo, "Qhull p")
            ld, lr = parse_coords(lo, "lifthull p")
            if qd != ld:
                raise Fail("dimension %d in Qhull, %d in lifthull" % (qd, ld))
            w = compare_point_rows(qr, lr, 1e-15 * ex.extent, "p")
            return "%d vertices within %.2g" % (len(qr), w)

        self.check(s, "qconvex", "p", p)
        self.check(s, "qconvex", "FC", per_facet("FC", d))

    # -- degenerate ----------------------------------------------------------------------------

    def degenerate(self, s, ex, tmp):
        st = {}

        def i():
            rc, lo, le = self.lift("qdelaunay", "i", s)
            if rc != 0:
                raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
            rows = parse_index_list(lo, False, "lifthull i")
            ok, msg = exact_check_i(self.args, s["text"], lo, tmp)
            if not ok:
                raise Fail(msg)
            used = {v for r in rows for v in r}
            have = {tuple(ex.ip[v]) for v in used}
            missing = [k for k, p in enumerate(ex.ip) if tuple(p) not in have]
            if missing:
                raise Fail("site %d is neither a vertex nor a duplicate of one" % missing[0])
            if len(have) != len(used):
                raise Fail("two vertices are the same point")
            s["exact_ok"] = True
            st["vol"] = sum(abs(ex.vol(r)) for r in rows)
            st["n"] = len(rows)
            return "exact check OK (%d simplices%s), every distinct site a vertex" \
                % (len(rows), ", --limit %d" % self.args.limit if self.args.limit else "")

        if not self.check(s, "qdelaunay", "i", i):
            return

        def fn():
            """lifthull's Fn alone: main neighbours share a side, every hull side has one of
            the other facets (a negative id) across."""
            rc, li, le = self.lift("qdelaunay", "i", s)
            rc2, lo, le2 = self.lift("qdelaunay", "Fn", s)
            if rc or rc2:
                raise Fail("lifthull failed: %s" % (le + le2).strip()[:100])
            if re.search(r"(^|\s)-0(\s|$)", lo):
                raise Fail("a hull side has no facet across: printed as -0 (%d times)"
                           % len(re.findall(r"(?:^|\s)-0(?=\s|$)", lo)))
            rows = parse_index_list(li, False, "lifthull i")
            pos, neg, count = sides_of("lifthull", rows, rows, parse_index_list(lo, True, "Fn"))
            if neg is None:
                raise Fail("a neighbour is not opposite its vertex")
            return "consistent: %d hull sides, each with a negative id (%d distinct)" \
                % (sum(count.values()), len(set(neg.values())))

        self.check_upper(s, "qdelaunay", "Fn", fn)
        self.degenerate_hull(s, ex, st.get("vol"))

    def degenerate_hull(self, s, ex, dvol):
        def hull():
            rc, lo, le = self.lift("qconvex", "i", s)
            if rc != 0:
                raise Fail("lifthull failed: %s" % (le.strip().splitlines() or ["rc %d" % rc])[-1])
            rows = parse_index_list(lo, False, "lifthull qconvex i")
            hvol = check_hull_exact(ex, rows)
            msg = "%d facets: every point inside or on every plane, ridges in two facets" % len(rows)
            if dvol is not None:
                if dvol != hvol:
                    raise Fail("the Delaunay simplices' volume %.17g != the hull's %.17g"
                               % (dvol / ex.den ** ex.d, hvol / ex.den ** ex.d))
                msg += "; Delaunay volume = hull volume (exact)"
            qv = qhull_volume(self.args, s["text"])
            if qv is not None:
                fact = 1
                for k in range(2, ex.d + 1):
                    fact *= k
                mine = float(Fraction(hvol, ex.den ** ex.d * fact))
                if abs(mine - qv) > 1e-7 * max(abs(qv), 1e-300) + 1e-12:  # FA has 8 digits
                    raise Fail("hull volume %.17g, Qhull's FA %.17g" % (mine, qv))
                msg += "; = Qhull's FA volume"
            return msg

        self.check(s, "qconvex", "i", hull)

    def lowdim(self, s):
        def refuse():
            rc, lo, le = self.lift("qdelaunay", "i", s)
            if rc == 0:
                raise Fail("lifthull answered for a lower-dimensional set")
            if "affine subspace" not in le:
                raise Fail("no 'affine subspace' message: %s" % le.strip()[:120])
            return "refused: %s" % le.strip().splitlines()[-1][:100]

        self.check(s, "qdelaunay", "i", refuse)

    # -- one set -------------------------------------------------------------------------------

    def run_set(self, s):
        t0 = time.time()
        ex = Exact(s["pts"])
        with tempfile.TemporaryDirectory(prefix="lh_golden_") as tmp:
            hull_general = self.classify_hull(s, ex)
            kind = self.classify(s, ex, tmp)
            s["kind"] = kind
            f0 = self.fails
            if kind == "lowdim":
                self.lowdim(s)
            elif kind == "general":
                self.general_delaunay(s, ex)
                self.general_voronoi(s, ex)
            else:
                self.degenerate(s, ex, tmp)
            if kind != "lowdim":
                if hull_general:
                    self.general_convex(s, ex)
                elif kind == "general":
                    self.degenerate_hull(s, ex, None)
            s["ok"] = self.fails == f0
        s["seconds"] = time.time() - t0
        self.rows.append(s)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lifthull", required=False)
    ap.add_argument("--rbox", default="rbox")
    ap.add_argument("--qdelaunay", default="qdelaunay")
    ap.add_argument("--qvoronoi", default="qvoronoi")
    ap.add_argument("--qconvex", default="qconvex")
    ap.add_argument("--invocations", default=DEFAULT_INVOCATIONS)
    ap.add_argument("--shard", default="1/1", help="K/N: run the sets k with k mod N == K-1")
    ap.add_argument("--only", default=None, help="regular expression on the set's name")
    ap.add_argument("--limit", type=int, default=4000,
                    help="exact_check.py --limit (0: no limit)")
    ap.add_argument("-v", action="store_true", help="print the skipped specifications")
    args = ap.parse_args(argv[1:])
    args.lifthull = os.environ.get("LH_GOLDEN_LIFTHULL") or args.lifthull
    if not args.lifthull:
        ap.error("--lifthull (or LH_GOLDEN_LIFTHULL) is required")
    try:
        k, nshard = (int(x) for x in args.shard.split("/"))
        assert 1 <= k <= nshard
    except (ValueError, AssertionError):
        ap.error("--shard K/N with 1 <= K <= N")

    def log(line):
        print(line, flush=True)

    t0 = time.time()
    sets, skipped = make_sets(args, log if args.v else (lambda line: None))
    sets = [s for j, s in enumerate(sets) if j % nshard == k - 1]
    if args.only:
        sets = [s for s in sets if re.search(args.only, s["name"])]
    print("qhull_golden: %d point sets (shard %s; %d specifications skipped), lifthull %s"
          % (len(sets), args.shard, len(skipped), args.lifthull), flush=True)
    r = Runner(args, log)
    for s in sets:
        r.run_set(s)

    # summary
    print("\nsummary (%.1f s):" % (time.time() - t0))
    print("  %-34s %2s %5s  %-11s %-34s %-22s %-8s %s" % (
        "set", "d", "n", "class", "Qhull qdelaunay", "Qhull qconvex", "lifthull", "seconds"))
    for s in r.rows:
        print("  %-34s %2d %5d  %-11s %-34s %-22s %-8s %.1f" % (
            s["name"], s["d"], len(s["pts"]), s["kind"], s.get("qhull_delaunay", "")[:34],
            s.get("qhull_convex", "")[:22], "ok" if s["ok"] else "FAIL", s["seconds"]))
    kinds = Counter(s["kind"] for s in r.rows)
    qfail = [s for s in r.rows if s["kind"] in ("degenerate", "inexact")]
    print("\n  %d sets: %d general, %d degenerate, %d inexact in Qhull, %d lower-dimensional"
          % (len(r.rows), kinds["general"], kinds["degenerate"], kinds["inexact"], kinds["lowdim"]))
    hard = [s for s in qfail if s["qhull_delaunay"] not in ("ok", "duplicates")]
    print("  Qhull's qdelaunay failed, merged, or was inexact on %d sets; lifthull's `qdelaunay i` "
          "passed the exact check on %d of them, all its checks on %d"
          % (len(hard), len([s for s in hard if s.get("exact_ok")]),
             len([s for s in hard if s["ok"]])))
    print("  Voronoi vertices: lifthull within %.3g of the exact circumcentres, Qhull within %.3g, "
          "apart %.3g (relative to the set's extent)"
          % (r.max_vor_err, r.max_vor_qhull, r.max_vor_diff))
    print("  %d checks passed, %d failed" % (r.passes, r.fails))
    return 1 if r.fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
