// Ring torus; closed forms of docs/algorithms.md §11.1. See torus.h.
#include "surfaces/torus.h"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/errors.h"
#include "surfaces/surface_point.h"

namespace curvbench {

namespace {

// Unit vector (cos u, sin u, 0) towards p's azimuth; (1, 0, 0) on the z axis.
Vec3 radial_direction(const Vec3& p) {
  const double rho = std::hypot(p.x(), p.y());
  if (rho > 0.0) return Vec3(p.x() / rho, p.y() / rho, 0.0);
  return Vec3(1.0, 0.0, 0.0);
}

}  // namespace

Torus::Torus(double R, double r) : R_(R), r_(r) {
  if (!(std::isfinite(R) && std::isfinite(r) && r > 0.0 && R > r)) {
    throw UsageError("torus: need finite radii with R > r > 0 (got R = " + std::to_string(R) +
                     ", r = " + std::to_string(r) + ")");
  }
}

Vec3 Torus::position(double u, double v) const {
  const double w = R_ + r_ * std::cos(v);
  return Vec3(w * std::cos(u), w * std::sin(u), r_ * std::sin(v));
}

Vec3 Torus::project(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const Vec3 e = radial_direction(p);
  const Vec3 c = R_ * e;  // closest point of the core circle
  const Vec3 d = p - c;
  const double len = d.norm();
  if (len > 0.0) return c + (r_ / len) * d;
  return c + r_ * e;  // p on the core circle: every tube point is closest; take the outer one
}

SurfacePoint Torus::evaluate(const Vec3& p) const {
  const Vec3 q = project(p);
  if (!q.allFinite()) return nan_surface_point();
  const Vec3 e = radial_direction(q);  // (cos u, sin u, 0)
  const Vec3 n = (q - R_ * e) / r_;    // (cos v cos u, cos v sin u, sin v), unit by construction
  const double cv = n.dot(e);
  const double sv = n.z();
  SurfacePoint s;
  s.point = q;
  s.normal = n.normalized();
  s.k1 = -cv / (R_ + r_ * cv);
  s.k2 = -1.0 / r_;
  s.H = 0.5 * (s.k1 + s.k2);
  s.K = s.k1 * s.k2;
  s.d1 = Vec3(-e.y(), e.x(), 0.0);
  s.d2 = Vec3(-sv * e.x(), -sv * e.y(), cv).normalized();
  s.umbilic = false;  // k1 - k2 = R / (r (R + r cos v)) > 0
  return s;
}

SurfacePtr make_torus(double R, double r) {
  return std::make_shared<const Torus>(R, r);
}

}  // namespace curvbench
