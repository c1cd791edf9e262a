#!/usr/bin/env bash
# triangle.sh LIFTHULL DATA: `lifthull triangle` end to end on Triangle's own inputs
# (DATA = tests/data/triangle) — its output file names (FILE.1.*, FILE.k -> FILE.k+1,
# -I), -z numbering, the .edge/.neigh files and every header line, the switches that
# suppress files or markers (-P -N -E -B, -j), -Q and -V, usage errors (unknown and
# unsupported switches, exit 2), bad input (exit 3, FILE:LINE[:COL]), and output files
# written all or none, never over an input; -v and -o2 at the ends of the range.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
fresh() { rm -rf w; mkdir w; for f in "$@"; do cp "$data/$f" w/; done; cd w; }

expect "--help" 0 '' '^usage: lifthull triangle' -- "$lh" triangle --help
expect "no file" 2 '^usage: lifthull triangle' '' -- "$lh" triangle -p

# names: A.poly -> A.1.*, A.1.poly -> A.2.*, no extension with -p -> A.poly
fresh A.poly
expect "-p A.poly" 0 '' '^A\.1: 29 points, 29 triangles \(0 Steiner points\), smallest angle' -- "$lh" triangle -p A.poly
exists A.1.node A.1.ele A.1.poly; absent A.1.edge A.1.neigh A.1.off
# A.poly: 29 vertices with one attribute and markers, 29 segments, one hole
same "A.1.node header" "$(line A.1.node 1)" "29 2 1 1"
same "A.1.node first" "$(line A.1.node 2 | cut -d' ' -f1)" "1"
same "A.1.ele header" "$(line A.1.ele 1)" "29 3 0"
same "A.1.poly header" "$(line A.1.poly 1)" "0 2 1 1"
same "A.1.poly segments" "$(line A.1.poly 2)" "29 1"
same "A.1.poly holes" "$(grep -v '^ ' A.1.poly | sed -n 3p | tr -d ' ')" "1"
same "A.1.ele lines" "$(wc -l < A.1.ele | tr -d ' ')" "30"
expect "-pQ A.1.poly" 0 '' '' -- "$lh" triangle -pQ A.1.poly
exists A.2.node A.2.ele A.2.poly
same "A.2.ele = A.1.ele" "$(cmp -s A.1.ele A.2.ele && echo same)" "same"
rm -f A.1.*
expect "-pQ A (no extension)" 0 '' '' -- "$lh" triangle -pQ A
exists A.1.node A.1.ele A.1.poly
cd ..

# -q30: the bound met (A has no input angle below 30 degrees); -V the report
fresh A.poly
expect "-pq30V" 0 '' '^Angles: smallest (3[0-9]|[4-9][0-9])' -- "$lh" triangle -pq30V A.poly
matches out.txt '^Triangles below the bounds: 0$' && ok || bad "-V: bad triangles line: $(cat out.txt)"
# -V numbers the triangles below the bounds as the .ele: from 1, from 0 with -z
cp "$data/la.poly" .
expect "-pq30V la.poly" 0 '' '^Triangles below the bounds: [0-9]+, numbered from 1 as the files: ' -- "$lh" triangle -pq30V la.poly
one="$(sed -nE 's/.*numbered from 1 as the files: ([0-9]+).*/\1/p' out.txt)"
expect "-pzq30V la.poly" 0 '' "^Triangles below the bounds: [0-9]+, numbered from 0 as the files: $((one - 1)) " -- "$lh" triangle -pzq30V la.poly
expect "-q41 refused" 2 "the angle bound must be 0\.\.40 degrees" '' -- "$lh" triangle -pq41 A.poly
# -S beyond any size_t (1e30, 1e400) is no limit: the same mesh as without -S (it
# became a budget of 0, UB in the conversion); -S alone is 0, as Triangle; a sign is
# refused
expect "-pq30Q" 0 '' '' -- "$lh" triangle -pq30Q A.poly
mv A.1.ele unbounded.ele
expect "-pq30S1e30" 0 '' '^A\.1: 78 points, 89 triangles \(49 Steiner points\)' -- "$lh" triangle -pq30S1e30 A.poly
same "-S1e30 = no -S" "$(cmp -s A.1.ele unbounded.ele && echo same)" "same"
expect "-pq30S1e400" 0 '' '^A\.1: 78 points, 89 triangles \(49 Steiner points\)' -- "$lh" triangle -pq30S1e400 A.poly
expect "-pq30S10" 0 '' '^A\.1: 39 points, 39 triangles \(10 Steiner points\)' -- "$lh" triangle -pq30S10 A.poly
expect "-pq30S" 0 '' '^A\.1: 29 points, 29 triangles \(0 Steiner points\)' -- "$lh" triangle -pq30S A.poly
expect "-S-1 refused" 2 "^lifthull triangle: -S takes a count of Steiner points \(0 or more\), not '-1'$" '' -- "$lh" triangle -pq30S-1 A.poly
cd ..

