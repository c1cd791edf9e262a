#!/usr/bin/env bash
# README command 1: install what is missing, build in Release, run the main job on a
# bundled example. Until the engine lands, the main job is the exact predicates'
# self-check on bundled near-degenerate cases (tests/data/near_degenerate.txt).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh build
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DLH_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc)" >/dev/null
./build-release/cli/lifthull selfcheck tests/data/near_degenerate.txt
