#!/usr/bin/env python3
"""seeds_plc_binary.py OUT_DIR — seed inputs for fuzz_plc_binary (fuzz/README.md): a
tetrahedron as PLY ascii, binary little- and big-endian (with skipped properties,
elements and lists), as STL ascii and binary (plain and "solid" headers), and
tests/data/plc_bin's sphere.ply and sphere.stl. The first byte picks the reader as the
target does: 0 "in.ply", 1 "in.stl", 2 "in" (by content), 3 PLY, 4 STL.
Writes OUT_DIR/plc_binary/seed-<name>.
"""
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PTS = [(0, 0, 0), (0.5, 0, 0), (0, 0.25, 0), (0, 0, 3)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3, 0)]
HEADER = ("element vertex 4\nproperty float x\nproperty double y\nproperty uchar red\n"
          "property short z\nelement edge 1\nproperty list uchar int pair\n"
          "element face 4\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
          "end_header\n")


def ply_ascii():
    body = "".join(f"{x} {y} 7 {int(z)}\n" for x, y, z in PTS) + "2 0 1\n"
    body += "".join(f"0 {len(f)} {' '.join(map(str, f))}\n" for f in FACES)
    return ("ply\nformat ascii 1.0\ncomment seed\n" + HEADER + body).encode()


def ply_binary(big):
    e = ">" if big else "<"
    out = ("ply\nformat binary_%s_endian 1.0\n" % ("big" if big else "little") + HEADER).encode()
    for x, y, z in PTS:
        out += struct.pack(e + "fdBh", x, y, 7, int(z))
    out += struct.pack(e + "Bii", 2, 0, 1)
    for f in FACES:
        out += struct.pack(e + "BB" + "i" * len(f), 0, len(f), *f)
    return out


TRIS = [(PTS[0], PTS[2], PTS[1]), (PTS[0], PTS[1], PTS[3]), (PTS[0], PTS[3], PTS[2]),
        (PTS[1], PTS[2], PTS[3])]


def stl_ascii():
    out = "solid seed\n"
    for t in TRIS:
        out += "facet normal 0 0 0\n outer loop\n"
        out += "".join(f"  vertex {x} {y} {z}\n" for x, y, z in t)
        out += " endloop\nendfacet\n"
    return (out + "endsolid seed\n").encode()


def stl_binary(header):
    out = header.ljust(80, b" ") + struct.pack("<I", len(TRIS))
    for t in TRIS:
        out += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *p) for p in t)
        out += struct.pack("<H", 0)
    return out


def main():
    out = os.path.join(sys.argv[1], "plc_binary")
    os.makedirs(out, exist_ok=True)
    data = os.path.join(HERE, "..", "tests", "data", "plc_bin")
    seeds = {
        "ply-ascii": (0, ply_ascii()), "ply-ascii-forced": (3, ply_ascii()),
        "ply-le": (2, ply_binary(False)), "ply-be": (0, ply_binary(True)),
        "stl-ascii": (1, stl_ascii()), "stl-ascii-auto": (2, stl_ascii()),
        "stl-binary": (2, stl_binary(b"binary seed")),
        "stl-binary-solid": (4, stl_binary(b"solid seed")),
        "sphere-ply": (0, open(os.path.join(data, "sphere.ply"), "rb").read()),
        "sphere-stl": (1, open(os.path.join(data, "sphere.stl"), "rb").read()),
    }
    for name, (pick, body) in seeds.items():
        with open(os.path.join(out, "seed-" + name), "wb") as f:
            f.write(bytes([pick]) + body)


if __name__ == "__main__":
    main()
