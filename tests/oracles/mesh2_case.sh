#!/usr/bin/env bash
# mesh2_case.sh: one 2D meshing check (issue #7) — runs the mesher under test and the
# references on one input in a scratch directory, then compare_mesh2.py on the outputs.
#
#   mesh2_case.sh --tool 'CMD' --triangle 'node .../triangle_run.mjs' --cgal ORACLE
#                 [--python PY] [--keep DIR] [--convex] MODE INPUT
#
# --tool is the mesher under test, run as `CMD -SWITCHES FILE.poly` writing FILE.1.node/.ele
# beside FILE.poly, as Triangle does (e.g. 'lifthull triangle'; the Triangle oracle itself to
# validate this harness). INPUT: a .poly (with its .node when it lists no vertex), JSON rings or
# a .edg file; the last two are first written as a .poly whose hole points give Triangle's rule
# the even-odd domain (oracle_cgal_cdt cdt --poly).
#
# --convex keeps the convex hull (Triangle's -c, added to every switch set; CGAL --convex), for
# inputs whose segments enclose nothing, such as box.poly.
#
# MODE
#   cdt         CMD -pQ against CGAL's CDT_2 of the domain: the same triangles
#   q30         CMD -pq30Q against Triangle -pq30Q: angles >= 30 but at small input angles,
#               segments kept, holes empty, area, triangle count <= 1.15 x Triangle's
#   cgal20.7    CMD -pq20.7Q against CGAL Mesh_2 (B = 0.125, 20.7 degrees): the same checks,
#               triangle count <= 1.0 x CGAL's
# Exit status: compare_mesh2.py's (0 pass, 1 a check failed, 2 bad input), or 2 if a tool
# failed.
set -euo pipefail

tool="" triangle="" cgal="" python="python3" keep="" c="" convex="" ratio=""
while [ $# -gt 2 ]; do
  case "$1" in
    --tool) tool="$2"; shift 2 ;;
    --triangle) triangle="$2"; shift 2 ;;
    --cgal) cgal="$2"; shift 2 ;;
    --python) python="$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    --convex) c=c; convex=--convex; shift ;;
    --ratio) ratio="$2"; shift 2 ;;  # the count bar instead of the mode's (a known gap)
    *) echo "mesh2_case.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[ $# -eq 2 ] && [ -n "$tool" ] && [ -n "$cgal" ] || {
  echo "usage: mesh2_case.sh --tool CMD --triangle CMD --cgal ORACLE [--python PY] [--keep DIR] cdt|q30|cgal20.7 INPUT" >&2
  exit 2
}
mode="$1" input="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
compare="$here/compare_mesh2.py"

if [ -n "$keep" ]; then work="$keep"; mkdir -p "$work"; else
  work="$(mktemp -d "${TMPDIR:-/tmp}/mesh2.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi

name="$(basename "$input")"
stem="${name%.*}"
# Triangle's output name: FILE.1, or FILE.(n+1) for FILE.n
if [[ "$stem" =~ ^(.+)\.([0-9]+)$ ]]; then out="${BASH_REMATCH[1]}.$((BASH_REMATCH[2] + 1))"; else out="$stem.1"; fi
run() {  # run a tool, its output shown only if it fails
  local log="$work/log.$$"
  if ! "$@" >"$log" 2>&1; then
    cat "$log" >&2
    echo "mesh2_case.sh: FAILED: $*" >&2
    exit 2
  fi
}

# the .poly every tool reads, one copy per tool directory
mkdir -p "$work/tool" "$work/ref"
case "$name" in
  *.poly)
    for d in tool ref; do
      cp "$input" "$work/$d/$stem.poly"
      [ -f "${input%.poly}.node" ] && cp "${input%.poly}.node" "$work/$d/$stem.node"
    done ;;
  *.json|*.edg)
    run "$cgal" cdt --poly "$work/tool/$stem.poly" "$input"
    cp "$work/tool/$stem.poly" "$work/ref/$stem.poly" ;;
  *) echo "mesh2_case.sh: INPUT must be .poly, .json or .edg" >&2; exit 2 ;;
esac

case "$mode" in
  cdt)
    run $tool -p${c}Q "$work/tool/$stem.poly"
    run "$cgal" cdt $convex --write "$work/ref/$stem.cgal" "$input"
    exec "$python" "$compare" cdt "$input" "$work/tool/$out" "$work/ref/$stem.cgal" ;;
  q30)
    [ -n "$triangle" ] || { echo "mesh2_case.sh: q30 needs --triangle" >&2; exit 2; }
    run $tool -p${c}q30Q "$work/tool/$stem.poly"
    run $triangle -p${c}q30Q "$work/ref/$stem.poly"
    exec "$python" "$compare" quality $convex --angle 30 --ratio "${ratio:-1.15}" "$input" "$work/tool/$out" "$work/ref/$out" ;;
  cgal20.7)
    run $tool -p${c}q20.7Q "$work/tool/$stem.poly"
    run "$cgal" mesh $convex --write "$work/ref/$stem.cgal" "$input"
    exec "$python" "$compare" quality $convex --angle 20.7 --ratio "${ratio:-1.0}" "$input" "$work/tool/$out" "$work/ref/$stem.cgal" ;;
  *) echo "mesh2_case.sh: MODE must be cdt, q30 or cgal20.7" >&2; exit 2 ;;
esac
