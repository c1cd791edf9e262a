#!/usr/bin/env bash
# hostile.sh LIFTHULL: the CLI half of the hostile input catalogue (docs/hostile-inputs.md),
# the rows that tests/cli/bad_input.sh and commands.sh do not already cover. A failure: its
# exit code, its one line on standard error, nothing on standard output. A success: its
# exact output. Each case is named as its row in the catalogue. LH_INDEX_BITS (CTest sets
# it): lifthull's index width, which sets the largest count a file may declare.
set -u
bits="${LH_INDEX_BITS:-32}"
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
# matches FILE REGEX: REGEX found in FILE; an empty REGEX: FILE is empty.
matches() { if [ -z "$2" ]; then [ ! -s "$1" ]; else grep -Eq -- "$2" "$1"; fi; }
# expect NAME CODE STDERR_REGEX STDOUT_EXACT -- COMMAND...: the exit code, stderr matched,
# stdout exactly STDOUT_EXACT (printf %b; empty: nothing).
expect() {
  local name="$1" code="$2" err="$3" out="$4"; shift 5
  "$@" > out.txt 2> err.txt; local got=$?
  printf '%b' "$out" > want.txt
  if [ "$got" -eq "$code" ] && matches err.txt "$err" && cmp -s out.txt want.txt; then ok
  else bad "$name: exit $got (want $code); stderr: $(head -c 300 err.txt); stdout: $(head -c 300 out.txt)"; fi
}
# file NAME CONTENT: writes CONTENT (printf %b) to NAME.
file() { printf '%b' "$2" > "$1"; }

# --- non-finite and extreme coordinates -----------------------------------------------------
file pinf '2 3\n0 0\n1 +inf\n0 1\n'
expect "+Inf" 3 "^pinf:3:3: coordinate 2 of point 2 is '\+inf': NaN and infinities are not points$" '' -- "$lh" delaunay pinf
file minf '2 3\n0 0\n1 -Infinity\n0 1\n'
expect "-Inf (hull)" 3 "^minf:3:3: coordinate 2 of point 2 is '-Infinity': NaN and infinities are not points$" '' -- "$lh" hull minf
file over '2 3\n0 0\n-1e999 1\n0 1\n'
expect "-1e999 overflows" 3 "^over:3:1: coordinate 1 of point 2 is '-1e999', which overflows a double$" '' -- "$lh" delaunay over
file under '2 3\n0 0\n1 1e-999\n0 1\n'
expect "1e-999 underflows to 0" 0 '' '1\n0 1 2\n' -- "$lh" delaunay under
# the square and its centre at 1 (reference), 2^1000, 1e-300 and subnormal scale: the same answer
sq='4\n0 1 4\n0 4 2\n1 3 4\n2 4 3\n'
file sq1 '2 5\n0 0\n1 0\n0 1\n1 1\n0.5 0.5\n'
file sqbig '2 5\n0 0\n0x1p1000 0\n0 0x1p1000\n0x1p1000 0x1p1000\n0x1p999 0x1p999\n'
file sqtiny '2 5\n0 0\n1e-300 0\n0 1e-300\n1e-300 1e-300\n5e-301 5e-301\n'
file sqsub '2 5\n0 0\n1e-323 0\n0 1e-323\n1e-323 1e-323\n5e-324 5e-324\n'
file sqmix '2 5\n-1e300 -1e300\n1e300 -1e300\n-1e300 1e300\n1e300 1e300\n0 0\n'
for f in sq1 sqbig sqtiny sqsub sqmix; do
  expect "square + centre ($f)" 0 '' "$sq" -- "$lh" delaunay "$f"
  "$lh" delaunay "$f" > tri.txt
  expect "square + centre ($f) checked" 0 '' 'ok: 4 simplices, the Delaunay triangulation of the 5 points (exact check)\n' -- "$lh" check "$f" tri.txt
done
file maxd '2 3\n-1.7976931348623157e308 -1.7976931348623157e308\n1.7976931348623157e308 -1.7976931348623157e308\n0 1.7976931348623157e308\n'
expect "DBL_MAX triangle" 0 '' '1\n0 1 2\n' -- "$lh" delaunay maxd
expect "DBL_MAX hull" 0 '' '3\n0 2\n1 0\n2 1\n' -- "$lh" hull maxd

