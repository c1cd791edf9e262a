#!/usr/bin/env python3
"""Canonical forms of Delaunay simplex lists, for cross-checking lifthull against oracles.

  canon.py canon [--format i|ele] [--width W] FILE|-      print the canonical form
  canon.py diff NAME_A FILE_A NAME_B FILE_B [--max K]    compare two canonical files
  canon.py node FILE|- OUT.node                         Qhull-format points -> TetGen .node
  canon.py header FILE|-                                print "d n" of a Qhull-format point file

Input formats:
  i    Qhull's `i` output (qdelaunay Qt i, lifthull delaunay, oracle_cgal_delaunay): a line
       with the simplex count, then one simplex per line as 0-based indices. Lines starting
       with '#' and blank lines are ignored.
  ele  TetGen's .ele file: "<#tets> <nodes per tet> <#attributes>", then
       "<tet #> <n1> ... <nk> [attributes]". Indices are taken as they are: write the .node
       file 0-based (the `node` command does) and run tetgen with -z, and they are 0-based.

The canonical form: each simplex's indices sorted ascending, the simplices sorted
lexicographically as integer tuples, one per line, space-separated; no count line.
Two triangulations are the same simplicial complex iff their canonical forms are identical.

`canon` fails (exit 2) on malformed input: a count that does not match the lines, simplices of
mixed width (or not W wide with --width), a repeated index inside a simplex, a negative index,
or the same simplex twice.

`diff` exits 0 if the two files are identical, 1 if they differ (2 on errors), printing how many simplices are
only in each and the first K (default 10) of each kind.
"""

import sys


class CanonError(Exception):
    pass


def _lines(path):
    if path == "-":
        return sys.stdin.read().splitlines()
    with open(path, "r", encoding="ascii", errors="replace") as f:
        return f.read().splitlines()


def _ints(tokens, lineno):
    try:
        return [int(t) for t in tokens]
    except ValueError:
        raise CanonError("line %d: not an integer list: %r" % (lineno, " ".join(tokens)))


def read_i(path):
    """Qhull `i` format -> list of index tuples (unsorted, as given)."""
    count = None
    simplices = []
    for lineno, line in enumerate(_lines(path), 1):
        s = line.split("#", 1)[0].strip()
        if not s:
            continue
        toks = s.split()
        if count is None:
            if len(toks) != 1:
                raise CanonError("line %d: expected the simplex count, got %r" % (lineno, s))
            count = _ints(toks, lineno)[0]
            continue
        simplices.append(_ints(toks, lineno))
    if count is None:
        raise CanonError("empty input: no count line")
    if count != len(simplices):
        raise CanonError("count line says %d simplices, %d lines follow" % (count, len(simplices)))
    return simplices


def read_ele(path):
    """TetGen .ele -> list of index tuples."""
    header = None
    simplices = []
    for lineno, line in enumerate(_lines(path), 1):
        s = line.split("#", 1)[0].strip()
        if not s:
            continue
        toks = _ints(s.split(), lineno)
        if header is None:
            if len(toks) < 2:
                raise CanonError("line %d: bad .ele header %r" % (lineno, s))
            header = toks
            continue
        k = header[1]
        if len(toks) < 1 + k:
            raise CanonError("line %d: expected %d node indices" % (lineno, k))
        simplices.append(toks[1:1 + k])
    if header is None:
        raise CanonError("empty .ele file")
    if header[0] != len(simplices):
        raise CanonError(".ele header says %d elements, %d follow" % (header[0], len(simplices)))
    return simplices


def canonical(simplices, width=None):
    out = []
    for s in simplices:
        t = tuple(sorted(s))
        if width is None:
            width = len(t)
        if len(t) != width:
            raise CanonError("simplex %r has %d indices, expected %d" % (s, len(t), width))
        if t and t[0] < 0:
            raise CanonError("negative index in simplex %r" % (s,))
        for a, b in zip(t, t[1:]):
            if a == b:
                raise CanonError("repeated index in simplex %r" % (s,))
        out.append(t)
    out.sort()
    for a, b in zip(out, out[1:]):
        if a == b:
            raise CanonError("simplex %r appears more than once" % (a,))
    return out


