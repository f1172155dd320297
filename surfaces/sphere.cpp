// Sphere; see sphere.h.
#include "surfaces/sphere.h"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/errors.h"
#include "surfaces/surface_point.h"

namespace curvbench {

Sphere::Sphere(double a) : a_(a) {
  if (!(std::isfinite(a) && a > 0.0)) {
    throw UsageError("sphere: need a finite radius a > 0 (got " + std::to_string(a) + ")");
  }
}

Vec3 Sphere::position(double u, double v) const {
  const double cv = std::cos(v);
  return a_ * Vec3(cv * std::cos(u), cv * std::sin(u), std::sin(v));
}

Vec3 Sphere::project(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const double len = p.norm();
  if (len > 0.0) return (a_ / len) * p;
  return Vec3(0.0, 0.0, a_);
}

SurfacePoint Sphere::evaluate(const Vec3& p) const {
  const Vec3 q = project(p);
  if (!q.allFinite()) return nan_surface_point();
  const Vec3 n = q.normalized();
  SurfacePoint s;
  s.point = q;
  s.normal = n;
  s.k1 = s.k2 = s.H = -1.0 / a_;
  s.K = 1.0 / (a_ * a_);
  orthonormal_tangents(n, s.d1, s.d2);  // d1 x d2 = n
  s.umbilic = true;
  return s;
}

SurfacePtr make_sphere(double a) {
  return std::make_shared<const Sphere>(a);
}

}  // namespace curvbench
