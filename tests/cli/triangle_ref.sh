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
  if "$py" "$tools/$@" > chk.txt 2>&1; then ok; else bad "$name: $(tail -3 chk.txt)"; fi
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

finish
