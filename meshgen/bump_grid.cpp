#include "meshgen/bump_grid.h"

#include <algorithm>
#include <string>

#include "core/errors.h"
#include "surfaces/gaussian_bump.h"

namespace curvbench {

int bump_grid_size(int level) {
  return 16 << (level - 1);
}

void check_bump_level(const std::string& family, int level) {
  if (level < 1 || level > max_bump_level())
    throw UsageError(family + ": level " + std::to_string(level) + " out of range [1, " +
                     std::to_string(max_bump_level()) + "]");
}

FaceMatrix canonical_faces(std::vector<std::array<int, 3>> ccw) {
  for (auto& t : ccw) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(ccw.begin(), ccw.end());
  FaceMatrix F(static_cast<Eigen::Index>(ccw.size()), 3);
  for (size_t k = 0; k < ccw.size(); ++k)
    F.row(static_cast<Eigen::Index>(k)) << ccw[k][0], ccw[k][1], ccw[k][2];
  return F;
}

GeneratedMesh lift_onto_bump(const PlanarPoints& xy, FaceMatrix faces, const std::string& family,
                             int level, const std::string& description) {
  SurfacePtr bump = make_gaussian_bump();
  VertexMatrix V(xy.rows(), 3);
  for (Eigen::Index i = 0; i < xy.rows(); ++i)
    V.row(i) = bump->position(xy(i, 0), xy(i, 1)).transpose();
  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), std::move(faces), family);
  out.surface = std::move(bump);
  out.family = family;
  out.level = level;
  out.description = description;
  return out;
}

GeneratedMesh bump_48(int level) {
  check_bump_level("bump-48", level);
  const int N = bump_grid_size(level);
  const int n1 = N + 1;
  PlanarPoints xy(n1 * n1, 2);
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i)
      xy.row(j * n1 + i) << static_cast<double>(i) / N, static_cast<double>(j) / N;

  auto idx = [n1](int i, int j) { return j * n1 + i; };
  FaceMatrix F(2 * N * N, 3);
  int f = 0;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      if ((i + j) % 2 == 0) {  // diagonal (i,j)-(i+1,j+1)
        F.row(f++) << idx(i, j), idx(i + 1, j), idx(i + 1, j + 1);
        F.row(f++) << idx(i, j), idx(i + 1, j + 1), idx(i, j + 1);
      } else {  // diagonal (i+1,j)-(i,j+1)
        F.row(f++) << idx(i, j), idx(i + 1, j), idx(i, j + 1);
        F.row(f++) << idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1);
      }
    }
  }
  return lift_onto_bump(
      xy, std::move(F), "bump-48", level,
      "bump-48 level " + std::to_string(level) +
          ": Gaussian bump a=81/16 on [0,1]^2, 4-8 mesh (docs/algorithms.md 10.2), "
          "N=" +
          std::to_string(N));
}

}  // namespace curvbench
