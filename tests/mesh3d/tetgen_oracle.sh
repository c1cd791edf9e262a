#!/usr/bin/env bash
# tetgen_oracle.sh PYTHON DATA_DIR TETGEN_CHECK: TetGen's own meshes (-pQ, -pQe) of a
# few small PLCs (tests/data/tetgen) pass the independent checker check_tetmesh.py,
# with the input surface's volume for the OFF files, and lh_tetmesh_check (through
# tetgen_check; with -pQ, whose .edge holds the subsegments, also conformity to the
# OFF input, which TetGen's merging of coplanar facets breaks on cubes.off); then each mutation of a mesh (an inverted tet, a duplicated tet, a
# subface dropped, a subface that is no face, an edge that is no edge) fails both
# with their messages. Skipped (77) without tetgen.
set -u
py=$1 data=$2 cchk=$3
here=$(cd "$(dirname "$0")" && pwd)
chk="$py $here/check_tetmesh.py"
command -v tetgen >/dev/null || { echo "tetgen not installed: skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() { # expect WANT_RC WANT_TEXT CMD...: the command's exit status and its output line
    local rc=$1 want=$2; shift 2
    local out; out=$("$@" 2>&1); local got=$?
    if [ "$got" != "$rc" ] || [ "${out#*"$want"}" = "$out" ]; then
        echo "FAIL: $* -> $got '$out' (want $rc '$want')"; fail=1
    else
        echo "ok: $out"
    fi
}
for f in cubes.off star.off wedge-5.smesh; do
    cp "$data/$f" "$tmp/"
    for sw in -pQ -pQe; do
        (cd "$tmp" && tetgen $sw "$f" >/dev/null) || { echo "FAIL: tetgen $sw $f"; fail=1; continue; }
        base=$tmp/${f%.*}.1
        if [ "${f##*.}" = off ]; then
            expect 0 "valid:" $chk "$base" --input "$tmp/$f"
        else
            expect 0 "valid:" $chk "$base"
        fi
        expect 0 "valid (off_exact 0)" "$cchk" "$base"
        # conformity to the OFF input; TetGen -p merges coplanar triangles (cubes.off's
        # squares), dropping their shared edge: not a union of subsegments
        case $sw$f in
        -pQstar.off) expect 0 "valid (off_exact 0)" "$cchk" "$base" "$tmp/$f" ;;
        -pQcubes.off) expect 1 "segment 2 (4 6) is not covered: its chain of subsegments from 4 stops at 4" \
                          "$cchk" "$base" "$tmp/$f" ;;
        esac
    done
done
# mutations of star.1 (written with -pQe last): each must fail
b=$tmp/star.1
mut() { cp "$b.node" "$tmp/m.node"; cp "$b.ele" "$tmp/m.ele"; cp "$b.face" "$tmp/m.face"; cp "$b.edge" "$tmp/m.edge"; }
mut; awk 'NR==2 { t=$4; $4=$5; $5=t } { print }' "$b.ele" > "$tmp/m.ele"
expect 1 "has orientation < 0 (inverted)" $chk "$tmp/m"
expect 1 "has orient_3 < 0 (inverted)" "$cchk" "$tmp/m"
mut; awk 'NR==1 { $1=$1+1 } { print } NR==2 { line=$0 } END { sub(/^ *[0-9]+/, "999", line); print line }' "$b.ele" > "$tmp/m.ele"
expect 1 "are the same tet" $chk "$tmp/m"
expect 1 "are the same tet" "$cchk" "$tmp/m"
mut; awk 'NR==1 { $1=$1-1 } NR!=2 { print }' "$b.face" > "$tmp/m.face"
expect 1 "is not a subface" $chk "$tmp/m"
expect 1 "is not a subface" "$cchk" "$tmp/m"
expect 0 "valid:" $chk "$tmp/m" --boundary-free
mut; awk 'NR==2 { $3=$2 } { print }' "$b.face" > "$tmp/m.face"
expect 1 "is not a face of a tet" $chk "$tmp/m"
expect 1 "is not a face of a tet" "$cchk" "$tmp/m"
mut; awk 'NR==2 { $3=$2 } { print }' "$b.edge" > "$tmp/m.edge"
expect 1 "is not an edge of a tet" $chk "$tmp/m"
expect 1 "is not an edge of a tet" "$cchk" "$tmp/m"
# the volume against the input: the star's mesh checked against the cubes' surface
expect 1 "differs from the input surface's" $chk "$b" --input "$tmp/cubes.off"
exit $fail
