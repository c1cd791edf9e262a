#!/usr/bin/env bash
# help_examples.sh LIFTHULL SOURCE_DIR: every example a user can paste runs as printed.
#   - every command listed by `lifthull --help` answers --help (exit 0, a usage line);
#   - every example line of every `lifthull COMMAND --help` (the indented lines after
#     "examples:" or "example:", and "e.g." lines), of README.md (its ```sh blocks that
#     set L=./build-release/cli/lifthull, and the one-line ./build-release block) and of
#     docs/lifthull.1 (EXAMPLES) exits 0, run in order with bash -o pipefail in a fresh
#     temporary directory holding a copy of SOURCE_DIR/examples and nothing else, with
#     `lifthull` on PATH;
#   - the man page lists the outputs of qdelaunay, qvoronoi and qconvex exactly as their
#     --help does.
# Lines needing Qhull's rbox or qdelaunay are skipped (and said so) when those are absent.
set -u
lh="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; src="$(cd "$2" && pwd)"
tmp="$(mktemp -d)"; trap 'chmod -R u+w "$tmp"; rm -rf "$tmp"' EXIT
mkdir "$tmp/bin"; ln -s "$lh" "$tmp/bin/lifthull"
export PATH="$tmp/bin:$PATH"
pass=0; fail=0; skip=0
bad() { fail=$((fail + 1)); echo "FAIL $*"; }

# run WHERE LINE: runs LINE in a fresh copy of examples/ (one per source of examples,
# shared by its lines in order, as a user pasting them one after another).
run() {
  local where="$1" line="$2" tool
  for tool in rbox qdelaunay; do
    if [[ " $line " == *" $tool "* ]] && ! command -v "$tool" > /dev/null; then
      skip=$((skip + 1)); echo "SKIP ($tool not installed) $where: $line"; return
    fi
  done
  (cd "$work" && bash -o pipefail -c "$line") > "$tmp/out" 2> "$tmp/err"; local rc=$?
  if [ "$rc" -ne 0 ] || grep -Eq 'Sanitizer|runtime error:' "$tmp/err"; then
    bad "$where: exit $rc: $line; stderr: $(head -c 300 "$tmp/err")"
  else
    pass=$((pass + 1))
  fi
}
fresh() { work="$tmp/w$((++nwork))"; mkdir "$work"; cp -R "$src/examples" "$work/examples"; }
nwork=0

# the commands, from the tool's own list
commands=$(lifthull --help | awk '/^commands:/ {on = 1; next} on && /^  [a-z]/ {print $1} on && /^$/ {on = 0}')
[ -n "$commands" ] || bad "no command found in lifthull --help"
for c in $commands; do
  if lifthull "$c" --help > "$tmp/help" 2> "$tmp/err" && grep -q "^usage: lifthull $c" "$tmp/help"; then
    pass=$((pass + 1))
  else
    bad "lifthull $c --help: no usage on standard output (stderr: $(head -c 200 "$tmp/err"))"; continue
  fi
  examples=$(awk '/^examples?:$/ {on = 1; next} on && /^  / {sub(/^  /, ""); print; next} {on = 0}
                  /^e\.g\.  / {sub(/^e\.g\.  /, ""); print}' "$tmp/help")
  fresh
  n=0
  while IFS= read -r line; do
    [ -n "$line" ] || continue
    n=$((n + 1)); run "lifthull $c --help" "$line"
  done <<< "$examples"
  [ "$n" -gt 0 ] || bad "lifthull $c --help shows no example"
done

# README.md: the sh blocks that use the built tool, the tool being `lifthull` here
fresh
readme=$(awk '/^```sh$/ {on = 1; block = ""; next}
              on && /^```$/ {on = 0; if (block ~ /build-release\/cli\/lifthull/) printf "%s", block; next}
              on && !/^L=/ {block = block $0 "\n"}
              on && /^L=/ {block = block "# " $0 "\n"}' "$src/README.md" |
         grep -v '^#' | sed -e 's|\$L|lifthull|g' -e 's|\./build-release/cli/lifthull|lifthull|g')
[ -n "$readme" ] || bad "no example found in README.md"
while IFS= read -r line; do run "README.md" "$line"; done <<< "$readme"

# docs/lifthull.1: the EXAMPLES section, roff escapes undone
fresh
man=$(awk '/^\.SH EXAMPLES/ {on = 1; next} /^\.SH/ {on = 0} on && /^\.fi/ {on = 0} on && !/^\./' "$src/docs/lifthull.1" |
      sed -e 's/\\-/-/g' -e 's/\\\\/\\/g')
[ -n "$man" ] || bad "no example found in docs/lifthull.1"
while IFS= read -r line; do run "docs/lifthull.1" "$line"; done <<< "$man"

# the man page's output lists of the Qhull programs = their --help's
for q in qdelaunay qvoronoi qconvex; do
  want=$(lifthull "$q" --help | sed -n 's/^outputs, printed in the order given: *//p' | tr -s ' ')
  got=$(grep -B1 "^($q)" "$src/docs/lifthull.1" | head -n 1 | sed -e 's/^\.BR //' -e 's/"//g' -e 's/, */ /g' | tr -s ' ')
  if [ -n "$want" ] && [ "$want" = "$got" ]; then pass=$((pass + 1)); else bad "$q outputs: man page '$got', --help '$want'"; fi
done

echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
