#!/usr/bin/env bash
# triangle_ref.sh LIFTHULL DATA PYTHON: `lifthull triangle` against what Triangle itself
# does (DATA = tests/data/triangle): regional attributes and area bounds after
# refinement (check_regions.py locates every triangle in the input's faces), and
# vertex counts beside Triangle 1.6's (measured with tests/oracles/triangle).
set -u
tools="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"; py="$3"
. "$tools/harness.sh"
fresh() { rm -rf w; mkdir w; for f in "$@"; do cp "$data/$f" w/; done; cd w; }
# check NAME SCRIPT ARGS...: a Python checker that prints one line and exits 0 when met.
check() {
  local name="$1"; shift
  if "$py" "$tools/$@" > chk.txt 2>&1; then ok; else bad "$name: $(head -4 chk.txt)"; fi
}
# near NAME GOT WANT: GOT within 20% of WANT (other Steiner points than Triangle's,
# the same ballpark).
near() { if [ "$2" -ge $(($3 * 4 / 5)) ] && [ "$2" -le $(($3 * 6 / 5)) ]; then ok; else bad "$1: $2, Triangle $3"; fi; }

# Regions: each triangle carries the attribute (-A) and obeys the area bound (-a) of
# the region whose face of the input holds it, refinement included: the pieces of a
# split triangle stay on their side of every segment. la.poly: 6 regions, 4 fields.
# Triangle 1.6's vertex counts: -pqA 365, -pAa 767, -pqAa 860.
fresh la.poly
for c in "pqA 365" "pAa 767" "pqAa 860"; do
  set -- $c
  expect "-$1 la.poly" 0 '' '' -- "$lh" triangle -Q"$1" la.poly
  check "-$1 la.poly regions" check_regions.py $(case $1 in *a*) echo --areas;; esac) la.poly la.1
  near "-$1 la.poly vertices" "$(line la.1.node 1 | cut -d' ' -f1)" "$2"
done
cd ..
# two fields split by one segment, the left one finer (Triangle: 413 and 432 vertices)
mkdir -p two; cd two
printf '6 2 0 1\n1 0 0 1\n2 1 0 1\n3 2 0 1\n4 2 1 1\n5 1 1 1\n6 0 1 1\n7 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 5 1\n5 5 6 1\n6 6 1 1\n7 2 5 7\n0\n2\n1 0.5 0.5 1 0.002\n2 1.5 0.5 2 0.5\n' > two.poly
for c in "pAa 413" "pqAa 432"; do
  set -- $c
  expect "-$1 two.poly" 0 '' '' -- "$lh" triangle -Q"$1" two.poly
  check "-$1 two.poly regions" check_regions.py --areas two.poly two.1
  near "-$1 two.poly vertices" "$(line two.1.node 1 | cut -d' ' -f1)" "$2"
done
cd ..