# -z: everything from 0; -e, -n: the .edge and .neigh files
fresh A.poly
expect "-pzenQ" 0 '' '' -- "$lh" triangle -pzenQ A.poly
exists A.1.edge A.1.neigh
same "-z .node first" "$(line A.1.node 2 | cut -d' ' -f1)" "0"
same "-z .ele first" "$(line A.1.ele 2 | cut -d' ' -f1)" "0"
same "-z .poly first segment" "$(line A.1.poly 3 | cut -d' ' -f1)" "0"
same "-z .edge first" "$(line A.1.edge 2 | cut -d' ' -f1)" "0"
same "-z .neigh first" "$(line A.1.neigh 2 | cut -d' ' -f1)" "0"
# every point number in the .ele is 0..28
same "-z .ele range" "$(awk 'NR > 1 && NF { for (i = 2; i <= 4; i++) { if ($i < lo || lo == "") lo = $i; if ($i > hi) hi = $i } } END { print lo, hi }' A.1.ele)" "0 28"
# 29 triangles: 3*29 = 2E - B edge sides, B = 29 boundary edges, so E = 58; markers on
same ".edge header" "$(line A.1.edge 1)" "58 1"
same ".neigh header" "$(line A.1.neigh 1)" "29 3"
same ".edge boundary markers" "$(awk 'NR > 1 && $4 == 1' A.1.edge | wc -l | tr -d ' ')" "29"
same ".neigh -1 count" "$(awk 'NR > 1 { for (i = 2; i <= 4; i++) n += $i == -1 } END { print n }' A.1.neigh)" "29"
cd ..

# -B: no markers anywhere; -P -N -E: no .poly, .node, .ele
fresh A.poly
expect "-peBQ" 0 '' '' -- "$lh" triangle -peBQ A.poly
same "-B .node header" "$(line A.1.node 1)" "29 2 1 0"
same "-B .node fields" "$(line A.1.node 2 | wc -w | tr -d ' ')" "4"
same "-B .poly segments" "$(line A.1.poly 2)" "29 0"
same "-B .edge header" "$(line A.1.edge 1)" "58 0"
rm -f A.1.*
expect "-pPQ" 0 '' '' -- "$lh" triangle -pPQ A.poly
exists A.1.node A.1.ele; absent A.1.poly
rm -f A.1.*
expect "-pNQ" 0 '' '' -- "$lh" triangle -pNQ A.poly
exists A.1.ele A.1.poly; absent A.1.node
rm -f A.1.*
expect "-pEQ" 0 '' '' -- "$lh" triangle -pEQ A.poly
exists A.1.node A.1.poly; absent A.1.ele
rm -f A.1.*
expect "-pgQ" 0 '' '' -- "$lh" triangle -pgQ A.poly
same "-g .off header" "$(line A.1.off 1) $(line A.1.off 2)" "OFF 29 29 0"
cd ..

