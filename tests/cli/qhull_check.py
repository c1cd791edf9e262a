"""What tests/cli/qhull_formats.py, qvoronoi_extras.py, qhull_good.py and
qhull_geomview.py share: running a program on a text, rbox sets, cdd's format, counted
checks and the main loop (skip, 77, without Qhull's programs; exit 1 on any failure)."""

import shutil
import subprocess
import sys

FAILS = []
PASSES = [0]
VERBOSE = [False]


def check(name, cond, detail=""):
    if cond:
        PASSES[0] += 1
        if VERBOSE[0]:
            print("PASS", name)
    else:
        FAILS.append(name)
        print("FAIL", name, detail)


def run(cmd, text):
    p = subprocess.run(cmd, input=text, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def rbox(spec):
    return subprocess.run(["rbox"] + spec.split(), capture_output=True, text=True, check=True).stdout


def cdd_rows(out):
    """cdd's format (FD): the header's (rows, columns, 'real') and the rows of numbers."""
    lines = out.split("\n")
    b, e = lines.index("begin"), lines.index("end")
    head = lines[b + 1].split()
    rows = [tuple(float(x) for x in l.split()) for l in lines[b + 2:e]]
    return (int(head[0]), int(head[1]), head[2]), rows


def same_rows(a, b, tol, relative=False):
    """Rows of numbers equal as multisets within tol (relative to the row's largest entry
    when `relative`), rows of other lengths never equal."""
    if len(a) != len(b):
        return False
    left = sorted(b)
    for r in sorted(a):
        scale = max([1.0] + [abs(x) for x in r]) if relative else 1.0
        j = next((j for j, q in enumerate(left) if len(q) == len(r)
                  and all(abs(x - y) <= tol * scale for x, y in zip(r, q))), None)
        if j is None:
            return False
        left.pop(j)
    return True


def main(doc, programs, groups):
    """Runs each (name, function) group on LIFTHULL (argv[1]); an output too malformed to
    parse is one failure."""
    if len(sys.argv) < 2:
        print(doc)
        return 2
    VERBOSE[0] = "-v" in sys.argv[2:]
    if not all(shutil.which(p) for p in programs):
        print("SKIP: Qhull's programs (qhull-bin) not found")
        return 77
    for name, fn in groups:
        try:
            fn(sys.argv[1])
        except (ValueError, IndexError, AttributeError, KeyError, TypeError, AssertionError,
                StopIteration) as e:
            check(name + " (output parses)", False, repr(e))
    print("%d passed, %d failed" % (PASSES[0], len(FAILS)))
    return 1 if FAILS else 0
