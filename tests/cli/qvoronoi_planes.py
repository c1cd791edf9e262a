#!/usr/bin/env python3
"""qvoronoi_planes.py LIFTHULL FILE [SCALE_EXPONENT ...]: `lifthull qvoronoi Fi` and `Fo` on the
sites of FILE (Qhull format), checked against the exact bisectors (issue 30, item 9): every
value finite (no nan, no inf), each normal the unit vector from site i towards site j to 1e-14,
each offset -n.(a+b)/2 to 1e-12 of the sum of its terms' magnitudes or 2^-1072 (the offset is
text: beyond DBL_MAX it is still a number). With SCALE_EXPONENTs k, the sites scaled by 2^k (exact for the
sets used) must give the same ridges with the same normals. Exit 1 on any failure."""

import decimal
import subprocess
import sys
from decimal import Decimal

decimal.getcontext().prec = 60


def read_sites(text):
    lines = [ln for ln in text.split("\n") if ln.strip()]
    head = lines[0].split()
    d = int(head[0])
    return d, [[float(x) for x in ln.split()] for ln in lines[1 if len(head) == 2 and head[1].isdigit() else 2:]]


def planes(lh, text, opt):
    out = subprocess.run([lh, "qvoronoi", opt], input=text, capture_output=True, text=True, check=True).stdout
    res = {}
    for line in out.split("\n")[1:]:
        w = line.split()
        if w:
            if any(x.lower().lstrip("-") in ("nan", "inf") for x in w):
                raise SystemExit("FAIL %s: non-finite value: %s" % (opt, line))
            res[(int(w[1]), int(w[2]))] = [Decimal(x) for x in w[3:]]
    return res


def check(lh, d, sites, text, name):
    bad = 0
    got = {}
    for opt in ("Fi", "Fo"):
        for (i, j), v in planes(lh, text, opt).items():
            got[(i, j)] = v
            a = [Decimal(x) for x in sites[i]]
            b = [Decimal(x) for x in sites[j]]
            diff = [y - x for x, y in zip(a, b)]
            norm = sum(t * t for t in diff).sqrt()
            n = [t / norm for t in diff]
            terms = [-c * (x + y) / 2 for c, x, y in zip(n, a, b)]
            off = sum(terms)
            err_n = max(abs(x - y) for x, y in zip(n, v[:d]))
            err_o = abs(off - v[d])
            scale = sum(abs(t) for t in terms)
            # the offset to 1e-12, or to a few units of the smallest subnormal
            if err_n > Decimal("1e-14") or err_o > Decimal("1e-12") * scale + Decimal(2) ** -1072:
                bad += 1
                if bad <= 3:
                    print("FAIL %s %s ridge %d %d: normal error %.3g, offset %s, want %s"
                          % (name, opt, i, j, err_n, v[d], off))
    return bad, got


def main():
    lh, path, exps = sys.argv[1], sys.argv[2], [int(k) for k in sys.argv[3:]]
    text = open(path).read()
    d, sites = read_sites(text)
    bad, base = check(lh, d, sites, text, path)
    print("%s: %d ridges, %d wrong" % (path, len(base), bad))
    for k in exps:
        scaled = [[x * 2.0 ** k for x in p] for p in sites]
        stext = "%d\n%d\n" % (d, len(scaled)) + "".join(" ".join(repr(x) for x in p) + "\n" for p in scaled)
        b2, got = check(lh, d, scaled, stext, "%s * 2^%d" % (path, k))
        same = got.keys() == base.keys() and all(got[r][:d] == base[r][:d] for r in got)
        print("%s * 2^%d: %d ridges, %d wrong, %s" % (path, k, len(got), b2,
              "the same ridges and normals" if same else "DIFFERENT ridges or normals"))
        bad += b2 + (not same)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
