#!/usr/bin/env bash
# bench/run_mesh2.sh: the 2D meshing benchmark of issue #7, lifthull against Triangle 1.6
# (npm triangle-wasm, tests/oracles/triangle/triangle_run.mjs) and CGAL (oracle_cgal_cdt:
# Constrained_Delaunay_triangulation_2, Delaunay_mesher_2):
#
#   cdt   10^6 random sites and 10^4 random non-crossing segments in the unit square
#         (bench/gen_cdt_poly.py; the square's sides are segments too): Triangle -pQ,
#         CGAL CDT_2 (+ the domain), lifthull triangle -pQ
#   mesh  A.poly refined to ~10^6 triangles: Triangle -pq30a1.3e-7 and -pq20.7a1.3e-7, CGAL
#         Mesh_2 at its 20.7 degree bound (B = 0.125) with the edge-length bound S = 6.5e-4,
#         lifthull triangle -pq30a1.3e-7 (written 0.00000013: Triangle reads no exponent)
#
#   bash bench/run_mesh2.sh [--rounds R] [--quick]
#
# Each cell is the median of R rounds (default 3; rounds interleaved, each run its own
# process). Times are the tools' own compute times, without reading or writing files:
# Triangle's triangulate() call (triangle_run.mjs), CGAL's construction + domain marking
# (+ refinement); lifthull's, if its command prints `compute_ms=T` on stderr, else its wall
# time (marked `wall`). --quick: 10^5 sites, 10^3 segments, ~10^5 triangles, for a smoke run.
# Builds oracle_cgal_cdt and lifthull (Release) in build-bench-mesh2/ ($LH_BENCH_BUILD);
# $LH names another lifthull. Needs node + `npm ci --prefix tests/oracles/triangle` (done by
# scripts/deps.sh test). Prints a Markdown table; the machine is noisy: compare in one run.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LH_BENCH_BUILD:-$root/build-bench-mesh2}"
rounds=3 quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    *) echo "usage: bash bench/run_mesh2.sh [--rounds R] [--quick]" >&2; exit 2 ;;
  esac
done

commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo none)"
[ -n "$(git -C "$root" status --porcelain 2>/dev/null || true)" ] && commit="$commit (uncommitted changes)"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DLH_BUILD_TESTS=ON -DLH_BUILD_BENCH=OFF >&2
cmake --build "$build" --target oracle_cgal_cdt -j "$(nproc)" >&2
cgal="$build/tests/oracles/oracle_cgal_cdt"
if [ -z "${LH:-}" ]; then
  LH="$build/cli/lifthull"
  cmake --build "$build" --target lifthull_cli -j "$(nproc)" >&2 || echo "run_mesh2: lifthull did not build" >&2
fi
triangle=(node "$root/tests/oracles/triangle/triangle_run.mjs")

work="$(mktemp -d "${TMPDIR:-/tmp}/mesh2bench.XXXXXX")"
trap 'rm -rf "$work"' EXIT
if [ "$quick" = 1 ]; then
  sites=100000 segs=1000 area=0.0000013 size=0.002
else
  sites=1000000 segs=10000 area=0.00000013 size=0.00065
fi
echo "run_mesh2: writing the CDT input ($sites sites, $segs segments)" >&2
python3 "$root/bench/gen_cdt_poly.py" --sites "$sites" --segments "$segs" "$work/cdt.poly"
cp "$root/tests/data/triangle/A.poly" "$work/A.poly"

# ---- one run of each tool: prints "SECONDS TRIANGLES" -----------------------------------
ele_count() { head -1 "$1" | awk '{print $1}'; }

run_triangle() {  # SWITCHES FILE
  local d="$work/tri" err
  mkdir -p "$d"
  err="$("${triangle[@]}" "$1" "$work/$2.poly" "$d" 2>&1 >/dev/null)"
  local ms="${err##*compute_ms=}"
  echo "$(awk -v m="$ms" 'BEGIN{printf "%.3f", m / 1000}') $(ele_count "$d/$2.1.ele")"
}

run_cgal_cdt() {
  local err
  err="$("$cgal" cdt --time "$work/cdt.poly" 2>&1 >/dev/null)"
  echo "$err" | awk '{for (i = 1; i <= NF; i++) { split($i, kv, "=");
    if (kv[1] == "time_cdt" || kv[1] == "time_domain") t += kv[2]; if (kv[1] == "triangles") n = kv[2] }}
    END { printf "%.3f %d\n", t, n }'
}

