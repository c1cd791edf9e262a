#!/usr/bin/env bash
# compare_delaunay.sh [options] LIFTHULL FILE...
#
# Cross-checks `LIFTHULL delaunay FILE` against the oracles on each point FILE (Qhull input
# format, e.g. rbox output) and exits 0 iff, for every file, all the simplex sets are identical.
#
#   lifthull  LIFTHULL delaunay FILE            (LIFTHULL=none skips it: oracles only)
#   cgal      oracle_cgal_delaunay --validate FILE       (d = 2, 3: Delaunay_triangulation_2/_3)
#   cgal_dd   oracle_cgal_delaunay --validate --dd FILE  (any d: Delaunay_triangulation<Epick_d>)
#   qhull     qdelaunay Qt i < FILE
#   tetgen    tetgen -Q -N -F -z on a 0-based .node copy of FILE (d = 3, with --with-tetgen)
#
# Each output is put in canonical form (canon.py: indices sorted in each simplex, simplices
# sorted) and the canonical forms are compared byte for byte. Per file it prints one line
#   compare: d=3 n=2000 simplices=13085 lifthull==cgal==cgal_dd==qhull==tetgen (FILE)
# and a line of wall-clock times; on a mismatch, the groups of agreeing producers, which
# producers disagree with the majority (ties go to a group without lifthull), the first
# simplices only in one side of each disagreement, and the verdict of exact_check.py (exact
# local Delaunay and hull test, at most 2,000 interior and 2,000 boundary facets) on one output
# of each group. --validate makes CGAL run is_valid(), which checks with exact predicates that
# every interior facet is locally Delaunay; with LIFTHULL=none a file where only one oracle
# applies (d >= 4 with --no-qhull) passes on that check alone.
#
# Options (anywhere on the line):
#   --with-tetgen     also run TetGen on d = 3 files (ignored for other d)
#   --no-qhull        skip qdelaunay (it is not an oracle on degenerate or cospherical input)
#   --no-dd           skip the dD CGAL triangulation
#   --cgal PATH       oracle_cgal_delaunay (default: $LH_CGAL_ORACLE, then PATH, then
#                     build-xcheck/ or build/ next to the source tree)
#   --qdelaunay PATH, --tetgen PATH, --python PATH   the tools (default: from PATH)
#   --keep DIR        keep raw and canonical outputs in DIR/<file name>/ (default: temporary)
#   --max K           show at most K differing simplices per side (default 10)
#
# Environment: LH_XCHECK_LIFTHULL, if set, replaces LIFTHULL (e.g. LH_XCHECK_LIFTHULL=none
# ctest -L oracle checks the oracles against each other only).
#
# Exit status: 0 all identical; 1 some mismatch; 2 a tool failed or bad usage.
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
canon=$here/canon.py

cgal=${LH_CGAL_ORACLE-}
qdelaunay=qdelaunay
tetgen=tetgen
python=python3
with_tetgen=0
use_qhull=1
use_dd=1
keep=
maxk=10
pos=()

usage() { awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case $1 in
    --with-tetgen) with_tetgen=1 ;;
    --no-qhull) use_qhull=0 ;;
    --no-dd) use_dd=0 ;;
    --cgal) cgal=${2?}; shift ;;
    --qdelaunay) qdelaunay=${2?}; shift ;;
    --tetgen) tetgen=${2?}; shift ;;
    --python) python=${2?}; shift ;;
    --keep) keep=${2?}; shift ;;
    --max) maxk=${2?}; shift ;;
    -h|--help) usage ;;
    -*) echo "compare_delaunay.sh: unknown option $1" >&2; usage ;;
    *) pos+=("$1") ;;
  esac
  shift