# Triangle's own outputs (reference_outputs/, each file's trailer names the command):
# check_reference.py compares markers of every vertex and subsegment by Triangle's
# rule as the reference shows it, the headers, holes, regions, attributes, and with
# --same (no Steiner points) the vertices, segments and triangles themselves.
# reference REF FLAGS "INPUTS" SWITCHES...: run in a fresh directory holding INPUTS
# (names in DATA; ref/NAME from reference_outputs), compare the output with REF.
ref="$data/reference_outputs"
reference() {
  local r="$1" flags="$2" inputs="$3"; shift 3
  rm -rf w; mkdir w; cd w
  for f in $inputs; do case $f in ref/*) cp "$ref/${f#ref/}" .;; *) cp "$data/$f" .;; esac; done
  ls > inputs.txt
  "$lh" triangle -Q "$@" > out.txt 2> err.txt; local got=$?
  if [ "$1" != "${1#-r}" ] && { [ "$got" -gt 128 ] || grep -Eq 'Sanitizer|runtime error:' err.txt; }; then
    # -r of a given mesh crashes on today's main (issue 30 item 1, fixed apart; its
    # tests cover the crash): skipped, loudly, until then
    echo "SKIP $r: lifthull triangle $* crashed (exit $got): $(head -c 120 err.txt)"
  elif [ "$got" -ne 0 ]; then
    bad "$r: lifthull triangle $* exit $got: $(head -c 300 err.txt)"
  else
    local out; out="$(ls *.node | grep -vxF -f inputs.txt | sed 's/\.node$//' | head -1)"
    check "$r ($*)" check_reference.py $flags "$ref/$r" "$PWD/$out"
  fi
  cd ..
}
reference A.1 --same "A.poly" -p A.poly
reference box.1 --same "box.poly" -pc box
reference double_hex.1 --same "double_hex.poly" -p double_hex.poly
reference double_hex2.1 --same "double_hex2.poly" -p double_hex2.poly
reference square_circle_hole.1 --same "square_circle_hole.poly" -p square_circle_hole.poly
reference spiral.1 --same "spiral.node" spiral
reference diamond_02_00009.1 --same "diamond_02_00009.node" diamond_02_00009.node
reference box.2 "" "ref/box.1.node ref/box.1.ele ref/box.1.poly" -rpa0.2 box.1
reference box.3 "" "ref/box.2.node ref/box.2.ele ref/box.2.poly" -rpa0.05 box.2
reference box.4 "" "ref/box.3.node ref/box.3.ele ref/box.3.poly" -rpa0.0125 box.3
reference double_hex.2 "" "ref/double_hex.1.node ref/double_hex.1.poly" -pqY -a0.0015 double_hex.1.poly
reference double_hex2.2 "" "ref/double_hex2.1.node ref/double_hex2.1.poly" -pqY -a0.0060 double_hex2.1.poly
reference double_hex3.1 "" "double_hex3.poly double_hex3.node" -pq -a0.0015 double_hex3.poly
reference la.1 "" "la.poly" -pqa la
reference spiral.q.1 "" "spiral.node" -q spiral
reference spiral.r.1 "" "spiral.node" -q32.5 spiral

# -v: the Voronoi diagram against Triangle's (check_voronoi.py: Voronoi vertices to
# 1e-8, as multisets, then the finite edges and the rays with their directions)
for r in "diamond_02_00009 diamond_02_00009.node" "dots dots"; do
  set -- $r
  rm -rf w; mkdir w; cd w; cp "$data/$1.node" .
  expect "-v $2" 0 '' '' -- "$lh" triangle -Qv "$2"
  check "-v $2 Voronoi" check_voronoi.py "$ref/$1.1" "$PWD/$1.1"
  cd ..
done

# Outputs of Triangle 1.6 (tests/oracles/triangle) for what drufat ships no reference
# of (triangle16/): -o2 quadratic elements, and -c on a point set writes the hull's
# edges to a .poly. Refined -o2 output: its structure, and markers against la.1.
t16="$data/triangle16"
rm -rf w; mkdir w; cd w; cp "$data/A.poly" .
expect "-po2 A.poly" 0 '' '' -- "$lh" triangle -Qpo2 A.poly
check "-po2 A.poly as Triangle" check_reference.py --same --o2 "$t16/A.1" "$PWD/A.1"
cd ..
rm -rf w; mkdir w; cd w; cp "$data/la.poly" .
expect "-pqao2 la.poly" 0 '' '' -- "$lh" triangle -Qpqao2 la.poly
check "-pqao2 la.poly" check_reference.py --o2 "$ref/la.1" "$PWD/la.1"
cd ..
rm -rf w; mkdir w; cd w; cp "$data/dots.node" .
expect "-c dots.node" 0 '' '' -- "$lh" triangle -Qc dots.node
exists dots.1.poly
check "-c dots.node as Triangle" check_reference.py --same "$t16/dots.1" "$PWD/dots.1"
rm dots.1.*
expect "dots.node: no .poly without -c" 0 '' '' -- "$lh" triangle -Q dots.node
absent dots.1.poly
cd ..
rm -rf w; mkdir w; cd w; cp "$data"/bbox.1.* .
expect "-rc bbox.1" 0 '' '' -- "$lh" triangle -Qrc bbox.1
check "-rc bbox.1: the mesh's boundary as Triangle" check_reference.py --same "$t16/bbox.2" "$PWD/bbox.2"
cd ..

# -s: segments split at midpoints until each is a chain of Delaunay edges. A.poly as
# Triangle 1.6 (31 vertices, triangle for triangle); la.poly: every edge locally
# Delaunay (Triangle's own -s output is not: it splits while inserting, earlier
# segments constraining later ones), 194 vertices against Triangle's 182, regions kept.
rm -rf w; mkdir w; cd w; cp "$data/A.poly" "$data/la.poly" .
expect "-ps A.poly" 0 '' '^A\.1: 31 points, 31 triangles \(2 Steiner points\)' -- "$lh" triangle -ps A.poly
check "-ps A.poly as Triangle" check_reference.py --same --delaunay "$t16/s/A.1" "$PWD/A.1"
expect "-psA la.poly" 0 '' '' -- "$lh" triangle -QpsA la.poly
check "-psA la.poly" check_reference.py --delaunay "$t16/s/la.1" "$PWD/la.1"
check "-psA la.poly regions" check_regions.py la.poly la.1
expect "-pA la.poly (no -s)" 0 '' '' -- "$lh" triangle -QpA la.poly
if "$py" "$tools/check_reference.py" --delaunay "$t16/s/la.1" "$PWD/la.1" > chk.txt; then bad "-pA la.poly is Delaunay: the -s test proves nothing"; else ok; fi
cd ..

# Markers of Steiner points (Triangle 1.6 on this square split by an interior
# segment, no marker columns): 1 on the boundary, 0 on the interior segment x = 1
mkdir -p nm; cd nm
printf '6 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 2 1\n5 1 1\n6 0 1\n7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n' > nm.poly
expect "-pa0.01 nm.poly" 0 '' '' -- "$lh" triangle -Qpa0.01 nm.poly
same "interior segment's points: marker 0" "$(awk 'NR > 1 && $2 == 1 && $3 > 0 && $3 < 1 { n++; z += $4 == 0 } END { print (n > 2 && n == z) }' nm.1.node)" 1
same "boundary points: marker 1" "$(awk 'NR > 1 && ($2 == 0 || $2 == 2 || $3 == 0 || $3 == 1) { n++; o += $4 == 1 } END { print (n > 6 && n == o) }' nm.1.node)" 1
cd ..

finish