# -j: a duplicate point is in no triangle; -j leaves it out of the .node
mkdir -p j; cd j
printf '6 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n5 0.5 0.5\n6 1 0\n' > dots.node
expect ".node input" 0 '' '^dots\.1: 6 points, 4 triangles' -- "$lh" triangle dots.node
same ".node: no .poly" "$(ls | tr '\n' ' ')" "dots.1.ele dots.1.node dots.node err.txt out.txt "
same "without -j" "$(line dots.1.node 1)" "6 2 0 1"
expect "-jQ" 0 '' '' -- "$lh" triangle -jQ dots.node
same "-j .node header" "$(line dots.1.node 1)" "5 2 0 1"
same "-j .ele range" "$(awk 'NR > 1 { for (i = 2; i <= 4; i++) if ($i > hi) hi = $i } END { print hi }' dots.1.ele)" "5"
cd ..

# -I: no iteration number, so the output would be the input: refused, nothing written
fresh A.poly
cp A.poly A.orig
expect "-pI refuses A.poly" 1 "lifthull triangle: 'A\.poly' is the input file; it is not overwritten" '' -- "$lh" triangle -pIQ A.poly
cmp -s A.poly A.orig && ok || bad "-pI changed A.poly"
absent A.node A.ele
same "-pI leaves nothing" "$(ls | tr '\n' ' ')" "A.orig A.poly err.txt out.txt "
expect "-pIP writes beside it" 0 '' '' -- "$lh" triangle -pIPQ A.poly
exists A.node A.ele
cmp -s A.poly A.orig && ok || bad "-pIP changed A.poly"
cd ..
# a .poly without vertices reads FILE.node: that is an input too
mkdir -p v; cd v
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' > sq.node
printf '0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' > sq.poly
cp sq.node sq.orig
expect "vertices from the .node" 0 '' '^sq\.1: 4 points, 2 triangles' -- "$lh" triangle -p sq.poly
expect "-pIP refuses the .node" 1 "lifthull triangle: 'sq\.node' is an input file; it is not overwritten" '' -- "$lh" triangle -pIPQ sq.poly
cmp -s sq.node sq.orig && ok || bad "-pIP changed sq.node"
absent sq.ele
cd ..

# all or none: one output path that cannot be written (a directory), nothing left
fresh A.poly
mkdir A.1.ele
expect "unwritable output" 1 "lifthull triangle: " '' -- "$lh" triangle -pQ A.poly
absent A.1.node A.1.poly
same "no temporaries" "$(ls | grep -c tmp)" "0"
cd ..

# -r: refine bbox.1.node + bbox.1.ele (-a: with bbox.1.area's bounds) into bbox.2.*
fresh bbox.1.node bbox.1.ele bbox.1.area
expect "-r" 0 '' '^bbox\.2: ' -- "$lh" triangle -r bbox.1
exists bbox.2.node bbox.2.ele
absent bbox.2.poly
same "-r keeps the 12 triangles' union, no Steiner point" "$(head -1 bbox.2.ele | awk '{print $1}')" "12"
expect "-ra" 0 '' '' -- "$lh" triangle -raQ bbox.1.ele
same "-ra splits the bounded triangle" "$(awk 'NR == 1 {print ($1 > 40)}' bbox.2.ele)" "1"
printf '12\n1 -1\n2 -1\n' > short.area; cp bbox.1.node short.node; cp bbox.1.ele short.ele
expect "-ra short .area" 3 '^short\.area:4:1: expected triangle number 3, found the end of the file$' '' -- "$lh" triangle -ra short
printf '3  3  0\n1 1 2 3\n2 1 2 99\n3 4 5 6\n' > bad.ele; cp bbox.1.node bad.node
expect "-r bad .ele" 3 '^bad\.ele:3:' '' -- "$lh" triangle -r bad
cp bbox.1.node nothere.node
expect "-r missing .ele" 3 '^nothere\.ele: No such file' '' -- "$lh" triangle -r nothere.node
absent bad.1.node short.1.node
cd ..

