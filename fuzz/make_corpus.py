#!/usr/bin/env python3
"""Writes the fuzz seed corpus tests/corpus/{off,obj,ply}/: small valid and broken mesh files.

The files are committed; this script documents how the binary ones were made and regenerates
them all (python3 fuzz/make_corpus.py). Names say what each file holds; the fuzzers only need
them as starting points, so valid and broken files live side by side. The prefix is a contract
checked by tests/mesh/test_io.cpp (MeshIoCorpus): "broken_" files are refused with an error, all
others are read ("defect_" ones with a warning).
"""
import os
import struct
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "corpus")

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
CUBE_V = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_Q = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def put(fmt, name, data):
    d = os.path.join(ROOT, fmt)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def off_text(V, F, head="OFF\n"):
    s = head + f"{len(V)} {len(F)} 0\n"
    s += "".join(" ".join(str(c) for c in v) + "\n" for v in V)
    s += "".join(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in F)
    return s


def obj_text(V, F):
    s = "".join("v " + " ".join(str(c) for c in v) + "\n" for v in V)
    return s + "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in F)


def ply_header(fmt, nv, nf, vprops=("float x", "float y", "float z"),
               flist="list uchar int vertex_indices", extra=""):
    h = f"ply\nformat {fmt} 1.0\ncomment curvbench fuzz seed\n{extra}"
    h += f"element vertex {nv}\n" + "".join(f"property {p}\n" for p in vprops)
    h += f"element face {nf}\nproperty {flist}\nend_header\n"
    return h.encode()


def ply_binary(V, F, endian, vtype="f", ctype="B", itype="i"):
    fmt = "binary_little_endian" if endian == "<" else "binary_big_endian"
    names = {"f": "float", "d": "double", "B": "uchar", "i": "int", "I": "uint", "H": "ushort"}
    vp = tuple(f"{names[vtype]} {c}" for c in "xyz")
    body = b"".join(struct.pack(endian + vtype * 3, *v) for v in V)
    for f in F:
        body += struct.pack(endian + ctype + itype * len(f), len(f), *f)
    return ply_header(fmt, len(V), len(F), vp, f"list {names[ctype]} {names[itype]} vertex_indices") + body


