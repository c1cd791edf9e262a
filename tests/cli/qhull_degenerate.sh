#!/usr/bin/env bash
# qhull_degenerate.sh LIFTHULL — the Qhull front ends on exactly degenerate input (issue 30),
# against Qhull's own programs on inputs where Qhull's answer is exact too (points on the
# faces of an axis-parallel cube, integer grids):
#   qconvex   Fx: the same vertices (the corners), whatever the input order (as given,
#             reversed, rotated); i: as many facets as qconvex Qt (2D and 3D; a flat face
#             is triangulated from its corners alone);
#   qvoronoi  Fv, Fi, Fo, o on grids and cospherical sets in 2D, 3D and 4D: the same ridges,
#             regions, as Voronoi vertices and hyperplanes (qvoronoi_compare.py; no ridge between
#             sites that meet at one Voronoi vertex only, nor, in 4D, the bounded ones
#             Qhull prints across a smaller face); FN: each region's vertices, a cell once, as
#             'o' numbers them, as many as Qhull lists (qvoronoi_fn.py);
# and, without Qhull (which refuses them), qvoronoi Fi/Fo at extreme scales: every value
# finite, the exact bisectors (qvoronoi_planes.py), the same ridges and normals at 2^-1070
# and 2^1000 as at the unit scale; qconvex's planes (n, Fi, FD n), qvoronoi's vertices and
# qdelaunay's lifted coordinates (p) finite numbers there too, also past DBL_MAX, each
# checked in decimal (qhull_extreme.py).
# usage: qhull_degenerate.sh LIFTHULL [PYTHON3]. Skipped (77) when rbox, qconvex, qvoronoi or
# python3 is missing.
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; here="$(cd "$(dirname "$0")" && pwd)"
py="${2:-python3}"
for p in rbox qconvex qvoronoi "$py"; do command -v "$p" > /dev/null || { echo "SKIP: $p missing"; exit 77; }; done
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

# qvoronoi: Fv, Fi, Fo as Qhull's on exactly degenerate sets
printf '2 13\n5 0\n4 3\n3 4\n0 5\n-3 4\n-4 3\n-5 0\n-4 -3\n-3 -4\n0 -5\n3 -4\n4 -3\n0 0\n' > circle.txt
"$py" - > sphere.txt <<'PY'
import itertools
p = {tuple(a if j == k else 0 for j in range(3)) for a in (3, -3) for k in range(3)}
p |= {tuple(x * y for x, y in zip(q, s)) for q in itertools.permutations((2, 2, 1))
      for s in itertools.product((1, -1), repeat=3)}
p = sorted(p) + [(0, 0, 0), (0, 0, 1)]  # 30 sites on a sphere of radius 3, its centre, one more
print(3); print(len(p)); print("\n".join(" ".join(map(str, q)) for q in p))
PY
"$py" - > cell24.txt <<'PY'
import itertools
p = list(itertools.product((1, -1), repeat=4))
p += [tuple(a if j == k else 0 for j in range(4)) for k in range(4) for a in (2, -2)]
p.append((0, 0, 0, 0))  # the 24-cell's vertices (on a sphere of radius 2) and its centre
print(4); print(len(p)); print("\n".join(" ".join(map(str, q)) for q in p))
PY
"$lh" points --grid 5 -d 2 > grid52.txt; "$lh" points --grid 4 -d 3 > grid43.txt; "$lh" points --grid 3 -d 4 > grid34.txt
"$py" - > huge3.txt <<'PY'
import random
r = random.Random(1)  # 3D sites spread over [-DBL_MAX, DBL_MAX]
print(3); print(300); print("\n".join(" ".join(repr((2 * r.random() - 1) * 1.7976931348623157e308) for _ in range(3)) for _ in range(300)))
PY
"$py" - > dblmin2.txt <<'PY'
import random
r = random.Random(2)  # 2D sites at multiples of DBL_MIN
print(2); print(300); print("\n".join(" ".join(repr(r.randint(-600, 600) * 2.2250738585072014e-308) for _ in range(2)) for _ in range(300)))
PY
printf '2 5\n1.6e308 1.6e308\n1.7e308 1.7e308\n1.7e308 1.6e308\n1.6e308 1.7e308\n1.66e308 1.63e308\n' > beyond.txt
if "$py" "$here/qvoronoi_compare.py" "$lh" "$(command -v qvoronoi)" grid52.txt circle.txt grid43.txt sphere.txt \
     grid34.txt cell24.txt > cmp.txt 2>&1
then ok; else bad "qvoronoi Fv/Fi/Fo against Qhull: $(grep -v ' same$' cmp.txt | head -5)"; fi
if "$py" "$here/qvoronoi_fn.py" "$lh" "$(command -v qvoronoi)" grid52.txt circle.txt grid43.txt sphere.txt \
     grid34.txt cell24.txt > fn.txt 2>&1
then ok; else bad "qvoronoi FN: $(grep -E 'FAIL|Error' fn.txt | head -3)"; fi
for f in grid52.txt circle.txt sphere.txt huge3.txt dblmin2.txt beyond.txt; do
  case "$f" in huge3.txt | dblmin2.txt | beyond.txt) scales= ;; *) scales="-1070 1000" ;; esac
  if "$py" "$here/qvoronoi_planes.py" "$lh" "$f" $scales > planes.txt 2>&1
  then ok; else bad "qvoronoi Fi/Fo on $f: $(grep -E 'FAIL|DIFF|Error' planes.txt | head -3)"; fi
done
for f in sphere.txt huge3.txt dblmin2.txt beyond.txt; do
  case "$f" in sphere.txt) scales="-1070 1000" ;; *) scales= ;; esac
  if "$py" "$here/qhull_extreme.py" "$lh" "$f" $scales > extreme.txt 2>&1
  then ok; else bad "qconvex n Fi, qvoronoi p, qdelaunay p on $f: $(grep -E 'FAIL|Error' extreme.txt | head -3)"; fi
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
