#!/usr/bin/env bash
# compare_hull.sh LIFTHULL QCONVEX RBOX [QDELAUNAY]: the convex hull facets of
# `lifthull hull` equal `qconvex Qt i`'s (as sets of site-index sets) on
# general-position rbox sets in 2D-8D; with QDELAUNAY, also the furthest-site
# triangulation `lifthull delaunay -u` equals `qdelaunay Qu Qt i` in 2D-5D.
set -euo pipefail
lifthull="$1"; qconvex="$2"; rbox="$3"; qdelaunay="${4:-}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
canon() { tail -n +2 | awk '{ n = split($0, a, " "); for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }; s = a[1]; for (i = 2; i <= n; i++) s = s " " a[i]; print s }' | LC_ALL=C sort; }
status=0
for case in 2:3000 3:2000 4:800 5:300 6:120 7:60 8:40; do
  d="${case%%:*}"; n="${case##*:}"
  "$rbox" "$n" "D$d" t"$d" > "$tmp/p.txt"
  "$lifthull" hull "$tmp/p.txt" | canon > "$tmp/a"
  "$qconvex" Qt i < "$tmp/p.txt" | canon > "$tmp/b"
  if cmp -s "$tmp/a" "$tmp/b"; then
    echo "hull d=$d n=$n: $(wc -l < "$tmp/a") facets, lifthull == qconvex"
  else
    echo "hull d=$d n=$n: DIFFER ($(wc -l < "$tmp/a") vs qconvex $(wc -l < "$tmp/b"))"; status=1
  fi
done
if [ -n "$qdelaunay" ]; then
  for case in 2:1000 3:500 4:200 5:80; do
    d="${case%%:*}"; n="${case##*:}"
    "$rbox" "$n" "D$d" t"$((d + 10))" > "$tmp/p.txt"
    "$lifthull" delaunay -u "$tmp/p.txt" | canon > "$tmp/a"
    "$qdelaunay" Qu Qt i < "$tmp/p.txt" | canon > "$tmp/b"
    if cmp -s "$tmp/a" "$tmp/b"; then
      echo "furthest-site d=$d n=$n: $(wc -l < "$tmp/a") simplices, lifthull == qdelaunay Qu"
    else
      echo "furthest-site d=$d n=$n: DIFFER ($(wc -l < "$tmp/a") vs qdelaunay $(wc -l < "$tmp/b"))"; status=1
    fi
  done
fi
exit "$status"
