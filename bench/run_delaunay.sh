#!/usr/bin/env bash
# Builds bench_delaunay (Release, in build-bench/), runs its suite and writes the report to
# docs/bench-delaunay.md, then prints that file. Extra arguments go to `bench_delaunay
# suite` (e.g. --quick for a smoke run, --rounds 5, --dims 4,5; see bench_delaunay --help).
# The full suite takes several minutes (Qhull 3D 10^6 alone is ~30 s per round).
# Exit status: the program's (0, or 2 if a run failed or the exact tools disagreed on a
# simplex count). Missed bars are reported in the file, not in the exit status.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
out="$root/docs/bench-delaunay.md"

# Record the commit before building, so that a commit made meanwhile is not credited.
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo 'none')"
if [ -n "$(git -C "$root" status --porcelain 2>/dev/null || true)" ]; then
  commit="$commit (working tree has uncommitted changes)"
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DLH_BUILD_BENCH=ON -DLH_BUILD_TESTS=OFF >&2
cmake --build "$build" --target bench_delaunay -j "$(nproc)" >&2

tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
status=0
"$build/bench/bench_delaunay" suite "$@" >"$tmp" || status=$?

mkdir -p "$(dirname "$out")"
{
  echo "# Delaunay benchmark: lifthull vs CGAL, Qhull, TetGen"
  echo
  echo "Produced by \`bash bench/run_delaunay.sh${*:+ $*}\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "(Release build in build-bench/, git commit $commit; program exit status $status)."
  echo "Uniform random sites in [0,1)^D, the same for every tool. Each tool runs in its own"
  echo "process, once per round; rounds are interleaved (tool order rotated every round) and"
  echo "each cell is the median over the rounds. Ratios are tool / lifthull, so 2.0x means"
  echo "lifthull took half the time (or memory). Source: bench/bench_delaunay.cpp. This"
  echo "machine is shared and noisy: compare within a run."
  echo
  cat "$tmp"
} >"$out"

cat "$out"
exit "$status"
