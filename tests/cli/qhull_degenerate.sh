#!/usr/bin/env bash
# qhull_degenerate.sh LIFTHULL — the Qhull front ends on exactly degenerate input (issue 30),
# against Qhull's own programs on inputs where Qhull's answer is exact too (points on the
# faces of an axis-parallel cube, integer grids):
#   qconvex   Fx: the same vertices (the corners), whatever the input order (as given,
#             reversed, rotated); i: as many facets as qconvex Qt (2D and 3D; a flat face
#             is triangulated from its corners alone);
# Skipped (77) when rbox or qconvex is missing.
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; here="$(cd "$(dirname "$0")" && pwd)"
for p in rbox qconvex; do command -v "$p" > /dev/null || { echo "SKIP: $p missing"; exit 77; }; done
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
same() { if [ "$2" = "$3" ]; then ok; else bad "$1: '$2', want '$3'"; fi; }

# reorder FILE HOW > OUT: the points of a Qhull point file reversed ('rev') or rotated by
# a third ('rot'); `back HOW N` then maps an index of the reordered file to the original.
reorder() {
  awk -v how="$2" 'NR <= 2 { print; next } { p[n++] = $0 }
    END { for (i = 0; i < n; i++) print p[how == "rev" ? n - 1 - i : (i + int(n / 3)) % n] }' "$1"
}
back() { awk -v how="$1" -v n="$2" '{ print how == "rev" ? n - 1 - $1 : ($1 + int(n / 3)) % n }'; }
# the vertex set of `... Fx` output, one index a line, sorted
fx() { tail -n +2 | tr -s ' ' '\n' | grep -v '^$' | sort -n; }

sets=()
i=0
for spec in "100 D2 W0" "100 D3 W0" "c G1 D3 100 W0" "c D4 100 W0" "300 D3 W0 t7"; do
  rbox $spec > "set$i.txt"; sets+=("set$i.txt:rbox $spec"); i=$((i + 1))
done
for g in "5 -d 2" "4 -d 3" "3 -d 4"; do
  "$lh" points --grid $g > "set$i.txt"; sets+=("set$i.txt:grid $g"); i=$((i + 1))
done
for s in "${sets[@]}"; do
  f="${s%%:*}"; name="${s#*:}"
  n=$(sed -n 2p "$f"); d=$(sed -n 1p "$f" | awk '{ print $1 }')
  want=$(qconvex Fx < "$f" | fx | tr '\n' ' ')
  same "$name: qconvex Fx" "$("$lh" qconvex Fx < "$f" | fx | tr '\n' ' ')" "$want"
  for how in rev rot; do
    reorder "$f" "$how" > r.txt
    same "$name ($how): qconvex Fx" "$("$lh" qconvex Fx < r.txt | fx | back "$how" "$n" | sort -n | tr '\n' ' ')" "$want"
  done
  if [ "$d" -le 3 ]; then
    same "$name: facets as qconvex Qt" "$("$lh" qconvex i < "$f" | head -1)" "$(qconvex Qt i < "$f" | head -1)"
  fi
done
# the README's example set: Qhull's 17 hull vertices
same "examples/ukraine.txt: qconvex Fx" "$("$lh" qconvex Fx < "$here/../../examples/ukraine.txt" | head -1)" 17

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