# -r with -a or -q on a mesh lifthull wrote: Steiner points on the old boundary were
# dropped as if removed, leaving triangles on point -1 (a double free). The union is
# kept, every corner is a point of the .node, and every triangle meets -a.
# mesh_sum FILE: "points triangles lowest highest total-area largest-area" of FILE.node/.ele
mesh_sum() {
  awk 'FNR == 1 { f++; if (f == 1) np = $1; else nt = $1; next }
       f == 1 && NF { x[$1] = $2; y[$1] = $3 }
       f == 2 && NF { for (i = 2; i <= 4; i++) { if (lo == "" || $i < lo) lo = $i; if ($i > hi) hi = $i }
                      a = ((x[$3] - x[$2]) * (y[$4] - y[$2]) - (y[$3] - y[$2]) * (x[$4] - x[$2])) / 2
                      s += a; if (a > mx) mx = a }
       END { printf "%d %d %d %d %.9g %.9g\n", np, nt, lo, hi, s, mx }' "$1.node" "$1.ele"
}
fresh box.poly face.poly
expect "-pcQ box.poly" 0 '' '' -- "$lh" triangle -pcQ box.poly
expect "-rpa0.2 box.1" 0 '' '^box\.2: ' -- "$lh" triangle -rpa0.2 box.1
read -r np nt lo hi total big <<< "$(mesh_sum box.2)"
same "-rpa0.2: corners are points 1..$np" "$lo $((hi <= np))" "1 1"
same "-rpa0.2: the union of box.1 kept" "$total" "$(mesh_sum box.1 | cut -d' ' -f5)"
same "-rpa0.2: every triangle at most 0.2" "$(awk -v b="$big" 'BEGIN { print (b <= 0.2) }')" "1"
expect "-pQ face.poly" 0 '' '' -- "$lh" triangle -pQ face.poly
for sw in -rq30 -rpq30 -ra20; do
  rm -f face.2.*
  expect "$sw face.1" 0 '' '^face\.2: ' -- "$lh" triangle "$sw" face.1
  read -r np nt lo hi total big <<< "$(mesh_sum face.2)"
  same "$sw face.1: corners are points 1..$np" "$lo $((hi <= np))" "1 1"
  same "$sw face.1: the union of face.1 kept" "$total" "$(mesh_sum face.1 | cut -d' ' -f5)"
done
cd ..

# usage errors: exit 2, the switch named
fresh A.poly
expect "unknown switch" 2 "lifthull triangle: unknown switch 'x' in '-pxq'" '' -- "$lh" triangle -pxq A.poly
expect "-o3 refused" 2 "lifthull triangle: -o must be -o2 \(quadratic elements\), not '-po3'" '' -- "$lh" triangle -po3 A.poly
expect "-u refused" 2 "lifthull triangle: -u is not supported" '' -- "$lh" triangle -pu A.poly
# the --help synopsis names every switch parse_switches accepts, the refused ones
# after "not supported"
"$lh" triangle --help > help.txt
same "--help synopsis" "$(sed -n '1s/.*\[-\([^]]*\)\].*/\1/p' help.txt | fold -w1 | sort | tr -d '\n')" \
  "$(printf '%s' prqaAcDsYSjevno2zBPNEIOQVgilFCX | fold -w1 | sort | tr -d '\n')"
for c in s v; do "$lh" triangle -Q$c A.poly > /dev/null 2>&1 || bad "-$c refused"; done
matches help.txt '^not supported \(refused\): -u -k -L -w -W$' && ok || bad "--help: the refused switches"
expect "two files" 2 "one input file, not 'A\.poly' and 'B\.poly'" '' -- "$lh" triangle -p A.poly B.poly
expect "accepted, no effect" 0 '' '' -- "$lh" triangle -pQiFlCX A.poly
expect "-D conforming" 0 '' '' -- "$lh" triangle -pDQ A.poly
cd ..

# bad input: exit 3, the place named
mkdir -p b; cd b
expect "missing file" 3 "^nosuch\.poly: No such file or directory" '' -- "$lh" triangle -p nosuch.poly
printf '# two segments that cross\n4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 2\n2 3 4\n0\n' > cross.poly
expect "crossing segments" 3 '^cross\.poly:9: segment 2 crosses segment 1 \(line 8\)$' '' -- "$lh" triangle -p cross.poly
absent cross.1.node cross.1.ele cross.1.poly
printf '4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 3\n2 3 7\n0\n' > range.poly
expect "endpoint out of range" 3 "^range\.poly:8:5: expected an endpoint of segment 2 \(a vertex number from 1 to 4\), found '7'$" '' -- "$lh" triangle -p range.poly
printf '3 2 0 0\n1 0 0\n2 1 1\n3 2 2\n0 0\n0\n' > line.poly
expect "collinear" 3 "^line\.poly: the vertices are all collinear" '' -- "$lh" triangle -p line.poly
cp "$data/box.poly" .
expect "unclosed boundary" 3 "^box\.poly: the domain is empty" '' -- "$lh" triangle -p box.poly
expect "-c keeps the hull" 0 '' '' -- "$lh" triangle -pcQ box.poly
exists box.1.node box.1.ele box.1.poly
cd ..

