#!/usr/bin/env bash
# bad_input.sh LIFTHULL: every malformed or degenerate input gets a non-zero exit and one
# clear line on standard error naming the file, line and column (or the problem), and
# nothing on standard output. LH_READ_MAX_POINTS (CTest sets it): the reader's count
# limit, 2147483646 unless lifthull has 64-bit indices.
set -u
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0

# expect NAME EXIT_CODE REGEX CONTENT: writes CONTENT to a file, runs delaunay on it.
expect() {
  local name="$1" code="$2" regex="$3"
  printf '%b' "$4" > "$tmp/$name"
  "$lh" delaunay "$tmp/$name" > "$tmp/out" 2> "$tmp/err"
  local got=$?
  if [ "$got" -eq "$code" ] && grep -Eq "$regex" "$tmp/err" && [ ! -s "$tmp/out" ]; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL $name: exit $got (want $code), stderr: $(head -c 300 "$tmp/err"), stdout bytes: $(wc -c < "$tmp/out")"
  fi
}

expect empty 3 "empty:1:1: expected the dimension, found the end of the input" ""
expect one_site 1 "the 1 site spans an affine subspace of dimension 0, not 2" "2\n1\n0.5 0.5\n"
expect too_few 1 "span an affine subspace of dimension 1, not 2" "2\n2\n0 0\n1 1\n"
expect collinear 1 "dimension 1, not 2" "2\n4\n0 0\n1 1\n2 2\n3 3\n"
expect coplanar 1 "dimension 2, not 3: nothing 3-dimensional to compute \\(lifthull delaunay -a triangulates" "3\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
expect nan 3 "nan:4:3: coordinate 2 of point 2 is 'nan'" "2\n3\n0 0\n1 nan\n0 1\n"
expect inf 3 "inf:3:1: coordinate 1 of point 1 is '-inf'" "2\n3\n-inf 0\n1 0\n0 1\n"
expect dim1 3 "dim1:1:1: expected the dimension \\(an integer from 2 to 8\\), found '1'" "1\n3\n0\n1\n2\n"
expect dim9 3 "dim9:1:1: expected the dimension \\(an integer from 2 to 8\\), found '9'" "9\n3\n"
expect truncated 3 "truncated:5:1: expected coordinate 1 of point 3, found the end of the input \\(3 points declared\\)" "2\n3\n0 0\n1 0\n"
expect half_point 3 "half_point:6:1: expected coordinate 2 of point 3" "2\n3\n0 0\n1 0\n0\n"
expect extra 3 "extra:6:1: expected the end of the input after 3 points of dimension 2, found '7'" "2\n3\n0 0\n1 0\n0 1\n7\n"
expect text 3 "text:3:3: expected coordinate 2 of point 1 \\(a number\\), found 'abc'" "2\n3\n0 abc\n1 0\n0 1\n"
expect count_text 3 "count_text:2:1: expected the number of points" "2\nmany\n0 0\n"
expect huge_count 3 "huge_count:2:1: expected the number of points \\(an integer from 1 to ${LH_READ_MAX_POINTS:-2147483646}\\)" "2\n10000000000000000000\n0 0\n"
expect binary 3 "binary:1:1: expected the dimension" "\x7fELF\x02\x01\x01\x00\xff\xfe"
expect zero_count 3 "expected the number of points" "2\n0\n"
expect short.csv 3 "short.csv:3:2: expected coordinate 2 of point 2 \\(2 per line, as on line 2\\), found the end of the line" "x,y\n0,0\n1\n0,1\n"
expect long.txt 3 "long.txt:2:5: expected the end of the line after 2 coordinates \\(as on line 1\\), found '5'" "0 0\n1 0 5\n0 1\n"
expect nul 3 "nul:4:2: expected coordinate 2 of point 2 \\(a number\\), found a NUL byte" "2\n3\n0 0\n1\x00 0\n0 1\n"

# Usage errors and a missing file.
"$lh" delaunay --frobnicate > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 2 ] && grep -q "unknown option '--frobnicate'" "$tmp/err"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL unknown option: exit $c"; fi
"$lh" delaunay "$tmp/does-not-exist" > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 3 ] && grep -q "does-not-exist" "$tmp/err"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL missing file: exit $c"; fi
"$lh" frobnicate > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 2 ] && grep -q "unknown command 'frobnicate'" "$tmp/err"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL unknown command: exit $c"; fi

