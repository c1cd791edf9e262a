"""meshio_check.py IO_TOOL WORKDIR — the writers' files read by an independent reader.

Random points (2D and 3D, magnitudes 1e-3..1e3, written with repr so that each value is
exact) go through `io_tool mesh` (lh_points_read, lh_delaunay, every writer); meshio then
reads the .vtu (ASCII, and binary: base64 inline with a cell field), the .msh (Gmsh 4.1), the .off (2D) and the TetGen .node/.ele pair (3D),
and each must hold exactly these points (padded with z = 0 in 2D), the cells of the .ele
file (parsed here by hand), the point field and, in the .vtu, the neighbours of the
.neigh file. Exit status 77 (skip) when meshio cannot be imported.
"""
import os
import random
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:
    print(f"SKIP: meshio not available ({e}); Debian: apt-get install python3-meshio")
    sys.exit(77)


def rows(path):
    """A Triangle/TetGen file's header and rows, '#' comments and blank lines dropped."""
    out = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                out.append(line)
    return out[0], out[1:]


def check(tool, work, d, n):
    rnd = random.Random(d)
    pts = [[rnd.uniform(-1, 1) * 10.0 ** rnd.randint(-3, 3) for _ in range(d)] for _ in range(n)]
    src = os.path.join(work, f"pts{d}.txt")
    with open(src, "w") as f:
        f.write(f"{d} {n}\n")
        for p in pts:
            f.write(" ".join(repr(x) for x in p) + "\n")
    prefix = os.path.join(work, f"mesh{d}")
    subprocess.run([tool, "mesh", src, prefix], check=True)

    head, node = rows(prefix + ".node")
    assert [int(x) for x in head] == [n, d, 1, 0], head
    assert [[float(x) for x in r[1:1 + d]] for r in node] == pts, "node coordinates"
    head, ele = rows(prefix + ".ele")
    cells = np.array([[int(x) - 1 for x in r[1:]] for r in ele])
    assert cells.shape == (int(head[0]), d + 1) and cells.min() >= 0, head
    _, neigh = rows(prefix + ".neigh")
    nbrs = np.array([[int(x) - 1 if int(x) >= 0 else -1 for x in r[1:]] for r in neigh])
    padded = np.array([p + [0.0] * (3 - d) for p in pts])
    half = 0.5 * np.arange(n)
    kind = {2: "triangle", 3: "tetra"}[d]

    def same(m, what, data=True):
        assert np.array_equal(m.points[:, :3], padded), f"{what}: points"
        assert len(m.cells) == 1 and m.cells[0].type == kind, f"{what}: {m.cells}"
        assert np.array_equal(m.cells[0].data, cells), f"{what}: cells"
        if data:
            assert np.array_equal(m.point_data["half_index"], half), f"{what}: point data"

    m = meshio.read(prefix + ".vtu")
    same(m, "vtu")
    assert np.array_equal(m.cell_data["neighbors"][0], nbrs), "vtu: neighbours"
    b = meshio.read(prefix + ".bin.vtu")
    same(b, "binary vtu")
    assert np.array_equal(b.cell_data["neighbors"][0], nbrs), "binary vtu: neighbours"
    assert np.array_equal(b.cell_data["quarter"][0], 0.25 * np.arange(len(cells))), "binary vtu: cell field"
    with open(prefix + ".bin.vtu", "rb") as f:
        head = f.read(300)
    assert b'format="binary"' in head and b'header_type="UInt64"' in head, head
    same(meshio.read(prefix + ".msh"), "msh")
    if d == 2:
        same(meshio.read(prefix + ".off"), "off", data=False)
    if d == 3:
        m = meshio.read(prefix + ".node", file_format="tetgen")
        same(m, "tetgen", data=False)
        assert np.array_equal(m.point_data["tetgen:attr1"], half), "tetgen: attribute"
    print(f"ok {d}D: {n} points, {len(cells)} {kind}s, vtu (ASCII, binary) msh{' off' if d == 2 else ' tetgen'}")


def main():
    tool, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    check(tool, work, 2, 200)
    check(tool, work, 3, 120)


if __name__ == "__main__":
    main()
