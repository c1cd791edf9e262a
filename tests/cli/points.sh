#!/usr/bin/env bash
# points.sh LIFTHULL PYTHON3: `lifthull points` — the output parses (header, count,
# columns), is the same bytes for the same command (golden outputs pin it across
# machines) and differs for another seed; every distribution's geometric promise holds
# exactly (checked with rational arithmetic); bad usage gives one line and exit 2;
# -o writes whole files and refuses to overwrite without -f; `lifthull delaunay` reads
# the output.
set -u
lh="$1"
py="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }

# check KIND ARGS...: runs `points ARGS`, then the Python check KIND on its output.
# Kinds: cube, ball, sphere, exact (one squared norm, exactly), grid:K, int:R, any.
check() {
  local kind="$1"; shift
  if ! "$lh" points "$@" > "$tmp/out" 2> "$tmp/err"; then bad "points $*: exit $?, $(head -c 200 "$tmp/err")"; return; fi
  if "$py" - "$kind" "$tmp/out" > "$tmp/why" 2>&1 <<'EOF'
import sys
from fractions import Fraction as F
kind, path = sys.argv[1], sys.argv[2]
lines = open(path).read().split('\n')
head = lines[0].split()
d, n = int(head[0]), int(lines[1])
assert head[1:3] == ['lifthull', 'points'], 'header ' + lines[0]
assert lines[-1] == '' and len(lines) == n + 3, 'expected %d point lines' % n
pts = [tuple(F(float(t)) for t in l.split()) for l in lines[2:2 + n]]
assert all(len(p) == d for p in pts), 'a line without %d coordinates' % d
for l in lines[2:2 + n]:  # "%.17g" round-trips: re-printing gives the same text
    assert ' '.join('%.17g' % float(t) for t in l.split()) == l, 'not %.17g: ' + l
sq = [sum(x * x for x in p) for p in pts]
if kind == 'cube':
    assert all(-F(1, 2) <= x < F(1, 2) for p in pts for x in p), 'outside the cube'
elif kind == 'ball':
    assert all(q <= F(1, 4) for q in sq), 'outside the ball'
elif kind == 'sphere':  # |x| = 0.5 within 1e-15 relative: |x|^2 within 2e-15 of 1/4
    worst = max(abs(q / F(1, 4) - 1) for q in sq)
    assert worst <= F(2, 10**15), 'off the sphere by %g' % float(worst)
elif kind == 'exact':
    assert len(set(sq)) == 1, '%d different squared norms' % len(set(sq))
    assert len(set(pts)) == n, 'duplicate points'
    assert all(x.denominator == 1 for p in pts for x in p), 'not integers'
elif kind.startswith('grid:'):
    k = int(kind[5:])
    assert n == k ** d and len(set(pts)) == n, 'not the %d^%d grid' % (k, d)
    assert all(x.denominator == 1 and 0 <= x < k for p in pts for x in p), 'grid coordinate'
elif kind.startswith('int:'):
    r = int(kind[4:])
    assert all(x.denominator == 1 and -r <= x <= r for p in pts for x in p), 'not an integer in [-R, R]'
    assert len(set(x for p in pts for x in p)) > 1, 'all coordinates equal'
EOF
  then ok; else bad "points $* ($kind): $(tail -1 "$tmp/why")"; fi
}

for d in 2 3 5 8; do
  check cube 300 -d $d
  check ball 300 -d $d --ball --seed 11
  check sphere 300 -d $d --sphere --seed 12
  check exact 300 -d $d --exact-sphere --seed 13
  check int:7 300 -d $d --integer 7 --seed 14
  check any 300 -d $d --clusters 4 --seed 15
done
check exact 15360 -d 2 --exact-sphere
check exact 100000 -d 2 --exact-sphere   # M about 2^86: past 64 bits
check exact 20000 -d 3 --exact-sphere
check exact 100000 -d 3 --exact-sphere --seed 4
check int:100 500 -d 3 --ball --integer 100
check int:5 2000 -d 2 --clusters 3 --integer 5   # tails clamped to [-R, R]
check int:1000000000000000 50 -d 2 --sphere --integer 1000000000000000
check grid:4 --grid 4 -d 3
check grid:2 --grid 2 -d 8
check grid:3 27 --grid 3 -d 3
check cube 1 -d 2

