// Marching cubes on a rectilinear grid (docs/algorithms.md §10.1(a); paper §5.1, "isosurface
// function of MATLAB").
//
// Input: axis coordinates x (nx), y (ny), z (nz), each strictly increasing with >= 2 entries, and
// a scalar field f sampled at every grid point (x[i], y[j], z[k]).
// Output: IsosurfaceMesh with
//   vertices  V x 3  one vertex per sign-changing grid edge (shared by the cells around the edge;
//                    never merged by distance), placed by linear interpolation along the edge
//                    from its lower-index end a to b: t = (0 - f_a) / (f_b - f_a);
//   faces     F x 3  triangles counter-clockwise seen from the side of increasing f.
// A sample is inside iff f < 0. Ambiguous cube faces (two diagonal inside corners) are resolved
// with the asymptotic decider, identically in both cells sharing the face (see
// meshgen/marching_cubes_tables.h), so the zero set of a field that is >= 0 on the boundary of the
// grid comes out as a closed, consistently oriented 2-manifold.
// Extra vertices: a cell polygon that cannot be triangulated without a chord lying in a cube face
// (possible only when it crosses two or more ambiguous faces twice) gets one more vertex, the mean
// of its vertices, and is fanned around it (MC33-style). Without ambiguous faces the vertex set is
// exactly one vertex per sign-changing grid edge.
// Vertex order: grid edges are numbered slice by slice (x- then y-edges of z-slice k, then the
// z-edges between slices k and k+1; extra vertices right after the edges of their slab); faces
// follow the cells in x-fastest order. Deterministic.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/types.h"

namespace curvbench {

struct IsosurfaceMesh {
  VertexMatrix vertices;    ///< V x 3
  FaceMatrix faces;         ///< F x 3
  int ambiguous_faces = 0;  ///< grid faces resolved by the asymptotic decider
  int center_vertices = 0;  ///< extra vertices inside cells (see below); 0 unless ambiguous
};

/// MATLAB's linspace(a, b, n): a + (i*(b - a))/(n - 1) for i < n-1, and exactly b last.
/// Throws UsageError if n < 2.
std::vector<double> matlab_linspace(double a, double b, int n);

/// Zero level set of f on the grid x (nx) x y (ny) x z (nz). Throws UsageError for an axis with
/// fewer than 2 points or not strictly increasing, InputError for a non-finite sample.
IsosurfaceMesh marching_cubes(std::span<const double> x, std::span<const double> y,
                              std::span<const double> z,
                              const std::function<double(double, double, double)>& f);

}  // namespace curvbench
