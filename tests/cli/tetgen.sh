#!/usr/bin/env bash
# tetgen.sh LIFTHULL DATA: `lifthull tetgen` end to end (DATA = tests/data/tetgen3d) —
# output file names (FILE.1.*, FILE.k -> FILE.k+1, -I), every switch's effect on the
# files (-z -f -e -n -k -g -A -B -N -E -F -Q -V), quality refinement (-q -a), the
# switches refused (those not implemented yet), usage errors (exit 2), bad input (exit 3,
# "lifthull tetgen: FILE:LINE:COL: ..."), and output files written all or none.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
fresh() { rm -rf w; mkdir w; for f in "$@"; do cp "$data/$f" w/; done; cd w; }
# volume FILE.node FILE.ele: the tetrahedra's total volume and their least signed
# volume (6 times each), the .node and .ele numbered alike
volume() {
  awk 'FNR == 1 { file++; next } file == 1 { x[$1] = $2; y[$1] = $3; z[$1] = $4; next }
       { a = $2; ux = x[$3] - x[a]; uy = y[$3] - y[a]; uz = z[$3] - z[a]
         vx = x[$4] - x[a]; vy = y[$4] - y[a]; vz = z[$4] - z[a]
         wx = x[$5] - x[a]; wy = y[$5] - y[a]; wz = z[$5] - z[a]
         d = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)
         s += d; if (NR == FNR + 0 || min == "" || d < min) min = d }
       END { printf "%g %g\n", s, min }' "$1" "$2"
}
# over FILE.node FILE.ele V: how many tetrahedra have a volume over V
over() {
  awk -v v="$3" 'FNR == 1 { file++; next } file == 1 { x[$1] = $2; y[$1] = $3; z[$1] = $4; next }
    { a = $2; ux = x[$3] - x[a]; uy = y[$3] - y[a]; uz = z[$3] - z[a]; vx = x[$4] - x[a]; vy = y[$4] - y[a]
      vz = z[$4] - z[a]; wx = x[$5] - x[a]; wy = y[$5] - y[a]; wz = z[$5] - z[a]
      d = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)
      if (d / 6 > v) n++ } END { print n + 0 }' "$1" "$2"
}

expect "--help" 0 '' '^usage: lifthull tetgen' -- "$lh" tetgen --help
expect "no file" 2 '^usage: lifthull tetgen' '' -- "$lh" tetgen -p
expect "two files" 2 "^lifthull tetgen: one input file, not 'a.node' and 'b.node'$" '' -- "$lh" tetgen a.node b.node

# a point set: the Delaunay tetrahedralization, FILE.1.node .ele .face
fresh cube.node
expect "cube.node" 0 '' '^cube\.1: 8 points, 6 tetrahedra, 12 boundary faces \(0 Steiner points\)' -- \
  "$lh" tetgen cube.node
exists cube.1.node cube.1.ele cube.1.face; absent cube.1.edge cube.1.neigh cube.1.vtk cube.1.mesh
same "cube.1.node header" "$(line cube.1.node 1)" "8 3 0 0"
same "cube.1.node first" "$(line cube.1.node 2)" "1 0 0 0"
same "cube.1.ele header" "$(line cube.1.ele 1)" "6 4 0"
same "cube.1.ele lines" "$(wc -l < cube.1.ele | tr -d ' ')" "7"
same "cube.1.face header" "$(line cube.1.face 1)" "12 0"
same "cube.1.face lines" "$(wc -l < cube.1.face | tr -d ' ')" "13"
# the six tetrahedra fill the cube (6 * volume 1), each positively oriented
read -r vol least < <(volume cube.1.node cube.1.ele)
same "total volume" "$vol" "6"
[ "$(awk -v m="$least" 'BEGIN { print (m > 0) }')" = 1 ] && ok || bad "a tetrahedron of volume $least"
# the boundary faces' normals (b - a) x (c - a) point into the domain (lh_tetmesh_faces)
same ".face inward" "$(awk 'FNR == 1 { file++; next } file == 1 { x[$1] = $2; y[$1] = $3; z[$1] = $4; next }
  { a = $2; ux = x[$3] - x[a]; uy = y[$3] - y[a]; uz = z[$3] - z[a]; vx = x[$4] - x[a]; vy = y[$4] - y[a]
    vz = z[$4] - z[a]; d = (uy * vz - uz * vy) * (0.5 - x[a]) + (uz * vx - ux * vz) * (0.5 - y[a])
    d += (ux * vy - uy * vx) * (0.5 - z[a]); if (d > 0) inward++ } END { print inward + 0 }' cube.1.node cube.1.face)" "12"
