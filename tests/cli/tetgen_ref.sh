#!/usr/bin/env bash
# tetgen_ref.sh LIFTHULL DATA TETGEN: `lifthull tetgen` against TetGen 1.5 itself (run
# as a separate program, the Debian package), on point sets in general position, whose
# Delaunay tetrahedralization is unique: the same tetrahedra, the same faces (-f, with
# the same hull markers) and the same edges (-e) as sets of vertex sets, whatever the
# order. DATA = tests/data/tetgen3d.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
tetgen="$3"
# items FILE K: the K vertex numbers of each item after the header, sorted within the
# item, then the items sorted (with the rest of the line: markers)
items() {
  awk -v k="$2" 'NR == 1 || /^#/ || NF == 0 { next }
    { n = 0; for (j = 2; j <= k + 1; j++) v[++n] = $j
      for (i = 2; i <= n; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
      s = v[1]; for (j = 2; j <= n; j++) s = s " " v[j]
      for (j = k + 2; j <= NF; j++) s = s " " $j
      print s }' "$1" | sort
}

for seed in 3 11; do
  "$lh" points 2000 -d 3 --ball --seed "$seed" -o p.txt -f
  awk 'NR == 1 { next } NR == 2 { print $1, 3, 0, 0; next } { print NR - 2, $1, $2, $3 }' p.txt > a.node
  cp a.node b.node
  "$lh" tetgen -fenQ a.node > out.txt 2> err.txt || bad "lifthull tetgen seed $seed: $(cat err.txt)"
  "$tetgen" -fenQ b.node > /dev/null 2>&1 || bad "tetgen seed $seed failed"
  same "seed $seed: tetrahedra" "$(items a.1.ele 4 | md5sum)" "$(items b.1.ele 4 | md5sum)"
  same "seed $seed: faces and hull markers" "$(items a.1.face 3 | md5sum)" "$(items b.1.face 3 | md5sum)"
  same "seed $seed: edges" "$(items a.1.edge 2 | cut -d' ' -f1,2 | md5sum)" \
    "$(items b.1.edge 2 | cut -d' ' -f1,2 | md5sum)"
  # the point files agree to the bit (both write %.17g, TetGen its own way: compare values)
  same "seed $seed: points" "$(awk 'NR > 1 && !/^#/ { printf "%.17g %.17g %.17g\n", $2, $3, $4 }' a.1.node | md5sum)" \
    "$(awk 'NR > 1 && !/^#/ { printf "%.17g %.17g %.17g\n", $2, $3, $4 }' b.1.node | md5sum)"
  same "seed $seed: counts" "$(head -n1 a.1.ele | tr -s ' ')" "$(head -n1 b.1.ele | tr -s ' ' | sed 's/^ //')"
done
finish
