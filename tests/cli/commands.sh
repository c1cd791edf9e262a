#!/usr/bin/env bash
# commands.sh LIFTHULL PYTHON: the native commands end to end — every command's --help,
# usage errors, the output formats of delaunay -o (read back), voronoi, locate,
# interpolate and check on cases with known answers, whole-or-nothing output files,
# and the Qhull front ends' option handling (TI, TO, notes, unknown options).
set -u
lh="$1"; py="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
# matches FILE REGEX: REGEX found in FILE; an empty REGEX: FILE is empty.
matches() { if [ -z "$2" ]; then [ ! -s "$1" ]; else grep -Eq -- "$2" "$1"; fi; }
# expect NAME CODE STDERR_REGEX STDOUT_REGEX -- COMMAND...: exit code and both streams.
expect() {
  local name="$1" code="$2" err="$3" out="$4"; shift 5
  "$@" > out.txt 2> err.txt; local got=$?
  if [ "$got" -eq "$code" ] && matches err.txt "$err" && matches out.txt "$out"; then ok
  else bad "$name: exit $got (want $code); stderr: $(head -c 300 err.txt); stdout: $(head -c 300 out.txt)"; fi
}

# the unit square's corners and centre; a 2D cloud; values v = 3x - 2y + 1
printf '2 5\n0 0\n1 0\n0 1\n1 1\n0.5 0.5\n' > sq.txt
"$lh" points 400 -d 2 --seed 4 > cloud.txt
"$lh" points 50 -d 2 --seed 9 > queries.txt
"$py" - <<'PY'
lines = open('cloud.txt').read().split('\n')[2:]
with open('cloud.csv', 'w') as f:
    f.write('x,y,v\n')
    for l in lines:
        if l.strip():
            x, y = map(float, l.split())
            f.write('%r,%r,%r\n' % (x, y, 3 * x - 2 * y + 1))
PY

for c in delaunay voronoi hull locate interpolate check points qdelaunay qvoronoi qconvex; do
  expect "$c --help" 0 '' '^usage: lifthull '"$c" -- "$lh" "$c" --help
done
expect "--threads accepted" 0 '' '^4$' -- "$lh" delaunay --threads 2 sq.txt
expect "--threads checked" 2 "--threads takes a whole number from 0 to 4096, not 'x'" '' -- "$lh" hull --threads x sq.txt
# enough sites for parallel phases: the same file from 1, 2 and 3 threads
"$lh" points 60000 -d 2 --seed 5 > big.txt
"$lh" delaunay -q --threads 1 big.txt -o one.txt
expect "--threads defaults to every CPU" 0 '' 'default 0: one per CPU' -- "$lh" delaunay --help
for k in 2 3 0 default; do
  if [ "$k" = default ]; then
    expect "no --threads: the one-thread output" 0 '' '' -- "$lh" delaunay -q big.txt -o many.txt
    if cmp -s one.txt many.txt && [ -s one.txt ]; then ok; else bad "no --threads: output differs"; fi
    rm -f many.txt
    continue
  fi
  expect "--threads $k: the one-thread output" 0 '' '' -- "$lh" delaunay -q --threads "$k" big.txt -o many.txt
  if cmp -s one.txt many.txt && [ -s one.txt ]; then ok; else bad "--threads $k: output differs"; fi
  rm -f many.txt
done
expect "unknown command" 2 "unknown command 'frobnicate'" '' -- "$lh" frobnicate
expect "unknown option" 2 "lifthull delaunay: unknown option '-z'" '' -- "$lh" delaunay -z sq.txt
expect "-o without a value" 2 "a value is needed after '-o'" '' -- "$lh" delaunay sq.txt -o
expect "locate needs two files" 2 "2 input files are needed" '' -- "$lh" locate sq.txt
expect "bad method" 2 "unknown method 'cubic'" '' -- "$lh" interpolate -m cubic cloud.csv queries.txt

# a comment with commas after the dimension is still Qhull's format, not CSV
printf '2 sites, from somewhere (ISC), in Qhull format\n3\n0 0\n1 0\n0 1\n' > commas.txt
expect "comment with commas" 0 '' '^0 1 2$' -- "$lh" delaunay commas.txt

