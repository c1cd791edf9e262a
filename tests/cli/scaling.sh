#!/usr/bin/env bash
# scaling.sh LIFTHULL: work that must grow linearly with the input, checked by
# valgrind's instruction count (deterministic, unlike a time) at n and 4n: a ratio
# above 8 fails (linear: about 4; quadratic: about 16). Skipped (77) without valgrind.
#   hole seeds  `triangle -pQ` of a square ring around a k x k grid of free vertices
#               with a hole seed on every one of them (each seed is checked against
#               the subsegments at its vertex: the vertex's fan, not every triangle)
set -u
command -v valgrind > /dev/null || { echo "valgrind not found: skipped"; exit 77; }
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0

# ring.poly for k: outer square [0, k+3]^2, the inner one [1, k+2]^2 (its sides are
# segments), the grid points (1.5 + i, 1.5 + j), a hole seed on each.
ring() {
  awk -v k="$1" 'BEGIN {
    L = k + 3; print 8 + k * k, 2, 0, 0
    split("0 0 " L " 0 " L " " L " 0 " L " 1 1 " L-1 " 1 " L-1 " " L-1 " 1 " L-1, c, " ")
    for (i = 1; i <= 8; i++) print i, c[2 * i - 1], c[2 * i]
    for (j = 0; j < k; j++) for (i = 0; i < k; i++) print 9 + j * k + i, 1.5 + i, 1.5 + j
    print 8, 0
    for (i = 1; i <= 4; i++) print i, i, i % 4 + 1
    for (i = 1; i <= 4; i++) print i + 4, i + 4, i % 4 + 5
    print k * k
    for (j = 0; j < k; j++) for (i = 0; i < k; i++) print 1 + j * k + i, 1.5 + i, 1.5 + j
  }' > "ring$1.poly"
}

# instructions NAME COMMAND...: valgrind's instruction count of COMMAND (0 when it fails)
instructions() {
  local name="$1"; shift
  if ! valgrind --tool=callgrind --callgrind-out-file=cg.out "$@" > out.txt 2> err.txt; then
    echo "FAIL $name: $(grep -v '^==' err.txt | tail -n 3)" >&2; echo 0; return
  fi
  sed -n 's/.*Collected : \([0-9]*\).*/\1/p' err.txt
}

ring 30; ring 60
a=$(instructions "hole seeds, k=30" "$lh" triangle -pQ ring30.poly)
b=$(instructions "hole seeds, k=60" "$lh" triangle -pQ ring60.poly)
[ "$(head -n1 ring60.1.ele | tr -s ' ')" = "8 3 0" ] || { echo "FAIL hole seeds: not the 8 triangles of the ring"; fail=1; }
if [ "$a" -eq 0 ] || [ "$b" -eq 0 ]; then fail=1
elif [ $((b > 8 * a)) -eq 1 ]; then echo "FAIL hole seeds: $a -> $b instructions for 4x the seeds"; fail=1; fi
echo "hole seeds: $a -> $b instructions for 900 -> 3600 seeds"
[ "$fail" -eq 0 ] && echo "scaling: all linear"
exit "$fail"
