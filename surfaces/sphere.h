// Sphere of radius a centred at the origin (the sign-convention test of docs/algorithms.md §0).
//
//   position(u, v) = a (cos v cos u, cos v sin u, sin v),  u = longitude, v = latitude in
//   [-pi/2, pi/2]; x_u x x_v = a^2 cos v * n points outward (the torus form with R = 0).
// Exact quantities: n = p/|p| (outward), k1 = k2 = H = -1/a, K = 1/a^2, umbilic; d1, d2 an
// orthonormal tangent pair (Duff et al. 2017 branchless basis, defined everywhere) with
// d1 x d2 = n.
#pragma once

#include "surfaces/surface.h"

namespace curvbench {

class Sphere final : public Surface {
 public:
  /// Throws UsageError unless a > 0 (finite).
  explicit Sphere(double a = 1.0);

  double radius() const { return a_; }

  std::string name() const override { return "sphere"; }
  /// a p/|p|; the centre maps to the north pole (0, 0, a).
  Vec3 project(const Vec3& p) const override;
  SurfacePoint evaluate(const Vec3& p) const override;
  Vec3 position(double u, double v) const override;

 private:
  double a_;
};

SurfacePtr make_sphere(double a = 1.0);

}  // namespace curvbench
