#!/usr/bin/env bash
# mesh.sh LIFTHULL DATA: `lifthull mesh` end to end on Triangle's inputs (DATA =
# tests/data/triangle) — the quality report, each option's effect on it, every -o
# format read back (XML checked by xmllint when installed, else by Python's parser;
# headers of .msh .off .node .ele .poly), whole-or-nothing output files that need -f
# to replace and never replace an input, usage errors (exit 2) and bad input (exit 3).
set -u
. "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
# xml NAME FILE: well-formed XML
if command -v xmllint > /dev/null; then xml() { xmllint --noout "$2" 2> xml.err && ok || bad "$1: $(head -c 300 xml.err)"; }
elif command -v python3 > /dev/null; then xml() { python3 -c 'import sys, xml.dom.minidom as m; m.parse(sys.argv[1])' "$2" 2> xml.err && ok || bad "$1: $(tail -1 xml.err)"; }
else xml() { ok; }; fi
# field REPORT REGEX: the first number after REGEX in the report
field() { sed -nE "s/.*$2 ([0-9.e+-]+).*/\1/p" "$1" | head -1; }
# ge A B: A >= B as numbers
ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 >= b + 0) }'; }

cp "$data"/A.poly "$data"/box.poly "$data"/la.poly "$data"/face.poly .

expect "--help" 0 '' '^usage: lifthull mesh' -- "$lh" mesh --help
grep -q '^exit codes: 0' out.txt && grep -q '^examples:' out.txt && ok || bad "--help lacks examples or exit codes"
"$lh" --help | grep -q '^  mesh ' && ok || bad "mesh not in lifthull --help"

