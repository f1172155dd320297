// Per-face quantities of the discrete curvature operators (Meyer et al. 2003, Taubin 1995,
// Rusinkiewicz 2004), computed once per mesh in the estimator's prepare() step.
//
//   For face f with corners k = 0, 1, 2 (vertex F(f,k), angle theta_k at that corner):
//   area(f)            |(x1 - x0) x (x2 - x0)| / 2
//   angle(f, k)        theta_k = atan2(|a x b|, a . b), a, b the two edges leaving corner k
//                      (only when asked for: one atan2 per corner is most of the cost)
//   cot(f, k)          cot theta_k = a . b / |a x b|  (infinite for a degenerate face); |a x b|
//                      is computed once per face (twice its area)
//   mixed_area(f, k)   Meyer et al. 2003 §3.3, Fig. 4 ("A_mixed"): the Voronoi part of the face
//                      at corner k, (|x_k - x_{k+1}|^2 cot theta_{k+2} + |x_k - x_{k+2}|^2
//                      cot theta_{k+1}) / 8, when no angle of the face is obtuse; area/2 at the
//                      obtuse corner and area/4 at the other two otherwise. The three corners
//                      sum to area(f).
// Arrays: m x 3 (row-major, one row per face) and m x 1. Each face is computed on its own from
// the positions, in parallel over faces; the result does not depend on the thread count.
#pragma once

#include "core/types.h"
#include "mesh/mesh.h"

namespace curvbench {

using CornerMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct FaceGeometry {
  Eigen::VectorXd area;     ///< m
  CornerMatrix angle;       ///< m x 3 (0 x 3 unless asked for)
  CornerMatrix cot;         ///< m x 3
  CornerMatrix mixed_area;  ///< m x 3
};

/// Computes the fields for every face of `mesh` with `threads` OpenMP threads (>= 1); the
/// angles only if `angles`.
FaceGeometry face_geometry(const Mesh& mesh, int threads, bool angles = true);

/// Corner k of face f that holds vertex v (0, 1 or 2); -1 if v is not a vertex of f.
inline int corner_of(const Mesh& mesh, int f, int v) {
  for (int k = 0; k < 3; ++k)
    if (mesh.face_vertex(f, k) == v) return k;
  return -1;
}

}  // namespace curvbench
