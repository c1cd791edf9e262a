#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS]: the bounded fuzzing run of CI (scripts/test.sh) and of
# local campaigns. Builds the fuzz targets with clang 14 (libFuzzer, AddressSanitizer +
# UndefinedBehaviorSanitizer, UB fatal, the library instrumented too) in build-fuzz/,
# then runs every target for SECONDS (default 30) on a copy of its corpus
# (fuzz/corpus/<target>/; the checkout is not touched), two at a time, from the fixed
# random seed LH_FUZZ_SEED (default 1): a run explores the same inputs in the same
# order every time, so CI's verdict on a commit is reproducible (a slower machine only
# stops earlier in that sequence), and a local run of SECONDS or more covers what CI
# will run. Campaigns for new findings set another seed. Any finding (a
# failed assertion, a sanitizer report, a leak, an input slower than 20 s) fails the
# script, which prints the input and the command that reproduces it. Exit status: 0
# clean, 1 a finding, 2 a build failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
secs="${1:-30}"
seed="${LH_FUZZ_SEED:-1}"
targets=(fuzz_delaunay fuzz_read fuzz_hull fuzz_check fuzz_cells fuzz_query fuzz_poly fuzz_trimesh
         fuzz_plc_read fuzz_plc_binary fuzz_tetrahedralize)
# -max_len per target: a few dozen points (the point targets cap n anyway); files for the readers
declare -A max_len=([fuzz_delaunay]=400 [fuzz_read]=2048 [fuzz_hull]=300 [fuzz_check]=200
                    [fuzz_cells]=1024 [fuzz_query]=200 [fuzz_poly]=2048 [fuzz_trimesh]=256
                    [fuzz_plc_read]=4096 [fuzz_plc_binary]=4096 [fuzz_tetrahedralize]=200)

flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
if ! { CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLH_BUILD_FUZZ=ON \
         -DLH_BUILD_TESTS=OFF -DLH_WERROR=ON -DCMAKE_C_FLAGS="$flags" >/dev/null &&
       cmake --build build-fuzz -j 2 --target "${targets[@]}" >/dev/null; }; then
  echo "fuzz: the clang build failed" >&2
  exit 2
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/lifthull-fuzz.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0" UBSAN_OPTIONS="print_stacktrace=1"

run_one() { # target: fuzz a copy of its corpus; the log in $work/<target>.log
  local t="$1" name="${1#fuzz_}"
  mkdir -p "$work/$t.corpus" "$work/$t.art"
  cp fuzz/corpus/"$name"/* "$work/$t.corpus/" 2>/dev/null || true
  build-fuzz/fuzz/"$t" -max_total_time="$secs" -seed="$seed" -max_len="${max_len[$t]}" -timeout=20 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/$t.art/" \
    "$work/$t.corpus" >"$work/$t.log" 2>&1
}

report() { # target: one line, or the finding
  local t="$1" rc="$2" runs
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t.log" | tail -1)"
  if [ "$rc" -eq 0 ]; then
    printf 'fuzz: %-14s %s s, seed %s, %s runs, no finding\n' "$t" "$secs" "$seed" "${runs:-?}"
    return 0
  fi
  echo "fuzz: $t FOUND A PROBLEM (exit $rc); the end of its log:" >&2
  grep -v '^#[0-9]' "$work/$t.log" | tail -40 >&2
  for a in "$work/$t.art"/*; do
    [ -e "$a" ] || continue
    mkdir -p build-fuzz/findings
    cp "$a" build-fuzz/findings/
    echo "fuzz: the input ($(wc -c < "$a") bytes; its first 128 in hex), kept as build-fuzz/findings/${a##*/}:" >&2
    od -An -tx1 -v "$a" | head -8 >&2
    echo "fuzz: reproduce with  build-fuzz/fuzz/$t build-fuzz/findings/${a##*/}" >&2
    echo "      (found from seed $seed: LH_FUZZ_SEED=$seed bash scripts/fuzz.sh $secs runs the same search)" >&2
    echo "      (or any compiler: cmake -DLH_BUILD_FUZZ=ON, then the replay driver build/fuzz/$t FILE)" >&2
  done
  return 1
}

status=0
for ((i = 0; i < ${#targets[@]}; i += 2)); do
  a="${targets[i]}" b="${targets[i + 1]:-}"
  run_one "$a" & pa=$!
  if [ -n "$b" ]; then run_one "$b" & pb=$!; fi
  ra=0; wait "$pa" || ra=$?
  report "$a" "$ra" || status=1
  if [ -n "$b" ]; then
    rb=0; wait "$pb" || rb=$?
    report "$b" "$rb" || status=1
  fi
done
exit "$status"
