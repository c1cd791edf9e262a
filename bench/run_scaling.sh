#!/usr/bin/env bash
# Dimension-scaling benchmark: builds bench_delaunay (Release), runs lifthull, CGAL,
# Qhull and TetGen over n and d = 2..8 on uniform, integer-grid and cospherical sites
# (bench/scaling.py), and writes docs/benchmarks.md with the plots
# docs/bench-scaling-{time,rate,memory}.svg and the raw runs docs/bench-scaling-runs.csv.
#
#   bash bench/run_scaling.sh [--quick] [--rounds R] [--dims 2,3,..] [--dists uniform,grid,sphere]
#                             [--budget S] [--timeout S] [--seed S] [--resume] [--report-only]
#
# --quick: tiny sizes, a smoke run of a minute or two (its report is labelled as such).
# --budget S: a tool is not run at larger n once its median exceeds S seconds (default 60)
# or its extrapolated time at the next size exceeds 2S. --resume continues an interrupted
# sweep from its runs file; --report-only rewrites the report from it.
# The full sweep takes about an hour on a 2-core machine; see docs/benchmarks.md.
# Environment: LH_BENCH_BUILD_DIR (default build-bench/), LH_BENCH_JOBS (build jobs,
# default nproc). Exit status: scaling.py's (0, or 2 if a run failed or the exact tools
# disagreed on uniform sites).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LH_BENCH_BUILD_DIR:-$root/build-bench}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
jobs="${LH_BENCH_JOBS:-$(nproc)}"

# Record the commit before building, so that a commit made meanwhile is not credited.
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo 'none')"
if [ -n "$(git -C "$root" status --porcelain 2>/dev/null || true)" ]; then
  commit="$commit (working tree has uncommitted changes)"
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DLH_BUILD_BENCH=ON -DLH_BUILD_TESTS=OFF >&2
cmake --build "$build" --target bench_delaunay -j "$jobs" >&2

# A --quick run keeps its own runs file, so that it never overwrites a full sweep's.
results="$build/scaling-runs.jsonl"
for a in "$@"; do
  [ "$a" = "--quick" ] && results="$build/scaling-runs-quick.jsonl"
done

exec python3 "$root/bench/scaling.py" --exe "$build/bench/bench_delaunay" \
  --out "$root/docs/benchmarks.md" --results "$results" --commit "$commit" \
  --build-dir "${build#"$root"/}/" --command "bash bench/run_scaling.sh${*:+ $*}" "$@"
