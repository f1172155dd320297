// Circular cylinder of radius a about the z axis (the lantern families, docs/mesh_families.md).
//
//   position(u, v) = (a cos u, a sin u, v),  u the angle, v the height; x_u x x_v points outward.
// Exact quantities at p with cos u = x/rho, sin u = y/rho (rho = |(x, y)|):
//   n  = (cos u, sin u, 0)                         (outward)
//   k1 = 0,     d1 = (0, 0, 1)                     (the axis: a straight line)
//   k2 = -1/a,  d2 = (sin u, -cos u, 0)            (the circle; d1 x d2 = n)
//   H = -1/(2a), K = 0 exactly. No umbilics.
// The surface is unbounded along z: project() keeps the height, a mesh chooses its own ends.
#pragma once

#include "surfaces/surface.h"

namespace curvbench {

class Cylinder final : public Surface {
 public:
  /// Throws UsageError unless a > 0 (finite).
  explicit Cylinder(double a = 1.0);

  double radius() const { return a_; }

  std::string name() const override { return "cylinder"; }
  /// (a x/rho, a y/rho, z); a point on the axis maps to (a, 0, z).
  Vec3 project(const Vec3& p) const override;
  SurfacePoint evaluate(const Vec3& p) const override;
  Vec3 position(double u, double v) const override;

 private:
  double a_;
};

SurfacePtr make_cylinder(double a = 1.0);

}  // namespace curvbench