# TetGen's file names: FILE.1.node in, FILE.2.* out; no extension: FILE.node
expect "cube.1.node" 0 '' '^cube\.2: ' -- "$lh" tetgen cube.1.node
exists cube.2.node cube.2.ele cube.2.face
same "cube.2.ele = cube.1.ele" "$(cmp -s cube.1.ele cube.2.ele && echo same)" "same"
rm -f cube.1.*
expect "cube (no extension)" 0 '' '^cube\.1: ' -- "$lh" tetgen cube
exists cube.1.node cube.1.ele cube.1.face
# -I: no iteration number, so FILE.node, the input itself: refused, nothing written
rm -f cube.1.*
expect "-I over the input" 1 "^lifthull tetgen: 'cube\.node' is the input file; it is not overwritten$" '' -- \
  "$lh" tetgen -I cube.node
absent cube.ele cube.face
cd ..

# -z numbers from 0; -f every face, -e every edge (markers), -n .neigh, -k .vtk, -g .mesh
fresh cube.node
expect "-zfenkg" 0 '' '^cube\.1: ' -- "$lh" tetgen -zfenkg cube.node
exists cube.1.node cube.1.ele cube.1.face cube.1.edge cube.1.neigh cube.1.vtk cube.1.mesh
same "-z .node first" "$(line cube.1.node 2)" "0 0 0 0"
same "-z .ele first number" "$(line cube.1.ele 2 | cut -d' ' -f1)" "0"
same "-f .face header" "$(line cube.1.face 1)" "18 1"
same "-f hull faces marked 1" "$(awk 'NR > 1 { c[$5]++ } END { print c[0] + 0, c[1] + 0 }' cube.1.face)" "6 12"
same "-e .edge header" "$(line cube.1.edge 1)" "19 1"
same "-e .edge lines" "$(wc -l < cube.1.edge | tr -d ' ')" "20"
same "-n .neigh header" "$(line cube.1.neigh 1)" "6 4"
# neighbours are mutual: t lists u exactly when u lists t
same "-n mutual" "$(awk 'NR > 1 { for (j = 2; j <= 5; j++) if ($j >= 0) { e[$1 " " $j]++; n++ } }
  END { for (k in e) { split(k, p, " "); if (!((p[2] " " p[1]) in e)) bad++ } print n, bad + 0 }' cube.1.neigh)" "12 0"
same "-k .vtk header" "$(head -n 5 cube.1.vtk | tr '\n' '/')" \
  "# vtk DataFile Version 2.0/Unstructured Grid/ASCII/DATASET UNSTRUCTURED_GRID/POINTS 8 double/"
matches cube.1.vtk '^CELLS 6 30$' && matches cube.1.vtk '^CELL_TYPES 6$' && ok || bad "-k: CELLS / CELL_TYPES"
same "-k cell types" "$(grep -cx 10 cube.1.vtk)" "6"
same "-g .mesh sections" "$(grep -E '^[A-Z]' cube.1.mesh | tr '\n' '/')" \
  "MeshVersionFormatted 1/Dimension 3/Vertices/Triangles/Tetrahedra/End/"