# without -o: the report
expect "report" 0 '' '^Mesh: 29 points \(29 input, 0 Steiner: 0 on segments\), 29 triangles, 29 subsegments$' -- "$lh" mesh A.poly
grep -q '^Angle histogram' out.txt && ok || bad "report: no histogram"
expect "--min-angle 30" 0 '' '^Triangles below the bounds: 0$' -- "$lh" mesh A.poly --min-angle 30
ge "$(field out.txt 'Angles: smallest')" 30 && ok || bad "--min-angle 30: $(grep Angles out.txt)"
# scale-free: A.poly times 2^k (exact in awk's doubles, printed to round-trip) reports
# what A.poly does, but for its areas and edges
scaled() {
    awk -v f="$1" 'function p(x) { return sprintf("%.17g", x * f) }
        /^[ \t]*(#|$)/ { print; next }
        part == 0 { n = $1; part = 1; print; next }
        part == 1 { print $1, p($2), p($3), $4; if (--n == 0) part = 2; next }
        part == 2 { n = $1; part = n ? 3 : 4; print; next }
        part == 3 { print; if (--n == 0) part = 4; next }
        part == 4 { n = $1; part = 5; print; next }
        { print $1, p($2), p($3) }' A.poly
}
"$lh" mesh A.poly --min-angle 30 | grep -v '^Areas' > unscaled.txt
for k in -600 -260 177 600; do
    scaled "$(awk -v k=$k 'BEGIN { printf "%.17g", 2 ^ k }')" > "A$k.poly"
    "$lh" mesh "A$k.poly" --min-angle 30 > "scaled$k.txt" && grep -v '^Areas' "scaled$k.txt" | cmp -s - unscaled.txt &&
        grep -q '^Triangles below the bounds: 0$' "scaled$k.txt" && ok ||
        bad "A.poly times 2^$k: $(diff <(grep -v '^Areas' "scaled$k.txt") unscaled.txt | head -5)"
done
grep -q '^Areas: smallest 8.54895e-366, largest 3.4183e-364; edges: shortest 3.58617e-183' scaled-600.txt && ok ||
    bad "A.poly times 2^-600: $(grep Areas scaled-600.txt)"
expect "--quality" 0 '' '^Angles' -- "$lh" mesh --quality A.poly
ge "$(field out.txt 'Angles: smallest')" 20 && ok || bad "--quality: $(grep Angles out.txt)"
! ge "$(field out.txt 'Angles: smallest')" 30 && ok || bad "--quality is 20 degrees, got $(grep Angles out.txt)"
expect "--quality --min-angle 25" 0 '' '^Angles' -- "$lh" mesh A.poly --min-angle 25 --quality
ge "$(field out.txt 'Angles: smallest')" 25 && ok || bad "--min-angle wins over --quality: $(grep Angles out.txt)"
expect "--max-area" 0 '' '^Areas' -- "$lh" mesh A.poly --max-area 0.001
ge 0.001 "$(field out.txt 'Areas: smallest [0-9.e+-]+, largest')" && ok || bad "--max-area 0.001: $(grep Areas out.txt)"
expect "--no-segment-steiner" 0 '' ' 0 on segments\), ' -- "$lh" mesh A.poly --quality --no-segment-steiner
expect "--no-boundary-steiner" 0 '' ' 0 on segments\), ' -- "$lh" mesh A.poly --quality --no-boundary-steiner
expect "--max-steiner" 0 '' '^Mesh: 34 points \(29 input, 5 Steiner' -- "$lh" mesh A.poly --min-angle 30 --max-steiner 5
# above the provable 20.7 degrees refinement need not end (Triangle's -q35.5 .. -q38 on
# these files ran without end, taking GBs): it stops at a Steiner budget from the input
# and says so; at 34 degrees these files meet the bound with no budget reached
cp "$data"/double_hex.poly .
# a memory limit for the runs (a sanitizer's shadow memory cannot live under one: none then)
vlimit=2000000; (ulimit -v $vlimit; "$lh" mesh A.poly > /dev/null 2>&1) || vlimit=unlimited
printf '3 2 0 0\n1 0 0\n2 1 0\n3 1 1e-10\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' > wedge.poly
for run in "la.poly 35.5" "la.poly 36" "double_hex.poly 35.5" "double_hex.poly 36" "A.poly 38" "face.poly 38" \
           "wedge.poly 32 --conforming"; do
    set -- $run
    (ulimit -v $vlimit; timeout 60 "$lh" mesh "$1" --min-angle "$2" ${3:-}) > budget.txt 2>&1
    rc=$?
    [ $rc -eq 0 ] && grep -Eq "^Refinement stopped at its budget of [0-9]+ Steiner points: the angle bound $2 degrees is above 20.7, where Delaunay refinement need not end; [1-9][0-9]* triangles are below the bounds$" budget.txt &&
        grep -Eq '^Triangles below the bounds: [1-9]' budget.txt && ok || bad "budget $run: exit $rc, $(head -c 300 budget.txt)"
done
for f in A.poly face.poly double_hex.poly la.poly; do
    (ulimit -v $vlimit; timeout 60 "$lh" mesh "$f" --min-angle 34) > budget.txt 2>&1 && ! grep -q 'budget' budget.txt &&
        { [ "$f" = la.poly ] || grep -q '^Triangles below the bounds: 0$' budget.txt; } && ok || bad "34 degrees on $f: $(head -c 300 budget.txt)"
done
grep -q 'the Steiner point limit was reached' out.txt && ok || bad "--max-steiner: no limit note"
expect "--ignore-holes" 0 '' '^Mesh: 29 points .*, 30 triangles' -- "$lh" mesh A.poly --ignore-holes
expect "--conforming" 0 '' '^Mesh' -- "$lh" mesh A.poly --conforming
expect "--convex-hull" 0 '' '^Mesh' -- "$lh" mesh box.poly --convex-hull
expect "unclosed" 3 '^box\.poly: the domain is empty' '' -- "$lh" mesh box.poly

# -o: each format, parsed back
"$lh" mesh A.poly --min-angle 30 > rep.txt
pts="$(sed -nE 's/^Mesh: ([0-9]+) points.*/\1/p' rep.txt)"; tris="$(sed -nE 's/.*\), ([0-9]+) triangles.*/\1/p' rep.txt)"
expect "-o vtu" 0 '' "^A\.vtu: $pts points, $tris triangles" -- "$lh" mesh A.poly --min-angle 30 -o A.vtu
xml "A.vtu is XML" A.vtu
grep -q "<Piece NumberOfPoints=\"$pts\" NumberOfCells=\"$tris\">" A.vtu && ok || bad "A.vtu: counts"
grep -q 'Name="marker"' A.vtu && ok || bad "A.vtu: no marker point data"
grep -q 'Name="region"' A.vtu && bad "A.vtu: region without --attributes" || ok
expect "-o vtu --attributes" 0 '' '' -- "$lh" mesh la.poly --attributes -o la.vtu -q --ascii
xml "la.vtu is XML" la.vtu
same "la.vtu region values" "$(awk '/Name="region"/ { on = 1; next } /<\/DataArray>/ { on = 0 } on { print $1 + 0 }' la.vtu | sort -u -g | tr '\n' ' ')" "0 0.05 0.2 0.4 0.8 3 "
same "la.vtu one value a cell" "$(awk '/Name="region"/ { on = 1; next } /<\/DataArray>/ { on = 0 } on' la.vtu | wc -l | tr -d ' ')" "$(sed -nE 's/.*NumberOfCells="([0-9]+)".*/\1/p' la.vtu)"
expect "-o msh" 0 '' '' -- "$lh" mesh A.poly --min-angle 30 -o A.msh -q
same "A.msh header" "$(sed -n 1,2p A.msh | tr '\n' ' ')" '$MeshFormat 4.1 0 8 '
grep -q '^\$Elements' A.msh && grep -q '^\$NodeData' A.msh && ok || bad "A.msh: no elements or node data"
expect "-o off" 0 '' '' -- "$lh" mesh A.poly --min-angle 30 -o A.off -q
same "A.off header" "$(line A.off 1) $(line A.off 2)" "OFF $pts $tris 0"
same "A.off lines" "$(wc -l < A.off | tr -d ' ')" "$((2 + pts + tris))"
expect "-o node" 0 '' '' -- "$lh" mesh A.poly --min-angle 30 -o m.node -q
exists m.node m.ele m.poly
same "m.node header" "$(line m.node 1)" "$pts 2 1 1"
same "m.ele header" "$(line m.ele 1)" "$tris 3 0"
same "m.poly header" "$(line m.poly 1)" "0 2 1 1"
same "m.node numbered from 1" "$(line m.node 2 | cut -d' ' -f1)" "1"
expect "-o ele names the same files" 0 '' '' -- "$lh" mesh A.poly -o e.ele -q
exists e.node e.ele e.poly
expect "-o svg" 0 '' '' -- "$lh" mesh A.poly --min-angle 30 -o A.svg -q
xml "A.svg is XML" A.svg
grep -q '<svg xmlns="http://www.w3.org/2000/svg" viewBox=' A.svg && grep -q 'id="segments"' A.svg && ok || bad "A.svg: no svg root or segments"
expect "-o svg, bad triangles" 0 '' 'triangles are below the bounds' -- "$lh" mesh la.poly --min-angle 30 -o la.svg
xml "la.svg is XML" la.svg
grep -A1 '<g id="bad"' la.svg | grep -q '<path d="M' && ok || bad "la.svg: the bad triangles are not outlined"
# --report numbers the triangles below the bounds as the files written: from 1 as the
# .ele (each listed number is a triangle of m30.ele with an angle below 30 degrees),
# from 0 as VTU cells (it numbered from 0 always)
expect "--report lists .ele numbers" 0 '' 'numbered from 1 as the files: ' -- "$lh" mesh la.poly --min-angle 30 -o m30.node --report
first="$(sed -nE 's/^Triangles below the bounds: [0-9]+, numbered from 1 as the files: ([0-9]+).*/\1/p' out.txt)"
small() { # small NODE ELE NUMBER: the smallest angle (degrees) of triangle NUMBER
  awk -v k="$3" 'FNR == 1 { f++; next } f == 1 && NF { x[$1] = $2; y[$1] = $3 }
    f == 2 && $1 == k { m = 180; for (i = 2; i <= 4; i++) { a = $i; b = $(i % 3 + 2); c = $((i + 1) % 3 + 2)
      ux = x[b] - x[a]; uy = y[b] - y[a]; vx = x[c] - x[a]; vy = y[c] - y[a]
      t = atan2(ux * vy - uy * vx, ux * vx + uy * vy) * 57.29577951308232; if (t < 0) t = -t; if (t < m) m = t }
      print m }' "$1" "$2"
}
ge 30 "$(small m30.node m30.ele "$first")" && ok || bad "--report: triangle $first of m30.ele is not below 30 degrees"
expect "--report lists VTU numbers" 0 '' "numbered from 0 as the files: $((first - 1)) " -- "$lh" mesh la.poly --min-angle 30 -o m30.vtu --report

# quality report and SVG of meshes near +-DBL_MAX, or mixing 1e300 and 1e-300: the
# angles were NaN (converted to int: undefined), the SVG's viewBox "... -nan"; now the
# angles are right and the DBL_MAX square draws as the square of +-(1 - 2^-53)
mkdir -p big unit
printf '4 2 0 0\n1 -%s -%s\n2 %s -%s\n3 %s %s\n4 -%s %s\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' \
  1.7976931348623157e+308 1.7976931348623157e+308 1.7976931348623157e+308 1.7976931348623157e+308 \
  1.7976931348623157e+308 1.7976931348623157e+308 1.7976931348623157e+308 1.7976931348623157e+308 > big/sq.poly
sed 's/1\.7976931348623157e+308/0.99999999999999989/g' big/sq.poly > unit/sq.poly
expect "DBL_MAX square --quality" 0 '' '^Angles: smallest 45, largest 90 degrees$' -- "$lh" mesh big/sq.poly --quality
grep -q '^   40 -  50:         4 ' out.txt && grep -q '^    0 -  10:         0    |   90 - 100:         2$' out.txt &&
  ! grep -qi nan out.txt && ok || bad "DBL_MAX square: $(cat out.txt)"
printf '5 2 0 0\n1 -1e300 -1e300\n2 1e300 -1e300\n3 1e300 1e300\n4 -1e300 1e300\n5 1e-300 1e-300\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' > mixed.poly
expect "1e300 square, 1e-300 centre --quality" 0 '' '^Angles: smallest 45, largest 90 degrees$' -- "$lh" mesh mixed.poly --quality
grep -q '^   40 -  50:         8 ' out.txt && grep -q '^    0 -  10:         0    |   90 - 100:         4$' out.txt &&
  ! grep -qi nan out.txt && ok || bad "mixed: $(cat out.txt)"
(cd big && "$lh" mesh sq.poly --quality -o sq.svg -q) && (cd unit && "$lh" mesh sq.poly --quality -o sq.svg -q) && ok || bad "DBL_MAX square -o svg failed"
same "DBL_MAX square SVG = unit square SVG" "$(cmp -s big/sq.svg unit/sq.svg && echo same)" "same"
grep -q 'viewBox="0 -1250 11000 12250"' big/sq.svg && ok || bad "DBL_MAX square viewBox: $(grep -o 'viewBox="[^"]*"' big/sq.svg)"
expect "--report with -o" 0 '' '^Mesh: ' -- "$lh" mesh A.poly -o r.off --report
grep -q '^r\.off:' out.txt && bad "--report: the summary line too" || ok
expect "-q" 0 '' '' -- "$lh" mesh A.poly -o q.off -q

# whole or nothing; -f to replace; never an input
expect "exists" 1 "lifthull mesh: 'A\.vtu' exists \(use -f to replace it\)" '' -- "$lh" mesh A.poly -o A.vtu
expect "-f replaces" 0 '' '' -- "$lh" mesh A.poly -o A.vtu -f -q
expect ".node exists" 1 "'m\.node' exists" '' -- "$lh" mesh A.poly -o m.node
cp A.poly A.orig
expect "never the input" 1 "lifthull mesh: 'A\.poly' is the input file; it is not overwritten" '' -- "$lh" mesh A.poly -o A.node -f
cmp -s A.poly A.orig && ok || bad "A.poly changed"
absent A.node A.ele
mkdir u.ele
expect "unwritable .ele" 1 "lifthull mesh: " '' -- "$lh" mesh A.poly -o u.node
absent u.node u.poly
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' > sq.node
printf '0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' > sq.poly
cp sq.node sq.orig
expect "vertices from sq.node" 0 '' '^Mesh: 4 points' -- "$lh" mesh sq.poly
expect "never the .node read" 1 "'sq\.(node|poly)' is (an|the) input file; it is not overwritten" '' -- "$lh" mesh sq.poly -o sq.node -f
cmp -s sq.node sq.orig && ok || bad "sq.node changed"
absent sq.ele
ln sq.node link.vtu
expect "never the .node read, by another name" 1 "'link\.vtu' is an input file" '' -- "$lh" mesh sq.poly -o link.vtu -f -q
cmp -s sq.node sq.orig && ok || bad "sq.node changed through link.vtu"
same "no temporaries" "$(ls | grep -c tmp)" "0"

# other inputs: a point set, polygon rings
printf '5 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n5 0.5 0.5\n' > dots.node
expect ".node input" 0 '' '^Mesh: 5 points .*, 4 triangles' -- "$lh" mesh dots.node
expect ".node to .node" 0 '' '' -- "$lh" mesh dots.node -o d.node -q
exists d.node d.ele; absent d.poly
printf '[[[0,0],[4,0],[4,4],[0,4]],[[1,1],[1,3],[3,3],[3,1]]]\n' > ring.json
expect ".json input" 0 '' '^Mesh: 8 points .*, 8 triangles' -- "$lh" mesh ring.json
expect ".json to .svg" 0 '' '' -- "$lh" mesh ring.json --quality -o ring.svg -q
xml "ring.svg is XML" ring.svg

# usage errors (2) and bad input (3)
expect "no file" 2 "lifthull mesh: an input file is needed" '' -- "$lh" mesh
expect "unknown option" 2 "lifthull mesh: unknown option '--frobnicate'" '' -- "$lh" mesh A.poly --frobnicate
expect "value needed" 2 "a value is needed after '--max-area'" '' -- "$lh" mesh A.poly --max-area
expect "angle range" 2 "--min-angle takes a number from 0 to 40, not '45'" '' -- "$lh" mesh A.poly --min-angle 45
expect "angle text" 2 "--min-angle takes a number from 0 to 40, not 'abc'" '' -- "$lh" mesh A.poly --min-angle abc
expect "steiner count" 2 "--max-steiner takes a whole number" '' -- "$lh" mesh A.poly --max-steiner -1
expect "two files" 2 "one input file only, not also 'B\.poly'" '' -- "$lh" mesh A.poly B.poly
expect "input name" 2 "must end in \.poly, \.node or \.json \(2D\), or \.poly, \.smesh, \.node, \.off, \.ply, \.stl, \.mesh or \.obj \(3D\): 'A\.txt'" '' -- "$lh" mesh A.txt
expect "output name" 2 "-o: the name must end in \.vtu, \.msh, \.off, \.node, \.ele or \.svg: 'A\.txt'" '' -- "$lh" mesh A.poly -o A.txt
expect "missing file" 3 "^nosuch\.poly: No such file or directory" '' -- "$lh" mesh nosuch.poly
printf '# two segments that cross\n4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 2\n2 3 4\n0\n' > cross.poly
expect "crossing segments" 3 '^cross\.poly:9: segment 2 crosses segment 1 \(line 8\)$' '' -- "$lh" mesh cross.poly -o cross.vtu
absent cross.vtu
expect "--split-crossings" 0 '' '^Mesh: 5 points' -- "$lh" mesh cross.poly --split-crossings --convex-hull
expect "--smooth" 0 '' '^Smoothing: [1-9][0-9]* moves$' -- "$lh" mesh A.poly --min-angle 28 --max-area 0.0005 --smooth 5
expect "--smooth -1" 2 'smooth' '' -- "$lh" mesh A.poly --smooth -1
printf '4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 3\n2 3 7\n0\n' > range.poly
expect "endpoint out of range" 3 "^range\.poly:8:5: expected an endpoint of segment 2 \(a vertex number from 1 to 4\), found '7'$" '' -- "$lh" mesh range.poly

finish
