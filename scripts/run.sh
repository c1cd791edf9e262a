#!/usr/bin/env bash
# README command 1: install what is missing, build in Release, run the main job on a
# bundled example: the exact Delaunay triangulation (and convex hull) of scipy's
# 9473-site degenerate point set, after the predicates' self-check on bundled
# near-degenerate cases.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

bash scripts/deps.sh build
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DLH_BUILD_TESTS=OFF >/dev/null
cmake --build build-release -j "$(nproc)" >/dev/null
./build-release/cli/lifthull selfcheck tests/data/near_degenerate.txt | tail -n 1
echo "== Delaunay triangulation of tests/data/points/degenerate_pointset.txt =="
./build-release/cli/lifthull delaunay -s tests/data/points/degenerate_pointset.txt
echo "== its convex hull =="
./build-release/cli/lifthull hull -s tests/data/points/degenerate_pointset.txt
