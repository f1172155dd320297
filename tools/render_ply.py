#!/usr/bin/python3
"""A PNG of a curvature-coloured PLY (`curvbench estimate --color ...`) with gnuplot, headless.

Reads the binary little-endian or ASCII PLY that curvbench writes (x, y, z and per-vertex red,
green, blue; triangle faces), turns the model by --azimuth/--elevation (degrees, about the
--up axis), shades every triangle by its vertices' mean colour times a headlight Lambert factor,
sorts the triangles back to front (painter's algorithm) and hands them to gnuplot
(`set terminal pngcairo`; one 2 x 2 pm3d surface per triangle, drawn in file order with
`fillcolor rgb variable`, 0xRRGGBB; gnuplot 5.4 ignores a variable colour `with polygons`).
The colour range written by `--color` in the PLY header goes into the caption.
Standard library only.
Usage: render_ply.py IN.ply OUT.png [--azimuth A] [--elevation E] [--up y|z|x] [--title T]
"""
import argparse
import math
import os
import re
import struct
import subprocess
import sys
import tempfile

PLY_TYPES = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H",
             "int16": "h", "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}


def read_ply(path):
    """Returns (positions, colours (r, g, b) or None, triangles, header comments)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt = None
    elements = []  # (name, count, [(prop name, type, list count type or None)])
    comments = []
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "comment":
            comments.append(line[len("comment "):])
        elif t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t[0] == "property":
            if t[1] == "list":
                elements[-1][2].append((t[4], t[3], t[2]))
            else:
                elements[-1][2].append((t[2], t[1], None))
    verts, faces = [], []
    if fmt == "ascii":
        toks = data[end:].decode().split()
        p = 0

        def take(_):
            nonlocal p
            p += 1
            return float(toks[p - 1])
    elif fmt == "binary_little_endian":
        p = end

        def take(ty):
            nonlocal p
            c = PLY_TYPES[ty]
            (x,) = struct.unpack_from("<" + c, data, p)
            p += struct.calcsize(c)
            return x
    else:
        raise SystemExit("render_ply: unsupported PLY format %s" % fmt)
    for name, count, props in elements:
        for _ in range(count):
            row = {}
            for pname, ty, lty in props:
                if lty is None:
                    row[pname] = take(ty)
                else:
                    n = int(take(lty))
                    row[pname] = [int(take(ty)) for _ in range(n)]
            if name == "vertex":
                verts.append(row)
            elif name == "face":
                idx = row.get("vertex_indices") or row.get("vertex_index")
                for j in range(1, len(idx) - 1):
                    faces.append((idx[0], idx[j], idx[j + 1]))
    P = [(v["x"], v["y"], v["z"]) for v in verts]
    C = None
    if verts and all(k in verts[0] for k in ("red", "green", "blue")):
        C = [(int(v["red"]), int(v["green"]), int(v["blue"])) for v in verts]
    return P, C, faces, comments


def rotate(P, up, azimuth, elevation):
    """Screen coordinates (x right, y up, z towards the viewer) of every point."""
    axes = {"x": (1, 2, 0), "y": (2, 0, 1), "z": (0, 1, 2)}[up]  # (a, b, up) right-handed
    a, e = math.radians(azimuth), math.radians(elevation)
    ca, sa, ce, se = math.cos(a), math.sin(a), math.cos(e), math.sin(e)
    out = []
    for p in P:
        u, v, w = p[axes[0]], p[axes[1]], p[axes[2]]
        # Turn about the up axis, then tilt towards the viewer by the elevation.
        x = ca * u - sa * v
        depth = sa * u + ca * v  # towards the viewer before the tilt
        y = ce * w - se * depth
        z = se * w + ce * depth
        out.append((x, y, z))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("ply")
    ap.add_argument("png")
    ap.add_argument("--azimuth", type=float, default=0.0)
    ap.add_argument("--elevation", type=float, default=0.0)
    ap.add_argument("--up", choices=["x", "y", "z"], default="y")
    ap.add_argument("--title", default="")
    ap.add_argument("--size", default="900,800")
    a = ap.parse_args()
    P, C, F, comments = read_ply(a.ply)
    if C is None:
        raise SystemExit("render_ply: %s has no red/green/blue (use estimate --color)" % a.ply)
    S = rotate(P, a.up, a.azimuth, a.elevation)
    tris = []
    for f in F:
        A, B, D = (S[i] for i in f)
        e1 = (B[0] - A[0], B[1] - A[1], B[2] - A[2])
        e2 = (D[0] - A[0], D[1] - A[1], D[2] - A[2])
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0])
        ln = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        if ln == 0:
            continue
        shade = 0.3 + 0.7 * abs(n[2]) / ln  # headlight; two-sided
        rgb = [min(255, int(shade * sum(C[i][k] for i in f) / 3 + 0.5)) for k in range(3)]
        tris.append(((A[2] + B[2] + D[2]) / 3, f, (rgb[0] << 16) | (rgb[1] << 8) | rgb[2]))
    tris.sort(key=lambda t: t[0])  # back to front
    rng = ""
    for c in comments:
        m = re.match(r"color: (\S+), .*L = ([0-9.eE+-]+)", c)
        if m:
            rng = "%s: blue -%s .. white 0 .. red +%s (clamped)" % (m.group(1), m.group(2),
                                                                    m.group(2))
    with tempfile.TemporaryDirectory() as tmp:
        dat = os.path.join(tmp, "tri.dat")
        with open(dat, "w") as out:
            for _, f, col in tris:
                # One pm3d surface of 2 x 2 corners per triangle (the last corner repeated).
                p0, p1, p2 = (S[i] for i in f)
                out.write("%.6g %.6g %.6g %d\n%.6g %.6g %.6g %d\n\n" % (*p0, col, *p1, col))
                out.write("%.6g %.6g %.6g %d\n%.6g %.6g %.6g %d\n\n\n" % (*p2, col, *p2, col))
        xs = [s[0] for s in S]
        ys = [s[1] for s in S]
        zs = [s[2] for s in S]
        pad = 0.03 * max(max(xs) - min(xs), max(ys) - min(ys))
        script = "\n".join([
            "set terminal pngcairo size %s background rgb 'white'" % a.size,
            "set output '%s'" % a.png.replace("'", "''"),
            "unset border; unset tics; unset key; unset colorbox",
            "set view 0,0,1.7; set view equal xy; set margins 0,0,0,0",
            "set xrange [%g:%g]; set yrange [%g:%g]; set zrange [%g:%g]" % (
                min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad, min(zs), max(zs)),
            "set title \"%s\" noenhanced" % a.title.replace('"', "'"),
            "set label 1 \"%s\" noenhanced at screen 0.5,0.03 center" % rng,
            "set pm3d corners2color c1 noborder",
            "splot '%s' using 1:2:3:4 with pm3d fillcolor rgb variable notitle" % dat,
        ])
        r = subprocess.run(["gnuplot"], input=script, text=True, capture_output=True)
        if r.returncode != 0 or not os.path.exists(a.png):
            sys.stderr.write(r.stderr)
            raise SystemExit("render_ply: gnuplot failed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