same "-g .mesh tetrahedra" "$(sed -n '/^Tetrahedra/{n;p}' cube.1.mesh)" "6"
# .ele numbered from 0 with -z; the .vtk always from 0: the same cells
same "-k = -z .ele" "$(awk '/^CELLS/ { on = 1; next } /^$/ { on = 0 } on { print $2, $3, $4, $5 }' cube.1.vtk)" \
  "$(awk 'NR > 1 { print $2, $3, $4, $5 }' cube.1.ele)"
# -B: no markers; -N -E -F: no .node, .ele, .face/.edge
rm -f cube.1.*
expect "-feB" 0 '' '' -- "$lh" tetgen -feBQ cube.node
same "-B .face header" "$(line cube.1.face 1)" "18 0"
same "-B .edge header" "$(line cube.1.edge 1)" "19 0"
rm -f cube.1.*
expect "-NEF" 0 '' '' -- "$lh" tetgen -NEFnQ cube.node
exists cube.1.neigh; absent cube.1.node cube.1.ele cube.1.face cube.1.edge
# -Q quiet; -V statistics; -Y -c -S -A -T -X -M change nothing for a point set
rm -f cube.1.*
expect "-Q" 0 '' '' -- "$lh" tetgen -Q cube.node
cp cube.1.ele plain.ele
expect "-V" 0 '' '^  Steiner points: 0 \(0 on segments, 0 on facets, 0 interior\)$' -- "$lh" tetgen -V cube.node
matches out.txt '^Statistics:$' && matches out.txt '^  Mesh tetrahedra: 6$' && ok || bad "-V: $(cat out.txt)"
expect "-YcS5AT1e-8XMJ" 0 '' '' -- "$lh" tetgen -YcS5AT1e-8XMJQ cube.node
same "-YcS5AT1e-8XMJ = plain" "$(cmp -s cube.1.ele plain.ele && echo same)" "same"
cd ..

# quality refinement: -q's radius-edge bound, -a's volume bound met (box.poly: no
# small angle, so no tet is left over), the mesh valid (-C); bad bounds: exit 2
fresh box.poly
expect "-pq1.2" 0 '' 'tetrahedra left over the radius-edge bound: 0, over the volume bound: 0' -- \
  "$lh" tetgen -pq1.2VC box.poly
matches out.txt '^check: the mesh is valid and conforms' && ok || bad "-pq1.2 -C: $(cat out.txt)"
awk '/Largest radius-edge ratio/ { exit !($4 <= 1.2) }' out.txt && ok || bad "-pq1.2: $(grep Largest out.txt)"
expect "-pa0.01" 0 '' '^box\.1: ' -- "$lh" tetgen -pa0.01VC box.poly
matches out.txt '^check: the mesh is valid and conforms' && ok || bad "-pa0.01 -C: $(cat out.txt)"
read -r vol least < <(volume box.1.node box.1.ele)
same "-pa0.01 volume" "$vol" "6"
same "-pa0.01 tets at most 0.01" "$(over box.1.node box.1.ele 0.01)" "0"
same "-pa0.01 refined" "$(awk 'NR == 1 { print ($1 > 100) }' box.1.ele)" "1"
# -a alone: the region's volume bound (box.poly's region, given 0.005); -A its attribute
sed 's/^1 0.5 0.5 0.5 7 0$/1 0.5 0.5 0.5 7 0.005/' box.poly > boxr.poly
expect "-pqaA" 0 '' 'over the volume bound: 0' -- "$lh" tetgen -pqaAVC boxr.poly
read -r vol least < <(volume boxr.1.node boxr.1.ele)
same "-pqaA volume" "$vol" "6"
same "-pqaA tets at most 0.005" "$(over boxr.1.node boxr.1.ele 0.005)" "0"
same "-pqaA attributes" "$(awk 'NR > 1 { print $6 }' boxr.1.ele | sort -u)" "7"
expect "-q0.5" 2 '^lifthull tetgen: -q takes a radius-edge bound of 1 or more, not 0\.5$' '' -- \
  "$lh" tetgen -pq0.5 box.poly