# --- counts that lie, huge counts --------------------------------------------------------------
# "d n" on one line in 2D with a count the lines do not hold: two columns, the header a site.
file lie_more '2 3\n0 0\n1 0\n0 1\n1 1\n'
expect "count 3, 4 points given, 'd n' line (columns)" 0 '' '4\n0 3 4\n0 4 2\n1 2 3\n2 4 3\n' -- "$lh" delaunay lie_more
file lie_1e12 '2 1000000000000\n0 0\n1 0\n0 1\n'
expect "count 10^12, 'd n' line, 2D (columns)" 0 '' '2\n0 3 2\n1 2 3\n' -- "$lh" delaunay lie_1e12
file lie_1e12_3d '3 1000000000000\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n'
if [ "$bits" = 64 ]; then # 10^12 points may be declared: the input ends first
  expect "count 10^12, 3D" 3 "^lie_1e12_3d:6:1: expected coordinate 1 of point 5, found the end of the input \(1000000000000 points declared\)$" '' -- "$lh" delaunay lie_1e12_3d
else
  expect "count 10^12, 3D" 3 "^lie_1e12_3d:1:3: expected the number of points \(an integer from 1 to 2147483646\), found '1000000000000'$" '' -- "$lh" delaunay lie_1e12_3d
fi
file lie_more_3d '3 2\n0 0 0\n1 0 0\n0 1 0\n'
expect "count 2, 3 points given, 3D" 3 "^lie_more_3d:4:1: expected the end of the input after 2 points of dimension 3, found '0'$" '' -- "$lh" delaunay lie_more_3d
file lie_2e9 '3\n2000000000\n0 0 0\n1 0 0\n'
expect "count 2*10^9, 2 points given" 3 "^lie_2e9:5:1: expected coordinate 1 of point 3, found the end of the input \(2000000000 points declared\)$" '' -- "$lh" delaunay lie_2e9
file lie.node '1000000000000 2 0 0\n1 0 0\n'
if [ "$bits" = 64 ]; then
  expect "count 10^12, .node" 3 "^lie.node:3:1: expected point number 2, found the end of the input \(1000000000000 points declared\)$" '' -- "$lh" delaunay lie.node
else
  expect "count 10^12, .node" 3 "^lie.node:1:1: expected the number of points \(an integer from 1 to 2147483646\), found '1000000000000'$" '' -- "$lh" delaunay lie.node
fi

# --- dimensions -------------------------------------------------------------------------------
file d0 '0\n3\n0 0\n'
expect "dimension 0" 3 "^d0:1:1: expected the dimension \(an integer from 2 to 8\), found '0'$" '' -- "$lh" delaunay d0
file dneg '-3\n3\n0 0\n'
expect "dimension -3" 3 "^dneg:1:1: expected the dimension \(an integer from 2 to 8\), found '-3'$" '' -- "$lh" delaunay dneg
file dhuge '99999999999999999999\n3\n0 0\n'
expect "dimension 10^20" 3 "^dhuge:1:1: expected the dimension \(an integer from 2 to 8\), found '99999999999999999999'$" '' -- "$lh" delaunay dhuge
file dfrac '2.5\n3\n0 0\n'
expect "dimension 2.5 (columns)" 3 "^dfrac:1:4: expected coordinate 2 of point 1 \(2 to 8 per line\), found the end of the line$" '' -- "$lh" delaunay dfrac
file d0n '0 3\n'
expect "dimension 0 in 'd n' (columns: one site)" 1 "^d0n: the 1 site spans an affine subspace of dimension 0, not 2: nothing 2-dimensional to compute$" '' -- "$lh" delaunay d0n
file d9n '9 1\n1 2 3 4 5 6 7 8 9\n'
expect "dimension 9 in 'd n' (columns)" 3 "^d9n:2:5: expected the end of the line after 2 coordinates \(as on line 1\), found '3'$" '' -- "$lh" delaunay d9n
file wide.csv "$(printf '1,%.0s' $(seq 1 50000))1\n"
expect "50001 columns" 3 "^wide.csv:1:16: expected the end of the line after 8 coordinates \(8 is the largest dimension\), found ','$" '' -- "$lh" delaunay wide.csv

