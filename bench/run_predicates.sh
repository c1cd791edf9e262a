#!/usr/bin/env bash
# Builds bench_predicates (Release, in build-bench/), runs it and writes its report to
# docs/bench-predicates.md, then prints that file. Extra arguments go to the program
# (e.g. --quick for a smoke run; see bench_predicates --help).
# Exit status: the program's (0, or 2 if lifthull and CGAL disagreed on a sign).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
out="$root/docs/bench-predicates.md"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DLH_BUILD_BENCH=ON -DLH_BUILD_TESTS=OFF >&2
cmake --build "$build" --target bench_predicates -j "$(nproc)" >&2

tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
status=0
"$build/bench/bench_predicates" "$@" >"$tmp" || status=$?

commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo 'none')"
if [ -n "$(git -C "$root" status --porcelain 2>/dev/null || true)" ]; then
  commit="$commit (working tree has uncommitted changes)"
fi

mkdir -p "$(dirname "$out")"
{
  echo "# Predicate benchmark: lifthull vs CGAL Epick"
  echo
  echo "Produced by \`bash bench/run_predicates.sh${*:+ $*}\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "(Release build in build-bench/, git commit $commit; program exit status $status)."
  echo "Each row: one pool of pre-generated tuples, timed by lifthull and by CGAL in"
  echo "interleaved rounds; ns/call is the median round. The exact-path fraction is"
  echo "lh_pred_counters exact_exits / calls; ratio = lifthull / CGAL. Source:"
  echo "bench/bench_predicates.cpp. This machine is shared and noisy: compare within a run."
  echo
  cat "$tmp"
} >"$out"

cat "$out"
exit "$status"
