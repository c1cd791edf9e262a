#!/usr/bin/env bash
# rbox.sh IO_TOOL: rbox's output (Qhull's point generator) as it is, in every dimension
# and with several of its options, read through a file and through standard input,
# gives exactly rbox's numbers (compared after strtod, by awk). Skips (77) without rbox.
set -u
tool="$1"
command -v rbox > /dev/null || { echo "SKIP: rbox not installed (Debian: qhull-bin)"; exit 77; }
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { # check DIM COUNT RBOX-ARGS...
  local d="$1" n="$2"; shift 2
  rbox "$@" > "$tmp/in.txt" || { fail=$((fail + 1)); echo "FAIL rbox $*"; return; }
  for how in file stdin; do
    if [ $how = file ]; then "$tool" read "$tmp/in.txt" > "$tmp/out" 2> "$tmp/err"
    else "$tool" read - < "$tmp/in.txt" > "$tmp/out" 2> "$tmp/err"; fi
    # rbox's coordinates: every line after its two header lines, printed by awk as %.17g.
    awk 'NR > 2 { s = ""; for (i = 1; i <= NF; i++) s = s (i > 1 ? " " : "") sprintf("%.17g", $i); print s }' \
      "$tmp/in.txt" > "$tmp/want"
    if [ "$(head -1 "$tmp/out")" = "qhull $d $n 0 0 0" ] && tail -n +2 "$tmp/out" | cmp -s - "$tmp/want"; then
      pass=$((pass + 1))
    else
      fail=$((fail + 1)); echo "FAIL rbox $* ($how): $(head -1 "$tmp/out") $(cat "$tmp/err")"
    fi
  done
}
for d in 2 3 4 5 6 7 8; do check $d 50 50 D$d t$d; done
check 3 10 10 D3 n t1        # no comment after the dimension
check 3 8 c D3               # the unit cube
check 2 20 20 D2 O1e10 t2    # offset coordinates
check 3 30 30 s D3 t3        # on a sphere
check 4 20 20 W0.1 D4 t4     # near the cube's surface
check 2 25 25 D2 z t5        # integer coordinates
check 3 1000 1000 D3 t6      # past the reader's 4 KiB look-ahead and first capacity
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
