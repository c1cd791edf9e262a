#!/usr/bin/env bash
# bad_input.sh LIFTHULL: every malformed or degenerate input gets a non-zero exit and one
# clear line on standard error naming the file, line and column (or the problem), and
# nothing on standard output. LH_READ_MAX_POINTS (CTest sets it): the reader's count
# limit, 2147483646 unless lifthull has 64-bit indices.
set -u
lh="$1"
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

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
