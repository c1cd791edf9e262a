#!/usr/bin/env python3
"""qvoronoi_fn.py LIFTHULL QVORONOI FILE...: `lifthull qvoronoi FN` (issue 30, item 8: the
Voronoi vertices of each region, a cell of the Delaunay complex once) on the sites of
each FILE: per site, the non-negative ids are each listed once and are exactly the
region's finite vertices of `lifthull qvoronoi o`, less one (Qhull's numbering); and as
many as Qhull's `qvoronoi FN` lists (its ids are its own facet ids: only the number
is compared; the negative ids, upper Delaunay facets, are each program's own). Exit 1
on any failure."""

import subprocess
import sys


def run(prog, args, text):
    return subprocess.run([prog] + args, input=text, capture_output=True, text=True, check=True).stdout


def lists(out, skip):
    return [[int(x) for x in ln.split()[1:]] for ln in out.split("\n")[skip:] if ln.strip()]


def main():
    lh, qv, files = sys.argv[1], sys.argv[2], sys.argv[3:]
    bad = 0
    for path in files:
        text = open(path).read()
        fn = lists(run(lh, ["qvoronoi", "FN"], text), 1)
        o = run(lh, ["qvoronoi", "o"], text)
        nv = int(o.split("\n")[1].split()[0])
        regions = lists(o, 2 + nv)
        theirs = lists(run(qv, ["FN"], text), 1)
        wrong = []
        for i, (ids, reg, q) in enumerate(zip(fn, regions, theirs)):
            mine = [x for x in ids if x >= 0]
            if len(mine) != len(set(mine)) or set(mine) != {v - 1 for v in reg if v}:
                wrong.append("site %d: FN %s, o region %s" % (i, ids, reg))
            elif len(mine) != len([x for x in q if x >= 0]):
                wrong.append("site %d: FN %s, qvoronoi FN %s" % (i, ids, q))
        if not (len(fn) == len(regions) == len(theirs)):
            wrong.append("%d, %d, %d sites" % (len(fn), len(regions), len(theirs)))
        for w in wrong[:3]:
            print("FAIL %s %s" % (path, w))
        print("%s: %d sites, %d wrong" % (path, len(fn), len(wrong)))
        bad += len(wrong)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
