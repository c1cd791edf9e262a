#!/usr/bin/env bash
# lifthull_oracle.sh PYTHON LIFTHULL TETGEN_CHECK DATA_DIR: lifthull's own meshes
# (tetgen -pQfe and -pYQfe) of the OFF models in DATA_DIR pass the independent checker
# check_tetmesh.py and lh_tetmesh_check (through tetgen_check, with conformity to the
# OFF input), and agree. For the models whose facets are planar the checker also
# compares the tets' volume with the input surface's, every number read as the double
# the programs hold (--doubles): equal exactly when the mesh's boundary is exactly the
# input's, Steiner points and all. mpi.off and double-torus-example.off have facets
# that are not planar, whose surface the checker would triangulate its own way.
set -u
py=$1 lh=$2 cchk=$3 data=$4
chk="$py $(cd "$(dirname "$0")" && pwd)/check_tetmesh.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() { # expect WANT_TEXT CMD...: exit status 0 and the output holding WANT_TEXT
    local want=$1; shift
    local out; out=$("$@" 2>&1); local got=$?
    if [ "$got" != 0 ] || [ "${out#*"$want"}" = "$out" ]; then
        echo "FAIL: $* -> $got '$out' (want '$want')"; fail=1
    else
        echo "ok: $out"
    fi
}
for f in schonhardt blob-closed eight hole joint part pipe u step mpi double-torus-example; do
    cp "$data/$f.off" "$tmp/"
    for sw in -pQfe -pYQfe; do
        (cd "$tmp" && "$lh" tetgen $sw "$f.off") || { echo "FAIL: lifthull tetgen $sw $f.off"; fail=1; continue; }
        case $f in
        mpi | double-torus-example) expect "valid:" $chk "$tmp/$f.1" --doubles ;;
        *) expect "valid:" $chk "$tmp/$f.1" --doubles --input "$tmp/$f.off" ;;
        esac
        expect "valid (off_exact 0)" "$cchk" "$tmp/$f.1" "$tmp/$f.off"
    done
done
exit $fail
