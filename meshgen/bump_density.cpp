#include "meshgen/bump_density.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "meshgen/bump_irregular.h"
#include "meshgen/random.h"

namespace curvbench {

namespace {

constexpr double kJitter = 0.25;  // in units of the local spacing, as bump-irregular
constexpr double kLevel1Vertices = 289.0;

int level1_columns(double density) {
  const double lnd = std::log(density);
  const double c = density > 1.0 ? (density - 1.0) * (density - 1.0) / (density * lnd * lnd) : 1.0;
  const double n = (-2.0 + std::sqrt(4.0 - 4.0 * c * (1.0 - kLevel1Vertices))) / (2.0 * c);
  return std::max(2, static_cast<int>(std::lround(n)));
}

}  // namespace

PlanarPoints bump_density_points(int level, double density, std::uint64_t seed) {
  const int n = level1_columns(density) << (level - 1);
  std::vector<double> x(static_cast<size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    x[i] = i == n        ? 1.0
           : density > 1 ? (std::pow(density, static_cast<double>(i) / n) - 1.0) / (density - 1.0)
                         : static_cast<double>(i) / n;
  const double h0 = density > 1 ? std::log(density) / ((density - 1.0) * n) : 1.0 / n;
  std::vector<int> m(x.size());
  Eigen::Index count = 0;
  for (int i = 0; i <= n; ++i) {
    m[i] = std::max(1, static_cast<int>(std::lround(1.0 / (h0 * (1.0 + (density - 1.0) * x[i])))));
    count += m[i] + 1;
  }
  Rng rng(derive_seed(derive_seed(seed, kBumpDensityStream), static_cast<std::uint64_t>(level)));
  PlanarPoints xy(count, 2);
  Eigen::Index p = 0;
  for (int i = 0; i <= n; ++i) {
    const double gap = i > 0 ? x[i] - x[i - 1] : 0.0;
    for (int k = 0; k <= m[i]; ++k) {
      double px = x[i], py = k == m[i] ? 1.0 : static_cast<double>(k) / m[i];
      const bool side_x = i == 0 || i == n, side_y = k == 0 || k == m[i];
      if (!side_x) px += rng.uniform(-kJitter, kJitter) * gap;
      if (!side_y) py += rng.uniform(-kJitter, kJitter) / m[i];
      xy.row(p++) << px, py;
    }
  }
  return xy;
}

GeneratedMesh generate_bump_density(const MeshSpec& spec) {
  const double density = spec.shape.density.value_or(kDefaultDensity);
  PlanarPoints xy = bump_density_points(spec.level, density, spec.seed);
  FaceMatrix F = delaunay_triangulation(xy);
  const Eigen::Index on_square = (xy.col(0).array() == 0.0 || xy.col(0).array() == 1.0 ||
                                  xy.col(1).array() == 0.0 || xy.col(1).array() == 1.0)
                                     .count();
  if (F.rows() != 2 * xy.rows() - on_square - 2)
    throw std::logic_error("bump-density: Delaunay triangulation has " + std::to_string(F.rows()) +
                           " faces, expected 2V - b - 2");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", density);
  return lift_onto_bump(
      xy, std::move(F), spec.family, spec.level,
      "bump-density level " + std::to_string(spec.level) +
          ": Gaussian bump a=81/16 on [0,1]^2, edge length growing linearly by density D=" + buf +
          " from x=0 to x=1, " + std::to_string(level1_columns(density) << (spec.level - 1)) +
          " columns, points jittered by 1/4 of the local spacing, CGAL Delaunay, seed=" +
          std::to_string(spec.seed));
}

}  // namespace curvbench