# --format forces the reader where the content is ambiguous ("2 3" could be a point)
printf '2 3\n0 0\n1 0\n0 1\n1 1\n' > amb.txt
expect "ambiguous, auto: columns" 0 '' '^4$' -- "$lh" delaunay amb.txt
expect "ambiguous, --format qhull" 3 "amb.txt:5:1: expected the end of the input after 3 points of dimension 2, found '1'" '' -- "$lh" delaunay --format qhull amb.txt
expect "--format checked" 2 "--format takes qhull, node or columns, not 'xml'" '' -- "$lh" hull --format xml amb.txt

# delaunay -o: each format read back
expect "delaunay -o vtu" 0 '' '' -- "$lh" delaunay cloud.txt -o m.vtu
"$py" - <<'PY' && ok || bad "m.vtu: not a VTK file with 400 points and the triangles"
import xml.dom.minidom as m
d = m.parse('m.vtu'); p = d.getElementsByTagName('Piece')[0]
assert p.getAttribute('NumberOfPoints') == '400' and int(p.getAttribute('NumberOfCells')) > 700
PY
expect "delaunay -o msh" 0 '' '' -- "$lh" delaunay cloud.txt -o m.msh
grep -q '^4.1 0 8' m.msh && ok || bad "m.msh: no MSH 4.1 header"
expect "delaunay -o ele" 0 '' '' -- "$lh" delaunay cloud.txt -o m.ele
[ -s m.node ] && [ -s m.ele ] && [ -s m.neigh ] && ok || bad "m.node/.ele/.neigh missing"
expect "check .node + .ele" 0 '' '^ok: ' -- "$lh" check m.node m.ele
expect "delaunay -o svg" 0 '' '' -- "$lh" delaunay cloud.txt -o m.svg
"$py" -c 'import xml.dom.minidom as m; m.parse("m.svg")' && ok || bad "m.svg is not XML"
expect "no overwrite" 1 "'m.svg' exists \(use -f" '' -- "$lh" delaunay cloud.txt -o m.svg
expect "-f replaces" 0 '' '' -- "$lh" delaunay cloud.txt -o m.svg -f
cp cloud.txt in.txt
expect "never the input" 1 "is the input file; it is not overwritten" '' -- "$lh" delaunay in.txt -o in.txt -f
cmp -s in.txt cloud.txt && ok || bad "the input was changed"
printf '3 4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n' > flat.txt
expect "failure leaves no file" 1 "dimension 2, not 3" '' -- "$lh" delaunay flat.txt -o flat.vtu
[ ! -e flat.vtu ] && ok || bad "flat.vtu written on failure"
expect "svg is 2D" 1 "SVG pictures are of 2D" '' -- "$lh" delaunay -a flat.txt -o flat.svg
ls | grep -q 'tmp' && bad "temporary files left: $(ls | grep tmp)" || ok

# voronoi: qvoronoi's 'o' layout; a picture
expect "voronoi text" 0 '' '^2$' -- "$lh" voronoi sq.txt
"$lh" voronoi sq.txt | "$py" -c '
import sys
l = sys.stdin.read().split("\n")
nv, nr, one = map(int, l[1].split()); assert (nv, nr, one) == (5, 5, 1), l[1]
assert l[2].split() == ["-10.101", "-10.101"]
centres = sorted(tuple(float(x) for x in s.split()) for s in l[3:7])
assert centres == [(0, 0.5), (0.5, 0), (0.5, 1), (1, 0.5)], centres
regions = [list(map(int, s.split())) for s in l[7:12]]
assert all(r[0] == 3 and r[-1] == 0 for r in regions[:4]) and regions[4][0] == 4 and 0 not in regions[4][1:], regions
' && ok || bad "voronoi of the square"
expect "voronoi svg" 0 '' '' -- "$lh" voronoi cloud.txt -o v.svg --circles
grep -q 'id="voronoi"' v.svg && grep -q 'id="circles"' v.svg && ok || bad "v.svg lacks the Voronoi diagram or circles"

