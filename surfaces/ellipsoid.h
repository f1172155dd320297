// Triaxial ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 with a >= b >= c > 0 (the `ellipsoid`
// family, docs/mesh_families.md).
//
//   position(u, v) = (a cos v cos u, b cos v sin u, c sin v),  u longitude, v latitude in
//   [-pi/2, pi/2]; x_u x x_v points outward.
// Exact quantities at p on the ellipsoid, from the implicit function f(p) = p^T D p - 1 with
// D = diag(1/a^2, 1/b^2, 1/c^2): n = D p / |D p| (outward), and on the tangent plane the shape
// operator of B = n . x_uu, W = -P D P / |D p| (P the tangent projector); eqs. (7)-(8) give
// k1 >= k2 (both negative) and d1, d2; H = (k1 + k2)/2, K = k1 k2 (= 1 / (a b c |D p|^2)^2).
// With a > b > c the four umbilics lie in the plane y = 0 at
// x^2 = a^2 (a^2 - b^2)/(a^2 - c^2), z^2 = c^2 (b^2 - c^2)/(a^2 - c^2), where d1 is undefined.
#pragma once

#include "surfaces/surface.h"

namespace curvbench {

class Ellipsoid final : public Surface {
 public:
  /// Throws UsageError unless a >= b >= c > 0 (finite).
  Ellipsoid(double a, double b, double c);

  double a() const { return e_[0]; }
  double b() const { return e_[1]; }
  double c() const { return e_[2]; }

  std::string name() const override { return "ellipsoid"; }
  /// The closest point (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a
  /// hyperellipsoid", Geometric Tools 2013: bisection on the Lagrange multiplier, with the
  /// cases of points on the coordinate planes). Exact to a few ulps.
  Vec3 project(const Vec3& p) const override;
  SurfacePoint evaluate(const Vec3& p) const override;
  Vec3 position(double u, double v) const override;
  /// p^T D p - 1: negative inside, zero on the surface.
  double implicit(const Vec3& p) const;

 private:
  double e_[3];
};

SurfacePtr make_ellipsoid(double a, double b, double c);

}  // namespace curvbench