# The same command line (however spelled) gives the same bytes; another seed others.
"$lh" points 1000 -d 4 --ball --seed 7 > "$tmp/a"
"$lh" points --seed=7 --ball -d 4 1000 > "$tmp/b"
"$lh" points 1000 -d 4 --ball --seed 8 > "$tmp/c"
if cmp -s "$tmp/a" "$tmp/b"; then ok; else bad "same seed, different bytes"; fi
if ! cmp -s "$tmp/a" "$tmp/c" && [ "$(sed 1d "$tmp/a" | sort | comm -12 - <(sed 1d "$tmp/c" | sort) | wc -l)" -eq 1 ]; then ok; else bad "seeds 7 and 8 share points"; fi
for kind in "" --sphere --exact-sphere "--clusters 3"; do
  "$lh" points 200 -d 3 $kind --seed 1 > "$tmp/a"; "$lh" points 200 -d 3 $kind --seed 2 > "$tmp/c"
  if ! cmp -s <(sed 1d "$tmp/a") <(sed 1d "$tmp/c"); then ok; else bad "$kind: seeds 1 and 2 agree"; fi
done

# Golden outputs: the generator (xoshiro256**, the polar method with its own logarithm,
# selection sampling) must give these bytes on every machine.
golden() {
  local want="$1"; shift
  if [ "$("$lh" points "$@")" = "$(printf '%b' "$want")" ]; then ok; else bad "golden points $*: $("$lh" points "$@" | tr '\n' '|')"; fi
}
golden '2 lifthull points 3 -d 2 --seed 7\n3\n0.2005764821796896 -0.22124877052621572\n0.33962746187641979 0.48109772501493508\n0.49086027883306826 0.37277393874513198' 3 -d 2 --seed 7
golden '2 lifthull points 3 -d 2 --clusters 2 --seed 7\n3\n0.13828480076805161 -0.30490632368389642\n0.08029627014157964 -0.33934762642850136\n0.3263184677517984 0.56566764330072472' 3 -d 2 --clusters 2 --seed 7
golden '3 lifthull points 4 -d 3 --exact-sphere --seed 7\n4\n0 0 1\n0 1 0\n0 -1 0\n1 0 0' 4 -d 3 --exact-sphere --seed 7
golden '2 lifthull points --grid 2 -d 2\n4\n0 0\n0 1\n1 0\n1 1' --grid 2 -d 2

# Bad usage: one line on standard error, nothing on standard output, exit 2.
usage() {
  local regex="$1"; shift
  "$lh" points "$@" > "$tmp/out" 2> "$tmp/err"; local c=$?
  if [ $c -eq 2 ] && [ "$(wc -l < "$tmp/err")" -eq 1 ] && grep -Eq "^lifthull points: .*$regex" "$tmp/err" && [ ! -s "$tmp/out" ]; then ok
  else bad "points $*: exit $c (want 2), stderr: $(head -c 200 "$tmp/err")"; fi
}
usage "N is missing"
usage "N must be an integer from 1 to 1000000000, not 'abc'" abc
usage "not '0'" 0
usage "not '-5'" -5
usage "not '1000000001'" 1000000001
usage "not '1e3'" 1e3
usage "-d must be an integer from 2 to 8, not '9'" 10 -d 9
usage "-d must be an integer from 2 to 8, not '1'" 10 -d 1
usage "-d needs a value" 10 -d
usage "--seed needs a value" 10 --seed
usage "--seed must be an integer from 0 to 18446744073709551615, not '-1'" 10 --seed -1
usage "--seed must be .*, not '18446744073709551616'" 10 --seed 18446744073709551616
usage "unknown option '--frobnicate'" 10 --frobnicate
usage "--ball and --sphere exclude each other" 10 --ball --sphere
usage "--ball takes no value" 10 --ball=1
usage "--grid 3 in 3D makes 27 points, not 10" 10 --grid 3
usage "--grid 1000 in 8D makes more than 1000000000 points" --grid 1000 -d 8
usage "--grid must be an integer from 2" --grid 1
usage "--integer does not apply to --exact-sphere" 10 --exact-sphere --integer 3
usage "--integer must be an integer from 1 to 1000000000000000" 10 --integer 0
usage "more clusters than the 5 points" 5 --clusters 6
usage "unexpected argument '4'" 3 4
usage "-f only makes sense with -o" 10 -f
usage "--exact-sphere in 2D gives at most 1105920 points" 1105921 -d 2 --exact-sphere
usage "--exact-sphere in 3D gives at most 10000000 points" 10000001 -d 3 --exact-sphere
"$lh" points --help > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 0 ] && grep -q "^usage: lifthull points N" "$tmp/out" && grep -q "examples:" "$tmp/out" && [ ! -s "$tmp/err" ]; then ok; else bad "--help: exit $c"; fi

