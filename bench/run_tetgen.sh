#!/usr/bin/env bash
# bench/run_tetgen.sh: the 3D meshing benchmark of issue #32, `lifthull tetgen` against
# TetGen 1.5 (Debian's /usr/bin/tetgen, a separate program), whole processes:
#
#   bash bench/run_tetgen.sh [--rounds R] [--switches S] [--timeout SECONDS] [--data DIR]
#                            [--out FILE] [FILE...]
#
# For each input, R rounds (default 5, interleaved: every round runs every input once with
# each tool, the tool order swapped every round) of `lifthull tetgen -S FILE` and
# `tetgen -S FILE` (S = --switches, default pQ), each run in its own temporary directory
# on a copy of the input. Per run: the wall time and peak RSS of the whole process
# (/usr/bin/time -v), the exit status (and the last line it wrote when it failed), and the
# output's point and tetrahedron counts (FILE.1.node, FILE.1.ele). Steiner points = output
# points - input points (the count in the input file's header). The report gives medians
# and the ratios lifthull / TetGen (at most 1.00: lifthull as fast or as small), the issue's
# bars (-p no slower than TetGen, peak memory no more, on knot, bunny, fandisk, elephant and
# armadillo) and TetGen's Steiner counts beside lifthull's, with -S and with -SM (TetGen then
# keeps coplanar facets apart and their common edges, as lifthull does; run once, untimed).
#
# Inputs (default): DIR/surfaces/{knot,bunny,fandisk,elephant,armadillo}.off and
# DIR/tetgen/{u,joint,eight,mpi,part}.off with DIR = ../shared/data beside the repository
# (--data DIR); FILE... replaces that list. A missing input is skipped with a note in the
# report. Builds lifthull (Release) in build-bench-mesh3d/ ($LH_BENCH_BUILD); $LH names
# another lifthull, $TETGEN another tetgen. Writes docs/bench-mesh3d.md (--out) only when
# the whole run finished, then prints it. Exit status: 0 when the report was written (failed
# runs are in the report), 1 on a setup error (no tetgen, no input), 2 on a usage error.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${LH_BENCH_BUILD:-$root/build-bench-mesh3d}"
rounds=5 switches=pQ limit=600 data="$root/../shared/data" out="$root/docs/bench-mesh3d.md"
args=("$@")
usage() {
  echo "usage: bash bench/run_tetgen.sh [--rounds R] [--switches S] [--timeout SECONDS]" >&2
  echo "                               [--data DIR] [--out FILE] [FILE...]" >&2
  exit 2
}
inputs=()
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) [ $# -ge 2 ] || usage; rounds="$2"; shift 2 ;;
    --switches) [ $# -ge 2 ] || usage; switches="${2#-}"; shift 2 ;;
    --timeout) [ $# -ge 2 ] || usage; limit="$2"; shift 2 ;;
    --data) [ $# -ge 2 ] || usage; data="$2"; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out="$2"; shift 2 ;;
    -h | --help) usage ;;
    -*) echo "run_tetgen: unknown option $1" >&2; usage ;;
    *) inputs+=("$1"); shift ;;
  esac
