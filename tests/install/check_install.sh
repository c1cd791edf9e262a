#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix and builds consumer.c against
# it: with find_package(lifthull), static and shared, and with pkg-config (shared).
# Checks that the shared library exports lh_ functions only, under its SONAME, and
# runs the installed tool. Usage: check_install.sh BUILD C_COMPILER
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

so="$(find "$tmp/prefix" -name 'liblifthull.so.*.*.*' | head -n 1)"
test -f "$(dirname "$so")/liblifthull.a" || { echo "install: no liblifthull.a beside $so" >&2; exit 1; }
soname="$(objdump -p "$so" | awk '$1 == "SONAME" { print $2 }')"
version="$("$tmp/prefix/bin/lifthull" --version | awk '{ print $2 }')" # MAJOR.MINOR.PATCH
test "$soname" = "liblifthull.so.${version%.*}" ||
  { echo "install: SONAME $soname" >&2; exit 1; }
others="$(nm -D --defined-only "$so" | awk '{ print $3 }' | grep -v '^lh_[a-z]' || true)"
test -z "$others" || { echo "install: liblifthull.so exports more than lh_ functions:" $others >&2; exit 1; }
# every function lifthull.h marks LH_API is exported
api="$(grep -o 'LH_API [^(]*(' "$tmp/prefix/include/lifthull.h" | grep -o 'lh_[a-z0-9_]*($' | tr -d '(' | sort)"
exported="$(nm -D --defined-only "$so" | awk '{ print $3 }' | sort)"
test -n "$api" && test "$api" = "$exported" ||
  { echo "install: LH_API functions and liblifthull.so's exports differ:" >&2; diff <(echo "$api") <(echo "$exported") >&2; exit 1; }

for shared in OFF ON; do
  CC="$cc" cmake -S "$here" -B "$tmp/cmake-consumer-$shared" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
    -DLH_SHARED=$shared >/dev/null
  cmake --build "$tmp/cmake-consumer-$shared" >/dev/null
  "$tmp/cmake-consumer-$shared/consumer"
done
# grep without -q reads all of ldd's output: under pipefail, grep -q quitting early
# would fail the pipeline whenever ldd then died of SIGPIPE
ldd "$tmp/cmake-consumer-ON/consumer" | grep liblifthull.so >/dev/null ||
  { echo "install: the shared consumer does not load liblifthull.so" >&2; exit 1; }

pcdir="$(dirname "$(find "$tmp/prefix" -name lifthull.pc | head -n 1)")"
# shellcheck disable=SC2046
"$cc" -o "$tmp/pc-consumer" "$here/consumer.c" \
  $(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs lifthull)
LD_LIBRARY_PATH="$(dirname "$so")" "$tmp/pc-consumer"
echo "install: CMake package (static, shared) and pkg-config consumers OK"