# locate: inside with barycentric coordinates, outside with the distance
printf '2 3\n0.25 0.5\n0 0\n3 0.5\n' > q.txt
"$lh" locate sq.txt q.txt > loc.txt
"$py" - <<'PY' && ok || bad "locate on the square: $(cat loc.txt)"
l = [s.split() for s in open('loc.txt').read().strip().split('\n')]
assert l[0][0] == 'in' and l[0][-2:] == ['nearest', '4'], l[0]
b = list(map(float, l[0][5:8])); assert abs(sum(b) - 1) < 1e-15 and min(b) >= 0
assert l[1][0] == 'in' and l[1][-1] == '0' and sorted(map(float, l[1][5:8]))[-1] == 1.0
assert l[2][0] == 'out' and l[2][3] == 'distance' and float(l[2][4]) == 2.0 and l[2][-1] == '1', l[2]  # 1 and 3 tie
PY
expect "locate dimension mismatch" 3 "the queries have dimension 3, the sites \(sq.txt\) 2" '' -- "$lh" locate sq.txt flat.txt

# interpolate: an affine function is reproduced; nan outside; values required
for m in linear natural; do
  "$lh" interpolate -m $m --values 1 cloud.csv queries.txt > iv.txt
  "$py" - "$m" <<'PY' && ok || bad "interpolate -m $m does not reproduce 3x - 2y + 1"
import sys
q = [tuple(map(float, s.split())) for s in open('queries.txt').read().split('\n')[2:] if s.strip()]
v = [float(s) for s in open('iv.txt').read().split()]
assert len(v) == len(q)
inside = 0
for (x, y), w in zip(q, v):
    if w == w:
        inside += 1
        assert abs(w - (3 * x - 2 * y + 1)) < 1e-12, (x, y, w)
assert inside > 20, inside
PY
done
"$lh" interpolate -m nearest --values 1 cloud.csv queries.txt | grep -q nan && bad "nearest gave nan" || ok
expect "values needed" 3 "no values: give --values K" '' -- "$lh" interpolate cloud.txt queries.txt
expect "too many value columns" 3 "at least 2 are needed" '' -- "$lh" interpolate --values 2 cloud.csv queries.txt

# check: a valid triangulation, a broken one, a malformed file
"$lh" delaunay cloud.txt > tri.txt
expect "check ok" 0 '' '^ok: ' -- "$lh" check cloud.txt tri.txt
awk 'NR == 1 { print $1 - 1; next } NR != 5' tri.txt > broken.txt
expect "check broken" 1 '' '^not Delaunay: ' -- "$lh" check cloud.txt broken.txt
# a fan over a pentagram: every local test passes, but it covers the pentagon twice
printf '2 6\n0 0\n1000 0\n309 951\n-809 588\n-809 -588\n309 -951\n' > penta.txt
printf '5\n0 1 3\n0 2 4\n0 3 5\n0 4 1\n0 5 2\n' > penta_fan.txt
expect "check a double cover" 1 '' 'cover the convex hull more than once' -- "$lh" check penta.txt penta_fan.txt
printf '1\n0 1 999\n' > outofrange.txt
expect "check index range" 3 "outofrange.txt:2:5: expected a point index of cell 1 \(an integer from 0 to 399\), found '999'" '' -- "$lh" check cloud.txt outofrange.txt

# the Qhull front ends: options, notes, TI/TO
expect "qdelaunay unknown option" 2 "option 'Fz' is not supported" '' -- "$lh" qdelaunay Fz
expect "qdelaunay QJ note" 0 "option 'QJ' ignored: no joggle is needed" '^[0-9]+$' -- "$lh" qdelaunay QJ i TI cloud.txt
expect "qdelaunay TO" 0 '' '' -- "$lh" qdelaunay i TI cloud.txt TO qi.txt
cmp -s qi.txt <("$lh" qdelaunay i < cloud.txt) && ok || bad "TO differs from standard output"
expect "qdelaunay TO is TI" 1 "is the input file" '' -- "$lh" qdelaunay i TI in.txt TO in.txt
cmp -s in.txt cloud.txt && ok || bad "TO overwrote the input"
expect "summary on stderr with outputs" 0 "Number of Delaunay regions" '^[0-9]+$' -- "$lh" qdelaunay s i TI sq.txt
expect "qconvex TI missing file" 3 "nosuch.txt: No such file" '' -- "$lh" qconvex i TI nosuch.txt

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