# Good input from standard input, rbox style (comment after the dimension), both commands.
printf '2 rbox 4 D2\n4\n0 0\n1 0\n0 1\n1 1.5\n' | "$lh" delaunay > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 0 ] && [ "$(head -1 "$tmp/out")" = "2" ] && [ "$(wc -l < "$tmp/out")" -eq 3 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL stdin delaunay: exit $c"; fi
printf '2 4\n0 0\n1 0\n0 1\n1 1.5\n' | "$lh" hull > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 0 ] && [ "$(head -1 "$tmp/out")" = "4" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL stdin hull: exit $c"; fi

# Coplanar points with -a: triangles (3 indices a line) within their plane.
printf '3 5\n0 0 0\n2 0 2\n0 2 2\n2 2 4\n1 1 2\n' | "$lh" delaunay -a > "$tmp/out" 2> "$tmp/err"; c=$?
if [ $c -eq 0 ] && [ "$(head -1 "$tmp/out")" = "4" ] && [ "$(awk 'NR > 1 && NF != 3' "$tmp/out" | wc -l)" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL delaunay -a: exit $c"; fi

# The 2D meshing inputs and every option: the exact line on standard error (the names
# relative, from inside $tmp), the exit code, nothing on standard output.
# exact NAME CODE STDERR -- COMMAND...
exact() {
  local name="$1" code="$2" want="$3"; shift 4
  (cd "$tmp" && "$@") > "$tmp/out" 2> "$tmp/err"; local got=$?
  if [ "$got" -eq "$code" ] && [ "$(cat "$tmp/err")" = "$want" ] && [ ! -s "$tmp/out" ]; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL $name: exit $got (want $code), stderr: '$(head -c 300 "$tmp/err")' (want '$want'), stdout bytes: $(wc -c < "$tmp/out")"
  fi
}
# a hole seed exactly on an inner segment (inside it, at an endpoint): refused, naming both
square='8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n7 3 3\n8 1 3\n8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n'
printf "${square}1 2 1\n" > "$tmp/hole_on_seg.poly"
exact hole_on_segment 3 "hole_on_seg.poly:20: hole 1 lies on segment 5" -- "$lh" triangle -pQ hole_on_seg.poly
exact hole_on_segment_mesh 3 "hole_on_seg.poly:20: hole 1 lies on segment 5" -- "$lh" mesh hole_on_seg.poly -q
printf "${square}1 3 3\n" > "$tmp/hole_on_corner.poly"
exact hole_on_corner 3 "hole_on_corner.poly:20: hole 1 lies on segment 6" -- "$lh" triangle -pQ hole_on_corner.poly
# a .poly with n = 0 numbered from 1, its .node from 0: segments keep the .poly's numbers
printf '4 2 0 0\n0 0 0\n1 2 0\n2 2 2\n3 0 2\n' > "$tmp/n0.node"
printf '0 2 0 0\n3 0\n1 0 2\n2 1 2\n3 1 3\n0\n' > "$tmp/n0.poly"
exact n0_crossing 3 "n0.poly:5: segment 3 crosses segment 1 (line 3)" -- "$lh" triangle -pQ n0.poly
printf '0 2 0 0\n3 0\n1 0 1\n2 1 2\n3 1 9\n0\n' > "$tmp/n0.poly"
exact n0_endpoint 3 "n0.poly:5: segment 3: endpoint 9 is not a vertex (0..3)" -- "$lh" triangle -pQ n0.poly

# a directory given as the input: said so, for every reader
mkdir "$tmp/dir.poly" "$tmp/dir.txt"
exact dir_points 3 "dir.txt: is a directory, not an input file" -- "$lh" delaunay dir.txt
exact dir_qhull 3 "dir.txt: is a directory, not an input file" -- "$lh" qconvex TI dir.txt
exact dir_qhalf 3 "dir.txt: is a directory, not an input file" -- "$lh" qhalf Fp TI dir.txt
exact dir_poly 3 "dir.poly: is a directory, not an input file" -- "$lh" mesh dir.poly
exact dir_check 3 "dir.txt: is a directory, not an input file" -- "$lh" check n0.node dir.txt
# -r: the .ele's attributes are numbers as a .node's are (finite); the .area file read
# whole: every line however long, its own line numbers, every token whole
printf '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n' > "$tmp/q.node"
printf '1 3 1\n1 1 2 3 nan\n' > "$tmp/q.ele"
exact ele_nan 3 "q.ele:2:9: attribute 1 of cell 1 is 'nan': NaN and infinities are not accepted" -- "$lh" triangle -rQ q
printf '1 3 1\n1 1 2 3 1e400\n' > "$tmp/q.ele"
exact ele_overflow 3 "q.ele:2:9: attribute 1 of cell 1 is '1e400', which overflows a double" -- "$lh" triangle -rQ q
printf '2 3 0\n1 1 2 3\n2 1 3 4\n' > "$tmp/q.ele"
area() { printf '%b' "$2" > "$tmp/q.area"; exact "$1" 3 "$3" -- "$lh" triangle -raQ q; }
area area_empty "" "q.area:1:1: expected the number of triangles (2, as in the .ele), found the end of the file"
area area_comments "# areas\n\n" "q.area:3:1: expected the number of triangles (2, as in the .ele), found the end of the file"
area area_2x "2\n1 2x\n2 1\n" "q.area:2:3: expected the area bound of triangle 1 (a number), found '2x'"
area area_nul "2\n1 0.1\0junk\n2 1\n" "q.area:2:6: expected the end of the line after triangle 1's area bound, found a NUL byte"
area area_nan "2\n1 nan\n2 1\n" "q.area:2:3: the area bound of triangle 1 is 'nan': NaN and infinities are not accepted (0 or below: no bound)"
area area_line_numbers "\n# c\n2\n\n1 1\n2 1 7\n" "q.area:6:5: expected the end of the line after triangle 2's area bound, found '7'"
area area_long_line "$(printf '%600s' '')2\n1 1\n$(printf '%600s' '')2 x\n" "q.area:3:603: expected the area bound of triangle 2 (a number), found 'x'"
area area_short "2\n1 1\n" "q.area:3:1: expected triangle number 2, found the end of the file"
area area_long "2\n1 1\n2 1\n3 1\n" "q.area:4:1: expected the end of the file after 2 triangles, found '3'"
# a number of any length, as in a .node (a 100-digit bound was "not a number")
printf '2\n1 1%s.5\n2 1\n' "$(printf '%099d' 0)" > "$tmp/q.area"
exact area_long_number 0 "" -- "$lh" triangle -raQ q

# numbers of options: empty, signed, blank-padded or trailing text is refused; a value
# just past a bound prints with every digit
exact threads_empty 2 "lifthull delaunay: --threads takes a whole number from 0 to 4096, not '' (lifthull delaunay --help)" -- "$lh" delaunay --threads "" n0.node
exact threads_blank 2 "lifthull hull: --threads takes a whole number from 0 to 4096, not ' 1' (lifthull hull --help)" -- "$lh" hull --threads " 1" n0.node
exact threads_plus 2 "lifthull voronoi: --threads takes a whole number from 0 to 4096, not '+1' (lifthull voronoi --help)" -- "$lh" voronoi --threads +1 n0.node
exact values_empty 2 "lifthull interpolate: --values takes a whole number from 1 to 6, not '' (lifthull interpolate --help)" -- "$lh" interpolate --values "" n0.node n0.node
exact q_past_40 2 "lifthull triangle: -q40.000000100000001: the angle bound must be 0..40 degrees" -- "$lh" triangle -pq40.0000001 n0.poly
exact min_angle_past_40 2 "lifthull mesh: --min-angle takes a number from 0 to 40, not '40.0000001' (lifthull mesh --help)" -- "$lh" mesh n0.poly --min-angle 40.0000001
exact max_area_nan 2 "lifthull mesh: --max-area takes a number from 0 to 1e+308, not 'nan' (lifthull mesh --help)" -- "$lh" mesh n0.poly --max-area nan

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
