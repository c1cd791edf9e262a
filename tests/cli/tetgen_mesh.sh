#!/usr/bin/env bash
# tetgen_mesh.sh LIFTHULL DATA: `lifthull mesh` with 3D input (DATA = tests/data/tetgen3d)
# — the statistics without -o; -o by extension: binary and ASCII .vtu, Gmsh 4.1 .msh,
# Medit .mesh, the .svg picture of the boundary; --check; quality refinement (--quality,
# --max-volume, --min-dihedral) and its report; the 2D-only options and 2D
# formats refused for 3D input (exit 2); bad input (exit 3); outputs never replaced
# without -f. The 2D command is tests/cli/mesh.sh.
set -u
. "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
fresh() { rm -rf w; mkdir w; for f in "$@"; do cp "$data/$f" w/; done; cd w; }

fresh cube.node
expect "statistics" 0 '' '^  Mesh tetrahedra: 6$' -- "$lh" mesh cube.node
matches out.txt '^  Steiner points: 0 \(0 on segments, 0 on facets, 0 interior\)$' && ok || bad "stats: $(cat out.txt)"
# .vtu, binary (default) and ASCII: 6 tetrahedra (VTK type 10), the markers as point data
expect "-o .vtu" 0 '' '^c\.vtu: 8 points, 6 tetrahedra, 12 boundary faces \(0 Steiner points\)' -- \
  "$lh" mesh cube.node -o c.vtu
matches c.vtu '<Piece NumberOfPoints="8" NumberOfCells="6">' && matches c.vtu 'format="binary"' && ok ||
  bad ".vtu: $(head -c 400 c.vtu)"
expect "-o .vtu --ascii" 0 '' '' -- "$lh" mesh cube.node -o a.vtu --ascii -q
same "ascii .vtu types" "$(sed -n '/Name="types"/,/<\/DataArray>/p' a.vtu | grep -o '\b10\b' | wc -l | tr -d ' ')" "6"
matches a.vtu 'Name="marker"' && ok || bad ".vtu: no marker field"
# Gmsh 4.1: one block of 6 tetrahedra (element type 4)
expect "-o .msh" 0 '' '' -- "$lh" mesh cube.node -o c.msh --quiet
same ".msh format" "$(sed -n 2p c.msh)" "4.1 0 8"
same ".msh tetrahedra block" "$(sed -n '/^\$Elements/{n;n;p}' c.msh)" "3 1 4 6"
# Medit: vertices, the 12 boundary triangles with their markers, 6 tetrahedra
expect "-o .mesh" 0 '' '' -- "$lh" mesh cube.node -o c.mesh -q
same ".mesh sections" "$(grep -E '^[A-Z]' c.mesh | tr '\n' '/')" \
  "MeshVersionFormatted 1/Dimension 3/Vertices/Triangles/Tetrahedra/End/"
same ".mesh counts" "$(sed -n '/^Vertices/{n;p};/^Triangles/{n;p};/^Tetrahedra/{n;p}' c.mesh | tr '\n' ' ')" "8 12 6 "
same ".mesh triangle refs" "$(sed -n '/^Triangles/,/^Tetrahedra/p' c.mesh | awk 'NF == 4 { print $4 }' | sort -u)" "1"
# the picture: one filled path per boundary face, painted far to near, a legend
expect "-o .svg" 0 '' '' -- "$lh" mesh cube.node -o c.svg -q
same ".svg faces" "$(grep -c '^<path d="M[0-9]* [0-9]*L[0-9]* [0-9]*L[0-9]* [0-9]*Z" fill="#' c.svg)" "12"
matches c.svg '^<title>lifthull mesh cube\.node</title>$' && matches c.svg '</svg>$' && ok || bad ".svg: $(head -c 300 c.svg)"
matches c.svg '>by facet marker<' && ok || bad ".svg legend"
# an output is replaced only with -f, and is checked before the input is read
expect "exists" 1 "^lifthull mesh: 'c\.vtu' exists \(use -f to replace it\)$" '' -- "$lh" mesh cube.node -o c.vtu
expect "-f" 0 '' '' -- "$lh" mesh cube.node -o c.vtu -f -q
# --check: lh_tetmesh_check's verdict after the summary
expect "--check" 0 '' '^check: the mesh is valid \(exact; ' -- "$lh" mesh cube.node --check -o k.vtu
cd ..

# a PLC: a .poly with 3 coordinates is 3D; the Medit file carries the facet markers and,
# with --region-attributes, the region attribute; the picture one colour per marker
fresh box.poly cube.off
expect "box.poly -o .mesh" 0 '' '^b\.mesh: 8 points, 6 tetrahedra, 12 boundary faces' -- \
  "$lh" mesh box.poly --region-attributes -o b.mesh
same "facet markers" "$(sed -n '/^Triangles/,/^Tetrahedra/p' b.mesh | awk 'NF == 4 { print $4 }' | sort -u | tr '\n' ' ')" \
  "1 2 3 4 5 6 "
same "region references" "$(sed -n '/^Tetrahedra/,/^End/p' b.mesh | awk 'NF == 5 { print $5 }' | sort -u)" "7"
expect "box.poly -o .vtu" 0 '' '' -- "$lh" mesh box.poly --region-attributes --ascii -o b.vtu -q
matches b.vtu 'Name="region"' && ok || bad ".vtu without the region field"
expect "box.poly --check" 0 '' '^check: the mesh is valid and conforms to the input' -- \
  "$lh" mesh box.poly --check -q -o k.msh