# --- text, bytes, line ends -------------------------------------------------------------------
file words 'hello world\n'
expect "only text (a title)" 3 "^words:2:1: expected the dimension, found the end of the input$" '' -- "$lh" delaunay words
file nul_end '2 3\n0 0\n1 0\n0 1\0\n'
expect "NUL after the last number" 3 "^nul_end:4:4: expected the end of the input after 3 points of dimension 2, found a NUL byte$" '' -- "$lh" delaunay nul_end
file nul_dim '2\0 3\n0 0\n1 0\n0 1\n'
expect "NUL after the dimension" 3 "^nul_dim:1:2: expected coordinate 2 of point 1 \(a number\), found a NUL byte$" '' -- "$lh" delaunay nul_dim
file crlf '2\r\n3\r\n0 0\r\n1 0\r\n0 1\r\n'
expect "CRLF" 0 '' '1\n0 1 2\n' -- "$lh" delaunay crlf
file crlf.csv 'x,y\r\n0,0\r\n1,0\r\n0,1\r\n'
expect "CRLF CSV" 0 '' '1\n0 1 2\n' -- "$lh" delaunay crlf.csv
file cr_only '2\r3\r0 0\r1 0\r0 1\r'
expect "CR line ends (one line of 8 numbers)" 1 "^cr_only: the 1 site spans an affine subspace of dimension 0, not 8: nothing 8-dimensional to compute$" '' -- "$lh" delaunay cr_only
file noeol '2 3\n0 0\n1 0\n0 1'
expect "no final line end" 0 '' '1\n0 1 2\n' -- "$lh" delaunay noeol

# --- long lines ---------------------------------------------------------------------------------
{ printf '2 3\n0 '; head -c 1048576 /dev/zero | tr '\0' '1'; printf '\n1 0\n0 1\n'; } > token1m
expect "a 1 MB token" 3 "^token1m:2:3: expected coordinate 2 of point 1 \(a number\), found a token of more than 255 bytes$" '' -- "$lh" delaunay token1m
{ printf '2 3\n'; head -c 1048576 /dev/zero | tr '\0' '0'; printf '1 0\n1 0\n0 1\n'; } > zeros1m
expect "1 MB of leading zeros (one token)" 3 "^zeros1m:2:1: expected coordinate 1 of point 1 \(a number\), found a token of more than 255 bytes$" '' -- "$lh" delaunay zeros1m
{ printf '#'; head -c 1048576 /dev/zero | tr '\0' 'x'; printf '\n2 3\n'; head -c 1048576 /dev/zero | tr '\0' ' '; printf '0 0\n1 0\n0 1\n'; } > comment1m
expect "a 1 MB comment and 1 MB of blanks" 0 '' '1\n0 1 2\n' -- "$lh" delaunay comment1m
awk 'BEGIN { printf "2 100000\n"; for (i = 0; i < 100000; i++) printf "%d %d ", i % 1000, int(i / 1000); printf "\n" }' > line1m
expect "a 1 MB line of 200000 numbers (a 1000 x 100 grid)" 0 '' '' -- "$lh" delaunay -q line1m -o grid.txt
[ "$(head -1 grid.txt)" = "197802" ] && ok || bad "1 MB line: $(head -1 grid.txt) triangles, not 197802"

# --- empty input ---------------------------------------------------------------------------------
file comments '# a\n# b\n\n'
expect "only comments" 3 "^comments:4:1: expected the dimension, found the end of the input$" '' -- "$lh" delaunay comments
file blanks '   \n\t\n'
expect "only blanks" 3 "^blanks:3:1: expected the dimension, found the end of the input$" '' -- "$lh" delaunay blanks
expect "empty standard input" 3 "^<stdin>:1:1: expected the dimension, found the end of the input$" '' -- "$lh" delaunay < /dev/null

