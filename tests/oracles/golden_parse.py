"""Parsers of Qhull's output formats (i, Fv, Fn, FN, p, n, FC, o, Fi, Fo) for qhull_golden.py,
and the Fail exception every check raises."""


class Fail(Exception):
    pass


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