expect "-q1.2/95" 2 '^lifthull tetgen: -q R/D takes a dihedral angle from 0 to 90 degrees, not 95$' '' -- \
  "$lh" tetgen -pq1.2/95 box.poly
expect "-a0" 2 '^lifthull tetgen: -a takes a volume bound above 0, not 0$' '' -- "$lh" tetgen -pa0 box.poly
# -V lists the tets left over the bound (a 1-degree wedge: many), counted by why, the
# nearest small input angle beside each
cp "$data/../mesh3d/wedge-1.smesh" .
expect "-pq1.414V wedge" 0 '' '^  Tetrahedra left over the bounds: [1-9]' -- "$lh" tetgen -pq1.414VQ wedge-1.smesh
same "leftovers = over the bound" "$(sed -n 's/^  Tetrahedra left over the bounds: //p' out.txt)" \
  "$(sed -n 's/.*left over the radius-edge bound: \([0-9]*\),.*/\1/p' out.txt)"
same "leftovers by why" "$(awk '/left over the bounds:/ { f = 1; next } f && /^    [0-9]+: / { s += $1 } /^  the worst/ { f = 0 }
  END { print s }' out.txt)" "$(sed -n 's/^  Tetrahedra left over the bounds: //p' out.txt)"
same "leftovers listed" "$(grep -c '^    [0-9.e+]*; [0-9]*: [0-9]* [0-9]* [0-9]* [0-9]*; .*; 1 degrees between' out.txt)" "20"
# -r: box.1 (-pqA) refined under -a0.01: FILE.2.*, the same volume, every tet within the
# bound, its region attribute kept (-A), its points first; bad meshes: exit 3
expect "-pqA" 0 '' '' -- "$lh" tetgen -pqAQ box.poly
expect "-rqa0.01AC" 0 '' '^check: the mesh is valid' -- "$lh" tetgen -rqa0.01AQC box.1
read -r vol least < <(volume box.2.node box.2.ele)
same "-r volume" "$vol" "6"
same "-r tets at most 0.01" "$(over box.2.node box.2.ele 0.01)" "0"
same "-r attributes" "$(awk 'NR == 1 { print $3 } NR > 1 { print $6 }' box.2.ele | sort -u | tr '\n' ' ')" "1 7 "
same "-r refined" "$(awk 'NR == 1 { print ($1 > 100) }' box.2.ele)" "1"
same "-r points kept" "$(head -n "$(($(head -1 box.1.node | awk '{ print $1 }') + 1))" box.2.node | tail -n +2 |
  awk '{ print $2, $3, $4 }' | md5sum)" "$(tail -n +2 box.1.node | grep -v '^#' | awk '{ print $2, $3, $4 }' | md5sum)"
printf '2 4 0\n1 1 2 4 5\n2 1 2 4 5\n' > twice.ele
cp box.1.node twice.node
expect "-r overlapping" 3 '^lifthull tetgen: twice\.ele: tets 0 and 1 are the same tet .* \(tetrahedra and points numbered from 0\)$' '' -- "$lh" tetgen -rq twice
printf '1 3 0\n1 1 2 4\n' > tri.ele
cp box.1.node tri.node
expect "-r triangles" 3 '^lifthull tetgen: tri\.ele: cells of 3 points; a tetrahedral mesh has 4$' '' -- \
  "$lh" tetgen -rq tri
