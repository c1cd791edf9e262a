#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix and builds consumer.c against
# it twice: with find_package(lifthull) and with pkg-config. Also runs the installed
# tool. Usage: check_install.sh BUILD C_COMPILER
set -euo pipefail
build="$1"
cc="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
test -f "$tmp/prefix/include/lifthull.h"
"$tmp/prefix/bin/lifthull" --version
# the installed tool from another directory: selfcheck needs no data file beside it
(cd "$tmp" && "$tmp/prefix/bin/lifthull" selfcheck | tail -n 1 | grep -q '^selfcheck: 33 cases, 0 wrong') ||
  { echo "install: the installed lifthull selfcheck failed outside the source tree" >&2; exit 1; }

CC="$cc" cmake -S "$here" -B "$tmp/cmake-consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/cmake-consumer" >/dev/null
"$tmp/cmake-consumer/consumer"

pcdir="$(dirname "$(find "$tmp/prefix" -name lifthull.pc | head -n 1)")"
# shellcheck disable=SC2046
"$cc" -o "$tmp/pc-consumer" "$here/consumer.c" \
  $(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs lifthull)
"$tmp/pc-consumer"
echo "install: CMake package and pkg-config consumers OK"
