#!/usr/bin/env bash
# Installs the Debian packages lifthull needs, only those that are missing.
#   scripts/deps.sh build   compiler and CMake: enough to build and run the tool
#   scripts/deps.sh test    also the test and benchmark oracles (GMP, CGAL, Eigen,
#                           Qhull, TetGen), clang and Python for the generated-code check,
#                           valgrind for the memcheck run, Node.js and npm for Triangle
#                           (npm triangle-wasm, pinned in tests/oracles/triangle/package-lock.json,
#                           installed into that folder with `npm ci`)
# Works as root (as in CI) or through sudo; never asks questions (no stdin needed).
set -euo pipefail

build_pkgs=(gcc make cmake)
test_pkgs=(g++ clang pkg-config libclang-rt-14-dev python3 libgmp-dev libcgal-dev libeigen3-dev
           libmpfr-dev qhull-bin libqhull-dev tetgen libtet1.5-dev python3-meshio valgrind)

# Node.js >= 18 runs the Triangle oracle: Debian's nodejs and npm, unless a Node.js is installed
# already (a NodeSource nodejs bundles npm and conflicts with Debian's npm package).
command -v node >/dev/null || test_pkgs+=(nodejs)
command -v npm >/dev/null || test_pkgs+=(npm)

# The npm packages of the test oracles, into the project (again only when missing or stale).
npm_oracles() {
  [ "${1:-build}" = test ] || return 0
  local dir
  dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/oracles/triangle"
  [ "$dir/node_modules/.package-lock.json" -nt "$dir/package-lock.json" ] && return 0
  echo "deps: npm ci in tests/oracles/triangle" >&2
  npm ci --prefix "$dir" --no-audit --no-fund --loglevel=error >&2 ||
    echo "deps: npm ci failed: the Triangle oracle (tests/oracles/triangle) is unavailable" >&2
}

case "${1:-build}" in
  build) want=("${build_pkgs[@]}") ;;
  test) want=("${build_pkgs[@]}" "${test_pkgs[@]}") ;;
  *) echo "usage: scripts/deps.sh build|test" >&2; exit 2 ;;
esac

missing=()
for p in "${want[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && { npm_oracles "${1:-build}"; exit 0; }

echo "deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo -n"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
npm_oracles "${1:-build}"