cp box.1.node lone.node
expect "-r no .ele" 3 '^lifthull tetgen: lone\.ele: No such file' '' -- "$lh" tetgen -rq lone
expect "-ra alone" 2 '^lifthull tetgen: -r with -a alone' '' -- "$lh" tetgen -rqa box.1
absent twice.2.node tri.2.node
# -O: the flips after refinement raise hole.off's smallest dihedral angle; -O0 has none;
# asking for smoothing (ops 2) says it is not implemented
cp "$data/../mesh3d/hole.off" .
dihedral() { sed -n 's/^  Smallest dihedral angle: \([0-9.e+-]*\) degrees$/\1/p' out.txt; }
expect "-pq1.414" 0 '' '^  Smallest dihedral angle' -- "$lh" tetgen -pq1.414VQ hole.off
with="$(dihedral)"
expect "-pq1.414O0" 0 '' '^  Smallest dihedral angle' -- "$lh" tetgen -pq1.414O0VQ hole.off
same "-O0: fewer degrees" "$(awk -v a="$with" -v b="$(dihedral)" 'BEGIN { print (a > 10 && b < a) }')" "1"
expect "-O2/3" 0 '^lifthull tetgen: -O: only flips \(ops 1\) are implemented; smoothing \(2\) is not$' '' -- \
  "$lh" tetgen -pq1.414O2/3Q hole.off
# -m: sizes at the input's points (box.mtr: 0.1 at z = 0, 0.5 at z = 1) met everywhere,
# so more points below than above; a bad .mtr: exit 3, its line and column named
printf '8 1\n0.1\n0.1\n0.1\n0.1\n0.5\n0.5\n0.5\n0.5\n' > box.mtr
expect "-pm" 0 '' ', over the size: 0$' -- "$lh" tetgen -pmVQC box.poly
matches out.txt '^check: the mesh is valid and conforms' && ok || bad "-pm -C: $(grep check out.txt)"
same "-pm graded" "$(awk 'NR > 1 && NF >= 4 { if ($4 < 0.5) lo++; else hi++ } END { print (lo > 2 * hi) }' box.1.node)" "1"
printf '8 1\n0.1\n0.1\n-1\n' > box.mtr
expect "-m negative" 3 '^box\.mtr:4:1: expected the size at point 3 \(a positive number\), found .-1.$' '' -- \
  "$lh" tetgen -pm box.poly
printf '7 1\n' > box.mtr
expect "-m count" 3 '^box\.mtr:1:1: expected the number of points \(8, as in the input\), found .7.$' '' -- \
  "$lh" tetgen -pm box.poly
rm box.mtr
expect "-m no .mtr" 3 'box\.mtr' '' -- "$lh" tetgen -pm box.poly
# -o2: a node at every edge's midpoint; .ele rows of 10 (TetGen 1.5's order: edges 2-3
# 0-3 0-1 1-2 1-3 0-2), .face of 6 (opposite corners 0 1 2), .edge of 3; the same tets
expect "-pq1.2" 0 '' '' -- "$lh" tetgen -pq1.2Q box.poly
cp box.1.ele linear.ele
expect "-pq1.2o2fe" 0 '' '^check: the mesh is valid' -- "$lh" tetgen -pq1.2o2feQC box.poly
same "-o2 corners" "$(awk 'NR > 1 { print $1, $2, $3, $4, $5 }' box.1.ele | md5sum)" \
  "$(awk 'NR > 1 { print $1, $2, $3, $4, $5 }' linear.ele | md5sum)"
same "-o2 headers" "$(head -1 box.1.ele | awk '{ print $2 }') $(awk 'FNR == 2 { print NF }' box.1.face box.1.edge | tr '\n' ' ')" \
  "10 8 5 "
# every extra node at its edge's midpoint (coordinates of the .node)
midpoints() { # FILE CORNERS PAIRS...: rows whose extra nodes are not the midpoints of PAIRS
  awk -v c="$2" -v pairs="$3" 'FNR == 1 { next } NR == FNR { x[$1] = $2; y[$1] = $3; z[$1] = $4; next }
    { n = split(pairs, p, " "); for (i = 1; i <= n; i++) { split(p[i], e, "-"); a = $(e[1] + 2); b = $(e[2] + 2); m = $(c + 1 + i)
        if (x[m] != (x[a] + x[b]) / 2 || y[m] != (y[a] + y[b]) / 2 || z[m] != (z[a] + z[b]) / 2) bad++ } }
    END { print bad + 0 }' box.1.node "$1"
}
same "-o2 .ele midpoints" "$(midpoints box.1.ele 4 '2-3 0-3 0-1 1-2 1-3 0-2')" "0"
same "-o2 .face midpoints" "$(midpoints box.1.face 3 '1-2 0-2 0-1')" "0"
same "-o2 .edge midpoints" "$(midpoints box.1.edge 2 '0-1')" "0"
same "-o2 nodes" "$(head -1 box.1.node | awk '{ print $1 }')" \
  "$(awk 'NR > 1 { for (i = 2; i <= 11; i++) print $i }' box.1.ele | sort -u | wc -l | tr -d ' ')"