# -o: the file equals standard output's bytes; an existing file is kept unless -f; no
# temporary file is left behind.
mkdir "$tmp/o"
"$lh" points 100 -d 2 > "$tmp/a"
"$lh" points 100 -d 2 -o "$tmp/o/p.txt"; c=$?
if [ $c -eq 0 ] && cmp -s "$tmp/a" "$tmp/o/p.txt"; then ok; else bad "-o: exit $c or different bytes"; fi
"$lh" points 5 -d 2 -o "$tmp/o/p.txt" 2> "$tmp/err"; c=$?
if [ $c -eq 1 ] && grep -q "exists (use -f to replace it)" "$tmp/err" && cmp -s "$tmp/a" "$tmp/o/p.txt"; then ok; else bad "-o overwrote or exit $c"; fi
"$lh" points 5 -d 2 -o "$tmp/o/p.txt" -f; c=$?
if [ $c -eq 0 ] && [ "$(sed -n 2p "$tmp/o/p.txt")" = 5 ]; then ok; else bad "-o -f: exit $c"; fi
"$lh" points 5 -o "$tmp/no-such-dir/p.txt" 2> "$tmp/err"; c=$?
if [ $c -eq 1 ] && grep -q "cannot create" "$tmp/err" && [ ! -e "$tmp/no-such-dir" ]; then ok; else bad "-o into a missing directory: exit $c"; fi
# What is not a regular file is written through with -f, never replaced.
ln -s p.txt "$tmp/o/link"
"$lh" points 5 -d 2 -o "$tmp/o/link" 2> "$tmp/err"; c=$?
if [ $c -eq 1 ] && grep -q "exists" "$tmp/err"; then ok; else bad "-o onto a symbolic link without -f: exit $c"; fi
"$lh" points 7 -d 2 -o "$tmp/o/link" -f; c=$?
if [ $c -eq 0 ] && [ -L "$tmp/o/link" ] && [ "$(sed -n 2p "$tmp/o/p.txt")" = 7 ]; then ok; else bad "-o -f onto a symbolic link: exit $c"; fi
# (Devices are written through the same way; not tested on /dev/full here, since a
# regression would replace it for a test run as root.)
if [ "$(ls "$tmp/o" | tr '\n' ' ')" = "link p.txt " ]; then ok; else bad "left behind: $(ls "$tmp/o" | tr '\n' ' ')"; fi

# `lifthull delaunay` reads every kind of output (exact, degenerate ones included).
for args in "500 -d 2" "300 -d 3 --ball" "200 -d 4 --sphere" "300 -d 3 --exact-sphere" \
            "200 -d 2 --exact-sphere" "400 -d 2 --integer 6" "--grid 3 -d 3" "300 -d 3 --clusters 3"; do
  "$lh" points $args | "$lh" delaunay -s > "$tmp/out" 2> "$tmp/err"; c=$?
  if [ $c -eq 0 ] && grep -Eq "^simplices [1-9]" "$tmp/out"; then ok; else bad "delaunay on points $args: exit $c, $(head -c 200 "$tmp/err")"; fi
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