done
[[ ${#pos[@]} -ge 2 ]] || usage
lifthull=${pos[0]}
files=("${pos[@]:1}")
if [[ -n ${LH_XCHECK_LIFTHULL-} ]]; then
  echo "compare: LH_XCHECK_LIFTHULL=$LH_XCHECK_LIFTHULL replaces $lifthull"
  lifthull=$LH_XCHECK_LIFTHULL
fi

die() { echo "compare_delaunay.sh: $*" >&2; exit 2; }

if [[ -z $cgal ]]; then
  if command -v oracle_cgal_delaunay >/dev/null 2>&1; then
    cgal=$(command -v oracle_cgal_delaunay)
  else
    for b in build-xcheck build; do
      c=$here/../../$b/tests/oracles/oracle_cgal_delaunay
      if [[ -x $c ]]; then cgal=$c; break; fi
    done
  fi
fi
[[ -n $cgal && -x $cgal ]] || die "oracle_cgal_delaunay not found (use --cgal PATH)"
if [[ $lifthull != none && ! -x $lifthull ]]; then die "lifthull binary '$lifthull' is not executable"; fi
command -v "$python" >/dev/null 2>&1 || die "python '$python' not found"
if [[ $use_qhull == 1 ]]; then
  qdelaunay=$(command -v "$qdelaunay") || die "qdelaunay not found (use --qdelaunay or --no-qhull)"
fi
if [[ $with_tetgen == 1 ]]; then
  tetgen=$(command -v "$tetgen") || die "tetgen not found"
  tetgen=$(cd "$(dirname "$tetgen")" && pwd)/$(basename "$tetgen")  # we run it from a temp dir
fi

now() { date +%s.%N; }

# run_tool NAME WORK COMMAND...: runs COMMAND with stdout to WORK/NAME.raw and stderr to
# WORK/NAME.err, appends its time to `times`; on failure prints the error and returns 1.
run_tool() {
  local name=$1 work=$2
  shift 2
  local t0 t1 rc
  t0=$(now)
  "$@" >"$work/$name.raw" 2>"$work/$name.err"
  rc=$?
  t1=$(now)
  times+=("$name $(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.3fs", b-a}')")
  if [[ $rc -ne 0 ]]; then
    echo "  $name FAILED: exit status $rc; its stderr ends with:"
    tail -n 5 "$work/$name.err" | sed 's/^/    /'
    return 1
  fi
}

run_tetgen() {
  local work=$1
  "$python" "$canon" node "$file" "$work/pts.node" || return 1
  (cd "$work" && "$tetgen" -Q -N -F -z pts.node >&2) || return 1
  cat "$work/pts.1.ele"
}

# canonicalize NAME WORK FORMAT: WORK/NAME.raw -> WORK/NAME.canon
canonicalize() {
  local name=$1 work=$2 fmt=$3
  if ! "$python" "$canon" canon --format "$fmt" --width $((d + 1)) "$work/$name.raw" \
      >"$work/$name.canon" 2>"$work/$name.cerr"; then
    echo "  $name FAILED: malformed output:"
    sed 's/^/    /' "$work/$name.cerr"
    return 1
  fi
}

status=0
tmproot=
cleanup() { [[ -n $tmproot ]] && rm -rf "$tmproot"; }
trap cleanup EXIT

for file in "${files[@]}"; do
  [[ -r $file ]] || { echo "compare: FAIL cannot read $file"; status=2; continue; }
  if [[ -n $keep ]]; then
    work=$keep/$(basename "$file")
    rm -rf "$work"
    mkdir -p "$work"
  else
    [[ -n $tmproot ]] || tmproot=$(mktemp -d "${TMPDIR:-/tmp}/lh_compare.XXXXXX")
    work=$tmproot/$(basename "$file")
    mkdir -p "$work"
  fi
  hdr=$("$python" "$canon" header "$file" 2>&1) || {
    echo "compare: FAIL cannot read the points of $file: $hdr"
    status=2
    continue
  }
  read -r d n <<<"$hdr"

  names=()
  times=()
  failed=0
  failed_names=()
  try() {  # try NAME FORMAT COMMAND...
    local name=$1 fmt=$2
    shift 2
    if run_tool "$name" "$work" "$@" && canonicalize "$name" "$work" "$fmt"; then
      names+=("$name")
    else
      failed=1
      failed_names+=("$name")
    fi
  }
  if [[ $lifthull != none ]]; then try lifthull i "$lifthull" delaunay "$file"; fi
  if [[ $d == 2 || $d == 3 ]]; then try cgal i "$cgal" --validate "$file"; fi
  if [[ $use_dd == 1 ]]; then try cgal_dd i "$cgal" --validate --dd "$file"; fi
  if [[ $use_qhull == 1 ]]; then try qhull i sh -c '"$0" Qt i <"$1"' "$qdelaunay" "$file"; fi
  if [[ $with_tetgen == 1 && $d == 3 ]]; then try tetgen ele run_tetgen "$work"; fi

  fail_note=
  if [[ $failed == 1 ]]; then
    status=2
    fail_note=" FAILED: $(IFS=,; echo "${failed_names[*]}");"
  fi
  if [[ ${#names[@]} -eq 1 && $lifthull == none && $failed == 0 && ${names[0]} == cgal* ]]; then
    echo "compare: d=$d n=$n simplices=$(wc -l <"$work/${names[0]}.canon" | tr -d ' ') ${names[0]}" \
         "(the only oracle here; CGAL is_valid passed) ($(basename "$file"))"
    echo "  times: ${times[*]}"
    continue
  fi
  if [[ ${#names[@]} -lt 2 ]]; then
    echo "compare: d=$d n=$n$fail_note fewer than two results to compare ($(basename "$file"))"
    status=2
    echo "  times: ${times[*]}"
    continue
  fi

  # Group the producers by identical canonical output, in order of first appearance.
  groups=()   # each: "name==name==..."
  reps=()     # a representative name per group
  for nm in "${names[@]}"; do
    placed=0
    for i in "${!reps[@]}"; do
      if cmp -s "$work/${reps[$i]}.canon" "$work/$nm.canon"; then
        groups[$i]="${groups[$i]}==$nm"
        placed=1
        break
      fi
    done
    if [[ $placed == 0 ]]; then
      groups+=("$nm")
      reps+=("$nm")
    fi
  done
  count_of() { wc -l <"$work/$1.canon" | tr -d ' '; }

  if [[ ${#groups[@]} -eq 1 ]]; then
    echo "compare: d=$d n=$n$fail_note simplices=$(count_of "${reps[0]}") ${groups[0]} ($(basename "$file"))"
  else
    # The reference group: the largest; on a tie, one holding an oracle, earliest first.
    best=0
    best_score=-1
    for i in "${!groups[@]}"; do
      members=$(tr -cd '=' <<<"${groups[$i]}" | wc -c)
      size=$((members / 2 + 1))
      oracle=1
      [[ "==${groups[$i]}==" == *==lifthull==* ]] && oracle=0
      score=$((size * 2 + oracle))
      if [[ $score -gt $best_score ]]; then best=$i; best_score=$score; fi
    done
    line="compare: d=$d n=$n$fail_note MISMATCH ${groups[$best]}($(count_of "${reps[$best]}"))"
    disagree=()
    for i in "${!groups[@]}"; do
      [[ $i == "$best" ]] && continue
      line+=" != ${groups[$i]}($(count_of "${reps[$i]}"))"
      disagree+=("${groups[$i]//==/,}")
    done
    echo "$line ($(basename "$file"))"
    echo "  disagreeing with ${groups[$best]}: $(IFS=,; echo "${disagree[*]}")"
    for i in "${!groups[@]}"; do
      [[ $i == "$best" ]] && continue
      "$python" "$canon" diff "${reps[$best]}" "$work/${reps[$best]}.canon" \
        "${reps[$i]}" "$work/${reps[$i]}.canon" --max "$maxk"
    done
    # Who is right? An exact, oracle-free local Delaunay check of one output per group.
    for i in "${!groups[@]}"; do
      r=$work/${reps[$i]}
      { count_of "${reps[$i]}"; cat "$r.canon"; } >"$r.i"  # `i` format, also for TetGen's
      echo "  exact check of ${reps[$i]}: $("$python" "$here/exact_check.py" --limit 2000 \
        "$file" "$r.i" 2>&1 | tail -n 1)"
    done
    [[ -z $keep ]] || echo "  outputs kept in $work"
    [[ $status == 2 ]] || status=1
  fi
  echo "  times: ${times[*]}"
done
exit $status