cd ..

# refused: TetGen switches lifthull does not have yet, unknown switches, a signed -S
# (exit 2, nothing read or written)
fresh cube.node
expect "-O11" 2 '^lifthull tetgen: -O takes a level from 0 to 10 and /ops from 0 to 7' '' -- \
  "$lh" tetgen -pO11 cube.node
for s in R i w v; do
  expect "-$s refused" 2 "^lifthull tetgen: -$s \(.*\) is not implemented yet" '' -- "$lh" tetgen "-$s" cube.node
done
expect "-o2k refused" 2 '^lifthull tetgen: -o2 writes second-order nodes to the \.node, \.ele, \.face and \.edge files only, not with -k \(VTK\)$' '' -- \
  "$lh" tetgen -o2k cube.node
expect "-o3" 2 "^lifthull tetgen: -o must be -o2 \(quadratic elements\), not '-o3'$" '' -- "$lh" tetgen -o3 cube.node
expect "unknown switch" 2 "^lifthull tetgen: unknown switch 'u' in '-pu' \(see --help\)$" '' -- "$lh" tetgen -pu cube.node
expect "-S-1" 2 "^lifthull tetgen: -S takes a count of Steiner points \(0 or more\), not '-1'$" '' -- \
  "$lh" tetgen -S-1 cube.node
absent cube.1.node cube.1.ele cube.1.face
cd ..

# bad input: exit 3, the file named (and the line and column)
fresh cube.node
expect "missing file" 3 '^lifthull tetgen: none\.node: No such file or directory$' '' -- "$lh" tetgen none.node
mkdir dir.node
expect "a directory" 3 '^lifthull tetgen: dir\.node: is a directory, not an input file$' '' -- "$lh" tetgen dir.node
printf '3 3 0 0\n1 0 0 0\n2 1 x 0\n3 0 1 0\n' > bad.node
expect "malformed .node" 3 '^lifthull tetgen: bad\.node:3:5: expected coordinate 2 of point 2' '' -- \
  "$lh" tetgen bad.node
printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n' > flat.node
expect "2D .node" 3 '^lifthull tetgen: flat\.node: the points have 2 coordinates; 3D meshing needs 3$' '' -- \
  "$lh" tetgen flat.node
printf '4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n' > plane.node
expect "coplanar points" 3 '^lifthull tetgen: plane\.node: ' '' -- "$lh" tetgen plane.node
absent bad.1.node flat.1.node plane.1.node plane.1.ele
cd ..

# a PLC: box.poly (the unit cube, facets marked 1..6, one region of attribute 7)
fresh box.poly
expect "-pA box.poly" 0 '' '^box\.1: 8 points, 6 tetrahedra, 12 boundary faces \(0 Steiner points\)' -- \
  "$lh" tetgen -pAe box.poly
same "-pA .ele header" "$(line box.1.ele 1)" "6 4 1"
same "-pA attributes" "$(awk 'NR > 1 { print $6 }' box.1.ele | sort -u)" "7"
same "-p .face header" "$(line box.1.face 1)" "12 1"
same "-p face markers" "$(awk 'NR > 1 { print $5 }' box.1.face | sort | uniq -c | tr -s ' ' | tr '\n' '/')" \
  " 2 1/ 2 2/ 2 3/ 2 4/ 2 5/ 2 6/"