def format_canon(simplices):
    return "".join(" ".join(map(str, t)) + "\n" for t in simplices)


def read_canon(path):
    out = []
    for lineno, line in enumerate(_lines(path), 1):
        s = line.strip()
        if s:
            out.append(tuple(_ints(s.split(), lineno)))
    return out


def cmd_canon(args):
    fmt, width, path = "i", None, None
    it = iter(args)
    for a in it:
        if a == "--format":
            fmt = next(it, None)
        elif a == "--width":
            width = int(next(it, "0"))
        elif path is None:
            path = a
        else:
            raise CanonError("canon: unexpected argument %r" % a)
    if path is None or fmt not in ("i", "ele"):
        raise CanonError("usage: canon.py canon [--format i|ele] [--width W] FILE|-")
    simplices = read_i(path) if fmt == "i" else read_ele(path)
    sys.stdout.write(format_canon(canonical(simplices, width)))
    return 0


def cmd_diff(args):
    maxk = 10
    pos = []
    it = iter(args)
    for a in it:
        if a == "--max":
            maxk = int(next(it, "10"))
        else:
            pos.append(a)
    if len(pos) != 4:
        raise CanonError("usage: canon.py diff NAME_A FILE_A NAME_B FILE_B [--max K]")
    na, fa, nb, fb = pos
    a, b = read_canon(fa), read_canon(fb)
    if a == b:
        return 0
    sa, sb = set(a), set(b)
    only_a = sorted(sa - sb)
    only_b = sorted(sb - sa)
    print("  %s: %d simplices, %s: %d simplices; %d only in %s, %d only in %s"
          % (na, len(a), nb, len(b), len(only_a), na, len(only_b), nb))
    for name, only in ((na, only_a), (nb, only_b)):
        for t in only[:maxk]:
            print("    only in %-9s %s" % (name + ":", " ".join(map(str, t))))
        if len(only) > maxk:
            print("    ... %d more only in %s" % (len(only) - maxk, name))
    return 1


def read_qhull_points(path):
    """Qhull input format -> (d, n, flat coordinate list). On every line a '#' or the first
    non-numeric token starts a comment; the smaller of the first two numbers is the dimension."""
    nums = []
    for line in _lines(path):
        line = line.split("#", 1)[0]
        for tok in line.split():
            try:
                nums.append(float(tok))
            except ValueError:
                break
    if len(nums) < 2:
        raise CanonError("no dimension/count header in %s" % path)
    d, n = sorted((int(nums[0]), int(nums[1])))
    coords = nums[2:]
    if len(coords) != d * n:
        raise CanonError("%s: expected %d coordinates (%d points, d=%d), found %d"
                         % (path, d * n, n, d, len(coords)))
    return d, n, coords


def cmd_header(args):
    """Print "d n" of a Qhull-format point file."""
    if len(args) != 1:
        raise CanonError("usage: canon.py header FILE|-")
    d, n, _ = read_qhull_points(args[0])
    print(d, n)
    return 0


def cmd_node(args):
    """Qhull-format 3D points -> TetGen .node numbered from 0."""
    if len(args) != 2:
        raise CanonError("usage: canon.py node FILE|- OUT.node")
    d, n, coords = read_qhull_points(args[0])
    if d != 3:
        raise CanonError("node: TetGen needs d = 3, got %d" % d)
    with open(args[1], "w", encoding="ascii") as f:
        f.write("%d 3 0 0\n" % n)
        for i in range(n):
            x, y, z = coords[3 * i:3 * i + 3]
            # repr() round-trips doubles exactly
            f.write("%d %r %r %r\n" % (i, x, y, z))
    return 0


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        sys.stdout.write(__doc__)
        return 0 if len(argv) >= 2 else 2
    cmds = {"canon": cmd_canon, "diff": cmd_diff, "node": cmd_node, "header": cmd_header}
    cmd = cmds.get(argv[1])
    if cmd is None:
        sys.stderr.write("canon.py: unknown command %r (canon, diff, node, header)\n" % argv[1])
        return 2
    try:
        return cmd(argv[2:])
    except (CanonError, OSError) as e:
        sys.stderr.write("canon.py %s: %s\n" % (argv[1], e))
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