def off():
    put("off", "tetra.off", off_text(TETRA_V, TETRA_F))
    put("off", "cube_quads_comments.off",
        "# a cube with quad faces\nOFF\n\n# counts\n8 6 12\n" +
        off_text(CUBE_V, CUBE_Q).split("\n", 2)[2].replace("\n", "  # c\n", 3))
    put("off", "tetra_crlf.off", off_text(TETRA_V, TETRA_F).replace("\n", "\r\n"))
    put("off", "counts_on_keyword_line.off", off_text(TETRA_V, TETRA_F).replace("OFF\n", "OFF ", 1))
    put("off", "coff_colors.off",
        "COFF\n4 4 0\n" + "".join(f"{v[0]} {v[1]} {v[2]} 255 0 0 255\n" for v in TETRA_V) +
        "".join(f"3 {f[0]} {f[1]} {f[2]} 0.5 0.5 0.5\n" for f in TETRA_F))
    put("off", "noff_normals.off",
        "NOFF\n4 4 0\n" + "".join(f"{v[0]} {v[1]} {v[2]} 0 0 1\n" for v in TETRA_V) +
        "".join(f"3 {f[0]} {f[1]} {f[2]}\n" for f in TETRA_F))
    put("off", "homogeneous_4off.off",
        "4OFF\n4 4 0\n" + "".join(f"{v[0]} {v[1]} {v[2]} 2\n" for v in TETRA_V) +
        "".join(f"3 {f[0]} {f[1]} {f[2]}\n" for f in TETRA_F))
    put("off", "scientific.off", off_text([(1e-3, -2.5E+2, +0.0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]))
    put("off", "broken_truncated.off", off_text(TETRA_V, TETRA_F)[:-9])
    put("off", "broken_counts_too_large.off", off_text(TETRA_V, TETRA_F).replace("4 4 0", "4000000 4 0"))
    put("off", "broken_counts_too_small.off", off_text(TETRA_V, TETRA_F).replace("4 4 0", "3 2 0"))
    put("off", "broken_index_out_of_range.off", off_text(TETRA_V, [(0, 1, 4)]))
    put("off", "broken_negative_index.off", off_text(TETRA_V, [(0, 1, -1)]))
    put("off", "broken_nan.off", off_text([("nan", 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]))
    put("off", "broken_face_size.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n")
    put("off", "defect_repeated_index.off", off_text(TETRA_V, [(0, 1, 1), (0, 1, 2)]))
    put("off", "broken_keyword.off", "OFX\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    put("off", "broken_binary.off", "OFF BINARY\n" + "\0" * 12)
    put("off", "broken_empty.off", "")


def obj():
    put("obj", "tetra.obj", obj_text(TETRA_V, TETRA_F))
    put("obj", "cube_quads_groups.obj",
        "# cube\nmtllib cube.mtl\no cube\n" + obj_text(CUBE_V, []) + "g side\nusemtl red\ns off\n" +
        "".join("f " + " ".join(str(i + 1) for i in q) + "\n" for q in CUBE_Q))
    put("obj", "tetra_vt_vn.obj",
        obj_text(TETRA_V, []) + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n" +
        "".join("f " + " ".join(f"{i + 1}/{(i % 3) + 1}/1" for i in f) + "\n" for f in TETRA_F) +
        "f 1//1 2//1 3//1\n")
    put("obj", "tetra_relative_indices.obj",
        obj_text(TETRA_V, []) + "f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n")
    put("obj", "tetra_crlf_tabs.obj", obj_text(TETRA_V, TETRA_F).replace(" ", "\t").replace("\n", "\r\n"))
    put("obj", "vertex_colors.obj",
        "".join(f"v {v[0]} {v[1]} {v[2]} 1 0 0\n" for v in TETRA_V) +
        "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in TETRA_F))
    put("obj", "broken_line_continuation.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n2 3\n")
    put("obj", "defect_truncated.obj", obj_text(TETRA_V, TETRA_F)[:-3])
    put("obj", "broken_index_out_of_range.obj", obj_text(TETRA_V, [(0, 1, 4)]))
    put("obj", "broken_zero_index.obj", obj_text(TETRA_V, []) + "f 0 1 2\n")
    put("obj", "broken_non_numeric.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n")
    put("obj", "broken_inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n")
    put("obj", "broken_face_size.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n")
    put("obj", "broken_no_faces.obj", obj_text(TETRA_V, []))
    put("obj", "broken_unknown_statement.obj", obj_text(TETRA_V, TETRA_F) + "xyz 1 2 3\n")
    put("obj", "broken_empty.obj", "")


def ply():
    put("ply", "tetra_ascii.ply",
        ply_header("ascii", 4, 4) + off_text(TETRA_V, TETRA_F).split("\n", 2)[2].encode())
    put("ply", "tetra_ascii_crlf.ply",
        (ply_header("ascii", 4, 4) + off_text(TETRA_V, TETRA_F).split("\n", 2)[2].encode())
        .replace(b"\n", b"\r\n"))
    put("ply", "cube_quads_ascii_extra_props.ply",
        ply_header("ascii", 8, 6, ("double x", "double y", "double z", "float nx", "uchar red"),
                   "list uchar uint vertex_indices", "obj_info made for fuzzing\n") +
        "".join(f"{v[0]} {v[1]} {v[2]} 0.5 200\n" for v in CUBE_V).encode() +
        "".join("4 " + " ".join(map(str, q)) + "\n" for q in CUBE_Q).encode())
    put("ply", "tetra_ascii_face_props.ply",
        b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        b"property float z\nelement face 4\nproperty list uchar int vertex_index\n"
        b"property uchar red\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
        b"end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 9\n3 0 1 3 9\n3 0 3 2 9\n3 1 2 3 9\n0 1\n")
    put("ply", "tetra_binary_le.ply", ply_binary(TETRA_V, TETRA_F, "<"))
    put("ply", "tetra_binary_be.ply", ply_binary(TETRA_V, TETRA_F, ">"))
    put("ply", "cube_quads_binary_le_double_uint.ply", ply_binary(CUBE_V, CUBE_Q, "<", "d", "B", "I"))
    put("ply", "cube_quads_binary_be_double_ushort.ply", ply_binary(CUBE_V, CUBE_Q, ">", "d", "H", "i"))
    put("ply", "broken_binary_le_truncated.ply", ply_binary(TETRA_V, TETRA_F, "<")[:-5])
    put("ply", "broken_binary_be_truncated_header.ply", ply_binary(TETRA_V, TETRA_F, ">")[:60])
    put("ply", "broken_binary_le_huge_count.ply",
        ply_binary(TETRA_V, TETRA_F, "<").replace(b"element vertex 4", b"element vertex 2147483647"))
    put("ply", "broken_binary_le_huge_list.ply",
        ply_binary(TETRA_V, TETRA_F, "<")[:-13] + struct.pack("<B3i", 255, 0, 1, 2))
    put("ply", "broken_ascii_index_out_of_range.ply",
        ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")
    put("ply", "broken_ascii_nan.ply", ply_header("ascii", 3, 1) + b"0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n")
    put("ply", "broken_no_format.ply", b"ply\nelement vertex 0\nend_header\n")
    put("ply", "broken_bad_magic.ply", b"plx\nformat ascii 1.0\nend_header\n")
    put("ply", "broken_no_xyz.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float a\nend_header\n1\n")
    put("ply", "broken_empty.ply", b"")


if __name__ == "__main__":
    for fn in (off, obj, ply):
        fn()
    sys.exit(0)