same "-pe edges on segments" "$(awk 'NR > 1 && $4 != 0' box.1.edge | wc -l | tr -d ' ')" "12"
read -r vol least < <(volume box.1.node box.1.ele)
same "-p volume" "$vol" "6"
# without -p: the points only, no markers on .face, no attributes
expect "box.poly without -p" 0 '' '' -- "$lh" tetgen -AQ box.poly
same "no -p .face header" "$(line box.1.face 1)" "12 0"
same "no -p .ele header" "$(line box.1.ele 1)" "6 4 0"
# a .poly without points takes BASE.node's; -I then would write over that input
grep -v '^#' box.poly | awk 'NR == 1 { print "0 3 0 0"; next } NR > 9' > hollow.poly
grep -v '^#' box.poly | sed -n 1,9p > hollow.node
expect "hollow.poly + hollow.node" 0 '' '' -- "$lh" tetgen -pAQ hollow.poly
same "hollow = box" "$(cmp -s hollow.1.ele box.1.ele || true; awk 'NR > 1' hollow.1.face | md5sum)" \
  "$(cmp -s hollow.1.ele box.1.ele || true; "$lh" tetgen -pAQ box.poly; awk 'NR > 1' box.1.face | md5sum)"
expect "-pI over the .node" 1 "^lifthull tetgen: 'hollow\.node' is an input file; it is not overwritten$" '' -- \
  "$lh" tetgen -pIQ hollow.poly
absent hollow.ele hollow.face
# bad .poly: the reader's FILE:LINE:COL
printf '8 3 0 0\n1 0 0 0\n' > bad.poly
expect "truncated .poly" 3 '^lifthull tetgen: bad\.poly:[0-9]+:[0-9]+: ' '' -- "$lh" tetgen -p bad.poly
absent bad.1.node
# -p FILE without an extension: FILE.poly, or FILE.smesh when only that exists
{ grep -v '^#' box.poly | sed -n 1,9p; echo "6 1"
  printf '4 1 2 3 4 1\n4 5 6 7 8 2\n4 1 2 6 5 3\n4 2 3 7 6 4\n4 3 4 8 7 5\n4 4 1 5 8 6\n0\n0\n'; } > only.smesh
expect "-p only (.smesh)" 0 '' '^only\.1: 8 points, 6 tetrahedra' -- "$lh" tetgen -p only
expect "-p none" 3 '^lifthull tetgen: none\.poly: No such file or directory$' '' -- "$lh" tetgen -p none
cd ..

# Schonhardt's prism needs Steiner points: -S0 refuses it, -c keeps its hull (more
# tetrahedra), -Y puts one inside, none on the boundary
rm -rf w; mkdir w; cp "$data/../mesh3d/schonhardt.off" w/; cd w
expect "-p schonhardt" 0 '' '^schonhardt\.1: [0-9]+ points, [0-9]+ tetrahedra, [0-9]+ boundary faces \([1-9][0-9]* Steiner' -- \
  "$lh" tetgen -p schonhardt.off
plain="$(line schonhardt.1.ele 1 | cut -d' ' -f1)"
expect "-pS0 schonhardt" 3 '^lifthull tetgen: schonhardt\.off: boundary recovery needs more than 0 Steiner points \(-S\)$' \
  '' -- "$lh" tetgen -pS0 schonhardt.off
expect "-pc schonhardt" 0 '' '' -- "$lh" tetgen -pcQ schonhardt.off
[ "$(line schonhardt.1.ele 1 | cut -d' ' -f1)" -gt "$plain" ] && ok || bad "-c: no more tetrahedra than $plain"
expect "-pY schonhardt" 0 '' '^  Steiner points: 1 \(0 on segments, 0 on facets, 1 interior\)$' -- \
  "$lh" tetgen -pYVC schonhardt.off
cd ..