# --- duplicates -----------------------------------------------------------------------------------
file dup5 '2 5\n1 1\n1 1\n1 1\n1 1\n1 1\n'
expect "all duplicates" 1 "^dup5: the 5 sites span an affine subspace of dimension 0, not 2: nothing 2-dimensional to compute$" '' -- "$lh" delaunay dup5
expect "all duplicates, -a" 1 "^dup5: the 5 sites span an affine subspace of dimension 0, not 2" '' -- "$lh" delaunay -a dup5
expect "all duplicates, hull" 1 "^dup5: the 5 sites span an affine subspace of dimension 0, not 2" '' -- "$lh" hull dup5
file dups '2 6\n0 0\n1 0\n0 1\n1 0\n0 0\n0 0\n'
"$lh" delaunay -s dups 2> err.txt | tr '\n' ' ' > out.txt
grep -Eq '^sites 6 dimension 2 simplices 1 hull facets 3 duplicates 3 seconds' out.txt && [ ! -s err.txt ] && ok || bad "duplicates reported: $(cat out.txt err.txt)"
awk 'BEGIN { print "3 1000000"; for (i = 0; i < 1000000; i++) print "1e300 -5e-324 7" }' > million
start=$(date +%s)
expect "10^6 identical sites" 1 "^million: the 1000000 sites span an affine subspace of dimension 0, not 3: nothing 3-dimensional to compute$" '' -- "$lh" delaunay million
[ $(( $(date +%s) - start )) -le 15 ] && ok || bad "10^6 identical sites took $(( $(date +%s) - start )) s"

# --- lower-dimensional sites -------------------------------------------------------------------------
file col2 '2 4\n0 0\n3 3\n1 1\n2 2\n'
expect "collinear 2D, -a" 0 '' '3\n0 2\n2 3\n3 1\n' -- "$lh" delaunay -a col2
expect "collinear 2D, hull" 1 "^col2: the 4 sites span an affine subspace of dimension 1, not 2: nothing 2-dimensional to compute \(lifthull delaunay -a triangulates within that subspace\)$" '' -- "$lh" hull col2
file col3 '3 4\n0 0 0\n3 3 3\n1 1 1\n2 2 2\n'
expect "collinear 3D" 1 "^col3: the 4 sites span an affine subspace of dimension 1, not 3" '' -- "$lh" delaunay col3
expect "collinear 3D, -a" 0 '' '3\n0 2\n2 3\n3 1\n' -- "$lh" delaunay -a col3
file copl '3 5\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.5 0\n'
expect "coplanar 3D, -a: square + centre" 0 '' "$sq" -- "$lh" delaunay -a copl
expect "coplanar 3D, hull" 1 "^copl: the 5 sites span an affine subspace of dimension 2, not 3" '' -- "$lh" hull copl

# --- sites on hull facets and on circumspheres ---------------------------------------------------------
file onedge '2 4\n0 0\n2 0\n0 2\n1 0\n'
expect "site on a hull edge (2D)" 0 '' '2\n0 3 2\n1 2 3\n' -- "$lh" delaunay onedge
file onface '3 5\n0 0 0\n3 0 0\n0 3 0\n0 0 3\n1 1 0\n'
expect "site on a hull face (3D)" 0 '' '3\n0 1 4 3\n0 2 3 4\n1 2 4 3\n' -- "$lh" delaunay onface
awk 'BEGIN { print "2 100"; for (i = 0; i < 10; i++) for (j = 0; j < 10; j++) print i, j }' > grid2
"$lh" delaunay -s grid2 | tr '\n' ' ' > out.txt
grep -q '^sites 100 dimension 2 simplices 162 hull facets 36 duplicates 0 ' out.txt && ok || bad "10 x 10 grid: $(cat out.txt)"
awk 'BEGIN { print "3 125"; for (i = 0; i < 5; i++) for (j = 0; j < 5; j++) for (k = 0; k < 5; k++) print i, j, k }' > grid3
"$lh" delaunay -s grid3 | tr '\n' ' ' > out.txt
grep -q '^sites 125 dimension 3 simplices 384 hull facets 192 duplicates 0 ' out.txt && ok || bad "5^3 grid: $(cat out.txt)"
file circle '2 12\n5 0\n4 3\n3 4\n0 5\n-3 4\n-4 3\n-5 0\n-4 -3\n-3 -4\n0 -5\n3 -4\n4 -3\n'
"$lh" delaunay circle > tri.txt
[ "$(head -1 tri.txt)" = "10" ] && ok || bad "12 cocircular sites: $(head -1 tri.txt) triangles, not 10"
expect "12 cocircular sites checked" 0 '' 'ok: 10 simplices, the Delaunay triangulation of the 12 points (exact check)\n' -- "$lh" check circle tri.txt
# a query on the hull's boundary is inside, at distance 0 (barycentric 0.5 0.5 on the edge)
file q '2 1\n0.5 0\n'
expect "query on a hull edge" 0 '' 'in 0 0 1 4 0.5 0.5 0 nearest 0\n' -- "$lh" locate sq1 q

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
