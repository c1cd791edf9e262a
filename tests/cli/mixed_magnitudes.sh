#!/usr/bin/env bash
# mixed_magnitudes.sh LIFTHULL PYTHON DATA: `lifthull delaunay` on the mixed-magnitude sets
# of issue 30 item 11 (tests/data/points/mixed_magnitudes_*.txt: coordinates from +-1e300,
# +-1e-300, 1e-323, 5e-324, 0 and small integers in every call): the simplex count, and the
# simplices checked exactly by tests/oracles/exact_check.py (Python integers, independent of
# lifthull's predicates): local Delaunay on a sample of the interior facets, every boundary
# facet on the hull. Took 66 s (8D) and 122 s (5D) once; the predicate cost that made them
# slow is bounded by test_spint, not here (no timing).
set -u
lh="$1"; py="$2"; data="$3"
check="$(dirname "$0")/../oracles/exact_check.py"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail=0
run() { # NAME FILE SIMPLICES LIMIT
  local name="$1" f="$data/$2" want="$3" limit="$4"
  if ! "$lh" delaunay -q --threads 1 "$f" > "$tmp/$name.i" 2> "$tmp/err"; then
    echo "FAIL $name: delaunay exit $?: $(head -c 300 "$tmp/err")"; fail=1; return
  fi
  local got; got="$(head -n 1 "$tmp/$name.i")"
  if [ "$got" != "$want" ]; then echo "FAIL $name: $got simplices, want $want"; fail=1; fi
  if ! "$py" "$check" "$f" "$tmp/$name.i" --limit "$limit" > "$tmp/check" 2>&1; then
    echo "FAIL $name: $(cat "$tmp/check")"; fail=1
  else
    echo "ok $name: $(cat "$tmp/check")"
  fi
}
run mixed_8d mixed_magnitudes_8d_20.txt 1013 150
run mixed_5d mixed_magnitudes_5d_200.txt 10826 300
exit $fail
