#!/bin/bash
# outputs.sh LIFTHULL DATA — the output files of every command (cli/outfile.h): all
# targets checked before the input is read; a set of files (.node .ele .neigh ...)
# written whole, together or not at all; no temporary file left after a failure; a
# file replaced with -f keeps its mode; binary and ASCII .vtu. Signals and progress:
# tests/cli/outputs_slow.sh. DATA: tests/data/triangle.
source "$(dirname "$0")/harness.sh"

printf '2\n5\n0 0\n1 0\n0 1\n1 1\n0.5 0.5\n' > p.txt
"$lh" points --grid 30 -d 2 -o g.txt
awk 'NR == 1 { next } NR == 2 { print $1, 2, 0, 0; next } { print NR - 2, $1, $2 }' g.txt > grid.node
cp "$data/A.poly" .
notemp() { local t; t=$(find . -name '*.tmp??????'); [ -z "$t" ] && ok || bad "$1: temporaries left: $t"; }
content() { same "$1" "$(head -c 20 "$2")" "$3"; }
old() { for f in "$@"; do echo OLD > "$f"; done; }

# ---- a set of files: every target checked before anything is written --------------
old m.ele
expect "delaunay .node, .ele exists" 1 "'m.ele' exists \(use -f" '' -- "$lh" delaunay p.txt -o m.node
absent m.node m.neigh; content "the old .ele" m.ele OLD; notemp "exists"
rm -f m.*; old m.node m.ele; mkdir m.neigh
expect "delaunay -f, .neigh a directory" 1 "'m.neigh' is a directory" '' -- "$lh" delaunay p.txt -o m.node -f
content ".node untouched" m.node OLD; content ".ele untouched" m.ele OLD; notemp "directory"
rmdir m.neigh; rm -f m.*
expect "delaunay .node set" 0 '' '' -- "$lh" delaunay p.txt -o m.node
same "the three files" "$(head -qn1 m.node m.ele m.neigh | tr -s ' ' | tr '\n' '/')" "5 2 0 0/4 3 0/4 3/"

# A write that fails on the second file (here: the file size limit, as a full disk
# would) leaves every old file: without the set, m.node was new beside the old m.ele.
old m.node m.ele m.neigh
(trap '' XFSZ; ulimit -f 20; "$lh" delaunay g.txt -o m.node -f > out.txt 2> err.txt; echo $? > rc.txt)
same "delaunay, file too large: exit" "$(cat rc.txt)" 1
matches err.txt "cannot write 'm.ele': File too large" && ok || bad "message: $(cat err.txt)"
for f in m.node m.ele m.neigh; do content "$f untouched" $f OLD; done; notemp "delaunay EFBIG"
old grid.1.node grid.1.ele
(trap '' XFSZ; ulimit -f 20; "$lh" triangle grid.node > out.txt 2> err.txt; echo $? > rc.txt)
same "triangle, file too large: exit" "$(cat rc.txt)" 1
content "triangle .node untouched" grid.1.node OLD; content "triangle .ele untouched" grid.1.ele OLD
notemp "triangle EFBIG"
expect "triangle replaces both" 0 '' 'grid.1: 900 points' -- "$lh" triangle grid.node
same "triangle .node" "$(head -n1 grid.1.node | tr -s ' ')" "900 2 0 1"
mkdir A.1.poly
expect "triangle, .poly a directory" 1 "'A.1.poly' is a directory" '' -- "$lh" triangle -pq30 A.poly
absent A.1.node A.1.ele; rmdir A.1.poly
rm -f m.*; mkdir m.ele
expect "mesh -o .node, .ele a directory" 1 "'m.ele' is a directory" '' -- "$lh" mesh A.poly -o m.node -f
rmdir m.ele; rm -f m.*

# ---- arguments checked before the input is read (no.txt does not exist) ------------
expect "-o ''" 1 "the output file name is empty" '' -- "$lh" delaunay no.txt -o ''
expect "-o missing directory" 1 "cannot create 'nodir/x.vtu': No such file or directory" '' -- \
  "$lh" delaunay no.txt -o nodir/x.vtu
mkdir d.vtu d.off d.txt d.node
expect "delaunay -o dir" 1 "'d.vtu' is a directory" '' -- "$lh" delaunay no.txt -o d.vtu -f
expect "voronoi -o dir" 1 "'d.txt' is a directory" '' -- "$lh" voronoi no.txt -o d.txt
expect "hull -o dir" 1 "'d.off' is a directory" '' -- "$lh" hull no.txt -o d.off
expect "locate -o dir" 1 "'d.txt' is a directory" '' -- "$lh" locate no.txt no.txt -o d.txt
expect "interpolate -o dir" 1 "'d.txt' is a directory" '' -- "$lh" interpolate no.txt no.txt -o d.txt
expect "points -o dir" 1 "'d.txt' is a directory" '' -- "$lh" points 10 -o d.txt
expect "qconvex TO dir" 1 "'d.txt' is a directory" '' -- "$lh" qconvex i TI no.txt TO d.txt
expect "qhalf TO dir" 1 "'d.txt' is a directory" '' -- "$lh" qhalf Fp TI no.txt TO d.txt
expect "mesh -o dir" 1 "'d.vtu' is a directory" '' -- "$lh" mesh no.poly -o d.vtu
expect "mesh -o .node set" 1 "'d.node' is a directory" '' -- "$lh" mesh no.poly -o d.ele
expect "triangle -I: .node a directory" 1 "'d.node' is a directory" '' -- "$lh" triangle -I d.poly
expect "delaunay -o exists" 1 "'p.txt' is the input file" '' -- "$lh" delaunay p.txt -o p.txt -f
rmdir d.vtu d.off d.txt d.node

