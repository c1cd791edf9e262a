#!/usr/bin/env bash
# gen_points.sh [--rbox RBOX] OUTDIR [DIM:COUNT:SEED[:s] ...]
#
# Writes the point sets of the Delaunay cross-checks, in Qhull's input format (first line
# "DIM rbox ..." -- the text after the dimension is a comment --, second line COUNT, then one
# point per line); the seed makes the output deterministic. For each case:
#   DIM:COUNT:SEED    OUTDIR/d<DIM>_n<COUNT>_t<SEED>.txt = `rbox COUNT D<DIM> t<SEED>`:
#                     uniform in the cube [-0.5, 0.5]^DIM. Uniform random doubles are in general
#                     position with probability 1, which qdelaunay needs to be an oracle.
#   DIM:COUNT:SEED:s  OUTDIR/d<DIM>_n<COUNT>_t<SEED>_s.txt = `rbox COUNT s D<DIM> t<SEED>`:
#                     on the sphere of radius 0.5 up to rounding, so nearly cospherical. For the
#                     sets the tests use, an exact check found no interior facet whose d+2
#                     points are exactly cospherical, so the Delaunay triangulation is unique,
#                     but only exact code finds it: qdelaunay does not (use
#                     compare_delaunay.sh --no-qhull on these).
#
# Without cases, writes the default list (the one tests/oracles/CMakeLists.txt uses).
# Prints the written paths, one per line.
set -euo pipefail

rbox=rbox
if [[ ${1-} == --rbox ]]; then
  rbox=$2
  shift 2
fi
if [[ $# -lt 1 ]]; then
  echo "usage: gen_points.sh [--rbox RBOX] OUTDIR [DIM:COUNT:SEED ...]" >&2
  exit 2
fi
outdir=$1
shift
cases=("$@")
if [[ ${#cases[@]} -eq 0 ]]; then
  cases=(2:2000:1 2:2000:2 2:2000:3 3:2000:1 3:2000:2 4:500:1 4:500:2 5:200:1 5:200:2 6:80:1 6:80:2
         7:40:1 7:40:2 8:30:1 8:30:2 2:2000:1:s 3:1000:1:s 4:300:1:s)
fi

mkdir -p "$outdir"
for c in "${cases[@]}"; do
  IFS=: read -r d n s dist <<<"$c"
  if ! [[ $d =~ ^[0-9]+$ && $n =~ ^[0-9]+$ && $s =~ ^[0-9]+$ && ( -z $dist || $dist == s ) ]]; then
    echo "gen_points.sh: bad case '$c' (want DIM:COUNT:SEED or DIM:COUNT:SEED:s)" >&2
    exit 2
  fi
  f=$outdir/d${d}_n${n}_t${s}${dist:+_$dist}.txt
  # Write to a temporary name first: a test never sees a half-written file.
  "$rbox" "$n" $dist "D$d" "t$s" >"$f.tmp"
  # rbox's own header is "DIM rbox ARGS" then COUNT: check it before trusting the file.
  read -r hd _ <"$f.tmp"
  hn=$(sed -n 2p "$f.tmp")
  lines=$(wc -l <"$f.tmp")
  if [[ $hd != "$d" || $hn != "$n" || $lines -ne $((n + 2)) ]]; then
    echo "gen_points.sh: rbox output for '$c' is not $n points of dimension $d" >&2
    exit 1
  fi
  mv "$f.tmp" "$f"
  echo "$f"
done
