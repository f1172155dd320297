// Ring torus about the z axis (paper §5.1; docs/algorithms.md §10.1, §11.1).
//
//   position(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),  u, v angles;
//   x_u x x_v points outward.
// Exact quantities at p on the torus, with rho = |(x, y)|, cos u = x/rho, sin u = y/rho,
// cos v = (rho - R)/r, sin v = z/r (§11.1):
//   n  = (cos v cos u, cos v sin u, sin v)                                   (outward)
//   k1 = -cos v / (R + r cos v) = -(rho - R)/(r rho),  d1 = (-sin u, cos u, 0)  (parallel)
//   k2 = -1/r,  d2 = (-sin v cos u, -sin v sin u, cos v)                        (meridian)
//   H = (k1 + k2)/2, K = k1 k2. k1 > k2 everywhere (no umbilics) since R > r > 0.
#pragma once

#include "surfaces/surface.h"

namespace curvbench {

class Torus final : public Surface {
 public:
  /// Throws UsageError unless R > r > 0 (finite).
  explicit Torus(double R = 1.0, double r = 0.3);

  double major_radius() const { return R_; }
  double minor_radius() const { return r_; }

  std::string name() const override { return "torus"; }
  /// Closest point (§10.1(a)): c = R (x, y, 0)/rho, p <- c + r (p - c)/|p - c|. On the axis
  /// (rho = 0) the core point c = (R, 0, 0) is used; at p = c the outward point c + r c/R.
  Vec3 project(const Vec3& p) const override;
  SurfacePoint evaluate(const Vec3& p) const override;
  Vec3 position(double u, double v) const override;

 private:
  double R_;
  double r_;
};

SurfacePtr make_torus(double R = 1.0, double r = 0.3);

}  // namespace curvbench