done
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "run_tetgen: --rounds wants a positive integer" >&2; usage; }
[[ "$limit" =~ ^[1-9][0-9]*$ ]] || { echo "run_tetgen: --timeout wants a positive integer" >&2; usage; }
[[ "$switches" =~ ^[A-Za-z0-9./]+$ ]] || { echo "run_tetgen: --switches: letters and numbers only" >&2; usage; }
if [ ${#inputs[@]} -eq 0 ]; then
  for m in knot bunny fandisk elephant armadillo; do inputs+=("$data/surfaces/$m.off"); done
  for m in u joint eight mpi part; do inputs+=("$data/tetgen/$m.off"); done
fi
# the issue's speed and memory bars are about these models
barred=" knot bunny fandisk elephant armadillo "

for tool in /usr/bin/time timeout; do
  command -v "$tool" >/dev/null || { echo "run_tetgen: $tool not found" >&2; exit 1; }
done
TETGEN="${TETGEN:-$(command -v tetgen || true)}"
if [ -z "$TETGEN" ] || [ ! -x "$TETGEN" ]; then echo "run_tetgen: tetgen not found (apt-get install tetgen)" >&2; exit 1; fi

# Record the commit before building, so that a commit made meanwhile is not credited.
# Changes to tracked files make it "uncommitted", except to the report itself.
out="$(realpath -m "$out")"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo none)"
spec=(.)
[[ "$out" == "$root"/* ]] && spec+=(":(exclude)$out")
if [ -n "$(git -C "$root" status --porcelain --untracked-files=no -- "${spec[@]}" 2>/dev/null || true)" ]; then
  commit="$commit (working tree has uncommitted changes)"
fi
if [ -z "${LH:-}" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DLH_BUILD_TESTS=OFF -DLH_BUILD_BENCH=OFF >&2
  cmake --build "$build" --target lifthull_cli -j "$(nproc)" >&2
  LH="$build/cli/lifthull"
fi
[ -x "$LH" ] || { echo "run_tetgen: $LH is not a program" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/mesh3dbench.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# ---- the input's point count, from its header ("?" when the format does not say) ------
header_count() {  # FILE: the first number of the first line that is not blank or a comment
  LC_ALL=C awk '{ sub(/#.*/, "") } NF { print $1; exit }' "$1"
}
input_points() {  # FILE
  local f="$1" n
  case "${f,,}" in
    *.off)  # OFF [n f e] | OFF \n n f e, comments allowed
      LC_ALL=C awk '{ sub(/#.*/, "") } !NF { next }
        !seen { seen = 1; if ($1 ~ /OFF$/) { if (NF > 1) { print $2; exit } next } }
        { print $1; exit }' "$f" ;;
    *.node) header_count "$f" ;;
    *.poly | *.smesh)
      n="$(header_count "$f")"
      if [ "$n" = 0 ] && [ -f "${f%.*}.node" ]; then header_count "${f%.*}.node"; else echo "$n"; fi ;;
    *.ply)
      LC_ALL=C awk '$1 == "element" && $2 == "vertex" { print $3; exit } $1 == "end_header" { exit }' "$f" ;;
    *.obj) LC_ALL=C awk '$1 == "v" { n++ } END { print n + 0 }' "$f" ;;
    *.mesh) LC_ALL=C awk 'want { print $1; exit } $1 == "Vertices" { if (NF > 1) { print $2; exit } want = 1 }' "$f" ;;
    *) echo "?" ;;
  esac
}
count_of() {  # FILE: the first number of its header, or "-" when it is not there
  if [ -s "$1" ]; then header_count "$1"; else echo "-"; fi
}

# ---- one run: prints "STATUS SECONDS PEAK_KB CPU_SECONDS POINTS TETS" --------------------
# STATUS: ok, fail (nonzero exit; its last output line in $work/msg.TOOL.INDEX), timeout.
run_one() {  # TOOL (lifthull|tetgen) INPUT INDEX [MORE_SWITCHES]
  local tool="$1" in="$2" idx="$3" more="${4:-}" d base rc=0 t0 t1 kb cpu status msg
  d="$(mktemp -d "$work/run.XXXXXX")"
  base="$(basename "$in")"
  cp "$in" "$d/$base"
  local cmd=("$TETGEN" "-$switches$more" "$base")
  [ "$tool" = lifthull ] && cmd=("$LH" tetgen "-$switches" "$base")
  t0="$(date +%s%N)"
  (cd "$d" && /usr/bin/time -v -o "$d/time.txt" timeout --foreground -k 10 "$limit" "${cmd[@]}" >"$d/out.txt" 2>&1) || rc=$?
  t1="$(date +%s%N)"
  kb="$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$d/time.txt" 2>/dev/null || true)"
  cpu="$(awk -F': ' '/User time|System time/ { c += $2; n++ } END { if (n) printf "%.3f", c }' "$d/time.txt" 2>/dev/null || true)"
  status=ok
  if [ "$rc" = 124 ]; then
    status=timeout
    echo "timed out after $limit s" >"$work/msg.$tool.$idx"
  elif [ "$rc" != 0 ]; then
    status=fail
    msg="$(awk 'NF { last = $0 } END { print last }' "$d/out.txt")"
    echo "exit $rc: ${msg:-no message}" >"$work/msg.$tool.$idx"
  fi
  echo "$status $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", (b - a) / 1e9 }') ${kb:--} ${cpu:--}" \
    "$(count_of "$d/${base%.*}.1.node") $(count_of "$d/${base%.*}.1.ele")"
  rm -rf "$d"
}

