// Weighted vertex normals of the discrete operators: the vertex normal each method's authors'
// code uses is selectable (EstimatorOptions::vertex_normals).
//
//   n_v = normalize( sum over the faces f of v of  w_f(v) (x1 - x0) x (x2 - x0) / |...| )
//   area   w = area of f                      (libigl's per_vertex_normals default; the bits
//                                              of Mesh::area_weighted_normals, with one cross
//                                              product per face; MeshContext::approx_normals)
//   angle  w = angle of f at v                (Thürmer & Wüthrich 1998)
//   max    w = |a x b| / (|a|^2 |b|^2) = sin(theta) / (|a| |b|), a, b the edges of f at v
//          (Max 1999; trimesh2's choice, used by Rusinkiewicz 2004)
// A vertex without faces, or whose weighted sum vanishes, gets the zero vector. n x 3.
// Deterministic: each vertex sums its faces in increasing face order (one pass over the faces;
// each thread owns a range of vertices), whatever the number of threads.
//
// Names (the option vertex-normals of include/curvbench/estimator_options.h): "default"
// (method_default), "area", "angle", "max".
#pragma once

#include <string>

#include "core/types.h"
#include "mesh/mesh.h"
#include "methods/estimator.h"

namespace curvbench {

/// Normals with the given weighting (not VertexNormals::method_default) and `threads` threads.
VertexMatrix weighted_vertex_normals(const Mesh& mesh, VertexNormals weighting, int threads);

}  // namespace curvbench
