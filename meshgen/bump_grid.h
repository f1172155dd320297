// Gaussian-bump meshes on [0,1]^2: the 4-8 ("union-jack") mesh (docs/algorithms.md §10.2; paper
// §5.2), and the lifting shared with bump_irregular.h.
//
// Bump z = f(x,y) = exp(-81/16 ((x-1/2)^2 + (y-1/2)^2)); vertices lie exactly on it, (x, y,
// f(x,y)), and triangles are counter-clockwise in xy, so the normals point to +z.
// Level L: N = 16*2^(L-1) (N = 16, 32, 64, 128, ...), h = 1/N.
// 4-8 mesh: grid vertices (i/N, j/N), index j*(N+1) + i; square (i,j) is split along the diagonal
// (i,j)-(i+1,j+1) if i+j is even, otherwise along (i+1,j)-(i,j+1).
//   V = (N+1)^2, F = 2N^2, V - E + F = 1. Interior vertices: valence 8 if i+j even, 4 if odd;
//   corners valence 3; non-corner boundary vertices valence 5 (i+j even) or 3 (odd).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/types.h"
#include "meshgen/generated_mesh.h"

namespace curvbench {

/// n x 2 planar points (x, y), one row per point.
using PlanarPoints = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// Grid cells per side at `level` (>= 1): N = 16 * 2^(level-1).
int bump_grid_size(int level);

/// Throws UsageError unless 1 <= level <= max_bump_level(); `family` names the generator.
void check_bump_level(const std::string& family, int level);
constexpr int max_bump_level() {
  return 6;
}  // N = 512: level 6 (263169 vertices) only for `make experiments-deep`

/// Triangles given counter-clockwise in xy as an m x 3 face matrix in canonical order: each row
/// rotated (orientation kept) so that its smallest index leads, rows sorted; the faces then depend
/// only on the triangulation, not on the order a library lists them in.
FaceMatrix canonical_faces(std::vector<std::array<int, 3>> ccw);

/// Lifts planar points xy (n x 2, in [0,1]^2) onto the Gaussian bump and wraps them with `faces`
/// (m x 3, ccw in xy) into a GeneratedMesh (exact_points == vertices, surface = bump).
GeneratedMesh lift_onto_bump(const PlanarPoints& xy, FaceMatrix faces, const std::string& family,
                             int level, const std::string& description);

/// The level-`level` 4-8 mesh; family "bump-48".
GeneratedMesh bump_48(int level);

}  // namespace curvbench
