# harness.sh — what the 2D meshing CLI tests (triangle.sh, mesh.sh) share; sourced
# with their arguments LIFTHULL DATA. Sets $lh, $data, works in a temporary directory
# (removed at exit), counts $pass and $fail; `finish` prints them and sets the status.
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; data="$(cd "$2" && pwd)"
tmp="$(mktemp -d)"; trap 'chmod -R u+w "$tmp"; rm -rf "$tmp"' EXIT
cd "$tmp"
pass=0; fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
# matches FILE REGEX: REGEX found in FILE; an empty REGEX: FILE is empty.
matches() { if [ -z "$2" ]; then [ ! -s "$1" ]; else grep -Eq -- "$2" "$1"; fi; }
# expect NAME CODE STDERR_REGEX STDOUT_REGEX -- COMMAND...: exit code and both streams.
expect() {
  local name="$1" code="$2" err="$3" out="$4"; shift 5
  "$@" > out.txt 2> err.txt; local got=$?
  # a sanitizer's report fails the case whatever the exit code (ASan exits 1 too)
  if grep -Eq 'Sanitizer|runtime error:' err.txt; then bad "$name: $(grep -E -m1 'Sanitizer|runtime error:' err.txt)"
  elif [ "$got" -eq "$code" ] && matches err.txt "$err" && matches out.txt "$out"; then ok
  else bad "$name: exit $got (want $code); stderr: $(head -c 300 err.txt); stdout: $(head -c 300 out.txt)"; fi
}
# line FILE N: line N of FILE with blanks squeezed to one space.
line() { sed -n "$2p" "$1" | tr -s ' \t' ' ' | sed 's/^ //; s/ $//'; }
# same NAME GOT WANT
same() { if [ "$2" = "$3" ]; then ok; else bad "$1: '$2', want '$3'"; fi; }
exists() { for f in "$@"; do [ -e "$f" ] || { bad "$f missing"; return; }; done; ok; }
absent() { for f in "$@"; do [ ! -e "$f" ] || { bad "$f exists"; return; }; done; ok; }
finish() { echo "$pass passed, $fail failed"; [ "$fail" -eq 0 ]; }