# -v and -o2 at the ends of the range: the Voronoi vertices of points scaled by 2^k are
# the unit-scale ones times 2^k (at 2^-1000 the squared lengths underflowed: every
# vertex was NaN), and -o2's midpoints and -v's rays on a square at +-2^1023 are
# finite (the sums and differences overflowed: inf in the .node and .v.edge)
rm -rf w; mkdir w; cd w
for k in 0 -1000 1000; do
  awk -v k="$k" 'BEGIN { f = 2 ^ k; split("0 0 4 0 0 4 4 4 1 2", c, " "); print "5 2 0 0"
                         for (i = 1; i <= 5; i++) printf "%d %.17g %.17g\n", i, c[2*i-1] * f, c[2*i] * f }' > "s$k.node"
  expect "-v 2^$k" 0 '' '' -- "$lh" triangle -vQ "s$k.node"
done
for k in -1000 1000; do
  same "-v 2^$k: the unit Voronoi vertices scaled" "$(awk -v k="$k" 'FNR == 1 { f++; next }
      f == 1 { x[$1] = $2; y[$1] = $3; next } !($2 == x[$1] * 2 ^ k && $3 == y[$1] * 2 ^ k) { bad++ }
      END { print bad + 0, FNR }' s0.1.v.node "s$k.1.v.node")" "0 5"
done
printf '4 2 0 0\n1 -0x1p1023 -0x1p1023\n2 0x1p1023 -0x1p1023\n3 0x1p1023 0x1p1023\n4 -0x1p1023 0x1p1023\n' > big.node
expect "-o2 -v at +-2^1023" 0 '' '' -- "$lh" triangle -o2vQ big.node
same "-v at +-2^1023: the rays' directions" "$(awk '$3 == -1 { printf "%s %s;", $4, $5 }' big.1.v.edge)" \
  "-8.9884656743115795e+307 0;0 -8.9884656743115795e+307;0 8.9884656743115795e+307;8.9884656743115795e+307 0;"
same "-o2 at +-2^1023: midpoints" "$(awk 'NR > 5 { printf "%s %s;", $2, $3 }' big.1.node)" \
  "0 0;-8.9884656743115795e+307 0;0 -8.9884656743115795e+307;0 8.9884656743115795e+307;8.9884656743115795e+307 0;"
# a circumcentre past DBL_MAX is written with all its digits, never inf (docs/meshing.md):
# (0, (1e600 - 1e616) / 2e300) for the flat triangle; a needle at unit scale (its cross
# product from the first vertex cancels to 0) gets its centre (-1, 2) to within ulps
printf '4 2 0 0\n1 -1e308 0\n2 1e308 0\n3 0 1e300\n4 0 1e305\n' > far.node
expect "-v past DBL_MAX" 0 '' '' -- "$lh" triangle -vQ far.node
same "-v past DBL_MAX: the centres" "$(awk 'NR > 1 { printf "%s %s;", $2, $3 }' far.1.v.node)" \
  "0 -4.9999999999999993e+315;-5.0000000000499988e+307 5.0000499988205894e+304;5.0000000000499988e+307 5.0000499988205894e+304;"
printf '3 2 0 0\n1 0 0\n2 1 1.0000000000000002\n3 0.99999999999999989 1\n' > needle.node
expect "-v needle" 0 '' '' -- "$lh" triangle -vQ needle.node
same "-v needle: the centre" "$(awk 'NR > 1 { printf "%s %s;", $2, $3 }' needle.1.v.node)" "-1.0000000000000004 2.0000000000000004;"
cd ..

finish