# an OFF surface: numbered from 0 as the file; -I names without the iteration number
fresh cube.off
expect "-pI cube.off" 0 '' '^cube: 8 points' -- "$lh" tetgen -pI cube.off
exists cube.node cube.ele cube.face
same "OFF numbered from 0" "$(line cube.node 2)" "0 0 0 0"
same "OFF .face header" "$(line cube.face 1)" "12 1"
cd ..

# -d: the pairs of facets that intersect (lh_plc_intersections), no mesh, exit 1 when
# any; -C: lh_tetmesh_check's verdict
fresh cube.node box.poly crossing.off cube.off
expect "-d points" 0 '' '^cube\.node: no facets intersect \(0 facets\)$' -- "$lh" tetgen -d cube.node
expect "-d cube.off" 0 '' '^cube\.off: no facets intersect \(6 facets\)$' -- "$lh" tetgen -d cube.off
expect "-d crossing" 1 '' '^crossing\.off: 1 pair of facets intersect$' -- "$lh" tetgen -d crossing.off
same "-d listing" "$(cat out.txt)" "crossing.off: facet 0 (line 9) and facet 1 (line 10) intersect
crossing.off: 1 pair of facets intersect"
expect "-dz crossing" 1 '' '^crossing\.off: facet 0 \(line 9\) and facet 1 \(line 10\) intersect$' -- \
  "$lh" tetgen -dz crossing.off
absent crossing.1.node crossing.1.ele crossing.1.face cube.1.node
# two pairs, the first listed: a floor crossed by two walls
printf 'OFF\n9 3 0\n0 0 0\n4 0 0\n0 4 0\n1 1 -1\n1 1 1\n1.5 1.5 -1\n2 0.5 -1\n2 0.5 1\n2.5 0.2 -1\n3 0 1 2\n3 3 4 5\n3 6 7 8\n' > walls.off
expect "-d1 walls" 1 '' '^walls\.off: 2 pairs of facets intersect; the first 1 is listed$' -- "$lh" tetgen -d1 walls.off
same "-d1 one pair listed" "$(grep -c ' intersect$' out.txt)" "1"
expect "-d walls" 1 '' '^walls\.off: facet 0 \(line 12\) and facet 2 \(line 14\) intersect$' -- "$lh" tetgen -d walls.off
# -p refuses intersecting facets, naming them; nothing written
expect "-p crossing" 3 '^lifthull tetgen: crossing\.off: 1 pair of facets intersect: 0 and 1' '' -- \
  "$lh" tetgen -p crossing.off
absent crossing.1.node crossing.1.ele crossing.1.face
expect "-pC box.poly" 0 '' '^check: the mesh is valid and conforms to the input \(exact; 0 Steiner points' -- \
  "$lh" tetgen -pQC box.poly
expect "-C points" 0 '' '^check: the mesh is valid \(exact; 0 Steiner points' -- "$lh" tetgen -QC cube.node
cd ..

# outputs all or none: a target that is a directory stops everything before the input
# is read; a write failing at the second file (the file size limit, as a full disk
# would) leaves no file and no temporary
fresh cube.node
mkdir cube.1.face
expect ".face a directory" 1 "^lifthull tetgen: 'cube\.1\.face' is a directory$" '' -- "$lh" tetgen cube.node
absent cube.1.node cube.1.ele; rmdir cube.1.face
"$lh" points 3000 -d 3 --seed 7 -o p.txt
awk 'NR == 1 { next } NR == 2 { print $1, 3, 0, 0; next } { print NR - 2, $1, $2, $3 }' p.txt > big.node
(trap '' XFSZ; ulimit -f 100; "$lh" tetgen big.node > out.txt 2> err.txt; echo $? > rc.txt)
same "file too large: exit" "$(cat rc.txt)" 1
matches err.txt "^lifthull tetgen: cannot write 'big\.1\.(node|ele)': File too large" && ok || bad "EFBIG: $(cat err.txt)"
absent big.1.node big.1.ele big.1.face
same "no temporaries" "$(find . -name '*.tmp??????' | wc -l | tr -d ' ')" "0"
cd ..

finish