# ---- -f keeps the replaced file's mode --------------------------------------------
old ro.vtu; chmod 444 ro.vtu
expect "-f on a read-only file" 0 '' '' -- "$lh" delaunay p.txt -o ro.vtu -f
same "mode kept" "$(stat -c %a ro.vtu)" 444
matches ro.vtu "<VTKFile" && ok || bad "ro.vtu not replaced"
old rx.txt; chmod 751 rx.txt
expect "-f on a 751 file" 0 '' '' -- "$lh" points 5 -o rx.txt -f
same "mode 751 kept" "$(stat -c %a rx.txt)" 751
(umask 027; "$lh" points 5 -o new.txt)
same "a new file: 0666 less the umask" "$(stat -c %a new.txt)" 640

# ---- .vtu: binary by default (base64 inline), --ascii as text; the same mesh --------
"$lh" points 300 -d 3 -o c3.txt
expect "delaunay -o vtu" 0 '' '' -- "$lh" delaunay c3.txt -o b.vtu
expect "delaunay -o vtu --ascii" 0 '' '' -- "$lh" delaunay c3.txt -o a.vtu --ascii
grep -q 'format="binary"' b.vtu && ! grep -q 'format="ascii"' b.vtu && ok || bad "b.vtu is not binary"
grep -q 'header_type="UInt64"' b.vtu && ok || bad "b.vtu: no header_type"
grep -q 'format="binary"' a.vtu && bad "a.vtu is not ASCII" || ok
expect "mesh --attributes -o vtu" 0 '' '' -- "$lh" mesh "$data/la.poly" --attributes -o la.vtu -q
expect "mesh --attributes -o vtu --ascii" 0 '' '' -- "$lh" mesh "$data/la.poly" --attributes -o la-a.vtu -q --ascii
py=; for p in ${LH_PYTHON:-} python3 /usr/bin/python3; do
  command -v "$p" > /dev/null && "$p" -c "import meshio" 2> /dev/null && { py=$p; break; }; done
if [ -n "$py" ]; then
  # meshio reads both, and they hold exactly the same points, cells and fields
  "$py" - <<'PY' && ok || bad "binary and ASCII .vtu differ (meshio)"
import meshio, numpy as np
for b, a, fields in (("b.vtu", "a.vtu", ["neighbors"]), ("la.vtu", "la-a.vtu", ["neighbors", "region"])):
    mb, ma = meshio.read(b), meshio.read(a)
    assert mb.points.shape[0] > 0 and np.array_equal(mb.points, ma.points), b
    assert len(mb.cells) == 1 and np.array_equal(mb.cells[0].data, ma.cells[0].data), b
    for f in fields:
        assert np.array_equal(mb.cell_data[f][0], ma.cell_data[f][0]), (b, f)
mb = meshio.read("la.vtu")
assert sorted(set(mb.cell_data["region"][0].tolist())) == [0, 0.05, 0.2, 0.4, 0.8, 3], "regions"
assert np.array_equal(mb.point_data["marker"], meshio.read("la-a.vtu").point_data["marker"]), "markers"
PY
else
  echo "meshio not found: the binary .vtu read-back skipped (Debian: python3-meshio)"
fi
# VTK's own reader (ParaView's), where Python has it (Debian: python3-vtk9)
py=; for p in ${LH_PYTHON:-} python3 /usr/bin/python3; do
  command -v "$p" > /dev/null && "$p" -c "import vtk" 2> /dev/null && { py=$p; break; }; done
if [ -n "$py" ]; then
  "$py" - <<'PY' && ok || bad "binary and ASCII .vtu differ (VTK)"
import vtk, numpy as np
from vtk.util.numpy_support import vtk_to_numpy as arr
def read(p):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(p); r.Update(); return r.GetOutput()
for b, a in (("b.vtu", "a.vtu"), ("la.vtu", "la-a.vtu")):
    gb, ga = read(b), read(a)
    assert gb.GetNumberOfCells() == ga.GetNumberOfCells() > 0, b
    assert np.array_equal(arr(gb.GetPoints().GetData()), arr(ga.GetPoints().GetData())), b
    assert np.array_equal(arr(gb.GetCells().GetConnectivityArray()), arr(ga.GetCells().GetConnectivityArray())), b
    assert np.array_equal(arr(gb.GetCellTypesArray()), arr(ga.GetCellTypesArray())), b
    for data in ("GetCellData", "GetPointData"):
        db, da = getattr(gb, data)(), getattr(ga, data)()
        assert db.GetNumberOfArrays() == da.GetNumberOfArrays() and (data == "GetPointData" or db.GetNumberOfArrays()), (b, data)
        for i in range(da.GetNumberOfArrays()):
            name = da.GetArrayName(i)
            assert np.array_equal(arr(db.GetArray(name)), arr(da.GetArray(name))), (b, name)
PY
fi

notemp "the end"
finish
