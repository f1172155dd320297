#!/usr/bin/python3
"""A minimal outside estimator for curvbench: vertex normals and mean curvature H from the
cotangent Laplacian (Pinkall & Polthier 1993; Meyer et al. 2003), with numpy only.

    /usr/bin/python3 cotangent_estimator.py MESH.ply OUT.csv

MESH.ply is the binary little-endian PLY that `curvbench run` writes for an `external` method
(x, y, z doubles; triangles as a uchar count and int indices). OUT.csv gets one row per vertex:
vertex,nx,ny,nz,H. Sign convention of curvbench: the normal is the area-weighted face normal
(outward for the closed torus, upward for the bump, from the meshes' face orientation), and
H = (k1 + k2) / 2 with the Laplace-Beltrami of the position equal to 2 H n, so a sphere of
radius r with outward normals has H = -1/r. The cotangent formula needs a full ring, so
boundary vertices get NaN (curvbench counts them as failed).
"""
import sys

import numpy as np


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").split("\n")
    if "format binary_little_endian 1.0" not in header:
        sys.exit(path + ": expected a binary little-endian PLY")
    sizes = {"double": "<f8", "float": "<f4", "int": "<i4", "uchar": "u1"}
    counts, vertex_props, element = {}, [], None
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            counts[element] = int(words[2])
        elif words[:1] == ["property"] and element == "vertex":
            vertex_props.append((words[2], sizes[words[1]]))
    vertices = np.frombuffer(data, dtype=np.dtype(vertex_props), count=counts["vertex"], offset=end)
    faces = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", 3)]),
                          count=counts["face"], offset=end + vertices.nbytes)
    if np.any(faces["n"] != 3):
        sys.exit(path + ": expected triangles only")
    return np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1), faces["v"].astype(np.int64)


def estimate(x, f):
    n = len(x)
    p0, p1, p2 = x[f[:, 0]], x[f[:, 1]], x[f[:, 2]]
    face_normal = np.cross(p1 - p0, p2 - p0)  # length = 2 * area
    area = 0.5 * np.linalg.norm(face_normal, axis=1)
    normal = np.zeros((n, 3))
    for k in range(3):
        np.add.at(normal, f[:, k], face_normal)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    # Laplace-Beltrami of the position: (1 / 2A_i) sum_j (cot a_ij + cot b_ij) (x_j - x_i), A_i
    # the barycentric area (a third of each incident triangle).
    laplace = np.zeros((n, 3))
    vertex_area = np.zeros(n)
    for k in range(3):
        i, j, o = f[:, k], f[:, (k + 1) % 3], f[:, (k + 2) % 3]
        u, v = x[i] - x[o], x[j] - x[o]
        cot = np.einsum("ij,ij->i", u, v) / np.linalg.norm(np.cross(u, v), axis=1)
        np.add.at(laplace, i, cot[:, None] * (x[j] - x[i]))
        np.add.at(laplace, j, cot[:, None] * (x[i] - x[j]))
        np.add.at(vertex_area, f[:, k], area / 3.0)
    laplace /= 2.0 * vertex_area[:, None]
    H = 0.5 * np.einsum("ij,ij->i", laplace, normal)
    # Boundary vertices: on an edge used by one triangle only.
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    unique, uses = np.unique(edges, axis=0, return_counts=True)
    boundary = np.unique(unique[uses == 1])
    H[boundary] = np.nan
    normal[boundary] = np.nan
    return normal, H


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: cotangent_estimator.py MESH.ply OUT.csv")
    x, f = read_ply(sys.argv[1])
    normal, H = estimate(x, f)
    table = np.column_stack([np.arange(len(x)), normal, H])
    np.savetxt(sys.argv[2], table, delimiter=",", header="vertex,nx,ny,nz,H", comments="",
               fmt=["%d"] + ["%.17g"] * 4)


if __name__ == "__main__":
    main()