expect "box.poly -o .svg" 0 '' '' -- "$lh" mesh box.poly -o b.svg -q
same "svg legend markers" "$(grep -o '<text x="[0-9.]*" y="[-0-9.]*">[0-9]</text>' b.svg | sed 's/.*>\([0-9]\)<.*/\1/' | tr '\n' ' ')" \
  "1 2 3 4 5 6 "
same "svg colours" "$(grep -o '^<path d="[^"]*" fill="#[0-9a-f]*"' b.svg | sed 's/.*fill=//' | sort -u | wc -l | tr -d ' ')" "6"
# quality refinement (TetGen's -q and -a): the bounds met, the report's figures say so
expect "box.poly --quality --max-volume" 0 '' '^check: the mesh is valid and conforms to the input' -- \
  "$lh" mesh box.poly --quality --max-volume 0.01 --min-dihedral 20 --check --report -o q.vtu
matches out.txt 'left over the radius-edge bound: 0, over the volume bound: 0, under the dihedral bound: 0, over the size: 0$' &&
  ok || bad "--quality: $(grep 'Quality refinement' out.txt)"
same "--max-volume met" "$(awk '/Largest volume:/ { print ($NF <= 0.01) }' out.txt)" "1"
# every tetrahedron in one of the 15 bins
same "radius-edge histogram" "$(awk '/Radius-edge ratio histogram/,/circumradius/' out.txt | grep -o ': *[0-9][0-9]*' |
  awk '{ n++; s += $2 } END { print n, s }')" "15 $(sed -n 's/^  Mesh tetrahedra: //p' out.txt)"
# --clip: the quality picture: the faces drawn as the legend counts them, every dihedral
# angle (six per tetrahedron) in the histogram's 18 bars
expect "--clip -o .svg" 0 '' '' -- "$lh" mesh box.poly --quality --max-volume 0.01 --clip -o q.svg -q
same "clip: faces drawn" "$(grep -c '^<path d="M[0-9]* [0-9]*L[0-9]* [0-9]*L[0-9]* [0-9]*Z" fill="#' q.svg)" \
  "$(sed -n 's/.*cut through the middle (\([0-9]*\) faces drawn).*/\1/p' q.svg)"
same "clip: histogram" "$(sed -n '/id="histogram"/,/<\/g>/p' q.svg | grep -o '<text x="[0-9]*" y="[0-9]*">[0-9]*</text><text' |
  sed 's/.*">\([0-9]*\)<.*/\1/' | awk '{ n++; s += $1 } END { print n, s }')" "18 $((6 * 192))"
expect "--clip on 2D input" 2 "^lifthull mesh: 3D meshing only .*: '--clip'" '' -- \
  "$lh" mesh "$data/../triangle/A.poly" --clip -o a.svg
expect "--radius-edge below 1" 2 "^lifthull mesh: --radius-edge takes a number from 1 to" '' -- \
  "$lh" mesh box.poly --radius-edge 0.9
expect "--max-volume on 2D input" 2 "^lifthull mesh: 3D meshing only .*: '--max-volume'" '' -- \
  "$lh" mesh "$data/../triangle/A.poly" --max-volume 1
expect "cube.off -o .msh" 0 '' '^c\.msh: 8 points, 6 tetrahedra' -- "$lh" mesh cube.off -o c.msh
expect "--no-boundary-steiner --max-steiner 0 --convex-hull" 0 '' '' -- \
  "$lh" mesh cube.off --no-boundary-steiner --max-steiner 0 --convex-hull -o d.msh -q
same "options: same mesh" "$(cmp -s c.msh d.msh && echo same)" "same"
cd ..

# refused for 3D input: 2D refinement options and 2D formats (exit 2, nothing written)
fresh cube.node
for o in "--min-angle 20" "--max-area 1" --conforming --ignore-holes "--smooth 2"; do
  # shellcheck disable=SC2086
  expect "$o refused" 2 "^lifthull mesh: 2D meshing only, not implemented for 3D input yet: '${o%% *}'" '' -- \
    "$lh" mesh cube.node $o -o x.vtu
done
expect ".off refused" 2 "^lifthull mesh: -o: a 3D mesh is written as \.vtu, \.msh, \.mesh or \.svg, not 'x\.off'" '' -- \
  "$lh" mesh cube.node -o x.off
expect ".node refused" 2 "not 'x\.node'" '' -- "$lh" mesh cube.node -o x.node
absent x.vtu x.off x.node
cd ..

# bad input: exit 3, the file named with "lifthull mesh: "
fresh cube.node
expect "missing .off" 3 '^lifthull mesh: none\.off: No such file or directory$' '' -- "$lh" mesh none.off
printf '3 3 0 0\n1 0 0 0\n2 1 0\n' > bad.node
expect "malformed .node" 3 '^lifthull mesh: bad\.node:3:' '' -- "$lh" mesh bad.node -o b.vtu
absent b.vtu
# a .poly or .node with 2 coordinates is still 2D meshing
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' > sq.node
expect "2D .node" 0 '' '^sq\.vtu: 4 points, 2 triangles' -- "$lh" mesh sq.node -o sq.vtu
expect "--check 2D" 2 "^lifthull mesh: not implemented for 2D input yet" '' -- "$lh" mesh sq.node --check
cd ..

finish
