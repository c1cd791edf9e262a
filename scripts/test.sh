#!/usr/bin/env bash
# README command 2 (and .ci/run): install the test dependencies, then build and run
# the whole suite twice:
#   build-asan/  clang, AddressSanitizer + UndefinedBehaviorSanitizer, warnings as
#                errors; the long oracle tests at LH_TEST_SCALE=0.2
#   build/       gcc, Release, warnings as errors, benchmarks built and smoke-run
# The Release run comes last, so the final lines are CTest's own summary.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc)"

bash scripts/deps.sh test

status=0
echo "== sanitizer build (clang, ASan+UBSan) =="
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLH_SANITIZE=ON -DLH_WERROR=ON -DLH_BUILD_TESTS=ON >/dev/null
cmake --build build-asan -j "$jobs" >/dev/null
LH_TEST_SCALE=0.2 ASAN_OPTIONS=detect_leaks=1 \
  ctest --test-dir build-asan -j "$jobs" --output-on-failure || status=1

echo "== release build (gcc) =="
CC=gcc CXX=g++ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLH_WERROR=ON \
  -DLH_BUILD_TESTS=ON -DLH_BUILD_BENCH=ON >/dev/null
cmake --build build -j "$jobs" >/dev/null
ctest --test-dir build -j "$jobs" --output-on-failure || status=1
exit "$status"
