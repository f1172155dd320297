// The test torus (R = 1, r = 0.3; docs/algorithms.md §11.1) for the torus-mesh tests: a point's
// distance to it and the outward normal direction at a point on it.
#pragma once

#include <cmath>

#include "core/types.h"

namespace curvbench::testing {

inline constexpr double kTorusR = 1.0, kTorusr = 0.3;

inline double torus_distance(const Vec3& p) {
  const double rho = std::hypot(p.x(), p.y());
  return std::abs(std::hypot(rho - kTorusR, p.z()) - kTorusr);
}

inline Vec3 torus_outward(const Vec3& p) {
  const double rho = std::hypot(p.x(), p.y());
  const Vec3 c(kTorusR * p.x() / rho, kTorusR * p.y() / rho, 0.0);
  return (p - c).normalized();
}

}  // namespace curvbench::testing
