#!/usr/bin/env bash
# Times whole programs from a text file to the triangulation: `lifthull delaunay -s`
# (one thread and the default, every CPU) beside bench_whole_cgal (CGAL's whole program:
# a strtod loop, then Delaunay_triangulation_2/3), on 10^6 uniform sites in 2D and 3D
# written by `lifthull points`. Rounds are interleaved (tool order rotated per round);
# prints each tool's median wall time over the rounds and the ratio CGAL / lifthull.
#   bash bench/run_whole.sh [ROUNDS] [N]     (default 5 rounds, N = 1000000)
# Uses build-bench/ (Release), as bench/run_delaunay.sh; writes docs/bench-whole.md and
# prints it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
rounds="${1:-5}"
n="${2:-1000000}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DLH_BUILD_BENCH=ON -DLH_BUILD_TESTS=OFF >&2
cmake --build "$build" --target lifthull_cli bench_whole_cgal -j "$(nproc)" >&2
lh="$build/cli/lifthull"
cgal="$build/bench/bench_whole_cgal"
out="$root/docs/bench-whole.md"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo 'none')"
if [ -n "$(git -C "$root" status --porcelain 2>/dev/null || true)" ]; then
  commit="$commit (working tree has uncommitted changes)"
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

wall() { # prints the wall seconds of "$@" (output discarded)
  local t0 t1
  t0=$(date +%s%N)
  "$@" > /dev/null
  t1=$(date +%s%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f\n", (b - a) / 1e9 }'
}
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

{
echo "# Whole programs: \`lifthull delaunay -s FILE\` against CGAL's"
echo
echo "Produced by \`bash bench/run_whole.sh $rounds $n\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "(Release build in build-bench/, git commit $commit). Each program reads a text file"
echo "of uniform sites written by \`lifthull points N -d D\` (17 significant digits a"
echo "coordinate) and triangulates it; wall time of the whole process, median over the"
echo "rounds, rounds interleaved with the order rotated. CGAL's program"
echo "(bench/bench_whole_cgal.cpp) reads the file with a plain strtod loop, then builds"
echo "Delaunay_triangulation_2/3 (Epick). The ratio is CGAL / lifthull with every CPU, so"
echo "above 1 means lifthull is faster. This machine is shared and noisy: compare within a"
echo "run."
echo
echo "| D | N | lifthull -s (1 thread) | lifthull -s (all CPUs) | CGAL whole program | CGAL / lifthull (all CPUs) |"
echo "|---|---|---|---|---|---|"
for d in 2 3; do
  f="$tmp/sites$d.txt"
  "$lh" points "$n" -d "$d" -o "$f" -f
  : > "$tmp/one" ; : > "$tmp/all" ; : > "$tmp/cgal"
  for r in $(seq 1 "$rounds"); do
    tools=(one all cgal)
    for k in 0 1 2; do
      tool="${tools[$(( (k + r) % 3 ))]}"
      case "$tool" in
        one) wall "$lh" delaunay -s --threads 1 "$f" >> "$tmp/one" ;;
        all) wall "$lh" delaunay -s "$f" >> "$tmp/all" ;;
        cgal) wall "$cgal" "$f" >> "$tmp/cgal" ;;
      esac
    done
  done
  one=$(median < "$tmp/one"); all=$(median < "$tmp/all"); c=$(median < "$tmp/cgal")
  printf '| %d | %d | %.3f s | %.3f s | %.3f s | %.2fx |\n' "$d" "$n" "$one" "$all" "$c" "$(awk -v a="$c" -v b="$all" 'BEGIN { print a / b }')"
done
} > "$out"
cat "$out"
