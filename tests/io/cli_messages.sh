#!/usr/bin/env bash
# cli_messages.sh IO_TOOL BAD_INPUT_SH: the library reader gives, for every malformed
# input of tests/cli/bad_input.sh (exit code 3 there), a message matching that script's
# expectation — read from the script itself, so the two cannot drift apart; the inputs
# the CLI rejects later (exit code 1: degenerate sites) must read fine.
set -u
tool="$1"; script="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
expect() {
  local name="$1" code="$2" regex="$3"
  printf '%b' "$4" > "$tmp/$name"
  "$tool" read "$tmp/$name" > "$tmp/out" 2> "$tmp/err"
  local got=$?
  if { [ "$code" -eq 3 ] && [ "$got" -eq 3 ] && grep -Eq "$regex" "$tmp/err"; } ||
     { [ "$code" -ne 3 ] && [ "$got" -eq 0 ]; }; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL $name: exit $got, stderr: $(head -c 300 "$tmp/err"), want /$regex/"
  fi
}
# shellcheck source=/dev/null
source <(grep -E '^expect ' "$script")
echo "$pass passed, $fail failed"
[ "$pass" -gt 10 ] && [ "$fail" -eq 0 ]