run_cgal_mesh() {
  local err
  err="$("$cgal" mesh --size "$size" --time "$work/A.poly" 2>&1 >/dev/null)"
  echo "$err" | awk '{for (i = 1; i <= NF; i++) { split($i, kv, "=");
    if (kv[1] == "time_total") t = kv[2]; if (kv[1] == "triangles") n = kv[2] }}
    END { printf "%.3f %d\n", t, n }'
}

# ==== lifthull: the slot for `lifthull triangle` ===========================================
# Runs `$LH triangle SWITCHES FILE.poly` on a copy of the input; its compute time if it prints
# `compute_ms=T` on stderr, else the wall time of the whole command (then marked `wall`).
lh_ready() { [ -x "$LH" ] && "$LH" triangle -h >/dev/null 2>&1; }
run_lifthull() {  # SWITCHES FILE
  local d="$work/lh" err t0 t1
  mkdir -p "$d"
  cp "$work/$2.poly" "$d/$2.poly"
  t0="$(date +%s%N)"
  err="$(LIFTHULL_TIMING=1 "$LH" triangle "$1" "$d/$2.poly" 2>&1 >/dev/null)" || { echo "failed 0"; return; }
  t1="$(date +%s%N)"
  if [[ "$err" == *compute_ms=* ]]; then
    local ms="${err##*compute_ms=}"
    echo "$(awk -v m="${ms%%[!0-9.]*}" 'BEGIN{printf "%.3f", m / 1000}') $(ele_count "$d/$2.1.ele")"
  else
    echo "$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.3f", (b - a) / 1e9}')wall $(ele_count "$d/$2.1.ele")"
  fi
}
# ===========================================================================================

# the cases: NAME|TOOL|SWITCHES|command
cases=(
  "cdt|Triangle 1.6 (wasm)|-pQ|run_triangle -pQ cdt"
  "cdt|CGAL CDT_2|Epick, no intersections|run_cgal_cdt"
  "cdt|lifthull|-pQ|run_lifthull -pQ cdt"
  "mesh|Triangle 1.6 (wasm)|-pq30a$area|run_triangle -pq30a${area}Q A"
  "mesh|Triangle 1.6 (wasm)|-pq20.7a$area|run_triangle -pq20.7a${area}Q A"
  "mesh|CGAL Mesh_2|B=0.125 S=$size|run_cgal_mesh"
  "mesh|lifthull|-pq30a$area|run_lifthull -pq30a${area}Q A"
)

declare -A times counts
for ((r = 1; r <= rounds; r++)); do
  for k in "${!cases[@]}"; do
    IFS='|' read -r name tool sw cmd <<<"${cases[$k]}"
    if [ "$tool" = lifthull ] && ! lh_ready; then continue; fi
    echo "run_mesh2: round $r: $name $tool $sw" >&2
    read -r t n <<<"$($cmd)"
    times[$k]="${times[$k]:-} $t"
    counts[$k]="$n"
  done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $0} END {print (NR ? v[int((NR + 1) / 2)] : "-")}'; }

echo "# 2D meshing benchmark: lifthull vs Triangle 1.6 (wasm) and CGAL 5.5"
echo
flags=""
[ "$quick" = 1 ] && flags=" --quick"
[ "$rounds" != 3 ] && flags="$flags --rounds $rounds"
echo "\`bash bench/run_mesh2.sh$flags\`, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit,"
echo "$(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg). Median of $rounds rounds, seconds of compute"
echo "(no file I/O). cdt: $sites sites + $segs segments in the unit square; mesh: A.poly."
echo
echo "| case | tool | switches | triangles | median s | runs (s) |"
echo "|---|---|---|---:|---:|---|"
for k in "${!cases[@]}"; do
  IFS='|' read -r name tool sw cmd <<<"${cases[$k]}"
  if [ -z "${times[$k]:-}" ]; then
    echo "| $name | $tool | $sw | - | - | not run (\`$LH triangle\` not available) |"
    continue
  fi
  echo "| $name | $tool | \`$sw\` | ${counts[$k]} | $(echo "${times[$k]}" | median) |${times[$k]} |"
done
