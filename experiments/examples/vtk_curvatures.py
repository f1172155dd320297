#!/usr/bin/python3
"""VTK's vtkCurvatures filter as an outside estimator for curvbench: H, K, k1, k2 per vertex.

    /usr/bin/python3 vtk_curvatures.py MESH.ply OUT.csv

MESH.ply is the binary little-endian PLY that `curvbench run` writes for an `external` method;
OUT.csv gets vertex,H,K,k1,k2 (no normals, no directions: vtkCurvatures computes neither).
Needs VTK's Python module for /usr/bin/python3 (Debian package python3-vtk9, `make deps`) and
numpy. When either is missing the script prints one line on stderr and exits with code 77,
which tells `curvbench run` to skip the method rather than fail (docs/cli.md).

What vtkCurvatures computes (read from Filters/General/vtkCurvatures.cxx: VTK 9.1, Debian 12's
python3-vtk9, and the current master compute the same):

* Mean curvature. Per edge shared by exactly two triangles f and g: the signed angle theta
  between the two face normals (positive when the surface bends away from the side the normals
  point to, i.e. convex seen from outside for counter-clockwise faces), and the value
  3 |e| theta / (A_f + A_g): the edge's integrated mean curvature (|e| theta / 2, the Steiner
  formula) over a third of the area of its two triangles, times two. A vertex gets half of the
  plain average of these values over its edges; every edge counts the same, whatever its
  length or area. Meyer et al. (curvbench's `meyer`, methods/operators/meyer.cpp) instead sum
  cotangent-weighted edge vectors (the cotangent Laplacian of the position) over the vertex's
  mixed Voronoi area, and take H from its component along the normal. Both come from the
  integral identity; they differ in the weights (dihedral angle times length against
  cotangents) and in the area each vertex is given (the equal-weight edge average against the
  mixed area).
* Gaussian curvature. The angle deficit 2 pi - (sum of the triangle angles at the vertex),
  divided by a third of the area of the incident triangles (the barycentric area). Meyer's
  deficit is the same; its area is the mixed Voronoi area, which differs from the barycentric
  one wherever the triangles are not all alike, so the two Ks differ on irregular meshes.
* Measured (the field study, experiments/field-estimators.exp, L2 errors at the finest
  level): on torus-structured both converge as O(h^2), VTK's H error 3.4 times Meyer's and its
  K error 0.74 times. On the other five families neither converges in H or K; VTK's H error
  is 1.7 times Meyer's on torus-unstructured, 1.6 on bump-irregular, 2.2 on bump-48, 1.5 on
  torus-iso-projected (both diverge there) and 0.58 on torus-jittered, and its K error is
  within 10% of Meyer's except on bump-48 (4 times) and bump-irregular (2.8 times).
* Maximum/minimum curvature: H +- sqrt(H^2 - K), with H when H^2 - K < 0 (VTK then warns if it
  is below -0.1). This script forms k1, k2 the same way from the H and K it writes.
* Orientation and normals. The filter takes no normals and does not reorient faces: the face
  normals come from each triangle's winding. Reversing every face reverses the sign of H (VTK's
  InvertMeanCurvature flag does the same); a face wound against its neighbour makes the angle
  across their common edge close to +-pi, a large spurious H at the edge's vertices. K does not
  depend on orientation.
* Boundary. Edges with one triangle (and non-manifold edges with more than two) are left out
  of H: a boundary vertex gets the average over its other edges only, a one-sided value, and 0
  when it has no other edge. K at a boundary vertex is still counted from 2 pi, not pi, so it is
  large and meaningless (it is not set to 0). This script writes nan (no answer, counted as
  failed by curvbench) for H, K, k1, k2 at every vertex on a boundary or non-manifold edge and
  at vertices without triangles.

curvbench's sign convention: B = n . x_uu with the outward normal (the area-weighted face normal
from the mesh's winding), so a sphere of radius r has k1 = k2 = H = -1/r, and k1 >= k2. VTK's H
has the opposite sign for the same winding (+1/r on that sphere), so the script sets
InvertMeanCurvature, i.e. H = -H_VTK; K is the same in both. Then k1 = H + sqrt(max(H^2 - K, 0))
and k2 = H - sqrt(max(H^2 - K, 0)) (these are -k_min and -k_max of VTK's own output). Checked
on torus-structured level 2: H has Meyer's sign at every vertex; on the outer equator the exact
H is -2.0513, this script gives -2.0527 and `curvbench estimate --method meyer` -2.0523.

The mesh is read with numpy in double precision (the PLY holds doubles) and handed to VTK as a
vtkPolyData with double points.
"""
import sys

SKIP = 77  # curvbench: "this estimator cannot run here; skip the method" (docs/cli.md)

try:
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkFiltersGeneral import vtkCurvatures
except ImportError as error:
    sys.stderr.write("vtk_curvatures.py: cannot import VTK for %s (install Debian's python3-vtk9: "
                     "make deps): %s\n" % (sys.executable, error))
    sys.exit(SKIP)


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
    x = np.stack([vertices["x"], vertices["y"], vertices["z"]], axis=1).astype(np.float64)
    return x, faces["v"].astype(np.int64)


def poly_data(x, f):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(x), deep=True))
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * len(f) + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(np.ascontiguousarray(f.ravel()), deep=True))
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(cells)
    return mesh


def vtk_curvature(mesh, mean):
    """VTK's mean (with InvertMeanCurvature: curvbench's sign) or Gaussian curvature."""
    filt = vtkCurvatures()
    filt.SetInputData(mesh)
    if mean:
        filt.SetCurvatureTypeToMean()
        filt.InvertMeanCurvatureOn()
    else:
        filt.SetCurvatureTypeToGaussian()
    filt.Update()
    name = "Mean_Curvature" if mean else "Gauss_Curvature"
    return vtk_to_numpy(filt.GetOutput().GetPointData().GetArray(name)).astype(np.float64)


def unanswered(x, f):
    """Vertices on an edge with other than two triangles, and vertices with no triangle."""
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    unique, uses = np.unique(edges, axis=0, return_counts=True)
    out = np.zeros(len(x), dtype=bool)
    out[unique[uses != 2].ravel()] = True
    used = np.zeros(len(x), dtype=bool)
    used[f.ravel()] = True
    return out | ~used


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: vtk_curvatures.py MESH.ply OUT.csv")
    x, f = read_ply(sys.argv[1])
    mesh = poly_data(x, f)
    H = vtk_curvature(mesh, mean=True)
    K = vtk_curvature(mesh, mean=False)
    root = np.sqrt(np.maximum(H * H - K, 0.0))
    k1, k2 = H + root, H - root
    table = np.column_stack([np.arange(len(x)), H, K, k1, k2])
    table[unanswered(x, f), 1:] = np.nan
    np.savetxt(sys.argv[2], table, delimiter=",", header="vertex,H,K,k1,k2", comments="",
               fmt=["%d"] + ["%.17g"] * 4)


if __name__ == "__main__":
    main()
