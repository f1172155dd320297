// Basic numeric types shared by every layer. Double precision everywhere.
#pragma once

#include <Eigen/Dense>
#include <cstdint>

namespace curvbench {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;

/// n x 3 vertex positions, one row per vertex (row-major so a row is contiguous).
using VertexMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// m x 3 triangle vertex indices, counter-clockwise seen from outside / above.
using FaceMatrix = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

}  // namespace curvbench