# ---- the rounds --------------------------------------------------------------------------
names=() files=() notes=()
for f in "${inputs[@]}"; do
  if [ ! -f "$f" ]; then
    notes+=("skipped \`$f\`: not found")
    echo "run_tetgen: skipping $f: not found" >&2
    continue
  fi
  n="$(basename "$f")"
  names+=("${n%.*}") files+=("$f")
done
[ ${#files[@]} -gt 0 ] || { echo "run_tetgen: none of the inputs exists" >&2; exit 1; }

declare -A secs kbs cpus stat pts tets
start="$(date +%s)"
for ((r = 1; r <= rounds; r++)); do
  order=(lifthull tetgen)
  [ $((r % 2)) = 0 ] && order=(tetgen lifthull)
  for i in "${!files[@]}"; do
    for tool in "${order[@]}"; do
      key="$tool.$i"
      echo "run_tetgen: round $r/$rounds: $tool -$switches ${names[$i]}" >&2
      run_one "$tool" "${files[$i]}" "$i" >"$work/result"
      read -r s t k c p e <"$work/result"
      secs[$key]="${secs[$key]:-} $t"
      kbs[$key]="${kbs[$key]:-} $k"
      cpus[$key]="${cpus[$key]:-} $c"
      # a status or count that changes between rounds is shown as both
      [[ " ${stat[$key]:-} " == *" $s "* ]] || stat[$key]="${stat[$key]:+${stat[$key]} }$s"
      [[ "/${pts[$key]:-}/" == *"/$p/"* ]] || pts[$key]="${pts[$key]:+${pts[$key]}/}$p"
      [[ "/${tets[$key]:-}/" == *"/$e/"* ]] || tets[$key]="${tets[$key]:+${tets[$key]}/}$e"
    done
  done
done
# TetGen -M once per input: it then keeps coplanar facets apart, as lifthull always does
# (without -M it merges them and drops their common edges), so its Steiner count is for
# the same problem.
declare -A mpts
for i in "${!files[@]}"; do
  echo "run_tetgen: tetgen -${switches}M ${names[$i]}" >&2
  run_one tetgen "${files[$i]}" "m$i" M >"$work/result"
  read -r s t k c p e <"$work/result"
  mpts[$i]="$p"
  [ "$s" = ok ] || mpts[$i]="-"
done
elapsed=$(($(date +%s) - start))

# ---- the report ----------------------------------------------------------------------------
median() {  # the median of the numbers in $1 ("-" when none)
  tr ' ' '\n' <<<"$1" | grep -E '^[0-9.]+$' | sort -g |
    awk '{ a[NR] = $1 } END { if (!NR) print "-"; else printf "%.3f\n", (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }' || true
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.2f", a / b }'; }
steiner() {  # OUTPUT_POINTS INPUT_POINTS
  if [[ "$1" =~ ^[0-9]+$ ]] && [[ "$2" =~ ^[0-9]+$ ]]; then echo $(($1 - $2)); else echo "-"; fi
}
cell() { echo "${1//|/\\|}"; }  # Markdown-safe table cell

cache="$(dirname "$LH")/../CMakeCache.txt"  # the build lifthull came from, if any
cc="$(awk -F= '/^CMAKE_C_COMPILER:/ { print $2 }' "$cache" 2>/dev/null || true)"
btype="$(awk -F= '/^CMAKE_BUILD_TYPE:/ { print $2 }' "$cache" 2>/dev/null || true)"
ccver="$({ [ -n "$cc" ] && "$cc" --version 2>/dev/null | head -1; } || echo unknown)"
cpu="$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null || true)"
tgver="$(dpkg-query -W -f '${Version}' tetgen 2>/dev/null || echo unknown)"
mem="$(awk '/MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo 2>/dev/null || true)"

# the tables first (they count the bars met), then the report around them
tables="$work/tables.md"
tbar=0 mbar=0 nbar=0 sbar=0 nsbar=0 smbar=0 nmbar=0 fails=0
{
  echo "| input | input points | lifthull s | TetGen s | time ratio | lifthull CPU s | TetGen CPU s | lifthull peak MiB | TetGen peak MiB | memory ratio | the issue's bars (time, memory) |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  for i in "${!files[@]}"; do
    lsec="$(median "${secs[lifthull.$i]}")" tsec="$(median "${secs[tetgen.$i]}")"
    lk="$(median "${kbs[lifthull.$i]}")" tk="$(median "${kbs[tetgen.$i]}")"
    lm="$(awk -v k="$lk" 'BEGIN { if (k == "-") print "-"; else printf "%.1f", k / 1024 }')"
    tm="$(awk -v k="$tk" 'BEGIN { if (k == "-") print "-"; else printf "%.1f", k / 1024 }')"
    trat="-" mrat="-"  # ratios only of runs that both finished
    if [ "${stat[lifthull.$i]}" = ok ] && [ "${stat[tetgen.$i]}" = ok ]; then
      trat="$(ratio "$lsec" "$tsec")" mrat="$(ratio "$lk" "$tk")"
    fi
    [ "${stat[lifthull.$i]}" = ok ] || fails=$((fails + 1))
    bar="-"
    if [[ "$barred" == *" ${names[$i]} "* ]]; then
      nbar=$((nbar + 1))
      tok="$(awk -v r="$trat" 'BEGIN { print (r != "-" && r <= 1) ? "PASS" : "FAIL" }')"
      mok="$(awk -v r="$mrat" 'BEGIN { print (r != "-" && r <= 1) ? "PASS" : "FAIL" }')"
      [ "$tok" = PASS ] && tbar=$((tbar + 1))
      [ "$mok" = PASS ] && mbar=$((mbar + 1))
      bar="$tok, $mok"
      [ "${stat[lifthull.$i]}" = ok ] || bar="FAIL (lifthull: ${stat[lifthull.$i]})"
    fi
    lnote="" tnote=""
    [ "${stat[lifthull.$i]}" = ok ] || lnote=" (${stat[lifthull.$i]})"
    [ "${stat[tetgen.$i]}" = ok ] || tnote=" (${stat[tetgen.$i]})"
    echo "| ${names[$i]} | $(input_points "${files[$i]}") | $lsec$lnote | $tsec$tnote | $trat |" \
      "$(median "${cpus[lifthull.$i]}") | $(median "${cpus[tetgen.$i]}") | $lm | $tm | $mrat | $bar |"
  done
  echo
  echo "### Output: points, Steiner points, tetrahedra"
  echo
  echo "| input | input points | lifthull points | lifthull Steiner | lifthull tets | TetGen points | TetGen Steiner | TetGen tets | Steiner <= TetGen's | TetGen -M Steiner | Steiner <= TetGen -M's | lifthull's run |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---|---|"
  for i in "${!files[@]}"; do
    np="$(input_points "${files[$i]}")"
    lp="${pts[lifthull.$i]}" tp="${pts[tetgen.$i]}"
    lst="$(steiner "$lp" "$np")" tst="$(steiner "$tp" "$np")"
    sok="-"
    if [[ "$tst" =~ ^-?[0-9]+$ ]]; then
      nsbar=$((nsbar + 1)) sok=FAIL
      if [[ "$lst" =~ ^-?[0-9]+$ ]] && [ "$lst" -le "$tst" ]; then sok=PASS sbar=$((sbar + 1)); fi
    fi
    mst="$(steiner "${mpts[$i]}" "$np")" mok="-"
    if [[ "$mst" =~ ^-?[0-9]+$ ]]; then
      nmbar=$((nmbar + 1)) mok=FAIL
      if [[ "$lst" =~ ^-?[0-9]+$ ]] && [ "$lst" -le "$mst" ]; then mok=PASS smbar=$((smbar + 1)); fi
    fi
    how="ok"
    if [ "${stat[lifthull.$i]}" != ok ]; then
      how="${stat[lifthull.$i]}: \`$(cell "$(cat "$work/msg.lifthull.$i")")\`"
    fi
    if [ "${stat[tetgen.$i]}" != ok ]; then
      how="$how; TetGen ${stat[tetgen.$i]}: \`$(cell "$(cat "$work/msg.tetgen.$i")")\`"
    fi
    echo "| ${names[$i]} | $np | $lp | $lst | ${tets[lifthull.$i]} | $tp | $tst | ${tets[tetgen.$i]} | $sok | $mst | $mok | $how |"
  done
  echo
  echo "Per run (seconds, in round order):"
  echo
  for i in "${!files[@]}"; do
    echo "- ${names[$i]}: lifthull${secs[lifthull.$i]}; TetGen${secs[tetgen.$i]}"
  done
} >"$tables"

report="$work/report.md"
{
  echo "# 3D meshing benchmark: \`lifthull tetgen -$switches\` against TetGen 1.5"
  echo
  echo "Produced by \`bash bench/run_tetgen.sh${args[*]:+ ${args[*]}}\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "(git commit $commit; $rounds interleaved rounds, $elapsed s in all)."
  echo "Every run is a whole process on a copy of the input in its own temporary directory:"
  echo "reading the input, meshing, writing FILE.1.node/.ele/.face. Time: wall seconds (CPU:"
  echo "user + system); memory: peak resident set size (\`/usr/bin/time -v\`, the largest of"
  echo "the process and the \`timeout\` wrapper around it). Each cell is the median over the"
  echo "rounds, the tool order swapped every round. Ratios are lifthull / TetGen: at most 1.00"
  echo "means lifthull was as fast (as small) or better. Steiner points: output points - input"
  echo "points. This machine is shared and noisy: compare within a run. Source:"
  echo "bench/run_tetgen.sh."
  echo
  echo "- CPU: ${cpu:-unknown} ($(nproc) logical CPUs online), memory ${mem:-unknown}; load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "- OS: $(uname -srm)"
  echo "- lifthull: \`$LH\` ($("$LH" --version 2>/dev/null || echo unknown)), C compiler ${ccver:-unknown}, build type ${btype:-unknown}"
  echo "- TetGen: \`$TETGEN\` (Debian package tetgen $tgver), the same switches \`-$switches\`"
  echo "- time limit per run: $limit s"
  for n in "${notes[@]}"; do echo "- $n"; done
  echo
  echo "lifthull failed on $fails of ${#files[@]} inputs. The issue's bars on the $nbar of knot, bunny, fandisk,"
  echo "elephant and armadillo run here: time (lifthull no slower) met on $tbar, peak memory (no"
  echo "more) on $mbar; Steiner points no more than TetGen's on $sbar of $nsbar inputs, and no"
  echo "more than TetGen -M's (coplanar facets kept apart, as lifthull does) on $smbar of $nmbar."
  echo
  cat "$tables"
} >"$report"

# the report replaces $out in one rename: never a partial file there
mkdir -p "$(dirname "$out")"
part="$(mktemp "$(dirname "$out")/.bench-mesh3d.XXXXXX")"
trap 'rm -rf "$work" "$part"' EXIT
cp "$report" "$part"
chmod 644 "$part"
mv -f "$part" "$out"
cat "$out"
