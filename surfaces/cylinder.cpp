// Cylinder; see cylinder.h.
#include "surfaces/cylinder.h"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/errors.h"
#include "surfaces/surface_point.h"

namespace curvbench {

Cylinder::Cylinder(double a) : a_(a) {
  if (!(std::isfinite(a) && a > 0.0)) {
    throw UsageError("cylinder: need a finite radius a > 0 (got " + std::to_string(a) + ")");
  }
}

Vec3 Cylinder::position(double u, double v) const {
  return Vec3(a_ * std::cos(u), a_ * std::sin(u), v);
}

Vec3 Cylinder::project(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double rho = std::hypot(p.x(), p.y());
  if (rho > 0.0) return Vec3(a_ * p.x() / rho, a_ * p.y() / rho, p.z());
  return Vec3(a_, 0.0, p.z());
}

SurfacePoint Cylinder::evaluate(const Vec3& p) const {
  const Vec3 q = project(p);
  if (!q.allFinite()) return nan_surface_point();
  const Vec3 n = Vec3(q.x(), q.y(), 0.0).normalized();
  SurfacePoint s;
  s.point = q;
  s.normal = n;
  s.k1 = 0.0;
  s.k2 = -1.0 / a_;
  s.H = -0.5 / a_;
  s.K = 0.0;
  s.d1 = Vec3(0.0, 0.0, 1.0);
  s.d2 = Vec3(n.y(), -n.x(), 0.0);
  s.umbilic = false;
  return s;
}

SurfacePtr make_cylinder(double a) {
  return std::make_shared<const Cylinder>(a);
}

}  // namespace curvbench
