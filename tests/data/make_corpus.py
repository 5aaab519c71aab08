#!/usr/bin/env python3
"""Writes the broken-file corpus (bad/) and the readable-but-invalid inputs (invalid/).

Each bad file is listed in bad/expected.tsv with the error class it must raise, the CLI's exit
code, the line the message must name (0: none) and a phrase the message must contain. The files
are committed; rerun this script only to change the corpus.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
BAD = os.path.join(HERE, "bad")
INVALID = os.path.join(HERE, "invalid")
rows = []


def bad(name, content, kind, code, line, phrase):
    with open(os.path.join(BAD, name), "wb") as f:
        f.write(content.encode() if isinstance(content, str) else content)
    rows.append((name, kind, str(code), str(line), phrase))


def stl_record(corners, normal=(0.0, 0.0, 1.0)):
    return struct.pack("<12fH", *normal, *[c for p in corners for c in p], 0)


TRI = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
TETRA_V = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"

bad("unknown_format.xyz", "0 0 0\n1 0 0\n", "unreadable input", 3, 0, "unknown format '.xyz'")
bad("no_extension", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "unreadable input", 3, 0, "unknown format (no extension)")
bad("truncated_binary.stl", b"\0" * 80 + struct.pack("<I", 10) + stl_record(TRI) * 3,
    "unreadable input", 3, 0, "truncated binary STL: the header promises 10 triangles")
bad("short_header.stl", b"\x01\x02" * 20, "unreadable input", 3, 0, "fewer than the 84-byte header")
bad("nan_binary.stl", b"\0" * 80 + struct.pack("<I", 1) + stl_record([(math.nan, 0, 0), (1, 0, 0), (0, 1, 0)]),
    "invalid geometry", 4, 0, "not a finite number")
bad("ascii_facet_two_vertices.stl",
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid t\n",
    "unreadable input", 3, 7, "a facet needs 3 vertices, this one has 2")
bad("ascii_truncated.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n",
    "unreadable input", 3, 5, "ends inside a facet")
bad("obj_index_past_end.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 99\n",
    "unreadable input", 3, 5, "face refers to vertex 99 but the file has only 3 vertices")
bad("obj_index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "unreadable input", 3, 4, "vertex index 0 is not valid")
bad("obj_relative_before_start.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n", "unreadable input", 3, 3, "reaches before the first vertex")
bad("obj_bad_number.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n", "unreadable input", 3, 2, "expected a y coordinate, found 'abc'")
bad("obj_missing_coordinate.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "unreadable input", 3, 2, "expected a z coordinate, found end of line")
bad("obj_nan.obj", "v 0 0 0\nv nan nan nan\nv 0 1 0\nf 1 2 3\n", "invalid geometry", 4, 2, "vertex 1 has a coordinate that is not a finite number")
bad("obj_repeated_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\n", "invalid geometry", 4, 4, "face repeats vertex 0")
bad("obj_two_corners.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "unreadable input", 3, 3, "a face needs at least 3 corners")
bad("obj_no_faces.obj", "# only points\nv 0 0 0\nv 1 0 0\n", "invalid geometry", 4, 0, "empty mesh")
bad("binary_garbage.obj", bytes((i * 37 + 11) % 256 for i in range(4096)), "invalid geometry", 4, 0, "empty mesh")
bad("all_nan.off", "OFF\n3 1 0\nnan nan nan\nnan nan nan\nnan nan nan\n3 0 1 2\n", "invalid geometry", 4, 3, "not a finite number")
bad("infinity.off", "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", "invalid geometry", 4, 4, "not a finite number")
bad("empty_file.off", "", "unreadable input", 3, 0, "empty file")
bad("bad_header.off", "OOF\n3 1 0\n", "unreadable input", 3, 1, "not an OFF file")
bad("truncated.off", "OFF\n8 1 0\n0 0 0\n1 0 0\n0 1 0\n", "unreadable input", 3, 5, "the header promises 8 vertices, the file ends after 3")
bad("truncated_faces.off", "OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "unreadable input", 3, 6, "the header promises 4 faces, the file ends after 1")
bad("index_out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "unreadable input", 3, 6, "vertex index 3 is out of range")
bad("negative_count.off", "OFF\n-3 1 0\n", "unreadable input", 3, 2, "negative vertex or face count")
bad("huge_count.off", "OFF\n999999999 1 0\n0 0 0\n", "unreadable input", 3, 2, "more than a file of")
bad("two_corner_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "unreadable input", 3, 6, "a face needs at least 3 corners")
bad("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "invalid geometry", 4, 0, "empty mesh")
PLY_HEAD = "ply\nformat {fmt} 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\nelement face {nf}\nproperty list uchar int vertex_indices\nend_header\n"
bad("truncated_binary.ply",
    PLY_HEAD.format(fmt="binary_little_endian", nv=3, nf=1).encode() + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\x03\x00\x00",
    "unreadable input", 3, 0, "truncated binary PLY")
bad("bad_format.ply", "ply\nformat ebcdic 1.0\nend_header\n", "unreadable input", 3, 2, "unknown PLY format 'ebcdic'")
bad("no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "unreadable input", 3, 3, "no 'end_header' line")
bad("not_ply.ply", "solid x\n", "unreadable input", 3, 1, "not a PLY file")
bad("index_out_of_range.ply", PLY_HEAD.format(fmt="ascii", nv=3, nf=1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
    "unreadable input", 3, 13, "face 0 refers to vertex 7 but the file has 3 vertices")
bad("huge_list.ply", PLY_HEAD.format(fmt="ascii", nv=3, nf=1) + "0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n",
    "unreadable input", 3, 13, "invalid list length")
bad("truncated_ascii.ply", PLY_HEAD.format(fmt="ascii", nv=3, nf=2) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    "unreadable input", 3, 0, "truncated PLY")

with open(os.path.join(BAD, "expected.tsv"), "w") as f:
    f.write("# file\tclass\texit code\tline (0: none)\tphrase the message contains\n")
    for r in rows:
        f.write("\t".join(r) + "\n")

# Readable, but validation must object (exit 4) or repair (exit 0).
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
          (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]


def write_off(name, verts, faces):
    with open(os.path.join(INVALID, name), "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%r %r %r\n" % tuple(float(c) for c in v))
        for t in faces:
            f.write("3 %d %d %d\n" % t)


write_off("cube.off", CUBE_V, CUBE_F)
write_off("cube_pierced.off", CUBE_V + [(0.5, 0.5, -0.5), (0.5, 0.5, 1.5), (0.6, 0.7, 0.5)], CUBE_F + [(8, 9, 10)])
write_off("cube_duplicate_face.off", CUBE_V, CUBE_F + [CUBE_F[3]])
write_off("cube_zero_area.off", CUBE_V + [(0.25, 0.25, 0.25), (0.5, 0.5, 0.5), (0.75, 0.75, 0.75)], CUBE_F + [(8, 9, 10)])
write_off("cube_flipped_face.off", CUBE_V, CUBE_F[:5] + [(0, 4, 5)] + CUBE_F[6:])
write_off("cube_inside_out.off", CUBE_V, [(a, c, b) for (a, b, c) in CUBE_F])
